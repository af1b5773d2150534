#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# I/O benchmark (not a test): `elastica curvature IN.ply -o OUT.ply` end to end (read, check,
# H/K/E, write) against Debian's `meshlabserver -i IN.ply -o OUT.ply` (read + write, under
# xvfb-run: it needs an X server, whose start-up is in its time) on the same binary PLY, at
# 655,362 and 2,621,442 vertices (icosphere level 8, and that subdivided once).
#
#   bench/io_bench.sh BUILD_BIN_DIR [RUNS] [WORKDIR]     # RUNS per command and size (default 5)
#
# The two commands run in turn (A B A B ...) after one warm-up each, so a drift in the machine's
# speed hits both; each run is timed by /usr/bin/time -v (wall seconds, peak resident set). Prints
# min / median / max per command and the ratio of medians, with the machine's load average: quote
# the medians and the ratios of one run.
set -euo pipefail
bin=${1:?usage: io_bench.sh BUILD_BIN_DIR [RUNS] [WORKDIR]}
runs=${2:-5}
work=${3:-$(mktemp -d /tmp/elastica-io-bench.XXXXXX)}
exe=$(cd "$bin" && pwd)/elastica
[[ -x "$exe" ]] || { echo "io_bench: no elastica in $bin" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "io_bench: /usr/bin/time missing (Debian package 'time', scripts/setup.sh)" >&2; exit 1; }
command -v meshlabserver >/dev/null && command -v xvfb-run >/dev/null ||
  { echo "io_bench: needs meshlabserver and xvfb-run (Debian packages meshlab, xvfb)" >&2; exit 1; }
mkdir -p "$work"
cd "$work"

[[ -f ico8.ply ]] || "$exe" generate icosphere --level 8 -o ico8.ply >/dev/null
[[ -f ico9.ply ]] || "$exe" subdivide ico8.ply -o ico9.ply >/dev/null

# One timed run: "WALL_SECONDS PEAK_KB" on stdout; the command's own output is discarded.
timed() {
  local log
  log=$(mktemp)
  /usr/bin/time -v -o "$log" "$@" >/dev/null 2>&1 || { echo "io_bench: failed: $*" >&2; cat "$log" >&2; exit 1; }
  awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + t[i] }
              /Maximum resident set size/ { kb = $2 }
              END { printf "%.3f %d\n", s, kb }' "$log"
  rm -f "$log"
}

# min median max of numbers on stdin.
stats() { sort -g | awk '{ v[NR] = $1 } END { m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2;
                                              printf "%s %s %s\n", v[1], m, v[NR] }'; }

printf 'load average before: %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '%s, %s cores, %s runs each\n\n' "$(uname -m)" "$(nproc)" "$runs"
printf '%-10s %-14s %-22s %-22s\n' vertices command "wall s (min/med/max)" "peak MB (min/med/max)"
for mesh in ico8 ico9; do
  vertices=$(head -c 400 "$mesh.ply" | awk '/^element vertex/ { print $3; exit }')
  ours=(nice -n 0 "$exe" curvature "$mesh.ply" -o "$work/out_elastica.ply")
  theirs=(xvfb-run -a meshlabserver -i "$mesh.ply" -o "$work/out_meshlab.ply")
  timed "${ours[@]}" >/dev/null   # warm-up: the file in the page cache for both
  timed "${theirs[@]}" >/dev/null
  : >a.txt
  : >b.txt
  for ((i = 0; i < runs; ++i)); do
    timed "${ours[@]}" >>a.txt
    timed "${theirs[@]}" >>b.txt
  done
  read -r aw0 aw aw1 < <(cut -d' ' -f1 a.txt | stats)
  read -r bw0 bw bw1 < <(cut -d' ' -f1 b.txt | stats)
  read -r am0 am am1 < <(cut -d' ' -f2 a.txt | awk '{ print $1 / 1024 }' | stats)
  read -r bm0 bm bm1 < <(cut -d' ' -f2 b.txt | awk '{ print $1 / 1024 }' | stats)
  printf '%-10s %-14s %-22s %-22s\n' "$vertices" "elastica" "$aw0 / $aw / $aw1" "$(printf '%.0f / %.0f / %.0f' "$am0" "$am" "$am1")"
  printf '%-10s %-14s %-22s %-22s\n' "$vertices" "meshlabserver" "$bw0 / $bw / $bw1" "$(printf '%.0f / %.0f / %.0f' "$bm0" "$bm" "$bm1")"
  awk -v a="$aw" -v b="$bw" -v m="$am" -v n="$bm" -v v="$vertices" \
    'BEGIN { printf "%-10s ratio elastica / meshlabserver (medians): time %.2fx (target <= 1.5x), peak memory %.2fx (target <= 2x)\n\n", v, a / b, m / n }'
done
printf 'load average after: %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
