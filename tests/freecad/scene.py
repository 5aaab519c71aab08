"""What both FreeCAD test scripts build and check, run inside FreeCAD (the scripts' folder is
on FreeCAD's sys.path)."""

import FreeCAD as App
import Mesh
import Part  # noqa: F401  (Part::Box needs the Part module loaded)


def check(condition, what):
    if not condition:
        raise AssertionError(what)


def box_and_sphere(doc):
    """A Part box 10 x 10 x 10 at the origin and a Mesh sphere of radius 4 apart from it;
    returns (box, sphere, the volume they enclose)."""
    box = doc.addObject("Part::Box", "Box")
    box.Length = box.Width = box.Height = 10
    sphere = doc.addObject("Mesh::Feature", "Sphere")
    sphere.Mesh = Mesh.createSphere(4.0, 48)
    sphere.Placement.Base = App.Vector(20, 5, 5)
    doc.recompute()
    return box, sphere, box.Shape.Volume + sphere.Mesh.Volume


def overlapping_box(doc):
    """A Part box that cuts into box_and_sphere()'s box: the two intersect."""
    overlap = doc.addObject("Part::Box", "Overlap")
    overlap.Length = overlap.Width = overlap.Height = 10
    overlap.Placement.Base = App.Vector(5, 5, 5)
    doc.recompute()
    return overlap
