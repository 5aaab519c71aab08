#!/usr/bin/env python3
"""`vorocrust mesh --method clipped` checked by outside tools: VTK's reader on mesh.vtu, OpenFOAM's
checkMesh on case/, SciPy's k-d tree on seeds.csv.

What every clipped mesh must show: the cells' volumes add up to the volume the input encloses;
their boundary is the input surface (its area, to rounding); faces between cells lie on their
seeds' bisectors; the Poisson-disk seeds are at least r apart and leave no point of the volume
farther than r from a seed (by sampling); two --seed values give two meshes (an ensemble); the
same --seed gives the same mesh. Several materials: each fills its region, and their cells
share the faces along every interface. checkMesh's topology and cell closure pass; its face-pyramid test
fails on cells that reflex edges make non-convex, which is what clipping does to cells.

Run by CTest as: /usr/bin/python3 test_clipped.py VOROCRUST_BINARY MODELS_DIR
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy
import vtk
from scipy.spatial import Delaunay, cKDTree
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from volume_mesh import (all_polyhedron_faces, cell_array, check_mesh, read_vtu,  # noqa: E402
                         vtk_boundary_volume, vtk_link_angles)

BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]


def run(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=600)


def read_seeds(path):
    with open(path) as f:
        rows = [line.strip().split(",") for line in f.readlines()[1:]]
    return numpy.array([[float(x) for x in r[:3]] for r in rows]), [int(r[3]) for r in rows]


def read_kinds(path):
    with open(path) as f:
        return [line.strip().split(",")[5] for line in f.readlines()[1:]]


def surface_of(grid):
    """The faces of the grid used by one cell only, as VTK finds them."""
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(grid)
    surface.Update()
    return surface.GetOutput()


def area(polydata):
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputData(polydata)
    mass = vtk.vtkMassProperties()
    mass.SetInputConnection(triangles.GetOutputPort())
    mass.Update()
    return mass.GetSurfaceArea()


def ply_area(path):
    """The area of a binary PLY triangle surface, in double precision (VTK's reader keeps floats)."""
    with open(path, "rb") as f:
        header = []
        while not header or header[-1] != "end_header":
            header.append(f.readline().decode().strip())
        vertices = int(next(h.split()[2] for h in header if h.startswith("element vertex")))
        faces = int(next(h.split()[2] for h in header if h.startswith("element face")))
        extra = sum(1 for h in header[header.index(next(h for h in header if h.startswith("element face"))) + 2:]
                    if h.startswith("property int"))
        points = numpy.frombuffer(f.read(24 * vertices), dtype="<f8").reshape(-1, 3)
        record = numpy.dtype([("n", "u1"), ("v", "<i4", 3), ("extra", "<i4", extra)])
        triangles = numpy.frombuffer(f.read(record.itemsize * faces), dtype=record)["v"]
    a, b, c = points[triangles[:, 0]], points[triangles[:, 1]], points[triangles[:, 2]]
    return float(numpy.linalg.norm(numpy.cross(b - a, c - a), axis=1).sum() / 2)


def points_inside(surface, points):
    """The points inside a closed surface, by VTK's own test."""
    return points[inside_mask(surface, points)]


def inside_mask(surface, points):
    """Whether each point lies inside a closed surface, by VTK's own test."""
    cloud = vtk.vtkPolyData()
    vtk_points = vtk.vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    cloud.SetPoints(vtk_points)
    select = vtk.vtkSelectEnclosedPoints()
    select.SetInputData(cloud)
    select.SetSurfaceData(surface)
    select.SetTolerance(1e-9)
    select.Update()
    return vtk_to_numpy(select.GetOutput().GetPointData().GetArray("SelectedPoints")).astype(bool)


class Clipped(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="vorocrust-clipped-")

    def mesh(self, model, *options, name="out"):
        out = os.path.join(self.dir, name)
        r = run("mesh", os.path.join(MODELS, model), "-o", out, "--method", "clipped", "-q", *options)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            return out, json.load(f)

    def check_clipped(self, model, *options, radius=None):
        out, report = self.mesh(model, *options)
        grid = read_vtu(os.path.join(out, "mesh.vtu"))
        seeds, labels = read_seeds(os.path.join(out, "seeds.csv"))
        material = numpy.array(labels) > 0
        self.assertEqual(grid.GetNumberOfCells(), int(material.sum()))
        # No balls, so no (empty) balls files.
        self.assertFalse({"balls.csv", "balls.vtk"} & set(os.listdir(out)))
        clipping = report["clipping"]
        self.assertGreater(clipping["clipped_cells"], 0)
        self.assertLessEqual(clipping["clipped_cells"], grid.GetNumberOfCells())
        self.assertGreaterEqual(clipping["surface_pieces"], report["cells"]["boundary_faces"])
        # Volumes: the cells', and what their outer surface encloses, as the input's.
        enclosed = report["regions"][1]["volume"]
        self.assertAlmostEqual(report["cells"]["volume"] / enclosed, 1, delta=1e-9)
        self.assertAlmostEqual(vtk_boundary_volume(grid) / enclosed, 1, delta=1e-9)
        # The boundary is the input surface: its area, to rounding.
        surface = surface_of(grid)
        with open(os.path.join(out, "surface.obj")) as f:
            self.assertTrue(f.read(1))
        model_surface = self.model_surface(out)
        self.assertAlmostEqual(area(surface) / ply_area(os.path.join(out, "surface.ply")), 1, delta=1e-9)
        # Faces between cells stay orthogonal to their seeds' links.
        largest, shared = vtk_link_angles(grid, seeds.tolist())
        self.assertGreater(shared, 0)
        self.assertLess(largest, 1e-5)
        # Poisson-disk seeds: at least r apart, and every sampled point of the volume within r of one.
        if radius is not None:
            inner = seeds[material]
            tree = cKDTree(inner)
            # Interior seeds at least r from every seed; seeds on reflex edges (kind "surface",
            # moved in by a thousandth) at least r / sqrt(2) from each other.
            kinds = [k for k, m in zip(read_kinds(os.path.join(out, "seeds.csv")), material) if m]
            for i, j in tree.query_pairs(radius * (1 - 1e-12)):
                self.assertEqual((kinds[i], kinds[j]), ("surface", "surface"))
                self.assertGreater(numpy.linalg.norm(inner[i] - inner[j]), radius / 2 ** 0.5 * (1 - 3e-3))
            lo, hi = inner.min(axis=0) - radius, inner.max(axis=0) + radius
            samples = numpy.random.default_rng(1).uniform(lo, hi, size=(20000, 3))
            inside = points_inside(model_surface, samples)
            self.assertGreater(len(inside), 1000)
            distance, _ = tree.query(inside)
            self.assertLess(distance.max(), 1.02 * radius)
        # checkMesh: topology, closed cells and positive volumes.
        result, _ = check_mesh(os.path.join(out, "case"))
        for line in ("Boundary definition OK", "Cell to face addressing OK", "Point usage OK", "Face vertices OK",
                     "Number of regions: 1 (OK)", "Boundary openness", "Cell volumes OK", "Face area magnitudes OK"):
            self.assertIn(line, result.stdout, model)
        openness = [line.strip() for line in result.stdout.splitlines() if "openness" in line]
        self.assertEqual(len(openness), 2, result.stdout)
        self.assertTrue(all(line.endswith("OK.") for line in openness), openness)
        return out, report, grid

    def model_surface(self, out):
        reader = vtk.vtkPLYReader()
        reader.SetFileName(os.path.join(out, "surface.ply"))
        reader.Update()
        return reader.GetOutput()

    def test_cad_models(self):
        self.check_clipped("cgal_fandisk.off", "--max-size", "0.1", radius=0.1)
        self.check_clipped("sandia_bracket.obj", "--max-size", "4", radius=4)

    def test_a_smooth_model(self):
        self.check_clipped("igl_bunny.off", "--max-size", "0.006", radius=0.006)

    def test_cvt_and_lattice(self):
        for mode in ("cvt", "lattice"):
            _, report, _ = self.check_clipped("cgal_joint.off", "--interior", mode, "--cvt-iterations", "5")
            self.assertGreater(report["cells"]["cells"], 100, mode)

    def test_dual_tetrahedra(self):
        """The report's dual tetrahedra (Yan et al. 5.2) are SciPy's Delaunay tetrahedra of the seeds
        whose circumcentre VTK finds inside the model, with the same Q4. Lloyd iterations make
        them better shaped than those of the Poisson-disk seeds, and their constrained phase holds
        the boundary cells' seeds a thousandth of the radius inside the surface, so that the
        tetrahedra reach it."""
        mean_q4, fill = {}, {}
        for mode in ("random", "cvt"):
            out, report = self.mesh("cgal_joint.off", "--interior", mode, "--cvt-iterations", "10", name=mode)
            figures = report["dual_tets"]
            seeds, labels = read_seeds(os.path.join(out, "seeds.csv"))
            sites = seeds[numpy.array(labels) > 0]
            tets = sites[Delaunay(sites).simplices]
            a, b, c, d = (tets[:, k] for k in range(4))
            # Circumcentres: a + x with 2 (v - a) . x = |v - a|^2 for v = b, c, d.
            edges = numpy.stack([b - a, c - a, d - a], axis=1)
            x = numpy.linalg.solve(2 * edges, (edges ** 2).sum(axis=2))
            inside = inside_mask(self.model_surface(out), a + x)
            self.assertLessEqual(abs(int(inside.sum()) - figures["tets"]), 2 + figures["tets"] // 500, mode)
            kept_edges = edges[inside]
            volume = numpy.abs(numpy.linalg.det(kept_edges)) / 6
            pairs = [(b - a), (c - a), (d - a), (c - b), (d - b), (d - c)]
            squares = sum((p[inside] ** 2).sum(axis=1) for p in pairs)
            q4 = 12 * numpy.cbrt(9 * volume ** 2) / squares
            self.assertAlmostEqual(q4.mean(), figures["mean_q4"], delta=2e-3, msg=mode)
            self.assertAlmostEqual(volume.sum() / figures["volume"], 1, delta=5e-3, msg=mode)
            self.assertLess(figures["volume"], report["regions"][1]["volume"])
            self.assertTrue(0 < figures["min_q4"] <= figures["mean_q4"] <= 1)
            self.assertTrue(0 < figures["min_min_dihedral"] <= figures["mean_min_dihedral"] < 70.53)
            self.check_tets_file(out, figures, seeds)
            mean_q4[mode] = figures["mean_q4"]
            fill[mode] = figures["volume"] / report["regions"][1]["volume"]
            if mode == "cvt":
                surface = self.model_surface(out)
                distance = vtk.vtkImplicitPolyDataDistance()
                distance.SetInput(surface)
                kinds = [k for k, label in zip(read_kinds(os.path.join(out, "seeds.csv")), labels) if label > 0]
                held = [p for p, k in zip(sites, kinds) if k == "surface"]
                self.assertGreater(len(held), 50)
                bounds = numpy.array(surface.GetBounds())
                radius = numpy.linalg.norm(bounds[1::2] - bounds[::2]) / 20  # the default max_size
                for p in held:
                    self.assertLess(abs(distance.EvaluateFunction(p)), 1.5e-3 * radius)
            print("\n  %s: %d tetrahedra (%d by SciPy), mean Q4 %.4f (%.4f), volume %.6g (%.6g)" % (
                mode, figures["tets"], inside.sum(), figures["mean_q4"], q4.mean(), figures["volume"], volume.sum()))
        self.assertGreater(mean_q4["cvt"], mean_q4["random"])  # 0.828 and 0.815 when written
        self.assertGreater(fill["cvt"], 0.9)  # 0.93; the Poisson-disk seeds' 0.71
        self.assertLess(fill["random"], fill["cvt"])

    def test_sliver_perturbation(self):
        """--sliver-angle: Yan et al.'s post-processing moves the seeds of the dual tetrahedra's
        slivers, keeping the cells exact; the smallest angle rises, the mean shape does not fall."""
        options = ("--interior", "cvt", "--cvt-iterations", "10")
        plain, before = self.mesh("cgal_joint.off", *options, name="plain")
        out, after = self.mesh("cgal_joint.off", *options, "--sliver-angle", "15", name="perturbed")
        perturbation = after["clipping"]["sliver_perturbation"]
        self.assertNotIn("sliver_perturbation", before["clipping"])
        self.assertGreater(perturbation["slivers_before"], 0)
        self.assertGreater(perturbation["moves_kept"], 0)
        self.assertLessEqual(perturbation["moves_kept"], perturbation["moves_tried"])
        self.assertLess(perturbation["slivers_after"], perturbation["slivers_before"] / 2)
        t0, t1 = before["dual_tets"], after["dual_tets"]
        self.assertGreater(t1["min_min_dihedral"], t0["min_min_dihedral"])
        self.assertGreater(t1["mean_min_dihedral"], t0["mean_min_dihedral"] - 0.5)
        self.assertGreater(t1["mean_q4"], t0["mean_q4"] - 0.005)
        self.assertGreater(t1["volume"], 0.98 * t0["volume"])
        # The cells are still the clipped Voronoi cells: they fill the model to rounding.
        grid = read_vtu(os.path.join(out, "mesh.vtu"))
        volume = sum(cell_array(grid, "volume"))
        self.assertAlmostEqual(volume / after["regions"][1]["volume"], 1, delta=1e-9)
        seeds, _ = read_seeds(os.path.join(out, "seeds.csv"))
        self.check_tets_file(out, t1, seeds)
        print("\n  %d slivers below 15 degrees, %d after (%d of %d moves kept, %d rounds); smallest angle %.2f -> "
              "%.2f, mean Q4 %.4f -> %.4f" % (perturbation["slivers_before"], perturbation["slivers_after"],
                                               perturbation["moves_kept"], perturbation["moves_tried"],
                                               perturbation["rounds"], t0["min_min_dihedral"], t1["min_min_dihedral"],
                                               t0["mean_q4"], t1["mean_q4"]))
        r = run("mesh", os.path.join(MODELS, "cgal_joint.off"), "-o", os.path.join(self.dir, "v"), "--sliver-angle", "15")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--method 'clipped'", r.stderr)

    def check_tets_file(self, out, figures, seeds):
        """tets.vtu holds the report's tetrahedra: positively oriented on the meshed seeds, with
        their volume and smallest dihedral angle."""
        grid = read_vtu(os.path.join(out, "tets.vtu"))
        self.assertEqual(grid.GetNumberOfCells(), figures["tets"])
        types = vtk_to_numpy(grid.GetCellTypesArray())
        self.assertTrue((types == vtk.VTK_TETRA).all())
        points = vtk_to_numpy(grid.GetPoints().GetData())
        seed = vtk_to_numpy(grid.GetPointData().GetArray("seed"))
        self.assertLess(numpy.abs(points - seeds[seed]).max(), 1e-12)
        tets = points[vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)]
        signed = numpy.linalg.det(tets[:, 1:] - tets[:, :1]) / 6
        self.assertGreater(signed.min(), 0)
        self.assertAlmostEqual(signed.sum() / figures["volume"], 1, delta=1e-9)
        q1 = vtk_to_numpy(grid.GetCellData().GetArray("min_dihedral"))
        self.assertAlmostEqual(q1.min(), figures["min_min_dihedral"], delta=1e-9)
        self.assertAlmostEqual(q1.mean(), figures["mean_min_dihedral"], delta=1e-9)
        material = vtk_to_numpy(grid.GetCellData().GetArray("material"))
        self.assertTrue((material == 1).all())

    def test_an_ensemble_of_meshes(self):
        a, _ = self.mesh("cgal_joint.off", "--seed", "1", name="a")
        b, _ = self.mesh("cgal_joint.off", "--seed", "2", name="b")
        c, _ = self.mesh("cgal_joint.off", "--seed", "1", name="c")
        seeds = [read_seeds(os.path.join(d, "seeds.csv"))[0] for d in (a, b, c)]
        self.assertFalse(numpy.array_equal(seeds[0], seeds[1]))
        with open(os.path.join(a, "mesh.vtu"), "rb") as fa, open(os.path.join(c, "mesh.vtu"), "rb") as fc:
            self.assertEqual(fa.read(), fc.read())

    def test_compare_reproduces_the_papers_finding(self):
        """The paper's Figure 1: a clipped surface has boundary faces with far shorter edges
        relative to their faces; its cells are not all convex; its volume is exact."""
        out = os.path.join(self.dir, "compare")
        r = run("compare", os.path.join(MODELS, "cgal_fandisk.off"), "-o", out, "--max-size", "0.05", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("boundary face shortest/longest edge, mean", r.stdout)
        with open(os.path.join(out, "compare.json")) as f:
            figures = {m["method"]: m for m in json.load(f)["methods"]}
        vorocrust, clipped = figures["vorocrust"], figures["clipped"]
        self.assertLess(clipped["boundary_edge_ratio"]["mean"], 0.75 * vorocrust["boundary_edge_ratio"]["mean"])
        self.assertGreater(clipped["boundary_edge_ratio"]["below_0.1"], 10 * vorocrust["boundary_edge_ratio"]["below_0.1"] + 10)
        self.assertEqual(vorocrust["non_convex_cells"], 0)
        self.assertGreater(clipped["non_convex_cells"], 0)
        self.assertEqual(vorocrust["off_link_faces"], 0)
        self.assertEqual(clipped["off_link_faces"], 0)
        self.assertLess(clipped["volume_error"], 1e-9)
        self.assertEqual(sum(clipped["boundary_edge_ratio"]["histogram"]), clipped["boundary_faces"])
        for method in ("vorocrust", "clipped"):
            self.assertTrue(os.path.isfile(os.path.join(out, method, "mesh.vtu")), method)
        with open(os.path.join(out, "compare.svg")) as f:
            svg = f.read()
        self.assertTrue(svg.startswith("<svg") or svg.startswith("<?xml"))
        self.assertIn("clipped: boundary faces", svg)

    def check_materials(self, model, *options):
        """Several materials: each one's cells fill its region, every cell is closed (so the faces
        along each interface are shared, point for point), and random points of the box lie in the
        cell of their material's nearest seed (by winding numbers, independent of the mesher)."""
        out, report = self.mesh(model, *options)
        grid = read_vtu(os.path.join(out, "mesh.vtu"))
        points = vtk_to_numpy(grid.GetPoints().GetData())
        materials = cell_array(grid, "material")
        seed_of = cell_array(grid, "seed")
        cells = all_polyhedron_faces(grid)
        centre = points.mean(axis=0)
        volumes = [polyhedron_volume(points - centre, faces) for faces in cells]
        regions = report["regions"][1:]
        self.assertGreater(len(regions), 1)
        for region in regions:
            filled = sum(v for v, m in zip(volumes, materials) if m == region["label"])
            self.assertAlmostEqual(filled / region["volume"], 1, delta=1e-9, msg=region["name"])
        for c, faces in enumerate(cells):
            edges = [(f[k], f[(k + 1) % len(f)]) for f in faces for k in range(len(f))]
            self.assertEqual(sorted(edges), sorted((b, a) for a, b in edges), "cell %d is open" % c)
        self.assertGreater(report["cells"]["interface_faces"], 0)
        seeds, labels = read_seeds(os.path.join(out, "seeds.csv"))
        cell_of_seed = {s: c for c, s in enumerate(seed_of)}
        lo, hi = points.min(axis=0), points.max(axis=0)
        samples = numpy.random.default_rng(3).uniform(lo, hi, size=(60, 3))
        found = 0
        for q in samples:
            holding = []
            for region in regions:
                own = [i for i, label in enumerate(labels) if label == region["label"]]
                nearest = own[int(numpy.argmin(numpy.linalg.norm(seeds[own] - q, axis=1)))]
                c = cell_of_seed[nearest]
                if abs(winding_number(points, cells[c], q) - 1) < 1e-6:
                    holding.append(region["label"])
            self.assertLessEqual(len(holding), 1, q)
            found += len(holding)
        self.assertGreater(found, 10)
        return out, report, grid

    def test_several_materials(self):
        # Walls between materials (edges of three and four faces), and nested shells.
        self.check_materials("sandia_cube_test_02.obj")
        self.check_materials("openmeeg_HeadNNb3.obj", "--interior", "lattice")

    def test_welding(self):
        """--weld: no edge shorter than the fraction of the radius where no chain was kept, every
        cell still closed, the non-planarity reported and bounded by about the fraction."""
        out, report = self.mesh("cgal_fandisk.off", "--max-size", "0.1", "--weld", "0.05")
        welding = report["welding"]
        self.assertGreater(welding["welded_points"], 0)
        self.assertLess(welding["shortest_edge_before"], 0.05)
        if welding["kept_edges"] == 0:
            self.assertGreaterEqual(welding["shortest_edge_after"], 0.05 * (1 - 1e-12))
        self.assertGreater(welding["max_non_planarity"], 0)
        self.assertLess(welding["max_non_planarity"], 0.1)
        grid = read_vtu(os.path.join(out, "mesh.vtu"))
        points = vtk_to_numpy(grid.GetPoints().GetData())
        shortest = numpy.inf
        for c, faces in enumerate(all_polyhedron_faces(grid)):
            edges = [(f[k], f[(k + 1) % len(f)]) for f in faces for k in range(len(f))]
            self.assertEqual(sorted(edges), sorted((b, a) for a, b in edges), "cell %d is open" % c)
            shortest = min(shortest, min(numpy.linalg.norm(points[a] - points[b]) for a, b in edges))
        self.assertAlmostEqual(shortest / 0.1, welding["shortest_edge_after"], delta=1e-9)
        result, _ = check_mesh(os.path.join(out, "case"))
        for line in ("Cell to face addressing OK", "Point usage OK", "Face vertices OK", "Cell volumes OK"):
            self.assertIn(line, result.stdout)
        r = run("mesh", os.path.join(MODELS, "cgal_fandisk.off"), "-o", os.path.join(self.dir, "v"), "--weld", "0.01")
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--method 'clipped'", r.stderr)

    def test_given_seeds(self):
        """--seeds: a run's own seeds.csv given back meshes those seeds, each moved by at most a
        thousandth of the distance to its nearest (test_a_grid_of_given_seeds says why), the same
        way on every run; --interior cvt moves given seeds; a seed outside the region it names is
        refused, naming it."""
        out, report = self.mesh("sandia_cube_test_02.obj", name="sampled")
        seeds_csv = os.path.join(out, "seeds.csv")
        again, again_report = self.mesh("sandia_cube_test_02.obj", "--seeds", seeds_csv, name="given")
        twice, _ = self.mesh("sandia_cube_test_02.obj", "--seeds", seeds_csv, name="twice")
        for name in ("mesh.vtu", "seeds.csv"):
            with open(os.path.join(again, name), "rb") as a, open(os.path.join(twice, name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)
        self.assertEqual(again_report["cells"]["cells"], report["cells"]["cells"])
        sampled, labels = read_seeds(seeds_csv)
        given, given_labels = read_seeds(os.path.join(again, "seeds.csv"))
        self.assertEqual(labels, given_labels)
        inside = numpy.array(labels) > 0
        nearest, _ = cKDTree(sampled[inside]).query(sampled[inside], k=2)
        moved = numpy.linalg.norm(given[inside] - sampled[inside], axis=1)
        self.assertTrue((moved <= 1e-3 * numpy.sqrt(3) * nearest[:, 1] * (1 + 1e-9)).all())
        moved, moved_report = self.mesh("sandia_cube_test_02.obj", "--seeds", seeds_csv, "--interior", "cvt",
                                        "--cvt-iterations", "3", name="moved")
        self.assertEqual(moved_report["cells"]["cells"], report["cells"]["cells"])
        with open(os.path.join(out, "seeds.csv"), "rb") as a, open(os.path.join(moved, "seeds.csv"), "rb") as b:
            self.assertNotEqual(a.read(), b.read())
        with open(seeds_csv) as f:
            lines = f.readlines()
        fields = lines[1].split(",")
        fields[3] = "2" if fields[3] != "2" else "3"
        wrong = os.path.join(self.dir, "wrong.csv")
        with open(wrong, "w") as f:
            f.writelines([lines[0], ",".join(fields)] + lines[2:])
        r = run("mesh", os.path.join(MODELS, "sandia_cube_test_02.obj"), "-o", os.path.join(self.dir, "w"),
                "--method", "clipped", "--seeds", wrong)
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertIn("seed 1 ", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.dir, "w", "mesh.vtu")))
        # A seed on the surface (a vertex of the model) is refused as such, naming the face.
        with open(os.path.join(MODELS, "sandia_cube_test_02.obj")) as f:
            vertex = next(line.split()[1:4] for line in f if line.startswith("v "))
        on_surface = os.path.join(self.dir, "on_surface.csv")
        with open(on_surface, "w") as f:
            f.writelines([lines[0], ",".join(vertex + lines[1].split(",")[3:])] + lines[2:])
        r = run("mesh", os.path.join(MODELS, "sandia_cube_test_02.obj"), "-o", os.path.join(self.dir, "s"),
                "--method", "clipped", "--seeds", on_surface)
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertRegex(r.stderr, r"seed 1 \(.*\) lies on the surface \(face \d+ \(sandia_cube_test_02.obj line \d+\)\)")
        r = run("mesh", os.path.join(MODELS, "sandia_cube_test_02.obj"), "-o", os.path.join(self.dir, "v"),
                "--seeds", seeds_csv)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--method 'clipped'", r.stderr)

    def test_a_grid_of_given_seeds(self):
        """A grid of seeds given for a box of two materials: every input face and the interface lie
        on the grid's bisectors, and Voronoi edges of four cells cross the input's edges. Each seed
        moves by at most a thousandth of the spacing (so the ties go), and the materials fill their
        regions with closed cells."""
        h = 25.0
        grid = [(x, y, z) for z in numpy.arange(h / 2, 100, h) for y in numpy.arange(h / 2, 250, h)
                for x in numpy.arange(h / 2, 500, h)]
        given = os.path.join(self.dir, "grid.csv")
        with open(given, "w") as f:
            f.write("x,y,z,label,radius,kind\n")
            for x, y, z in grid:
                f.write("%r,%r,%r,%d,%r,interior\n" % (x, y, z, 1 if z < 50 else 2, h))
        out, _, _ = self.check_materials("sandia_non_manifold_box.obj", "--seeds", given)
        seeds, _ = read_seeds(os.path.join(out, "seeds.csv"))
        material = seeds[: len(grid)]
        moved = numpy.linalg.norm(material - numpy.array(grid), axis=1)
        self.assertLessEqual(moved.max(), 1e-3 * h * numpy.sqrt(3) * (1 + 1e-9))
        self.assertGreater(moved.min(), 0)

    def test_inputs_it_cannot_clip_are_refused(self):
        r = run("mesh", os.path.join(MODELS, "gmsh_terrain.stl"), "-o", os.path.join(self.dir, "t"),
                "--method", "clipped")
        self.assertEqual(r.returncode, 4, r.stderr)
        self.assertIn("open sheet", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.dir, "t", "mesh.vtu")))


def polyhedron_volume(points, faces):
    """A closed polyhedron's volume, by the divergence theorem over its faces' fans (cells need
    not be convex)."""
    total = 0.0
    for f in faces:
        p = points[list(f)]
        total += numpy.einsum("ij,ij->", numpy.broadcast_to(p[0], p[1:-1].shape), numpy.cross(p[1:-1], p[2:]))
    return total / 6


def winding_number(points, faces, q):
    """The solid angle of a closed polyhedron about q over 4 pi: 1 inside, 0 outside."""
    total = 0.0
    for f in faces:
        a = points[f[0]] - q
        for k in range(1, len(f) - 1):
            b, d = points[f[k]] - q, points[f[k + 1]] - q
            la, lb, ld = numpy.linalg.norm(a), numpy.linalg.norm(b), numpy.linalg.norm(d)
            total += 2 * numpy.arctan2(a.dot(numpy.cross(b, d)),
                                       la * lb * ld + a.dot(b) * ld + a.dot(d) * lb + b.dot(d) * la)
    return total / (4 * numpy.pi)


if __name__ == "__main__":
    unittest.main()
