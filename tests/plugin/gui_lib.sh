# SPDX-License-Identifier: GPL-3.0-or-later
# Shared by the GUI tests (sourced): fail, wait_display for Xvfb, and wait_window for MeshLab's windows.
# The sourcing script sets meshlab_pid once MeshLab runs.

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
