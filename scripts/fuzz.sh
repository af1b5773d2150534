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

if [[ ! -f $build/CMakeCache.txt ]]; then
  CC=clang CXX=clang++ cmake -S . -B $build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DELASTICA_BUILD_FUZZERS=ON \
    -DELASTICA_BUILD_PLUGIN=OFF -DELASTICA_BUILD_CLI=OFF -DELASTICA_BUILD_TESTS=OFF -DELASTICA_BUILD_BENCH=OFF -DELASTICA_BUILD_PYTHON=OFF >/dev/null
fi
cmake --build $build -j"$(nproc)" --target "${targets[@]}" >/dev/null

mkdir -p $build/artifacts
summary=$build/fuzz-summary.txt
: >"$summary"
failed=0
for t in "${targets[@]}"; do
  format=${t#fuzz_read_}
  [[ $t == fuzz_flow ]] && format=flow
  corpus=$build/corpus/$t
  mkdir -p "$corpus"
  seeds=(tests/fuzz/corpus/"$format")
  [[ $format != flow && -d tests/hostile ]] && seeds+=(tests/hostile)
  log=$build/$t.log
  # One process (the machine has 2 cores); -timeout catches hangs (generous: a niced fuzzer on a
  # loaded machine once exceeded 25 s on an input that takes 0.2 s, and fuzz_flow's remeshings
  # before a run's first step, which its time limit does not cut, take up to 34 s in this build:
  # docs/robustness.md), -rss_limit_mb huge allocations.
  if ! nice "$build/bin/$t" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=120 \
      -rss_limit_mb=2048 ${FUZZ_RUNS:+-runs=$FUZZ_RUNS} -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" >"$log" 2>&1; then
    failed=1
    echo "fuzz.sh: $t FAILED, see $log and $build/artifacts/" >&2
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1)
  # libFuzzer names an artifact by what it found: crash-, leak-, timeout- and oom- inputs fail the
  # run; slow-unit- inputs (slower than -report_slow_units, 10 s) are kept for a look only.
  crashes=$(find $build/artifacts \( -name "$t-crash-*" -o -name "$t-leak-*" -o -name "$t-timeout-*" -o -name "$t-oom-*" \) | wc -l)
  slow=$(find $build/artifacts -name "$t-slow-unit-*" | wc -l)
  printf '%s: %s executions in %s s, %s, corpus %s files, %s failing inputs, %s slow inputs (not failures)\n' \
    "$t" "${runs:-?}" "${secs:-?}" "${cov:-cov: ?}" "$(find "$corpus" -type f | wc -l)" "$crashes" "$slow" | tee -a "$summary"
done
exit $failed
