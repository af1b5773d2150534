#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# CI's extra step, run by .ci/run after the README's test command (which builds build/ and runs
# the test suite):
#   1. the whole test suite again, built with AddressSanitizer + UndefinedBehaviorSanitizer
#      (build-asan/, g++, any report fails the run);
#   2. a bounded libFuzzer run of every fuzz target (scripts/fuzz.sh, clang, build-fuzz/).
#
#   scripts/ci-extra.sh [FUZZ_SECONDS_PER_TARGET]   (default 60)
#
# float-cast-overflow is named because g++'s -fsanitize=undefined leaves it out (clang's, in the
# fuzz build, has it: fuzzing found a 1e300 converted to an integer in the PLY reader).
# The sanitizer build is optimised (-O2 -g1, without NDEBUG so Eigen's and vcglib's assertions stay
# on): Debug at -O1 made single flow tests take minutes (Flow.ScaleCovariance 250 s; 13 s here,
# 1.3 s in Release), and the suite never finished. OpenMP is left out of it: libgomp is not built
# with the sanitizers, so what happens inside its thread pool is unchecked and can be misreported.
# The `#pragma omp` loops (geometry.cpp, flow_state.cpp) then run serially with the same bodies,
# which are checked; they go parallel only above 20,000 elements (elastica/parallel.h), more than
# any test mesh has. The MeshLab plugin and the Python module are not in this build: they load into
# unsanitized hosts (MeshLab's binaries and libmeshlab-common; /usr/bin/python3), which cannot
# carry the ASan runtime.
# -g1 (line tables only) and a unity build (CMake's batches of 8 sources per unit, so the headers
# (Eigen, vcglib, gtest) are compiled once per batch, not per file), for CI's 45 minutes: reports
# still name the function and file:line of every frame, inlined ones too (docs/decisions.md, "CI's time").
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds=${1:-60}
start=$SECONDS

echo "== sanitizers: ASan + UBSan build of the test suite (build-asan/)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -g1" -DCMAKE_UNITY_BUILD=ON \
  -DELASTICA_BUILD_PLUGIN=OFF -DELASTICA_BUILD_BENCH=OFF -DELASTICA_BUILD_PYTHON=OFF -DCMAKE_DISABLE_FIND_PACKAGE_OpenMP=ON \
  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=undefined,float-cast-overflow -fno-omit-frame-pointer" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
nice cmake --build build-asan -j"$(nproc)" >/dev/null
echo "== sanitizers: built ($((SECONDS - start)) s)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:halt_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# Not here: tier_includes (compiles probe files, runs none of them) and readme_layout (reads the
# docs): no instrumented code runs in them, so the sanitizers have nothing to watch (nor threads:
# .ci/run's one-thread pass leaves them out too, so no test here is owed a one-thread run).
# Nor two long instances of two real-scan families, whose other instances stay here: the same
# test body on a longer run, and every line they reach is reached here too (measured with
# coverage, docs/decisions.md "CI's time"); .ci/run runs them on one thread in Release.
sanitizer_skip='^(tier_includes|readme_layout)$'
sanitizer_skip+='|^LibcgalDemo/RealShape\.GenusZeroScanBecomesARoundSphere/dino( |$)'
sanitizer_skip+='|^LibcgalDemo/RealShapeWithHandles\.ReachesAResolvedFairShapeWithItsHandles/elephant( |$)'
# The names this pass runs, without gtest's "# GetParam() = ..." suffix (it can hold an address):
# .ci/run's one-thread pass runs build/'s other tests.
ctest --test-dir build-asan -N -E "$sanitizer_skip" | sed -n 's/^ *Test *#[0-9]*: //p' |
  sed 's/  # GetParam() = .*//' | sort -u >build-asan/sanitized-tests.txt
# On one thread: this pass is also CI's one-thread run of these tests (.ci/run runs the rest in
# Release). OMP_THREAD_LIMIT=1 because Debian's CHOLMOD starts four OpenMP threads whatever
# OMP_NUM_THREADS says; Release keeps it on one (spd_solver.cpp), which needs OpenMP in our code.
OMP_NUM_THREADS=1 OMP_THREAD_LIMIT=1 \
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E "$sanitizer_skip"
echo "== sanitizers: clean ($((SECONDS - start)) s so far)"

echo "== fuzzing: ${fuzz_seconds} s per target"
scripts/fuzz.sh "$fuzz_seconds"
echo "== ci-extra: done in $((SECONDS - start)) s"
