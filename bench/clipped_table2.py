#!/usr/bin/env python3
"""Yan et al.'s Table 2 against `vorocrust mesh --method clipped`: the shape of the tetrahedra dual
to a clipped CVT of a sphere (report.json's dual_tets), with and without their sliver
perturbation, next to their figures.

The sphere is an icosahedron subdivided four times onto the unit sphere (5 120 triangles), written
into a temporary folder: no shared model is a sphere.

Usage: python3 bench/clipped_table2.py [--build build] [--threads 2] [--max-size 0.08]

Prints a Markdown table for bench/RESULTS.md.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from current_table import machine  # noqa: E402

# Their Table 2, "ours" row: mean Q1, min Q1, mean Q4, min Q4.
YAN = (56.37, 24.23, 0.932, 0.560)


def icosphere(path, subdivisions=4):
    """Writes the unit icosphere as an OFF file."""
    t = (1 + math.sqrt(5)) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
              (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    points = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = [(x + y) / 2 for x, y in zip(points[a], points[b])]
                n = math.sqrt(sum(x * x for x in m))
                points.append(tuple(x / n for x in m))
                middle[key] = len(points) - 1
            return middle[key]

        finer = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in points:
            f.write("%.17g %.17g %.17g\n" % p)
        for face in faces:
            f.write("3 %d %d %d\n" % face)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--build", default=os.path.join(here, "..", "build"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--max-size", default="0.08")
    args = parser.parse_args()
    binary = os.path.join(args.build, "cli", "vorocrust")
    print(machine())
    print()
    print("| options (`--method clipped --max-size %s`, and) | cells | tets | mean Q1 | min Q1 | mean Q4 | min Q4 "
          "| below 24° | tets' volume / sphere's | seconds: CVT | perturbation |" % args.max_size)
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    runs = [
        ("`--interior cvt`", ["--interior", "cvt"]),
        ("`--interior cvt --sliver-angle 24`", ["--interior", "cvt", "--sliver-angle", "24"]),
        ("`--interior cvt --cvt-iterations 60 --sliver-angle 24`",
         ["--interior", "cvt", "--cvt-iterations", "60", "--sliver-angle", "24"]),
    ]
    with tempfile.TemporaryDirectory() as work:
        sphere = os.path.join(work, "sphere.off")
        icosphere(sphere)
        for label, options in runs:
            out = os.path.join(work, "out")
            subprocess.run([binary, "mesh", sphere, "-o", out, "-q", "--method", "clipped", "--max-size", args.max_size,
                            "--threads", str(args.threads), "--format", "tets", *options], check=True)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            t = report["dual_tets"]
            seconds = {p["phase"]: p["seconds"] for p in report["timings"]}
            perturbation = report["clipping"].get("sliver_perturbation")
            below = count_below(os.path.join(out, "tets.vtu"), 24)
            print("| %s | %d | %d | %.2f° | %.2f° | %.3f | %.3f | %d | %.3f | %.1f | %s |" % (
                label, report["cells"]["cells"], t["tets"], t["mean_min_dihedral"], t["min_min_dihedral"], t["mean_q4"],
                t["min_q4"], below, t["volume"] / report["regions"][1]["volume"], seconds.get("cvt", 0),
                "%.1f (%d rounds)" % (seconds["sliver perturbation"], perturbation["rounds"]) if perturbation else ""))
    print("| Yan et al.'s Table 2, sphere | | | %.2f° | %.2f° | %.3f | %.3f | | | | |" % YAN)


def count_below(tets_vtu, degrees):
    """Tetrahedra of tets.vtu with a dihedral angle below `degrees`."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(tets_vtu)
    reader.Update()
    return int((vtk_to_numpy(reader.GetOutput().GetCellData().GetArray("min_dihedral")) < degrees).sum())


if __name__ == "__main__":
    main()
