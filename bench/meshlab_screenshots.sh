#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Screenshots of the fairing filter in Debian's MeshLab GUI for docs/meshlab.md: a scan before and
# after the filter at its dialog's defaults, and a scan with a selected, noisy region before and
# after. The meshes are libcgal-demo's lion head (an open scan) from the setup cache; the region is
# 1,000 faces on the cheek, the 500 innermost faces' vertices moved by noise of 0.2 mean edge lengths
# (bench/meshlab_screenshot_input.py writes it with MeshLab's face-selection flags). MeshLab draws a
# mesh without vertex normals flat and a filtered one smooth, so the "before" screen is switched to
# smooth shading (the Vert button) first: both pictures are drawn alike. Run under Xvfb:
#
#   scripts/with-xvfb.sh -s "-screen 0 1920x1080x24" bench/meshlab_screenshots.sh [BUILD_DIR] [OUT_DIR]
#
# Writes OUT_DIR/meshlab_default_before_after.png and meshlab_region_before_after.png (the head's
# part of the main window, before beside after), and the MeshLab logs beside them. Defaults:
# build/, docs/images/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} out=${2:-$root/docs/images}
source "$root/tests/plugin/gui_lib.sh"   # fail, wait_display, wait_window
[[ -n "${DISPLAY:-}" ]] || fail "no X display (run under scripts/with-xvfb.sh)"
cache=${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}
lion=$(ls -d "$cache"/cgal-data-*/meshes/lion-head.off | head -n1)
[[ -f $lion ]] || fail "lion-head.off not in $cache (scripts/setup.sh)"
work=$(mktemp -d) home=$(mktemp -d) prefix=$(mktemp -d)
meshlab_pid=
cleanup() { [[ -n "$meshlab_pid" ]] && kill "$meshlab_pid" 2>/dev/null; rm -rf "$work" "$home" "$prefix"; }
trap cleanup EXIT
mkdir -p "$out"
wait_display
"$root/scripts/meshlab-with-plugin.sh" --prefix "$prefix" "$build/meshlab_plugin/libfilter_elastica.so" >/dev/null
PYTHONPATH=$build/python /usr/bin/python3 "$root/bench/meshlab_screenshot_input.py" "$lion" "$work"

# shoot NAME MESH: opens MESH, smooth shading, screenshot, the fairing filter at its defaults, screenshot.
shoot() {
  local name=$1 mesh=$2 log=$out/meshlab_$1.log main dialog
  HOME=$home "$prefix/bin/meshlab" "$mesh" >"$log" 2>&1 &
  meshlab_pid=$! meshlab_log=$log
  main=$(wait_window '^MeshLab 20' 20) || fail "$name: no MeshLab window"
  for _ in $(seq 20); do grep -q "Opened mesh" "$log" && break; sleep 0.5; done
  xdotool windowsize "$main" 1280 1024 windowmove "$main" 0 0
  sleep 1.5
  xdotool mousemove 1046 578 click 1   # the layer panel's Shading: Vert
  sleep 1.5
  import -window root -crop 1280x1024+0+0 "$out/meshlab_${name}_before.png"
  xdotool windowfocus "$main"; sleep 0.3
  xdotool key ctrl+f; sleep 0.5
  xdotool type --delay 20 "Discrete Elastica Fairing"; sleep 0.5
  xdotool key Down Return
  dialog=$(wait_window "^Discrete Elastica Fairing\$" 10) || fail "$name: no dialog"
  xdotool windowmove "$dialog" 1290 0; sleep 0.5
  xdotool windowfocus "$dialog"; sleep 0.3
  xdotool key space
  for _ in $(seq 120); do grep -q "Applied filter\|Filter failed" "$log" && break; sleep 0.5; done
  grep -q "Applied filter" "$log" || fail "$name: the filter did not apply (see $log)"
  sleep 1.5
  import -window root -crop 1280x1024+0+0 "$out/meshlab_${name}_after.png"
  kill "$meshlab_pid" 2>/dev/null || true
  wait "$meshlab_pid" 2>/dev/null || true
  meshlab_pid=
  grep "LOG: [12] Discrete Elastica" "$log" | sed "s/^/  $name: /"
}
shoot default "$work/lion_head.ply"
shoot region "$work/lion_head_region.ply"
# The docs' pictures: the head's part of each screen, before beside after.
for name in default region; do
  convert "$out/meshlab_${name}_before.png" "$out/meshlab_${name}_after.png" -crop 640x520+0+250 +repage +append \
    "$out/meshlab_${name}_before_after.png"
  rm "$out/meshlab_${name}_before.png" "$out/meshlab_${name}_after.png"
done
echo "wrote $out/meshlab_{default,region}_before_after.png"
