#!/usr/bin/env python3
"""One model and one set of options give byte-identical seeds.csv (and mesh.vtu) from every front
end: the vorocrust program, the Python module, the MeshLab filter in meshlabserver and the FreeCAD
workbench in freecadcmd, each given the options its own way (--smooth, smooth=True, the filter's
"Smooth surface", Parameters(smooth=True)).

The model is taken as MeshLab opens it (single precision, written back as PLY), so that every
front end starts from the same coordinates: FreeCAD's Mesh objects hold single precision too.

Cases: igl_bunny.off with smooth (a scan), cgal_joint.off with the default rules (CAD).

Run by CTest as: python3 test_same_seeds.py --cli ... --package ... --plugin ... --meshlabserver ...
    --meshlab-lib-dir ... --freecadcmd ... --build ... --models ... --work ...
"""
import argparse
import os
import shutil
import subprocess
import sys
import unittest

p = argparse.ArgumentParser()
for name in ("cli", "package", "plugin", "meshlabserver", "meshlab-lib-dir", "freecadcmd", "build", "models", "work"):
    p.add_argument("--" + name, required=True)
ARGS = p.parse_args()
del sys.argv[1:]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "meshlab"))
sys.path.insert(0, ARGS.package)
import vorocrust  # noqa: E402
from meshlab_runs import make_prefix, option_rows, option_table, run_meshlabserver, script  # noqa: E402

SEED = 11
FORMATS = ["seeds", "vtu"]
OUTPUTS = ("seeds.csv", "mesh.vtu")

FREECAD_SCRIPT = r'''
import os, sys, traceback
try:
    import FreeCAD as App
    import Mesh
    import VoroCrustMesher
    doc = App.newDocument("Same")
    obj = doc.addObject("Mesh::Feature", "model")
    obj.Mesh = Mesh.Mesh(os.environ["SAME_MODEL"])
    parameters = VoroCrustMesher.Parameters(smooth=os.environ["SAME_SMOOTH"] == "1", seed=int(os.environ["SAME_SEED"]))
    VoroCrustMesher.voronoi_mesh([obj], parameters, output_dir=os.environ["SAME_OUT"],
                                 formats=os.environ["SAME_FORMATS"].split(","), progress=lambda phase, fraction: True)
except BaseException:
    traceback.print_exc()
    sys.stdout.flush()
    sys.exit(1)
sys.exit(0)
'''


class SameSeeds(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = os.path.abspath(ARGS.work)
        shutil.rmtree(cls.work, ignore_errors=True)
        os.makedirs(cls.work)
        cls.server, _ = make_prefix(cls.work, ARGS.meshlabserver, ARGS.meshlab_lib_dir, ARGS.plugin)
        cls.options = option_table(ARGS.cli)
        # The FreeCAD add-on, installed as its users install it, into a private user folder.
        cls.userdata = os.path.join(cls.work, "freecad")
        subprocess.run(["cmake", "--install", ARGS.build, "--component", "freecad", "--prefix",
                        os.path.join(cls.userdata, "Mod")], check=True, capture_output=True)
        with open(os.path.join(cls.work, "freecad_run.py"), "w") as f:
            f.write(FREECAD_SCRIPT)

    def case(self, name, model, smooth):
        work = os.path.join(self.work, name)
        os.makedirs(work)
        loaded = os.path.join(work, "loaded.ply")
        r = run_meshlabserver(self.server, work, "-i", os.path.join(ARGS.models, model), "-o", loaded)
        self.assertEqual(r.returncode, 0, r.stdout[-3000:])
        out = {}

        out["cli"] = os.path.join(work, "cli")
        r = subprocess.run([ARGS.cli, "mesh", loaded, "-o", out["cli"], "--seed", str(SEED), "--format", ",".join(FORMATS),
                            "-q"] + (["--smooth"] if smooth else []), capture_output=True, text=True, timeout=1800)
        self.assertEqual(r.returncode, 0, r.stderr)

        out["python"] = os.path.join(work, "python")
        vorocrust.mesh(loaded, smooth=smooth, seed=SEED, output_dir=out["python"], formats=FORMATS)

        out["meshlab"] = os.path.join(work, "meshlab")
        rows = option_rows(self.options, [o["name"] for o in self.options],
                           dict(smooth=smooth, seed=SEED, formats=FORMATS))
        rows.append(f'  <Param type="RichString" name="outputFolder" value="{out["meshlab"]}"/>')
        rows.append('  <Param type="RichBool" name="allVisibleLayers" value="false"/>')
        mlx = script(os.path.join(work, "voronoi.mlx"), "VoroCrust Voronoi Mesh", rows)
        r = run_meshlabserver(self.server, work, "-i", loaded, "-s", mlx)
        self.assertEqual(r.returncode, 0, r.stdout[-3000:])

        out["freecad"] = os.path.join(work, "freecad_out")
        env = dict(os.environ, HOME=os.path.join(work, "home"), FREECAD_USER_DATA=self.userdata, SAME_MODEL=loaded,
                   SAME_SMOOTH="1" if smooth else "0", SAME_SEED=str(SEED), SAME_OUT=out["freecad"],
                   SAME_FORMATS=",".join(FORMATS))
        env.pop("PYTHONPATH", None)  # the add-on brings its own module
        r = subprocess.run([ARGS.freecadcmd, os.path.join(self.work, "freecad_run.py")], capture_output=True, text=True,
                           env=env, cwd=work, timeout=1800)
        self.assertEqual(r.returncode, 0, r.stdout[-3000:] + r.stderr[-3000:])

        for output in OUTPUTS:
            contents = {}
            for front_end, folder in out.items():
                with open(os.path.join(folder, output), "rb") as f:
                    contents[front_end] = f.read()
            for front_end, data in contents.items():
                self.assertTrue(data == contents["cli"], f"{model}: {output} of {front_end} differs from the program's")
        with open(os.path.join(out["cli"], "seeds.csv")) as f:
            seeds = sum(1 for _ in f) - 1
        print(f"{model}{' (smooth)' if smooth else ''}: {seeds} seeds, seeds.csv and mesh.vtu byte for byte the same "
              f"from {', '.join(out)}")

    def test_a_scan_smoothed(self):
        self.case("bunny", "igl_bunny.off", smooth=True)

    def test_a_cad_model(self):
        self.case("joint", "cgal_joint.off", smooth=False)


if __name__ == "__main__":
    unittest.main(verbosity=2)
