#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Behaviour check for refactorings: runs a fixed set of `elastica` commands (every flow, both
# schemes, subdivision, selection, sliding boundary, edge flips, fill and its stages, curvature,
# subdivide, .mlx scripts) on bundled and generated meshes, and writes each output mesh and the
# command's stdout (timing lines removed, the checkout's and the cache's paths replaced by SOURCE
# and HOME, so two clones compare) into OUTDIR, with a SHA256SUMS file.
#
#   scripts/golden-outputs.sh BUILD_BIN_DIR OUTDIR [THREADS]
#   diff before/SHA256SUMS after/SHA256SUMS     # byte-identical outputs: no difference
#
# Only step-bounded runs (no --max-seconds), so two runs of the same code give the same bytes, on
# THREADS OpenMP threads (default 1). The bytes must not depend on THREADS either:
# scripts/same-output.sh runs this at 1 and 2 threads and compares.
set -euo pipefail
usage="usage: golden-outputs.sh BUILD_BIN_DIR OUTDIR [THREADS]"
bin=${1:?$usage}
out=${2:?$usage}
threads=${3:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
exe="$(cd "$bin" 2>/dev/null && pwd)/elastica"
[[ -x "$exe" ]] || { echo "golden-outputs: no elastica in $bin" >&2; exit 1; }
export OMP_NUM_THREADS=$threads
mkdir -p "$out"
cd "$out"
rm -f ./*.ply ./*.txt SHA256SUMS

home=${HOME%/}
[[ -n "$home" ]] || home=/nonexistent-home  # HOME=/ would turn every slash into HOME
# name, then the command's arguments; stdout goes to NAME.txt without lines that carry seconds.
run() {
  local name=$1; shift
  "$exe" "$@" 2>/dev/null | sed -E 's/[0-9.]+ s\b/# s/g; s/[0-9.]+ ms\b/# ms/g' \
    | sed "s|$root|SOURCE|g; s|$home|HOME|g" >"$name.txt" \
    || echo "exit $?" >>"$name.txt"
}

"$exe" generate icosphere --level 2 --noise 0.05 --seed 7 -o noisy.ply >/dev/null
"$exe" generate torus --segments 24,12 -o torus.ply >/dev/null
"$exe" generate frame -o frame.ply >/dev/null
# Every other face of the bunny's first 400: a scattered selection (most vertices stay fixed).
printf '%s\n' $(seq 0 2 400) >faces.txt

run fair_explicit        fair noisy.ply -o fair_explicit.ply --feature-size 0 --scheme explicit --max-steps 3000
run fair_semi            fair noisy.ply -o fair_semi.ply --feature-size 0 --scheme semi-implicit
run fair_lmc             fair noisy.ply -o fair_lmc.ply --feature-size 0 --flow lmc --scheme explicit --max-steps 2000
run fair_lmc_semi        fair noisy.ply -o fair_lmc_semi.ply --feature-size 0 --flow lmc --scheme semi-implicit --max-steps 200
run fair_bilaplacian     fair noisy.ply -o fair_bilaplacian.ply --feature-size 0 --flow bilaplacian --max-steps 2000
run fair_subdivide       fair noisy.ply -o fair_subdivide.ply --feature-size 0 --scheme explicit --subdivide 1 --max-steps 4000
run fair_subdivide_semi  fair noisy.ply -o fair_subdivide_semi.ply --feature-size 0 --scheme semi-implicit --subdivide 1
run fair_torus_semi      fair torus.ply -o fair_torus_semi.ply --feature-size 0 --scheme semi-implicit --max-steps 150
run fair_frame_remesh    fair frame.ply -o fair_frame_remesh.ply --feature-size 0 --scheme semi-implicit --subdivide 1 --remesh --max-steps 300
run fair_frame_explicit  fair frame.ply -o fair_frame_explicit.ply --feature-size 0 --scheme explicit --remesh --max-steps 3000 --h2k lambda --area barycentric
run fair_bunny_selected  fair "$root/data/bunny.ply" -o fair_bunny_selected.ply --feature-size 0 --selected-faces faces.txt --scheme semi-implicit
run fair_bunny_sel_expl  fair "$root/data/bunny.ply" -o fair_bunny_sel_expl.ply --feature-size 0 --selected-faces faces.txt --scheme explicit --max-steps 2000 --no-tangential
run fair_slide           fair "$root/data/bunny_flank_hole.ply" -o fair_slide.ply --feature-size 0 --scheme explicit --boundary slide --max-steps 1500
run fair_slide_semi      fair "$root/data/bunny_flank_hole.ply" -o fair_slide_semi.ply --feature-size 0 --boundary slide --scheme semi-implicit --max-steps 60
run fair_color           fair noisy.ply -o fair_color.ply --feature-size 0 --scheme explicit --max-steps 500 --color-by-mean-curvature --ascii
run fair_cage_torus      fair "$root/data/cages/torus_quad_5x5.off" -o fair_cage_torus.ply --feature-size 0 --subdivide 2
# The default: a fairing amount sized from the mesh (app/fairing_amount.h), whole and on a region.
run fair_amount          fair "$root/data/bunny.ply" -o fair_amount.ply
run fair_amount_region   fair "$root/data/bunny.ply" -o fair_amount_region.ply --selected-faces faces.txt
run fair_cage_no_remesh  fair "$root/data/cages/hex_nut.off" -o fair_cage_no_remesh.ply --feature-size 0 --no-remesh --max-steps 100
run fill_default         fill "$root/data/bunny_flank_hole.ply" -o fill_default.ply --color-by-mean-curvature
run fill_lmc             fill "$root/data/bunny_flank_hole.ply" -o fill_lmc.ply --flow lmc
run fill_explicit        fill "$root/data/bunny_flank_hole.ply" -o fill_explicit.ply --scheme explicit --max-steps 3000
for stage in triangulation refinement biharmonic; do
  run fill_$stage        fill "$root/data/bunny_flank_hole.ply" -o fill_$stage.ply --stop-after $stage
done
run fill_shape0          fill "$root/data/bunny_flank_hole.ply" -o fill_shape0.ply --shape-tol 0 --max-steps 100
elephant=$(ls -d "${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}"/cgal-data-*/meshes/elephant-with-holes.off 2>/dev/null | head -n1 || true)
[[ -n "$elephant" ]] && run fill_elephant fill "$elephant" -o fill_elephant.ply
# Whole scans with the defaults (the dino's arrays pass parallel.h's grain once remeshed), the
# elephant's handles for a bounded number of attempts, and a contiguous region of the cow.
meshes=$(dirname "${elephant:-/nonexistent/x}")
if [[ -f "$meshes/dino.off" ]]; then
  run fair_dino          fair "$meshes/dino.off" -o fair_dino.ply --feature-size 0
  run fair_elephant      fair "$meshes/elephant.off" -o fair_elephant.ply --feature-size 0 --max-steps 150
  seq 0 999 >cow_region.txt
  run fair_cow_region    fair "$meshes/cow.off" -o fair_cow_region.ply --feature-size 0 --selected-faces cow_region.txt
  rm -f cow_region.txt
fi
# Above parallel.h's grain from the start: 40,962 vertices, a few steps of each scheme.
"$exe" generate icosphere --level 6 --noise 0.02 --seed 3 -o big.ply >/dev/null
run fair_big_vector      fair big.ply -o fair_big_vector.ply --feature-size 0 --max-steps 4
run fair_big_semi        fair big.ply -o fair_big_semi.ply --feature-size 0 --scheme semi-implicit --max-steps 4
run fair_big_explicit    fair big.ply -o fair_big_explicit.ply --feature-size 0 --scheme explicit --max-steps 40
run fair_big_amount      fair big.ply -o fair_big_amount.ply   # the default amount: incomplete-Cholesky CG
rm -f big.ply
run curvature            curvature "$root/data/bunny.ply" -o curvature.ply
run curvature_paper      curvature "$root/data/bunny.ply" -o curvature_paper.ply --area barycentric --lambda-fix --ascii
run subdivide            subdivide "$root/data/bunny.ply" -o subdivide.ply --levels 1
for s in "$root"/meshlab_plugin/examples/*.mlx "$root"/tests/plugin/scripts/fairing_explicit_*.mlx; do
  name=run_$(basename "$s" .mlx)
  input="$root/data/bunny.ply"
  [[ $name == run_fill_holes ]] && input="$root/data/bunny_flank_hole.ply"
  run "$name" run -i "$input" -o "$name.ply" -s "$s"
done
rm -f noisy.ply torus.ply frame.ply faces.txt
sha256sum ./*.ply ./*.txt >SHA256SUMS
echo "golden-outputs: $(ls ./*.ply | wc -l) meshes, $(ls ./*.txt | wc -l) transcripts in $out"
