#!/usr/bin/env python3
"""Files do not depend on the host application's locale. FreeCAD and MeshLab are Qt programs, and
Qt sets the C library's locale from the environment: in a German session LC_NUMERIC is de_DE,
where printf writes 0,5 for one half (and a seeds.csv line would gain four commas). The Python
module, run in that locale as the FreeCAD workbench runs it, must write every file byte for byte
as the `vorocrust` program does in the C locale.

The decimal-comma locale is compiled from Debian's `locales` package (localedef) into a temporary
folder, which LOCPATH names.

Run by CTest as: PYTHONPATH=BUILD/python /usr/bin/python3 test_locale.py VOROCRUST_BINARY MODELS_DIR
"""
import filecmp
import json
import locale
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import vorocrust

BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]

MODEL = os.path.join(MODELS, "sandia_non_manifold_box.obj")  # several materials, every output


class FilesInADecimalCommaLocale(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="vorocrust_locale_")
        locales = os.path.join(cls.dir, "locales")
        # localedef exits 1 for warnings about the source; the compiled locale is what counts.
        os.makedirs(locales)
        made = subprocess.run(["localedef", "-i", "de_DE", "-f", "UTF-8", os.path.join(locales, "de_DE.UTF-8")],
                              capture_output=True, text=True)
        if not os.path.isdir(os.path.join(locales, "de_DE.UTF-8")):
            raise RuntimeError("localedef could not compile de_DE (is Debian's `locales` installed?): " + made.stderr)
        os.environ["LOCPATH"] = locales
        cls.cli_out = os.path.join(cls.dir, "cli")
        r = subprocess.run([BINARY, "mesh", MODEL, "-o", cls.cli_out, "--seed", "3", "-q"],
                           capture_output=True, text=True, timeout=600, env={**os.environ, "LC_ALL": "C"})
        if r.returncode != 0:
            raise RuntimeError(r.stderr)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_the_module_in_de_DE_writes_what_the_program_writes_in_C(self):
        out = os.path.join(self.dir, "module")
        previous = locale.setlocale(locale.LC_NUMERIC)
        locale.setlocale(locale.LC_NUMERIC, "de_DE.UTF-8")
        try:
            self.assertEqual(locale.localeconv()["decimal_point"], ",")
            self.assertEqual(locale.format_string("%g", 0.5), "0,5")  # what printf would write
            result = vorocrust.mesh(MODEL, seed=3)
            vorocrust.write_outputs(result, out)
        finally:
            locale.setlocale(locale.LC_NUMERIC, previous)
        files = []
        for root, _, names in os.walk(self.cli_out):
            files += [os.path.relpath(os.path.join(root, n), self.cli_out) for n in names]
        # report.json and report.html hold timings, report.json the command line, quality.svg the
        # output path in its title.
        compared = sorted(f for f in files if f not in ("report.json", "report.html", "quality.svg"))
        for name in ("seeds.csv", "balls.csv", "balls.vtk", "surface.obj", "surface.ply", "mesh.vtu", "MESH",
                     "case/constant/polyMesh/points", "pflotran/mesh.uge"):
            self.assertIn(name, compared)
        for name in compared:
            self.assertTrue(filecmp.cmp(os.path.join(self.cli_out, name), os.path.join(out, name), shallow=False),
                            name + " differs between the program in C and the module in de_DE")
        # report.html: the same page but for the timings (the program's and the module's differ).
        def page(folder):
            with open(os.path.join(folder, "report.html")) as f:
                return re.sub(r'<table id="timings">.*?</table>', "", f.read(), flags=re.S)

        self.assertIn("report.html", files)
        self.assertEqual(page(self.cli_out), page(out), "report.html differs between C and de_DE")
        with open(os.path.join(out, "seeds.csv")) as f:
            self.assertEqual(f.readline().strip().split(","), ["x", "y", "z", "label", "radius", "kind"])
            self.assertTrue(all(len(line.split(",")) == 6 for line in f), "a seeds.csv line has a decimal comma")
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["cells"]["cells"], result.cells.num_cells)
        print("%d files byte for byte the same: %s" % (len(compared), ", ".join(compared)))


if __name__ == "__main__":
    unittest.main(verbosity=2)
