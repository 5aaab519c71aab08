#!/usr/bin/env python3
"""The scale benchmark: the whole mesher on one shared model at sizes that give about 0.1, 1, 3 and
10 million cells, with the seconds and the process's peak resident memory by the end of each stage
(report.json's timings), cells per second, peak memory per cell, the memory guard's estimate
against the peak, and checkMesh on the OpenFOAM case.

Usage: python3 bench/scale.py [--build build] [--models ../shared/models] [--threads 2]
                              [--sizes 0.6,0.3] [--no-check-mesh]

Prints a Markdown table for bench/RESULTS.md. A size whose estimate exceeds the machine's memory
is refused by the mesher's own guard (--max-memory, set to the machine's memory less 2 GB) in
seconds, and its row says so.
"""
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from current_table import STAGES, machine, stage_seconds, whole_mesher_arguments  # noqa: E402
from stress import check_mesh, run_measured  # noqa: E402

MODEL = "sandia_bracket.obj"
# --max-size on the bracket (65 x 40 x 54, 22 775 volume units): the default run has about 21 000
# cells, 0.6 gives 180 000 and 0.34 688 000; cells grow about as the inverse cube of the size
# (a little slower: the layer along the surface keeps its own sizes), so about 1, 3 and 10 million
# at the others.
SIZES = [0.6, 0.3, 0.21, 0.14]


def machine_gb():
    with open("/proc/meminfo") as f:
        return int(f.readline().split()[1]) / 1024 / 1024 * 1.073741824


def stage_peaks(report):
    """Per stage, the process's peak (MB) by the end of its last phase."""
    peaks = {name: 0.0 for name, _ in STAGES}
    for t in report["timings"]:
        phase = t["phase"].split(":")[0]
        for name, phases in STAGES:
            if phase in phases:
                peaks[name] = max(peaks[name], t["peak_resident_bytes"] / 1e6)
    return peaks


def main():
    parser = whole_mesher_arguments(__doc__)
    parser.add_argument("--sizes", default=",".join(str(s) for s in SIZES))
    parser.add_argument("--no-check-mesh", action="store_true")
    args = parser.parse_args()
    binary = os.path.join(args.build, "cli", "vorocrust")
    bound = max(1.0, machine_gb() - 2)
    print("Machine: %s. Command: `vorocrust mesh %s -o OUT -q --threads %s --seed 1 --format openfoam --max-memory %.0f "
          "--max-size S`. Per stage: seconds / peak resident MB by its end.\n" % (machine(), MODEL, args.threads, bound))
    print("| max size | cells | " + " | ".join(name for name, _ in STAGES) +
          " | total s | cells/s | peak MB | bytes per cell | estimate / peak | checkMesh |")
    print("|---:|---:|" + "---|" * len(STAGES) + "---:|---:|---:|---:|---:|---|")
    for size in (float(s) for s in args.sizes.split(",")):
        with tempfile.TemporaryDirectory() as out:
            command = [binary, "mesh", os.path.join(args.models, MODEL), "-o", out, "-q", "--threads", args.threads,
                       "--seed", "1", "--format", "openfoam", "--max-memory", "%.0f" % bound, "--max-size", str(size)]
            code, stderr, seconds, peak_mb = run_measured(command, 4 * 3600)
            if code == 2 and "max-memory" in stderr:
                print("| %g | refused: %s |" % (size, stderr.strip().splitlines()[-1][:200]))
                continue
            if code != 0:
                print("| %g | exit %s: %s |" % (size, code, stderr.strip()[-200:]))
                continue
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            verdict = "not run" if args.no_check_mesh else (check_mesh(os.path.join(out, "case")) or "Mesh OK")
        cells = report["cells"]["cells"]
        times, peaks = stage_seconds(report), stage_peaks(report)
        # The kernel's peak of the whole process (getrusage), in the units of the stages' peaks.
        peak = peak_mb * 1024 * 1024
        print("| %g | %d | %s | %.1f | %.0f | %.0f | %.0f | %.2f | %s |" % (
            size, cells, " | ".join("%.1f / %.0f" % (times[n], peaks[n]) for n, _ in STAGES), report["total_seconds"],
            cells / report["total_seconds"], peak / 1e6, peak / cells, report["memory"]["estimated_peak_bytes"] / peak,
            verdict))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
