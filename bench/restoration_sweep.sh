#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# docs/restoration.md's hole-size sweep: on three real scans from Debian's libcgal-demo data
# archive (the Stanford bunny as CGAL ships it, the armadillo, a refined elephant), geodesic-disc
# holes of 20–200 border edges in the scans as shipped, of 400 in the scans refined once (1-to-4 at
# edge midpoints), of 800 in the scans refined twice and of 2,000 in the armadillo and the elephant
# refined three times (1.7 and 2.8 M vertices; these rows take most of the run's half hour), each
# filled by `elastica fill`'s default
# and by CGAL's triangulate_refine_and_fair_hole
# (bench/restoration_sweep.cpp). Rewrites the part of docs/restoration.md between the
# `<!-- sweep:begin -->` and `<!-- sweep:end -->` markers.
#
#   bench/restoration_sweep.sh [BUILD_DIR]     (default: build; needs libcgal-dev at configure time)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
bin=$build/bin/restoration_sweep
[[ -x $bin ]] || { echo "restoration_sweep.sh: build $build first (cmake --build $build --target restoration_sweep)" >&2; exit 1; }
grep -q ELASTICA_HAVE_CGAL "$build/bench/CMakeFiles/restoration_sweep.dir/flags.make" 2>/dev/null ||
  { echo "restoration_sweep.sh: $build has no CGAL comparison (apt-get install libcgal-dev, then configure again)" >&2; exit 1; }

# The scans: scripts/setup.sh keeps them with the other sample meshes (Debian's libcgal-demo).
samples=$(sed -n 's/^CGAL_SAMPLE_MESH_DIR:PATH=//p' "$build/CMakeCache.txt")
for m in bunny00.off armadillo.off refined_elephant.off; do
  [[ -f $samples/$m ]] || { echo "restoration_sweep.sh: no $m in '$samples' (run scripts/setup.sh)" >&2; exit 1; }
done

# name  mesh  centre (a point on the surface: the disc grows around the vertex nearest it)  2000
# The last column says whether the scan gets a 2,000-edge row: the bunny's disc wraps over most of
# its body from 200 edges on (truth→patch 15 %), and at 2,000 edges in the bunny refined three times
# (2.4 M vertices) the distances alone ran for more than 20 minutes without finishing.
cases=(
  "bunny $samples/bunny00.off -0.337074 0.301293 -0.010123 no"
  "armadillo $samples/armadillo.off 1.14795 84.5526 -17.0774 yes"
  "elephant $samples/refined_elephant.off 0.0772 -0.1207 0.2918 yes"
)
table=$(mktemp)
{
  echo "| mesh | vertices | border edges | new vertices | ms | smallest angle | border allows | folded faces | patch→truth RMS | truth→patch RMS | CGAL new vertices | CGAL ms | time ÷ CGAL's | CGAL smallest angle | CGAL folded faces | CGAL patch→truth | CGAL truth→patch |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for c in "${cases[@]}"; do
    read -r name mesh x y z big <<<"$c"
    "$bin" "$mesh" --center "$x" "$y" "$z" --edges 20,50,100,200 --name "$name"
    "$bin" "$mesh" --center "$x" "$y" "$z" --edges 400 --subdivide 1 --name "$name"
    "$bin" "$mesh" --center "$x" "$y" "$z" --edges 800 --subdivide 2 --name "$name"
    [[ $big == yes ]] && "$bin" "$mesh" --center "$x" "$y" "$z" --edges 2000 --subdivide 3 --name "$name"
  done
} >"$table"
commit=$(git rev-parse --short HEAD)
section=$(mktemp)
{
  echo "<!-- sweep:begin -->"
  echo "Made by \`bench/restoration_sweep.sh\` at commit $commit, one run, on a shared 2-core machine (times: the best"
  echo "of the runs that fit in a second, one run above it; distances in % of the bounding-box diagonal)."
  echo
  cat "$table"
  echo "<!-- sweep:end -->"
} >"$section"
scan=$(mktemp)
{
  echo "<!-- scan:begin -->"
  echo "Made by \`bench/restoration_sweep.sh\` (\`scan_holes_bench\`) at commit $commit, one run:"
  echo
  "$build/bin/scan_holes_bench" --header
  "$build/bin/scan_holes_bench" "$samples/bunny00.off" --subdivide 3 --holes 200 --name "bunny00, refined 3 times"
  echo "<!-- scan:end -->"
} >"$scan"
python3 - "$section" "$scan" <<'EOF'
import re, sys
doc = open("docs/restoration.md").read()
for path, name in ((sys.argv[1], "sweep"), (sys.argv[2], "scan")):
    new = open(path).read().rstrip("\n")
    pattern = re.compile(r"<!-- %s:begin -->.*?<!-- %s:end -->" % (name, name), re.S)
    if not pattern.search(doc):
        sys.exit("restoration_sweep.sh: docs/restoration.md has no %s markers" % name)
    doc = pattern.sub(lambda m: new, doc)
open("docs/restoration.md", "w").write(doc)
EOF
rm -f "$table" "$section" "$scan"
echo "restoration_sweep.sh: rewrote docs/restoration.md's sweep and big-scan sections"
