#!/usr/bin/env bash
# The README's second command (and CI's): installs what is needed, builds, and runs every test
# through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -d ../shared/models ]; then
  echo "test.sh: the shared test models are expected at $(cd .. && pwd)/shared/models" >&2
  exit 1
fi
bash scripts/install-deps.sh
# The tests of every front end must run: a front end that cannot be built fails here.
bash scripts/build.sh -DVOROCRUST_REQUIRE_MESHLAB_PLUGIN=ON -DVOROCRUST_REQUIRE_PYTHON_MODULE=ON
cd build
ctest --output-on-failure --timeout 1200 -j 2
