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
  voronoi-surface MODEL
                       the Voronoi Mesh filter asked for no volume file runs the library to its
                       surface stage and gives the surface and seeds the vorocrust program gives for
                       the same seed: a surface layer with the same faces, topology, triangle quality
                       (face quality) and a colour per region pair, a seeds layer with the same seeds,
                       radii (vertex quality) and a colour per label, and the same files.
  voronoi-vtu MODEL    the Voronoi Mesh filter asked for mesh.vtu: VTK reads it, its polyhedra fill
                       the volume the output surface encloses.

Run by CTest as: python3 test_meshlab_plugin.py CASE [MODEL] --plugin ... (see parse_arguments).
"""
import argparse
import collections
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import unittest

from meshlab_runs import FAILED, make_prefix, option_rows, option_table, run_meshlabserver, script

SEED = 11
STRATUM_COLOURS = {"corner": (220, 40, 40), "crease": (235, 190, 40), "patch": (120, 150, 200)}


def parse_arguments():
    p = argparse.ArgumentParser()
    p.add_argument("case", choices=["balls", "invalid", "voronoi-surface", "voronoi-vtu", "voronoi-layers"])
    p.add_argument("model", nargs="?")
    p.add_argument("--smooth", action="store_true",
                   help="the filter's 'Smooth surface' with a sharp angle of 60, against the program's --smooth")
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


PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H",
             "int32": "i", "uint32": "I", "float32": "f", "float64": "d"}


def read_ply(path):
    """The elements of a binary little-endian PLY, as {element: [row dicts]}; a list property
    (a face's vertex_indices) is a tuple."""
    with open(path, "rb") as f:
        assert f.readline().strip() == b"ply", path
        elements = []  # (name, count, [(property, type, list count type or None)])
        while True:
            words = f.readline().decode("ascii").split()
            if words == ["end_header"]:
                break
            if words[0] == "format":
                assert words[1] == "binary_little_endian", words
            elif words[0] == "element":
                elements.append((words[1], int(words[2]), []))
            elif words[0] == "property" and words[1] == "list":
                elements[-1][2].append((words[4], PLY_TYPES[words[3]], PLY_TYPES[words[2]]))
            elif words[0] == "property":
                elements[-1][2].append((words[2], PLY_TYPES[words[1]], None))
        data = f.read()
    result, at = {}, 0
    for name, count, properties in elements:
        rows = []
        if all(length is None for _, _, length in properties):  # fixed rows: one unpack
            row = struct.Struct("<" + "".join(t for _, t, _ in properties))
            names = [n for n, _, _ in properties]
            rows = [dict(zip(names, values)) for values in row.iter_unpack(data[at:at + row.size * count])]
            at += row.size * count
        else:
            for _ in range(count):
                values = {}
                for prop, t, length in properties:
                    if length is None:
                        (values[prop],), at = struct.unpack_from("<" + t, data, at), at + struct.calcsize(t)
                    else:
                        (n,), at = struct.unpack_from("<" + length, data, at), at + struct.calcsize(length)
                        values[prop] = struct.unpack_from(f"<{n}{t}", data, at)
                        at += n * struct.calcsize(t)
                rows.append(values)
        result[name] = rows
    assert at == len(data), f"{path}: {len(data) - at} bytes after the last element"
    return result


def read_ply_vertices(path):
    return read_ply(path)["vertex"]


def read_csv_rows(path, header):
    with open(path) as f:
        got = f.readline().strip().split(",")
        assert got == header, got
        return [line.strip().split(",") for line in f if line.strip()]


def triangle_quality(a, b, c):
    """6 S / (sqrt(3) h p): the paper's triangle quality, 1 for the equilateral triangle."""
    ab, bc, ca = math.dist(a, b), math.dist(b, c), math.dist(c, a)
    u, v = [b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)]
    cross = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    area = 0.5 * math.hypot(*cross)
    longest = max(ab, bc, ca)
    return min(1.0, 6 * area / (math.sqrt(3) * longest * 0.5 * (ab + bc + ca))) if area > 0 else 0.0


def topology(faces):
    """Components of faces joined through shared edges, as a sorted list of (Euler characteristic
    V - E + F, closed) per component."""
    parent = list(range(len(faces)))

    def root(f):
        while parent[f] != f:
            parent[f] = parent[parent[f]]
            f = parent[f]
        return f

    edge_faces = {}
    for f, face in enumerate(faces):
        for k in range(3):
            edge_faces.setdefault(frozenset((face[k], face[(k + 1) % 3])), []).append(f)
    for around in edge_faces.values():
        for f in around[1:]:
            parent[root(f)] = root(around[0])
    components = {}
    for f, face in enumerate(faces):
        c = components.setdefault(root(f), {"v": set(), "e": set(), "f": 0, "closed": True})
        c["v"].update(face)
        c["f"] += 1
    for edge, around in edge_faces.items():
        c = components[root(around[0])]
        c["e"].add(edge)
        c["closed"] &= len(around) > 1
    return sorted((len(c["v"]) - len(c["e"]) + c["f"], c["closed"]) for c in components.values())


def enclosed_volume(vertices, faces):
    """The signed volume a closed, outward oriented triangle surface encloses (divergence theorem)."""
    total = 0.0
    for a, b, c in faces:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = vertices[a], vertices[b], vertices[c]
        total += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return total / 6


def region_volumes(ply):
    """The volume of each region a surface.ply's faces bound: a face's normal points from its
    back region to its front one, so it adds its signed volume to the back's and takes it from
    the front's (the outside's, label 0, is left out)."""
    vertices = [(v["x"], v["y"], v["z"]) for v in ply["vertex"]]
    volumes = collections.defaultdict(float)
    for f in ply["face"]:
        v = enclosed_volume(vertices, [f["vertex_indices"]])
        volumes[f["back_region"]] += v
        volumes[f["front_region"]] -= v
    volumes.pop(0, None)
    return dict(volumes)


def read_balls_csv(path):
    return read_csv_rows(path, ["x", "y", "z", "radius", "stratum_type", "stratum_index"])


def read_seeds_csv(path):
    return read_csv_rows(path, ["x", "y", "z", "label", "radius", "kind"])


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


# The library's option table, as the filter's parameters are made from it.
OPTIONS = option_table(ARGS.cli)
# The Protecting Balls filter offers the options the balls depend on.
BALL_OPTIONS = ("lipschitz", "smooth", "sharp_angle", "max_size", "sizing", "smoothing_iterations",
                "smoothing_tolerance", "box", "self_intersections", "seed", "threads")


def balls_script(path, seed=SEED, lipschitz=0.25, resolve=True, smooth=False):
    values = dict(seed=seed, lipschitz=lipschitz, smooth=smooth, self_intersections="resolve" if resolve else "refuse")
    return script(path, "VoroCrust Protecting Balls", option_rows(OPTIONS, BALL_OPTIONS, values))


def voronoi_script(path, folder, vtu, openfoam, seed=SEED, cvt_iterations=20, all_visible=False, resolve=True,
                   max_aspect_ratio=5.0):
    formats = ["seeds", "obj", "ply"] + (["vtu"] if vtu else []) + (["openfoam", "tough", "pflotran"] if openfoam else [])
    values = dict(seed=seed, cvt_iterations=cvt_iterations, max_aspect_ratio=max_aspect_ratio, formats=formats,
                  self_intersections="resolve" if resolve else "refuse")
    rows = option_rows(OPTIONS, [o["name"] for o in OPTIONS], values)
    rows.append(f'  <Param type="RichString" name="outputFolder" value="{folder}"/>')
    rows.append(f'  <Param type="RichBool" name="allVisibleLayers" value="{str(all_visible).lower()}"/>')
    return script(path, "VoroCrust Voronoi Mesh", rows)


class MeshLabCase(unittest.TestCase):
    def setUp(self):
        self.work = os.path.abspath(ARGS.work)
        shutil.rmtree(self.work, ignore_errors=True)
        os.makedirs(os.path.join(self.work, "home"))
        self.server, self.plugins = make_prefix(self.work, ARGS.meshlabserver, ARGS.meshlab_lib_dir, ARGS.plugin)

    def meshlabserver(self, *arguments):
        """Runs meshlabserver under xvfb-run; returns (exit status, everything it printed)."""
        r = run_meshlabserver(self.server, self.work, *arguments)
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

    def model_for_meshlab(self):
        """The case's model as MeshLab opens it: OBJ models as an OFF copy."""
        model = os.path.join(ARGS.models, ARGS.model)
        if model.endswith(".obj"):
            off = os.path.join(self.work, os.path.splitext(ARGS.model)[0] + ".off")
            off_from_obj(model, off)
            model = off
        return model

    def cli_on_what_meshlab_loaded(self, model, stop_after):
        """Runs `vorocrust mesh --stop-after STOP_AFTER` on what MeshLab loaded from MODEL, in its
        single precision, so both start from the same coordinates (read in double precision,
        bunny's decimals give other balls); returns the CLI's output folder."""
        loaded = os.path.join(self.work, "loaded.ply")
        status, output = self.meshlabserver("-i", model, "-o", loaded)
        self.assertEqual(status, 0, output[-3000:])
        cli_out = os.path.join(self.work, "cli")
        r = subprocess.run([ARGS.cli, "mesh", loaded, "-o", cli_out, "--stop-after", stop_after, "--seed", str(SEED),
                            "--quiet", *(["--smooth"] if ARGS.smooth else [])],
                           capture_output=True, text=True, timeout=1800)
        self.assertEqual(r.returncode, 0, r.stderr)
        return cli_out

    def assert_points_close(self, got, expected, what):
        """MeshLab's single-precision points against the library's double-precision ones."""
        self.assertEqual(len(got), len(expected), what)
        for k, (v, p) in enumerate(zip(got, expected)):
            scale = max(map(abs, p))
            for axis, value in zip("xyz", p):
                self.assertAlmostEqual(v[axis], value, delta=1e-6 * scale, msg=f"{what} {k} {axis}")

    def test_case(self):
        getattr(self, "case_" + ARGS.case.replace("-", "_"))()

    def case_balls(self):
        model = self.model_for_meshlab()
        cli_out = self.cli_on_what_meshlab_loaded(model, "balls")
        expected = read_balls_csv(os.path.join(cli_out, "balls.csv"))

        out = os.path.join(self.work, "balls.ply")
        status, output = self.meshlabserver("-i", model, "-o", out, "-m", "vq", "vc", "-s",
                                            balls_script(os.path.join(self.work, "balls.mlx"), smooth=ARGS.smooth))
        self.assertEqual(status, 0, output[-3000:])
        self.assertIn(f"VoroCrust: {len(expected)} balls", output)
        got = read_ply_vertices(out)
        self.assert_points_close(got, [tuple(map(float, row[:3])) for row in expected], "ball")
        for k, (v, row) in enumerate(zip(got, expected)):
            radius = float(row[3])
            self.assertAlmostEqual(v["quality"], radius, delta=1e-6 * radius, msg=f"ball {k} radius")
            self.assertEqual((v["red"], v["green"], v["blue"]), STRATUM_COLOURS[row[4]], f"ball {k} type")
        types = {t: sum(row[4] == t for row in expected) for t in STRATUM_COLOURS}
        if ARGS.smooth:  # a closed smooth surface has no corner and no crease
            self.assertEqual((types["corner"], types["crease"]), (0, 0))
        print(f"{ARGS.model}: {len(got)} balls from MeshLab and from the vorocrust program with seed {SEED} "
              f"({types['corner']} corner, {types['crease']} crease, {types['patch']} patch); radii and centres agree")

    def case_voronoi_surface(self):
        model = self.model_for_meshlab()
        cli_out = self.cli_on_what_meshlab_loaded(model, "surface")
        cli_ply = read_ply(os.path.join(cli_out, "surface.ply"))
        cli_vertices = [(v["x"], v["y"], v["z"]) for v in cli_ply["vertex"]]
        cli_faces = [f["vertex_indices"] for f in cli_ply["face"]]
        cli_seeds = read_seeds_csv(os.path.join(cli_out, "seeds.csv"))
        with open(os.path.join(cli_out, "report.json")) as f:
            cli_surface = json.load(f)["surface"]

        # Layers: 0 the model, 1 the surface, 2 the seeds. No volume file is asked for, so the
        # filter runs the library to its surface stage only.
        folder = os.path.join(self.work, "voronoi")
        surface_out, seeds_out = os.path.join(self.work, "surface_layer.ply"), os.path.join(self.work, "seeds_layer.ply")
        mlx = voronoi_script(os.path.join(self.work, "voronoi.mlx"), folder, vtu=False, openfoam=False)
        status, output = self.meshlabserver("-i", model, "-o", surface_out, "-l", "1", "-m", "fc", "fq",
                                            "-o", seeds_out, "-l", "2", "-m", "vc", "vq", "-s", mlx)
        self.assertEqual(status, 0, output[-3000:])
        self.assertIn("up to the surface (no volume file asked for)", output)
        self.assertIn(f"VoroCrust: {len(cli_seeds)} surface seeds, a surface of {len(cli_faces)} triangles", output)
        stem = os.path.splitext(os.path.basename(model))[0]
        self.assertIn(f'VoroCrust: layers "{stem} VoroCrust surface" and "{stem} VoroCrust seeds"', output)

        # The surface layer: the CLI's surface, in single precision.
        layer = read_ply(surface_out)
        faces = [f["vertex_indices"] for f in layer["face"]]
        self.assertEqual(len(faces), len(cli_faces))
        self.assertEqual(len(faces), cli_surface["triangles"])
        expected_topology = sorted(zip(cli_surface["quality"]["topology"]["output"]["euler_characteristic"],
                                       cli_surface["quality"]["topology"]["output"]["closed"]))
        self.assertEqual(topology(faces), expected_topology)
        self.assertEqual(faces, cli_faces)
        self.assert_points_close(layer["vertex"], cli_vertices, "surface vertex")
        # Face quality: Q of the CLI's (double-precision) triangles, and the report's summary of it.
        qualities = [f["quality"] for f in layer["face"]]
        for k, (q, face) in enumerate(zip(qualities, cli_faces)):
            self.assertAlmostEqual(q, triangle_quality(*(cli_vertices[v] for v in face)), delta=1e-6, msg=f"face {k}")
        figures = cli_surface["quality"]["triangle_quality"]
        self.assertAlmostEqual(min(qualities), figures["min"], delta=1e-6)
        self.assertAlmostEqual(sum(qualities) / len(qualities), figures["mean"], delta=1e-6)
        # Face colours: one per region pair, as the CLI's surface.ply labels the faces.
        colour_of_pair = {}
        for k, (f, cli_face) in enumerate(zip(layer["face"], cli_ply["face"])):
            pair = (cli_face["back_region"], cli_face["front_region"])
            colour = colour_of_pair.setdefault(pair, (f["red"], f["green"], f["blue"]))
            self.assertEqual((f["red"], f["green"], f["blue"]), colour, f"face {k} of region pair {pair}")
        self.assertEqual(len(set(colour_of_pair.values())), len(colour_of_pair))

        # The seeds layer: the CLI's seeds, radius as quality, a colour per label.
        seeds = read_ply_vertices(seeds_out)
        self.assertEqual(len(seeds), len(cli_seeds))
        self.assert_points_close(seeds, [tuple(map(float, row[:3])) for row in cli_seeds], "seed")
        colour_of_label = {}
        for k, (v, row) in enumerate(zip(seeds, cli_seeds)):
            radius = float(row[4])
            self.assertAlmostEqual(v["quality"], radius, delta=1e-6 * radius, msg=f"seed {k} radius")
            colour = colour_of_label.setdefault(row[3], (v["red"], v["green"], v["blue"]))
            self.assertEqual((v["red"], v["green"], v["blue"]), colour, f"seed {k} of label {row[3]}")
        self.assertEqual(len(set(colour_of_label.values())), len(colour_of_label))

        # The files: equal input and seed, equal files, byte for byte; no volume file.
        self.assertEqual(sorted(os.listdir(folder)), ["report.json", "seeds.csv", "surface.obj", "surface.ply"])
        for name in ["seeds.csv", "surface.obj", "surface.ply"]:
            with open(os.path.join(folder, name), "rb") as a, open(os.path.join(cli_out, name), "rb") as b:
                self.assertTrue(a.read() == b.read(), f"{name} differs from the vorocrust program's")
        print(f"{ARGS.model}: a surface of {len(faces)} triangles (components and Euler characteristics "
              f"{expected_topology}), {len(seeds)} seeds, region pairs {sorted(colour_of_pair)}, Q min "
              f"{min(qualities):.4f}, as the vorocrust program's with seed {SEED}")

    def case_voronoi_vtu(self):
        model = self.model_for_meshlab()
        folder = os.path.join(self.work, "voronoi")
        mlx = voronoi_script(os.path.join(self.work, "voronoi.mlx"), folder, vtu=True, openfoam=False)
        status, output = self.meshlabserver("-i", model, "-o", os.path.join(self.work, "surface_layer.ply"),
                                            "-l", "1", "-s", mlx)
        self.assertEqual(status, 0, output[-3000:])
        self.check_vtu(folder)

    def case_voronoi_layers(self):
        """All visible layers as materials: two unit cubes side by side, one layer each, meshed
        together; their common face is the interface between their materials."""
        cubes = []
        for k in range(2):
            path = os.path.join(self.work, "cube%d.off" % k)
            corners = [(k + (i & 1), (i >> 1) & 1, (i >> 2) & 1) for i in range(8)]
            quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
            with open(path, "w") as f:
                f.write("OFF\n8 12 0\n" + "".join("%d %d %d\n" % c for c in corners))
                for a, b, c, d in quads:
                    f.write("3 %d %d %d\n3 %d %d %d\n" % (a, b, c, a, c, d))
            cubes.append(path)
        folder = os.path.join(self.work, "voronoi")
        mlx = voronoi_script(os.path.join(self.work, "voronoi.mlx"), folder, vtu=True, openfoam=True, all_visible=True)
        status, output = self.meshlabserver("-i", *cubes, "-s", mlx)
        self.assertEqual(status, 0, output[-3000:])
        volumes = self.check_vtu(folder)
        self.assertEqual(len(volumes), 2, volumes)
        for material, volume in volumes.items():
            self.assertAlmostEqual(volume, 1.0, delta=1e-9, msg=f"material {material}")
        surface = read_ply(os.path.join(folder, "surface.ply"))
        between = [f for f in surface["face"] if f["back_region"] > 0 and f["front_region"] > 0]
        self.assertGreaterEqual(len(between), 2)
        for name in ("MESH", "pflotran/mesh.uge", "case/constant/polyMesh/faceZones"):
            self.assertTrue(os.path.exists(os.path.join(folder, name)), name)
        print(f"two cube layers: materials of volume {sorted(volumes.values())}, {len(between)} interface triangles")

    def check_vtu(self, folder):
        """VTK reads mesh.vtu; its cells' volumes per material are the regions' volumes inside the
        output surface, and VTK's volume inside its outer faces their sum. Returns the volumes."""
        import vtk  # VTK's Python modules, from python3-paraview; imported here so the cases without cells need no VTK
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(folder, "mesh.vtu"))
        reader.Update()
        grid = reader.GetOutput()
        seeds = read_seeds_csv(os.path.join(folder, "seeds.csv"))
        material = [k for k, row in enumerate(seeds) if int(row[3]) > 0]
        self.assertEqual(grid.GetNumberOfCells(), len(material))
        self.assertEqual({grid.GetCellType(c) for c in range(grid.GetNumberOfCells())}, {vtk.VTK_POLYHEDRON})
        # VTK's volume inside the grid's outer faces, and the cells' own volumes per material.
        sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        from vtk_volume import vtk_boundary_volume
        measured = vtk_boundary_volume(grid)
        own = grid.GetCellData().GetArray("volume")
        # Each cell's aspect ratio (circumradius over inradius) beside it: at least 1, finite.
        ratios = grid.GetCellData().GetArray("aspect_ratio")
        self.assertEqual(ratios.GetNumberOfTuples(), grid.GetNumberOfCells())
        self.assertTrue(all(1 <= ratios.GetValue(c) < float("inf") for c in range(ratios.GetNumberOfTuples())))
        materials = grid.GetCellData().GetArray("material")
        by_material = collections.defaultdict(float)
        for c in range(own.GetNumberOfTuples()):
            by_material[materials.GetValue(c)] += own.GetValue(c)
        regions = region_volumes(read_ply(os.path.join(folder, "surface.ply")))
        self.assertEqual(sorted(by_material), sorted(regions))
        enclosed = sum(regions.values())
        self.assertGreater(enclosed, 0)
        self.assertAlmostEqual(measured, enclosed, delta=1e-9 * enclosed)
        for material, volume in by_material.items():
            self.assertAlmostEqual(volume, regions[material], delta=1e-9 * enclosed, msg=f"material {material}")
        print(f"{ARGS.model}: VTK reads {grid.GetNumberOfCells()} polyhedra of total volume {measured:.9g}; the "
              f"output surface encloses {enclosed:.9g}, per material {dict(sorted(by_material.items()))}")
        return dict(by_material)

    def case_invalid(self):
        mlx = balls_script(os.path.join(self.work, "balls.mlx"))
        data = ARGS.data
        with self.subTest(input="a pierced cube, its self-intersections refused"):
            self.assert_fails_with(os.path.join(data, "invalid/cube_pierced.off"),
                                   balls_script(os.path.join(self.work, "refuse.mlx"), resolve=False),
                                   "VoroCrust: invalid geometry:", "pairs of intersecting faces")
        with self.subTest(input="a pierced cube, its self-intersections resolved"):
            status, output = self.meshlabserver("-i", os.path.join(data, "invalid/cube_pierced.off"), "-o",
                                                os.path.join(self.work, "pierced.ply"), "-s", mlx)
            self.assertEqual(status, 0, output[-3000:])
            self.assertIn("warning: 4 pairs of intersecting faces", output)
            self.assertIn("self-intersections resolved", output)
        cases = [
            ("invalid/cube_zero_area.off", ["VoroCrust: invalid geometry:", "faces with zero area"]),
            ("bad/all_nan.off", ["VoroCrust: invalid geometry:", "NaN or infinite coordinate"]),
            ("bad/infinity.off", ["VoroCrust: invalid geometry:", "vertex 1 ", "NaN or infinite coordinate"]),
            ("bad/no_faces.off", ["VoroCrust: invalid geometry:", "has no faces"]),
        ]
        for name, phrases in cases:
            with self.subTest(input=name):
                self.assert_fails_with(os.path.join(data, name), mlx, *phrases)
        cube = os.path.join(data, "invalid/cube.off")
        with self.subTest(input="a Lipschitz constant out of range"):
            self.assert_fails_with(cube, balls_script(os.path.join(self.work, "bad_l.mlx"), lipschitz=1.5),
                                   "VoroCrust: usage error:", '"Lipschitz constant L" must lie strictly between 0 and 1')
        # The Voronoi Mesh filter: the same validation, its own parameters and its output folder.
        folder = os.path.join(self.work, "voronoi")
        with self.subTest(input="the Voronoi Mesh filter on a pierced cube, its self-intersections refused"):
            self.assert_fails_with(os.path.join(data, "invalid/cube_pierced.off"),
                                   voronoi_script(os.path.join(self.work, "v.mlx"), folder, False, False, resolve=False),
                                   "VoroCrust: invalid geometry:", "pairs of intersecting faces")
        with self.subTest(input="negative CVT iterations"):
            self.assert_fails_with(cube, voronoi_script(os.path.join(self.work, "v_cvt.mlx"), folder, False, False,
                                                        cvt_iterations=-1),
                                   "VoroCrust: usage error:", '"CVT iterations" must lie between 0 and 10000, got -1')
        with self.subTest(input="a largest aspect ratio below 3"):
            self.assert_fails_with(cube, voronoi_script(os.path.join(self.work, "v_ar.mlx"), folder, False, False,
                                                        max_aspect_ratio=2.0),
                                   "VoroCrust: usage error:",
                                   '"Largest cell aspect ratio" must be at least 3, or 0 (no splits), got 2')
        with self.subTest(input="an output folder that cannot be made"):
            blocker = os.path.join(self.work, "a_file")
            open(blocker, "w").close()
            self.assert_fails_with(cube, voronoi_script(os.path.join(self.work, "v_out.mlx"),
                                                        os.path.join(blocker, "out"), False, False),
                                   "VoroCrust: output error:", "cannot create the output folder")
        self.assertFalse(os.path.exists(folder))  # refused before anything was made


if __name__ == "__main__":
    unittest.main(verbosity=2)
