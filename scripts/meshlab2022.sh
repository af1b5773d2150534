#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The MeshLab plugin built for, and run in, Debian 13 (trixie)'s MeshLab 2022.02, on a Debian 12 machine
# (as root):
#
#   scripts/meshlab2022.sh [--screenshot OUT.png]
#
# 1. A trixie root (scripts/debian-root.sh, shared with scripts/meshlab2025.sh: debootstrap from the
#    Debian mirror of the system's own apt sources, read at run time), with trixie's meshlab and the
#    build's Debian packages installed in it: $cache/trixie-root (cache: as scripts/setup.sh,
#    $ELASTICA_CACHE_DIR or ~/.cache/elastica). Made once; a later run reuses it.
# 2. In it, this source tree (bind-mounted read-only) built with -DELASTICA_MESHLAB_API=2022 against
#    trixie's meshlab source tree (scripts/setup.sh fetches it) and trixie's libmeshlab-common.so: the
#    plugin, the elastica command, and tests/meshlab2022/run_filter (a driver that loads plugins
#    through MeshLab's own PluginManager, as MeshLab does, and applies a filter of an .mlx script).
#    Build folder: $cache/trixie-root/build/elastica.
# 3. The fairing and fill filters run in that MeshLab on meshlab_plugin/examples/{fairing,fill_holes}.mlx
#    (a noisy sphere, a torus cage split three times; the bunny with its flank cut away), loaded from MeshLab's plugin folder after
#    `apt-get install` of the plugin's trixie .deb; each result equals `elastica run`'s on the same
#    script and input (same counts, positions within 1e-5 of the diagonal) and differs from the input.
# 4. With --screenshot: MeshLab 2022.02's window under Xvfb, the faired sphere loaded and the menu
#    Filters > Smoothing, Fairing and Deformation open, saved as OUT.png (the faired torus).
# 5. The user's shading (packaging/meshlab2022/shading.sh, Xvfb): the bunny opened in Face shading,
#    faired from the filter search at its defaults, still in Face shading (both saved projects kept).
# 6. The Load-Plugins file: the package removed again, the file loaded with Help > Plugin Info > Load
#    Plugins in MeshLab's GUI (Xvfb), which copies it into its per-user folder; the fairing filter from
#    that copy equals `elastica run` again.
# Leaves $cache/meshlab2022/: the trixie .deb of the plugin (meshlab-plugin-elastica_*_amd64.deb),
# the Load-Plugins file (libfilter_elastica.so with a note of its MeshLab version), the outputs.
# Prints each step's time.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/debian-root.sh
root_script meshlab2022 '3,30p' trixie-root "$@"
mltree=$(ls -d "$cache"/meshlab-trixie-src-2022.02*/ 2>/dev/null | tail -n1)
[[ -n "$mltree" && -f "$mltree/.elastica-complete" ]] || fail "no MeshLab 2022.02 source tree in $cache (run scripts/setup.sh)"

# The packages of the root: trixie's MeshLab, and what the plugin, the command and the driver build with.
# meshlab and its Recommends (apt-get install meshlab would add them on a fresh root, not on one where
# meshlab is already installed): several of its plugins need them, and MeshLab's plugin manager fails on
# any plugin it cannot load.
root_packages=(meshlab lib3ds-1-3 libopenctm1 libxerces-c3.2t64 libmuparser2v5 libqhull-r8.0 libgmp10 libmpfr6 chemical-mime-data
  g++ cmake make pkg-config dpkg-dev file
  qtbase5-dev libqt5opengl5-dev libglew-dev
  libeigen3-dev libsuitesparse-dev libopenblas0-serial libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libtinyxml2-dev
  xvfb xauth xdotool imagemagick)

# ---------------------------------------------------------------- 1. the trixie root
step "trixie root ($root)"
debian_root trixie "$root" "$cache/trixie" "${root_packages[@]}" || fail "the trixie root could not be made"
echo "trixie's meshlab: $(in_root dpkg-query -W -f='${Version}' meshlab); $(du -shx "$root" 2>/dev/null | cut -f1) in all"

# ---------------------------------------------------------------- 2. the build in the root
step "build in the trixie root: the plugin for MeshLab 2022.02, the command, run_filter"
bind "$src" "$root/src/elastica" ro
bind "$mltree" "$root/src/meshlab" ro
commit=$(git -C "$src" describe --always --dirty 2>/dev/null || echo unknown)
in_root cmake -S /src/elastica -B /build/elastica -DCMAKE_BUILD_TYPE=Release -DELASTICA_MESHLAB_API=2022 \
  -DMESHLAB_SOURCE_DIR=/src/meshlab -DELASTICA_BUILD_TESTS=OFF -DELASTICA_BUILD_BENCH=OFF -DELASTICA_BUILD_PYTHON=OFF \
  -DELASTICA_SOURCE_COMMIT="$commit" -DELASTICA_DEB_MAINTAINER="$(git -C "$src" log -1 --format='%an <%ae>')" >"$cache/trixie-build.log" 2>&1 \
  || { tail -n 30 "$cache/trixie-build.log" >&2; fail "cmake (configure) failed in the trixie root"; }
in_root nice cmake --build /build/elastica -j2 --target filter_elastica elastica >>"$cache/trixie-build.log" 2>&1 \
  || { grep -m5 -A5 'error' "$cache/trixie-build.log" >&2; fail "the build failed in the trixie root (log: $cache/trixie-build.log)"; }
in_root cmake -S /src/elastica/packaging/meshlab2022 -B /build/run_filter -DMESHLAB_SOURCE_DIR=/src/meshlab >>"$cache/trixie-build.log" 2>&1 \
  && in_root nice cmake --build /build/run_filter >>"$cache/trixie-build.log" 2>&1 \
  || { grep -m5 -A5 'error' "$cache/trixie-build.log" >&2; fail "run_filter did not build (log: $cache/trixie-build.log)"; }

step "the trixie package of the plugin, installed into trixie's MeshLab"
rm -rf "$root/build/elastica/packages"
in_root sh -c 'cd /build/elastica && cpack -G DEB -D CPACK_COMPONENTS_ALL=deb_meshlab' >>"$cache/trixie-build.log" 2>&1 \
  || { tail -n 20 "$cache/trixie-build.log" >&2; fail "cpack failed in the trixie root"; }
deb=$(cd "$root" && ls build/elastica/packages/meshlab-plugin-elastica_*.deb)
in_root dpkg-deb -f "/$deb" Package Version Depends
in_root apt-get install -y -qq --reinstall "/$deb" >/dev/null || fail "apt-get install /$deb failed in the trixie root"
plugins=/usr/lib/x86_64-linux-gnu/meshlab/plugins
in_root test -f $plugins/libfilter_elastica.so || fail "the package did not install $plugins/libfilter_elastica.so"
mkdir -p "$out"
rm -f "$out"/*.deb
cp "$root/$deb" "$out/"
# The Load-Plugins file: the plugin as MeshLab's Help > Plugin Info > Load Plugins takes it, and its note.
cp "$root/build/elastica/meshlab_plugin/libfilter_elastica.so" "$out/libfilter_elastica.so"
ml_version=$(in_root dpkg-query -W -f='${Version}' meshlab)
cat >"$out/libfilter_elastica.so.txt" <<NOTE
libfilter_elastica.so: the Elastica filters (Discrete Elastica Fairing, Fill Holes with Discrete Elastica,
Discrete Elastica Curvature) for MeshLab 2022.02, x86-64 Linux, single precision (MESHLAB_SCALAR=float).
Built from Elastica commit $commit against Debian 13's meshlab $ml_version (its source tree and
libmeshlab-common.so) with g++ $(in_root g++ -dumpfullversion) and Qt $(in_root dpkg-query -W -f='${Version}' libqt5core5t64 2>/dev/null || in_root dpkg-query -W -f='${Version}' libqt5core5a).
MeshLab loads a plugin only if it was built for its own version (2022.02) and precision. It also needs
the same Qt 5 and libstdc++ ABI as that MeshLab, and CHOLMOD (libcholmod5), libgomp1 and libGLEW at
run time (Debian 13's package names). Load it with Help > Plugin Info > Load Plugins.
NOTE
echo "Load-Plugins file: $out/libfilter_elastica.so (+ .txt note)"

# ---------------------------------------------------------------- 3. the filters in MeshLab 2022.02
step "the fairing and fill filters in MeshLab 2022.02 (run_filter) against elastica run"
rm -rf "$root/work" && mkdir -p "$root/work"
ex=/src/elastica/meshlab_plugin/examples
run() { in_root env OMP_NUM_THREADS=1 HOME=/work "$@"; }
run /build/elastica/bin/elastica generate icosphere --level 3 --noise 0.05 -o /work/noisy.ply >/dev/null
run /build/elastica/bin/elastica run -i /work/noisy.ply -o /work/fair_run.ply -s $ex/fairing.mlx
run xvfb-run -a -n "$(free_display)" /build/run_filter/run_filter $plugins /work/noisy.ply /work/fair_meshlab.ply $ex/fairing.mlx /work/fair_run.ply 1e-5 \
  || fail "the fairing filter in MeshLab 2022.02 differs from elastica run (or did not run)"
run /build/elastica/bin/elastica run -i /src/elastica/data/bunny_flank_hole.ply -o /work/fill_run.ply -s $ex/fill_holes.mlx
run xvfb-run -a -n "$(free_display)" /build/run_filter/run_filter $plugins /src/elastica/data/bunny_flank_hole.ply /work/fill_meshlab.ply $ex/fill_holes.mlx \
  /work/fill_run.ply 1e-5 || fail "the fill filter in MeshLab 2022.02 differs from elastica run (or did not run)"
# The hand-written torus cage (data/cages), split three times, faired to the Clifford torus: the screenshot's mesh.
# MeshLab keeps positions in float: the split cage (written in double) goes through MeshLab first (a
# script without filters), so that both runs start from the same positions. From the double file the
# remeshing stages decide differently: 1223 vertices by `elastica run`, 1261 in MeshLab.
run /build/elastica/bin/elastica subdivide /src/elastica/data/cages/torus_quad_5x5.off --levels 3 -o /work/torus_double.ply >/dev/null
printf '<!DOCTYPE FilterScript>\n<FilterScript>\n</FilterScript>\n' >"$root/work/no_filter.mlx"
run xvfb-run -a -n "$(free_display)" /build/run_filter/run_filter $plugins /work/torus_double.ply /work/torus.ply /work/no_filter.mlx >/dev/null 2>&1 \
  || fail "MeshLab 2022.02 could not read and write the torus"
run /build/elastica/bin/elastica run -i /work/torus.ply -o /work/torus_run.ply -s $ex/fairing.mlx >/dev/null
run xvfb-run -a -n "$(free_display)" /build/run_filter/run_filter $plugins /work/torus.ply /work/torus_meshlab.ply $ex/fairing.mlx /work/torus_run.ply 1e-5 \
  || fail "the fairing filter in MeshLab 2022.02 differs from elastica run on the torus (or did not run)"
cp "$root"/work/*_meshlab.ply "$out/"


# ---------------------------------------------------------------- 4. a screenshot of MeshLab 2022.02
if [[ -n "$shot" ]]; then
  step "screenshot: MeshLab 2022.02 with the faired torus and the Filters menu"
  cp "$src/packaging/meshlab2022/screenshot.sh" "$root/work/screenshot.sh"
  run xvfb-run -a -n "$(free_display)" -s "-screen 0 1600x900x24" bash /work/screenshot.sh /work/torus_meshlab.ply /work/shot.png \
    || fail "no screenshot"
  mkdir -p "$(dirname "$shot")"
  cp "$root/work/shot.png" "$shot"
  echo "screenshot: $shot"
fi
# ---------------------------------------------------------------- 5. the user's shading in MeshLab 2022.02
step "the user's shading after a fairing in MeshLab 2022.02's GUI"
run xvfb-run -a -n "$(free_display)" -s "-screen 0 1600x900x24" bash /src/elastica/packaging/meshlab2022/shading.sh \
  /src/elastica/data/bunny.ply /work || fail "MeshLab 2022.02 changed the shading after a fairing (see $out/shading_after.png)"
cp "$root"/work/shading_* "$out/"
# ---------------------------------------------------------------- 6. the Load-Plugins file in MeshLab 2022.02
step "the Load-Plugins file through MeshLab 2022.02's Help > Plugin Info > Load Plugins"
# Without the package, MeshLab's plugin folder lacks ours: the filter can only come from the loaded copy.
in_root apt-get remove -y -qq meshlab-plugin-elastica >/dev/null
in_root test ! -e $plugins/libfilter_elastica.so || fail "the plugin is still in $plugins"
cp "$src/packaging/meshlab2022/load_plugins.sh" "$out/libfilter_elastica.so" "$root/work/"
rm -rf "$root/work/.local"
run xvfb-run -a -n "$(free_display)" -s "-screen 0 1600x900x24" bash /work/load_plugins.sh /work/libfilter_elastica.so /work/load_plugins.png \
  || fail "Load Plugins did not take the file"
extra=$(cd "$root" && find work/.local -name libfilter_elastica.so -printf '/%h\n' | head -n1)
[[ -n "$extra" ]] || fail "MeshLab did not copy the plugin into its extra-plugins folder"
echo "MeshLab copied it into $extra"
cp "$root/work/load_plugins.png" "$out/"
run xvfb-run -a -n "$(free_display)" /build/run_filter/run_filter "$plugins:$extra" /work/noisy.ply /work/fair_loaded.ply $ex/fairing.mlx /work/fair_run.ply 1e-5 \
  || fail "the fairing filter of the loaded plugin differs from elastica run (or did not run)"
step "done"
