#!/usr/bin/env python3
"""Runs one of the FreeCAD add-on's tests in real FreeCAD and checks what it wrote.

  app: installs the add-on with `cmake --install --component freecad` into
       WORK/userdata/Mod, runs `freecadcmd freecad_app_test.py` with FREECAD_USER_DATA there;
  gui: installs it with scripts/install-freecad-addon.sh into the default place under a
       private HOME, runs `xvfb-run freecad freecad_gui_test.py` (QTWEBENGINE_DISABLE_SANDBOX=1).

Either way HOME is WORK/home and TMPDIR WORK/tmp, so FreeCAD's configuration, caches and
temporary files stay out of the real home and /tmp.
The script inside FreeCAD exits non-zero on any failure and leaves a JSON summary; this driver
then reads the written mesh.vtu with VTK's own reader (VTK's Python modules, from python3-paraview) and checks its cells and
volumes against the summary.

Run by CTest as: python3 run_freecad_test.py MODE SOURCE_DIR BUILD_DIR WORK_DIR CMAKE FREECAD [XVFB_RUN]
"""
import json
import os
import shutil
import subprocess
import sys
import unittest

MODE, SOURCE, BUILD, WORK, CMAKE, FREECAD = sys.argv[1:7]
XVFB_RUN = sys.argv[7] if len(sys.argv) > 7 else None
del sys.argv[1:]
HERE = os.path.dirname(os.path.abspath(__file__))


def run(command, env, timeout=1200):
    r = subprocess.run(command, capture_output=True, text=True, env=env, timeout=timeout, cwd=WORK)
    return r.returncode, r.stdout + r.stderr


class FreeCAD(unittest.TestCase):
    def test_addon_in_freecad(self):
        shutil.rmtree(WORK, ignore_errors=True)
        home = os.path.join(WORK, "home")
        os.makedirs(home)
        summary = os.path.join(WORK, "summary.json")
        # FreeCAD leaves start-page thumbnails in its temporary folder: WORK's, removed at the end.
        tmp = os.path.join(WORK, "tmp")
        os.makedirs(tmp)
        env = dict(os.environ, HOME=home, TMPDIR=tmp, VOROCRUST_TEST_WORK=WORK, VOROCRUST_TEST_SUMMARY=summary)
        env.pop("FREECAD_USER_DATA", None)
        env.pop("PYTHONPATH", None)  # the add-on must bring its own module
        if MODE == "app":
            userdata = os.path.join(WORK, "userdata")
            code, log = run([CMAKE, "--install", BUILD, "--component", "freecad", "--prefix",
                             os.path.join(userdata, "Mod")], env)
            self.assertEqual(code, 0, log)
            env["FREECAD_USER_DATA"] = userdata
            code, log = run([FREECAD, os.path.join(HERE, "freecad_app_test.py")], env)
            installed = os.path.join(userdata, "Mod", "VoroCrust")
        else:
            code, log = run(["bash", os.path.join(SOURCE, "scripts", "install-freecad-addon.sh")],
                            dict(env, VOROCRUST_BUILD_DIR=BUILD))
            self.assertEqual(code, 0, log)
            installed = os.path.join(home, ".local", "share", "FreeCAD", "Mod", "VoroCrust")
            env["QTWEBENGINE_DISABLE_SANDBOX"] = "1"
            code, log = run([XVFB_RUN, "-a", "-s", "-screen 0 1280x1024x24", FREECAD,
                             os.path.join(HERE, "freecad_gui_test.py")], env)
            # xvfb-run exits 5 when it cannot remove its own temporary folder, hiding FreeCAD's
            # status: the test's summary (written last, after every check) and no failure file say
            # how FreeCAD ended.
            if (code == 5 and "problem while cleaning up temporary directory" in log and os.path.isfile(summary)
                    and not os.path.isfile(os.path.join(WORK, "failure.txt"))):
                code = 0
        failure = os.path.join(WORK, "failure.txt")
        if os.path.isfile(failure):
            with open(failure) as f:
                log += "\n" + f.read()
        self.assertEqual(code, 0, log[-6000:])
        self.assertTrue(os.path.isfile(summary), "no summary: " + log[-6000:])
        with open(summary) as f:
            s = json.load(f)
        print(json.dumps(s, indent=1))
        self.assertTrue(s["vorocrust_module"].startswith(installed), s["vorocrust_module"])
        self.check_vtu(os.path.join(s["out"], "mesh.vtu"), s)
        shutil.rmtree(WORK, ignore_errors=True)

    def check_vtu(self, path, summary):
        import vtk

        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        self.assertEqual(grid.GetNumberOfCells(), summary["cells"])
        volumes = grid.GetCellData().GetArray("volume")
        total = sum(volumes.GetValue(i) for i in range(volumes.GetNumberOfTuples()))
        self.assertAlmostEqual(total, summary["volume"], delta=1e-9 * summary["volume"])
        # VTK's own measure: the volume inside the grid's outer faces (VTK's triangulation of the
        # cells' near-degenerate polygons makes its per-cell volumes only close).
        outer = vtk.vtkDataSetSurfaceFilter()
        outer.SetInputData(grid)
        triangles = vtk.vtkTriangleFilter()
        triangles.SetInputConnection(outer.GetOutputPort())
        mass = vtk.vtkMassProperties()
        mass.SetInputConnection(triangles.GetOutputPort())
        mass.Update()
        self.assertAlmostEqual(mass.GetVolume(), total, delta=1e-6 * total)
        self.assertAlmostEqual(total, summary["input_volume"], delta=0.02 * summary["input_volume"])
        materials = grid.GetCellData().GetArray("material")
        self.assertEqual({materials.GetValue(i) for i in range(materials.GetNumberOfTuples())},
                         set(range(1, summary.get("materials", 1) + 1)))


if __name__ == "__main__":
    unittest.main(verbosity=2)
