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

MODELS_TO_CHECK = ["cgal_joint.off", "cgal_fandisk.off", "igl_bunny.off", "sandia_bracket.obj",
                   "sandia_non_manifold_box.obj", "netgen_hinge.stl"]


class RefinementMeetsTheBallConditions(unittest.TestCase):
    def mesh_balls(self, path, out, *options):
        """Runs the refinement; returns report.json's features."""
        r = subprocess.run([BINARY, "mesh", path, "-o", out, "--stop-after", "balls", "-q", *options],
                           capture_output=True, text=True, timeout=1200)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            return json.load(f)["features"]

    def assert_conditions_hold(self, surface, out):
        check = subprocess.run([BINARY, "check-balls", surface, os.path.join(out, "balls.csv")],
                               capture_output=True, text=True, timeout=600)
        self.assertEqual(check.returncode, 0, check.stdout + check.stderr)
        self.assertIn("all ball conditions hold", check.stdout)

    def test_each_model(self):
        for name in MODELS_TO_CHECK:
            with self.subTest(model=name), tempfile.TemporaryDirectory() as out:
                path = os.path.join(MODELS, name)
                self.mesh_balls(path, out)
                self.assert_conditions_hold(path, out)

    def test_smoothing_keeps_the_conditions_on_the_smoothed_surface(self):
        # Smoothed, the balls cover the smoothed surface, and check-balls verifies against it.
        with tempfile.TemporaryDirectory() as out:
            features = self.mesh_balls(os.path.join(MODELS, "cgal_joint.off"), out, "--smoothing-iterations", "6")
            self.assertEqual(features["smoothing_iterations"], 6)
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


if __name__ == "__main__":
    unittest.main(verbosity=2)
