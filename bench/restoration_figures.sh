#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The pictures of docs/restoration.md: each real-mesh cut of the restoration benchmark, before and
# after filling with CGAL's triangulate_refine_and_fair_hole and with elastica, coloured by mean
# curvature (red low, blue high; same 2–98 % ramp rule for every panel) with the triangle edges,
# seen along the removed region's mean normal.
#
#   bench/restoration_figures.sh [BUILD_DIR]     (default: build)
#
# Needs a build with restoration_bench (CGAL panels only if libcgal-dev was found at configure
# time), the sample meshes of scripts/setup.sh, and bench/render_mesh.sh's f3d + xvfb. Writes
# docs/images/restoration_<mesh>.png (three panels: hole, CGAL, elastica).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
bin=$build/bin
[[ -x $bin/restoration_bench && -x $bin/elastica ]] || { echo "restoration_figures: build $build first" >&2; exit 1; }
samples=$(sed -n 's/^CGAL_SAMPLE_MESH_DIR:PATH=//p' "$build/CMakeCache.txt")
[[ -f $samples/elephant.off ]] || { echo "restoration_figures: no sample meshes (run scripts/setup.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p docs/images

# name  mesh  centre  radius  camera position  view-up
cases=(
  "bunny data/bunny.ply 0.82,2.95,3.81 2.0 -0.23,4.14,17.7 0,1,0"
  "elephant $samples/elephant.off -0.084,-0.119,-0.148 0.17 -0.142,0.331,-1.04 0,1,0"
)
for c in "${cases[@]}"; do
  read -r name mesh centre radius camera up <<<"$c"
  mkdir -p "$work/$name"
  "$bin/restoration_bench" "$mesh" --center ${centre//,/ } --radius "$radius" --write-dir "$work/$name" >"$work/$name/table.md"
  panels=()
  for m in holed CGAL_triangulate_refine_and_fair_hole elastica__semi_implicit; do
    [[ -f $work/$name/$m.ply ]] || continue
    "$bin/elastica" curvature "$work/$name/$m.ply" -o "$work/$name/${m}_h.ply" >/dev/null
    bench/render_mesh.sh "$work/$name/${m}_h.ply" "$work/$name/$m.png" --size 360,300 --edges -- \
      --camera-position="$camera" --camera-focal-point="$centre" --camera-view-up="$up" --up=+Y
    panels+=("$work/$name/$m.png")
  done
  convert "${panels[@]}" +append -colors 192 "docs/images/restoration_$name.png"
  echo "wrote docs/images/restoration_$name.png (${#panels[@]} panels)"
done
