#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# MeshLab 2022.02's (MESHLAB_TITLE="MeshLab 2025": 2025.07's) window with MESH loaded and Filters > Smoothing, Fairing and Deformation open,
# saved as OUT.png (scripts/meshlab2022.sh --screenshot runs it in the trixie root, under Xvfb).
#   screenshot.sh MESH OUT.png
set -euo pipefail
mesh=$1 out=$2
fail() { printf 'screenshot: %s\n' "$*" >&2; exit 1; }
meshlab "$mesh" >/tmp/meshlab.log 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
main=
for _ in $(seq 150); do
  main=$(xdotool search --name "${MESHLAB_TITLE:-MeshLab 2022}" 2>/dev/null | head -n1) && [[ -n "$main" ]] && break
  kill -0 $pid 2>/dev/null || { cat /tmp/meshlab.log >&2; fail "meshlab exited"; }
  sleep 0.2
done
[[ -n "$main" ]] || fail "no MeshLab window"
xdotool windowsize "$main" 1600 900 windowmove "$main" 0 0
sleep 3
xdotool windowfocus "$main"
sleep 0.5
# Tilt the view (a drag in the viewport) so that the torus shows its hole, then move it right of the menu
# (a drag with Ctrl pans).
xdotool mousemove 760 300 mousedown 1 mousemove 760 340 mousemove 760 380 mousemove 760 420 mouseup 1
sleep 0.5
xdotool mousemove 700 600 keydown ctrl mousedown 1 mousemove 800 600 mousemove 900 600 mousemove 1000 600 mouseup 1 keyup ctrl
sleep 1
xdotool key alt+l          # Fi&lters
sleep 1
for _ in $(seq "${SMOOTHING_ITEM:-7}"); do xdotool key Down; sleep 0.1; done
xdotool key Right          # the submenu
sleep 1.5
import -window root "$out"
