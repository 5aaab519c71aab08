#!/usr/bin/env python3
"""Short edges and tiny faces over the shared CAD models and the smooth bunny (issue 38's figures).

Each run is `vorocrust mesh MODEL -o OUT --format seeds --seed 1 [--smooth] OPTIONS`; the figures
come from its report.json (`cells.quality`): per layer (the boundary layer: cells of seeds on
protecting spheres (surface, cap), of repair seeds and cells with a face on the surface; the interior: the others) the cells, the
shortest edge over its cell's size (the cube root of the cell's volume) and the share of edges
below 0.01, 0.05 and 0.1 of it, and the share of faces below 1e-4 of the size squared. An edge is
counted once for every cell it bounds. Prints one Markdown table.

Usage:
  python3 bench/short_edges.py [--build build] [--models ../shared/models] [--only NAME,...]
                               [-- EXTRA OPTION...]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

# The CAD models of the shared set, then the smooth scan the issue names.
MODELS = [
    ("sandia_OneBox.obj", []),
    ("sandia_bracket.obj", []),
    ("cgal_joint.off", []),
    ("cgal_fandisk.off", []),
    ("netgen_hinge.stl", []),
    ("ajc_rocker-arm.obj", []),
    ("sandia_non_manifold_box.obj", []),
    ("sandia_cube_test_01.obj", []),
    ("igl_bunny.off", ["--smooth"]),
]


def layer_cells(quality, layer):
    edges = quality["edge_length"][layer]
    faces = quality["face_area"][layer]
    if edges["count"] == 0:
        return ["0", "", "", "", "", ""]
    below = [t["percent"] for t in edges["thresholds"]]
    return [str(quality["layers"][layer + "_cells"]), "%.2g" % edges["min"]] + ["%.2f" % p for p in below] + [
        "%.2f" % faces["thresholds"][0]["percent"]
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--build", default=os.path.join(here, "..", "build"))
    parser.add_argument("--models", default=os.path.join(here, "..", "..", "shared", "models"))
    parser.add_argument("--only", default="")
    parser.add_argument("extra", nargs="*", help="options added to every run, after --")
    args = parser.parse_args()
    program = os.path.join(args.build, "cli", "vorocrust")
    only = set(filter(None, args.only.split(",")))
    header = ["model", "options", "seconds",
              "boundary-layer cells", "min", "% < 0.01", "% < 0.05", "% < 0.1", "% faces < 1e-4",
              "interior cells", "min", "% < 0.01", "% < 0.05", "% < 0.1", "% faces < 1e-4"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    failed = False
    for name, options in MODELS:
        if only and name not in only:
            continue
        options = options + args.extra
        with tempfile.TemporaryDirectory() as out:
            begin = time.monotonic()
            run = subprocess.run([program, "mesh", os.path.join(args.models, name), "-o", out, "--format", "seeds",
                                  "--seed", "1", "--quiet"] + options, capture_output=True, text=True)
            seconds = time.monotonic() - begin
            if run.returncode != 0:
                print("| %s | %s | failed: %s |" % (name, " ".join(options), run.stderr.strip()))
                failed = True
                continue
            with open(os.path.join(out, "report.json")) as f:
                quality = json.load(f)["cells"]["quality"]
        row = [name, " ".join(options) or "defaults", "%.1f" % seconds]
        row += layer_cells(quality, "boundary_layer") + layer_cells(quality, "interior")
        print("| " + " | ".join(row) + " |", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
