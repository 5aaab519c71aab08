#!/usr/bin/env bash
# Fuzzes the readers: each libFuzzer target of tests/fuzz for SECONDS seconds (default 600), two
# at a time, from a copy of the committed corpus, under AddressSanitizer and UBSan.
#
#   bash bench/fuzz.sh [SECONDS] [TARGET...]      targets: off obj stl ply seeds sizing balls poly
#
# Builds build-fuzz/ with clang 14 (VOROCRUST_FUZZ=ON). Crashes land in build-fuzz/crashes/<target>/;
# a crash becomes a regression test by adding its input (minimised with -minimize_crash=1) to
# tests/fuzz/corpus/<target>/, which every build replays. Prints per target the executions run,
# their rate and the corpus grown; nothing here is committed by itself.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(off obj stl ply seeds sizing balls poly)

build=build-fuzz
if [ ! -f "$build/build.ninja" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DVOROCRUST_FUZZ=ON -DVOROCRUST_SANITIZE=address,undefined -DVOROCRUST_WERROR=OFF \
    -DVOROCRUST_BUILD_TESTS=OFF -DVOROCRUST_BUILD_CLI=OFF -DVOROCRUST_BUILD_PYTHON=OFF \
    -DVOROCRUST_BUILD_MESHLAB_PLUGIN=OFF -DVOROCRUST_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$build" -j2 --target "${targets[@]/#/vorocrust_fuzz_}"

run_one() {
  local t=$1 corpus="$build/corpus/$1" crashes="$build/crashes/$1"
  mkdir -p "$corpus" "$crashes"
  cp -n tests/fuzz/corpus/"$t"/* "$corpus"/ 2>/dev/null || true
  local before
  before=$(ls "$corpus" | wc -l)
  # One job per target; the readers refuse bad input, so only a crash, a leak, undefined
  # behaviour, a timeout (10 s) or memory beyond 2 GB ends a run early.
  if "$build/tests/fuzz/vorocrust_fuzz_$t" "$corpus" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$crashes/" \
      >"$build/fuzz-$t.log" 2>&1; then
    status=ok
  else
    status="FAILED (see $build/fuzz-$t.log, $crashes/)"
  fi
  local runs rate
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/fuzz-$t.log" | grep -o '[0-9]*$' || echo 0)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$build/fuzz-$t.log" | grep -o '[0-9]*$' || echo 0)
  printf '%-7s %12s runs %8s/s  corpus %4d -> %4d  %s\n' "$t" "$runs" "$rate" "$before" \
    "$(ls "$corpus" | wc -l)" "$status"
}

failed=0
for ((i = 0; i < ${#targets[@]}; i += 2)); do
  run_one "${targets[i]}" >"$build/fuzz-${targets[i]}.line" &
  if ((i + 1 < ${#targets[@]})); then run_one "${targets[i + 1]}" >"$build/fuzz-${targets[i + 1]}.line" & fi
  wait
  cat "$build/fuzz-${targets[i]}.line"
  ((i + 1 < ${#targets[@]})) && cat "$build/fuzz-${targets[i + 1]}.line"
done
grep -l FAILED "$build"/fuzz-*.line >/dev/null 2>&1 && failed=1
exit $failed
