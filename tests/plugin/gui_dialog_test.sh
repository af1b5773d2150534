#!/usr/bin/env bash
# GUI test: Debian's MeshLab, with the freshly built plugin in a private prefix, opens a mesh; the
# filter search (Ctrl+F) finds "Discrete Elastica Fairing" and opens its parameter dialog, which
# must appear as a window of that title. A screenshot of the screen is kept as an artefact.
# Run under `xvfb-run -a` (ctest does). Usage:
#   gui_dialog_test.sh PREFIX_SCRIPT PLUGIN.so PREFIX_DIR MESH ARTEFACT_DIR
set -euo pipefail
prefix_script=$1 plugin=$2 prefix=$3 mesh=$4 artefacts=$5
title="Discrete Elastica Fairing"
source "$(dirname "$0")/gui_lib.sh"   # fail, wait_window
[[ -n "${DISPLAY:-}" ]] || fail "no X display (run under xvfb-run -a)"
for tool in xdotool import; do command -v $tool >/dev/null || fail "$tool not installed (scripts/setup.sh)"; done

"$prefix_script" --prefix "$prefix" "$plugin" >/dev/null
mkdir -p "$artefacts"
shot="$artefacts/fairing_dialog.png"
rm -f "$shot"
home=$(mktemp -d)  # MeshLab writes its settings under $HOME
meshlab_pid=
cleanup() { [[ -n "$meshlab_pid" ]] && kill "$meshlab_pid" 2>/dev/null; rm -rf "$home"; }
trap cleanup EXIT
HOME=$home "$prefix/bin/meshlab" "$mesh" >"$artefacts/meshlab.log" 2>&1 &
meshlab_pid=$! meshlab_log=$artefacts/meshlab.log


main=$(wait_window '^MeshLab 20' 20) || fail "MeshLab's main window did not appear in 20 s"
# The dialog must not be there before we ask for it (so finding it below means something).
xdotool search --name "^$title\$" >/dev/null 2>&1 && fail "a '$title' window exists before opening the dialog"
grep -q "Opened mesh" "$artefacts/meshlab.log" || sleep 1   # let the mesh load and render
xdotool windowfocus "$main"
sleep 0.5
xdotool key ctrl+f
sleep 0.5
xdotool type --delay 20 "$title"
sleep 0.5
xdotool key Down Return
dialog=$(wait_window "^$title\$" 10) || { import -window root "$shot"; fail "no '$title' dialog within 10 s (screen: $shot)"; }
sleep 0.5   # let it paint
import -window root "$shot"
[[ -s "$shot" ]] || fail "screenshot $shot is empty"
echo "PASS: '$title' dialog (window $dialog) shown; screenshot $shot"
