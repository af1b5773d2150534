# SPDX-License-Identifier: GPL-3.0-or-later
# Shared by the GUI tests (sourced): fail, wait_display for Xvfb, wait_window for MeshLab's windows,
# and the tests' common start (gui_check_display, gui_install_plugin). The sourcing script sets
# meshlab_pid once MeshLab runs.

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
