#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzz the mesh readers and the flow with libFuzzer (clang, AddressSanitizer, UBSan).
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#
# SECONDS per target (default 60); TARGETs among fuzz_read_ply fuzz_read_off fuzz_read_stl
# fuzz_read_obj fuzz_flow (default: all). Builds build-fuzz/ (-DELASTICA_BUILD_FUZZERS=ON, clang)
# if needed, then runs each target niced for SECONDS, starting from the seeds in
# tests/fuzz/corpus/<format>/ and the hostile inputs in tests/hostile/ and growing a working
# corpus in build-fuzz/corpus/<target>/ (kept between runs, so long campaigns add up).
# A crash, leak, sanitizer report or timeout leaves its input in build-fuzz/artifacts/ and makes
# the script fail: turn it into a regression file in tests/hostile/ (see docs/robustness.md).
# One line per target (executions, seconds, coverage, crashes) goes to build-fuzz/fuzz-summary.txt.
#
# For a long campaign: scripts/fuzz.sh 3600 fuzz_read_ply   (an hour on one target)
# FUZZ_RUNS=N stops each target after N executions if that comes before SECONDS:
#   FUZZ_RUNS=1000000 scripts/fuzz.sh 3600 fuzz_read_obj
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(fuzz_read_ply fuzz_read_off fuzz_read_stl fuzz_read_obj fuzz_flow)
build=build-fuzz

# Line tables only and a unity build (as the sanitizer build, scripts/ci-extra.sh): a report still
# names every frame's function and file:line:column, inlined frames too (docs/decisions.md, "CI's time").
if [[ ! -f $build/CMakeCache.txt ]]; then
  CC=clang CXX=clang++ cmake -S . -B $build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DELASTICA_BUILD_FUZZERS=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" -DCMAKE_UNITY_BUILD=ON \
    -DELASTICA_BUILD_PLUGIN=OFF -DELASTICA_BUILD_CLI=OFF -DELASTICA_BUILD_TESTS=OFF -DELASTICA_BUILD_BENCH=OFF -DELASTICA_BUILD_PYTHON=OFF >/dev/null
fi
cmake --build $build -j"$(nproc)" --target "${targets[@]}" >/dev/null

mkdir -p $build/artifacts
summary=$build/fuzz-summary.txt
: >"$summary"

# One target: SECONDS of libFuzzer, then its summary line into $build/$t.summary and 1 (a find)
# or 0 into $build/$t.status.
fuzz_target() {
  local t=$1 format=${1#fuzz_read_} status=0
  [[ $t == fuzz_flow ]] && format=flow
  local corpus=$build/corpus/$t log=$build/$t.log
  mkdir -p "$corpus"
  local seeds=(tests/fuzz/corpus/"$format")
  [[ $format != flow && -d tests/hostile ]] && seeds+=(tests/hostile)
  # One process per target; -timeout catches hangs (generous: a niced fuzzer on a loaded machine
  # once exceeded 25 s on an input that takes 0.2 s, and fuzz_flow's remeshings before a run's
  # first step, which its time limit does not cut, take up to 34 s in this build:
  # docs/robustness.md), -rss_limit_mb huge allocations.
  if ! nice "$build/bin/$t" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=120 \
      -rss_limit_mb=2048 ${FUZZ_RUNS:+-runs=$FUZZ_RUNS} -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" >"$log" 2>&1; then
    status=1
    echo "fuzz.sh: $t FAILED, see $log and $build/artifacts/" >&2
  fi
  local runs secs cov crashes slow
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1 || true)
  # libFuzzer names an artifact by what it found: crash-, leak-, timeout- and oom- inputs fail the
  # run; slow-unit- inputs (slower than -report_slow_units, 10 s) are kept for a look only.
  crashes=$(find $build/artifacts \( -name "$t-crash-*" -o -name "$t-leak-*" -o -name "$t-timeout-*" -o -name "$t-oom-*" \) | wc -l)
  slow=$(find $build/artifacts -name "$t-slow-unit-*" | wc -l)
  printf '%s: %s executions in %s s, %s, corpus %s files, %s failing inputs, %s slow inputs (not failures)\n' \
    "$t" "${runs:-?}" "${secs:-?}" "${cov:-cov: ?}" "$(find "$corpus" -type f | wc -l)" "$crashes" "$slow" >"$build/$t.summary"
  echo $status >"$build/$t.status"
}

# FUZZ_JOBS targets at once (default: the cores), each a single process on its own core, so each
# still gets SECONDS of one core's executions; on 2 cores the 5 targets take 3 rounds, not 5.
jobs=${FUZZ_JOBS:-$(nproc)}
for t in "${targets[@]}"; do
  rm -f "$build/$t.summary" "$build/$t.status"
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  fuzz_target "$t" &
done
wait
failed=0
for t in "${targets[@]}"; do
  cat "$build/$t.summary" 2>/dev/null | tee -a "$summary" || echo "$t: no summary" | tee -a "$summary"
  [[ $(cat "$build/$t.status" 2>/dev/null) == 0 ]] || failed=1
done
exit $failed
