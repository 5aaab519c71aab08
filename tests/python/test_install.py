#!/usr/bin/env python3
"""`cmake --install` of the Python module into a private prefix: the installed package imports
from there with no build tree on any path, loads the installed libvorocrust, and meshes.

Run by CTest as: python3 test_install.py CMAKE BUILD_DIR WORK_DIR PYTHON_INSTALL_DIR LIBDIR MODEL
"""
import os
import shutil
import subprocess
import sys
import unittest

CMAKE, BUILD, WORK, PYTHON_DIR, LIBDIR, MODEL = sys.argv[1:7]
del sys.argv[1:7]

PROBE = r"""
import sys, vorocrust
result = vorocrust.mesh(sys.argv[1], stop_after="surface", seed=3)
with open("/proc/self/maps") as f:
    libraries = sorted({line.split()[-1] for line in f if "libvorocrust.so" in line})
print(vorocrust.__file__)
print(libraries[0] if len(libraries) == 1 else libraries)
print(result.surface.num_faces, result.surface_quality["topology"]["matches"])
"""


class Install(unittest.TestCase):
    def test_the_installed_module_uses_the_installed_library(self):
        shutil.rmtree(WORK, ignore_errors=True)
        prefix = os.path.join(WORK, "prefix")
        r = subprocess.run([CMAKE, "--install", BUILD, "--prefix", prefix], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        site = PYTHON_DIR if os.path.isabs(PYTHON_DIR) else os.path.join(prefix, PYTHON_DIR)
        package = os.path.join(site, "vorocrust")
        self.assertEqual(sorted(n for n in os.listdir(package) if not n.startswith("__pycache__")),
                         ["__init__.py", "_vorocrust.cpython-%d%d-x86_64-linux-gnu.so" % sys.version_info[:2]])
        env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": site, "HOME": WORK}
        r = subprocess.run([sys.executable, "-c", PROBE, MODEL], capture_output=True, text=True, env=env, cwd=WORK)
        self.assertEqual(r.returncode, 0, r.stderr)
        module_file, library, surface = r.stdout.splitlines()
        self.assertEqual(module_file, os.path.join(package, "__init__.py"))
        self.assertTrue(library.startswith(os.path.join(prefix, LIBDIR, "libvorocrust.so")), library)
        faces, matches = surface.split()
        self.assertGreater(int(faces), 12)
        self.assertEqual(matches, "True")
        shutil.rmtree(WORK, ignore_errors=True)


if __name__ == "__main__":
    unittest.main(verbosity=2)
