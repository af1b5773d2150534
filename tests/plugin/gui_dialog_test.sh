#!/usr/bin/env bash
# GUI test: Debian's MeshLab, with the freshly built plugin in a private prefix, opens a mesh; the
# filter search (Ctrl+F) finds "Discrete Elastica Fairing" and opens its parameter dialog, which
# must appear as a window of that title. A screenshot of the screen is kept as an artefact.
# Run under `xvfb-run -a` (ctest does). Usage:
#   gui_dialog_test.sh PREFIX_SCRIPT PLUGIN.so PREFIX_DIR MESH ARTEFACT_DIR
set -euo pipefail
prefix_script=$1 plugin=$2 prefix=$3 mesh=$4 artefacts=$5
title="Discrete Elastica Fairing"
fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }
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
meshlab_pid=$!

# Polls `xdotool search --name PATTERN` for up to $2 seconds; prints the first window id.
wait_window() {
  local deadline=$((SECONDS + $2)) id
  while ((SECONDS < deadline)); do
    id=$(xdotool search --name "$1" 2>/dev/null | head -n1) || true
    [[ -n "$id" ]] && { echo "$id"; return 0; }
    kill -0 "$meshlab_pid" 2>/dev/null || fail "meshlab exited early (see $artefacts/meshlab.log)"
    sleep 0.2
  done
  return 1
}

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
