#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# MeshLab 2022.02's (or, with MESHLAB_TITLE="MeshLab 2025", 2025.07's) Help > Plugin Info > Load Plugins, done as a user does it, on PLUGIN.so; the screen
# after loading (the plugin list) saved as OUT.png. MeshLab copies the file into its per-user
# extra-plugins folder. scripts/meshlab2022.sh runs it in the trixie root, under Xvfb.
#   load_plugins.sh PLUGIN.so OUT.png
set -euo pipefail
plugin=$1 out=$2
fail() { printf 'load_plugins: %s\n' "$*" >&2; import -window root "${out%.png}_failed.png" || true; exit 1; }
wait_window() {  # NAME SECONDS: the first window called NAME
  local id
  for _ in $(seq $(($2 * 5))); do
    id=$(xdotool search --name "$1" 2>/dev/null | head -n1) && [[ -n "$id" ]] && { echo "$id"; return 0; }
    sleep 0.2
  done
  return 1
}
# The X server first: a MeshLab started before Xvfb takes clients aborts ("could not connect to display").
for _ in $(seq 50); do xdotool getdisplaygeometry >/dev/null 2>&1 && break; sleep 0.2; done
xdotool getdisplaygeometry >/dev/null 2>&1 || fail "no X server on display ${DISPLAY:-(unset)}"
meshlab >/tmp/meshlab-load.log 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
main=$(wait_window "${MESHLAB_TITLE:-MeshLab 2022}" 30) || fail "no MeshLab window"
xdotool windowsize "$main" 1600 900 windowmove "$main" 0 0
sleep 2
xdotool windowfocus "$main"
sleep 0.5
xdotool mousemove 374 9 click 1          # Help
sleep 1
xdotool key Down; sleep 0.2; xdotool key Down; sleep 0.2   # (About MeshLab) Plugin Info
xdotool key Return
dialog=$(wait_window "Plugin Information" 10) || fail "no Plugin Information dialog"
sleep 1
eval "$(xdotool getwindowgeometry --shell "$dialog")"
xdotool mousemove $((X + 50)) $((Y + HEIGHT - 24)) click 1   # Load Plugins, the dialog's bottom-left button
files=$(wait_window "Load Plugins" 10) || fail "no Load Plugins file dialog"
xdotool windowfocus "$files"
sleep 0.5
xdotool type --delay 10 "$plugin"
xdotool key Return
sleep 2
xdotool search --name "Error while loading plugin" >/dev/null 2>&1 && fail "MeshLab refused the plugin"
# The plugin list, scrolled to its end, where the new plugin is.
xdotool mousemove $((X + 200)) $((Y + 200)) click 1 key End
sleep 1
import -window root "$out"
