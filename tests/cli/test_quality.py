#!/usr/bin/env python3
"""`vorocrust quality OUTDIR` as a user meets it: the table, the JSON, quality.svg, the failures;
the surface figures from OUTDIR/surface.ply, the cell figures from the cells of OUTDIR/seeds.csv.

Run by CTest as: python3 test_quality.py VOROCRUST_BINARY MODELS_DIR
"""
import json
import math
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


def bcc_seeds(path, n):
    """The body-centred cubic lattice of n^3 unit cubes; material where every coordinate is in
    [1.25, n - 2.25], so each material cell is a whole truncated octahedron. Returns the cell count."""
    cells = 0
    with open(path, "w") as f:
        f.write("x,y,z,label,radius,kind\n")
        for i in range(n):
            for j in range(n):
                for k in range(n):
                    for d in (0, 0.5):
                        p = (i + d, j + d, k + d)
                        inside = all(1.25 <= c <= n - 2.25 for c in p)
                        cells += inside
                        f.write("%g,%g,%g,%d,0.5,%s\n" % (*p, inside, "interior" if inside else "outside"))
    return cells


def svg_texts(path):
    root = ElementTree.parse(path).getroot()  # well-formed XML
    return [e.text for e in root.iter("{http://www.w3.org/2000/svg}text")]


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

    def test_a_run_is_measured_against_the_surface_it_started_from(self):
        # An open sheet is meshed in its box: measured against the sheet alone, the box's sides
        # were 19 % of the diagonal away and the topology differed. Measured against the sheet in
        # its box, as the run measured it, the figures are report.json's.
        r = run("mesh", model("gmsh_terrain.stl"), "-o", self.out, "--stop-after", "surface", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(self.out, "report.json")) as f:
            reported = json.load(f)["surface"]["quality"]
        r = run("quality", self.out, "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        measured = json.loads(r.stdout)
        self.assertTrue(measured["topology"]["matches"])
        self.assertEqual(measured["topology"], reported["topology"])
        self.assertLess(measured["hausdorff"]["percent_of_bounding_box_diagonal"], 1)
        self.assertAlmostEqual(measured["hausdorff"]["distance"], reported["hausdorff"]["distance"], places=9)
        volume = measured["enclosed_volume"]
        self.assertEqual(volume, reported["enclosed_volume"])
        self.assertLess(abs(volume["percent_change"]), 0.01)  # the box holds it all
        # The sheet floats in its box, which holds one material, "domain", on both of its sides.
        self.assertEqual([region["name"] for region in volume["regions"]], ["domain"])
        # Domain options given on the command line win over report.json's: a box the terrain
        # does not fit in is refused, naming it.
        r = run("quality", self.out, "--json", "--box", "-1", "-1", "-1", "1", "1", "1")
        self.assertEqual(r.returncode, 4, r.stdout + r.stderr)
        self.assertIn("box", r.stderr)

    def test_a_run_in_a_box_of_its_own_is_measured_in_that_box(self):
        # report.json records the run's box; quality takes it from there when given none.
        r = run("mesh", model("gmsh_terrain.stl"), "-o", self.out, "--stop-after", "surface", "-q",
                "--box", "-50", "-50", "-1000", "3400", "2600", "1500")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["options"]["box"], [-50, -50, -1000, 3400, 2600, 1500])
        reported = report["surface"]["quality"]
        r = run("quality", self.out, "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        measured = json.loads(r.stdout)
        self.assertEqual(measured["topology"], reported["topology"])
        self.assertAlmostEqual(measured["hausdorff"]["distance"], reported["hausdorff"]["distance"], places=9)
        self.assertEqual(measured["enclosed_volume"], reported["enclosed_volume"])
        # The default box instead (another surface) tells another distance and volume.
        r = run("quality", self.out, "--json", "--self-intersections", "resolve")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotEqual(json.loads(r.stdout)["enclosed_volume"]["input"], reported["enclosed_volume"]["input"])

    def test_cells_alone_from_seeds_csv(self):
        # Truncated octahedra: R / r = sqrt(5/3), 14 faces, volume 1/2, edge sqrt(2)/4.
        cells = bcc_seeds(os.path.join(self.out, "seeds.csv"), 6)
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("output surface", r.stdout)
        self.assertIn("cells               %d, of the %d seeds in %s" % (cells, 2 * 6 ** 3, os.path.join(self.out, "seeds.csv")),
                      r.stdout)
        self.assertRegex(r.stdout, r"aspect ratio\s+min 1\.291, mean 1\.291, max 1\.291 \(cell \d+, seed \d+\); 0 above 5")
        self.assertRegex(r.stdout, r"faces per cell\s+min 14, mean 14\.00, max 14")
        self.assertIn("total %.10g\n" % (cells / 2), r.stdout)
        # Edges sqrt(2)/4 against a size of cbrt(1/2); none short. The core's outer cells have a
        # face to no cell: the boundary layer.
        self.assertRegex(r.stdout, r"\ninterior\s+\d+ cells\n  edges / size\s+min 0\.4454 \(cell \d+\); 0% below 0\.01, 0%")
        self.assertRegex(r.stdout, r"dihedral angles\s+min 109\.5, mean 120, max 125\.3 degrees")
        texts = svg_texts(os.path.join(self.out, "quality.svg"))
        self.assertIn("cell quality: " + os.path.join(self.out, "seeds.csv"), texts)
        self.assertNotIn("triangle quality Q = 6S / (sqrt(3) h p) of the output surface", texts)

        r = run("quality", self.out, "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual(list(doc), ["cells"])
        q = doc["cells"]
        self.assertEqual(q["cells"], cells)
        self.assertAlmostEqual(q["aspect_ratio"]["max"], math.sqrt(5 / 3), delta=1e-9)
        self.assertAlmostEqual(q["aspect_ratio"]["min"], math.sqrt(5 / 3), delta=1e-9)
        self.assertEqual(q["aspect_ratio"]["histogram"]["counts"][1], cells)  # [1.25, 1.5)
        self.assertAlmostEqual(q["volume"]["total"], cells / 2, delta=1e-9)
        self.assertAlmostEqual(q["shortest_edge"]["min"], math.sqrt(2) / 4 / 0.5 ** (1 / 3), delta=1e-9)

    def test_surface_and_cells_together(self):
        # A real run: its surface against the model, the cells of its seeds.
        r = run("mesh", model("cgal_joint.off"), "-o", self.out, "--stop-after", "surface", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        r = run("quality", self.out, "--samples", "2000")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("topology            matches", r.stdout)
        self.assertRegex(r.stdout, r"\ncells\s+\d+, of the \d+ seeds in ")
        self.assertIn("histograms          " + os.path.join(self.out, "quality.svg"), r.stdout)
        texts = svg_texts(os.path.join(self.out, "quality.svg"))
        self.assertIn("surface and cell quality: " + self.out, texts)
        self.assertIn("triangle quality Q = 6S / (sqrt(3) h p) of the output surface", texts)
        self.assertIn("cell aspect ratio R / r (circumradius over inradius)", texts)
        r = run("quality", self.out, "--samples", "2000", "--json")
        doc = json.loads(r.stdout)
        # The surface, the aspect ratios, then edges, faces and dihedral angles per layer with cells.
        layers = doc["cells"]["layers"]
        self.assertGreater(layers["boundary_layer_cells"], 0)
        panels = 2 + 3 * ((layers["boundary_layer_cells"] > 0) + (layers["interior_cells"] > 0))
        self.assertEqual(sum(1 for t in texts if t.startswith("min ")), panels)
        self.assertEqual(sum(1 for t in texts if t.startswith("mean ")), panels)
        self.assertIn("edge length / cell size, boundary layer (%d cells)" % layers["boundary_layer_cells"], texts)
        with open(os.path.join(self.out, "seeds.csv")) as f:
            inside = sum(1 for line in f.readlines()[1:] if line.split(",")[3] == "1")
        self.assertEqual(doc["cells"]["cells"], inside)
        # The same figures `vorocrust cells` writes for the same seeds.
        r = run("cells", os.path.join(self.out, "seeds.csv"), "-o", os.path.join(self.tmp, "cells"), "-q",
                "--format", "vtu")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(self.tmp, "cells", "report.json")) as f:
            self.assertEqual(json.load(f)["cells"]["quality"], doc["cells"])

    def test_bad_seeds_name_their_file(self):
        self.make_run("cgal_joint.off")
        seeds = os.path.join(self.out, "seeds.csv")
        with open(seeds, "w") as f:
            f.write("x,y,z,label,radius,kind\n0,0,0,1,0.5,interior\n")
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertEqual(r.stdout, "")
        self.assertIn(seeds + ": its cells cannot be measured: cell of seed 0 is not bounded by seeds", r.stderr)
        with open(seeds, "w") as f:
            f.write("x,y,z,label\n")
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn(seeds + ":1:", r.stderr)

    def test_missing_surface_names_the_file(self):
        with open(os.path.join(self.out, "report.json"), "w") as f:
            json.dump({"inputs": [model("cgal_joint.off")]}, f)
        r = run("quality", self.out)
        self.assertEqual(r.returncode, 3)
        self.assertEqual(r.stdout, "")
        self.assertIn(os.path.join(self.out, "surface.ply"), r.stderr)
        self.assertIn("missing, and so is seeds.csv", r.stderr)
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
