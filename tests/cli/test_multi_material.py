"""Multi-material and non-manifold domains (paper section 3, "Non-manifold models", Figures 15-16),
meshed with default options as a user meshes them and read back by the real readers:

- each region's cells fill the region: their volumes sum to the region's volume in report.json
  within what the surface's Hausdorff error allows, and to the region's volume found here
  independently (a voxel flood fill of the input, tests/voxel_regions.py) within its grid error;
- the cells' boundary and interface faces are the output surface's triangles, one for one;
- the interfaces are closed: every region's boundary in the output, the faces with that region
  on exactly one side, uses each of its edges an even number of times, so no interface has a hole;
- checkMesh reads the case with its zones: one cell zone per material, one face zone per pair of
  materials that touch, one boundary patch per region pair on the boundary;
- the TOUGH MESH and the PFLOTRAN grid pass readers written from the formats' specifications
  (tests/simulator_files.py) and hold the same cells, volumes and connections as mesh.vtu.
"""
import collections
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from simulator_files import read_ex, read_tough_mesh, read_uge  # noqa: E402
from volume_mesh import all_polyhedron_faces, cell_array, check_mesh, read_vtu, vtk_boundary_volume  # noqa: E402
from voxel_regions import VoxelRegions, read_triangles  # noqa: E402


BINARY, MODELS = sys.argv[1:3]
del sys.argv[1:3]

# Model, its regions of space other than the outside.
CASES = [
    ("sandia_non_manifold_box.obj", 2),
    ("sandia_cube_test_01.obj", 4),
    ("sandia_cube_test_02.obj", 3),
    ("sandia_cube_test_04.obj", 5),
    ("cgal_polyhedral_complex_patches.obj", 3),
    ("cgal_cubes_edge_contact.off", 2),
    ("openmeeg_HeadNNb3.obj", 5),  # nested shells
    ("openmeeg_HeadNNc3.obj", 4),  # non-manifold: north and south halves inside the skull
    # Non-manifold and self-intersecting: the south half pokes through the skull (30 face pairs),
    # which the mesher resolves; the voxel fill of the input as it is sees the thin pockets between
    # the crossing faces as regions of their own.
    ("openmeeg_HeadNNa1.obj", 4),
]
# The voxel flood fill's volumes are off by about the surface area times a grid step over 4.
VOXEL_TOLERANCE = 0.025


def run(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=900)


class MultiMaterial(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="vorocrust-materials-")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def check_model(self, model, expected_regions):
        out = os.path.join(self.dir, model)
        r = run("mesh", os.path.join(MODELS, model), "-o", out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
        regions = report["regions"]
        materials = [g for g in regions if g["label"] > 0]
        self.assertEqual(len(materials), expected_regions, regions)
        self.assertEqual(report["slivers"]["half_covered_left"], 0)

        grid = read_vtu(os.path.join(out, "mesh.vtu"))
        material = cell_array(grid, "material")
        volume = cell_array(grid, "volume")
        by_material = collections.defaultdict(float)
        for m, v in zip(material, volume):
            by_material[m] += v
        self.assertEqual(sorted(by_material), [g["label"] for g in materials])
        total = sum(volume)
        self.assertAlmostEqual(vtk_boundary_volume(grid), total, delta=1e-9 * total)

        # Against the regions the library found: within the Hausdorff distance times the area.
        hausdorff = report["surface"]["quality"]["hausdorff"]["distance"]
        area = report["input"]["area"]
        for g in materials:
            self.assertAlmostEqual(by_material[g["label"]], g["volume"], delta=2 * hausdorff * area + 1e-9 * g["volume"],
                                   msg="%s %s" % (model, g["name"]))

        # Against regions found independently: each material's largest cell lies in a voxel
        # region of its own, whose volume it matches.
        vertices, triangles = read_triangles(os.path.join(MODELS, model))
        voxels = VoxelRegions(vertices, triangles, n=160)
        if report["self_intersections"]["faces_cut"] == 0:
            self.assertEqual(len(voxels.bounded_regions()), expected_regions)
        largest = {}
        for c, (m, v) in enumerate(zip(material, volume)):
            if v > largest.get(m, (-1, 0))[1]:
                largest[m] = (c, v)
        matched = {}
        for m, (c, _) in largest.items():
            points = grid.GetCell(c).GetPoints()
            centre = [sum(points.GetPoint(i)[k] for i in range(points.GetNumberOfPoints())) / points.GetNumberOfPoints()
                      for k in range(3)]
            matched[m] = voxels.region_at(centre)
        self.assertEqual(len(set(matched.values())), len(matched), "two materials in one voxel region")
        # Voxel regions no material matched are the pockets where faces cross: a sliver of the whole.
        pockets = sum(voxels.volume(r) for r in voxels.bounded_regions() if r not in matched.values())
        self.assertLess(pockets, 1e-3 * total)
        for m, region in matched.items():
            self.assertNotEqual(region, voxels.outside)
            self.assertAlmostEqual(by_material[m], voxels.volume(region), delta=VOXEL_TOLERANCE * voxels.volume(region),
                                   msg="%s material %d" % (model, m))

        # Closed interfaces: each region's boundary uses every edge an even number of times.
        sides = collections.defaultdict(list)  # face (sorted point ids) -> materials of its cells
        faces_of = {}
        for c, faces in enumerate(all_polyhedron_faces(grid)):
            for face in faces:
                key = tuple(sorted(face))
                sides[key].append(material[c])
                faces_of[key] = face
        edge_uses = collections.defaultdict(int)  # (region, edge) -> faces of that region's boundary
        interface_pairs = collections.Counter()
        for key, mats in sides.items():
            pair = (mats[0], mats[1] if len(mats) == 2 else 0)
            if pair[0] == pair[1]:
                continue
            interface_pairs[tuple(sorted(pair))] += 1
            face = faces_of[key]
            for k in range(len(face)):
                edge = tuple(sorted((face[k], face[(k + 1) % len(face)])))
                for region in pair:
                    edge_uses[(region, edge)] += 1
        odd = [key for key, n in edge_uses.items() if n % 2]
        self.assertEqual(odd[:5], [], "%s: %d region-boundary edges used an odd number of times" % (model, len(odd)))

        # checkMesh: the zones and patches, and every check it makes.
        r, _ = check_mesh(os.path.join(out, "case"))
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        for check in ("Boundary openness", "Cell volumes OK", "Upper triangular ordering OK", "Cell to face addressing OK",
                      "Point usage OK", "Face vertices OK", "Boundary definition OK", "Non-orthogonality check OK",
                      "Face pyramids OK"):
            self.assertIn(check, r.stdout, r.stdout[-2500:])
        for g in materials:
            self.assertRegex(r.stdout, r"\n\s+%s\s+\d+\s+\d+" % re.escape(g["name"]), "cell zone of " + g["name"])
        internal_pairs = [p for p in interface_pairs if p[0] > 0]
        self.assertIn("faceZones", os.listdir(os.path.join(out, "case", "constant", "polyMesh")))
        with open(os.path.join(out, "case", "constant", "polyMesh", "faceZones")) as f:
            zones = re.findall(r"\n(\w+)\n\{\n    type faceZone;\n    faceLabels List<label>\n(\d+)", f.read())
        names = {g["label"]: g["name"] for g in regions}
        self.assertEqual(sorted((z, int(n)) for z, n in zones),
                         sorted(("%s_to_%s" % (names[a], names[b]), interface_pairs[(a, b)]) for a, b in internal_pairs))
        skew = re.search(r"(\d+) highly skew faces", r.stdout)
        self.assertEqual([line for line in r.stdout.splitlines() if "***" in line], [])
        # Mesh OK: the skew repair leaves no highly skew face, even in the thin wedges where
        # HeadNNa1's south half crosses its skull at about 20 degrees.
        self.assertIn("\nMesh OK.", r.stdout, r.stdout[-2500:])
        self.assertEqual(report["cells"]["quality"]["skewness"]["highly_skew_faces"], int(skew.group(1)) if skew else 0)

        # The simulators' files hold the same mesh.
        elements, connections = read_tough_mesh(os.path.join(out, "MESH"))
        self.assertEqual(len(elements), grid.GetNumberOfCells())
        self.assertEqual(len({e["name"] for e in elements}), len(elements))
        self.assertTrue(all(e["volume"] > 0 for e in elements))
        self.assertAlmostEqual(sum(e["volume"] for e in elements), total, delta=1e-4 * total)
        self.assertEqual(len({e["material"] for e in elements}), expected_regions)
        names_known = {e["name"] for e in elements}
        self.assertTrue(all(set(c["names"]) <= names_known for c in connections))
        self.assertTrue(all(c["area"] > 0 and c["d1"] > 0 and c["d1"] == c["d2"] and -1 <= c["betax"] <= 1
                            for c in connections))
        cells, links = read_uge(os.path.join(out, "pflotran", "mesh.uge"))
        self.assertEqual(len(cells), grid.GetNumberOfCells())
        self.assertAlmostEqual(sum(v for _, v in cells.values()), total, delta=1e-9 * total)
        self.assertEqual(len(links), len(connections))
        self.assertTrue(all(a in cells and b in cells and a != b and area > 0 for a, b, _, area in links))
        listed = []
        for g in materials:
            with open(os.path.join(out, "pflotran", g["name"] + ".txt")) as f:
                ids = [int(line) for line in f if line.strip()]
            self.assertTrue(all(material[i - 1] == g["label"] for i in ids))
            listed += ids
        self.assertEqual(sorted(listed), list(range(1, len(cells) + 1)))
        boundary = 0
        for name in os.listdir(os.path.join(out, "pflotran")):
            if name.endswith(".ex"):
                records = read_ex(os.path.join(out, "pflotran", name))
                self.assertTrue(all(i in cells and area > 0 for i, _, area in records))
                boundary += len(records)
        self.assertEqual(boundary, sum(n for p, n in interface_pairs.items() if p[0] == 0))

        # The cells conform to the output surface face for face: one boundary face per triangle
        # with a material on one side only, one interface face per triangle between two materials.
        by_sides = report["surface"]["triangles_by_sides"]
        self.assertEqual(report["cells"]["boundary_faces"], by_sides["boundary"])
        self.assertEqual(report["cells"]["interface_faces"], by_sides["interface"])
        self.assertEqual(sum(n for p, n in interface_pairs.items() if p[0] > 0), by_sides["interface"])

        print("\n  %s: %s; voxel volumes %s; checkMesh %s" % (
            model, ", ".join("%s %.6g" % (g["name"], by_material[g["label"]]) for g in materials),
            ", ".join("%.6g" % voxels.volume(matched[g["label"]]) for g in materials),
            "Mesh OK" if "\nMesh OK." in r.stdout else "%s skew faces" % (skew.group(1) if skew else "?")))


def make_test(model, regions):
    return lambda self: self.check_model(model, regions)


for _model, _regions in CASES:
    setattr(MultiMaterial, "test_" + re.sub(r"\W", "_", _model.rsplit(".", 1)[0]), make_test(_model, _regions))


if __name__ == "__main__":
    unittest.main(verbosity=2)
