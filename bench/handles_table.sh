#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `elastica fair --feature-size 0` (to the limit shape) on closed meshes with handles (issue 40), one run per row: attempts
# (refused), seconds, stop, E, E of the output Loop-subdivided once (bench/loop_energy.py) and
# its gap, the most vertices a stage reached (and the output's, if fewer), faces crossing after
# (bench/mesh_check: vcglib's test), genus before → after. Prints a Markdown table.
#
#   bench/handles_table.sh [--build DIR] [--label NAME] [--max-seconds S] MESH...
#
# --label names the build in its column (e.g. "before", "after"); --build is its build directory
# (bin/elastica, bin/mesh_check, python/). Needs /usr/bin/python3 with NumPy.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build label=this seconds=120
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --label) label=$2; shift 2 ;;
    --max-seconds) seconds=$2; shift 2 ;;
    *) break ;;
  esac
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { "$build/bin/mesh_check" "$1"; }
field() { /usr/bin/python3 -c 'import json,sys; print(json.loads(sys.argv[1])[sys.argv[2]])' "$1" "$2"; }
echo "| mesh | genus | input vertices | build | attempts (refused) | seconds | stop | E | Loop-1 E | vertices reached | crossing faces | genus after |"
echo "|---|---:|---:|---|---:|---:|---|---:|---:|---:|---:|---:|"
for f in "$@"; do
  name=$(basename "$f" .off)
  q=$(check "$f")
  out=$tmp/$name.off
  "$build/bin/elastica" fair "$f" -o "$out" --feature-size 0 --max-seconds "$seconds" --report "$tmp/r.json" >/dev/null 2>&1 || true
  loop=$(PYTHONPATH=$build/python /usr/bin/python3 "$root/bench/loop_energy.py" "$out" 1 | awk '/level 1/ {print $NF}')
  q1=$(check "$out")
  row=$(/usr/bin/python3 - "$tmp/r.json" "$loop" "$(field "$q1" vertices)" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
loop, nout = float(sys.argv[2]), int(sys.argv[3])
e = r["energy_final"]
reached = max(s["vertices"] for s in r["stages"])
v = f"{reached:,}" + (f" ({nout:,})" if nout != reached else "")
print(f'{r["steps"]} ({r["rejected_steps"]}) | {r["seconds"]:.1f} | {r["stop"]} | {e:.2f} | {loop:.2f} ({100 * (loop - e) / e:+.1f} %) | {v}')
PY
)
  echo "| $name | $(field "$q" genus) | $(field "$q" vertices) | $label | $row | $(field "$q1" self_intersecting_faces) | $(field "$q1" genus) |"
done
