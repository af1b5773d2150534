#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The user's shading kept after a fairing (meshlab_plugin/view_shading.h), in MeshLab 2022.02 (or,
# with MESHLAB_TITLE="MeshLab 2025", 2025.07), done as a user does it: MESH opened (MeshLab shades a
# mesh without normals in its file by face), the project saved (File > Save Project As), Discrete
# Elastica Fairing applied at its defaults from the filter search (Ctrl+F, Apply), the project saved
# again. Both projects' shading (tests/plugin/gui_lib.sh `shading`) must be the same. Leaves
# OUT_DIR/shading_before.mlp, shading_after.mlp and shading_after.png (the screen after Apply).
# scripts/meshlab2022.sh and scripts/meshlab2025.sh run it in their roots, under Xvfb:
#   shading.sh MESH OUT_DIR
set -euo pipefail
mesh=$1 out=$2
source "$(dirname "$0")/../../tests/plugin/gui_lib.sh"   # fail, wait_display, wait_window, search_filter, save_project, same_shading
filter="Discrete Elastica Fairing"
wait_display
log=$out/meshlab-shading.log
meshlab "$mesh" >"$log" 2>&1 &
meshlab_pid=$! meshlab_log=$log
trap 'kill $meshlab_pid 2>/dev/null || true' EXIT
main=$(wait_window "^${MESHLAB_TITLE:-MeshLab 2022}" 30) || fail "no MeshLab window"
xdotool windowsize "$main" 1600 900 windowmove "$main" 0 0
sleep 3   # the mesh opens and the viewport paints
save_project "$main" "$out/shading_before.mlp"
search_filter "$main" "$filter"
sleep 1
# The parameters open in a dock (2022.02 on) with Apply focused and default; when the dock floats
# it is a window of the filter's name.
if dialog=$(wait_window "^$filter\$" 3); then xdotool windowfocus "$dialog"; sleep 0.3; fi
xdotool key space
deadline=$((SECONDS + 120))
until grep -q "Applied filter:\{0,1\} $filter" "$log"; do
  ((SECONDS < deadline)) || { import -window root "$out/shading_after.png"; fail "the filter did not finish in 120 s (see $log)"; }
  sleep 0.5
done
sleep 1.5   # the viewport repaints
import -window root "$out/shading_after.png"
save_project "$main" "$out/shading_after.mlp"
kept=$(same_shading "$out/shading_before.mlp" "$out/shading_after.mlp" "$filter")
echo "shading: $kept before and after $filter"
