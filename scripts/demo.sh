#!/usr/bin/env bash
# The README's first command: installs what is needed, builds, and runs the main job on the
# bundled sample.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
echo
echo "== build/cli/vorocrust info samples/cgal_joint.off"
build/cli/vorocrust info samples/cgal_joint.off
echo
echo "== build/cli/vorocrust mesh samples/cgal_joint.off -o demo-output --stop-after balls"
build/cli/vorocrust mesh samples/cgal_joint.off -o demo-output --stop-after balls
echo
echo "== build/cli/vorocrust check-balls samples/cgal_joint.off demo-output/balls.csv"
build/cli/vorocrust check-balls samples/cgal_joint.off demo-output/balls.csv
echo
echo "The protecting balls are in demo-output/: balls.csv, balls.vtk (open in ParaView and glyph the"
echo "points as spheres scaled by 'radius'), and report.json (counts and the time of each phase)."
