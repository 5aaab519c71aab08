"""The VoroCrust add-on's App-level function in freecadcmd, without the GUI.

Run by run_freecad_test.py as `freecadcmd freecad_app_test.py` with VOROCRUST_TEST_WORK (a
fresh folder) and VOROCRUST_TEST_SUMMARY (a JSON file for the driver's own checks) set.
freecadcmd exits 0 even when a script raises, so every failure ends in sys.exit(1).
"""

import json
import os
import sys
import traceback

# How far the runs go: "cells" meshes the volume with interior seeds; "surface" stops after the
# surface (the volume files are then not written). Both pass.
STOP_AFTER = "cells"
# One material per solid, named after it: the compound's two touching boxes and the sphere.
EXPECTED_MATERIALS = ["Boxes/solid 1", "Boxes/solid 2", "Sphere"]
# The output surface's triangles are chords of the input: with max_size 2 the sphere of radius 4
# keeps 97.5 % of its volume.
SURFACE_TOLERANCE = 0.04

WORK = os.environ["VOROCRUST_TEST_WORK"]
SUMMARY = os.environ["VOROCRUST_TEST_SUMMARY"]


def count_lines(path):
    with open(path) as f:
        return sum(1 for _ in f)


def main():
    import FreeCAD as App
    import Part

    import VoroCrustMesher
    import vorocrust
    from scene import box_and_sphere, check, check_mesh_ok, overlapping_box, sketch_domain

    def close(a, b, relative, what):
        check(abs(a - b) <= relative * abs(b), "%s: %r is not within %g %% of %r" % (what, a, 100 * relative, b))

    summary = {"vorocrust_module": vorocrust.__file__, "mesher_module": VoroCrustMesher.__file__}
    # The add-on carries its own module, installed beside it.
    check(os.path.dirname(vorocrust.__file__).startswith(os.path.dirname(VoroCrustMesher.__file__)),
          "vorocrust is not the add-on's copy: %s" % vorocrust.__file__)

    doc = App.newDocument("VoroCrustApp")

    # Every option of the library's table is a property of a result object, under its FreeCAD
    # spelling, of its kind's type, holding the table's default (unset: the table's number for
    # it) and saying the range in its documentation.
    blank = doc.addObject("App::DocumentObjectGroupPython", "Blank")
    VoroCrustMesher.VoronoiMeshResult(blank)
    offered = [o for o in vorocrust.OPTIONS if "freecad" in o["front_ends"] and o["name"] != "formats"]
    for o in offered:
        name = o["freecad"]
        check(name in blank.PropertiesList, "no property %s for the option %s" % (name, o["name"]))
        check(blank.getTypeIdOfProperty(name) == VoroCrustMesher.PROPERTY_TYPES[o["kind"]],
              "%s is a %s" % (name, blank.getTypeIdOfProperty(name)))
        expected = VoroCrustMesher.property_value(o, o["default"])
        check(getattr(blank, name) == expected, "%s holds %r, the table's default is %r" % (
            name, getattr(blank, name), expected))
        if o["kind"] == "choice":
            check(list(blank.getEnumerationsOfProperty(name)) == list(o["choices"]), "choices of %s" % name)
        doc_text = blank.getDocumentationOfProperty(name)
        check(o["kind"] == "flag" or ("range: " + o["range_text"]) in doc_text, "%s's documentation: %s" % (name, doc_text))
        check(o["default_text"][len("default: "):] in doc_text, "%s's documentation: %s" % (name, doc_text))
    check("Formats" in blank.PropertiesList, "no Formats property")
    summary["options_checked"] = len(offered) + 1
    doc.removeObject(blank.Name)

    box, sphere, material_volumes = box_and_sphere(doc)
    input_volume = sum(material_volumes.values())
    parameters = VoroCrustMesher.Parameters(stop_after=STOP_AFTER, seed=7, max_size=2.0, tolerance=0.05)

    # A cancelled run raises, writes nothing and leaves the document as it was.
    cancelled_dir = os.path.join(WORK, "cancelled")
    objects_before = len(doc.Objects)
    try:
        VoroCrustMesher.voronoi_mesh([box, sphere], parameters, output_dir=cancelled_dir,
                                     progress=lambda phase, fraction: phase != "slivers")
        raise AssertionError("the cancelled run did not raise")
    except vorocrust.Cancelled as e:
        summary["cancelled"] = str(e)
    check(not os.path.exists(cancelled_dir), "the cancelled run wrote %s" % cancelled_dir)
    check(len(doc.Objects) == objects_before, "the cancelled run changed the document")

    # The run: objects in the document and files on disk.
    out = os.path.join(WORK, "out")
    phases = []
    result = VoroCrustMesher.voronoi_mesh([box, sphere], parameters, output_dir=out,
                                          formats=["vtu", "openfoam", "seeds", "obj", "ply", "report"],
                                          progress=lambda phase, fraction: phases.append(phase))
    check("slivers" in phases, "no progress reports: %s" % phases[:5])
    check(VoroCrustMesher.is_result(result), "no VoronoiMesh object")
    check(result.Sources == [box, sphere], "sources %s" % result.Sources)
    surfaces = [o for o in result.Group if o.isDerivedFrom("Mesh::Feature")]
    seeds = [o for o in result.Group if o.isDerivedFrom("Points::Feature")]
    check(sorted(o.Label for o in surfaces) == ["Voronoi surface: %s" % m for m in EXPECTED_MATERIALS],
          "material surfaces %s" % [o.Label for o in surfaces])
    check(len(seeds) == 1, "%d seed objects" % len(seeds))
    check(seeds[0].Points.CountPoints == result.SeedCount, "seed points %d of %d" % (
        seeds[0].Points.CountPoints, result.SeedCount))
    run = result.Proxy.result()
    between_materials = int(((run.surface.regions[:, 0] > 0) & (run.surface.regions[:, 1] > 0)).sum())
    # Every triangle is in the surface of each material beside it: interfaces in two.
    check(sum(o.Mesh.CountFacets for o in surfaces) == result.SurfaceTriangles + between_materials, "surface facets")
    for o in surfaces:
        check(o.Mesh.isSolid(), "the surface of %s is not closed" % o.Label)
        check(o.Mesh.countComponents() == 1, "%d components in %s" % (o.Mesh.countComponents(), o.Label))
        close(o.Mesh.Volume, material_volumes[o.Label.split(": ", 1)[1]], SURFACE_TOLERANCE, "volume inside %s" % o.Label)
    # The boxes' common face is an interface between their materials, and each material's cells
    # fill its solid.
    names = list(run.surface.region_names)
    box1, box2 = names.index("Boxes/solid 1"), names.index("Boxes/solid 2")
    pairs = [tuple(sorted(p)) for p in run.surface.regions.tolist()]
    check(pairs.count((box1, box2)) >= 2, "%d triangles between the boxes" % pairs.count((box1, box2)))
    for name, volume in material_volumes.items():
        label = names.index(name)
        close(float(run.cells.volumes[run.cells.materials == label].sum()), volume, SURFACE_TOLERANCE, "cells of %s" % name)
    check(result.TopologyMatches, "topology differs from the input's")
    # The volume mesh fills the solids up to the surface's distance from them.
    close(result.Volume, input_volume, 0.02, "sum of the cell volumes")
    check(result.CellCount > 0, "no cells")

    check(count_lines(os.path.join(out, "seeds.csv")) == result.SeedCount + 1, "seeds.csv rows")
    for name in ("mesh.vtu", "surface.obj", "surface.ply", "case/constant/polyMesh/owner", "report.json"):
        check(os.path.isfile(os.path.join(out, name)), "%s missing" % name)
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    check(report["status"] == "ok" and report["options"]["seed"] == 7, "report.json: %s" % report["status"])
    check(report["options"]["stop_after"] == STOP_AFTER, "report.json stage")
    check(not result.Smooth and result.SharpAngle == 30 and not report["options"]["smooth"],
          "default rules: Smooth %r, SharpAngle %r" % (result.Smooth, result.SharpAngle))

    # The sphere as the smooth surface it is: the mode's own sharp angle and smoothing, no feature.
    smooth = VoroCrustMesher.voronoi_mesh(
        [sphere], parameters.replace(stop_after="surface", smooth=True),
        output_dir=os.path.join(WORK, "smooth"), formats=["report"])
    smooth_report = smooth.Proxy.result().report()
    check(smooth.Smooth and smooth.SharpAngle == 60, "smooth: Smooth %r, SharpAngle %r" % (
        smooth.Smooth, smooth.SharpAngle))
    check(smooth_report["features"]["corners"] == 0 and smooth_report["options"]["smoothing_iterations"] == 6,
          "smooth: features %s, options %s" % (smooth_report["features"], smooth_report["options"]))
    check(smooth.TopologyMatches, "the smooth sphere's topology differs from the input's")
    check([g["name"] for g in report["input"]["groups"]] == EXPECTED_MATERIALS,
          "input groups %s" % report["input"]["groups"])

    # Stopping after the surface: the surface as the whole run made it, and no volume file (one
    # of an earlier run in the folder goes).
    surface_dir = os.path.join(WORK, "surface_only")
    os.makedirs(surface_dir)
    open(os.path.join(surface_dir, "mesh.vtu"), "w").close()
    surface_only = VoroCrustMesher.voronoi_mesh(
        [box, sphere], parameters.replace(stop_after="surface"), output_dir=surface_dir, formats=["vtu", "ply"])
    check(surface_only.StopAfter == "surface", "stage %s" % surface_only.StopAfter)
    check(surface_only.CellCount == 0 and surface_only.Proxy.result().cells is None, "cells of a surface run")
    check(surface_only.SurfaceTriangles == result.SurfaceTriangles, "the surface differs between the stages")
    check(sorted(os.listdir(surface_dir)) == ["report.json", "surface.ply"], "files %s" % os.listdir(surface_dir))
    surface_only.removeObjectsFromDocument()  # its surfaces and seeds
    doc.removeObject(surface_only.Name)

    # Export writes the same volume mesh again: from the run in memory, then from the seeds the
    # saved document keeps.
    with open(os.path.join(out, "mesh.vtu"), "rb") as f:
        vtu = f.read()
    again = os.path.join(WORK, "export_memory")
    VoroCrustMesher.export_result(result, again, ["vtu", "seeds"])
    with open(os.path.join(again, "mesh.vtu"), "rb") as f:
        check(f.read() == vtu, "exported mesh.vtu differs from the run's")
    saved = os.path.join(WORK, "voronoi.FCStd")
    name = result.Name
    summary.update(out=out, cells=result.CellCount, volume=result.Volume, input_volume=input_volume, materials=len(surfaces),
                   seeds=result.SeedCount, triangles=result.SurfaceTriangles, stop_after=STOP_AFTER)
    doc.saveAs(saved)
    App.closeDocument(doc.Name)
    doc = App.openDocument(saved)
    reopened = doc.getObject(name)
    check(VoroCrustMesher.is_result(reopened) and reopened.Proxy.result() is None, "reopened result")
    again = os.path.join(WORK, "export_document")
    VoroCrustMesher.export_result(reopened, again, ["vtu", "openfoam", "obj"])
    with open(os.path.join(again, "mesh.vtu"), "rb") as f:
        check(f.read() == vtu, "mesh.vtu from the saved document's seeds differs from the run's")
    with open(os.path.join(again, "surface.obj"), "rb") as a, open(os.path.join(out, "surface.obj"), "rb") as b:
        check(a.read() == b.read(), "surface.obj from the saved document differs")
    try:
        VoroCrustMesher.export_result(reopened, again, ["report"])
        raise AssertionError("exporting a report from a reopened document did not raise")
    except vorocrust.UsageError as e:
        summary["export_refused"] = str(e)

    # Bad input: overlapping solids intersect each other; the library's message names the part.
    other = overlapping_box(doc)
    first = doc.getObject("Box")
    try:
        VoroCrustMesher.voronoi_mesh([first, other], parameters, output_dir=os.path.join(WORK, "bad"))
        raise AssertionError("intersecting solids did not raise")
    except vorocrust.InvalidGeometryError as e:
        summary["invalid"] = str(e)
        check("intersect" in str(e) and "Overlap" in str(e), "message: %s" % e)
    check(not os.path.exists(os.path.join(WORK, "bad")), "the failed run wrote files")

    # Part shapes follow the tolerance: a finer one gives more triangles.
    cylinder = doc.addObject("Part::Cylinder", "Cylinder")
    doc.recompute()
    coarse = VoroCrustMesher.model_parts([cylinder], 0.5)[0][1].num_faces
    fine = VoroCrustMesher.model_parts([cylinder], 0.01)[0][1].num_faces
    check(fine > coarse, "tessellation: %d triangles at 0.01, %d at 0.5" % (fine, coarse))

    # A sketch as a 2D domain (paper 2.6): its circle a hole, its open segment a breakline.
    sketch, (low, high) = sketch_domain(doc)
    check(VoroCrustMesher.is_planar_wire(sketch) and not VoroCrustMesher.is_meshable(sketch), "the sketch's kind")
    out2d = os.path.join(WORK, "out2d")
    group, plane = VoroCrustMesher.voronoi_mesh_2d([sketch], VoroCrustMesher.Parameters(0.01, max_size=0.3, seed=7),
                                                   output_dir=out2d, thickness=0.5)
    area = plane.quality["area_by_region"][1]
    check(low <= area <= high, "2D area %r outside [%r, %r]" % (area, low, high))
    check(plane.region_names[1] == "inside" and plane.quality["interface_edges"] == 0, "one region, the breakline in it")
    check(plane.quality["convex"] and plane.quality["max_link_angle"] < 1e-6, "convex cells, edges orthogonal to the links")
    cells = [o for o in group.Group if o.isDerivedFrom("Mesh::Feature")]
    check(len(cells) == 1 and cells[0].Mesh.CountFacets == sum(len(c) - 2 for c in plane.cells),
          "cells in the document: %s" % [o.Label for o in group.Group])
    # The cells lie in the sketch's plane: y = 0 there after the turn, z from 5 to 11.
    box = cells[0].Mesh.BoundBox
    check(abs(box.YMin) < 1e-9 and abs(box.YMax) < 1e-9 and abs(box.ZMin - 5) < 1e-9 and abs(box.ZMax - 11) < 1e-9,
          "cells placed at %s" % box)
    ok, log = check_mesh_ok(os.path.join(out2d, "case"))
    check(ok, "checkMesh on the 2D case: " + log)
    summary["plane"] = {"cells": len(plane.cells), "area": area}
    # An open sketch bounds nothing: the library's message says where the gap is.
    open_sketch = doc.addObject("Sketcher::SketchObject", "Open")
    for a, b in ((0, 0), (4, 0)), ((4, 0), (4, 3)), ((4, 3), (0, 3)):
        open_sketch.addGeometry(Part.LineSegment(App.Vector(*a, 0), App.Vector(*b, 0)))
    doc.recompute()
    try:
        VoroCrustMesher.voronoi_mesh_2d([open_sketch], output_dir=os.path.join(WORK, "open"))
        raise AssertionError("an open sketch did not raise")
    except vorocrust.InvalidGeometryError as e:
        check("gap" in str(e), "message: %s" % e)

    with open(SUMMARY, "w") as f:
        json.dump(summary, f, indent=1)


try:
    main()
except BaseException:
    traceback.print_exc()
    sys.stdout.flush()
    sys.exit(1)
sys.exit(0)
