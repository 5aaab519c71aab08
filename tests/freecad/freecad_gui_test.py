"""The VoroCrust workbench in FreeCAD's GUI: activated, its "Voronoi mesh" command run through
FreeCADGui.runCommand with parameters preset in FreeCAD's preferences, its task panel's OK and
Cancel buttons clicked, a run cancelled, a run finished, its result exported again, and a bad
input reported.

Run by run_freecad_test.py as `xvfb-run freecad freecad_gui_test.py` with VOROCRUST_TEST_WORK
and VOROCRUST_TEST_SUMMARY set. Exits FreeCAD with 0 when every check holds, 1 otherwise.
"""

import json
import os
import shutil
import sys
import time
import traceback

# How far the run goes (see freecad_app_test.py).
STOP_AFTER = "cells"

WORK = os.environ["VOROCRUST_TEST_WORK"]
SUMMARY = os.environ["VOROCRUST_TEST_SUMMARY"]


def main():
    import FreeCAD as App
    import FreeCADGui as Gui
    from PySide import QtGui

    from scene import box_and_sphere, check, check_mesh_ok, overlapping_box, sketch_domain

    def wait(condition, what, timeout=900):
        end = time.monotonic() + timeout
        while not condition():
            if time.monotonic() > end:
                raise AssertionError("timed out waiting for " + what)
            QtGui.QApplication.processEvents()
            time.sleep(0.02)

    def task_buttons():
        """The OK and Cancel buttons of the open task panel, as a user clicks them."""
        boxes = [b for b in Gui.getMainWindow().findChildren(QtGui.QDialogButtonBox)
                 if b.isVisible() and b.button(QtGui.QDialogButtonBox.Ok) is not None]
        check(len(boxes) == 1, "%d task dialogs with an OK button" % len(boxes))
        return boxes[0].button(QtGui.QDialogButtonBox.Ok), boxes[0].button(QtGui.QDialogButtonBox.Cancel)

    def open_panel(objects):
        """Runs "Voronoi mesh" on the objects as selected; returns its task panel."""
        Gui.Selection.clearSelection()
        for obj in objects:
            Gui.Selection.addSelection(obj)
        Gui.runCommand("VoroCrust_VoronoiMesh")
        QtGui.QApplication.processEvents()
        panel = VoroCrustGui.active_panel()
        check(panel is not None and Gui.Control.activeDialog() and panel.objects == objects,
              "no Voronoi mesh task panel for %s" % [o.Label for o in objects])
        return panel

    def results(doc):
        return [o for o in doc.Objects if o.Name.startswith("VoronoiMesh")]

    Gui.activateWorkbench("VoroCrustWorkbench")
    QtGui.QApplication.processEvents()
    check(Gui.activeWorkbench().name() == "VoroCrustWorkbench", "workbench %s" % Gui.activeWorkbench().name())
    import VoroCrustGui
    import vorocrust

    summary = {"vorocrust_module": vorocrust.__file__}
    for command in VoroCrustGui.COMMANDS:
        check(command in Gui.listCommands(), "%s is not registered" % command)
    toolbar = Gui.getMainWindow().findChild(QtGui.QToolBar, "VoroCrust")
    check(toolbar is not None and toolbar.isVisible(), "no VoroCrust toolbar")

    doc = App.newDocument("VoroCrustGui")
    box, sphere, material_volumes = box_and_sphere(doc)
    input_volume = sum(material_volumes.values())

    out = os.path.join(WORK, "out")
    preferences = App.ParamGet(VoroCrustGui.PREFERENCES)
    preferences.SetString("StopAfter", STOP_AFTER)
    preferences.SetInt("Seed", 7)
    preferences.SetFloat("MaxSize", 2.0)
    preferences.SetFloat("Tolerance", 0.05)
    preferences.SetString("OutputFolder", out)
    preferences.SetString("Formats", "vtu,openfoam,seeds,ply")

    panel = open_panel([box, sphere])
    check((panel.seed.value(), panel.max_size.value(), panel.stop_after.currentText()) == (7, 2.0, STOP_AFTER),
          "the panel does not show the preset parameters")
    check(panel.chosen_formats() == ["seeds", "ply", "vtu", "openfoam"] or
          set(panel.chosen_formats()) == {"vtu", "openfoam", "seeds", "ply"}, "formats %s" % panel.chosen_formats())

    check(not panel.cvt_iterations.isEnabled(), "CVT iterations offered for the random interior")
    panel.interior.setCurrentText("cvt")
    check(panel.cvt_iterations.isEnabled(), "CVT iterations not offered for the cvt interior")
    panel.interior.setCurrentText("random")
    check(panel.max_aspect_ratio.value() == vorocrust.DEFAULT_OPTIONS["max_aspect_ratio"] == 5,
          "largest aspect ratio %r" % panel.max_aspect_ratio.value())
    check(panel.parameters().max_aspect_ratio == 5, "the panel's parameters lose the largest aspect ratio")

    # The sharp angle is left to the mode ("auto": 30, or 60 with "Smooth surface", as the library
    # decides), unless the user chooses one.
    check(not panel.smooth.isChecked() and panel.sharp_angle.value() == 0 and
          panel.sharp_angle.specialValueText().startswith("auto") and panel.parameters().sharp_angle is None,
          "smooth %r, angle %r" % (panel.smooth.isChecked(), panel.sharp_angle.value()))
    panel.sharp_angle.setValue(40)
    check(panel.parameters().sharp_angle == 40, "the chosen angle: %r" % panel.parameters().sharp_angle)
    panel.sharp_angle.setValue(0)

    # Cancel during a run: it stops, nothing is written, the panel stays open for another try.
    ok, cancel = task_buttons()
    ok.click()
    check(panel.running(), "OK did not start a run")
    cancel.click()
    wait(lambda: not panel.running(), "the cancelled run to stop")
    check(panel.status.text().startswith("Cancelled"), "status after cancelling: %s" % panel.status.text())
    check(not os.path.exists(out), "the cancelled run wrote %s" % out)
    check(not results(doc), "the cancelled run added objects")
    check(Gui.Control.activeDialog(), "cancelling the run closed the panel")

    # The run: the panel closes, the result is in the document and on disk.
    fractions = []
    original_poll = panel._poll

    def watched_poll():
        fractions.append(panel.progress.maximum())
        original_poll()

    panel._timer.timeout.disconnect()
    panel._timer.timeout.connect(watched_poll)
    ok.click()
    wait(lambda: not panel.running(), "the run")
    QtGui.QApplication.processEvents()
    if panel.result_object is None:  # the panel is closed (its widgets gone) only when it succeeded
        raise AssertionError("the run failed: %s" % panel.status.text())
    check(not Gui.Control.activeDialog(), "the panel stayed open after the run")
    check(fractions, "the progress bar was never updated")
    result = panel.result_object
    check(results(doc) == [result], "results %s" % results(doc))
    surfaces = [o for o in result.Group if o.isDerivedFrom("Mesh::Feature")]
    seeds = [o for o in result.Group if o.isDerivedFrom("Points::Feature")]
    # One surface per material: the two boxes and the sphere.
    check(len(surfaces) == 3 and len(seeds) == 1, "children %s" % [o.Label for o in result.Group])
    check(all(o.ViewObject.Visibility for o in surfaces) and seeds[0].Points.CountPoints == result.SeedCount,
          "shown objects")
    check(all(o.Mesh.isSolid() and o.Mesh.countComponents() == 1 for o in surfaces), "the output surfaces")
    check(abs(result.Volume - input_volume) < 0.02 * input_volume, "cells volume %g" % result.Volume)
    for name in ("mesh.vtu", "seeds.csv", "surface.ply", "case/constant/polyMesh/faces"):
        check(os.path.isfile(os.path.join(out, name)), "%s not written" % name)
    check(not os.path.exists(os.path.join(out, "surface.obj")), "a format not asked for was written")
    check(result.ViewObject.Proxy.getIcon().endswith("VoronoiMeshResult.svg"), "result icon")

    # The result window: the cut through the cells, ParaView offered when it is installed.
    window = VoroCrustGui.active_panel("result")
    check(window is not None and window.dialog.isVisible(), "no result window after the run")
    image = window.picture.pixmap().toImage()
    check((image.width(), image.height()) == (720, 540), "cut picture %dx%d" % (image.width(), image.height()))
    drawn = sum(1 for x in range(0, 720, 8) for y in range(0, 540, 8) if image.pixel(x, y) & 0xFFFFFF != 0xFFFFFF)
    check(drawn > 0.1 * 90 * 68, "the cut picture is nearly empty: %d of %d samples drawn" % (drawn, 90 * 68))
    paraview = shutil.which("paraview")
    check(window.paraview_button.isEnabled() == (paraview is not None), "ParaView button enabled with paraview %r" % paraview)
    if paraview:
        check(window.paraview_command() == [paraview, os.path.join(out, "mesh.vtu")],
              "ParaView command %r" % window.paraview_command())
    window.dialog.close()
    summary["cut_picture_drawn_samples"] = drawn

    # Export the finished result again.
    export = os.path.join(WORK, "export")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(result)
    Gui.runCommand("VoroCrust_Export")
    QtGui.QApplication.processEvents()
    export_panel = VoroCrustGui.active_panel("export")
    check(export_panel is not None and Gui.Control.activeDialog(), "no export panel")
    export_panel.folder.setText(export)
    for name, box_widget in export_panel.formats.items():
        box_widget.setChecked(name in ("vtu", "obj"))
    ok, _ = task_buttons()
    ok.click()
    wait(lambda: not Gui.Control.activeDialog(), "the export panel to close", timeout=300)
    with open(os.path.join(out, "mesh.vtu"), "rb") as a, open(os.path.join(export, "mesh.vtu"), "rb") as b:
        check(a.read() == b.read(), "exported mesh.vtu differs from the run's")
    check(os.path.isfile(os.path.join(export, "surface.obj")), "surface.obj not exported")

    # A bad input: the library's message in the panel, the panel still open, no crash.
    overlap = overlapping_box(doc)
    preferences.SetString("OutputFolder", os.path.join(WORK, "bad"))
    panel = open_panel([box, overlap])
    ok, cancel = task_buttons()
    ok.click()
    wait(lambda: not panel.running(), "the run on bad input")
    check(panel.status.text().startswith("Failed:") and "intersect" in panel.status.text(),
          "status after bad input: %s" % panel.status.text())
    check(Gui.Control.activeDialog(), "the failed run closed the panel")
    check(not os.path.exists(os.path.join(WORK, "bad")), "the failed run wrote files")
    summary["invalid"] = panel.status.text()
    cancel.click()
    wait(lambda: not Gui.Control.activeDialog(), "the panel to close", timeout=60)

    # A sketch through the same command: the 2D panel, its run, the cells in the document.
    sketch, (low, high) = sketch_domain(doc)
    out2d = os.path.join(WORK, "out2d")
    preferences.SetString("OutputFolder", out2d)
    preferences.SetString("PlaneFormats", "vtu,svg,openfoam")
    panel = open_panel([sketch])
    check(isinstance(panel, VoroCrustGui.VoronoiMesh2dPanel), "sketches open %s" % type(panel).__name__)
    check(not hasattr(panel, "smooth") and panel.chosen_formats() == ["vtu", "svg", "openfoam"],
          "the 2D panel offers %s, formats %s" % (sorted(panel.widgets), panel.chosen_formats()))
    panel.max_size.setValue(0.3)
    panel.tolerance.setValue(0.01)
    ok, _ = task_buttons()
    ok.click()
    wait(lambda: not panel.running(), "the 2D run")
    QtGui.QApplication.processEvents()
    if panel.result_object is None:
        raise AssertionError("the 2D run failed: %s" % panel.status.text())
    cells = [o for o in panel.result_object.Group if o.isDerivedFrom("Mesh::Feature")]
    check(len(cells) == 1 and low <= cells[0].Mesh.Area <= high, "2D cells: %s, area %r not in [%r, %r]" % (
        [o.Label for o in panel.result_object.Group], cells[0].Mesh.Area if cells else None, low, high))
    for name in ("mesh.vtu", "mesh.svg", "report.json"):
        check(os.path.isfile(os.path.join(out2d, name)), "%s not written" % name)
    mesh_ok, log = check_mesh_ok(os.path.join(out2d, "case"))
    check(mesh_ok, "checkMesh on the 2D case: " + log)
    summary["plane_area"] = cells[0].Mesh.Area

    summary.update(out=out, cells=result.CellCount, volume=result.Volume, input_volume=input_volume, materials=3,
                   seeds=result.SeedCount, triangles=result.SurfaceTriangles, stop_after=STOP_AFTER,
                   progress_updates=len(fractions))
    with open(SUMMARY, "w") as f:
        json.dump(summary, f, indent=1)


code = 1
try:
    main()
    code = 0
except BaseException:
    # FreeCAD's window takes over stdout and stderr: the driver reads the failure from a file.
    with open(os.path.join(WORK, "failure.txt"), "w") as f:
        f.write(traceback.format_exc())
sys.stdout.flush()
sys.stderr.flush()
os._exit(code)  # FreeCAD's window would otherwise stay open (and ask about the unsaved document)
