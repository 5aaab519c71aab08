"""The VoroCrust workbench's commands and task panels.

"Voronoi mesh" meshes the selected Mesh objects and Part solids: a task panel takes the
parameters (remembered in FreeCAD's preferences, under Mod/VoroCrust), runs the mesher in a
worker thread while a progress bar follows it, and its Cancel stops the run (nothing is written
then). When a run has cells, a window shows a cut through them (the picture report.html opens
with) and opens the result in ParaView when it is installed, or report.html in the browser.
"Export Voronoi mesh" writes the files of a selected result again. Errors go to FreeCAD's
report view and the panel, never to a crash. The work itself is VoroCrustMesher's.
"""

import os
import shutil
import subprocess
import threading

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import VoroCrustMesher
import VoroCrustResources
import vorocrust

PREFERENCES = "User parameter:BaseApp/Preferences/Mod/VoroCrust"
COMMANDS = ["VoroCrust_VoronoiMesh", "VoroCrust_Export"]

# The panel shown last, for scripts that drive the GUI (tests).
_panels = {}


def active_panel(kind="mesh"):
    """The Voronoi mesh ("mesh") or export ("export") panel or the result window ("result") opened
    last, or None."""
    return _panels.get(kind)


def preferences():
    return App.ParamGet(PREFERENCES)


def report_error(error):
    """An error as FreeCAD shows messages: in the report view, in the library's words."""
    App.Console.PrintError("VoroCrust: %s\n" % error)


def _spec(name):
    return next(o for o in VoroCrustMesher.OPTIONS if o["name"] == name)


def _remembered(p, o):
    """An option's value as the preferences remember it (under its property name), or its
    default; numbers as the widgets hold them (unset as the table's unset_number)."""
    key, default = o["freecad"], VoroCrustMesher.property_value(o, o["default"])
    if o["kind"] == "flag":
        return p.GetBool(key, default)
    if o["kind"] == "integer":
        return p.GetInt(key, default)
    if o["kind"] == "real":
        return p.GetFloat(key, default)
    return p.GetString(key, default)


def _remember_value(p, o, value):
    key = o["freecad"]
    if o["kind"] == "flag":
        p.SetBool(key, value)
    elif o["kind"] == "integer":
        p.SetInt(key, value)
    elif o["kind"] == "real":
        p.SetFloat(key, value)
    else:
        p.SetString(key, value)


def _option_widget(o, value):
    """The widget of an option: a check box, a spin box (its lowest value "auto" or "none" where
    the option may be unset), a list of choices, or a line for a file or the box."""
    tip = VoroCrustMesher.option_help(o)
    if o["kind"] == "flag":
        widget = QtGui.QCheckBox()
        widget.setChecked(bool(value))
    elif o["kind"] in ("integer", "real"):
        widget = QtGui.QSpinBox() if o["kind"] == "integer" else QtGui.QDoubleSpinBox()
        limit = 2 ** 31 - 1 if o["kind"] == "integer" else 1e9
        low = o["min"] if o["min"] is not None else -limit
        high = o["max"] if o["max"] is not None else limit
        if o["also"] is not None:
            low = min(low, o["also"])
        if o["unset_number"] is not None:
            low = o["unset_number"]
            widget.setSpecialValueText("auto: " + o["default_text"].split(": ", 1)[1])
        if o["kind"] == "integer":
            widget.setRange(int(low), int(high))
        else:
            widget.setDecimals(6)
            widget.setRange(low, high)
            widget.setSingleStep(0.05 if high <= 1 else 1)
        widget.setValue(value)
    elif o["kind"] == "choice":
        widget = QtGui.QComboBox()
        widget.addItems(list(o["choices"]))
        widget.setCurrentText(value)
    else:
        widget = QtGui.QLineEdit(value)
        widget.setPlaceholderText("auto: " + o["default_text"].split(": ", 1)[1])
    widget.setToolTip(tip)
    return widget


def _widget_value(widget):
    if isinstance(widget, QtGui.QCheckBox):
        return widget.isChecked()
    if isinstance(widget, (QtGui.QSpinBox, QtGui.QDoubleSpinBox)):
        return widget.value()
    if isinstance(widget, QtGui.QComboBox):
        return widget.currentText()
    return widget.text()


def _format_boxes(layout, chosen, with_report=True):
    """A check box per format, the files it makes in its label; returns {format: box}."""
    boxes = {}
    for name, files in VoroCrustMesher.FORMATS.items():
        if name == "report" and not with_report:
            continue
        box = QtGui.QCheckBox("%s (%s)" % (name, ", ".join(files)))
        box.setChecked(name in chosen)
        layout.addWidget(box)
        boxes[name] = box
    return boxes


def _folder_row(initial):
    """A line edit with a Browse button; returns (widget, line edit)."""
    row = QtGui.QWidget()
    layout = QtGui.QHBoxLayout(row)
    layout.setContentsMargins(0, 0, 0, 0)
    edit = QtGui.QLineEdit(initial)
    browse = QtGui.QPushButton("Browse...")

    def choose():
        folder = QtGui.QFileDialog.getExistingDirectory(row, "Output folder", edit.text())
        if folder:
            edit.setText(folder)

    browse.clicked.connect(choose)
    layout.addWidget(edit)
    layout.addWidget(browse)
    return row, edit


class VoronoiMeshPanel:
    """The task panel of "Voronoi mesh"."""

    def __init__(self, objects):
        self.objects = list(objects)
        self.doc = self.objects[0].Document
        self.result_object = None
        self._worker = None
        self._state = {}
        self._cancel = False
        self.form = self._build()
        self._timer = QtCore.QTimer()
        self._timer.setInterval(100)
        self._timer.timeout.connect(self._poll)
        _panels["mesh"] = self

    def _build(self):
        p = preferences()
        form, layout, grid = self._option_form(
            "Voronoi mesh", "Input (each solid or mesh one material): ",
            ("Tessellation tolerance", "Tolerance", 0.1, 1e-4, "Largest distance between a Part shape and its triangles"),
            [o for o in VoroCrustMesher.OPTIONS if o["name"] != "formats"])
        chosen = p.GetString("Formats", ",".join(VoroCrustMesher.DEFAULT_FORMATS)).split(",")
        self._outputs_and_progress(layout, grid, lambda box_layout: _format_boxes(box_layout, chosen, with_report=False))
        return form

    def _outputs_and_progress(self, layout, grid, make_boxes):
        """The rest of a panel's form: the output folder, the format boxes make_boxes(layout)
        returns, the progress bar and the status line."""
        folder_row, self.folder = _folder_row(preferences().GetString("OutputFolder", "") or
                                              VoroCrustMesher.default_output_dir(self.doc))
        grid.addRow("Output folder", folder_row)
        formats = QtGui.QGroupBox("Outputs (report.json is always written)")
        self.formats = make_boxes(QtGui.QVBoxLayout(formats))
        layout.addWidget(formats)
        self._inputs += [folder_row, formats]
        self.progress = QtGui.QProgressBar()
        self.progress.setRange(0, 100)
        self.progress.setValue(0)
        self.status = QtGui.QLabel("OK runs the mesher; Cancel stops it.")
        self.status.setWordWrap(True)
        layout.addWidget(self.progress)
        layout.addWidget(self.status)

    def _option_form(self, title, inputs_text, tolerance, options):
        """The panel's form: its title, the inputs, the tolerance (label, preference key,
        default, lowest value, tip) and a widget per option of `options`, in the table's order;
        each widget is also an attribute of the panel under the option's name
        (self.sharp_angle). Returns (form, its layout, the grid of rows)."""
        p = preferences()
        form = QtGui.QWidget()
        form.setWindowTitle(title)
        form.setWindowIcon(QtGui.QIcon(VoroCrustResources.icon("VoronoiMesh.svg")))
        layout = QtGui.QVBoxLayout(form)
        inputs = QtGui.QLabel(inputs_text + ", ".join(o.Label for o in self.objects))
        inputs.setWordWrap(True)
        layout.addWidget(inputs)
        grid = QtGui.QFormLayout()
        layout.addLayout(grid)
        label, key, default, lowest, tip = tolerance
        self.tolerance = QtGui.QDoubleSpinBox()
        self.tolerance.setRange(lowest, 1e6)
        self.tolerance.setDecimals(6 if lowest < 1e-4 else 4)
        self.tolerance.setSingleStep(0.05)
        self.tolerance.setValue(p.GetFloat(key, default))
        self.tolerance.setToolTip(tip)
        grid.addRow(label, self.tolerance)
        self.widgets = {}
        self._inputs = [self.tolerance]
        for o in options:
            widget = _option_widget(o, _remembered(p, o))
            self.widgets[o["name"]] = widget
            setattr(self, o["name"], widget)
            grid.addRow(o["label"] + (" (%s)" % o["unit"] if o["unit"] else ""), widget)
            self._inputs.append(widget)
        self.cvt_iterations.setEnabled(self.interior.currentText() == "cvt")
        self.interior.currentTextChanged.connect(lambda mode: self.cvt_iterations.setEnabled(mode == "cvt"))
        return form, layout, grid

    def parameters(self):
        """The parameters as the panel shows them."""
        options = {name: VoroCrustMesher.option_value(_spec(name), _widget_value(widget))
                   for name, widget in self.widgets.items()}
        return VoroCrustMesher.Parameters(self.tolerance.value(), **options)

    def chosen_formats(self):
        return [name for name, box in self.formats.items() if box.isChecked()]

    def _remember(self, parameters):
        p = preferences()
        p.SetFloat("Tolerance", parameters.tolerance)
        for name, widget in self.widgets.items():
            _remember_value(p, _spec(name), _widget_value(widget))
        p.SetString("OutputFolder", self.folder.text())
        p.SetString("Formats", ",".join(self.chosen_formats()))

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def running(self):
        """True while a run is under way."""
        return self._worker is not None

    def accept(self):
        """OK: starts a run; the panel stays open until it ends."""
        if self.running():
            return False
        parameters = self.parameters()
        self._remember(parameters)
        try:
            work = self._prepare(parameters)
        except Exception as e:  # the library's and FreeCAD's errors alike become messages
            self._failed(e)
            return False
        self._cancel = False
        self._state = {"phase": "starting", "fraction": None, "done": False}
        self._worker = threading.Thread(target=self._work, args=work, daemon=True)
        self._set_inputs_enabled(False)
        self.status.setText("Meshing...")
        self._worker.start()
        self._timer.start()
        return False

    def reject(self):
        """Cancel: stops a run (which then writes nothing), or closes the panel."""
        if self.running():
            self._cancel = True
            self.status.setText("Cancelling...")
            return False
        return True

    def _prepare(self, parameters):
        """What the worker needs, read from the document in the GUI thread: _work's arguments."""
        return VoroCrustMesher.model_of(self.objects, parameters.tolerance), parameters, self.folder.text(), self.chosen_formats()

    def _work(self, model, parameters, folder, formats):
        # The worker thread: only the library runs here (meshing, writing the files), no FreeCAD
        # object is touched.
        try:
            self._state["result"] = VoroCrustMesher.run(model, parameters, folder, formats, self._progress)
            self._state["parameters"] = parameters
        except BaseException as e:  # handed to the GUI thread, which reports it
            self._state["error"] = e
        finally:
            self._state["done"] = True

    def _progress(self, phase, fraction):
        self._state["phase"], self._state["fraction"] = phase, fraction
        return not self._cancel

    def _poll(self):
        fraction = self._state.get("fraction")
        if fraction is None:
            self.progress.setRange(0, 0)  # busy: the library does not know how far it is
        else:
            self.progress.setRange(0, 100)
            self.progress.setValue(int(100 * fraction))
        if not self._cancel:
            self.status.setText("Meshing: %s" % self._state.get("phase"))
            Gui.getMainWindow().statusBar().showMessage("VoroCrust: %s" % self._state.get("phase"))
        if not self._state.get("done"):
            return
        Gui.getMainWindow().statusBar().clearMessage()
        self._timer.stop()
        self._worker.join()
        self._worker = None
        self.progress.setRange(0, 100)
        self.progress.setValue(0)
        self._set_inputs_enabled(True)
        error = self._state.get("error")
        if isinstance(error, vorocrust.Cancelled):
            App.Console.PrintWarning("VoroCrust: cancelled; nothing was written\n")
            self.status.setText("Cancelled; nothing was written.")
            return
        if error is not None:
            self._failed(error)
            return
        try:
            self.result_object = self._add_result()
        except Exception as e:
            self._failed(e)
            return
        self.progress.setValue(100)
        self.status.setText("Done: %s" % self.result_object.Label)
        Gui.Control.closeDialog()
        if self._shows_result_window():
            try:
                ResultWindow(self.result_object, self._state["result"], self._state["result"].written).show()
            except Exception as e:  # the result is in the document and on disk: say so, go on
                report_error(e)

    def _add_result(self):
        return VoroCrustMesher.add_result(self.doc, self.objects, self._state["parameters"], self._state["result"],
                                          self.folder.text(), self.chosen_formats())

    def _shows_result_window(self):
        return self._state["result"].stop_after == "cells"

    def _failed(self, error):
        report_error(error)
        self.status.setText("Failed: %s" % error)

    def _set_inputs_enabled(self, enabled):
        for widget in self._inputs:
            widget.setEnabled(enabled)
        self.cvt_iterations.setEnabled(enabled and self.interior.currentText() == "cvt")


class VoronoiMesh2dPanel(VoronoiMeshPanel):
    """The task panel of "Voronoi mesh" on sketches and Draft wires: a 2D domain (paper 2.6),
    with the options a 2D run takes, the slab thickness of the volume formats, and the 2D
    formats. Closed wires inside an odd number of others bound holes; open wires are breaklines."""

    def _build(self):
        p = preferences()
        form, layout, grid = self._option_form(
            "Voronoi mesh (2D)", "2D domain (closed wires bound regions and holes, open wires are breaklines): ",
            ("Curve tolerance", "CurveTolerance", 0.01, 1e-6, "Largest distance between a curve and the segments it becomes"),
            VoroCrustMesher.PLANE_OPTIONS)
        self.thickness = QtGui.QDoubleSpinBox()
        self.thickness.setRange(1e-9, 1e9)
        self.thickness.setDecimals(6)
        self.thickness.setValue(p.GetFloat("Thickness", 1.0))
        self.thickness.setToolTip("Thickness of the one-cell slab the OpenFOAM, TOUGH, PFLOTRAN and Exodus files hold")
        grid.addRow("Slab thickness", self.thickness)
        self._inputs.append(self.thickness)
        chosen = p.GetString("PlaneFormats", ",".join(VoroCrustMesher.DEFAULT_PLANE_FORMATS)).split(",")

        def boxes(box_layout):
            made = {}
            for name in VoroCrustMesher.PLANE_FORMATS:
                made[name] = QtGui.QCheckBox(name)
                made[name].setChecked(name in chosen)
                box_layout.addWidget(made[name])
            return made

        self._outputs_and_progress(layout, grid, boxes)
        return form

    def _remember(self, parameters):
        p = preferences()
        p.SetFloat("CurveTolerance", parameters.tolerance)
        p.SetFloat("Thickness", self.thickness.value())
        for name, widget in self.widgets.items():
            _remember_value(p, _spec(name), _widget_value(widget))
        p.SetString("OutputFolder", self.folder.text())
        p.SetString("PlaneFormats", ",".join(self.chosen_formats()))

    def _prepare(self, parameters):
        domain, self._placement = VoroCrustMesher.planar_domain(self.objects, parameters.tolerance)
        return domain, parameters, self.folder.text(), self.chosen_formats(), self.thickness.value()

    def _work(self, domain, parameters, folder, formats, thickness):
        # The worker thread: only the library runs here.
        try:
            self._state["result"] = VoroCrustMesher.run_2d(domain, parameters, folder, formats, thickness)
            self._state["parameters"] = parameters
        except BaseException as e:
            self._state["error"] = e
        finally:
            self._state["done"] = True

    def _add_result(self):
        return VoroCrustMesher.add_result_2d(self.doc, self._state["result"], self._placement)

    def _shows_result_window(self):
        return False


class ResultWindow:
    """A finished run at a glance: the cut through its cells coloured by material, with buttons
    that open its files in ParaView (when installed) and report.html in the web browser."""

    def __init__(self, obj, result, written):
        self.written = [os.path.abspath(os.fspath(p)) for p in written]
        self.dialog = QtGui.QDialog(Gui.getMainWindow())
        self.dialog.setWindowTitle("VoroCrust: " + obj.Label)
        layout = QtGui.QVBoxLayout(self.dialog)
        pixmap = QtGui.QPixmap()
        pixmap.loadFromData(QtCore.QByteArray(result.cut_picture_png()), "PNG")
        self.picture = QtGui.QLabel()
        self.picture.setPixmap(pixmap)
        layout.addWidget(self.picture)
        caption = QtGui.QLabel("%d cells, cut across the mesh's thinnest extent; each colour a material. "
                               "%s" % (obj.CellCount, " ".join(result.summary[:1])))
        caption.setWordWrap(True)
        layout.addWidget(caption)
        buttons = QtGui.QDialogButtonBox(QtGui.QDialogButtonBox.Close)
        self.paraview_button = buttons.addButton("Open in ParaView", QtGui.QDialogButtonBox.ActionRole)
        self.paraview_button.setEnabled(self.paraview_command() is not None)
        if self.paraview_command() is None:
            self.paraview_button.setToolTip("needs ParaView (`paraview` on the PATH) and mesh.vtu or mesh.exo")
        self.paraview_button.clicked.connect(self.open_paraview)
        self.report_button = buttons.addButton("Open report", QtGui.QDialogButtonBox.ActionRole)
        self.report_button.setEnabled(self._written("report.html") is not None)
        self.report_button.clicked.connect(self.open_report)
        buttons.rejected.connect(self.dialog.close)
        layout.addWidget(buttons)
        _panels["result"] = self

    def _written(self, name):
        return next((p for p in self.written if os.path.basename(p) == name), None)

    def paraview_command(self):
        """The command that opens the result in ParaView, or None without ParaView or a file it reads."""
        paraview = shutil.which("paraview")
        mesh = self._written("mesh.vtu") or self._written("mesh.exo")
        return [paraview, mesh] if paraview and mesh else None

    def open_paraview(self):
        command = self.paraview_command()
        if command:
            subprocess.Popen(command, start_new_session=True)

    def open_report(self):
        path = self._written("report.html")
        if path:
            QtGui.QDesktopServices.openUrl(QtCore.QUrl.fromLocalFile(path))

    def show(self):
        self.dialog.show()


class ExportPanel:
    """The task panel of "Export Voronoi mesh": a folder and the formats to write there."""

    def __init__(self, obj):
        self.obj = obj
        self.written = []
        self.form = QtGui.QWidget()
        self.form.setWindowTitle("Export Voronoi mesh")
        self.form.setWindowIcon(QtGui.QIcon(VoroCrustResources.icon("ExportVoronoiMesh.svg")))
        layout = QtGui.QVBoxLayout(self.form)
        layout.addWidget(QtGui.QLabel("Result: " + obj.Label))
        folder_row, self.folder = _folder_row(preferences().GetString("ExportFolder", "") or obj.OutputFolder)
        layout.addWidget(folder_row)
        box = QtGui.QGroupBox("Outputs")
        self.formats = _format_boxes(QtGui.QVBoxLayout(box), list(obj.Formats) or VoroCrustMesher.DEFAULT_FORMATS)
        layout.addWidget(box)
        self.status = QtGui.QLabel("")
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        _panels["export"] = self

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        formats = [name for name, box in self.formats.items() if box.isChecked()]
        preferences().SetString("ExportFolder", self.folder.text())
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            self.written = VoroCrustMesher.export_result(self.obj, self.folder.text(), formats)
        except Exception as e:
            report_error(e)
            self.status.setText("Failed: %s" % e)
            return False
        finally:
            QtGui.QApplication.restoreOverrideCursor()
        for path in self.written:
            App.Console.PrintMessage("VoroCrust: wrote %s\n" % path)
        return True

    def reject(self):
        return True


class VoronoiMeshCommand:
    """Meshes the selected Mesh objects and Part solids, or the selected sketches and wires in 2D."""

    def GetResources(self):
        return {"Pixmap": VoroCrustResources.icon("VoronoiMesh.svg"), "MenuText": "Voronoi mesh",
                "ToolTip": "Conforming Voronoi mesh of the selected Mesh objects and Part solids (the output "
                           "surface, the seeds and the volume mesh files), or of the selected sketches and "
                           "wires as a 2D domain"}

    def IsActive(self):
        return App.ActiveDocument is not None and any(
            VoroCrustMesher.is_meshable(o) or VoroCrustMesher.is_planar_wire(o) for o in Gui.Selection.getSelection())

    def Activated(self):
        selected = Gui.Selection.getSelection()
        objects = [o for o in selected if VoroCrustMesher.is_meshable(o)]
        wires = [o for o in selected if VoroCrustMesher.is_planar_wire(o)]
        if objects and wires:
            report_error("select either solids and meshes (3D) or sketches and wires (2D), not both")
            return
        if not objects and not wires:
            report_error("select Mesh objects or Part solids, or sketches and wires, to mesh")
            return
        if Gui.Control.activeDialog():
            report_error("close the open task panel first")
            return
        Gui.Control.showDialog(VoronoiMeshPanel(objects) if objects else VoronoiMesh2dPanel(wires))


class ExportCommand:
    """Writes the files of a selected Voronoi mesh result again."""

    def GetResources(self):
        return {"Pixmap": VoroCrustResources.icon("ExportVoronoiMesh.svg"), "MenuText": "Export Voronoi mesh",
                "ToolTip": "Write the selected Voronoi mesh's files (VTU, OpenFOAM, seeds, surface) to a folder"}

    def IsActive(self):
        return any(VoroCrustMesher.is_result(o) for o in Gui.Selection.getSelection())

    def Activated(self):
        results = [o for o in Gui.Selection.getSelection() if VoroCrustMesher.is_result(o)]
        if not results:
            report_error("select a Voronoi mesh result to export")
            return
        if Gui.Control.activeDialog():
            report_error("close the open task panel first")
            return
        Gui.Control.showDialog(ExportPanel(results[0]))


class ViewProviderVoronoiMesh:
    """Shows a VoronoiMesh result in the tree with its icon and its surfaces and seeds below it."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return VoroCrustResources.icon("VoronoiMeshResult.svg")

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None


Gui.addCommand("VoroCrust_VoronoiMesh", VoronoiMeshCommand())
Gui.addCommand("VoroCrust_Export", ExportCommand())
