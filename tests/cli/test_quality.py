#!/usr/bin/env python3
"""`vorocrust quality OUTDIR` as a user meets it: the table, the JSON, quality.svg, the failures.

Run by CTest as: python3 test_quality.py VOROCRUST_BINARY MODELS_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ElementTree

BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]


def run(*args, **kwargs):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=300, **kwargs)


def model(name):
    return os.path.join(MODELS, name)


def ply_copy(source, target):
    """Writes `source` as an ASCII PLY mesh, as the mesher writes OUTDIR/surface.ply."""
    vertices, faces = [], []
    with open(source) as f:
        lines = [line.split() for line in f if line.strip() and not line.startswith("#")]
    if source.endswith(".off"):
        nv, nf = int(lines[1][0]), int(lines[1][1])
        vertices = lines[2:2 + nv]
        faces = [row[1:4] for row in lines[2 + nv:2 + nv + nf]]
    else:  # OBJ
        vertices = [row[1:4] for row in lines if row[0] == "v"]
        faces = [[str(int(i.split("/")[0]) - 1) for i in row[1:4]] for row in lines if row[0] == "f"]
    with open(target, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
                "property double z\nelement face %d\nproperty list uchar int vertex_indices\n"
                "property int back_region\nproperty int front_region\nend_header\n" % (len(vertices), len(faces)))
        for v in vertices:
            f.write(" ".join(v) + "\n")
        for t in faces:
            f.write("3 " + " ".join(t) + " 1 0\n")


class Quality(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.out = os.path.join(self.tmp, "run")
        os.mkdir(self.out)

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def make_run(self, name, report_inputs=None):
        ply_copy(model(name), os.path.join(self.out, "surface.ply"))
        with open(os.path.join(self.out, "report.json"), "w") as f:
            json.dump({"status": "ok", "inputs": report_inputs or [model(name)]}, f)

    def test_a_surface_against_its_own_input(self):
        self.make_run("cgal_joint.off")
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, r"Hausdorff distance\s+0 \(0% of the input's bounding-box diagonal")
        self.assertRegex(r.stdout, r"topology\s+matches: 1 component: 1 closed with Euler characteristic -2")
        self.assertRegex(r.stdout, r"\(446 triangles\)")
        self.assertIn(model("cgal_joint.off"), r.stdout)
        svg = os.path.join(self.out, "quality.svg")
        root = ElementTree.parse(svg).getroot()  # well-formed XML
        self.assertEqual(root.tag, "{http://www.w3.org/2000/svg}svg")
        bars = [e for e in root.iter("{http://www.w3.org/2000/svg}rect") if e.get("fill") == "#4a7fb5"]
        self.assertGreater(len(bars), 0)
        texts = [e.text for e in root.iter("{http://www.w3.org/2000/svg}text")]
        self.assertTrue(any(t.startswith("min ") for t in texts), texts)
        self.assertTrue(any(t.startswith("mean ") for t in texts), texts)

    def test_json_agrees_with_the_histogram_and_counts(self):
        self.make_run("sandia_torus.obj")
        r = run("quality", self.out, "--json", "--samples", "5000")
        self.assertEqual(r.returncode, 0, r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual(doc["triangles"], 9216)
        self.assertEqual(sum(doc["triangle_quality"]["histogram"]["counts"]), 9216)
        self.assertEqual(doc["hausdorff"]["distance"], 0)
        self.assertEqual(doc["hausdorff"]["percent_of_bounding_box_diagonal"], 0)
        self.assertTrue(doc["topology"]["matches"])
        self.assertEqual(doc["topology"]["output"]["euler_characteristic"], [0])
        self.assertEqual(doc["hausdorff"]["input_samples"], 4608 + 13824 + 5000)
        for key in ("min_degrees", "max_degrees", "percent_below_30_degrees", "percent_above_90_degrees"):
            self.assertIn(key, doc["angles"])

    def test_input_option_overrides_report_json_and_topology_can_differ(self):
        self.make_run("igl_bunny.off")
        r = run("quality", self.out, "--input", model("sandia_torus.obj"), "--samples", "2000")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("DIFFERS", r.stdout)
        self.assertIn(model("sandia_torus.obj"), r.stdout)
        self.assertNotRegex(r.stdout, r"Hausdorff distance\s+0 ")

    def test_missing_surface_names_the_file(self):
        with open(os.path.join(self.out, "report.json"), "w") as f:
            json.dump({"inputs": [model("cgal_joint.off")]}, f)
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 3)
        self.assertEqual(r.stdout, "")
        self.assertIn(os.path.join(self.out, "surface.ply"), r.stderr)
        self.assertIn("missing", r.stderr)
        self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.out, "quality.svg")))

    def test_missing_report_and_missing_input_name_their_files(self):
        ply_copy(model("cgal_joint.off"), os.path.join(self.out, "surface.ply"))
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 3)
        self.assertIn(os.path.join(self.out, "report.json"), r.stderr)
        self.assertIn("--input", r.stderr)
        with open(os.path.join(self.out, "report.json"), "w") as f:
            json.dump({"inputs": ["no/such/model.off"]}, f)
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 3)
        self.assertIn("no/such/model.off", r.stderr)
        r = run("quality", self.out, "--input", os.path.join(self.tmp, "absent.obj"))
        self.assertEqual(r.returncode, 3)
        self.assertIn("absent.obj: cannot open: no such file", r.stderr)

    def test_bad_surface_and_missing_folder(self):
        self.make_run("cgal_joint.off")
        with open(os.path.join(self.out, "surface.ply"), "w") as f:
            f.write("ply\nformat ascii 1.0\nelement vertex 3\n")
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 3)
        self.assertIn("surface.ply", r.stderr)
        r = run("quality", os.path.join(self.tmp, "nowhere"))
        self.assertEqual(r.returncode, 3)
        self.assertIn("nowhere: no such output folder", r.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
