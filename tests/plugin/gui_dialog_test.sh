#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# GUI test of the filter dialogs: Debian's MeshLab, with the freshly built plugin in a private
# prefix, opens a mesh; for each filter the filter search (Ctrl+F) opens its parameter dialog, which
# must appear as a window of the filter's name; then Help is shown and every help paragraph must
# fit: dialog_probe.so (preloaded into MeshLab, see dialog_probe.cpp) clicks Help and measures each
# word-wrapped label against the height its text needs at its width. MeshLab caps the dialog at 2/3
# of the screen, so the screen size matters: ctest runs this on a 1440x900 screen (a 600 px cap).
# Kept in ARTEFACT_DIR: fairing_dialog.png (the fairing dialog as it opens), help_CASE.png (each
# dialog with its help) and help_CASE.txt (the probe's measurements).
# Run under `scripts/with-xvfb.sh` (ctest does). Usage:
#   gui_dialog_test.sh PREFIX_SCRIPT PLUGIN.so PREFIX_DIR MESH ARTEFACT_DIR DIALOG_PROBE.so
set -euo pipefail
prefix_script=$1 plugin=$2 prefix=$3 mesh=$4 artefacts=$5 probe=$6
source "$(dirname "$0")/gui_lib.sh"   # fail, wait_window, gui_check_display, gui_install_plugin
gui_check_display
[[ -f $probe ]] || fail "no dialog probe at $probe"

gui_install_plugin

# check_dialog CASE TITLE PARAMETERS: opens the dialog TITLE, shows its help and asserts that the
# description and the PARAMETERS help paragraphs are all shown in full.
check_dialog() {
  local case=$1 title=$2 parameters=$3
  local measured=$artefacts/help_$case.txt shot=$artefacts/help_$case.png main dialog
  meshlab_log=$artefacts/meshlab_dialog_$case.log
  rm -f "$measured" "$measured.help" "$shot"
  HOME=$home LD_PRELOAD=$probe ELASTICA_DIALOG_PROBE_TITLE=$title ELASTICA_DIALOG_PROBE_OUT=$measured \
    "$prefix/bin/meshlab" "$mesh" >"$meshlab_log" 2>&1 &
  meshlab_pid=$!
  main=$(wait_window '^MeshLab 20' 20) || fail "$case: MeshLab's main window did not appear in 20 s"
  # The dialog must not be there before we ask for it (so finding it below means something).
  xdotool search --name "^$title\$" >/dev/null 2>&1 && fail "$case: a '$title' window exists before opening the dialog"
  grep -q "Opened mesh" "$meshlab_log" || sleep 1   # let the mesh load and render
  xdotool windowfocus "$main"
  sleep 0.5
  xdotool key ctrl+f
  sleep 0.5
  xdotool type --delay 20 "$title"
  sleep 0.5
  xdotool key Down Return
  dialog=$(wait_window "^$title\$" 10) || { import -window root "$shot"; fail "$case: no '$title' dialog within 10 s (screen: $shot)"; }
  sleep 0.5   # let it paint
  if [[ $case == fairing ]]; then
    import -window root "$artefacts/fairing_dialog.png"
    [[ -s "$artefacts/fairing_dialog.png" ]] || fail "screenshot $artefacts/fairing_dialog.png is empty"
  fi
  touch "$measured.help"   # the probe clicks Help now
  local deadline=$((SECONDS + 10))
  until [[ -f $measured ]] && grep -q '^done$' "$measured"; do
    ((SECONDS < deadline)) || { import -window root "$shot"; fail "$case: the dialog probe reported nothing in 10 s (is it preloaded?)"; }
    sleep 0.2
  done
  sleep 0.3
  import -window root "$shot"
  kill "$meshlab_pid" 2>/dev/null || true
  wait "$meshlab_pid" 2>/dev/null || true
  meshlab_pid=
  rm -f "$measured.help"
  sed "s/^/    /" "$measured"
  local shown clipped
  shown=$(grep -c '^\(FIT\|CLIPPED\) ' "$measured" || true)
  clipped=$(grep -c '^CLIPPED ' "$measured" || true)
  ((shown == parameters + 1)) || fail "$case: $shown paragraphs shown with Help, expected the description and $parameters parameters' help"
  ((clipped == 0)) || fail "$case: $clipped of $shown paragraphs do not fit the dialog ($shot): $(grep '^CLIPPED ' "$measured" | cut -c1-80 | tr '\n' ';')"
  echo "--- $case: '$title' dialog (window $dialog): its description and $parameters help paragraphs fit ($(head -n1 "$measured"))"
}

check_dialog fairing "Discrete Elastica Fairing" 11
check_dialog fill "Fill Holes with Discrete Elastica" 7
check_dialog curvature "Discrete Elastica Curvature" 2
echo "PASS: each filter's dialog shown, its help fits; screenshots in $artefacts (fairing_dialog.png, help_*.png)"
