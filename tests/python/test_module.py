#!/usr/bin/env python3
"""The `vorocrust` Python module against the `vorocrust` program: the same seed gives the same
arrays and byte-identical files; cancelling raises and writes nothing; bad input raises with the
library's message; every public name is documented.

Run by CTest as: PYTHONPATH=BUILD/python /usr/bin/python3 test_module.py VOROCRUST_BINARY MODELS_DIR TEST_DATA_DIR
"""
import csv
import inspect
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import unittest

import numpy as np

import vorocrust

BINARY, MODELS, DATA = sys.argv[1:4]
del sys.argv[1:4]

JOINT = os.path.join(MODELS, "cgal_joint.off")
BOX = os.path.join(MODELS, "sandia_OneBox.obj")

# Exception class for each of the CLI's error classes.
CLASSES = {
    "usage error": vorocrust.UsageError,
    "unreadable input": vorocrust.UnreadableInputError,
    "invalid geometry": vorocrust.InvalidGeometryError,
    "output error": vorocrust.OutputError,
    "cancelled": vorocrust.Cancelled,
    "not yet implemented": vorocrust.NotYetImplementedError,
    "internal error": vorocrust.InternalError,
}


def cli(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=600)


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def read_seeds_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["x", "y", "z", "label", "radius", "kind"], rows[0]
    rows = rows[1:]
    return (np.array([[float(v) for v in r[:3]] for r in rows]), np.array([int(r[3]) for r in rows]),
            np.array([float(r[4]) for r in rows]), [r[5] for r in rows])


def read_obj(path):
    """Vertices, triangles (0-based) and each face's group name, as the CLI writes surface.obj."""
    vertices, triangles, groups, group = [], [], [], None
    with open(path) as f:
        for line in f:
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                vertices.append([float(v) for v in fields[1:4]])
            elif fields[0] in ("g", "o"):
                group = fields[1]
            elif fields[0] == "f":
                triangles.append([int(v.split("/")[0]) - 1 for v in fields[1:4]])
                groups.append(group)
    return np.array(vertices), np.array(triangles), groups


def closed_volume(cells):
    """The volume the mesh's boundary faces enclose (divergence theorem over triangle fans):
    equal to the sum of cell volumes when faces, offsets and orientations are consistent."""
    boundary = np.flatnonzero(cells.neighbour == -1)
    total = 0.0
    for f in boundary:
        polygon = cells.points[cells.face(f)]
        for k in range(1, len(polygon) - 1):
            total += np.dot(polygon[0], np.cross(polygon[k], polygon[k + 1])) / 6
    return total


class Module(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # The joint to the surface with seed 7, once through the program and once through the module.
        cls.dir = tempfile.mkdtemp(prefix="vorocrust-python-")
        cls.cli_out = os.path.join(cls.dir, "cli")
        r = cli("mesh", JOINT, "-o", cls.cli_out, "--stop-after", "surface", "--seed", "7", "-q")
        assert r.returncode == 0, r.stderr
        cls.phases = []
        cls.result = vorocrust.mesh(JOINT, stop_after="surface", seed=7,
                                    progress=lambda phase, fraction: cls.phases.append((phase, fraction)))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def out(self, name):
        path = os.path.join(self.dir, name)
        shutil.rmtree(path, ignore_errors=True)
        return path

    def test_seed_arrays_match_the_programs_seeds_csv(self):
        positions, labels, radii, kinds = read_seeds_csv(os.path.join(self.cli_out, "seeds.csv"))
        seeds = self.result.seeds
        self.assertEqual(len(seeds), len(labels))
        self.assertGreater(len(seeds), 1000)
        # 17 significant digits: the text gives back every double exactly.
        np.testing.assert_array_equal(seeds.positions, positions)
        np.testing.assert_array_equal(seeds.labels, labels)
        np.testing.assert_array_equal(seeds.radii, radii)
        self.assertEqual(list(seeds.kinds), kinds)
        self.assertEqual(set(kinds), {"surface"})
        self.assertEqual(seeds.positions.dtype, np.float64)
        self.assertEqual(seeds.labels.dtype, np.int32)
        # Two seeds per seed pair, one each side: as many inside as outside.
        self.assertEqual(int((seeds.labels == 1).sum()), int((seeds.labels == 0).sum()))

    def test_surface_arrays_match_the_programs_surface_obj(self):
        vertices, triangles, groups = read_obj(os.path.join(self.cli_out, "surface.obj"))
        surface = self.result.surface
        np.testing.assert_array_equal(surface.vertices, vertices)
        np.testing.assert_array_equal(surface.triangles, triangles)
        names = surface.region_names
        self.assertEqual(names, ["outside", "inside"])  # the seeds' labels 0 and 1
        self.assertEqual(["%s|%s" % (names[b], names[f]) for b, f in surface.regions], groups)
        self.assertEqual(set(groups), {"inside|outside"})
        self.assertEqual(surface.vertices.shape[1], 3)
        self.assertFalse(surface.vertices.flags.writeable)
        # Euler characteristic of a closed genus-2 surface: -2, as the input.
        edges = {tuple(sorted(e)) for t in surface.triangles for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}
        self.assertEqual(surface.num_vertices - len(edges) + surface.num_faces, -2)

    def test_written_files_are_the_programs_byte_for_byte(self):
        out = self.out("module")
        written = vorocrust.write_outputs(self.result, out)
        self.assertEqual(sorted(os.path.basename(p) for p in written),
                         sorted(["balls.csv", "balls.vtk", "report.json", "seeds.csv", "surface.obj", "surface.ply",
                                 "quality.svg", "report.html"]))
        for name in ("balls.csv", "balls.vtk", "seeds.csv", "surface.obj", "surface.ply"):
            self.assertEqual(read_bytes(os.path.join(out, name)), read_bytes(os.path.join(self.cli_out, name)), name)
        with open(os.path.join(self.cli_out, "report.json")) as f:
            cli_report = json.load(f)
        report = self.result.report()
        for key in ("features", "refinement", "slivers", "surface", "input"):
            self.assertEqual(_without_seconds(report[key]), _without_seconds(cli_report[key]), key)
        self.assertEqual(report["status"], "ok")
        self.assertEqual(report["inputs"], [JOINT])
        self.assertEqual(self.result.surface_quality, cli_report["surface"]["quality"])
        self.assertTrue(self.result.surface_quality["topology"]["matches"])

    def test_cells_of_the_seeds_match_the_cells_command(self):
        seeds_csv = os.path.join(self.cli_out, "seeds.csv")
        r = cli("cells", seeds_csv, "-o", self.out("cli_cells"), "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        cells = vorocrust.compute_cells(self.result.seeds, region_names=self.result.surface.region_names)
        self.assertEqual(cells.num_cells, int((self.result.seeds.labels == 1).sum()))
        self.assertEqual(vorocrust.compute_cells(seeds_csv).region_names, ["outside", "inside"])
        out = self.out("module_cells")
        os.makedirs(out)
        vorocrust.write_vtu(cells, os.path.join(out, "mesh.vtu"))
        vorocrust.write_openfoam(cells, os.path.join(out, "case"))
        for name in ("mesh.vtu", "case/constant/polyMesh/points", "case/constant/polyMesh/faces",
                     "case/constant/polyMesh/owner", "case/constant/polyMesh/neighbour",
                     "case/constant/polyMesh/boundary"):
            self.assertEqual(read_bytes(os.path.join(out, name)), read_bytes(os.path.join(self.dir, "cli_cells", name)),
                             name)
        # The arrays agree with each other: offsets, orientation and volumes.
        self.assertEqual(len(cells.face_offsets), cells.num_faces + 1)
        self.assertEqual(cells.face_offsets[-1], len(cells.face_points))
        self.assertEqual(len(cells.cell_face_offsets), cells.num_cells + 1)
        np.testing.assert_array_equal(cells.materials, np.ones(cells.num_cells))
        np.testing.assert_array_equal(self.result.seeds.labels[cells.cell_seeds], cells.materials)
        total = cells.volumes.sum()
        self.assertAlmostEqual(closed_volume(cells), total, delta=1e-9 * total)
        for c in (0, cells.num_cells - 1):
            for f in cells.cell(c):
                self.assertIn(c, (cells.owner[f], cells.neighbour[f]))
        # A run's volume files from cells given apart, and the seeds alone.
        again = self.out("given_cells")
        vorocrust.write_outputs(self.result, again, ["vtu"], cells=cells)
        self.assertEqual(read_bytes(os.path.join(again, "mesh.vtu")), read_bytes(os.path.join(out, "mesh.vtu")))
        vorocrust.write_files(again, ["seeds", "openfoam"], seeds=self.result.seeds, cells=cells)
        self.assertEqual(read_bytes(os.path.join(again, "seeds.csv")), read_bytes(seeds_csv))
        with self.assertRaises(vorocrust.UsageError) as caught:
            vorocrust.write_files(again, ["obj"], seeds=self.result.seeds)
        self.assertEqual(str(caught.exception), "nothing to write as 'obj': no surface")
        # A seeds.csv path gives the same cells.
        again = vorocrust.compute_cells(seeds_csv, threads=1)
        np.testing.assert_array_equal(again.points, cells.points)
        np.testing.assert_array_equal(again.face_points, cells.face_points)

    def test_arrays_in_give_the_same_run_as_the_file(self):
        surface = vorocrust.read_mesh(JOINT)
        result = vorocrust.mesh((surface.vertices.astype(np.float64), surface.triangles.astype(np.int64)),
                                stop_after="surface", seed=7)
        np.testing.assert_array_equal(result.seeds.positions, self.result.seeds.positions)
        np.testing.assert_array_equal(result.surface.triangles, self.result.surface.triangles)
        self.assertEqual(result.report()["inputs"], ["arrays"])

    def test_messages_spell_the_options_as_python_does(self):
        # The memory guard names the maximum size at fault and the bound beside it.
        with self.assertRaises(vorocrust.UsageError) as caught:
            vorocrust.mesh(JOINT, output_dir=self.out("too_fine"), max_size=0.003, max_memory=2)
        message = str(caught.exception)
        self.assertTrue(message.startswith("max_size 0.003 asks for at least 3.18e+06 cells"), message)
        self.assertTrue(message.endswith("above max_memory's 2 GB: raise max_size (above 0.00475 for that memory) or "
                                         "max_memory"), message)

    def test_smooth_is_the_programs_smooth_with_the_papers_settings(self):
        # smooth=True leaves the sharp angle and the smoothing to the mode: 60 degrees, 6 rounds.
        bimba = os.path.join(MODELS, "directional_bimba.off")
        out = self.out("smooth")
        r = cli("mesh", bimba, "-o", out, "--smooth", "--stop-after", "balls", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        result = vorocrust.mesh(bimba, smooth=True, stop_after="balls")
        report = result.report()
        self.assertEqual(report["options"]["sharp_angle_degrees"], 60)
        self.assertEqual(report["options"]["smoothing_iterations"], 6)
        self.assertEqual(report["options"]["min_triangle_angle_degrees"], 30)
        # Unset by default, the angle follows the mode: the table says both.
        self.assertIsNone(vorocrust.DEFAULT_OPTIONS["min_triangle_angle"])
        table = {o["name"]: o for o in vorocrust.OPTIONS}
        self.assertEqual((table["min_triangle_angle"]["plain_default"], table["min_triangle_angle"]["smooth_default"]),
                         (0, 30))
        self.assertTrue(report["options"]["smooth"])
        self.assertEqual(report["options"]["smoothing_tolerance"], vorocrust.DEFAULT_OPTIONS["smoothing_tolerance"])
        self.assertGreaterEqual(report["features"]["smoothing_bounding_rounds"], 1)  # a coarse mesh, strongly bent
        self.assertEqual(report["features"]["corners"], 0)  # 397 by the default rules
        self.assertEqual(report["features"]["smoothing_iterations"], 6)
        vorocrust.write_balls(result.balls, os.path.join(out, "module_balls.csv"))
        self.assertEqual(read_bytes(os.path.join(out, "module_balls.csv")), read_bytes(os.path.join(out, "balls.csv")))
        # An explicit angle wins over the mode's.
        self.assertEqual(vorocrust.mesh(bimba, smooth=True, sharp_angle=45, stop_after="balls")
                         .report()["options"]["sharp_angle_degrees"], 45)
        # Skinny triangles are split as the program splits them, and not when told so.
        bird = os.path.join(MODELS, "sandia_bird.obj")
        r = cli("mesh", bird, "-o", out, "--smooth", "--stop-after", "surface", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        split = vorocrust.mesh(bird, smooth=True, stop_after="surface")
        self.assertGreater(split.report()["slivers"]["skinny_triangle_rounds"], 0)
        np.testing.assert_array_equal(split.seeds.positions, vorocrust.read_seeds(os.path.join(out, "seeds.csv")).positions)
        kept = vorocrust.mesh(bird, smooth=True, min_triangle_angle=0, stop_after="surface").report()
        self.assertEqual(kept["options"]["min_triangle_angle_degrees"], 0)
        self.assertEqual(kept["slivers"]["skinny_triangle_rounds"], 0)
        with self.assertRaises(vorocrust.UsageError):
            vorocrust.mesh(bird, smooth=True, min_triangle_angle=31, stop_after="surface")
        with self.assertRaises(vorocrust.UsageError):
            vorocrust.mesh(bird, smooth=True, smoothing_tolerance=-0.01, stop_after="balls")
        # Features are found after smoothing: with none, the folds of the coarse mesh are creases,
        # as by the default rules, and the refinement ends as it does with them.
        unsmoothed = vorocrust.mesh(bimba, smooth=True, smoothing_iterations=0, stop_after="balls").report()
        rules = vorocrust.mesh(bimba, sharp_angle=60, stop_after="balls").report()
        self.assertGreater(rules["features"]["corners"], 0)
        self.assertEqual(unsmoothed["features"], rules["features"])

    def test_max_aspect_ratio_is_the_programs(self):
        # Cells above the bound split at their centroids, as the program splits them; 0 splits none.
        out = self.out("aspect")
        r = cli("mesh", JOINT, "-o", out, "--seed", "7", "--max-aspect-ratio", "4", "--format", "vtu,seeds", "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        result = vorocrust.mesh(JOINT, seed=7, max_aspect_ratio=4)
        report = result.report()
        self.assertEqual(report["options"]["max_aspect_ratio"], 4)
        self.assertGreater(report["interior"]["aspect_split_seeds"], 0)
        np.testing.assert_array_equal(result.seeds.positions, read_seeds_csv(os.path.join(out, "seeds.csv"))[0])
        self.assertEqual(vorocrust.mesh(JOINT, seed=7, max_aspect_ratio=0).report()["interior"]["aspect_split_seeds"], 0)
        self.assertEqual(vorocrust.DEFAULT_OPTIONS["max_aspect_ratio"], 5)
        with self.assertRaises(vorocrust.UsageError):
            vorocrust.mesh(JOINT, max_aspect_ratio=2)

    def test_clipped_cells_fill_the_joint_exactly(self):
        result = vorocrust.mesh(JOINT, method="clipped", seed=3)
        report = result.report()
        enclosed = report["regions"][1]["volume"]
        self.assertAlmostEqual(float(np.sum(result.cells.volumes)) / enclosed, 1, delta=1e-9)
        self.assertEqual(len(result.cells.volumes), int(np.sum(result.seeds.labels > 0)))
        self.assertEqual(report["options"]["method"], "clipped")

    def test_an_open_sheet_meshes_in_the_box_given(self):
        # A square sheet across the middle of the unit cube: one material on both sides.
        vertices = np.array([[0.2, 0.2, 0.5], [0.8, 0.2, 0.5], [0.8, 0.8, 0.5], [0.2, 0.8, 0.5]])
        triangles = np.array([[0, 1, 2], [0, 2, 3]])
        result = vorocrust.mesh((vertices, triangles), box=(0, 0, 0, 1, 1, 1), max_size=0.2, seed=3)
        cells = result.cells
        self.assertAlmostEqual(cells.volumes.sum(), 1.0, delta=1e-9)
        self.assertAlmostEqual(closed_volume(cells), 1.0, delta=1e-9)
        self.assertEqual(set(cells.materials.tolist()), {1})
        self.assertEqual(result.report()["options"]["box"], [0, 0, 0, 1, 1, 1])
        with self.assertRaises(vorocrust.InvalidGeometryError) as caught:
            vorocrust.mesh((vertices, triangles), box=(0, 0, 0, 1, 1, 0.4))
        self.assertIn("does not lie inside the box", str(caught.exception))

    def test_progress_reports_every_phase(self):
        phases = [p for p, _ in self.phases]
        for phase in ("features", "slivers", "surface quality"):
            self.assertIn(phase, phases)
        self.assertTrue(any(p.startswith("refinement") for p in phases), phases)
        for _, fraction in self.phases:
            self.assertTrue(fraction is None or 0 <= fraction <= 1, fraction)

    def test_a_cancelled_run_raises_and_leaves_no_files(self):
        out = os.path.join(self.dir, "cancelled")
        calls = []

        def cancel_in_refinement(phase, fraction):
            calls.append(phase)
            return not phase.startswith("refinement")

        with self.assertRaises(vorocrust.Cancelled) as caught:
            vorocrust.write_outputs(vorocrust.mesh(JOINT, stop_after="surface", progress=cancel_in_refinement), out)
        self.assertEqual(caught.exception.kind, "cancelled")
        self.assertIn("cancelled", str(caught.exception))
        self.assertFalse(os.path.exists(out))
        # The run stopped at the check that got False: no report came after it.
        self.assertTrue(calls[-1].startswith("refinement"), calls)
        self.assertEqual(sum(1 for c in calls if c.startswith("refinement")), 1, calls)

    def test_an_exception_in_the_callback_propagates(self):
        def fail(phase, fraction):
            if phase == "slivers":
                raise KeyError("stop here")

        with self.assertRaises(KeyError) as caught:
            vorocrust.mesh(JOINT, stop_after="surface", progress=fail)
        self.assertEqual(caught.exception.args, ("stop here",))

    def test_a_run_in_another_thread_gives_the_same_result(self):
        results = []
        thread = threading.Thread(target=lambda: results.append(
            vorocrust.mesh(JOINT, stop_after="surface", seed=7, threads=1, progress=lambda p, f: None)))
        thread.start()
        thread.join()
        np.testing.assert_array_equal(results[0].seeds.positions, self.result.seeds.positions)

    def test_writing_what_the_run_did_not_make_is_refused(self):
        balls_only = vorocrust.mesh(BOX, stop_after="balls")
        self.assertIsNone(balls_only.surface)
        self.assertIsNone(balls_only.seeds)
        self.assertIsNone(balls_only.cells)
        self.assertGreater(len(balls_only.balls), 8)
        self.assertEqual(set(balls_only.balls.types), {0, 1, 2})
        out = os.path.join(self.dir, "refused")
        with self.assertRaises(vorocrust.UsageError) as caught:
            vorocrust.write_outputs(balls_only, out, ["balls", "seeds"])
        self.assertEqual(str(caught.exception), "nothing to write as 'seeds': no seeds (the run stopped after balls)")
        self.assertEqual((caught.exception.kind, caught.exception.message, caught.exception.file),
                         ("usage error", str(caught.exception), None))
        self.assertFalse(os.path.exists(out))
        with self.assertRaises(vorocrust.UsageError):
            vorocrust.write_outputs(self.result, out, ["stl"])
        self.assertIsNone(self.result.cells)

    def test_whole_runs_write_the_programs_files(self):
        for model, arguments, options in (
                (JOINT, [], {}),
                (BOX, ["--interior", "lattice", "--max-size", "0.3"], {"interior": "lattice", "max_size": 0.3}),
                (BOX, ["--interior", "cvt", "--cvt-iterations", "3", "--max-size", "0.3"],
                 {"interior": "cvt", "cvt_iterations": 3, "max_size": 0.3})):
            with self.subTest(model=os.path.basename(model), options=options):
                cli_out, out = self.out("whole_cli"), self.out("whole_module")
                r = cli("mesh", model, "-o", cli_out, "--seed", "7", "-q", *arguments)
                self.assertEqual(r.returncode, 0, r.stderr)
                result = vorocrust.mesh(model, seed=7, **options)
                written = vorocrust.write_outputs(result, out)
                self.assertIn(os.path.join(out, "mesh.vtu"), written)
                for name in ("seeds.csv", "surface.obj", "mesh.vtu", "case/constant/polyMesh/points",
                             "case/constant/polyMesh/faces", "case/constant/polyMesh/owner",
                             "case/constant/polyMesh/neighbour", "case/constant/polyMesh/boundary",
                             "case/constant/polyMesh/cellZones"):
                    self.assertEqual(read_bytes(os.path.join(out, name)), read_bytes(os.path.join(cli_out, name)), name)
                with open(os.path.join(cli_out, "report.json")) as f:
                    cli_report = json.load(f)
                report = result.report()
                self.assertEqual(report["cells"], cli_report["cells"])
                self.assertEqual(_without_seconds(report["interior"]), _without_seconds(cli_report["interior"]))
                self.assertEqual(report["options"]["interior"], options.get("interior", "random"))
                # The arrays: a cell per material seed, interior and outside seeds after the surface seeds.
                seeds, cells = result.seeds, result.cells
                kinds = list(seeds.kinds)
                self.assertLessEqual({"surface", "interior", "outside", "cap"}, set(kinds))
                self.assertLessEqual(set(kinds), {"surface", "interior", "outside", "cap", "repair"})
                self.assertEqual(kinds.count("repair"), report["interior"]["split_seeds"])
                surface_seeds = kinds.count("surface")
                self.assertEqual(kinds[:surface_seeds], ["surface"] * surface_seeds)  # surface seeds first
                self.assertEqual(cells.num_cells, int((seeds.labels > 0).sum()))
                np.testing.assert_array_equal(seeds.labels[cells.cell_seeds], cells.materials)
                total = cells.volumes.sum()
                self.assertAlmostEqual(total, report["cells"]["volume"], delta=1e-12 * total)
                self.assertAlmostEqual(closed_volume(cells), total, delta=1e-9 * total)
                enclosed = sum(report["input"]["shell_volumes"])
                self.assertAlmostEqual(total, enclosed, delta=0.01 * enclosed)


class Example(unittest.TestCase):
    def test_the_sample_runs_and_its_cells_fill_the_joint(self):
        sample = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "samples", "python_example.py")
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "out")
            r = subprocess.run([sys.executable, sample, JOINT, out], capture_output=True, text=True, timeout=600)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            for name in ("seeds.csv", "surface.obj", "mesh.vtu", "case/constant/polyMesh/owner"):
                self.assertTrue(os.path.isfile(os.path.join(out, name)), name)
        m = re.search(r"volume (\S+) \(the input encloses (\S+)\)", r.stdout)
        self.assertIsNotNone(m, r.stdout)
        self.assertAlmostEqual(float(m.group(1)), float(m.group(2)), delta=0.01 * float(m.group(2)))


class Errors(unittest.TestCase):
    def test_bad_files_raise_the_programs_message(self):
        with open(os.path.join(DATA, "bad", "expected.tsv")) as f:
            rows = [line.rstrip("\n").split("\t") for line in f if line.strip() and not line.startswith("#")]
        self.assertGreater(len(rows), 20)
        for name, kind, _, line, phrase in rows:
            path = os.path.join(DATA, "bad", name)
            with self.subTest(name=name):
                with self.assertRaises(CLASSES[kind]) as caught:
                    vorocrust.read_mesh(path)
                e = caught.exception
                self.assertIsInstance(e, vorocrust.Error)
                self.assertEqual(e.kind, kind)
                self.assertIn(phrase, e.message)
                self.assertEqual(e.file, path)
                self.assertEqual(e.line, int(line) or None)
                # The message the program prints, word for word.
                r = cli("info", path)
                self.assertEqual(r.stderr, "vorocrust: %s: %s\n" % (kind, e))

    def test_mesh_names_the_file_and_line(self):
        path = os.path.join(DATA, "bad", "truncated_faces.off")
        with self.assertRaises(vorocrust.UnreadableInputError) as caught:
            vorocrust.mesh(path)
        self.assertTrue(str(caught.exception).startswith(path + ":"), str(caught.exception))
        self.assertIsNotNone(caught.exception.line)

    def test_self_intersections_are_resolved_unless_refused(self):
        path = os.path.join(DATA, "invalid", "cube_pierced.off")
        self.assertEqual(vorocrust.DEFAULT_OPTIONS["self_intersections"], "resolve")
        run = vorocrust.mesh(path, stop_after="balls")
        resolved = run.report()["self_intersections"]
        self.assertEqual(resolved["face_pairs"], 4)
        self.assertGreater(resolved["faces_cut"], 0)
        with self.assertRaises(vorocrust.InvalidGeometryError) as caught:
            vorocrust.mesh(path, stop_after="balls", self_intersections="refuse")
        self.assertIn("cube_pierced.off line", str(caught.exception))
        self.assertIn('self_intersections resolve', str(caught.exception))
        with self.assertRaises(vorocrust.UsageError):
            vorocrust.mesh(path, stop_after="balls", self_intersections="ignore")
        findings = vorocrust.validate(vorocrust.read_mesh(path))
        self.assertTrue(findings["has_errors"])
        self.assertEqual([f["code"] for f in findings["findings"] if f["severity"] == "error"], ["self-intersection"])

    def test_bad_arrays(self):
        v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
        t = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        self.assertEqual(vorocrust.Surface(v, t, "tet").num_faces, 4)
        bad = t.copy()
        bad[2, 1] = 9
        with self.assertRaises(vorocrust.UnreadableInputError) as caught:
            vorocrust.Surface(v, bad, "tet")
        self.assertEqual(str(caught.exception),
                         "tet: triangle 2 has vertex index 9, out of range: there are 4 vertices (0-based)")
        self.assertEqual(caught.exception.face, 2)
        nan = v.copy()
        nan[3, 0] = math.nan
        with self.assertRaises(vorocrust.InvalidGeometryError) as caught:
            vorocrust.mesh((nan, t))
        self.assertEqual(str(caught.exception),
                         "arrays: vertex 3 has a coordinate that is not a finite number (NaN or infinity)")
        with self.assertRaises(vorocrust.UsageError) as caught:
            vorocrust.Surface(v[:, :2], t)
        self.assertIn("n x 3", str(caught.exception))
        with self.assertRaises(TypeError):
            vorocrust.Surface(v, t.astype(float))  # indices must be integers

    def test_options_out_of_range(self):
        # The library's messages, naming each option as mesh() names it.
        for options, phrase in (({"lipschitz": 1.5}, "lipschitz must lie strictly between 0 and 1, got 1.5"),
                                ({"sharp_angle": 95}, "sharp_angle must lie strictly between 0 and 90 degrees"),
                                ({"max_size": -1}, "max_size must be above 0, got -1"),
                                ({"seed": -5}, "seed must lie between 0 and 2147483647, got -5"),
                                ({"seed": 2 ** 70}, "seed is out of its range"),
                                ({"smooth": "yes"}, "smooth takes True or False"),
                                ({"interior": "hex"}, "interior must be random, lattice or cvt, got 'hex'"),
                                ({"stop_after": "seeds"}, "stop_after must be balls, surface or cells, got 'seeds'"),
                                ({"sharpangle": 30}, "unknown option 'sharpangle'")):
            with self.subTest(options=options):
                with self.assertRaises(vorocrust.UsageError) as caught:
                    vorocrust.mesh(BOX, **options)
                self.assertIn(phrase, str(caught.exception))

    def test_cells_of_seeds_that_do_not_enclose_the_material(self):
        grid = np.array([[i, j, k] for i in range(4) for j in range(4) for k in range(4)], float)
        with self.assertRaises(vorocrust.InvalidGeometryError) as caught:
            vorocrust.compute_cells(vorocrust.Seeds(grid, np.ones(len(grid), int)))
        self.assertIn("is not bounded by seeds", str(caught.exception))

    def test_unwritable_output(self):
        result = vorocrust.mesh(BOX, stop_after="balls")
        with tempfile.TemporaryDirectory() as d:
            blocker = os.path.join(d, "file")
            open(blocker, "w").close()
            with self.assertRaises(vorocrust.OutputError):
                vorocrust.write_balls(result.balls, os.path.join(blocker, "balls.csv"))


class Data(unittest.TestCase):
    def test_seeds_round_trip_through_seeds_csv(self):
        positions = np.array([[0.1, 0.2, 0.3], [1, 2, 3], [-1e-300, 5e300, 0.0]])
        seeds = vorocrust.Seeds(positions, [1, 0, 2], [0.5, 0.25, 1.0], ["surface", "outside", "interior"])
        with tempfile.TemporaryDirectory() as d:
            vorocrust.write_seeds(seeds, os.path.join(d, "seeds.csv"))
            back = vorocrust.read_seeds(os.path.join(d, "seeds.csv"))
        np.testing.assert_array_equal(back.positions, positions)
        np.testing.assert_array_equal(back.labels, [1, 0, 2])
        np.testing.assert_array_equal(back.radii, [0.5, 0.25, 1.0])
        self.assertEqual(list(back.kinds), ["surface", "outside", "interior"])
        self.assertEqual(list(vorocrust.Seeds(positions, [1, 0, 2]).kinds), ["interior", "outside", "interior"])
        with self.assertRaises(vorocrust.UsageError) as caught:
            vorocrust.Seeds(positions, [1, 0, 2], kinds=["surface", "outside", "inside"])
        self.assertEqual(caught.exception.message,
                         "unknown seed kind 'inside': expected surface, interior, outside, cap or repair")
        with self.assertRaises(vorocrust.UsageError):
            vorocrust.Seeds(positions, [1, 0, 2**40])

    def test_info_is_the_programs_info_json(self):
        for name in ("cgal_joint.off", "openmeeg_HeadNNc3.obj"):
            path = os.path.join(MODELS, name)
            r = cli("info", "--json", path)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(vorocrust.info(vorocrust.read_mesh(path)), json.loads(r.stdout))

    def test_merged_parts_keep_their_names(self):
        box = vorocrust.read_mesh(BOX)
        far = vorocrust.Surface(box.vertices + 5, box.triangles, "far box")
        merged = vorocrust.merge_surfaces([("near", box), ("far", far)])
        self.assertEqual(merged.groups, ["near", "far"])
        self.assertEqual(merged.num_vertices, 16)
        np.testing.assert_array_equal(merged.face_groups, [0] * 12 + [1] * 12)
        self.assertEqual(vorocrust.info(merged)["components"], 2)

    def test_quality_of_a_surface_against_itself(self):
        joint = vorocrust.read_mesh(JOINT)
        q = vorocrust.measure_surface_quality(joint, joint, samples=1000)
        self.assertEqual(q["hausdorff"]["two_sided"] if "two_sided" in q["hausdorff"] else q["hausdorff"]["distance"], 0)
        self.assertTrue(q["topology"]["matches"])

    def test_every_public_name_is_documented(self):
        for name in vorocrust.__all__:
            obj = getattr(vorocrust, name)
            if isinstance(obj, (str, tuple, dict)):
                continue
            with self.subTest(name=name):
                self.assertTrue((obj.__doc__ or "").strip(), name)
            if inspect.isclass(obj) and not issubclass(obj, BaseException):
                for member, value in vars(obj).items():
                    if member.startswith("_"):
                        continue
                    with self.subTest(name="%s.%s" % (name, member)):
                        self.assertTrue((getattr(value, "__doc__", None) or "").strip(), member)


def _without_seconds(value):
    """A report part without its timings, which differ between runs."""
    if isinstance(value, dict):
        return {k: _without_seconds(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [_without_seconds(v) for v in value]
    return value


if __name__ == "__main__":
    unittest.main(verbosity=2)
