"""What both FreeCAD test scripts build and check, run inside FreeCAD (the scripts' folder is
on FreeCAD's sys.path)."""

import FreeCAD as App
import Mesh
import Part  # noqa: F401  (Part::Box needs the Part module loaded)


def check(condition, what):
    if not condition:
        raise AssertionError(what)


def box_and_sphere(doc):
    """A Part compound "Boxes" of two 10 x 10 x 10 boxes touching along a face (Box at the
    origin, Block beside it at x = 10) and a Mesh sphere of radius 4 apart from them; returns
    (the compound, the sphere, {material: volume}) with the materials the library names them:
    "Boxes/solid 1", "Boxes/solid 2" and "Sphere"."""
    box = doc.addObject("Part::Box", "Box")
    block = doc.addObject("Part::Box", "Block")
    for b in (box, block):
        b.Length = b.Width = b.Height = 10
    block.Placement.Base = App.Vector(10, 0, 0)
    boxes = doc.addObject("Part::Compound", "Boxes")
    boxes.Links = [box, block]
    sphere = doc.addObject("Mesh::Feature", "Sphere")
    sphere.Mesh = Mesh.createSphere(4.0, 48)
    sphere.Placement.Base = App.Vector(30, 5, 5)
    doc.recompute()
    return boxes, sphere, {"Boxes/solid 1": 1000.0, "Boxes/solid 2": 1000.0, "Sphere": sphere.Mesh.Volume}


def overlapping_box(doc):
    """A Part box that cuts into box_and_sphere()'s box: the two intersect."""
    overlap = doc.addObject("Part::Box", "Overlap")
    overlap.Length = overlap.Width = overlap.Height = 10
    overlap.Placement.Base = App.Vector(5, 5, 5)
    doc.recompute()
    return overlap
