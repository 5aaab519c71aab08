#!/usr/bin/env python3
"""The stress harness: the whole mesher over the shared models, several seeds and the option
families users try, checking on every run what holds for every correct mesh.

Each run is `vorocrust mesh MODEL -o OUT --format openfoam,seeds,ply OPTIONS`. It passes when
- the program exits 0, or refuses with a documented code (3 unreadable input, 4 invalid geometry)
  and a message; exit 1 (an internal error), a crash, any other code or the timeout fail it;
and, on exit 0,
- checkMesh says "Mesh OK" with no failed check ("***");
- every face between two cells is orthogonal to its seed link (the report's link angle, under
  0.05 degrees: rounding and welding only);
- the cells' volumes sum to the volume the output surface encloses (1e-8 relative; closed
  surfaces);
- there is one cell per material seed of seeds.csv;
- the cells conform to the output surface face for face: one boundary face per triangle with a
  material on one side only and one interface face per triangle between two materials (report.json's
  `surface.triangles_by_sides`; triangles of a sheet inside one region are not counted). Column
  "extra faces" shows the differences, boundary/interface; near-twin seeds, once dropped, made
  them differ by 1 to 13.
The clipped families (`--method clipped`) are held to the same checks but three: their boundary
and interface faces are the input's triangles cut by the cells (not one per triangle); their faces
on an interface lie on the input, not across their seeds' link (the link angle is checked on
single-material meshes only); and checkMesh may flag face pyramids, skewness and non-orthogonality
against cell centres in their non-convex cells (every other check must pass).
It records each run's wall time and peak resident memory, prints a table, and exits non-zero
when a run failed.

Usage:
  python3 bench/stress.py [--build build | --binary PROGRAM] [--models ../shared/models] [--slice full|ci]
                          [--budget SECONDS] [--only NAME,...] [--jobs N]

--slice ci is CI's time-boxed part (small models, every family); --budget stops starting runs
after that many seconds (the runs started still finish and count).
"""
import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor

# Scans and tessellations of smooth shapes, which users mesh with --smooth.
SCANS = {"igl_bunny.off", "directional_bimba.off", "cgal_elephant.off", "igl_fertility.off", "igl_3holes.off",
         "cgal_knot2.off", "igl_camelhead.off", "sandia_bird.obj", "sandia_torus.obj", "heptoroid_welded.off",
         "openmeeg_HeadNNb3.obj", "openmeeg_mne_sample_bem.obj"}

# The option families: name, options. Every model gets each of them; scans get --smooth too.
FAMILIES = [
    ("default", []),
    ("seed 1", ["--seed", "1"]),
    ("seed 2", ["--seed", "2"]),
    ("1 thread", ["--threads", "1"]),
    ("lattice", ["--interior", "lattice"]),
    ("cvt", ["--interior", "cvt"]),
    ("coarse L", ["--lipschitz", "0.5"]),
    ("fine L", ["--lipschitz", "0.15"]),
    ("clipped", ["--method", "clipped"]),
    ("clipped cvt", ["--method", "clipped", "--interior", "cvt", "--cvt-iterations", "5"]),
]
SMOOTH = ("smooth", ["--smooth"])

# CI's slice: models that mesh in seconds, among them non-manifold ones with several materials and
# a scan. (openmeeg_HeadNNa1 is small in faces but gives 340 000 cells: 35-200 s a run.)
CI_MODELS = ["sandia_OneBox.obj", "cgal_joint.off", "sandia_non_manifold_box.obj", "cgal_cubes_edge_contact.off",
             "directional_bimba.off"]

DOCUMENTED_REFUSALS = {3: "unreadable input", 4: "invalid geometry"}
# Clipped cells a reflex edge or a concave surface crosses are not convex; checkMesh's face-pyramid
# test (from the cell centre), skewness and non-orthogonality (against the line between cell
# centres, which an interface face is not orthogonal to) flag some of their faces. Every other
# check must pass.
CLIPPED_ALLOWED = ("face pyramids", "skewness", "non-orthogonality")
LINK_ANGLE_DEGREES = 0.05
VOLUME_RELATIVE = 1e-8


def run_measured(command, timeout):
    """Runs `command`; returns (exit code or None on timeout, stderr, seconds, peak RSS in MB)."""
    start = time.monotonic()
    with tempfile.TemporaryFile() as err:
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err, start_new_session=True)
        timer = threading.Timer(timeout, lambda: os.killpg(process.pid, signal.SIGKILL))
        timer.start()
        _, status, usage = os.wait4(process.pid, 0)
        timed_out = not timer.is_alive()
        timer.cancel()
        process.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        stderr = err.read().decode(errors="replace")
    code = None if timed_out else process.returncode
    return code, stderr, time.monotonic() - start, usage.ru_maxrss / 1024


def check_mesh(case, clipped=False):
    env = dict(os.environ, WM_PROJECT_DIR="/usr/share/openfoam")
    r = subprocess.run(["checkMesh", "-case", case], capture_output=True, text=True, env=env)
    failed = [line.strip() for line in r.stdout.splitlines() if "***" in line]
    if clipped:
        failed = [line for line in failed if not any(allowed in line for allowed in CLIPPED_ALLOWED)]
        if r.returncode != 0 or failed:
            return "checkMesh: " + ("; ".join(failed[:2]) or "exit %d" % r.returncode)
        return None
    if r.returncode != 0 or failed or "\nMesh OK." not in r.stdout:
        return "checkMesh: " + ("; ".join(failed[:2]) or "exit %d" % r.returncode)
    return None


def material_seeds(path):
    with open(path) as f:
        next(f)
        return sum(1 for line in f if line.split(",")[3] != "0")


def check_run(out, clipped=False):
    """The invariants of a mesh written to `out`; a list of what failed. Clipped cells take the
    input's triangles, cut, as boundary faces: their count is not the triangles'."""
    problems = []
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    cells = report["cells"]
    link = cells["quality"]["link_angle"]["max"]
    on_links = not clipped or cells["interface_faces"] == 0
    if on_links and link is not None and not link < LINK_ANGLE_DEGREES:
        problems.append("link angle %.3g deg" % link)
    enclosed = report["surface"]["quality"]["enclosed_volume"]["output"]
    if enclosed and abs(cells["volume"] - enclosed) > VOLUME_RELATIVE * enclosed:
        problems.append("cells' volume %.12g, surface encloses %.12g" % (cells["volume"], enclosed))
    seeds = material_seeds(os.path.join(out, "seeds.csv"))
    if seeds != cells["cells"]:
        problems.append("%d cells for %d material seeds" % (cells["cells"], seeds))
    by_sides = report["surface"]["triangles_by_sides"]
    excess = (cells["boundary_faces"] - by_sides["boundary"], cells["interface_faces"] - by_sides["interface"])
    if clipped:
        excess = (0, 0)
    if excess[0]:
        problems.append("%+d boundary faces against the surface's triangles" % excess[0])
    if excess[1]:
        problems.append("%+d interface faces against the surface's triangles" % excess[1])
    problem = check_mesh(os.path.join(out, "case"), clipped)
    if problem:
        problems.append(problem)
    return problems, cells["cells"], excess


def one_run(binary, models, model, family, options, timeout):
    with tempfile.TemporaryDirectory() as out:
        command = [binary, "mesh", os.path.join(models, model), "-o", out, "-q", "--format", "openfoam,seeds,ply",
                   *options]
        code, stderr, seconds, memory = run_measured(command, timeout)
        row = {"model": model, "family": family, "options": " ".join(options), "exit": code,
               "seconds": seconds, "peak_mb": memory, "cells": None, "problems": []}
        message = stderr.strip().splitlines()[-1] if stderr.strip() else ""
        if code is None:
            row["problems"].append("no end within %d s" % timeout)
        elif code in DOCUMENTED_REFUSALS:
            row["refusal"] = message
            if not message.startswith("vorocrust:"):
                row["problems"].append("refused (exit %d) without a message" % code)
        elif code != 0:
            row["problems"].append("exit %d: %s" % (code, message[:200]))
        else:
            row["problems"], row["cells"], row["boundary_excess"] = check_run(out, "clipped" in family)
        return row


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--binary", help="the vorocrust program (default: BUILD/cli/vorocrust)")
    parser.add_argument("--models", default=os.path.join(root, "..", "shared", "models"))
    parser.add_argument("--slice", choices=["full", "ci"], default="full")
    parser.add_argument("--budget", type=float, default=float("inf"), help="seconds after which no run starts")
    parser.add_argument("--only", default="", help="comma-separated model names")
    parser.add_argument("--families", default="", help="comma-separated family names")
    parser.add_argument("--jobs", type=int, default=1, help="runs at a time (each uses every core)")
    parser.add_argument("--timeout", type=float, default=1800)
    parser.add_argument("--json", help="write the rows to this file")
    args = parser.parse_args()

    binary = args.binary or os.path.join(args.build, "cli", "vorocrust")
    if args.only:
        models = args.only.split(",")
    elif args.slice == "ci":
        models = CI_MODELS
    else:
        models = sorted(f for f in os.listdir(args.models) if f.endswith((".off", ".obj", ".stl", ".ply")))
    wanted = set(args.families.split(",")) if args.families else None
    plan = []
    for model in models:
        families = FAMILIES + ([SMOOTH] if model in SCANS else [])
        for family, options in families:
            if wanted is None or family in wanted:
                plan.append((model, family, options))

    start = time.monotonic()
    rows = []

    def start_run(item):
        if time.monotonic() - start > args.budget:
            return None
        return one_run(binary, args.models, *item, args.timeout)

    print("| model | options | exit | cells | seconds | peak MB | KB per cell | extra faces | verdict |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---|")
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for row in pool.map(start_run, plan):
            if row is None:
                continue
            rows.append(row)
            verdict = "; ".join(row["problems"]) or ("refused: " + row["refusal"] if "refusal" in row else "pass")
            per_cell = "%.1f" % (row["peak_mb"] * 1024 / row["cells"]) if row["cells"] else ""
            excess = row.get("boundary_excess")
            print("| %s | %s | %s | %s | %.1f | %.0f | %s | %s | %s |" % (
                row["model"], row["options"] or "(default)", row["exit"], row["cells"] or "", row["seconds"],
                row["peak_mb"], per_cell, "" if excess is None else "%+d/%+d" % tuple(excess),
                "FAIL " + verdict if row["problems"] else verdict), flush=True)
    failed = [r for r in rows if r["problems"]]
    print("\n%d runs on %d models in %.0f s: %d passed, %d refused as documented, %d failed (of %d planned)" % (
        len(rows), len({r["model"] for r in rows}), time.monotonic() - start, len(rows) - len(failed)
        - sum(1 for r in rows if "refusal" in r and not r["problems"]),
        sum(1 for r in rows if "refusal" in r and not r["problems"]), len(failed), len(plan)))
    mismatched = [r for r in rows if r.get("boundary_excess") and any(r["boundary_excess"])]
    print("the cells' boundary or interface faces and the output triangles differ in %d of %d meshed runs" % (
        len(mismatched), sum(1 for r in rows if r.get("boundary_excess") is not None)))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
