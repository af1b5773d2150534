#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Elastica's fairing amount (`fair --feature-size F`) as a denoiser, beside MeshLab's Taubin and HC
# Laplacian smoothing run by Debian's meshlabserver, on libcgal-demo scans with 3-D vertex noise
# (bench/add_noise: uniform in a ball of AMOUNT × the mean edge length). Distances are RMS, from
# points sampled on the result to the clean scan and back (bench/mesh_distance), as fractions of the
# clean scan's bounding-box diagonal. One run each. Prints a Markdown table; with --pictures DIR,
# also renders the clean, noisy, best-MeshLab and elastica meshes of the first scan there.
#
#   bench/denoise.sh [--build DIR] [--noise "0.5 0.2"] [--pictures DIR] [MESH...]
#
# Default meshes: bull and dino from the setup cache. Needs meshlabserver, xvfb-run, f3d.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build noises="0.5 0.2" pictures=
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --noise) noises=$2; shift 2 ;;
    --pictures) pictures=$2; shift 2 ;;
    *) break ;;
  esac
done
cache=${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}
samples=$(ls -d "$cache"/cgal-data-*/meshes 2>/dev/null | head -1)
meshes=("$@")
[[ ${#meshes[@]} -gt 0 ]] || meshes=("$samples/bull.off" "$samples/dino.off")
bin=$build/bin
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

script() {  # NAME FILTER-XML REPEAT -> an .mlx applying the filter REPEAT times
  { echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'
    for ((k = 0; k < $3; ++k)); do echo "$2"; done; echo '</FilterScript>'; } >"$tmp/$1.mlx"
}
taubin='<filter name="Taubin Smooth"><Param type="RichFloat" value="0.5" name="lambda"/><Param type="RichFloat" value="-0.53" name="mu"/><Param type="RichInt" value="10" name="stepSmoothNum"/><Param type="RichBool" value="false" name="Selected"/></filter>'
hc='<filter name="HC Laplacian Smooth"/>'
for n in 1 5 10; do script "taubin$((10 * n))" "$taubin" "$n"; done
for n in 1 3 10; do script "hc$n" "$hc" "$n"; done

distance() {  # RESULT CLEAN -> "a→b b→a" (fractions of the diagonal)
  "$bin/mesh_distance" "$1" "$2" | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
print("%.2e %.2e" % (j["a_to_b"]["rms_per_diagonal"], j["b_to_a"]["rms_per_diagonal"]))'
}

echo "| scan | noise | result | RMS result→clean | RMS clean→result | steps, stop |"
echo "|---|---:|---|---:|---:|---|"
first=1
for mesh in "${meshes[@]}"; do
  name=$(basename "${mesh%.*}")
  for noise in $noises; do
    noisy=$tmp/$name-noisy.ply
    "$bin/add_noise" "$mesh" "$noisy" "$noise" 1
    row() { echo "| $name | $noise | $1 | $(distance "$2" "$mesh" | sed 's/ / | /') | $3 |"; }
    row "noisy input" "$noisy" ""
    best= bestSum=1
    for s in taubin10 taubin50 taubin100 hc1 hc3 hc10; do
      xvfb-run -a meshlabserver -i "$noisy" -o "$tmp/$s.ply" -s "$tmp/$s.mlx" >/dev/null 2>&1
      d=$(distance "$tmp/$s.ply" "$mesh")
      label=$([[ $s == taubin* ]] && echo "MeshLab Taubin, ${s#taubin} steps" || echo "MeshLab HC Laplacian ×${s#hc}")
      echo "| $name | $noise | $label | ${d/ / | } | |"
      sum=$(awk '{print $1 + $2}' <<<"$d")
      if awk "BEGIN {exit !($sum < $bestSum)}"; then best=$s bestSum=$sum; fi
    done
    diagonal=$("$bin/mesh_distance" "$mesh" "$mesh" | /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["diagonal"])')
    for f in 0.01 0.015 0.02 0.03 0.04; do  # fractions of the diagonal; --feature-size takes the length
      out=$("$bin/elastica" fair "$noisy" -o "$tmp/e$f.ply" --feature-size "$(awk "BEGIN {print $f * $diagonal}")" --max-seconds 60)
      steps=$(sed -n 's/.*: \([0-9]*\) steps in \([0-9.]*\) s (\([a-z_]*\)).*/\1 attempts, \2 s, \3/p' <<<"$out")
      row "elastica --feature-size $f × diagonal" "$tmp/e$f.ply" "$steps"
    done
    if [[ -n $pictures && $first == 1 ]]; then
      mkdir -p "$pictures"
      "$root/bench/render_mesh.sh" "$mesh" "$pictures/denoise_${name}_clean.png" >/dev/null
      "$root/bench/render_mesh.sh" "$noisy" "$pictures/denoise_${name}_noisy.png" >/dev/null
      "$root/bench/render_mesh.sh" "$tmp/$best.ply" "$pictures/denoise_${name}_meshlab_best.png" >/dev/null
      "$root/bench/render_mesh.sh" "$tmp/e0.03.ply" "$pictures/denoise_${name}_elastica_f0.03.png" >/dev/null
      echo "<!-- pictures: $name, noise $noise; best MeshLab: $best -->"
      first=0
    fi
  done
done
