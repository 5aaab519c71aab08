#!/usr/bin/env python3
"""`vorocrust mesh2d` as users run it, checked by the real tools: OpenFOAM's checkMesh on the
one-cell-thick case (its front and back an `empty` patch), VTK's reader on mesh.vtu (polygons,
areas against report.json), the TOUGH and PFLOTRAN files against the cells, the picture, and bad
domains refused with a message naming the line.

Run by CTest as: /usr/bin/python3 test_mesh2d.py VOROCRUST_BINARY SAMPLES_DIR
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from volume_mesh import cell_array, check_mesh, read_vtu  # noqa: E402

import vtk  # noqa: E402

BINARY, SAMPLES = sys.argv[1:3]
del sys.argv[1:3]

# The domains with the sizes they are meshed at, and each region's area (None: within
# the hole's chords, checked in the unit test).
DOMAINS = {
    "square_hole.poly": ("0.05", {"inside": None}),
    "sharp_corners.poly": ("0.1", {"region1": 2 * math.tan(math.radians(10))}),
    "cross_section.poly": ("0.25", {"region1": 24.0, "region2": 13.5, "region3": 22.5}),
    "thin_channel.poly": ("0.1", {"inside": 2.01}),
}


def read(path):
    with open(path) as f:
        return f.read()


def run(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=600)


class Mesh2d(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="vorocrust-mesh2d-")
        cls.runs = {}
        for name, (size, _) in DOMAINS.items():
            out = os.path.join(cls.dir, name)
            r = run("mesh2d", os.path.join(SAMPLES, "2d", name), "-o", out, "--max-size", size, "--thickness", "0.5")
            cls.runs[name] = (r, out)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_every_domain_meshes_and_checkmesh_says_mesh_ok(self):
        for name, (r, out) in self.runs.items():
            with self.subTest(domain=name):
                self.assertEqual(r.returncode, 0, r.stderr)
                result, _ = check_mesh(os.path.join(out, "case"))
                self.assertIn("Mesh OK.", result.stdout, result.stdout[-3000:])
                self.assertIn("Mesh has 2 geometric (non-empty/wedge) directions", result.stdout)
                boundary = read(os.path.join(out, "case", "constant", "polyMesh", "boundary"))
                self.assertIn("type            empty;", boundary)

    def test_vtu_polygons_and_report_agree_on_the_areas(self):
        for name, (r, out) in self.runs.items():
            with self.subTest(domain=name):
                self.assertEqual(r.returncode, 0, r.stderr)
                report = json.loads(read(os.path.join(out, "report.json")))
                self.assertEqual(report["status"], "ok")
                self.assertEqual(report["dimension"], 2)
                cells = report["cells"]
                self.assertTrue(cells["convex"])
                self.assertLess(cells["quality"]["link_angle"]["max"], 1e-6)
                grid = read_vtu(os.path.join(out, "mesh.vtu"))
                self.assertEqual(grid.GetNumberOfCells(), cells["cells"])
                self.assertTrue(all(grid.GetCellType(i) == vtk.VTK_POLYGON for i in range(grid.GetNumberOfCells())))
                areas = vtk.vtkCellSizeFilter()
                areas.SetInputData(grid)
                areas.ComputeAreaOn()
                areas.Update()
                vtk_areas = cell_array(areas.GetOutput(), "Area")
                materials = cell_array(grid, "material")
                names = {v: k for k, v in enumerate(sorted(cells["area_by_region"]))}
                self.assertEqual(len(names), len(DOMAINS[name][1]) if name != "sharp_corners.poly" else 2)
                total = sum(cells["area_by_region"].values())
                self.assertAlmostEqual(sum(vtk_areas), total, delta=1e-9 * total)
                for region, area in DOMAINS[name][1].items():
                    if area is not None:
                        self.assertAlmostEqual(cells["area_by_region"][region], area, delta=1e-9 * area)
                self.assertEqual(len(set(materials)), len(cells["area_by_region"]))

    def test_tough_and_pflotran_list_every_cell_with_its_area_times_the_thickness(self):
        r, out = self.runs["cross_section.poly"]
        self.assertEqual(r.returncode, 0, r.stderr)
        report = json.loads(read(os.path.join(out, "report.json")))
        n = report["cells"]["cells"]
        uge = read(os.path.join(out, "pflotran", "mesh.uge")).split("\n")
        self.assertEqual(uge[0], "CELLS %d" % n)
        volume = sum(float(line.split()[4]) for line in uge[1:n + 1])
        self.assertAlmostEqual(volume, 60.0 * 0.5, delta=1e-9 * 30)
        connections = int(uge[n + 1].split()[1])
        self.assertEqual(connections, report["cells"]["edges"] - report["cells"]["boundary_edges"])
        # The front and back are no boundary of the flow: no region file lists them.
        self.assertFalse([f for f in os.listdir(os.path.join(out, "pflotran")) if "frontAndBack" in f])
        mesh = read(os.path.join(out, "MESH"))
        eleme = mesh.split("CONNE")[0].strip().split("\n")[1:]
        self.assertEqual(len(eleme), n)

    def test_the_picture_shows_every_cell_and_segment(self):
        r, out = self.runs["cross_section.poly"]
        svg = ElementTree.parse(os.path.join(out, "mesh.svg")).getroot()
        ns = "{http://www.w3.org/2000/svg}"
        report = json.loads(read(os.path.join(out, "report.json")))
        self.assertEqual(len(svg.findall(".//%spolygon" % ns)), report["cells"]["cells"])
        self.assertEqual(len(svg.findall(".//%sline" % ns)), report["domain"]["segments"])

    def test_bad_domains_are_refused_naming_the_line(self):
        cases = {
            "zero length": ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 0\n1 1 2\n2 2 3\n3 3 1\n4 2 2\n0\n", "segment 4 (line 9) has zero length"),
            "twice": ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 0\n1 1 2\n2 2 3\n3 3 1\n4 2 1\n0\n", "repeats segment 1"),
            "no such vertex": ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 9\n0\n", ":8: segment end 9 names no vertex"),
            "open boundary": ("4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n3 0\n1 1 2\n2 2 3\n3 3 4\n0\n", "outside every closed region"),
            "node file": ("0 2 0 0\n0 0\n0\n", "separate .node file"),
        }
        for what, (text, expected) in cases.items():
            with self.subTest(case=what):
                path = os.path.join(self.dir, what.replace(" ", "_") + ".poly")
                with open(path, "w") as f:
                    f.write(text)
                out = os.path.join(self.dir, "bad_" + what.replace(" ", "_"))
                r = run("mesh2d", path, "-o", out)
                self.assertIn(r.returncode, (3, 4), r.stderr)
                self.assertIn(expected, r.stderr)
                self.assertFalse(os.path.exists(os.path.join(out, "mesh.vtu")))
                self.assertEqual(json.loads(read(os.path.join(out, "report.json")))["status"], "failed")

    def test_obj_polylines_with_a_breakline(self):
        # A square as one closed polyline and a breakline inside it, ending in the middle.
        path = os.path.join(self.dir, "square.obj")
        with open(path, "w") as f:
            f.write("v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 0.5 0.5 0\nv 1.2 1.3 0\nl 1 2 3 4 1\nl 5 6\n")
        out = os.path.join(self.dir, "square_obj")
        r = run("mesh2d", path, "-o", out, "--max-size", "0.1", "--format", "vtu,openfoam")
        self.assertEqual(r.returncode, 0, r.stderr)
        report = json.loads(read(os.path.join(out, "report.json")))
        self.assertAlmostEqual(report["cells"]["area_by_region"]["inside"], 4.0, delta=1e-9)
        self.assertEqual(report["cells"]["interface_edges"], 0)
        self.assertEqual(sorted(os.listdir(out)), ["case", "mesh.vtu", "report.json"])
        result, _ = check_mesh(os.path.join(out, "case"))
        self.assertIn("Mesh OK.", result.stdout)


if __name__ == "__main__":
    unittest.main()
