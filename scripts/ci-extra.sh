#!/usr/bin/env bash
# CI's extra step, run by .ci/run after the README's test command (which builds build/ and runs
# the test suite):
#   1. the whole test suite again, built with AddressSanitizer + UndefinedBehaviorSanitizer
#      (build-asan/, g++, any report fails the run);
#   2. a bounded libFuzzer run of every fuzz target (scripts/fuzz.sh, clang, build-fuzz/).
#
#   scripts/ci-extra.sh [FUZZ_SECONDS_PER_TARGET]   (default 60)
#
# OpenMP is left out of the sanitizer build: libgomp is not built with the sanitizers, so what
# happens inside its thread pool is unchecked and can be misreported. The `#pragma omp` loops
# (geometry.cpp, flow_state.cpp) then run serially with the same bodies, which are checked; they
# go parallel only above 20,000 elements (elastica/parallel.h), more than any test mesh has.
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds=${1:-60}
start=$SECONDS

echo "== sanitizers: ASan + UBSan build of the test suite (build-asan/)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DELASTICA_BUILD_PLUGIN=OFF -DELASTICA_BUILD_BENCH=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_OpenMP=ON \
  -DCMAKE_CXX_FLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-asan -j"$(nproc)" >/dev/null
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:halt_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
echo "== sanitizers: clean ($((SECONDS - start)) s so far)"

echo "== fuzzing: ${fuzz_seconds} s per target"
scripts/fuzz.sh "$fuzz_seconds"
echo "== ci-extra: done in $((SECONDS - start)) s"
