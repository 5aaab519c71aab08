#!/usr/bin/env python3
"""Times the surface stage (paper 2.4) through the CLI and prints bench/RESULTS.md table rows.

Usage: python3 bench/surface_stage.py BUILD_DIR MODELS_DIR [--threads N] MODEL[:SHARP_ANGLE]...
Each model runs `vorocrust mesh MODEL --stop-after surface`; the per-phase seconds and counts
come from its report.json.
"""
import argparse
import json
import os
import subprocess
import tempfile


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("models")
    parser.add_argument("--threads", default="0")
    parser.add_argument("cases", nargs="+")
    args = parser.parse_args()
    print("| model | sharp angle | threads | balls | sliver rounds | half-covered at first | surface seeds "
          "| triangles | refinement | slivers | seeds and surface | quality | total |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for case in args.cases:
        name, _, angle = case.partition(":")
        angle = angle or "30"
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([os.path.join(args.build, "cli", "vorocrust"), "mesh", os.path.join(args.models, name),
                            "-o", out, "--stop-after", "surface", "-q", "--sharp-angle", angle,
                            "--threads", args.threads], check=True)
            with open(os.path.join(out, "report.json")) as f:
                r = json.load(f)
        # Progress phases: "refinement: ..." passes (the first run and the reruns after sliver
        # rounds), "slivers" (finding the seed pairs), "surface seeds", "surface quality".
        t = {}
        for x in r["timings"]:
            key = x["phase"].split(":")[0]
            t[key] = t.get(key, 0) + x["seconds"]
        s = r["slivers"]
        print(f"| {name} | {angle} | {args.threads} | {r['refinement']['balls']['total']} | {s['iterations']} "
              f"| {s['per_iteration'][0]['half_covered']} | {r['surface']['surface_seeds']} "
              f"| {r['surface']['triangles']} | {t.get('refinement', 0):.2f} | {t.get('slivers', 0):.2f} "
              f"| {t.get('surface seeds', 0):.2f} | {t.get('surface quality', 0):.2f} | {r['total_seconds']:.2f} |")


if __name__ == "__main__":
    main()
