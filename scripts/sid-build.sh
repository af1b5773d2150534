# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian sid root of scripts/meshlab2025.sh and scripts/blender5.sh, and this tree built in it:
# sourced after scripts/debian-root.sh, with $src (this tree), $cache and $root set.
#
#   sid_root_and_build TARGET...   # root, MeshLab's source, configure /build/sid, build the targets
#
# Sets sid_meshlab_tree (MeshLab's source in the root), sid_cmake_args, sid_commit, sid_log.

# sid's MeshLab with the Recommends its own plugins need (MeshLab's plugin manager fails on any plugin
# it cannot load), Blender (with what its Extensions add-on imports: Debian's blender does not depend on
# python3-cattr and python3-requests, and without them bl_pkg fails to register), and what the core, the plugin, the module and the host tools build with.
sid_packages=(meshlab lib3ds-1-3 libopenctm1 libmuparser2v5 libqhull-r8.0 chemical-mime-data libgomp1
  blender python3-numpy python3-cattr python3-requests
  g++ cmake make pkg-config dpkg-dev file
  qtbase5-dev libqt5opengl5-dev libglew-dev
  libeigen3-dev libsuitesparse-dev libopenblas0-serial libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libtinyxml2-dev
  pybind11-dev python3-dev
  xvfb xauth xdotool imagemagick)
sid_log=$cache/sid-build.log

# MeshLab's source in the root (/meshlab-src), from sid's source package: the mirror may hold only the
# upstream tarball (its .dsc and Debian patches were missing, 404, when this was written), so the
# tarball is unpacked when apt-get source cannot unpack the package.
sid_meshlab_source() {
  local tree
  if [[ ! -f $root/meshlab-src/.elastica-complete ]]; then
    rm -rf "$root/meshlab-src" && mkdir -p "$root/meshlab-src"
    in_root sh -c 'cd /meshlab-src && apt-get source -qq meshlab' >>"$sid_log" 2>&1 || true
    if ! ls -d "$root"/meshlab-src/meshlab-*/src/common >/dev/null 2>&1; then
      (cd "$root/meshlab-src" && ls meshlab_*.orig.tar.* >/dev/null 2>&1 && tar xf meshlab_*.orig.tar.*) \
        || { echo "no meshlab source from sid's source package (log: $sid_log)" >&2; return 1; }
      echo "sid's meshlab source: the upstream tarball only (no Debian patches)" >&2
    fi
    touch "$root/meshlab-src/.elastica-complete"
  fi
  tree=$(cd "$root" && ls -d meshlab-src/meshlab-*/ | head -n1)
  sid_meshlab_tree=/${tree%/}
}

sid_root_and_build() {
  debian_root sid "$root" "$cache/sid" "${sid_packages[@]}" || return 1
  echo "sid: meshlab $(in_root dpkg-query -W -f='${Version}' meshlab), blender $(in_root dpkg-query -W -f='${Version}' blender), g++ $(in_root g++ -dumpfullversion); $(du -shx "$root" 2>/dev/null | cut -f1) in all"
  sid_meshlab_source || return 1
  bind "$src" "$root/src/elastica" ro
  sid_commit=$(git -C "$src" describe --always --dirty 2>/dev/null || echo unknown)
  sid_cmake_args=(-DCMAKE_BUILD_TYPE=Release -DELASTICA_MESHLAB_API=2025 -DMESHLAB_SOURCE_DIR="$sid_meshlab_tree"
    -DELASTICA_BUILD_TESTS=OFF -DELASTICA_BUILD_BENCH=OFF -DELASTICA_SOURCE_COMMIT="$sid_commit"
    -DELASTICA_DEB_MAINTAINER="$(git -C "$src" log -1 --format='%an <%ae>')")
  in_root cmake -S /src/elastica -B /build/sid "${sid_cmake_args[@]}" -DELASTICA_BUILD_PYTHON=ON >>"$sid_log" 2>&1 \
    || { tail -n 30 "$sid_log" >&2; echo "cmake (configure) failed in the sid root" >&2; return 1; }
  in_root nice cmake --build /build/sid -j2 --target "$@" >>"$sid_log" 2>&1 \
    || { grep -m5 -A5 'error' "$sid_log" >&2; echo "the build failed in the sid root (log: $sid_log)" >&2; return 1; }
}
