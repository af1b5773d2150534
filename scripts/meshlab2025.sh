#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The MeshLab plugin built for, and run in, MeshLab 2025.07 (Debian sid's meshlab 2025.07~dfsg), on a
# Debian 12 machine (as root):
#
#   scripts/meshlab2025.sh [--screenshot OUT.png]
#
# 1. A sid root (scripts/debian-root.sh: debootstrap from the system's mirror, cached in
#    $cache/sid-root; $ELASTICA_CACHE_DIR or ~/.cache/elastica), with sid's meshlab, blender and the
#    build's packages (shared with scripts/blender5.sh), and MeshLab's source from sid's source package.
# 2. In it, this tree (bind-mounted read-only) built with -DELASTICA_MESHLAB_API=2025 (single precision,
#    the version from the tree's ML_VERSION): the plugin, the elastica command and Python module, and the
#    host tools of packaging/meshlab2022 (run_filter: MeshLab's PluginManager applying an .mlx; plugin_version).
#    Also the double-precision plugin's sources (PyMeshLab's precision): compiled (not linked: sid's
#    libmeshlab-common is single precision).
# 3. plugin_version: the plugin's baked version and precision equal the host's, and checkPlugin of sid's
#    libmeshlab-common accepts it; against a double-precision host it must fail.
# 4. The plugin's .deb installed into sid's MeshLab; run_filter applies fairing (a noisy sphere), fill
#    (the bunny with its flank cut away), a selected region (libcgal-demo's lion head, 1,000 faces of
#    its cheek selected in MeshLab's face flags, the inner 500 rough) and curvature (the bunny: H in the
#    vertex quality within 1e-5 of the largest |H|), each equal to `elastica run` on the same script and input;
#    then the user's shading (packaging/meshlab2022/shading.sh, Xvfb): the bunny opened in Face shading,
#    faired from the filter search at its defaults, still in Face shading (both saved projects kept).
# 5. Help > Plugin Info > Load Plugins in MeshLab's GUI (Xvfb) takes the bundle's .so (package removed);
#    the fairing filter from the copy MeshLab made equals `elastica run` again.
# 6. The bundle for users of the upstream 2025.07 Linux build: $cache/meshlab2025/
#    elastica-meshlab-2025.07-linux-x86_64.tar.gz (libfilter_elastica.so and README.txt).
# With --screenshot: MeshLab 2025.07's window (the faired lion head region, the Filters menu open) as OUT.png.
# First run on the development machine (2 shared cores): see docs/meshlab.md. Exit 1 on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/debian-root.sh
root_script meshlab2025 '3,29p' sid-root "$@"
source scripts/sid-build.sh

# ---------------------------------------------------------------- 1-2. root and build
step "sid root ($root) and its build"
sid_root_and_build filter_elastica elastica elastica_python || fail "the sid root or the build failed"
ml_version=$(in_root dpkg-query -W -f='${Version}' meshlab)
echo "sid's meshlab $ml_version; MeshLab source $sid_meshlab_tree ($(cat "$root$sid_meshlab_tree/ML_VERSION"))"
in_root cmake -S /src/elastica/packaging/meshlab2022 -B /build/meshlab-tools -DMESHLAB_SOURCE_DIR="$sid_meshlab_tree" >>"$sid_log" 2>&1 \
  && in_root nice cmake --build /build/meshlab-tools -j2 >>"$sid_log" 2>&1 \
  || { grep -m5 -A5 'error' "$sid_log" >&2; fail "run_filter / plugin_version did not build (log: $sid_log)"; }

step "the double-precision plugin (PyMeshLab's precision): its sources compiled"
# In the same build folder (only the plugin's own files depend on the precision), then back to float.
# Compiled, not linked: its symbols take double where sid's libmeshlab-common (single precision) has
# float; it links against a double-precision MeshLab's library (PyMeshLab's), which Debian lacks.
plugin_build() {  # SCALAR TARGET
  in_root cmake /build/sid -DELASTICA_MESHLAB_SCALAR="$1" >>"$sid_log" 2>&1 \
    && in_root nice cmake --build /build/sid -j2 --target "$2" >>"$sid_log" 2>&1
}
plugin_build double elastica_meshlab_filters || { grep -m5 -A5 'error' "$sid_log" >&2; fail "the double-precision plugin does not compile (log: $sid_log)"; }
echo "compiles with MESHLAB_SCALAR=double: $(cd "$root/build/sid/meshlab_plugin/CMakeFiles/elastica_meshlab_filters.dir" && find . -name '*.o' | wc -l) object files"
plugin_build float filter_elastica || fail "the plugin did not build again for float (log: $sid_log)"

# ---------------------------------------------------------------- 3. version and precision
step "the plugin's version and precision against MeshLab $ml_version's"
in_root /build/meshlab-tools/plugin_version /build/sid/meshlab_plugin/libfilter_elastica.so float \
  || fail "the 2025.07 plugin's version or precision is not the host's"
if in_root /build/meshlab-tools/plugin_version /build/sid/meshlab_plugin/libfilter_elastica.so double; then
  fail "the check accepted the single-precision plugin for a double-precision MeshLab"
fi
echo "(refused for a double-precision host, as it must be)"
# Against a real 2022.02 host: the trixie root of scripts/meshlab2022.sh, when this machine has one.
trixie=$cache/trixie-root
if [[ -f $trixie/.elastica-packages && -x $trixie/usr/bin/meshlab ]]; then
  mkdir -p "$trixie/work-2025" "$trixie/src/elastica"
  cp "$root/build/sid/meshlab_plugin/libfilter_elastica.so" "$trixie/work-2025/"
  trixie_tree=$(ls -d "$cache"/meshlab-trixie-src-2022.02*/ 2>/dev/null | tail -n1)
  [[ -n $trixie_tree ]] || fail "no MeshLab 2022.02 source tree in $cache (run scripts/setup.sh)"
  bind "$src" "$trixie/src/elastica" ro
  bind "$trixie_tree" "$trixie/src/meshlab" ro
  t_root() { chroot "$trixie" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LC_ALL=C.UTF-8 "$@"; }
  t_root cmake -S /src/elastica/packaging/meshlab2022 -B /build/meshlab-tools -DMESHLAB_SOURCE_DIR=/src/meshlab >>"$sid_log" 2>&1 \
    && t_root nice cmake --build /build/meshlab-tools -j2 --target plugin_version >>"$sid_log" 2>&1 \
    || fail "plugin_version did not build in the trixie root (log: $sid_log)"
  if t_root /build/meshlab-tools/plugin_version /work-2025/libfilter_elastica.so float; then
    fail "MeshLab 2022.02 (trixie root) accepted the 2025.07 plugin"
  fi
  echo "(refused by MeshLab 2022.02 of the trixie root, as it must be)"
else
  echo "no trixie root with MeshLab 2022.02 ($trixie; scripts/meshlab2022.sh makes it): the check against 2022.02 skipped"
fi

# ---------------------------------------------------------------- 4. the filters through MeshLab 2025.07
step "the plugin's package in sid's MeshLab; fairing, fill, region and curvature against elastica run"
rm -rf "$root/build/sid/packages"
in_root sh -c 'cd /build/sid && cpack -G DEB -D CPACK_COMPONENTS_ALL=deb_meshlab' >>"$sid_log" 2>&1 || fail "cpack failed in the sid root"
deb=$(cd "$root" && ls build/sid/packages/meshlab-plugin-elastica_*.deb)
in_root dpkg-deb -f "/$deb" Package Version Depends
in_root apt-get install -y -qq --reinstall "/$deb" >/dev/null || fail "apt-get install /$deb failed in the sid root"
plugins=/usr/lib/x86_64-linux-gnu/meshlab/plugins
in_root test -f $plugins/libfilter_elastica.so || fail "the package did not install $plugins/libfilter_elastica.so"
rm -rf "$root/work" && mkdir -p "$root/work" "$out"
ex=/src/elastica/meshlab_plugin/examples
run() { in_root env OMP_NUM_THREADS=1 HOME=/work "$@"; }
elastica=/build/sid/bin/elastica
in_meshlab() { run xvfb-run -a -n "$(free_display)" /build/meshlab-tools/run_filter "$@"; }
# Each case: elastica run, then the same script and input through MeshLab; positions within 1e-5 of the diagonal.
check() {  # NAME INPUT SCRIPT [--measure]
  run $elastica run -i "$2" -o "/work/$1_run.ply" -s "$3" >/dev/null || fail "elastica run failed on $1"
  in_meshlab "$plugins" "$2" "/work/$1_meshlab.ply" "$3" "/work/$1_run.ply" 1e-5 ${4:-} \
    || fail "$1: MeshLab 2025.07's result differs from elastica run (or the filter failed)"
}
run $elastica generate icosphere --level 3 --noise 0.05 -o /work/noisy.ply >/dev/null
check fair /work/noisy.ply $ex/fairing.mlx
check fill /src/elastica/data/bunny_flank_hole.ply $ex/fill_holes.mlx
# The region on a scan: libcgal-demo's lion head with 1,000 faces of its cheek selected (MeshLab's face
# flags) and the inner 500 made rough (bench/meshlab_screenshot_input.py, also the docs' pictures),
# faired by fairing.mlx with Selected on, as the dialog's OK does with a selection.
lion=$cache/cgal-data-5.5.1-2/meshes/lion-head.off
[[ -f $lion ]] || fail "no $lion (run scripts/setup.sh)"
cp "$lion" "$root/work/lion-head.off"
run env PYTHONPATH=/build/sid/python python3 /src/elastica/bench/meshlab_screenshot_input.py /work/lion-head.off /work \
  || fail "no selected region on the lion head"
sed 's/name="Selected" value="false"/name="Selected" value="true"/' "$src/meshlab_plugin/examples/fairing.mlx" >"$root/work/fairing_selected.mlx"
grep -q 'name="Selected" value="true"' "$root/work/fairing_selected.mlx" || fail "fairing.mlx has no Selected parameter to set"
check region /work/lion_head_region.ply /work/fairing_selected.mlx
# Curvature, value by value: H in each vertex's quality within 1e-5 of the largest |H|, positions unmoved.
check curvature /src/elastica/data/bunny.ply $ex/curvature.mlx --measure
# The comparison bites: MeshLab's H (mixed areas) against `elastica run`'s with barycentric areas must fail.
sed 's/name="area" value="0"/name="area" value="1"/' "$src/meshlab_plugin/examples/curvature.mlx" >"$root/work/curvature_barycentric.mlx"
run $elastica run -i /src/elastica/data/bunny.ply -o /work/curvature_barycentric_run.ply -s /work/curvature_barycentric.mlx >/dev/null \
  || fail "elastica run failed on curvature_barycentric"
if in_meshlab "$plugins" /src/elastica/data/bunny.ply /work/curvature_other.ply $ex/curvature.mlx /work/curvature_barycentric_run.ply 1e-5 --measure; then
  fail "the curvature comparison accepted another curvature (barycentric areas)"
fi
echo "(another curvature refused by the comparison, as it must be)"
cp "$root"/work/*_meshlab.ply "$out/"
step "the user's shading after a fairing in MeshLab 2025.07's GUI"
run env MESHLAB_TITLE="MeshLab 2025" xvfb-run -a -n "$(free_display)" -s "-screen 0 1600x900x24" bash /src/elastica/packaging/meshlab2022/shading.sh \
  /src/elastica/data/bunny.ply /work || fail "MeshLab 2025.07 changed the shading after a fairing (see $out/shading_after.png)"
cp "$root"/work/shading_* "$out/"

if [[ -n "$shot" ]]; then
  step "screenshot: MeshLab 2025.07 with the faired lion head region and the Filters menu"
  cp "$src/packaging/meshlab2022/screenshot.sh" "$root/work/screenshot.sh"
  run env MESHLAB_TITLE="MeshLab 2025" xvfb-run -a -n "$(free_display)" -s "-screen 0 1600x900x24" bash /work/screenshot.sh /work/region_meshlab.ply /work/shot.png \
    || fail "no screenshot"
  mkdir -p "$(dirname "$shot")" && cp "$root/work/shot.png" "$shot" && echo "screenshot: $shot"
fi

# ---------------------------------------------------------------- 5-6. the bundle, through Load Plugins
step "the bundle, and its .so through MeshLab 2025.07's Help > Plugin Info > Load Plugins"
bundle=elastica-meshlab-2025.07-linux-x86_64
rm -rf "${out:?}/$bundle" && mkdir -p "$out/$bundle"
cp "$root/build/sid/meshlab_plugin/libfilter_elastica.so" "$out/$bundle/"
cat >"$out/$bundle/README.txt" <<NOTE
Elastica filters for MeshLab 2025.07 (Linux x86-64, single precision): Discrete Elastica Fairing,
Fill Holes with Discrete Elastica, Discrete Elastica Curvature, under Filters > Smoothing, Fairing
and Deformation (and Remeshing). GPL-3.0-or-later.

Install: MeshLab > Help > Plugin Info > Load Plugins, choose libfilter_elastica.so. MeshLab copies it
into its per-user plugin folder and loads it at every start.

MeshLab loads a plugin only if it was built for its own version (2025.07) and precision (this one is
single precision: not for MeshLab's double-precision builds or PyMeshLab). It needs Qt 5.15, a
libstdc++ of GCC 16 or later, and at run time CHOLMOD (SuiteSparse 7), libgomp and GLEW 2.2.
Built from Elastica commit $sid_commit against Debian sid's meshlab $ml_version with g++ $(in_root g++ -dumpfullversion).
NOTE
tar -C "$out" -czf "$out/$bundle.tar.gz" "$bundle"
echo "bundle: $out/$bundle.tar.gz ($(du -h "$out/$bundle.tar.gz" | cut -f1))"
in_root apt-get remove -y -qq meshlab-plugin-elastica >/dev/null
in_root test ! -e $plugins/libfilter_elastica.so || fail "the plugin is still in $plugins"
tar -C "$root/work" -xzf "$out/$bundle.tar.gz"
cp "$src/packaging/meshlab2022/load_plugins.sh" "$root/work/"
rm -rf "$root/work/.local"
run env MESHLAB_TITLE="MeshLab 2025" xvfb-run -a -n "$(free_display)" -s "-screen 0 1600x900x24" bash /work/load_plugins.sh "/work/$bundle/libfilter_elastica.so" /work/load_plugins.png \
  || fail "Load Plugins did not take the file"
extra=$(cd "$root" && find work/.local -name libfilter_elastica.so -printf '/%h\n' | head -n1)
[[ -n "$extra" ]] || fail "MeshLab did not copy the plugin into its per-user plugin folder"
echo "MeshLab copied it into $extra"
cp "$root/work/load_plugins.png" "$out/"
in_meshlab "$plugins:$extra" /work/noisy.ply /work/fair_loaded.ply $ex/fairing.mlx /work/fair_run.ply 1e-5 \
  || fail "the fairing filter of the loaded plugin differs from elastica run (or did not run)"
step "done"
