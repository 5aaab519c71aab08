#!/usr/bin/env python3
"""The `vorocrust` program as a user meets it: exit codes, one-line messages, JSON, report.json.

Run by CTest as: python3 test_cli.py VOROCRUST_BINARY MODELS_DIR TEST_DATA_DIR
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

BINARY, MODELS, DATA = sys.argv[1:4]
del sys.argv[1:4]


def run(*args, **kwargs):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=300, **kwargs)


def model(name):
    return os.path.join(MODELS, name)


def bad_manifest():
    with open(os.path.join(DATA, "bad", "expected.tsv")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            name, kind, code, line_no, phrase = line.rstrip("\n").split("\t")
            yield name, kind, int(code), int(line_no), phrase


class Info(unittest.TestCase):
    def test_head_json_counts(self):
        r = run("info", model("openmeeg_HeadNNc3.obj"), "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        doc = json.loads(r.stdout)
        self.assertEqual(doc["faces"], 5350)
        self.assertEqual(doc["vertices"], 2607)
        self.assertEqual(doc["non_manifold_edges"], 150)
        self.assertEqual(doc["boundary_edges"], 0)
        self.assertEqual(doc["components"], 3)
        self.assertEqual([g["name"] for g in doc["groups"]], ["cut", "north", "scalp", "skull", "south"])
        self.assertEqual(sum(g["faces"] for g in doc["groups"]), 5350)
        self.assertIsNone(doc["genus"])
        self.assertTrue(doc["valid"])

    def test_text_output_for_a_closed_model(self):
        r = run("info", model("cgal_joint.off"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, r"faces\s+446")
        self.assertRegex(r.stdout, r"genus\s+2")
        self.assertRegex(r.stdout, r"component 0: 446 faces, genus 2, volume \d")
        self.assertRegex(r.stdout, r"findings\s+none")

    def test_volume_of_the_unit_box(self):
        doc = json.loads(run("info", "--json", model("sandia_OneBox.obj")).stdout)
        box = doc["bounding_box"]
        size = [hi - lo for lo, hi in zip(box["min"], box["max"])]
        self.assertAlmostEqual(doc["shell_volumes"][0], size[0] * size[1] * size[2], places=12)

    def test_several_inputs_merge(self):
        doc = json.loads(run("info", "--json", model("sandia_OneBox.obj"), model("cgal_joint.off")).stdout)
        self.assertEqual(doc["faces"], 458)
        self.assertEqual([g["name"] for g in doc["groups"]], ["sandia_OneBox", "cgal_joint"])
        self.assertEqual(len(doc["shell_volumes"]), 2)


class BadInput(unittest.TestCase):
    def test_every_corpus_file_fails_with_its_code_and_message(self):
        for name, kind, code, line_no, phrase in bad_manifest():
            with self.subTest(file=name):
                path = os.path.join(DATA, "bad", name)
                r = run("info", path)
                self.assertEqual(r.returncode, code, r.stderr)
                self.assertEqual(r.stdout, "", "nothing but the error on failure")
                lines = r.stderr.strip().splitlines()
                self.assertEqual(len(lines), 1, r.stderr)
                location = f"{path}:{line_no}: " if line_no else f"{path}: "
                self.assertIn(f"vorocrust: {kind}: {location}", lines[0])
                self.assertIn(phrase, lines[0])

    def test_named_cases_from_the_issue(self):
        cases = {"truncated_binary.stl": (3, "truncated binary STL"),
                 "obj_index_past_end.obj": (3, "face refers to vertex 99"),
                 "all_nan.off": (4, "not a finite number")}
        for name, (code, phrase) in cases.items():
            r = run("info", os.path.join(DATA, "bad", name))
            self.assertEqual(r.returncode, code)
            self.assertIn(phrase, r.stderr)

    def test_missing_file(self):
        r = run("info", "/nonexistent/model.obj")
        self.assertEqual(r.returncode, 3)
        self.assertIn("/nonexistent/model.obj: cannot open: no such file", r.stderr)

    def test_self_intersection_is_invalid_geometry_with_pairs(self):
        r = run("info", "--json", os.path.join(DATA, "invalid", "cube_pierced.off"))
        self.assertEqual(r.returncode, 4)
        doc = json.loads(r.stdout)
        self.assertFalse(doc["valid"])
        (finding,) = [f for f in doc["findings"] if f["code"] == "self-intersection"]
        self.assertEqual(finding["severity"], "error")
        # The piercing triangle (face 12) crosses the bottom and top diagonals: both triangles of each.
        self.assertEqual(sorted(finding["face_pairs"]), [[0, 12], [1, 12], [2, 12], [3, 12]])
        self.assertIn("invalid geometry", r.stderr)

    def test_orientation_is_fixed_and_reported(self):
        r = run("info", os.path.join(DATA, "invalid", "cube_flipped_face.off"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("fixed [inconsistent-orientation]: 1 faces flipped", r.stdout)


class Usage(unittest.TestCase):
    def test_no_subcommand_is_a_usage_error(self):
        self.assertEqual(run().returncode, 2)

    def test_unknown_option(self):
        r = run("info", "--frobnicate", model("cgal_joint.off"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("usage error", r.stderr)

    def test_help_names_every_mesh_option(self):
        r = run("mesh", "--help")
        self.assertEqual(r.returncode, 0)
        for option in ("--output", "--seed", "--threads", "--quiet", "--lipschitz", "--sharp-angle", "--max-size"):
            self.assertIn(option, r.stdout)
        self.assertIn("Exit codes", run("--help").stdout)

    def test_out_of_range_option(self):
        with tempfile.TemporaryDirectory() as out:
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--lipschitz", "1.5")
            self.assertEqual(r.returncode, 2)
            self.assertIn("--lipschitz must lie strictly between 0 and 1", r.stderr)
            for bad, says in (("2", "must be at least 3, or 0 (no splits), got 2"),
                              ("-1", "must be at least 3, or 0 (no splits), got -1"),
                              ("inf", "must be a finite number, got inf")):
                r = run("mesh", model("cgal_joint.off"), "-o", out, "--max-aspect-ratio", bad)
                self.assertEqual(r.returncode, 2, bad)
                self.assertIn("--max-aspect-ratio " + says, r.stderr)
            # A whole number out of its range, a negative one where no sign is meant included, is
            # named, never wrapped around.
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--seed", "-5")
            self.assertEqual(r.returncode, 2)
            self.assertIn("--seed must lie between 0 and 2147483647, got -5", r.stderr)
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--sharp-angle", "abc")
            self.assertEqual(r.returncode, 2)
            self.assertIn("--sharp-angle takes a number, got 'abc'", r.stderr)


class Mesh(unittest.TestCase):
    def test_makes_the_whole_mesh_and_writes_report(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "run")
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--seed", "7", "--threads", "1")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("mesh.vtu (open it in ParaView)", r.stderr)
            self.assertIn("checkMesh -case " + os.path.join(out, "case"), r.stderr)
            # Not a terminal: plain progress lines, no carriage returns.
            self.assertIn("vorocrust: reading ...", r.stderr)
            self.assertNotIn("\r", r.stderr)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertEqual(report["status"], "ok")
            self.assertEqual(report["options"]["seed"], 7)
            self.assertEqual(report["options"]["threads"], 1)
            self.assertEqual(report["input"]["faces"], 446)
            self.assertEqual([t["phase"] for t in report["timings"]][:2], ["reading", "validating"])
            self.assertEqual(sorted(os.listdir(out)),
                             ["MESH", "balls.csv", "balls.vtk", "case", "mesh.exo", "mesh.vtu", "pflotran", "quality.svg",
                              "report.html", "report.json", "seeds.csv", "surface.obj", "surface.ply"])
            self.assertEqual(report["features"]["corners"], 12)
            self.assertEqual(report["refinement"]["balls"]["corner"], 12)
            self.assertEqual(report["slivers"]["half_covered_left"], 0)
            # Every material seed has a cell; the cells' boundary is the output surface.
            with open(os.path.join(out, "seeds.csv")) as f:
                rows = list(csv.DictReader(f))
            kinds = [row["kind"] for row in rows]
            self.assertEqual(kinds.count("interior"), report["interior"]["interior_seeds"])
            self.assertEqual(kinds.count("outside"), report["interior"]["outside_seeds"])
            self.assertEqual(sum(1 for row in rows if row["label"] != "0"), report["cells"]["cells"])
            self.assertEqual(report["cells"]["boundary_faces"], report["surface"]["triangles"])
            # The memory guard's estimate, made before the cells, against the peak the kernel saw.
            memory = report["memory"]
            self.assertGreater(memory["resident_bytes_before_cells"], 0)
            self.assertGreater(memory["estimated_peak_bytes"], memory["resident_bytes_before_cells"])
            self.assertLess(abs(memory["estimated_peak_bytes"] / memory["peak_resident_bytes"] - 1), 0.25)
            # Each phase's peak is the process's by its (last) end: the reading's the lowest, none
            # above the whole run's, and the cells' stages hold the most.
            peaks = {t["phase"]: t["peak_resident_bytes"] for t in report["timings"]}
            self.assertGreater(peaks["reading"], 0)
            self.assertEqual(min(peaks.values()), peaks["reading"])
            self.assertLessEqual(max(peaks.values()), memory["peak_resident_bytes"])
            self.assertGreater(peaks["assembly"], peaks["interior seeds"])
            # A run that stops at the surface leaves no volume mesh of the run before.
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--stop-after", "surface", "-q")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertNotIn("mesh.vtu", os.listdir(out))
            self.assertNotIn("case", os.listdir(out))

    def test_surface_files_agree_with_the_report_and_stale_ones_go(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "run")
            r = run("mesh", model("sandia_torus.obj"), "-o", out, "--stop-after", "surface", "-q")
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertEqual(report["options"]["stop_after"], "surface")
            slivers = report["slivers"]
            self.assertEqual(slivers["iterations"] + 1, len(slivers["per_iteration"]))
            self.assertEqual(slivers["per_iteration"][-1]["half_covered"], 0)
            self.assertEqual(slivers["sliver_rounds"], slivers["iterations"])  # nothing split by default
            self.assertEqual(slivers["per_iteration"][-1]["shrunk_for"], "nothing")
            for it in slivers["per_iteration"][:-1]:
                self.assertEqual(it["shrunk_for"], "slivers")
                self.assertGreater(it["half_covered"], 0)
                self.assertGreater(it["max_shrinkage_ratio"], 0)
            with open(os.path.join(out, "seeds.csv")) as f:
                rows = list(csv.DictReader(f))
            self.assertEqual(list(rows[0].keys()), ["x", "y", "z", "label", "radius", "kind"])
            self.assertEqual(len(rows), report["surface"]["surface_seeds"])
            self.assertEqual({row["kind"] for row in rows}, {"surface"})
            # The torus bounds one material: every facet separates a seed inside from one outside.
            self.assertEqual(len(rows), 2 * report["surface"]["triangles"])
            self.assertEqual({(rows[i]["label"], rows[i + 1]["label"]) for i in range(0, len(rows), 2)},
                             {("0", "1"), ("1", "0")})
            quality = report["surface"]["quality"]
            self.assertTrue(quality["topology"]["matches"])
            self.assertLess(quality["hausdorff"]["percent_of_bounding_box_diagonal"], 1.0)
            self.assertGreater(quality["triangle_quality"]["min"], 0.3)
            info = json.loads(run("info", "--json", os.path.join(out, "surface.ply")).stdout)
            self.assertEqual(info["faces"], report["surface"]["triangles"])
            self.assertEqual(info["genus"], 1)
            self.assertEqual(info["boundary_edges"], 0)
            self.assertEqual(sorted(info["regions"]), ["inside", "outside"])
            # Stopping earlier in the same folder leaves no surface from the run before.
            r = run("mesh", model("sandia_torus.obj"), "-o", out, "--stop-after", "balls", "-q")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(sorted(os.listdir(out)), ["balls.csv", "balls.vtk", "report.json"])

    def test_quiet_prints_only_the_error(self):
        with tempfile.TemporaryDirectory() as out:
            r = run("mesh", os.path.join(DATA, "invalid", "cube_pierced.off"), "-o", out, "--quiet",
                    "--self-intersections", "refuse")
            self.assertEqual(r.returncode, 4)
            self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)

    def test_self_intersections_are_resolved_refused_or_kept(self):
        pierced = os.path.join(DATA, "invalid", "cube_pierced.off")
        with tempfile.TemporaryDirectory() as out:
            # By default the faces are cut where they cross: the warning names them, the run goes on.
            r = run("mesh", pierced, "-o", out, "--stop-after", "balls")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("warning: 4 pairs of intersecting faces", r.stderr)
            self.assertIn("self-intersections resolved", r.stderr)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertEqual(report["options"]["self_intersections"], "resolve")
            resolved = report["self_intersections"]
            self.assertEqual(resolved["face_pairs"], 4)
            self.assertGreater(resolved["faces_cut"], 0)
            self.assertGreater(resolved["faces"], 13)
            # Asked to, the run stops before meshing and says how to go on.
            r = run("mesh", pierced, "-o", out, "--self-intersections", "refuse")
            self.assertEqual(r.returncode, 4)
            self.assertIn("pairs of intersecting faces", r.stderr)
            self.assertIn("--self-intersections resolve", r.stderr)
            with open(os.path.join(out, "report.json")) as f:
                self.assertEqual(json.load(f)["status"], "invalid geometry")
            # Kept as they are, the curve where the surfaces cross is no feature, so the balls
            # cannot converge there, and the run ends with a message naming the face where the
            # uncovered pieces crowd, and a point of it.
            r = run("mesh", pierced, "-o", out, "--self-intersections", "keep", "--stop-after", "balls")
            self.assertEqual(r.returncode, 4, r.stderr)
            self.assertIn("refinement cannot converge", r.stderr)
            self.assertRegex(r.stderr, r"crowding most on face \d+ \(cube_pierced.off line \d+\) \(\d+ pieces\) near \(")

    def test_a_run_above_the_memory_bound_is_refused_while_its_seeds_are_placed(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "run")
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--max-memory", "0.01", "-q")
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertRegex(r.stderr, r"would need more than [0-9.e+-]+ GB at its peak: the seeds placed so far already "
                                       r"make \d+ cells \([0-9.e+-]+ GB now and about 2\.5 KB for each\), above "
                                       r"--max-memory's 0\.01 GB: raise it, or make fewer cells \(a larger maximum size "
                                       r"or Lipschitz constant\)")
            with open(os.path.join(out, "report.json")) as f:
                self.assertNotEqual(json.load(f)["status"], "ok")
            self.assertEqual([f for f in os.listdir(out) if f.startswith("mesh") or f == "case"], [])
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--max-memory", "4", "-q", "--format", "seeds")
            self.assertEqual(r.returncode, 0, r.stderr)

    def test_a_run_of_far_too_many_cells_stops_before_its_seeds_fill_the_memory(self):
        # A maximum size of a hundredth of the part: about a million cells, some 2.5 GB. The sampler
        # stops once its seeds alone need more than the bound, so the run never holds more.
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "run")
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--max-size", "0.01", "--max-memory", "0.3", "-q")
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertIn("the seeds placed so far already make", r.stderr)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertNotEqual(report["status"], "ok")
            phases = [t["phase"] for t in report["timings"]]
            self.assertEqual(phases[-1], "interior seeds")
            self.assertLess(max(t["peak_resident_bytes"] for t in report["timings"]), 0.3e9)

    def test_a_maximum_size_too_small_for_the_memory_is_refused_before_the_surface_stages(self):
        # A fifth of a millimetre on a part a metre across: 10^10 cells, terabytes on any machine.
        # No bound given: the machine's memory is the bound, and the run stops after the regions.
        volume = 0.3594944502  # cgal_joint's, as `vorocrust info` gives it
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "run")
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--max-size", "0.0002", "-q")
            self.assertEqual(r.returncode, 2, r.stderr)
            found = re.search(r"--max-size 0\.0002 asks for at least ([0-9.e+]+) cells \(the materials' volume 0\.3595, "
                              r"a ball of radius --max-size at most for each\), which would need at least ([0-9.e+]+) GB "
                              r"at about 2\.5 KB for each, above this machine's ([0-9.]+) GB: raise --max-size \(above "
                              r"([0-9.e-]+) for that memory\)\n", r.stderr)
            self.assertIsNotNone(found, r.stderr)
            cells, needed, machine, fitting = (float(x) for x in found.groups())
            self.assertAlmostEqual(cells / (volume / (4 / 3 * math.pi * 0.0002 ** 3)), 1, places=2)
            self.assertAlmostEqual(needed / (cells * 2500 / 1e9), 1, places=2)
            # The size offered needs just the machine's memory.
            self.assertAlmostEqual(volume / (4 / 3 * math.pi * fitting ** 3) * 2500 / 1e9 / machine, 1, places=1)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertEqual(report["status"], "usage error")
            self.assertEqual(report["timings"][-1]["phase"], "regions")
            self.assertEqual([f for f in os.listdir(out) if f != "report.json"], [])
            # With a bound given, that bound; the message names both options.
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--max-size", "0.003", "--max-memory", "2", "-q")
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertRegex(r.stderr, r"above --max-memory's 2 GB: raise --max-size \(above 0\.00475 for that memory\) "
                                       r"or --max-memory\n")

    def test_a_run_above_the_memory_bound_is_refused_before_its_cells(self):
        # A cube's few interior seeds never reach the sampler's first check: the guard after them.
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "run")
            r = run("mesh", os.path.join(DATA, "invalid", "cube.off"), "-o", out, "--max-memory", "0.01", "-q")
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertRegex(r.stderr, r"would need about [0-9.e+-]+ GB at its peak \([0-9.e+-]+ GB now and about 2\.5 KB "
                                       r"for each of its \d+ cells\), above --max-memory's 0\.01 GB: raise it, or make "
                                       r"fewer cells \(a larger maximum size or Lipschitz constant\)")
            self.assertEqual([f for f in os.listdir(out) if f.startswith("mesh") or f == "case"], [])

    def test_unreadable_input_still_leaves_a_report(self):
        with tempfile.TemporaryDirectory() as out:
            r = run("mesh", os.path.join(DATA, "bad", "truncated_binary.stl"), "-o", out)
            self.assertEqual(r.returncode, 3)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertEqual(report["status"], "unreadable input")
            self.assertIn("truncated binary STL", report["message"])

    def test_unwritable_output_folder(self):
        with tempfile.NamedTemporaryFile() as not_a_folder:
            r = run("mesh", model("sandia_OneBox.obj"), "-o", not_a_folder.name)
            self.assertEqual(r.returncode, 5)
            self.assertIn("output error", r.stderr)


class Balls(unittest.TestCase):
    def test_stop_after_balls_writes_csv_vtk_and_table_one(self):
        with tempfile.TemporaryDirectory() as out:
            r = run("mesh", model("sandia_OneBox.obj"), "-o", out, "--stop-after", "balls", "--seed", "3")
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(out, "balls.csv")) as f:
                rows = f.read().splitlines()
            self.assertEqual(rows[0], "x,y,z,radius,stratum_type,stratum_index")
            types = [row.split(",")[4] for row in rows[1:]]
            self.assertEqual(types.count("corner"), 8)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            self.assertEqual(report["status"], "ok")
            self.assertEqual(report["refinement"]["balls"]["total"], len(rows) - 1)
            for row in ("corner_protection", "edge_protection", "surface_coverage", "fixing_c3_violations"):
                self.assertGreaterEqual(report["refinement"]["seconds"][row], 0)
            # Same seed, same balls.
            with tempfile.TemporaryDirectory() as again:
                run("mesh", model("sandia_OneBox.obj"), "-o", again, "--stop-after", "balls", "--seed", "3")
                with open(os.path.join(again, "balls.csv")) as f:
                    self.assertEqual(f.read().splitlines(), rows)

    def test_tets_asked_of_a_vorocrust_mesh_are_said_to_be_none(self):
        # tets.vtu is the dual of a clipped mesh: asked for by name on a VoroCrust run, a warning
        # says none comes; by default (every format) nothing is said.
        said = "asks for tets (tets.vtu), the tetrahedra dual to a clipped mesh"
        with tempfile.TemporaryDirectory() as out:
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--format", "tets,seeds")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("(--method 'clipped' makes a clipped mesh)", r.stderr)
            self.assertIn(said, r.stderr)
            self.assertEqual(sorted(os.listdir(out)), ["report.json", "seeds.csv"])
        with tempfile.TemporaryDirectory() as out:
            r = run("mesh", model("cgal_joint.off"), "-o", out, "--stop-after", "surface")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertNotIn(said, r.stderr)

    def test_a_scan_meshed_as_a_cad_part_gets_the_hint_naming_smooth(self):
        # The bunny at the default sharp angle: its folds would be creases. With --smooth, or for a
        # CAD part (the fandisk), no hint.
        hint = "looks like a scan or a tessellation of a curved shape"
        with tempfile.TemporaryDirectory() as out:
            r = run("mesh", model("igl_bunny.off"), "-o", out, "--stop-after", "balls")
            self.assertEqual(r.returncode, 0, r.stderr)
            lines = [line for line in r.stderr.splitlines() if hint in line]
            self.assertEqual(len(lines), 1, r.stderr)
            self.assertIn("Mesh it with --smooth, or with a larger --sharp-angle", lines[0])
            self.assertIn("bend past --sharp-angle (30 degrees)", lines[0])
            # Said before the refinement starts.
            self.assertLess(r.stderr.index(hint), r.stderr.index("refinement"))
            r = run("mesh", model("igl_bunny.off"), "-o", out, "--stop-after", "balls", "--smooth")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertNotIn(hint, r.stderr)
            r = run("mesh", model("cgal_fandisk.off"), "-o", out, "--stop-after", "balls")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertNotIn(hint, r.stderr)

    def test_sizing_file_bounds_radii_and_bad_sizing_names_the_line(self):
        with tempfile.TemporaryDirectory() as out:
            sizing = os.path.join(out, "sizing.txt")
            with open(sizing, "w") as f:
                f.write("# x y z size\n-10 -10 -10 0.05\n10 10 10 0.05\n")
            r = run("mesh", model("sandia_OneBox.obj"), "-o", out, "--stop-after", "balls", "--sizing", sizing)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(out, "balls.csv")) as f:
                radii = [float(row.split(",")[3]) for row in f.read().splitlines()[1:]]
            self.assertLessEqual(max(radii), 0.05)
            with open(sizing, "w") as f:
                f.write("0 0 0 1\n1 1 oops 1\n")
            r = run("mesh", model("sandia_OneBox.obj"), "-o", out, "--stop-after", "balls", "--sizing", sizing)
            self.assertEqual(r.returncode, 3)
            self.assertIn("sizing.txt:2: expected a z coordinate, found 'oops'", r.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
