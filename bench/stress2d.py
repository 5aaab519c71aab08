#!/usr/bin/env python3
"""The 2D mesher over random domains: a convex outer polygon (5 to 12 sides), up to six random
segments inside it (crossing each other at any angle, ending anywhere inside), every fourth
domain an island triangle, at a random --max-size (or none) and --interior mode, one trial a
seed. Each run must end in exit 0 with a report whose cells are convex and orthogonal to their
seed links, or in a documented refusal (exit 3 or 4 with a message); an internal error, a crash
or a run past the time limit fails the harness.

Usage: python3 bench/stress2d.py [--build build | --binary PATH] [--trials 300] [--first 0] [--timeout 60]
                                 [--keep DIR]
Prints one line per outcome with its count and the slowest trials; exit 1 when any run failed.
"""
import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time


def domain(trial):
    """The trial's points, segments and options."""
    rng = random.Random(trial)
    n = rng.randint(5, 12)
    points = []
    for i in range(n):
        angle = 2 * math.pi * (i + rng.uniform(-0.2, 0.2)) / n
        radius = rng.uniform(0.8, 1.0)
        points.append((radius * math.cos(angle), radius * math.sin(angle)))
    segments = [(i, (i + 1) % n) for i in range(n)]
    for _ in range(rng.randint(0, 6)):
        k = len(points)
        points += [(rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)) for _ in range(2)]
        segments.append((k, k + 1))
    if trial % 4 == 1:
        k = len(points)
        cx, cy = rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)
        points += [(cx, cy + 0.1), (cx - 0.1, cy - 0.05), (cx + 0.1, cy - 0.05)]
        segments += [(k, k + 1), (k + 1, k + 2), (k + 2, k)]
    size = rng.choice([None, 0.05, 0.1, 0.3])
    options = ["--interior", rng.choice(["random", "lattice", "cvt"]), "--seed", str(trial)]
    return points, segments, options + ([] if size is None else ["--max-size", str(size)])


def write_poly(path, points, segments):
    with open(path, "w") as f:
        f.write("%d 2 0 0\n" % len(points) + "".join("%d %r %r\n" % (i, x, y) for i, (x, y) in enumerate(points)))
        f.write("%d 0\n" % len(segments) + "".join("%d %d %d\n" % (i, a, b) for i, (a, b) in enumerate(segments)))
        f.write("0\n")


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--binary", help="the vorocrust program (default: BUILD/cli/vorocrust)")
    parser.add_argument("--trials", type=int, default=300)
    parser.add_argument("--first", type=int, default=0)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--keep", help="a folder to keep the domains and outputs in")
    args = parser.parse_args()
    binary = args.binary or os.path.join(args.build, "cli", "vorocrust")
    work = args.keep or tempfile.mkdtemp(prefix="vorocrust-stress2d-")
    os.makedirs(work, exist_ok=True)
    outcomes, failed = {}, False
    begin = time.time()
    for trial in range(args.first, args.first + args.trials):
        points, segments, options = domain(trial)
        poly = os.path.join(work, "t%d.poly" % trial)
        out = os.path.join(work, "o%d" % trial)
        write_poly(poly, points, segments)
        command = [binary, "mesh2d", poly, "-o", out, "-q", "--format", "seeds", *options]
        start = time.time()
        try:
            r = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
            code, message = r.returncode, r.stderr.strip()
        except subprocess.TimeoutExpired:
            code, message = "timeout", ""
        seconds = time.time() - start
        if code == 0:
            with open(os.path.join(out, "report.json")) as f:
                cells = json.load(f)["cells"]
            good = cells["convex"] and cells["quality"]["link_angle"]["max"] < 1e-6
            key = "ok" if good else "FAILED: cells not convex or not orthogonal"
            failed |= not good
        elif code in (3, 4):
            key = "refused: " + message.split(": ")[-1][:90]
        else:
            key = "FAILED: exit %s %s" % (code, message[:120])
            failed = True
        outcomes.setdefault(key, []).append((seconds, trial, " ".join(options)))
    for key, runs in sorted(outcomes.items(), key=lambda kv: -len(kv[1])):
        slowest = ", ".join("%d (%.2f s, %s)" % (t, s, o) for s, t, o in sorted(runs, reverse=True)[:3])
        print("%4d  %s; slowest: %s" % (len(runs), key, slowest))
    print("%d trials in %.0f s" % (args.trials, time.time() - begin))
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
