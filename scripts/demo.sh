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
