#!/usr/bin/env python3
"""vorocrust.mesh2d() against `vorocrust mesh2d`: the same domain, options and seed give
byte-identical files; a domain given as arrays meshes as the same domain read from a file; the
arrays describe the cells; bad domains and options raise with the library's message.

Run by CTest as: PYTHONPATH=BUILD/python /usr/bin/python3 test_mesh2d.py VOROCRUST_BINARY SAMPLES_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import vorocrust

BINARY, SAMPLES = sys.argv[1:3]
del sys.argv[1:3]

SECTION = os.path.join(SAMPLES, "2d", "cross_section.poly")


def shoelace(points):
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


class Mesh2d(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="vorocrust-py2d-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def test_the_module_writes_the_programs_bytes(self):
        program = os.path.join(self.dir, "program")
        module = os.path.join(self.dir, "module")
        r = subprocess.run([BINARY, "mesh2d", SECTION, "-o", program, "--max-size", "0.3", "--seed", "3",
                            "--format", "vtu,svg,seeds,tough"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        result = vorocrust.mesh2d(SECTION, max_size=0.3, seed=3, output_dir=module, formats=["vtu", "svg", "seeds", "tough"])
        for name in ("mesh.vtu", "mesh.svg", "seeds.csv", "MESH"):
            with open(os.path.join(program, name), "rb") as a, open(os.path.join(module, name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)
        self.assertEqual(len(result.cells), len(result.regions))
        self.assertEqual(result.region_names[1:], ["region1", "region2", "region3"])

    def test_arrays_describe_the_cells(self):
        result = vorocrust.mesh2d(SECTION, max_size=0.3)
        areas = [shoelace(result.points[cell]) for cell in result.cells]
        np.testing.assert_allclose(areas, result.areas, rtol=1e-10)
        for label, expected in ((1, 24.0), (2, 13.5), (3, 22.5)):
            self.assertAlmostEqual(float(result.areas[result.regions == label].sum()), expected, delta=1e-9)
        self.assertTrue(result.quality["convex"])
        self.assertLess(result.quality["max_link_angle"], 1e-6)
        # Each cell holds its seed.
        seeds = result.seeds[result.cell_seeds]
        self.assertTrue(np.all(result.seed_labels[result.cell_seeds] == result.regions))
        self.assertEqual(seeds.shape, (len(result.cells), 2))
        self.assertFalse(result.points.flags.writeable)

    def test_a_domain_as_arrays_is_the_domain_of_the_file(self):
        # A square with a square hole and a breakline from the hole toward the outer side.
        domain = {
            "points": [[0, 0], [3, 0], [3, 3], [0, 3], [1, 1], [2, 1], [2, 2], [1, 2], [2, 1.5], [2.6, 1.5]],
            "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [8, 9]],
            "holes": [[1.5, 1.5]],
            "regions": [(0.5, 0.5, 4)],
        }
        result = vorocrust.mesh2d(domain, max_size=0.1)
        self.assertAlmostEqual(result.quality["area_by_region"][4], 8.0, delta=1e-9)
        self.assertEqual(set(result.regions.tolist()), {4})
        path = os.path.join(self.dir, "same.poly")
        with open(path, "w") as f:
            pts, segs = domain["points"], domain["segments"]
            f.write("%d 2 0 0\n" % len(pts) + "".join("%d %r %r\n" % (i, p[0], p[1]) for i, p in enumerate(pts)))
            f.write("%d 0\n" % len(segs) + "".join("%d %d %d\n" % (i, s[0], s[1]) for i, s in enumerate(segs)))
            f.write("1\n0 1.5 1.5\n1\n0 0.5 0.5 4 -1\n")
        again = vorocrust.mesh2d(path, max_size=0.1)
        np.testing.assert_array_equal(result.points, again.points)

    def test_bad_domains_and_options_raise(self):
        with self.assertRaisesRegex(vorocrust.UsageError, "unknown option 'smooth'"):
            vorocrust.mesh2d(SECTION, smooth=True)
        with self.assertRaisesRegex(vorocrust.UsageError, "lipschitz"):
            vorocrust.mesh2d(SECTION, lipschitz=2.0)
        with self.assertRaisesRegex(vorocrust.UsageError, "names point 7"):
            vorocrust.mesh2d({"points": [[0, 0], [1, 0], [0, 1]], "segments": [[0, 1], [1, 7]]})
        with self.assertRaisesRegex(vorocrust.InvalidGeometryError, "gap|closed region"):
            vorocrust.mesh2d({"points": [[0, 0], [1, 0], [1, 1], [0, 1]], "segments": [[0, 1], [1, 2], [2, 3]]})


if __name__ == "__main__":
    unittest.main()
