#!/usr/bin/env python3
"""The MeshLab plugin, run as a user runs it: meshlabserver under xvfb-run with a filter script.

meshlabserver runs from a private prefix made afresh in the work folder: a copy of the installed
meshlabserver in PREFIX/bin (a copy, not a link: MeshLab finds its plugins from the real path of
its binary), with PREFIX/LIBDIR/meshlab holding links to the installed libmeshlab-common.so and
stock plugins, and to the plugin under test. Nothing outside the work folder is written.

Cases:
  balls MODEL          the Protecting Balls filter on MODEL gives the balls the vorocrust program
                       gives for the same seed: the same count, radii (vertex quality), centres and
                       stratum types (vertex colours).
  invalid              inputs the library refuses make the filter fail with the library's message
                       and meshlabserver exit with its failure status, never crash.
  voronoi-not-yet      the Voronoi Mesh filter fails cleanly with the library's "not yet" message.

Run by CTest as: python3 test_meshlab_plugin.py CASE [MODEL] --plugin ... (see parse_arguments).
"""
import argparse
import os
import shutil
import struct
import subprocess
import sys
import unittest

FAILED = 255  # meshlabserver's exit(-1), after a filter in its script fails
SEED = 11
STRATUM_COLOURS = {"corner": (220, 40, 40), "crease": (235, 190, 40), "patch": (120, 150, 200)}


def parse_arguments():
    p = argparse.ArgumentParser()
    p.add_argument("case", choices=["balls", "invalid", "voronoi-not-yet"])
    p.add_argument("model", nargs="?")
    p.add_argument("--plugin", required=True, help="libfilter_vorocrust.so under test")
    p.add_argument("--meshlabserver", required=True, help="the installed meshlabserver")
    p.add_argument("--meshlab-lib-dir", required=True, help="the folder of libmeshlab-common.so")
    p.add_argument("--cli", required=True, help="the vorocrust program")
    p.add_argument("--models", required=True)
    p.add_argument("--data", required=True, help="tests/data")
    p.add_argument("--work", required=True, help="a folder of the test's own, emptied first")
    return p.parse_args()


ARGS = parse_arguments()
del sys.argv[1:]


def make_prefix(work):
    """The private prefix; returns its meshlabserver and its plugins folder."""
    server = os.path.realpath(ARGS.meshlabserver)
    root = os.path.dirname(os.path.dirname(server))  # /usr for /usr/bin/meshlabserver
    lib_dir = os.path.realpath(ARGS.meshlab_lib_dir)
    prefix = os.path.join(work, "prefix")
    prefix_lib = os.path.join(prefix, os.path.relpath(lib_dir, root))  # PREFIX/lib/<triplet>/meshlab
    os.makedirs(os.path.join(prefix, "bin"))
    os.makedirs(os.path.join(prefix_lib, "plugins"))
    copy = os.path.join(prefix, "bin", os.path.basename(server))
    shutil.copy2(server, copy)
    os.symlink(os.path.join(lib_dir, "libmeshlab-common.so"), os.path.join(prefix_lib, "libmeshlab-common.so"))
    ours = os.path.basename(ARGS.plugin)
    stock = os.path.join(lib_dir, "plugins")
    for name in sorted(os.listdir(stock)):
        if name.endswith(".so") and name != ours:  # an installed copy of ours must not shadow the one under test
            os.symlink(os.path.join(stock, name), os.path.join(prefix_lib, "plugins", name))
    os.symlink(os.path.realpath(ARGS.plugin), os.path.join(prefix_lib, "plugins", ours))
    return copy, os.path.join(prefix_lib, "plugins")


def read_ply_vertices(path):
    """The vertex rows of a binary little-endian PLY, as dicts of property values."""
    types = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d"}
    with open(path, "rb") as f:
        assert f.readline().strip() == b"ply", path
        count, properties, element = 0, [], None
        while True:
            words = f.readline().decode("ascii").split()
            if words == ["end_header"]:
                break
            if words[0] == "format":
                assert words[1] == "binary_little_endian", words
            elif words[0] == "element":
                element = words[1]
                if element == "vertex":
                    count = int(words[2])
            elif words[0] == "property" and element == "vertex":
                properties.append((words[2], types[words[1]]))
        row = struct.Struct("<" + "".join(t for _, t in properties))
        data = f.read(row.size * count)
    names = [n for n, _ in properties]
    return [dict(zip(names, values)) for values in row.iter_unpack(data)]


def read_balls_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
        assert header == ["x", "y", "z", "radius", "stratum_type", "stratum_index"], header
        return [line.strip().split(",") for line in f if line.strip()]


def off_from_obj(obj, off):
    """An OFF copy of a triangle OBJ, coordinates as written: Debian's MeshLab 2020.09 aborts on
    every OBJ it imports (an assertion in its OBJ reader), so MeshLab gets the OFF copy."""
    vertices, faces = [], []
    with open(obj) as f:
        for line in f:
            words = line.split()
            if words and words[0] == "v":
                vertices.append(words[1:4])
            elif words and words[0] == "f":
                faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
    with open(off, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        f.writelines(" ".join(v) + "\n" for v in vertices)
        f.writelines(f"{len(face)} " + " ".join(map(str, face)) + "\n" for face in faces)


def script(path, filter_name, **parameters):
    """A MeshLab filter script (.mlx) applying one filter. meshlabserver 2020.09 aborts on a
    script that leaves out a parameter of the filter, so the callers give them all."""
    rows = []
    for name, value in parameters.items():
        if isinstance(value, bool):
            rows.append(f'  <Param type="RichBool" name="{name}" value="{str(value).lower()}"/>')
        elif isinstance(value, int):
            rows.append(f'  <Param type="RichInt" name="{name}" value="{value}"/>')
        elif isinstance(value, float):
            rows.append(f'  <Param type="RichFloat" name="{name}" value="{value!r}"/>')
        elif isinstance(value, tuple):  # (kind, value): enum or absolute-or-percentage
            kind, v = value
            if kind == "enum":
                rows.append(f'  <Param type="RichEnum" name="{name}" value="{v}" enum_cardinality="3"'
                            ' enum_val0="random" enum_val1="lattice" enum_val2="cvt"/>')
            else:
                rows.append(f'  <Param type="RichAbsPerc" name="{name}" value="{v!r}" min="0" max="1"/>')
        else:
            rows.append(f'  <Param type="RichString" name="{name}" value="{value}"/>')
    with open(path, "w") as f:
        f.write("<!DOCTYPE FilterScript>\n<FilterScript>\n"
                f' <filter name="{filter_name}">\n' + "\n".join(rows) + "\n </filter>\n</FilterScript>\n")
    return path


def balls_script(path, seed=SEED, lipschitz=0.25):
    return script(path, "VoroCrust Protecting Balls", lipschitz=lipschitz, sharpAngle=30.0,
                  maxSize=("abs", 0.0), seed=seed)


class MeshLabCase(unittest.TestCase):
    def setUp(self):
        self.work = os.path.abspath(ARGS.work)
        shutil.rmtree(self.work, ignore_errors=True)
        os.makedirs(os.path.join(self.work, "home"))
        self.server, self.plugins = make_prefix(self.work)

    def meshlabserver(self, *arguments):
        """Runs meshlabserver under xvfb-run; returns (exit status, everything it printed)."""
        env = dict(os.environ, HOME=os.path.join(self.work, "home"))  # no settings of the user's
        for attempt in range(3):
            r = subprocess.run(["xvfb-run", "-a", self.server, *arguments], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, errors="replace", env=env,
                               cwd=self.work, timeout=1800)
            if "Xvfb failed to start" not in r.stdout:  # two servers may race for a display
                break
        # xvfb-run reports a command killed by signal N as 128+N; the shell's own codes lie between.
        self.assertFalse(r.returncode < 0 or 128 < r.returncode < FAILED,
                         f"meshlabserver crashed (status {r.returncode}):\n{r.stdout[-3000:]}")
        self.assertIn(f"Current Plugins Dir is: {self.plugins}", r.stdout)  # the prefix's, not the system's
        return r.returncode, r.stdout

    def assert_fails_with(self, model, mlx, *phrases):
        status, output = self.meshlabserver("-i", model, "-o", os.path.join(self.work, "out.ply"), "-s", mlx)
        self.assertEqual(status, FAILED, output[-3000:])
        self.assertIn("Problem with filter: VoroCrust", output)
        for phrase in phrases:
            self.assertIn(phrase, output)
        self.assertFalse(os.path.exists(os.path.join(self.work, "out.ply")))
        return output

    def test_case(self):
        getattr(self, "case_" + ARGS.case.replace("-", "_"))()

    def case_balls(self):
        model = os.path.join(ARGS.models, ARGS.model)
        if model.endswith(".obj"):
            off = os.path.join(self.work, os.path.splitext(ARGS.model)[0] + ".off")
            off_from_obj(model, off)
            model = off
        # What MeshLab loaded, in its single precision: the vorocrust program meshes that, so both
        # start from the same coordinates (read in double precision, bunny's decimals give other balls).
        loaded = os.path.join(self.work, "loaded.ply")
        status, output = self.meshlabserver("-i", model, "-o", loaded)
        self.assertEqual(status, 0, output[-3000:])
        cli_out = os.path.join(self.work, "cli")
        r = subprocess.run([ARGS.cli, "mesh", loaded, "-o", cli_out, "--stop-after", "balls", "--seed", str(SEED),
                            "--quiet"], capture_output=True, text=True, timeout=1800)
        self.assertEqual(r.returncode, 0, r.stderr)
        expected = read_balls_csv(os.path.join(cli_out, "balls.csv"))

        out = os.path.join(self.work, "balls.ply")
        status, output = self.meshlabserver("-i", model, "-o", out, "-m", "vq", "vc", "-s",
                                            balls_script(os.path.join(self.work, "balls.mlx")))
        self.assertEqual(status, 0, output[-3000:])
        self.assertIn(f"VoroCrust: {len(expected)} balls", output)
        got = read_ply_vertices(out)
        self.assertEqual(len(got), len(expected))
        for k, (v, row) in enumerate(zip(got, expected)):
            x, y, z, radius = map(float, row[:4])
            scale = max(radius, abs(x), abs(y), abs(z))
            for axis, value in zip("xyz", (x, y, z)):
                self.assertAlmostEqual(v[axis], value, delta=1e-6 * scale, msg=f"ball {k} {axis}")
            self.assertAlmostEqual(v["quality"], radius, delta=1e-6 * radius, msg=f"ball {k} radius")
            self.assertEqual((v["red"], v["green"], v["blue"]), STRATUM_COLOURS[row[4]], f"ball {k} type")
        types = {t: sum(row[4] == t for row in expected) for t in STRATUM_COLOURS}
        print(f"{ARGS.model}: {len(got)} balls from MeshLab and from the vorocrust program with seed {SEED} "
              f"({types['corner']} corner, {types['crease']} crease, {types['patch']} patch); radii and centres agree")

    def case_invalid(self):
        mlx = balls_script(os.path.join(self.work, "balls.mlx"))
        data = ARGS.data
        cases = [
            ("invalid/cube_pierced.off", ["VoroCrust: invalid geometry:", "pairs of intersecting faces"]),
            ("invalid/cube_zero_area.off", ["VoroCrust: invalid geometry:", "faces with zero area"]),
            ("bad/all_nan.off", ["VoroCrust: invalid geometry:", "NaN or infinite coordinate"]),
            ("bad/infinity.off", ["VoroCrust: invalid geometry:", "vertex 1 ", "NaN or infinite coordinate"]),
            ("bad/no_faces.off", ["VoroCrust: invalid geometry:", "has no faces"]),
        ]
        for name, phrases in cases:
            with self.subTest(input=name):
                self.assert_fails_with(os.path.join(data, name), mlx, *phrases)
        with self.subTest(input="a Lipschitz constant out of range"):
            self.assert_fails_with(os.path.join(data, "invalid/cube.off"),
                                   balls_script(os.path.join(self.work, "bad_l.mlx"), lipschitz=1.5),
                                   "VoroCrust: usage error:", "lipschitz must lie strictly between 0 and 1")

    # CHANGE WHEN THE CELLS LAND: the full pipeline stops with NotImplemented today. Once seeds and
    # cells exist, this case checks the surface and seeds layers and the written mesh.vtu instead.
    def case_voronoi_not_yet(self):
        folder = os.path.join(self.work, "voronoi")
        mlx = script(os.path.join(self.work, "voronoi.mlx"), "VoroCrust Voronoi Mesh", lipschitz=0.25,
                     sharpAngle=30.0, maxSize=("abs", 0.0), seed=SEED, interior=("enum", 0), outputFolder=folder,
                     writeVtu=True, writeOpenFoam=True, writeSeeds=True, writeSurface=True, allVisibleLayers=False)
        output = self.assert_fails_with(os.path.join(ARGS.models, "cgal_joint.off"), mlx,
                                        "VoroCrust: not yet implemented:", "Voronoi cells")
        self.assertIn("interior seeds: random", output)


if __name__ == "__main__":
    unittest.main(verbosity=2)
