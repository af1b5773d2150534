#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The default `elastica fair` on whole scans from Debian's libcgal-demo (the sample meshes
# scripts/setup.sh unpacks, plus any other file of that package's data/meshes given by path),
# beside another scheme, one run each, 60 s limit: attempts (rejected), seconds, stop reason,
# energy before and after, genus before and after, faces crossing after, and for genus 0 the
# radius spread about the least-squares sphere. Prints a Markdown table; with --page, also
# replaces the real-shapes section of docs/benchmarks.md (between its markers).
#
#   bench/real_shapes.sh [--page] [--build DIR] [--schemes "semi-implicit auto"] [MESH...]
#
# Default meshes: cow, dino, bull, knot1, elephant from the setup cache, and camel,
# ChineseDragon-10kv, homer, elk, femur if a full libcgal-demo data directory is given in
# CGAL_DATA (its meshes/ folder). Needs /usr/bin/python3 with NumPy (scripts/setup.sh installs it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build page=0 schemes="semi-implicit auto"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --page) page=1; shift ;;
    --build) build=$2; shift 2 ;;
    --schemes) schemes=$2; shift 2 ;;
    *) break ;;
  esac
done
cache=${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}
samples=$(ls -d "$cache"/cgal-data-*/meshes 2>/dev/null | head -1)
meshes=("$@")
if [[ ${#meshes[@]} -eq 0 ]]; then
  for m in cow dino bull knot1 elephant; do meshes+=("$samples/$m.off"); done
  if [[ -n ${CGAL_DATA:-} ]]; then
    for m in camel ChineseDragon-10kv homer elk femur; do meshes+=("$CGAL_DATA/meshes/$m.off"); done
  fi
fi
bin=$build/bin
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
measure() {  # FILE -> "genus crossings spread%" (spread only for genus 0)
  local q genus crossings
  q=$("$bin/mesh_check" "$1")
  genus=$(sed 's/.*"genus":\([0-9-]*\).*/\1/' <<<"$q")
  crossings=$(sed 's/.*"self_intersecting_faces":\([0-9]*\).*/\1/' <<<"$q")
  spread=$(/usr/bin/python3 "$root/bench/sphere_spread.py" "$1" 2>/dev/null || echo "?")
  [[ $genus == 0 ]] || spread="–"
  echo "$genus $crossings $spread"
}
table=$tmp/table.md
{
  echo "| mesh | vertices | scheme | attempts (rejected) | seconds | stop | E before → after | genus before → after | crossing faces after | spread % (genus 0) |"
  echo "|---|---:|---|---:|---:|---|---|---|---:|---:|"
  for f in "${meshes[@]}"; do
    name=$(basename "$f" .off)
    read -r g0 _ _ < <(measure "$f")
    nv=$(awk '!/^#/ && NF {n++; if (n == 2) {print $1; exit}}' "$f")
    for s in $schemes; do
      out=$tmp/$name-$s.ply
      "$bin/elastica" fair "$f" -o "$out" --feature-size 0 --scheme "$s" --max-seconds 60 --report "$tmp/r.json" >/dev/null 2>&1 || true
      row=$(/usr/bin/python3 -c '
import json,sys; r=json.load(open(sys.argv[1]))
print("%d (%d) | %.1f | %s | %.0f → %.2f" % (r["steps"], r["rejected_steps"], r["seconds"], r["stop"], r["energy_initial"], r["energy_output"]))' "$tmp/r.json")
      read -r g1 x1 sp1 < <(measure "$out")
      echo "| $name | $nv | $s | $row | $g0 → $g1 | $x1 | $sp1 |"
    done
  done
} >"$table"
cat "$table"
if ((page)); then
  doc=$root/docs/benchmarks.md
  commit=$(git -C "$root" rev-parse --short HEAD)
  {
    echo "<!-- real-shapes: written by bench/real_shapes.sh --page; do not edit by hand -->"
    cat <<'TEXT'
Whole closed scans from Debian's libcgal-demo, each faired by `elastica fair` with the
semi-implicit scheme (the default until issue 28) and with `auto`, today's default (the vector
scheme, or the semi-implicit one on meshes with handles and under 600 vertices per handle, and
where the vector scheme cannot take its first step: the femur). Attempts count refused steps too; E is the total curvature energy (a round
sphere: 8π ≈ 25.13); *crossing faces* is vcglib's self-intersection test on the output (the cow's
input already has 137); *spread* is (max − min)/r of the vertices' distances to the least-squares
sphere. Stops: `converged` (the shape stopped changing at the flow's time scale), `self_contact`
(the surface pressed against itself for 10 steps, or only crossing itself would lower E),
`stalled`, `max_seconds`. Genus −1: the genus formula does not apply (the 10k dragon is one
component with two triangular holes).

TEXT
    echo "Commit $commit (with the working tree's changes, if any), $(date -u +%Y-%m-%dT%H:%MZ), load average at the end of the run $(cut -d' ' -f1-3 /proc/loadavg); one run per row, 60 s limit, \`elastica fair IN -o OUT --feature-size 0 --scheme S --max-seconds 60\` (to the limit shape)."
    echo
    cat "$table"
    echo "<!-- /real-shapes -->"
  } >"$tmp/section.md"
  /usr/bin/python3 - "$doc" "$tmp/section.md" <<'PY'
import sys, re
doc, sec = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
start, end = "<!-- real-shapes:", "<!-- /real-shapes -->"
if start in text:
    a = text.index(start); b = text.index(end) + len(end)
    text = text[:a] + sec.rstrip("\n") + text[b:]
else:
    text = text.rstrip("\n") + "\n\n## Real shapes: the default fair on libcgal-demo scans\n\n" + sec
open(doc, "w").write(text)
PY
fi
