# Shared by the GUI tests (sourced): fail, and wait_window for MeshLab's windows under Xvfb.
# The sourcing script sets meshlab_pid once MeshLab runs.

fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }

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
