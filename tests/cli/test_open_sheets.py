"""Open sheets in their box (paper Figure 17): gmsh_terrain.stl meshed as it is, through VTK and
checkMesh. The terrain splits the cells: its triangles in the output are faces between two
cells, no cell reaches across it, and the cells fill the box."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import vtk

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from volume_mesh import (all_polyhedron_faces, cell_array, check_mesh, read_obj_triangles, read_vtu,  # noqa: E402
                         vtk_boundary_volume)

BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]
TERRAIN = os.path.join(MODELS, "gmsh_terrain.stl")


def run(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=600)


def read_stl(path):
    reader = vtk.vtkSTLReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def triangle_area(t):
    u = [t[1][k] - t[0][k] for k in range(3)]
    v = [t[2][k] - t[0][k] for k in range(3)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return 0.5 * sum(c * c for c in n) ** 0.5


class TerrainInItsBox(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="vorocrust-sheet-")
        cls.out = os.path.join(cls.dir, "terrain")
        cls.result = run("mesh", TERRAIN, "-o", cls.out, "--seed", "3", "-q")
        # The box from the file's decimal coordinates (VTK's reader rounds them to float).
        with open(TERRAIN) as f:
            vertices = [[float(x) for x in line.split()[1:4]] for line in f if line.split()[:1] == ["vertex"]]
        lo = [min(v[k] for v in vertices) for k in range(3)]
        hi = [max(v[k] for v in vertices) for k in range(3)]
        terrain = read_stl(TERRAIN)
        cls.diagonal = sum((b - a) ** 2 for a, b in zip(lo, hi)) ** 0.5
        margin = 0.1 * cls.diagonal
        cls.box = ([a - margin for a in lo], [b + margin for b in hi])
        cls.terrain = terrain

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def setUp(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr)

    def box_volume(self):
        lo, hi = self.box
        return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])

    def test_the_cells_fill_the_default_box(self):
        grid = read_vtu(os.path.join(self.out, "mesh.vtu"))
        lo, hi = self.box
        bounds = grid.GetBounds()
        for k in range(3):
            self.assertAlmostEqual(bounds[2 * k], lo[k], delta=1e-9 * self.diagonal)
            self.assertAlmostEqual(bounds[2 * k + 1], hi[k], delta=1e-9 * self.diagonal)
        volume = self.box_volume()
        self.assertAlmostEqual(sum(cell_array(grid, "volume")), volume, delta=1e-9 * volume)
        self.assertAlmostEqual(vtk_boundary_volume(grid), volume, delta=1e-9 * volume)
        # One material, "domain", on both sides of the sheet.
        self.assertEqual(set(cell_array(grid, "material")), {1})
        with open(os.path.join(self.out, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["cells"]["cells"], grid.GetNumberOfCells())

    def test_the_terrain_is_made_of_faces_between_two_cells(self):
        grid = read_vtu(os.path.join(self.out, "mesh.vtu"))
        points = grid.GetPoints()
        scale = 1e-7 * self.diagonal

        def key(xyz):
            return tuple(sorted(tuple(round(c / scale) for c in p) for p in xyz))

        cells_of_face = {}
        for faces in all_polyhedron_faces(grid):
            for face in faces:
                if len(face) == 3:
                    k = key(points.GetPoint(i) for i in face)
                    cells_of_face[k] = cells_of_face.get(k, 0) + 1
        lo, hi = self.box
        on_box = lambda t: any(all(abs(p[k] - b[k]) < scale for p in t) for k in range(3) for b in (lo, hi))  # noqa: E731
        sheet = [t for t in read_obj_triangles(os.path.join(self.out, "surface.obj")) if not on_box(t)]
        # The sheet in the output is the terrain's shape: its area within 1 % of the input's.
        area = sum(triangle_area(t) for t in sheet)
        mass = vtk.vtkMassProperties()
        mass.SetInputData(self.terrain)
        mass.Update()
        self.assertAlmostEqual(area, mass.GetSurfaceArea(), delta=0.01 * area)
        # Away from the sheet's rim, each of its triangles is one face between two cells. Along the
        # rim (triangles with an edge on no other sheet triangle) nothing closes a pair's facet at
        # the rim: it may spread past it, or share a quad with a neighbouring pair's.
        edge_count = {}
        for t in sheet:
            for a, b in ((0, 1), (1, 2), (2, 0)):
                e = key((t[a], t[b]))
                edge_count[e] = edge_count.get(e, 0) + 1
        rim = lambda t: any(edge_count[key((t[a], t[b]))] == 1 for a, b in ((0, 1), (1, 2), (2, 0)))  # noqa: E731
        inner = [t for t in sheet if not rim(t)]
        self.assertGreater(len(inner), 0.8 * len(sheet))
        missing = [t for t in inner if cells_of_face.get(key(t), 0) != 2]
        self.assertEqual(missing, [], "%d of %d terrain triangles are not faces between two cells" % (len(missing), len(inner)))

    def test_no_cell_reaches_across_the_terrain(self):
        grid = read_vtu(os.path.join(self.out, "mesh.vtu"))
        with open(os.path.join(self.out, "report.json")) as f:
            hausdorff = json.load(f)["surface"]["quality"]["hausdorff"]["distance"]
        # The output sheet lies within the Hausdorff distance of the input's.
        tolerance = hausdorff + 1e-9 * self.diagonal
        locator = vtk.vtkCellLocator()
        locator.SetDataSet(self.terrain)
        locator.BuildLocator()
        lo, hi = self.box

        def height_above_terrain(p):
            t, x, pc, sub, cell = vtk.mutable(0.0), [0.0] * 3, [0.0] * 3, vtk.mutable(0), vtk.mutable(0)
            if not locator.IntersectWithLine((p[0], p[1], hi[2]), (p[0], p[1], lo[2]), 1e-12, t, x, pc, sub, cell):
                return None
            return p[2] - x[2]

        heights = [height_above_terrain(grid.GetPoint(i)) for i in range(grid.GetNumberOfPoints())]
        above = below = 0
        across = []
        for c in range(grid.GetNumberOfCells()):
            ids = grid.GetCell(c).GetPointIds()
            h = [heights[ids.GetId(i)] for i in range(ids.GetNumberOfIds())]
            h = [x for x in h if x is not None]
            if not h:
                continue
            if min(h) < -tolerance and max(h) > tolerance:
                across.append((c, min(h), max(h)))
            above += min(h) >= -tolerance and max(h) > tolerance
            below += max(h) <= tolerance and min(h) < -tolerance
        self.assertEqual(across, [], "cells reaching across the terrain (cell, lowest, highest height)")
        self.assertGreater(above, 500)
        self.assertGreater(below, 500)
        print("\n  %d cells above the terrain, %d below, tolerance %.3g" % (above, below, tolerance))

    def test_checkmesh_reads_the_case(self):
        r, _ = check_mesh(os.path.join(self.out, "case"))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        for check in ("Boundary openness", "Cell volumes OK", "Upper triangular ordering OK",
                      "Cell to face addressing OK", "Point usage OK", "Number of regions: 1 (OK)",
                      "ok (closed singly connected)", "Face vertices OK", "Boundary definition OK"):
            self.assertIn(check, r.stdout, r.stdout[-2500:])

    def test_a_box_that_cuts_the_model_is_refused(self):
        out = os.path.join(self.dir, "cut")
        r = run("mesh", TERRAIN, "-o", out, "--box", "0", "0", "0", "1000", "1000", "1000", "-q")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("does not lie inside the box", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(out, "mesh.vtu")))

    def test_an_explicit_box(self):
        out = os.path.join(self.dir, "explicit")
        r = run("mesh", TERRAIN, "-o", out, "--box", "-100", "-200", "-300", "2800", "2600", "400", "--seed", "3", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        grid = read_vtu(os.path.join(out, "mesh.vtu"))
        volume = 2900 * 2800 * 700
        self.assertAlmostEqual(sum(cell_array(grid, "volume")), volume, delta=1e-9 * volume)
        with open(os.path.join(out, "report.json")) as f:
            self.assertEqual(json.load(f)["options"]["box"], [-100, -200, -300, 2800, 2600, 400])


if __name__ == "__main__":
    unittest.main(verbosity=2)
