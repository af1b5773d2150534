#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command under a private Xvfb whose display number the X server itself picked.
#
#   scripts/with-xvfb.sh [-s "XVFB ARGS"] COMMAND [ARGS...]
#
# Why not `xvfb-run -a`: it picks the first number without a /tmp/.X*-lock file and then starts
# Xvfb on it. Two test suites starting at once (or stale lock files from crashed servers, which
# made every run land on :135) let two servers race for one number; the loser exits, and the
# test's client then talks to the other suite's server, or to none ("could not connect to
# display"). Here Xvfb binds a free display atomically (-displayfd) and tells us which, and the
# command starts only once the server answers. Local clients only (-nolisten tcp).
# -noreset: by default an X server resets whenever its last client disconnects, and a client that
# connects during the reset is refused. The GUI tests start MeshLab once per case, after the
# previous one (and xdotool, xdpyinfo) closed: MeshLab then failed now and then with "could not
# connect to display" although the server had just answered.
# Exits with the command's status; the server is stopped however the command ends.
set -euo pipefail
xvfb_args="-screen 0 1280x1024x24"
if [[ ${1:-} == -s ]]; then xvfb_args=$2; shift 2; fi
(($# > 0)) || { echo "usage: with-xvfb.sh [-s \"XVFB ARGS\"] COMMAND [ARGS...]" >&2; exit 2; }
for tool in Xvfb xdpyinfo; do
  command -v $tool >/dev/null || { echo "with-xvfb: $tool not found (scripts/setup.sh installs xvfb and x11-utils)" >&2; exit 2; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/with-xvfb.XXXXXX")
xvfb_pid=
cleanup() {
  [[ -n "$xvfb_pid" ]] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

mkfifo "$work/displayfd"
# shellcheck disable=SC2086  # the server's arguments are words on purpose
Xvfb -displayfd 3 -nolisten tcp -noreset $xvfb_args 3>"$work/displayfd" >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
display=
read -r -t 30 display <"$work/displayfd" || true
[[ -n "$display" ]] || { echo "with-xvfb: Xvfb did not start:" >&2; cat "$work/xvfb.log" >&2; exit 1; }
export DISPLAY=:$display
deadline=$((SECONDS + 30))
until xdpyinfo >/dev/null 2>&1; do
  ((SECONDS < deadline)) || { echo "with-xvfb: the X server on $DISPLAY did not answer in 30 s" >&2; exit 1; }
  kill -0 "$xvfb_pid" 2>/dev/null || { echo "with-xvfb: Xvfb exited:" >&2; cat "$work/xvfb.log" >&2; exit 1; }
  sleep 0.1
done
status=0
"$@" || status=$?
exit $status
