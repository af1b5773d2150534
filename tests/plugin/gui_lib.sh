# SPDX-License-Identifier: GPL-3.0-or-later
# Shared by the GUI tests (sourced): fail, wait_display for Xvfb, wait_window for MeshLab's windows,
# search_filter, save_project, shading and same_shading for the view's shading, and the tests'
# common start (gui_check_display, gui_install_plugin). packaging/meshlab2022/shading.sh sources it
# in the trixie and sid roots. The sourcing script sets meshlab_pid once MeshLab runs.

fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }

# Waits up to 15 s for the X server on $DISPLAY to answer (scripts/with-xvfb.sh already waits;
# kept for a test started by hand under another server).
wait_display() {
  local deadline=$((SECONDS + 15))
  until xdotool getdisplaygeometry >/dev/null 2>&1; do
    ((SECONDS < deadline)) || fail "the X server on $DISPLAY did not answer within 15 s"
    sleep 0.2
  done
}

# Polls `xdotool search --name PATTERN` for up to $2 seconds; prints the first window id. Fails
# if MeshLab (meshlab_pid) exits meanwhile.
wait_window() {
  local deadline=$((SECONDS + $2)) id
  while ((SECONDS < deadline)); do
    id=$(xdotool search --name "$1" 2>/dev/null | head -n1) || true
    [[ -n "$id" ]] && { echo "$id"; return 0; }
    kill -0 "$meshlab_pid" 2>/dev/null || fail "meshlab exited early${meshlab_log:+ (see $meshlab_log)}"
    sleep 0.2
  done
  return 1
}

# search_filter MAIN_WINDOW NAME: MeshLab's filter search (Ctrl+F) opens the filter NAME's parameters.
search_filter() {
  xdotool windowfocus "$1"
  sleep 0.5
  xdotool key ctrl+f
  sleep 0.5
  xdotool type --delay 20 "$2"
  sleep 0.5
  xdotool key Down Return
}

# save_project MAIN_WINDOW OUT.mlp: File > Save Project As (Ctrl+S in MeshLab 2020.09 to 2025.07)
# writes OUT.mlp, the view state with it (the dialog's default), the mesh files left as they are.
save_project() {
  local main=$1 out=$2
  rm -f "$out"
  xdotool windowfocus "$main"
  sleep 0.3
  xdotool key ctrl+s
  wait_window '^Save Project File' 10 >/dev/null || fail "no Save Project File dialog"
  sleep 0.5
  xdotool type --delay 10 "$out"
  xdotool key Return
  local deadline=$((SECONDS + 10))
  until [[ -s $out ]] && grep -q '</MeshLabProject>' "$out"; do
    ((SECONDS < deadline)) || fail "MeshLab did not save the project $out in 10 s"
    sleep 0.2
  done
}

# shading PROJECT.mlp: how the view shades the project's first mesh, as its RenderingOption stores
# it (vcglib's PerViewData::serialize): the 4 modalities' on-bits, solid first (bitset order), then
# 9 attribute bits per modality (points, edges, wireframe, solid: position, vertex normal, face
# normal, ...), then the view options. Prints "Vert", "Face" or "None" (solid drawn with neither
# normal), or "no solid" with the bits.
shading() {
  local bits solid
  bits=$(sed -n 's/.*<RenderingOption[^>]*>\([01]*\)<.*/\1/p' "$1" | head -n1)
  ((${#bits} >= 40)) || fail "no RenderingOption in $1"
  [[ ${bits:0:1} == 1 ]] || { echo "no solid (${bits:0:40})"; return 0; }
  solid=${bits:31:9}
  if [[ ${solid:1:1} == 1 ]]; then echo Vert; elif [[ ${solid:2:1} == 1 ]]; then echo Face; else echo None; fi
}

# same_shading BEFORE.mlp AFTER.mlp WHAT: prints the shading both projects have, or fails saying
# how WHAT changed it.
same_shading() {
  local before after
  before=$(shading "$1") after=$(shading "$2")
  [[ $before == "$after" ]] || fail "MeshLab's shading went from $before to $after after $3 (meshlab_plugin/view_shading.h)"
  echo "$before"
}

# An X display that answers, and the tools the tests drive MeshLab with.
gui_check_display() {
  [[ -n "${DISPLAY:-}" ]] || fail "no X display (run under scripts/with-xvfb.sh)"
  local tool
  for tool in xdotool import; do command -v $tool >/dev/null || fail "$tool not installed (scripts/setup.sh)"; done
  wait_display
}

# Installs $plugin into $prefix with $prefix_script, makes $artefacts, and sets home to a private
# folder for MeshLab's settings; on exit the MeshLab still running (meshlab_pid) is ended and home removed.
gui_install_plugin() {
  "$prefix_script" --prefix "$prefix" "$plugin" >/dev/null
  mkdir -p "$artefacts"
  home=$(mktemp -d)  # MeshLab writes its settings under $HOME
  meshlab_pid=
  trap _gui_cleanup EXIT
}
_gui_cleanup() { [[ -n "$meshlab_pid" ]] && kill "$meshlab_pid" 2>/dev/null; rm -rf "$home"; }
