#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The default fair at scale beside Debian's meshlabserver running 100 Taubin steps on the same file
# (docs/benchmarks.md, "Scale"): a 163,842-vertex icosphere with 3-D vertex noise of half an edge
# (`elastica generate icosphere --level 7`, bench/add_noise 0.5) and libcgal-demo's
# refined_elephant Loop-subdivided twice (bench/loop_energy.py's Loop step; 711,420 vertices) with
# noise of 0.2 edge. Each round runs Taubin ×100, the default `elastica fair IN -o OUT` and, on the
# sphere, `--feature-size 0`, one after another, each under /usr/bin/time -v; the ratio is taken
# round by round (paired), and the table prints the median over the rounds (min – max beside it).
# With --choices, also the factorisation-choice table (bench/solver_choice.cpp) on both files.
#
#   bench/scale.sh [--build DIR] [--rounds N] [--choices] [--only sphere|elephant]
#
# Needs meshlabserver, xvfb-run and the Python module (BUILD/python) with /usr/bin/python3.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build rounds=3 choices=0 only=
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --choices) choices=1; shift ;;
    --only) only=$2; shift 2 ;;
    *) echo "usage: bench/scale.sh [--build DIR] [--rounds N] [--choices] [--only sphere|elephant]" >&2; exit 2 ;;
  esac
done
bin=$build/bin
cache=${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}
samples=$(ls -d "$cache"/cgal-data-*/meshes 2>/dev/null | head -1)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

{ echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'
  for ((k = 0; k < 10; ++k)); do
    echo '<filter name="Taubin Smooth"><Param type="RichFloat" value="0.5" name="lambda"/><Param type="RichFloat" value="-0.53" name="mu"/><Param type="RichInt" value="10" name="stepSmoothNum"/><Param type="RichBool" value="false" name="Selected"/></filter>'
  done; echo '</FilterScript>'; } >"$tmp/taubin100.mlx"

"$bin/elastica" generate icosphere --level 7 -o "$tmp/ico7.ply" >/dev/null
"$bin/add_noise" "$tmp/ico7.ply" "$tmp/sphere.ply" 0.5 1
PYTHONPATH=$build/python:$root/bench /usr/bin/python3 -c "
import elastica
from loop_energy import loop_subdivide
V, F = elastica.read('$samples/refined_elephant.off')
for _ in range(2):
    V, F = loop_subdivide(V, F)
elastica.write('$tmp/elephant2.ply', V, F)"
"$bin/add_noise" "$tmp/elephant2.ply" "$tmp/elephant.ply" 0.2 1

timed() {  # OUT-PREFIX COMMAND... -> "wall_s peak_MB" (the command's own output to OUT-PREFIX.log)
  local prefix=$1; shift
  /usr/bin/time -v "$@" >"$prefix.log" 2>"$prefix.time" || { echo "scale: failed: $*" >&2; cat "$prefix.time" >&2; exit 1; }
  awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = 60 * s + t[i]}
              /Maximum resident set size/ {m = $2 / 1024} END {printf "%.2f %.0f\n", s, m}' "$prefix.time"
}
stats() {  # numbers on stdin -> "median (min – max)"
  sort -g | awk '{v[NR] = $1} END {m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2;
                  if (NR > 1) printf "%.2f (%.2f – %.2f)", m, v[1], v[NR]; else printf "%.2f", m}'
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| file | vertices | command | wall s | peak MB | ÷ Taubin wall (paired) | peak ÷ Taubin |"
echo "|---|---:|---|---:|---:|---:|---:|"
for name in sphere elephant; do
  [[ -z $only || $only == "$name" ]] || continue
  in=$tmp/$name.ply
  vertices=$(PYTHONPATH=$build/python /usr/bin/python3 -c "import elastica; print(f'{len(elastica.read(\"$in\")[0]):,}')")
  commands=("default" "")
  [[ $name == sphere ]] && commands+=("--feature-size 0" "--feature-size 0")
  : >"$tmp/taubin.wall"; : >"$tmp/taubin.peak"
  for c in default fs0; do : >"$tmp/$c.wall"; : >"$tmp/$c.peak"; : >"$tmp/$c.ratio"; : >"$tmp/$c.peakratio"; done
  for ((r = 0; r < rounds; ++r)); do
    read -r tw tp < <(timed "$tmp/t" xvfb-run -a meshlabserver -i "$in" -o "$tmp/taubin.ply" -s "$tmp/taubin100.mlx")
    echo "$tw" >>"$tmp/taubin.wall"; echo "$tp" >>"$tmp/taubin.peak"
    for c in default fs0; do
      [[ $c == fs0 && $name != sphere ]] && continue
      extra=(); [[ $c == fs0 ]] && extra=(--feature-size 0)
      read -r w p < <(timed "$tmp/e" "$bin/elastica" fair "$in" -o "$tmp/out.ply" "${extra[@]}")
      echo "$w" >>"$tmp/$c.wall"; echo "$p" >>"$tmp/$c.peak"
      awk -v a="$w" -v b="$tw" 'BEGIN {print a / b}' >>"$tmp/$c.ratio"
      awk -v a="$p" -v b="$tp" 'BEGIN {print a / b}' >>"$tmp/$c.peakratio"
    done
  done
  echo "| $name | $vertices | \`meshlabserver -i IN -o OUT -s taubin100.mlx\` | $(stats <"$tmp/taubin.wall") | $(stats <"$tmp/taubin.peak") | 1 | 1 |"
  for c in default fs0; do
    [[ -s $tmp/$c.wall ]] || continue
    label='`elastica fair IN -o OUT`'; [[ $c == fs0 ]] && label='`elastica fair IN -o OUT --feature-size 0`'
    echo "| $name | $vertices | $label | $(stats <"$tmp/$c.wall") | $(stats <"$tmp/$c.peak") | **$(stats <"$tmp/$c.ratio")** | $(stats <"$tmp/$c.peakratio") |"
  done
done
echo
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

if ((choices)); then
  echo
  echo "| option | rows | fill | flops | analyse s | factorise s | solve s (3 columns) | CG iterations | residual | peak MB |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for name in sphere elephant; do
    [[ -z $only || $only == "$name" ]] || continue
    for o in two-ring-simplicial two-ring-amd two-ring-supernodal block-simplicial one-ring-pcg incomplete-pcg one-ring-complex; do
      "$bin/solver_choice" "$tmp/$name.ply" "$o" || echo "| $o | failed |"
    done
  done
  echo "(mannequin-devil, slivers:)"
  for o in two-ring-simplicial one-ring-pcg incomplete-pcg one-ring-complex; do
    "$bin/solver_choice" "$samples/mannequin-devil.off" "$o" 2>&1 || echo "| $o | failed |"
  done
fi
