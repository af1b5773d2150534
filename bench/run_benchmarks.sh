#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the benchmarks, runs them once and writes docs/benchmarks.md: every figure on the page
# comes from this one run on this machine.
#
#   bench/run_benchmarks.sh [BUILD_DIR]        (default: build; configured Release if missing)
#
# Environment: EXPLICIT_SECONDS (time limit of the explicit torus run, default 300),
# QUICK=1 (smaller sizes, for trying the script; the page then says so).
# Other processes on the machine skew the figures: the page records the load average before and
# after the run. Run it when the machine is otherwise idle.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
page=$root/docs/benchmarks.md
explicit_seconds=${EXPLICIT_SECONDS:-300}
sizes=10000,100000,1000000
levels=3,4,5,6,7
tori=48,16,96,32,192,64
if [[ ${QUICK:-0} == 1 ]]; then
  sizes=10000,100000
  levels=3,4,5,6
  tori=48,16,96,32
  explicit_seconds=30
fi

if [[ ! -f $build/CMakeCache.txt ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")
[[ $build_type == Release ]] || { echo "run_benchmarks: $build is a '$build_type' build; use a Release build" >&2; exit 1; }
cmake --build "$build" -j2 --target flow_bench restoration_bench >/dev/null

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bin=$build/bin
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
start=$(date -u +%Y-%m-%dT%H:%MZ)
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}  # shared cores: idle threads must not spin

echo "run_benchmarks: throughput" >&2
"$bin/flow_bench" throughput --sizes "$sizes" >"$tmp/throughput.md"
echo "run_benchmarks: factorisation" >&2
"$bin/flow_bench" factorization --levels "$levels" >"$tmp/factorization.md"
echo "run_benchmarks: convergence (explicit runs up to ${explicit_seconds} s)" >&2
"$bin/flow_bench" convergence --bunny "$root/data/bunny_flank_hole.ply" --explicit-seconds "$explicit_seconds" \
  >"$tmp/convergence.md"
echo "run_benchmarks: the default pipeline across resolutions (explicit runs up to ${explicit_seconds} s)" >&2
"$bin/flow_bench" resolution --tori "$tori" --explicit-seconds "$explicit_seconds" >"$tmp/resolution.md"
echo "run_benchmarks: restoration vs CGAL" >&2
"$bin/restoration_bench" "$root/data/bunny.ply" --center 0.82 2.95 3.81 --radius 2.0 >"$tmp/restoration.md"
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

cpu=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
cores=$(nproc)
threads_per_core=$(lscpu | sed -n 's/^Thread(s) per core: *//p')
l3=$(lscpu | sed -n 's/^L3 cache: *//p')
l3=${l3:-$(cat /sys/devices/system/cpu/cpu0/cache/index3/size 2>/dev/null || echo unknown)}
cholmod=$(grep -q 'ELASTICA_HAVE_CHOLMOD\|CHOLMOD_LIBRARY:FILEPATH=/' "$build/CMakeCache.txt" && echo yes || echo no)
blas=$(readlink -f /usr/lib/x86_64-linux-gnu/libblas.so.3 2>/dev/null || echo unknown)
compiler=$("${CXX:-c++}" --version | head -1)
rev=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=$(git -C "$root" status --porcelain 2>/dev/null | grep -v -e '^?? ' -e 'docs/benchmarks.md' | wc -l || true)
[[ $dirty == 0 ]] || rev="$rev (with uncommitted changes)"

# The real-shape, denoising and regions sections have their own, slower runs (bench/real_shapes.sh
# --page, bench/denoise.sh, bench/region_sweep.py --cgal by hand): kept as they were.
real_shapes=$(sed -n '/^<!-- real-shapes:/,/^<!-- \/real-shapes -->/p' "$page" 2>/dev/null || true)
real_shapes_notes=$(sed -n '/^<!-- real-shapes-notes/,/^<!-- \/real-shapes-notes -->/p' "$page" 2>/dev/null || true)
denoising=$(sed -n '/^<!-- denoise/,/^<!-- \/denoise -->/p' "$page" 2>/dev/null || true)
regions=$(sed -n '/^<!-- regions:/,/^<!-- \/regions -->/p' "$page" 2>/dev/null || true)
{
  cat "$root/bench/benchmarks_header.md"
  cat <<EOF

## This run

- Machine: $cpu, $cores cores visible ($threads_per_core thread(s) per core), L3 $l3; $compiler,
  Release build; BLAS $blas; CHOLMOD linked: $cholmod.
- Load average (1, 5, 15 min) before: $load_before; after: $load_after. The machine is shared with
  other jobs: figures are the best of several repetitions, and the ratios on each row come from
  the same minute of the same run.
- Date $start, commit $rev${QUICK:+ — QUICK run (smaller sizes), not the reference figures}.
- Command: \`bench/run_benchmarks.sh\` (with \`EXPLICIT_SECONDS=$explicit_seconds\`), which ran:
  \`\`\`
  OMP_WAIT_POLICY=$OMP_WAIT_POLICY
  flow_bench throughput --sizes $sizes
  flow_bench factorization --levels $levels
  flow_bench resolution --tori $tori --explicit-seconds $explicit_seconds
  flow_bench convergence --bunny data/bunny_flank_hole.ply --explicit-seconds $explicit_seconds
  restoration_bench data/bunny.ply --center 0.82 2.95 3.81 --radius 2.0
  \`\`\`

## 1. Explicit step throughput and the memory-bandwidth reference

One explicit elastica step (geometry, curvature, Δ_B H, speed, tangential drift, update) on tori
R/r = 3 with every vertex free; threads set with \`omp_set_num_threads\`. *Step bytes/vertex*: the
bytes of every array the step reads or writes (positions, topology, geometry, curvature,
scratch); *triad*: a STREAM triad a = b + ½c over three arrays of that many bytes in total, with
the same threads, measured right after the step — the time a step would take if it only had to
stream its arrays once. *step / triad* is how many such passes one step costs.

EOF
  cat "$tmp/throughput.md"
  cat <<EOF

## 2. Time to converge: explicit vs semi-implicit

Wall time of the flow until the energy is within 1 % of the converged energy E*, the
semi-implicit run's plateau, from the same start: the issue's criterion (E ≤ 1.01 E*), and
E − E* ≤ 1 % of E₀ − E* (99 % of the decrease), which is the meaningful one where the start is
already within 1 % of E*. Explicit: the paper's step (τ = A_min²/150, energy checked every 100
steps), limited to ${explicit_seconds} s or 2,000,000 steps (fair's default step limit when these tables were made), whichever comes
first; semi-implicit: adaptive τ to its plateau, without remeshing (the two integrators on the same
mesh; section 5 has the default pipeline). The torus is the
issue's (R/r = 3, 48×16 = 768 vertices, every vertex free); the restoration times the flow stage of
\`elastica fill\` on the bunny's flank (both schemes from the same bi-Laplace start).

EOF
  cat "$tmp/convergence.md"
  cat <<EOF

## 3. Semi-implicit system: factorisation, SimplicialLDLT vs CHOLMOD

The matrix M + τ/2·C M⁻¹ C of one semi-implicit step on icospheres (every vertex free), the
pattern analysed once (as the flow does once per connectivity), then numeric factorisations and
solves (best of several).

EOF
  cat "$tmp/factorization.md"
  cat <<EOF

## 4. Bunny-flank restoration vs CGAL

\`restoration_bench\` (see docs/restoration.md): the same 37-edge hole filled by each method; wall
time of the whole fill (best of repeated runs) and sampled distances to the removed surface in % of the bounding-box
diagonal.

EOF
  sed -n '/^|/p' "$tmp/restoration.md"
  # Target: the default fill (elastica, semi-implicit) within 3x of CGAL's time.
  awk -F'|' '
    /elastica, semi-implicit/ { ours = $3 + 0 }
    /CGAL/ { cgal = $3 + 0 }
    END {
      if (cgal > 0 && ours > 0) {
        r = ours / cgal
        printf "\nTarget (issue 6): the default fill (elastica, semi-implicit) takes %.1fx CGAL'"'"'s time against within 3x: %s (%.0f %% over).\n", r, r <= 3 ? "met" : "missed", r <= 3 ? 0 : 100 * (r / 3 - 1)
      } else print "\n(CGAL not built: libcgal-dev missing at configure time.)"
    }' "$tmp/restoration.md"
  cat <<EOF

## 5. The default pipeline across resolutions

\`fair\` on tori R/r = 3 (→ the Clifford torus, R/r = √2, E = 8π²) at several resolutions, every
vertex free: the default (\`--scheme auto\`: the vector scheme from 600 vertices per handle of the input,
the semi-implicit one below; remeshing, flips and the embedding guard), the semi-implicit pipeline
and the paper's explicit scheme (stopped at its energy plateau or ${explicit_seconds} s). Steps count
attempts (rejected ones included) for the adaptive schemes; R/r is a least-squares fit of a torus of
revolution, E the flow's own.

EOF
  cat "$tmp/resolution.md"
  cat "$root/bench/benchmarks_footer.md"
  if [[ -n $real_shapes ]]; then
    printf '\n## Real shapes: the default fair on libcgal-demo scans\n\n%s\n' "$real_shapes"
    [[ -z $real_shapes_notes ]] || printf '\n%s\n' "$real_shapes_notes"
  fi
  if [[ -n $denoising ]]; then
    printf '\n## Denoising against MeshLab\n\n%s\n' "$denoising"
  fi
  if [[ -n $regions ]]; then
    printf "\n## Regions beside CGAL's fair() (issue 53)\n\n%s\n" "$regions"
  fi
} >"$page"
echo "run_benchmarks: wrote $page" >&2
