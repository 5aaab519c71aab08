#!/usr/bin/env python3
"""`vorocrust cells` checked by the real tools: VTK's own reader (VTK's Python modules, from python3-paraview) on mesh.vtu and
OpenFOAM's checkMesh on case/; rebuilding from a run's seeds.csv; the cell quality in report.json
and quality.svg; bad seed files.

Run by CTest as: /usr/bin/python3 test_cells.py VOROCRUST_BINARY MODELS_DIR
"""
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ElementTree

import vtk

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from volume_mesh import (check_mesh, cell_array, obj_enclosed_volume, read_seed_positions, read_vtu,  # noqa: E402
                         vtk_boundary_volume, vtk_cell_volumes, vtk_link_angles)

BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]

def run(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=600)


def lattice_seeds(path, n, jitter, label, rng_seed=1):
    """n^3 seeds on the unit lattice moved by up to `jitter`, labelled label(x, y, z); returns the labels."""
    rng = random.Random(rng_seed)
    labels = []
    with open(path, "w") as f:
        f.write("x,y,z,label,radius,kind\n")
        for i in range(n):
            for j in range(n):
                for k in range(n):
                    p = [c + rng.uniform(-jitter, jitter) for c in (i, j, k)]
                    lab = label(*p)
                    labels.append(lab)
                    f.write("%.17g,%.17g,%.17g,%d,0.5,%s\n" % (*p, lab, "interior" if lab else "outside"))
    return labels


def in_ball(c, r):
    return lambda x, y, z: 1 if (x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 < r * r else 0


def split_ball(c, r):
    return lambda x, y, z: (1 if x < c else 2) if (x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 < r * r else 0


class Cells(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="vorocrust-cells-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def path(self, *names):
        return os.path.join(self.dir, *names)

    def cells(self, seeds, out, *options):
        r = run("cells", seeds, "-o", out, *options)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr, "")
        return r

    def test_vtk_reads_the_polyhedra_and_their_volumes(self):
        # Two materials in a ball, well-shaped cells.
        labels = lattice_seeds(self.path("seeds.csv"), 12, 0.3, split_ball(5.5, 4.2), 2)
        self.cells(self.path("seeds.csv"), self.path("out"))
        grid = read_vtu(self.path("out", "mesh.vtu"))
        material = [i for i, lab in enumerate(labels) if lab > 0]
        self.assertEqual(grid.GetNumberOfCells(), len(material))
        self.assertEqual({grid.GetCellType(c) for c in range(grid.GetNumberOfCells())}, {vtk.VTK_POLYHEDRON})
        self.assertEqual(cell_array(grid, "seed"), material)
        self.assertEqual(cell_array(grid, "material"), [labels[s] for s in material])
        library = cell_array(grid, "volume")
        measured = vtk_cell_volumes(grid)
        for c, (a, b) in enumerate(zip(library, measured)):
            self.assertAlmostEqual(a, b, delta=1e-9 * a, msg="cell %d" % c)
        total = sum(library)
        self.assertAlmostEqual(sum(measured), total, delta=1e-9 * total)
        self.assertAlmostEqual(vtk_boundary_volume(grid), total, delta=1e-9 * total)
        print("\n  VTK: %d polyhedra, volume %.12g (library %.12g)" % (len(measured), sum(measured), total))

    def test_vtk_reads_near_degenerate_cells(self):
        # A lattice moved by 1e-3: eight nearly cospherical seeds at every vertex, so faces carry
        # edges a thousandth of their size. VTK's own triangulation of such polygons drops some
        # sliver triangles, so its volumes are only close.
        labels = lattice_seeds(self.path("seeds.csv"), 10, 1e-3, in_ball(4.5, 3.6), 1)
        self.cells(self.path("seeds.csv"), self.path("out"))
        grid = read_vtu(self.path("out", "mesh.vtu"))
        self.assertEqual(grid.GetNumberOfCells(), sum(1 for lab in labels if lab))
        library, measured = cell_array(grid, "volume"), vtk_cell_volumes(grid)
        for a, b in zip(library, measured):
            self.assertAlmostEqual(a, b, delta=1e-4 * a)
            self.assertAlmostEqual(a, 1, delta=1e-2)

    def test_checkmesh_passes_with_orthogonal_faces(self):
        # Seeds at their cells' centroids (a lattice moved by 1e-3): the links between cell
        # centres, which checkMesh measures against, are the seed links the faces are orthogonal to.
        lattice_seeds(self.path("seeds.csv"), 10, 1e-3, in_ball(4.5, 3.6), 1)
        self.cells(self.path("seeds.csv"), self.path("out"), "--format", "openfoam")
        self.assertFalse(os.path.exists(self.path("out", "mesh.vtu")))
        r, (max_angle, mean_angle) = check_mesh(self.path("out", "case"))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("\nMesh OK.", r.stdout)
        self.assertIn("material1_to_outside", r.stdout)
        self.assertLess(max_angle, 1.0)
        print("\n  checkMesh: Mesh OK, non-orthogonality max %.4g deg, average %.4g deg" % (max_angle, mean_angle))

    def test_checkmesh_passes_on_two_materials(self):
        # Jittered seeds: true Voronoi faces, orthogonal to the seed links, but the cell centres
        # are off the seeds, so checkMesh (measuring against centre links) finds some
        # non-orthogonality; every other check passes.
        lattice_seeds(self.path("seeds.csv"), 12, 0.3, split_ball(5.5, 4.2), 2)
        self.cells(self.path("seeds.csv"), self.path("out"), "--format", "openfoam", "--threads", "1")
        r, (max_angle, mean_angle) = check_mesh(self.path("out", "case"))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("\nMesh OK.", r.stdout)
        for patch in ("material1_to_outside", "material2_to_outside"):
            self.assertRegex(r.stdout, r"\n\s+%s\s+\d+\s+\d+\s+ok" % patch)
        for zone in ("material1", "material2"):
            self.assertRegex(r.stdout, r"\n\s+%s\s+\d+\s+\d+" % zone)
        self.assertLess(max_angle, 30)
        print("\n  checkMesh (jitter 0.3): Mesh OK, non-orthogonality max %.4g deg, average %.4g deg" % (max_angle, mean_angle))

    def test_rebuilding_a_runs_seeds_gives_the_same_mesh(self):
        r = run("mesh", os.path.join(MODELS, "cgal_joint.off"), "-o", self.path("run"), "--stop-after", "surface", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        seeds = self.path("run", "seeds.csv")
        summary = self.cells(seeds, self.path("one"), "--threads", "1").stdout
        self.cells(seeds, self.path("two"), "--threads", "2", "-q")
        for name in ("mesh.vtu", "case/constant/polyMesh/points", "case/constant/polyMesh/faces",
                     "case/constant/polyMesh/owner", "case/constant/polyMesh/neighbour", "case/constant/polyMesh/boundary"):
            with open(self.path("one", name), "rb") as a, open(self.path("two", name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)
        with open(seeds) as f:
            rows = [line.split(",") for line in f.readlines()[1:]]
        inside = sum(1 for row in rows if row[3] == "1")
        self.assertRegex(summary, r"^%d seeds: %d cells, " % (len(rows), inside))
        grid = read_vtu(self.path("one", "mesh.vtu"))
        self.assertEqual(grid.GetNumberOfCells(), inside)
        total = sum(cell_array(grid, "volume"))
        self.assertAlmostEqual(vtk_boundary_volume(grid), total, delta=1e-9 * total)

    def test_report_and_picture_hold_the_cell_quality(self):
        # Unjittered: every cell a unit cube, aspect ratio sqrt(3), six faces, relative edge 1.
        labels = lattice_seeds(self.path("seeds.csv"), 8, 0, in_ball(3.5, 2.9), 1)
        summary = self.cells(self.path("seeds.csv"), self.path("out"), "--format", "vtu").stdout
        cells = sum(1 for lab in labels if lab)
        self.assertRegex(summary, r"\naspect ratio 1\.732 min, 1\.732 mean, 1\.732 max \(cell \d+, seed \d+\); "
                                  r"0 cells above 5; in ")
        # Cubes: every face orthogonal to the links between both seeds and centroids.
        self.assertRegex(summary, r"\nfaces orthogonal to their seed links within 0 deg \(face \d+\); against the cell "
                                  r"centroids, as checkMesh measures: non-orthogonality max 0 deg, mean 0 deg, "
                                  r"skewness max (0|\d\.?\d*e-1\d), 0 faces above 4\n")  # skewness from rounding
        with open(self.path("out", "report.json")) as f:
            doc = json.load(f)
        self.assertEqual(doc["status"], "ok")
        self.assertEqual(doc["seeds"], len(labels))
        self.assertEqual(doc["seeds_file"], self.path("seeds.csv"))
        self.assertEqual(doc["command"][1:3], ["cells", self.path("seeds.csv")])
        self.assertEqual(doc["cells"]["cells"], cells)
        q = doc["cells"]["quality"]
        self.assertEqual(q["cells"], cells)
        for key in ("min", "mean", "max"):
            self.assertAlmostEqual(q["aspect_ratio"][key], math.sqrt(3), delta=1e-9)
        histogram = q["aspect_ratio"]["histogram"]
        self.assertEqual((histogram["low"], histogram["high"], histogram["above_high"]), (1, 5, 0))
        self.assertEqual(histogram["counts"][2], cells)  # [1.5, 1.75)
        self.assertEqual(sum(histogram["counts"]), cells)
        self.assertEqual((q["faces"]["min"], q["faces"]["max"]), (6, 6))
        self.assertAlmostEqual(q["shortest_edge"]["min"], 1, delta=1e-9)
        self.assertAlmostEqual(q["volume"]["total"], cells, delta=1e-8)
        # The same volumes VTK finds in mesh.vtu.
        grid = read_vtu(self.path("out", "mesh.vtu"))
        self.assertAlmostEqual(sum(vtk_cell_volumes(grid)), q["volume"]["total"], delta=1e-9 * cells)
        # Each cell's aspect ratio beside it, for ParaView's Threshold.
        ratios = cell_array(grid, "aspect_ratio")
        self.assertEqual(len(ratios), cells)
        for ratio in ratios:
            self.assertAlmostEqual(ratio, math.sqrt(3), delta=1e-9)
        svg = ElementTree.parse(self.path("out", "quality.svg")).getroot()
        texts = [e.text for e in svg.iter("{http://www.w3.org/2000/svg}text")]
        self.assertIn("cell aspect ratio R / r (circumradius over inradius)", texts)
        self.assertIn("%d in 16 bins, 0 above 5" % cells, texts)
        self.assertIn(str(cells), texts)  # the count above the one bar
        # The seeds go along, unchanged.
        with open(self.path("seeds.csv")) as a, open(self.path("out", "seeds.csv")) as b:
            self.assertEqual(a.read(), b.read())

    def test_rebuilding_in_a_runs_folder_keeps_its_report(self):
        r = run("mesh", os.path.join(MODELS, "cgal_joint.off"), "-o", self.path("run"), "--stop-after", "surface", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(self.path("run", "report.json")) as f:
            before = json.load(f)
        self.cells(self.path("run", "seeds.csv"), self.path("run"), "-q")
        with open(self.path("run", "report.json")) as f:
            after = json.load(f)
        cells = after.pop("cells")
        before.pop("cells", None)
        self.assertEqual(after, before)  # the run's inputs, options and figures stay
        self.assertEqual(cells["seeds_file"], self.path("run", "seeds.csv"))
        self.assertGreater(cells["quality"]["aspect_ratio"]["max"], cells["quality"]["aspect_ratio"]["min"])
        # And `quality` still finds the model, and measures both.
        r = run("quality", self.path("run"), "--samples", "1000")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("Hausdorff distance", r.stdout)
        self.assertRegex(r.stdout, r"\ncells\s+%d, of the " % cells["cells"])

    def test_bad_seed_files(self):
        bad = self.path("bad.csv")
        with open(bad, "w") as f:
            f.write("x,y,z,label,radius,kind\n0,0,0,1,0.5,interior\n0,0,zero,1,0.5,interior\n")
        r = run("cells", bad, "-o", self.path("out"))
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        self.assertIn(bad + ":3: z is not a finite number: 'zero'", r.stderr)

        r = run("cells", self.path("missing.csv"), "-o", self.path("out"))
        self.assertEqual(r.returncode, 3, r.stderr)

        # All material: the outer cells reach past every seed.
        lattice_seeds(self.path("all.csv"), 4, 0.2, lambda x, y, z: 1)
        r = run("cells", self.path("all.csv"), "-o", self.path("out"))
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertIn("cell of seed 0 is not bounded by seeds", r.stderr)

        r = run("cells", self.path("all.csv"), "-o", self.path("out"), "--format", "stl")
        self.assertEqual(r.returncode, 2, r.stderr)


class MeshRuns(unittest.TestCase):
    """The whole mesher, each interior mode: the cells fill the output surface exactly, VTK and
    checkMesh read them, and the seeds.csv of a run rebuilds the same mesh."""

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="vorocrust-mesh-")
        cls.reports = {}

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def check_run(self, model, mode, *options):
        out = os.path.join(self.dir, model + "-" + mode)
        r = run("mesh", os.path.join(MODELS, model), "-o", out, "--interior", mode, "--seed", "5", "-q", *options)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "seeds.csv")) as f:
            rows = [line.split(",") for line in f.readlines()[1:]]
        material = sum(1 for row in rows if row[3] != "0")
        grid = read_vtu(os.path.join(out, "mesh.vtu"))
        self.assertEqual(grid.GetNumberOfCells(), material)
        enclosed = obj_enclosed_volume(os.path.join(out, "surface.obj"))
        # The cells' own volumes, and VTK's volume inside the grid's outer faces, are the volume the
        # output surface encloses. (VTK's per-polyhedron volumes, vtkCellSizeFilter, fall short by
        # about 2e-4 here: it mis-measures some cells with many nearly degenerate faces.)
        vtk_total = vtk_boundary_volume(grid)
        self.assertAlmostEqual(vtk_total, enclosed, delta=1e-9 * enclosed)
        self.assertAlmostEqual(sum(cell_array(grid, "volume")), enclosed, delta=1e-9 * enclosed)
        self.assertAlmostEqual(sum(vtk_cell_volumes(grid)), enclosed, delta=1e-3 * enclosed)
        r, angles = check_mesh(os.path.join(out, "case"))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        for check in ("Boundary openness", "Cell volumes OK", "Upper triangular ordering OK",
                      "Cell to face addressing OK", "Point usage OK", "Number of regions: 1 (OK)",
                      "ok (closed singly connected)", "Face vertices OK",
                      "Boundary definition OK", "Non-orthogonality check OK", "Face pyramids OK",
                      "Coupled point location match"):
            self.assertIn(check, r.stdout, r.stdout[-2500:])
        # checkMesh measures orthogonality and skewness against cell centroids, not seeds: the skew
        # repair leaves no highly skew face in any mode.
        self.assertEqual([line for line in r.stdout.splitlines() if "***" in line], [])
        self.assertIn("\nMesh OK.", r.stdout, r.stdout[-2500:])
        # Rebuilding from the run's seeds gives the run's mesh, byte for byte.
        again = os.path.join(self.dir, model + "-" + mode + "-again")
        self.assertEqual(run("cells", os.path.join(out, "seeds.csv"), "-o", again, "-q").returncode, 0)
        with open(os.path.join(out, "mesh.vtu"), "rb") as a, open(os.path.join(again, "mesh.vtu"), "rb") as b:
            self.assertTrue(a.read() == b.read(), "rebuilt mesh.vtu differs")
        # The run's report measures every cell (paper section 3): its figures are the cells'.
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
        quality = report["cells"]["quality"]
        self.assertEqual(quality["cells"], material)
        # Its faces are orthogonal to their seed links, in the mesh.vtu VTK reads too; against the
        # centroids, its figures are checkMesh's.
        largest, shared = vtk_link_angles(grid, read_seed_positions(os.path.join(out, "seeds.csv")))
        self.assertEqual(shared, report["cells"]["interior_faces"])
        self.assertLess(largest, 1e-6)
        self.assertLess(quality["link_angle"]["max"], 1e-6)
        self.assertAlmostEqual(quality["non_orthogonality"]["max"], angles[0], delta=1e-6 * angles[0])
        self.assertAlmostEqual(quality["non_orthogonality"]["mean"], angles[1], delta=1e-6 * angles[1])
        ratio = quality["aspect_ratio"]
        self.assertLessEqual(1.0, ratio["min"])
        self.assertLessEqual(ratio["min"], ratio["mean"])
        self.assertLessEqual(ratio["mean"], ratio["max"])
        self.assertEqual(sum(ratio["histogram"]["counts"]) + ratio["histogram"]["above_high"], material)
        self.assertAlmostEqual(quality["volume"]["total"], enclosed, delta=1e-9 * enclosed)
        self.reports[mode] = quality
        print("\n  %s --interior %s: %d cells, volume %.9g (surface encloses %.9g), checkMesh non-orthogonality "
              "max %.3g deg, average %.3g deg, %s" % (model, mode, material, vtk_total, enclosed, angles[0], angles[1],
                                                     "Mesh OK" if "\nMesh OK." in r.stdout else "skewness or other warning"))

    def test_random(self):
        self.check_run("cgal_fandisk.off", "random")

    def test_lattice(self):
        self.check_run("cgal_fandisk.off", "lattice")
        # Hex-dominant: the lattice's deep cells are cubes, hexahedra to checkMesh.
        r, _ = check_mesh(os.path.join(self.dir, "cgal_fandisk.off-lattice", "case"))
        hexahedra = int(re.search(r"hexahedra:\s+(\d+)", r.stdout).group(1))
        cells = int(re.search(r"\n\s+cells:\s+(\d+)", r.stdout).group(1))
        self.assertGreater(hexahedra, cells // 5)

    def test_cvt(self):
        self.check_run("cgal_fandisk.off", "cvt", "--cvt-iterations", "5")
        # Lloyd iterations make the interior cells rounder than the random seeds they start from.
        if "random" not in self.reports:
            self.check_run("cgal_fandisk.off", "random")
        cvt, random = (self.reports[m]["aspect_ratio"]["mean"] for m in ("cvt", "random"))
        print("\n  mean aspect ratio: random %.4f, cvt %.4f" % (random, cvt))
        self.assertLess(cvt, random)


if __name__ == "__main__":
    unittest.main(verbosity=2)
