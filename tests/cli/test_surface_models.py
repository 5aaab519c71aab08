#!/usr/bin/env python3
"""The surface stage (paper 2.4) on the models of the surface-seeds issue.

For each model, `vorocrust mesh MODEL --stop-after surface`: the run ends with no half-covered
seed pair, the output surface has the input's topology (checked by `vorocrust info`, apart from
the mesher's own figures), every corner ball's centre is a vertex of the surface, the balls after
sliver elimination still meet C1-C4 (the independent `check-balls`), and report.json holds the
paper's quality figures, which stay above floors measured on these models.

Run by CTest as: python3 test_surface_models.py VOROCRUST_BINARY MODELS_DIR
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]

# model, options, floor for Q min, ceiling for the Hausdorff distance in % of the diagonal,
# floor for the smallest angle in degrees, ceiling for the share of angles below 30 degrees in %,
# ceiling for the change of the enclosed volume in %.
# Sharp models use the default rules; their worst triangles sit at creases and corners, where
# the protecting balls set the spacing (the public implementation's sandia_bracket: 6.8 % below
# 30 degrees). The smooth models are meshed as the smooth surfaces they are (--smooth: no creases
# from their tessellation, 60 degrees, 6 rounds of Loop subdivision and skinny triangles split,
# as the paper meshes smooth models), and must reach the paper's smooth figures: at most 0.1 %
# of angles below 30 degrees, Q min at least 0.4. By the default rules igl_bunny keeps 1 090
# corners at 30 degrees and 187 at 60, and its worst triangles sit there (Q min 0.03 to 0.09,
# smallest angle 1 to 3 degrees). directional_bimba (697 vertices, folds up to 129 degrees) is
# smoothed within the default --smoothing-tolerance (0.0075 of the diagonal): Loop's rules alone
# would take it 1.56 % of its diagonal away.
CASES = [
    ("cgal_joint.off", [], 0.15, 1.0, 4, 8, 1),
    # Q min on fandisk spans 0.10 to 0.18 over seeds 1 to 4: one triangle decides it.
    ("cgal_fandisk.off", [], 0.1, 1.0, 3, 9, 1),
    ("sandia_bracket.obj", [], 0.12, 1.0, 3, 9, 1),
    # The public implementation's torus loses 6.7 % of its volume; Loop's rules shrink it by 3.6 %.
    ("sandia_torus.obj", [], 0.35, 1.0, 20, 1, 2),
    ("sandia_torus.obj", ["--smooth"], 0.4, 1.0, 28, 0.1, 5),
    ("igl_bunny.off", ["--smooth"], 0.4, 1.0, 25, 0.1, 2),
    ("directional_bimba.off", ["--smooth"], 0.4, 1.0, 24, 0.1, 3),
]


def run(*args, timeout=1200):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=timeout)


def topology(path):
    info = json.loads(run("info", "--json", "--no-self-intersections", path).stdout)
    return {k: info[k] for k in ("boundary_edges", "non_manifold_edges", "genus")}, len(info["component_details"])


def obj_vertices(path):
    with open(path) as f:
        return {tuple(float(x) for x in line.split()[1:4]) for line in f if line.startswith("v ")}


class SurfaceOfEachModel(unittest.TestCase):
    def test_each_model(self):
        for name, options, q_floor, hausdorff_ceiling, angle_floor, below_30_ceiling, volume_ceiling in CASES:
            with self.subTest(model=name), tempfile.TemporaryDirectory() as out:
                path = os.path.join(MODELS, name)
                r = run("mesh", path, "-o", out, "--stop-after", "surface", "-q", *options)
                self.assertEqual(r.returncode, 0, r.stderr)
                with open(os.path.join(out, "report.json")) as f:
                    report = json.load(f)
                slivers = report["slivers"]
                self.assertEqual(slivers["half_covered_left"], 0)
                self.assertEqual(slivers["per_iteration"][-1]["half_covered"], 0)
                self.assertFalse(slivers["safe_mode"])

                self.assertEqual(topology(os.path.join(out, "surface.obj")), topology(path))
                quality = report["surface"]["quality"]
                self.assertTrue(quality["topology"]["matches"])

                with open(os.path.join(out, "balls.csv")) as f:
                    corners = {(float(b["x"]), float(b["y"]), float(b["z"]))
                               for b in csv.DictReader(f) if b["stratum_type"] == "corner"}
                self.assertEqual(len(corners), report["features"]["corners"])
                self.assertLessEqual(corners, obj_vertices(os.path.join(out, "surface.obj")))

                # A smoothed run covers the surface it smoothed, which it writes beside the balls.
                smoothed = os.path.join(out, "smoothed_surface.ply")
                self.assertEqual(os.path.exists(smoothed), "--smooth" in options)
                checked = smoothed if os.path.exists(smoothed) else path
                check = run("check-balls", checked, os.path.join(out, "balls.csv"), *options, timeout=600)
                self.assertEqual(check.returncode, 0, check.stdout + check.stderr)

                for key in ("min_degrees", "percent_below_30_degrees", "percent_above_90_degrees"):
                    self.assertIn(key, quality["angles"])
                self.assertGreaterEqual(quality["triangle_quality"]["min"], q_floor)
                self.assertGreaterEqual(quality["angles"]["min_degrees"], angle_floor)
                self.assertLessEqual(quality["angles"]["percent_below_30_degrees"], below_30_ceiling)
                # At most ten rounds split skinny triangles (igl_bunny takes all ten).
                self.assertLessEqual(slivers["skinny_triangle_rounds"], 10 if "--smooth" in options else 0)
                self.assertLessEqual(quality["hausdorff"]["percent_of_bounding_box_diagonal"], hausdorff_ceiling)
                volume = quality["enclosed_volume"]
                self.assertGreater(volume["input"], 0)
                self.assertAlmostEqual(volume["percent_change"], 100 * (volume["output"] / volume["input"] - 1))
                self.assertLessEqual(abs(volume["percent_change"]), volume_ceiling)


class SkinnyTriangles(unittest.TestCase):
    """--smooth splits surface triangles with an angle below 30 degrees; --min-triangle-angle 0
    leaves them, and the default rules (sharp models) split none."""

    def surface(self, out, *options):
        r = run("mesh", os.path.join(MODELS, "sandia_bird.obj"), "-o", out, "--stop-after", "surface", "-q", *options)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            return json.load(f)

    def test_split_only_where_asked(self):
        with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
            kept = self.surface(a, "--smooth", "--min-triangle-angle", "0")
            split = self.surface(b, "--smooth")
        self.assertEqual(kept["options"]["min_triangle_angle_degrees"], 0)
        self.assertEqual(split["options"]["min_triangle_angle_degrees"], 30)
        self.assertEqual(kept["slivers"]["skinny_triangle_rounds"], 0)
        self.assertEqual(kept["refinement"]["skinny_triangle_shrinks"], 0)
        self.assertGreater(kept["surface"]["quality"]["angles"]["percent_below_30_degrees"], 0.2)

        slivers = split["slivers"]
        self.assertGreater(slivers["skinny_triangle_rounds"], 0)
        self.assertLessEqual(slivers["skinny_triangle_rounds"], 10)
        # Each round says what it shrank for: slivers while a pair is half-covered, near-twin seeds
        # or skinny triangles only once none is; the last shrinks nothing.
        rounds = slivers["per_iteration"]
        self.assertEqual(slivers["sliver_rounds"] + slivers["near_twin_rounds"] + slivers["skinny_triangle_rounds"],
                         slivers["iterations"])
        self.assertEqual(sum(it["shrunk_for"] == "skinny_triangles" for it in rounds), slivers["skinny_triangle_rounds"])
        self.assertEqual(sum(it["shrunk_for"] == "near_twins" for it in rounds), slivers["near_twin_rounds"])
        self.assertEqual(rounds[-1]["shrunk_for"], "nothing")
        for it in rounds[:-1]:
            if it["shrunk_for"] == "slivers":
                self.assertGreater(it["half_covered"], 0)
                continue
            self.assertIn(it["shrunk_for"], ("skinny_triangles", "near_twins"))
            self.assertEqual(it["half_covered"], 0)
            self.assertGreater(it[it["shrunk_for"]], 0)
            self.assertGreater(it["balls_shrunk"], 0)
        self.assertGreater(split["refinement"]["skinny_triangle_shrinks"], 0)
        self.assertEqual(slivers["half_covered_left"], 0)
        self.assertFalse(slivers["safe_mode"])
        counts = [it["skinny_triangles"] for it in slivers["per_iteration"] if it["skinny_triangles"]]
        self.assertLess(slivers["skinny_triangles_left"], counts[0])
        quality = split["surface"]["quality"]
        self.assertLessEqual(quality["angles"]["percent_below_30_degrees"], 0.1)
        self.assertGreater(quality["triangle_quality"]["min"],
                           kept["surface"]["quality"]["triangle_quality"]["min"])
        self.assertTrue(quality["topology"]["matches"])

    def test_the_bound_is_checked(self):
        with tempfile.TemporaryDirectory() as out:
            for bad in ("31", "-1"):
                r = run("mesh", os.path.join(MODELS, "sandia_bird.obj"), "-o", out, "--min-triangle-angle", bad, "-q")
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertIn("--min-triangle-angle must lie between 0 and 30 degrees", r.stderr)


class SmoothingTolerance(unittest.TestCase):
    """--smoothing-tolerance keeps a coarse surface near its input through smoothing: the faces
    about vertices Loop's rules would move farther are split at their midpoints first."""

    def surface(self, out, *options):
        r = run("mesh", os.path.join(MODELS, "directional_bimba.off"), "-o", out, "--stop-after", "surface", "-q",
                "--smooth", *options)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            return json.load(f)

    def test_loops_rules_alone_stray_farther(self):
        with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
            bounded = self.surface(a)
            plain = self.surface(b, "--smoothing-tolerance", "0")
        self.assertEqual(bounded["options"]["smoothing_tolerance"], 0.0075)
        self.assertEqual(plain["options"]["smoothing_tolerance"], 0)
        self.assertGreaterEqual(bounded["features"]["smoothing_bounding_rounds"], 1)
        self.assertEqual(plain["features"]["smoothing_bounding_rounds"], 0)
        self.assertEqual(bounded["features"]["smoothing_iterations"], plain["features"]["smoothing_iterations"])
        self.assertGreater(bounded["features"]["faces_after_smoothing"], plain["features"]["faces_after_smoothing"])
        distance = {name: r["surface"]["quality"]["hausdorff"]["percent_of_bounding_box_diagonal"]
                    for name, r in (("bounded", bounded), ("plain", plain))}
        self.assertLessEqual(distance["bounded"], 1.0, distance)
        self.assertGreater(distance["plain"], 1.2, distance)

    def test_the_tolerance_is_checked(self):
        with tempfile.TemporaryDirectory() as out:
            for bad, says in (("-0.01", "must be at least 0, got -0.01"), ("inf", "must be a finite number, got inf")):
                r = run("mesh", os.path.join(MODELS, "directional_bimba.off"), "-o", out, "--smooth",
                        "--smoothing-tolerance", bad, "-q")
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertIn("--smoothing-tolerance " + says, r.stderr)
                self.assertFalse(os.listdir(out))


if __name__ == "__main__":
    unittest.main(verbosity=2)
