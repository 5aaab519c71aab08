#!/usr/bin/env python3
"""Times the whole mesher through the CLI and prints bench/RESULTS.md table rows: per model the
seeds by kind, the cells, the skew repairs, the phases' seconds from report.json, and what
checkMesh says of the case.

Usage: python3 bench/whole_mesher.py BUILD_DIR MODELS_DIR [--threads N] [--seed S] MODEL...
"""
import argparse
import json
import os
import re
import subprocess
import tempfile


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("models")
    parser.add_argument("--threads", default="0")
    parser.add_argument("--seed", default="0")
    parser.add_argument("cases", nargs="+")
    args = parser.parse_args()
    print("| model | interior / outside / cap seeds | repair seeds (rounds) | cells | interior seeds | cells "
          "| skew repair | total | highly skew faces | checkMesh |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    env = dict(os.environ, WM_PROJECT_DIR="/usr/share/openfoam")
    for name in args.cases:
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([os.path.join(args.build, "cli", "vorocrust"), "mesh", os.path.join(args.models, name),
                            "-o", out, "-q", "--threads", args.threads, "--seed", args.seed,
                            "--format", "openfoam"], check=True)
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            check = subprocess.run(["checkMesh", "-case", os.path.join(out, "case")], capture_output=True, text=True,
                                   env=env).stdout
        seconds = {}
        for t in report["timings"]:
            phase = t["phase"].split(":")[0]
            seconds[phase] = seconds.get(phase, 0) + t["seconds"]
        i, c = report["interior"], report["cells"]
        skew = c["quality"]["skewness"]["highly_skew_faces"]
        verdict = "Mesh OK" if "\nMesh OK." in check else ", ".join(re.findall(r"\*\*\*([^,\n]*)", check))
        print("| %s | %d / %d / %d | %d (%d) | %d | %.2f s | %.2f s | %.2f s | %.2f s | %d | %s |" % (
            name, i["interior_seeds"], i["outside_seeds"], i["cap_seeds"], i["repair_seeds"], i["repair_rounds"],
            c["cells"], seconds.get("interior seeds", 0) + seconds.get("cap seeds", 0), seconds.get("cells", 0) + seconds.get("assembly", 0),
            seconds.get("skew repair", 0), report["total_seconds"], skew, verdict))


if __name__ == "__main__":
    main()
