#!/usr/bin/env python3
"""The refinement on the models of the refinement issue, verified by the independent checker.

For each model: `vorocrust mesh MODEL --stop-after balls` with default parameters, then
`vorocrust check-balls MODEL balls.csv`, which shares no code with the refinement, must report
no violation of C1-C4 or of the protection of corners and creases; every corner of the input
carries a corner ball centred exactly on it.

Run by CTest as: python3 test_refinement_models.py VOROCRUST_BINARY MODELS_DIR
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]

# igl_camelhead: a decimated scan whose two inverted faces, once unfolded, leave creases that meet
# at a few degrees at corners; its refinement stopped (exit 4) until a crease piece left uncovered
# while a corner ball shrank was sampled again whole.
MODELS_TO_CHECK = ["cgal_joint.off", "cgal_fandisk.off", "igl_bunny.off", "sandia_bracket.obj",
                   "sandia_non_manifold_box.obj", "netgen_hinge.stl", "igl_camelhead.off"]


class RefinementMeetsTheBallConditions(unittest.TestCase):
    def mesh_balls(self, path, out, *options, report_section="features"):
        """Runs the refinement; returns a section of report.json (its features unless told)."""
        r = subprocess.run([BINARY, "mesh", path, "-o", out, "--stop-after", "balls", "-q", *options],
                           capture_output=True, text=True, timeout=1200)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
        # No piece of the surface was given up bare at the deepest subdivision.
        self.assertEqual(report["refinement"]["bare_at_deepest"],
                         {"pieces": 0, "crease_length": 0, "patch_area": 0})
        return report[report_section] if report_section else report

    def assert_conditions_hold(self, surface, out, *options):
        check = subprocess.run([BINARY, "check-balls", *options, surface, os.path.join(out, "balls.csv")],
                               capture_output=True, text=True, timeout=600)
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)
        self.assertIn("all ball conditions hold", check.stdout)

    def test_each_model(self):
        for name in MODELS_TO_CHECK:
            with self.subTest(model=name), tempfile.TemporaryDirectory() as out:
                path = os.path.join(MODELS, name)
                self.mesh_balls(path, out)
                self.assert_conditions_hold(path, out)

    def test_a_finely_smoothed_scan_refines_within_a_pool_near_its_face_count(self):
        # igl_camelhead smoothed twice has 149 883 faces, each a piece awaiting darts. Darts thrown
        # only until 100 missed in a row left most pieces without one, and the pool grew about
        # fourfold a level to 9.4 million pieces, refused as a refinement that cannot converge
        # (exit 4). A dart a piece kept it at 0.74 million.
        with tempfile.TemporaryDirectory() as out:
            report = self.mesh_balls(os.path.join(MODELS, "igl_camelhead.off"), out, "--smooth",
                                     "--smoothing-iterations", "2", "--format", "balls", report_section=None)
            faces = report["features"]["faces_after_smoothing"]
            self.assertGreater(faces, 22704 * 4)
            self.assertLessEqual(report["refinement"]["largest_pool"], 10 * faces)
            self.assert_conditions_hold(os.path.join(out, "smoothed_surface.ply"), out, "--smooth")

    def test_smoothing_keeps_the_conditions_on_the_smoothed_surface(self):
        # Smoothed, the balls cover the smoothed surface, and check-balls verifies against it.
        with tempfile.TemporaryDirectory() as out:
            features = self.mesh_balls(os.path.join(MODELS, "cgal_joint.off"), out, "--smoothing-iterations", "6")
            self.assertEqual(features["smoothing_iterations"], 6)
            self.assertEqual(features["smoothing_rounds_crossing"], 0)
            self.assertGreater(features["faces_after_smoothing"], 446)
            self.assert_conditions_hold(os.path.join(out, "smoothed_surface.ply"), out)

    def test_smoothing_that_would_make_a_feature_is_refused(self):
        # On fandisk every round of smoothing makes a cone point next to a corner: none is kept,
        # no smoothed surface is written (not even a stale one), and the balls check against the input.
        with tempfile.TemporaryDirectory() as out:
            path = os.path.join(MODELS, "cgal_fandisk.off")
            open(os.path.join(out, "smoothed_surface.ply"), "w").close()  # a stale file from an earlier run
            features = self.mesh_balls(path, out, "--smoothing-iterations", "6")
            self.assertEqual(features["smoothing_iterations"], 0)
            self.assertEqual(features["smoothing_rounds_refused"], 1)
            self.assertFalse(os.path.exists(os.path.join(out, "smoothed_surface.ply")))
            self.assert_conditions_hold(path, out)

    def test_smoothing_that_would_carry_a_shell_through_another_is_refused(self):
        # An icosahedron of circumradius 1.2 around a finer sphere of radius 0.3 centred 0.6 off
        # its centre: the sphere reaches 0.9 out along +x, where the icosahedron's nearest edge
        # passes 1.02 out. Loop's rules round the icosahedron in towards 0.85 (its vertices'
        # limit); one round brings that edge to about 0.92, the second through the sphere. The
        # refinement gave up on a surface crossing itself, or ran on for minutes. The most rounds
        # that cross nothing (one) are kept, and the balls cover that smoothed surface. (Loop's
        # rules alone: within --smoothing-tolerance the icosahedron is split before it is
        # smoothed, stays near its faces and crosses nothing.)
        for tolerance, crossing, rounds in (("0", 2, 1), ("0.0075", 0, None)):
            with self.subTest(tolerance=tolerance), tempfile.TemporaryDirectory() as out:
                path = os.path.join(out, "nested.off")
                write_off(path, [icosphere(0, 1.2), icosphere(3, 0.3, (0.6, 0, 0))])
                features = self.mesh_balls(path, out, "--smooth", "--smoothing-tolerance", tolerance)
                self.assertEqual(features["smoothing_rounds_crossing"], crossing)
                if rounds is not None:
                    self.assertEqual(features["smoothing_iterations"], rounds)
                else:
                    self.assertGreater(features["smoothing_bounding_rounds"], 0)
                    self.assertGreater(features["smoothing_iterations"], 1)
                smoothed = os.path.join(out, "smoothed_surface.ply")
                info = subprocess.run([BINARY, "info", smoothed], capture_output=True, text=True, timeout=600)
                self.assertEqual(info.returncode, 0, info.stdout + info.stderr)  # it would name crossing faces
                self.assert_conditions_hold(smoothed, out, "--smooth")

    def test_smoothing_that_would_carry_a_shell_wholly_across_another_is_refused(self):
        # The icosahedron of circumradius 1.2 around a concentric sphere of radius 0.9: one round
        # brings some of it inside the sphere, two bring it wholly inside (towards 0.85) with no
        # faces crossing. Kept, the regions' labels were on the wrong sides, and the run stopped
        # at the cells ("cell of seed ... is not bounded by seeds"). By Loop's rules alone no
        # round is kept; within --smoothing-tolerance both are, the icosahedron split first and
        # kept off the sphere. Either way the whole run ends with cells filling both regions.
        for tolerance, rounds, crossing, volume in (("0", 0, 1, 0.01), ("0.0075", 2, 0, 0.05)):
            with self.subTest(tolerance=tolerance), tempfile.TemporaryDirectory() as out:
                path = os.path.join(out, "concentric.off")
                write_off(path, [icosphere(0, 1.2), icosphere(3, 0.9)])
                r = subprocess.run([BINARY, "mesh", path, "-o", out, "--smooth", "--smoothing-iterations", "2",
                                    "--smoothing-tolerance", tolerance, "--format", "vtu", "-q"],
                                   capture_output=True, text=True, timeout=600)
                self.assertEqual(r.returncode, 0, r.stderr)
                with open(os.path.join(out, "report.json")) as f:
                    report = json.load(f)
                self.assertEqual(report["features"]["smoothing_iterations"], rounds)
                self.assertEqual(report["features"]["smoothing_rounds_crossing"], crossing)
                self.assertEqual(len(report["regions"]), 3)
                icosahedron = sum(region["volume"] for region in report["regions"])
                # Smoothed, the icosahedron's corners are rounded off (3.4 %).
                self.assertAlmostEqual(report["cells"]["volume"] / icosahedron, 1, delta=volume)


    def test_smoothing_leaves_the_box_around_a_smooth_sheet(self):
        # gmsh_terrain is an open sheet, so it is meshed in a box. Smoothed with it as if the box
        # were part of the smooth surface, the cube rounded into a blob through the terrain and
        # every round was refused; the box keeps its edges, and all six rounds smooth the sheet.
        with tempfile.TemporaryDirectory() as out:
            features = self.mesh_balls(os.path.join(MODELS, "gmsh_terrain.stl"), out, "--smooth")
            self.assertEqual(features["smoothing_iterations"], 6)
            self.assertEqual(features["smoothing_rounds_crossing"], 0)
            self.assertEqual(features["corners"], 8 + 4)  # the box's, and the four where the terrain's rim turns
            self.assert_conditions_hold(os.path.join(out, "smoothed_surface.ply"), out, "--smooth")

    def test_balls_check_against_the_surface_the_run_started_from(self):
        # Two cubes overlapping by half are cut along their intersection curves, and an open
        # square gets the default box: check-balls starts from the same surfaces. Against the
        # cubes as they cross, the balls break the conditions where the cut made creases.
        with tempfile.TemporaryDirectory() as out:
            cubes = os.path.join(out, "cubes.off")
            write_off(cubes, [cube((0, 0, 0), 1), cube((0.5, 0.4, 0.3), 1)])
            self.mesh_balls(cubes, out)
            self.assert_conditions_hold(cubes, out)
            keep = subprocess.run([BINARY, "check-balls", "--self-intersections", "keep", cubes,
                                   os.path.join(out, "balls.csv")], capture_output=True, text=True, timeout=600)
            self.assertEqual(keep.returncode, 8, keep.stdout + keep.stderr)
        with tempfile.TemporaryDirectory() as out:
            sheet = os.path.join(out, "sheet.off")
            write_off(sheet, [([(0, 0, 0), (1, 0, 0), (1, 1, 0.2), (0, 1, 0.2)], [(0, 1, 2), (0, 2, 3)])])
            self.mesh_balls(sheet, out)
            self.assert_conditions_hold(sheet, out)


def cube(corner, side):
    """Vertices and outward triangles of an axis-aligned cube."""
    points = [tuple(c + side * ((i >> k) & 1) for k, c in enumerate(corner)) for i in range(8)]
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
    return points, [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]


def icosphere(level, radius, centre=(0, 0, 0)):
    """Vertices and triangles of an icosahedron split `level` times, on a sphere of `radius`."""
    t = (1 + 5 ** 0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        middle = {}
        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(points)
                points.append(tuple((p + q) / 2 for p, q in zip(points[a], points[b])))
            return middle[key]
        faces = [f for a, b, c in faces
                 for f in ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)), (c, mid(c, a), mid(b, c)),
                           (mid(a, b), mid(b, c), mid(c, a)))]
    scaled = [tuple(c + radius * x / sum(y * y for y in p) ** 0.5 for x, c in zip(p, centre)) for p in points]
    return scaled, faces


def write_off(path, shells):
    points = [p for shell_points, _ in shells for p in shell_points]
    faces, offset = [], 0
    for shell_points, shell_faces in shells:
        faces += [tuple(offset + i for i in f) for f in shell_faces]
        offset += len(shell_points)
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in points)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)

if __name__ == "__main__":
    unittest.main(verbosity=2)
