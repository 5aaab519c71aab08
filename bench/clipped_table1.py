#!/usr/bin/env python3
"""Yan et al.'s Table 1 against `vorocrust mesh --method clipped`: the clipped Voronoi diagram of
a model at the number of sites their table gives, timed as they time it (Delaunay triangulation
and surface RVD: here the "cells" phase, compute_cells and the clipping), next to their seconds.

Their models are not all shared; the shared models of the same kind stand in (ajc_rocker-arm is
their Rockerarm, igl_bunny their Bunny; the 30 000-site Bust runs on the bunny). The Poisson-disk
radius for a number of sites comes from one trial run: sites grow as the inverse cube of the radius.

Usage: python3 bench/clipped_table1.py [--build build] [--models ../shared/models] [--threads 2]

Prints a Markdown table for bench/RESULTS.md.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from current_table import machine  # noqa: E402

# (their model, their sites, their seconds, the shared model that stands in)
TABLE1 = [
    ("Bunny", 2000, 1.8, "igl_bunny.off"),
    ("Rockerarm", 3000, 12.1, "ajc_rocker-arm.obj"),
    ("Homer", 10000, 6.3, "igl_bunny.off"),
    ("Bust", 30000, 16.2, "igl_bunny.off"),
]


def run(binary, model, radius, threads, out):
    """The run's sites, its radius (unset: the default, a twentieth of the diagonal) and its
    seconds by phase."""
    size = ["--max-size", repr(radius)] if radius else []
    command = [binary, "mesh", model, "-o", out, "-q", "--method", "clipped", *size, "--threads", str(threads),
               "--format", "vtu"]
    subprocess.run(command, check=True, capture_output=True, text=True)
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    seconds = {t["phase"]: t["seconds"] for t in report["timings"]}
    radius = radius or report["input"]["bounding_box"]["diagonal"] / 20
    return report["cells"]["cells"], radius, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--build", default=os.path.join(here, "..", "build"))
    parser.add_argument("--models", default=os.path.join(here, "..", "..", "shared", "models"))
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    binary = os.path.join(args.build, "cli", "vorocrust")
    print(machine())
    print()
    print("| their model | sites | their seconds | shared model | our sites | radius | interior seeds (s) "
          "| Voronoi cells (s) | clipping (s) | faster |")
    print("|---|---:|---:|---|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        for name, sites, theirs, model in TABLE1:
            path = os.path.join(args.models, model)
            radius = None
            for _ in range(3):  # the default size, then twice scaled toward their number of sites
                cells, radius, seconds = run(binary, path, radius, args.threads, os.path.join(work, name))
                if abs(cells / sites - 1) < 0.05:
                    break
                radius *= (cells / sites) ** (1 / 3)
            ours = seconds["cells"] + seconds["clipping"]
            print("| %s | %d | %.1f | %s | %d | %.4g | %.3f | %.3f | %.3f | %.0fx |" % (
                name, sites, theirs, model, cells, radius, seconds["interior seeds"], seconds["cells"],
                seconds["clipping"], theirs / ours))


if __name__ == "__main__":
    main()
