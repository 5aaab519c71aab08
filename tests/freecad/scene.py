"""What both FreeCAD test scripts build and check, run inside FreeCAD (the scripts' folder is
on FreeCAD's sys.path)."""

import math
import os
import shutil
import subprocess

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


def sketch_domain(doc):
    """A sketch of a 10 x 6 rectangle with a circular hole of radius 1.5 and an open segment
    inside (a breakline), in a plane turned 90 degrees about x and lifted 5 along z; returns the
    sketch and the bounds of the meshed area: the hole's area is at most the circle's, and at
    least that of its polygons within 0.02 of it."""
    import Sketcher  # noqa: F401  (Sketcher::SketchObject needs the module loaded)

    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    corners = [App.Vector(0, 0, 0), App.Vector(10, 0, 0), App.Vector(10, 6, 0), App.Vector(0, 6, 0)]
    for a, b in zip(corners, corners[1:] + corners[:1]):
        sketch.addGeometry(Part.LineSegment(a, b))
    sketch.addGeometry(Part.Circle(App.Vector(3, 3, 0), App.Vector(0, 0, 1), 1.5))
    sketch.addGeometry(Part.LineSegment(App.Vector(6, 1, 0), App.Vector(8, 4, 0)))
    sketch.Placement = App.Placement(App.Vector(0, 0, 5), App.Rotation(App.Vector(1, 0, 0), 90))
    doc.recompute()
    circle = math.pi * 1.5 ** 2
    return sketch, (60 - circle, 60 - circle * (1 - 0.02 / 1.5) ** 2)


def check_mesh_ok(case):
    """Whether OpenFOAM's checkMesh says "Mesh OK." on a case folder; and its output."""
    env = dict(os.environ, WM_PROJECT_DIR="/usr/share/openfoam")
    r = subprocess.run([shutil.which("checkMesh") or "/usr/bin/checkMesh", "-case", case], capture_output=True,
                       text=True, env=env, timeout=600)
    return "Mesh OK." in r.stdout, r.stdout[-2000:]
