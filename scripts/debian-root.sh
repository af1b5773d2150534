# SPDX-License-Identifier: GPL-3.0-or-later
# A cached Debian root for the host scripts (scripts/meshlab2025.sh, scripts/blender5.sh): sourced, not run.
#
#   source scripts/debian-root.sh
#   root_script NAME USAGE_LINES SUITE_ROOT "$@"   # the scripts' shared start (below)
#   debian_root SUITE ROOT LOG_PREFIX PACKAGE...   # debootstrap (once), mounts, apt-get install (when the list changed)
#   in_root CMD...                                  # CMD in the root, with a clean environment
#   bind SOURCE TARGET [ro]                         # a bind mount, undone on exit
#   free_display                                    # an X display number free here and in the root
#
# The root is made by debootstrap --variant=minbase from the Debian mirror of the system's own apt
# sources (read at run time, never written in the repository), marked $ROOT/.elastica-debootstrap when
# complete, and reused by later runs; $ROOT/.elastica-packages holds the installed package list.
# A mirror's sid Release file may be past its Valid-Until date: apt in the root is told to accept it
# (debootstrap itself does not check). On exit, processes left in the root are ended and mounts undone.

# The start of every host script that sources this (blender5.sh, meshlab2022.sh, meshlab2025.sh), run
# from the checkout's top: NAME, the sed range of its usage comment, the root's folder name in the
# cache, then the script's own arguments ([--screenshot OUT] only). Checks for root and sets src, shot,
# t0, cache, root, out=$cache/NAME, and step/fail, which print under NAME.
root_script() {
  _script_name=$1
  local usage=$2 root_name=$3
  shift 3
  src=$PWD
  shot=
  if [[ "${1:-}" == --screenshot ]]; then shot=$(realpath -m "${2:?--screenshot needs a file}"); shift 2; fi
  [[ $# -eq 0 ]] || { sed -n "$usage" "$0" | sed 's/^# \{0,1\}//'; exit 2; }
  [[ $(id -u) -eq 0 ]] || { echo "$_script_name: run as root (debootstrap and chroot)" >&2; exit 1; }
  t0=$SECONDS
  export DEBIAN_FRONTEND=noninteractive LC_ALL=C.UTF-8
  cache=${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}
  root=$cache/$root_name
  out=$cache/$_script_name
}
step() { printf '\n== %s [%4d s] %s\n' "$_script_name" $((SECONDS - t0)) "$*"; }
fail() { printf '%s: FAIL: %s\n' "$_script_name" "$*" >&2; exit 1; }

# The Debian mirror the system's apt uses (the URI of its main suite).
debian_mirror() {
  local codename f
  codename=$(. /etc/os-release && echo "$VERSION_CODENAME")
  for f in /etc/apt/sources.list.d/*.sources; do
    [[ -f $f ]] || continue
    awk -v cn="$codename" '
      /^[ \t]*$/ { if (ok && uri != "") { print uri; exit } ok = 0; uri = ""; next }
      /^Types:/ { deb = ($0 ~ /(^|[ \t])deb([ \t]|$)/) }
      /^URIs:/ { split($0, u, /[ \t]+/); uri = u[2] }
      /^Suites:/ { ok = 0; for (i = 2; i <= NF; i++) if ($i == cn) ok = deb }
      END { if (ok && uri != "") print uri }' "$f"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [[ -f $f ]] || continue
    awk -v cn="$codename" '$1 == "deb" { i = 2; if ($2 ~ /^\[/) while ($i !~ /\]$/) i++; if ($2 ~ /^\[/) i++; if ($(i+1) == cn) print $i }' "$f"
  done
}

_root_mounts=()
_root_dir=
_root_cleanup() {
  local m p i
  # Only processes whose root directory is this root (an Xvfb of a failed xvfb-run, say).
  for p in /proc/[0-9]*; do
    [[ -n $_root_dir && "$(readlink "$p/root" 2>/dev/null)" == "$_root_dir" ]] && kill "${p#/proc/}" 2>/dev/null
  done
  sleep 0.5
  for ((i = ${#_root_mounts[@]} - 1; i >= 0; i--)); do umount -l "${_root_mounts[i]}" 2>/dev/null || true; done
}
trap _root_cleanup EXIT

bind() {
  mkdir -p "$2"
  mount --bind "$1" "$2"
  _root_mounts+=("$2")
  [[ "${3:-}" == ro ]] && mount -o remount,bind,ro "$2"
  return 0
}

in_root() { chroot "$_root_dir" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LC_ALL=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"; }

# xvfb-run -a looks only at the root's /tmp, but X servers share the host's abstract sockets: pick a
# display free in both (an Xvfb of a test beside this run made the root's Xvfb fail), whose abstract
# socket no server still holds (/proc/net/unix): the Xvfb of the step before, ended by its xvfb-run,
# may hold it a moment after its lock file is gone, and a client of the next step then reaches that
# dying server (the likely cause of "could not connect to display" in 2 of 5 GUI steps on
# 2026-12-03, each right after another step's Xvfb). Each call starts elsewhere.
free_display() {
  local n
  for ((n = 200 + ($$ + 10#$(date +%N) / 1000) % 500; ; ++n)); do
    [[ -e /tmp/.X$n-lock || -e /tmp/.X11-unix/X$n || -e $_root_dir/tmp/.X$n-lock ]] && continue
    grep -q "@/tmp/.X11-unix/X$n\$" /proc/net/unix && continue
    echo "$n"
    return
  done
}

debian_root() {
  local suite=$1 root=$2 log=$3 uri wanted
  shift 3
  _root_dir=$root
  command -v debootstrap >/dev/null || { apt-get update -qq; apt-get install -y -qq --no-install-recommends debootstrap >/dev/null; }
  if [[ ! -f $root/.elastica-debootstrap ]]; then
    uri=$(debian_mirror | head -n1)
    [[ -n "$uri" ]] || { echo "no Debian mirror found in the system's apt sources" >&2; return 1; }
    echo "debootstrap --variant=minbase $suite from the system's mirror $uri"
    findmnt -rn -o TARGET | grep -q "^$root/" && { echo "something is mounted under $root: unmount it first" >&2; return 1; }
    rm -rf "$root"
    debootstrap --variant=minbase "$suite" "$root" "$uri" >"$log-debootstrap.log" 2>&1 \
      || { tail -n 20 "$log-debootstrap.log" >&2; echo "debootstrap failed (log: $log-debootstrap.log)" >&2; return 1; }
    echo 'Acquire::Check-Valid-Until "false";' >"$root/etc/apt/apt.conf.d/99elastica-valid-until"
    # The source package too (apt-get source), from the same mirror.
    sed -n 's/^deb /deb-src /p' "$root/etc/apt/sources.list" >"$root/etc/apt/sources.list.d/elastica-src.list"
    touch "$root/.elastica-debootstrap"
  fi
  bind /proc "$root/proc"
  bind /dev "$root/dev"
  bind /dev/pts "$root/dev/pts"
  wanted="$*"
  if [[ "$(cat "$root/.elastica-packages" 2>/dev/null)" != "$wanted" ]]; then
    in_root apt-get update -qq
    in_root apt-get install -y -qq --no-install-recommends "$@" >"$log-apt.log" 2>&1 \
      || { tail -n 20 "$log-apt.log" >&2; echo "apt-get install in the $suite root failed (log: $log-apt.log)" >&2; return 1; }
    echo "$wanted" >"$root/.elastica-packages"
  fi
}
