#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Run Debian's MeshLab with the Elastica plugin, without installing anything into /usr.
#
#   scripts/meshlab-with-plugin.sh [--prefix DIR] PLUGIN.so                  set up DIR only
#   scripts/meshlab-with-plugin.sh [--prefix DIR] PLUGIN.so meshlab [ARGS]   ... and start the GUI
#   scripts/meshlab-with-plugin.sh [--prefix DIR] PLUGIN.so meshlabserver [ARGS]
#
# MeshLab 2020.09 loads plugins only from <dir of its executable>/../lib/x86_64-linux-gnu/meshlab/
# plugins (a symlinked executable does not count: Qt resolves it to /usr/bin). So DIR becomes a
# private prefix: copies of the two executables in DIR/bin, a link to libmeshlab-common.so, and a
# plugins directory with links to every system plugin plus ours. PLUGIN.so is linked, not copied:
# rebuild it and the next run picks it up.
# DIR defaults to ${XDG_DATA_HOME:-$HOME/.local/share}/elastica/meshlab-prefix.
# Headless (no DISPLAY): run it under `xvfb-run -a`; MeshLab needs an X server even for meshlabserver.
set -euo pipefail

die() { printf 'meshlab-with-plugin: error: %s\n' "$*" >&2; exit 1; }

prefix=${XDG_DATA_HOME:-$HOME/.local/share}/elastica/meshlab-prefix
if [[ "${1:-}" == --prefix ]]; then
  [[ $# -ge 2 ]] || die "--prefix needs a directory"
  prefix=$2
  shift 2
fi
case "${1:-}" in
  -h|--help|"") sed -n '3,16p' "$0" | sed 's/^# \{0,1\}//'; [[ -n "${1:-}" ]]; exit $? ;;
esac
plugin=$(realpath -e -- "$1") || die "plugin '$1' not found (build it: cmake --build build --target filter_elastica)"
shift

syslib=/usr/lib/x86_64-linux-gnu/meshlab
[[ -f $syslib/libmeshlab-common.so && -x /usr/bin/meshlabserver ]] || die "Debian's meshlab package is not installed"

lib=$prefix/lib/x86_64-linux-gnu/meshlab
mkdir -p "$prefix/bin" "$lib/plugins" "$prefix/share"
for exe in meshlab meshlabserver; do
  cmp -s "/usr/bin/$exe" "$prefix/bin/$exe" || cp "/usr/bin/$exe" "$prefix/bin/$exe"
done
ln -sfn "$syslib/libmeshlab-common.so" "$lib/libmeshlab-common.so"
ln -sfn /usr/share/meshlab "$prefix/share/meshlab"
find "$lib/plugins" -maxdepth 1 -type l -delete   # drop links to plugins that are gone
for p in "$syslib"/plugins/*.so; do
  [[ $(basename "$p") == "$(basename "$plugin")" ]] && continue  # ours wins over an installed copy
  ln -sfn "$p" "$lib/plugins/$(basename "$p")"
done
ln -sfn "$plugin" "$lib/plugins/$(basename "$plugin")"

if [[ $# -eq 0 ]]; then
  printf '%s\n' "$prefix"
  exit 0
fi
case "$1" in
  meshlab|meshlabserver) exe=$1; shift; exec "$prefix/bin/$exe" "$@" ;;
  *) die "unknown program '$1' (meshlab or meshlabserver)" ;;
esac
