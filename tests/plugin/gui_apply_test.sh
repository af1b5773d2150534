#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# GUI test after Apply: Debian's MeshLab, with the freshly built plugin in a private prefix, opens
# a mesh, the filter search (Ctrl+F) opens one of our filters' dialog, Apply runs it at its
# defaults, and File > Export Mesh As writes the result. Asserted, per case: MeshLab's log (its
# "LOG: level text" lines on stderr) has our summary lines, "Applied filter", no failure and no
# warning; the exported PLY has the vertex and face counts the log reports and only the
# attributes the filter wrote (MeshLab's export dialog ticks what the mesh carries). Kept per case
# in ARTEFACT_DIR: before_CASE.png (the mesh as opened), apply_CASE.png (the screen after Apply), export_CASE.png (the export options),
# and meshlab_CASE.log; with SHADING=1 (the fairing case), shading_before_CASE.mlp and
# shading_after_CASE.mlp, the projects saved before and after Apply, whose shading must be the same.
# Run under `scripts/with-xvfb.sh -s "-screen 0 1920x1080x24"` (ctest does). Usage:
#   gui_apply_test.sh PREFIX_SCRIPT PLUGIN.so PREFIX_DIR DATA_DIR ARTEFACT_DIR ELASTICA_EXE
set -euo pipefail
prefix_script=$1 plugin=$2 prefix=$3 data=$4 artefacts=$5 elastica=$6
source "$(dirname "$0")/gui_lib.sh"   # fail, wait_window, gui_check_display, gui_install_plugin
gui_check_display
gui_install_plugin

# Waits up to $2 seconds for a line matching $1 in file $3.
wait_log() {
  local deadline=$((SECONDS + $2))
  while ((SECONDS < deadline)); do
    grep -q -- "$1" "$3" && return 0
    sleep 0.5
  done
  return 1
}
# The PLY header of $1 (ASCII lines up to end_header, also of a binary file).
ply_header() { LC_ALL=C sed -n '1,/^end_header/p' "$1"; }
ply_count() { ply_header "$1" | awk -v e="$2" '$1 == "element" && $2 == e { print $3 }'; }

# run_case CASE MESH FILTER: opens MESH, applies FILTER at its defaults, exports to $out.
run_case() {
  local case=$1 mesh=$2 filter=$3
  log=$artefacts/meshlab_$case.log out=$artefacts/export_$case.ply
  local shot=$artefacts/apply_$case.png options=$artefacts/export_$case.png
  rm -f "$log" "$out" "$shot" "$options"
  HOME=$home "$prefix/bin/meshlab" "$mesh" >"$log" 2>&1 &
  meshlab_pid=$! meshlab_log=$log
  local main dialog save
  main=$(wait_window '^MeshLab 20' 20) || fail "$case: MeshLab's main window did not appear in 20 s"
  wait_log "Opened mesh" 10 "$log" || fail "$case: the mesh did not open (see $log)"
  xdotool windowsize "$main" 1280 1024 windowmove "$main" 0 0
  sleep 1.5   # let the viewport paint
  import -window root "$artefacts/before_$case.png"
  ((${SHADING:-0})) && save_project "$main" "$artefacts/shading_before_$case.mlp"
  search_filter "$main" "$filter"
  dialog=$(wait_window "^$filter\$" 10) || { import -window root "$shot"; fail "$case: no '$filter' dialog (screen: $shot)"; }
  xdotool windowmove "$dialog" 1290 0   # beside the main window, so the viewport shows
  sleep 0.5
  xdotool windowfocus "$dialog"
  sleep 0.3
  xdotool key space   # the dialog gives Apply the focus
  wait_log "Applied filter $filter\|Filter failed" 90 "$log" || { import -window root "$shot"; fail "$case: the filter did not finish in 90 s"; }
  sleep 1.5   # let the viewport repaint
  import -window root "$shot"
  grep -q "Filter failed" "$log" && fail "$case: the filter failed: $(grep 'LOG: ' "$log" | tail -n 3)"
  grep -q "^LOG: 1 " "$log" && fail "$case: a warning was logged: $(grep '^LOG: 1 ' "$log")"
  if ((${SHADING:-0})); then
    save_project "$main" "$artefacts/shading_after_$case.mlp"
    local kept
    kept=$(same_shading "$artefacts/shading_before_$case.mlp" "$artefacts/shading_after_$case.mlp" "$case")
    echo "--- $case: shading $kept before and after"
  fi
  # Export: the file dialog takes a path, the options dialog is accepted as proposed.
  xdotool windowfocus "$main"
  sleep 0.3
  xdotool key ctrl+shift+e
  save=$(wait_window '^Save ".*" Layer' 10) || fail "$case: no export file dialog"
  sleep 0.5
  xdotool type --delay 10 "$out"
  xdotool key Return
  wait_window "^Choose Saving Options" 10 >/dev/null || { import -window root "$options"; fail "$case: no export options dialog"; }
  sleep 0.5
  import -window root "$options"
  xdotool key Return
  wait_log "Saved Mesh" 10 "$log" || fail "$case: the mesh was not saved"
  kill "$meshlab_pid" 2>/dev/null || true
  wait "$meshlab_pid" 2>/dev/null || true
  meshlab_pid=
  [[ -s $out ]] || fail "$case: $out is empty"
  echo "--- $case: $(grep -c '^LOG: 2 ' "$log") filter log lines; exported $(ply_count "$out" vertex) vertices, $(ply_count "$out" face) faces"
}
expect_log() { grep -q -- "$1" "$log" || fail "$case: no log line matching '$1' (see $log)"; }
expect_no_property() {
  ! ply_header "$out" | grep -q "^property .* $1\$" || fail "$case: the export carries '$1' (header: $(ply_header "$out" | tr '\n' ' '))"
}

# Fairing the whole bunny at the defaults (the mesh's own fairing amount, app/fairing_amount.h):
# a fairer bunny with its vertices and faces kept; positions and normals change, no colour or
# quality is added; the log says the amount and how far the surface moved. The view's shading
# (Face: the bunny has no normals in its file) is the same after Apply.
case=fairing; SHADING=1 run_case fairing "$data/bunny.ply" "Discrete Elastica Fairing"
expect_log "Discrete Elastica Fairing: 1839 -> 1839 vertices, [0-9]* steps in .* (faired to the feature size)"
expect_log "Discrete Elastica Fairing: fairing amount: feature size [0-9.e+-]* ([0-9.e+-]* % of the bounding-box diagonal, [0-9.]* mean edge lengths"
expect_log "Discrete Elastica Fairing: the vertices moved by [0-9.e+-]* % of the bounding-box diagonal"
[[ $(ply_count "$out" vertex) == 1839 ]] || fail "fairing: exported $(ply_count "$out" vertex) vertices, not the input's 1839"
for p in red quality; do expect_no_property $p; done

# Fairing a selection: the bunny's flank hole filled flat by `elastica fill --stop-after refinement`,
# whose new faces come selected (PLY face flags); the dialog's 'Affect only selected faces' is then
# on, and after Apply the selection is the faired patch as remeshed (apply_fairing_selected.png).
"$elastica" fill "$data/bunny_flank_hole.ply" -o "$artefacts/bunny_flat_patch.ply" --stop-after refinement >/dev/null
case=fairing_selected; run_case fairing_selected "$artefacts/bunny_flat_patch.ply" "Discrete Elastica Fairing"
expect_log "Discrete Elastica Fairing: total curvature energy "
expect_log "Discrete Elastica Fairing: region energy [-0-9.e+]* -> [-0-9.e+]* (the selected faces' vertices"

# Filling the bunny's flank hole: faces appended, the new ones selected, no colour or quality.
case=fill; run_case fill "$data/bunny_flank_hole.ply" "Fill Holes with Discrete Elastica"
expect_log "Fill Holes with Discrete Elastica: filled 1 of 1 holes"
(($(ply_count "$out" face) > 3459)) || fail "fill: $(ply_count "$out" face) faces, not more than the input's 3459"
for p in red quality; do expect_no_property $p; done

# Filling a mesh without holes: said plainly; nothing changes (counts as the input's).
case=fill_closed; run_case fill_closed "$data/bunny.ply" "Fill Holes with Discrete Elastica"
expect_log "the mesh has no holes: nothing to fill; the mesh and its selection are unchanged"
[[ $(ply_count "$out" vertex) == 1839 && $(ply_count "$out" face) == 3674 ]] ||
  fail "fill_closed: exported $(ply_count "$out" vertex)/$(ply_count "$out" face), not the input's 1839/3674"

# Curvature: H into quality and colour, which the export then offers and writes.
case=curvature; run_case curvature "$data/bunny.ply" "Discrete Elastica Curvature"
expect_log "Discrete Elastica Curvature: total curvature energy E = "
ply_header "$out" | grep -q "^property .* quality$" || fail "curvature: no vertex quality exported"
ply_header "$out" | grep -q "^property .* red$" || fail "curvature: no vertex colour exported"

echo "PASS: each filter applied in MeshLab; screenshots in $artefacts (apply_*.png, export_*.png)"
