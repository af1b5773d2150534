#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders a mesh to a PNG headless, with Debian's f3d under xvfb-run (for the pictures in docs/).
#
#   bench/render_mesh.sh IN.ply OUT.png [--view iso|top|front|side] [--size W,H] [--edges]
#                        [--azimuth DEG] [--elevation DEG] [-- EXTRA f3d OPTIONS...]
#
# A PLY with vertex colours (`elastica fair|fill|curvature ... --color-by-mean-curvature`) is drawn
# in those colours: f3d 1.3.1 does not read the `quality` or `mean_curvature` properties, so the
# colour ramp written by elastica is the curvature picture. VTK treats RGBA colours as possibly
# translucent, so depth peeling is on (without it, back faces show through in patches).
# Z is up; --view picks the camera direction (iso: 20° azimuth, 35° elevation; --azimuth and
# --elevation override). --edges draws the triangle edges. Needs f3d, xvfb and xauth
# (scripts/setup.sh).
set -euo pipefail

usage() { sed -n '3,15p' "$0" | sed 's/^# \{0,1\}//'; }
die() { printf 'render_mesh: error: %s\n' "$*" >&2; exit 1; }

[[ $# -ge 2 ]] || { usage >&2; exit 2; }
in=$1 out=$2
shift 2
view=iso size=800,600 edges=0 azimuth="" elevation=""
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --view) view=${2:?--view needs a value}; shift 2 ;;
    --size) size=${2:?--size needs W,H}; shift 2 ;;
    --edges) edges=1; shift ;;
    --azimuth) azimuth=${2:?--azimuth needs degrees}; shift 2 ;;
    --elevation) elevation=${2:?--elevation needs degrees}; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) usage; exit 0 ;;
    *) die "unknown option '$1' (try --help)" ;;
  esac
done
[[ -f "$in" ]] || die "no such file: $in"
command -v f3d >/dev/null || die "f3d not found (scripts/setup.sh installs it)"
command -v xvfb-run >/dev/null || die "xvfb-run not found (scripts/setup.sh installs xvfb)"

case "$view" in
  iso) az=20 el=35 ;;
  top) az=0 el=89 ;;   # 90 would make the view-up vector parallel to the view direction
  front) az=0 el=0 ;;
  side) az=90 el=0 ;;
  *) die "unknown view '$view' (iso, top, front or side)" ;;
esac
az=${azimuth:-$az} el=${elevation:-$el}

opts=(--output="$out" --resolution="$size" --up=+Z --camera-azimuth-angle="$az" --camera-elevation-angle="$el"
      --roughness=0.8 --fxaa --quiet)
# The PLY header is text up to end_header; only vertex colours decide the colouring.
if head -c 4096 "$in" | sed '/end_header/q' | grep -qa '^property uchar red'; then
  opts+=(--scalars --comp=-2 --depth-peeling)
fi
((edges)) && opts+=(--edges)

rm -f "$out"
xvfb-run -a f3d "${opts[@]}" "${extra[@]}" "$in" >/dev/null 2>&1 || die "f3d failed on $in"
[[ -s "$out" ]] || die "f3d wrote no image for $in"
