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
# Every test but the million-cell run (label large: `ctest -L large`, about 11 minutes).
(cd build && ctest --output-on-failure --timeout 1200 -j 2 -LE large)
# The quick suite again, built with AddressSanitizer and UBSan (the readers' fuzz corpus among
# it): a memory error, a leak or undefined behaviour fails here even where results come out right.
# Without -Werror: GCC 12 at -O1 with the sanitizers warns of uninitialised reads inside
# OpenMesh's headers that are not there.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DVOROCRUST_SANITIZE=address,undefined -DVOROCRUST_BUILD_PYTHON=OFF -DVOROCRUST_BUILD_MESHLAB_PLUGIN=OFF \
  -DVOROCRUST_BUILD_CLI=OFF -DVOROCRUST_BUILD_BENCH=OFF -DVOROCRUST_WERROR=OFF
cmake --build build-asan -j "$(nproc)"
# The twelve heaviest unit tests (whole models through the interior sampler, the growing cells, the
# smoothing, the refinement and a brute-force check of the boundary samples: 25 to 70 s each under
# the sanitizers) run in the main suite only; the sanitizers see those stages through the others.
(cd build-asan && ctest --output-on-failure --timeout 1200 -j 2 -L quick \
  -E '^(SampleInterior\.(CvtMovesInteriorSeedsTowardTheirCentroidsAndKeepsTheSurface|SameSeedSameSeedsOnOneThread|LatticeGivesCubesInTheDeepInterior|RadiiAreLipschitzAndSeedsOutsideEachOthersBalls|RandomSeedsStayOutOfEveryBallAndKeepTheSurface)|GrowingCells\.(AddedSeedsGiveTheCellsOfAllSeedsOfAWholeRun|LongCellsAreTheMeshCellsAboveTheBound|CutFacesAreTheMeshFacesWithTheirSkewness)|SmoothPatches\.(BoundingRoundsKeepACoarseBentSurfaceNearItsInput|BunnyGetsFlatterPatches)|RefineBalls\.SmallerLipschitzGivesMoreBalls|BoundarySamples\.NearestNonCosmoothSampleOnACurvedPatchMatchesABruteForce)$')
