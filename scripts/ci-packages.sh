#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian packages, built, checked, installed, used and removed (CI; run as root or with
# password-less sudo, after the README's build into BUILD_DIR):
#
#   scripts/ci-packages.sh [BUILD_DIR]        (default: build)
#
# 1. `cpack` in BUILD_DIR: BUILD_DIR/packages/{elastica,meshlab-plugin-elastica,python3-elastica,
#    blender-addon-elastica}_*.deb (packaging/packaging.cmake).
# 2. lintian (installed here with apt-get if missing) on each: any error fails.
# 3. `apt-get install` of the four files, then each used as a user would, from the system's paths:
#    - `elastica` from PATH fairs a bundled cage (data/cages/torus_quad_5x5.off) to the Clifford torus;
#    - Debian's meshlabserver (no private prefix: MeshLab's own plugin folder) runs
#      meshlab_plugin/examples/fairing.mlx on a noisy sphere, and the result equals `elastica run`'s
#      on the same script (positions within 1e-5 of the diagonal) and differs from the input;
#    - /usr/bin/python3 without PYTHONPATH imports elastica from /usr/lib/python3/dist-packages and
#      fairs with it;
#    - Blender --factory-startup enables the add-on from /usr/share/blender/scripts/addons and runs
#      its fairing operator on a noisy sphere.
# 4. `apt-get remove` of the four: no file of theirs is left, no folder they made, and the set of
#    installed packages is what it was before step 3.
# Prints each step's time. Exit status non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
src=$PWD
build=$(realpath -e "${1:-build}") || { echo "ci-packages: no build folder ${1:-build} (build first: README)" >&2; exit 1; }
packages=(elastica meshlab-plugin-elastica python3-elastica blender-addon-elastica)

t0=$SECONDS
step() { printf '\n== ci-packages [%3d s] %s\n' $((SECONDS - t0)) "$*"; }
fail() { printf 'ci-packages: FAIL: %s\n' "$*" >&2; exit 1; }
as_root() {
  if [[ $(id -u) -eq 0 ]]; then "$@"
  elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then sudo "$@"
  else fail "needs root or password-less sudo for: $*"
  fi
}
export DEBIAN_FRONTEND=noninteractive

step "tools: lintian"
if ! command -v lintian >/dev/null; then
  as_root apt-get update -qq
  as_root apt-get install -y -qq --no-install-recommends lintian >/dev/null
fi

step "cpack in $build"
rm -rf "$build/packages"
cpack --config "$build/CPackConfig.cmake" >"$build/cpack.log" 2>&1 || { cat "$build/cpack.log" >&2; fail "cpack failed"; }
grep -i "warning" "$build/cpack.log" >&2 || true
debs=()
for p in "${packages[@]}"; do
  f=$(ls "$build"/packages/${p}_*.deb 2>/dev/null | head -n1)
  [[ -n "$f" ]] || fail "cpack made no package $p (see $build/cpack.log)"
  debs+=("$f")
done
for f in "${debs[@]}"; do
  echo "--- $(basename "$f")"
  dpkg-deb -f "$f" Package Version Architecture Depends
  dpkg-deb -c "$f" | awk '{print "    " $6}' | grep -v '/$'
done

step "lintian"
lintian_out=$(lintian --tag-display-limit 0 "${debs[@]}" 2>&1) || true
echo "$lintian_out"
grep -q '^E: ' <<<"$lintian_out" && fail "lintian reports errors"

step "apt-get install"
work=$(mktemp -d)
installed=0
# On a failure after the install, the packages go again, so that a failed run leaves the system as it was.
trap 'rm -rf "$work"; ((installed)) && as_root apt-get remove -y -qq "${packages[@]}" >/dev/null 2>&1' EXIT
chmod 755 "$work"
# A copy installed before (an earlier run, a user) goes first, so that "before" is the system without them.
for p in "${packages[@]}"; do
  if dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null | grep -qx installed; then
    echo "  removing the installed $p first"
    as_root apt-get remove -y -qq "$p" >/dev/null
  fi
done
before=$(dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' | sort)
# Copies readable by apt's sandbox user, so apt does not warn about an unsandboxed download.
mkdir "$work/debs" && cp "${debs[@]}" "$work/debs/" && chmod -R a+rX "$work/debs"
installed=1
as_root apt-get install -y -qq --no-install-recommends "$work"/debs/*.deb >/dev/null
for p in "${packages[@]}"; do
  dpkg-query -W -f='${db:Status-Abbrev} ${Package} ${Version}\n' "$p"
done

step "elastica from PATH"
[[ $(command -v elastica) == /usr/bin/elastica ]] || fail "elastica on PATH is $(command -v elastica), not /usr/bin/elastica"
cd "$work"
elastica fair "$src/data/cages/torus_quad_5x5.off" -o clifford.ply --subdivide 2 --report clifford.json >/dev/null
python3 - <<'PY'
import json, math
r = json.load(open("clifford.json"))
e = r["mesh_energy_after"]
print(f"  Clifford torus from the cage: E = {e:.2f} (8 pi^2 = {8 * math.pi ** 2:.2f})")
assert abs(e / (8 * math.pi ** 2) - 1) < 0.03, e
PY

step "meshlabserver with the plugin from MeshLab's own folder"
plugin=$(dpkg -L meshlab-plugin-elastica | grep '/libfilter_elastica\.so$')
[[ $plugin == /usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_elastica.so ]] || fail "plugin installed at $plugin"
elastica generate icosphere --level 3 --noise 0.05 -o noisy.ply >/dev/null
HOME=$work "$src/scripts/with-xvfb.sh" meshlabserver -i noisy.ply -o meshlab.ply -s "$src/meshlab_plugin/examples/fairing.mlx" >meshlabserver.log 2>&1 \
  || { cat meshlabserver.log >&2; fail "meshlabserver failed"; }
grep -F "Discrete Elastica Fairing" meshlabserver.log | head -n3
elastica run -i noisy.ply -o run.ply -s "$src/meshlab_plugin/examples/fairing.mlx" >/dev/null

step "python3-elastica without PYTHONPATH (/usr/bin/python3), and the comparison above"
env -u PYTHONPATH /usr/bin/python3 - <<'PY'
import elastica
import numpy as np
assert elastica.__file__.startswith("/usr/lib/python3/dist-packages/"), elastica.__file__
print("  module:", elastica.__file__)
V0, F0 = elastica.read("noisy.ply")
Vm, Fm = elastica.read("meshlab.ply")
Vr, Fr = elastica.read("run.ply")
diag = float(np.linalg.norm(V0.max(0) - V0.min(0)))
assert Fm.shape == Fr.shape and (Fm == Fr).all(), (Fm.shape, Fr.shape)
same = np.abs(Vm - Vr).max() / diag
changed = Vm.shape != V0.shape or np.abs(Vm - V0).max() > 1e-3 * diag
print(f"  meshlabserver: {len(V0)} -> {len(Vm)} vertices; vs elastica run: {same:.2e} of the diagonal")
assert changed and same <= 1e-5
V, F, report = elastica.fair(V0, F0, feature_size=0)  # to the limit shape
print(f"  elastica.fair: {len(V0)} -> {len(V)} vertices, stop: {report['stop']}, E {report['energy_initial']:.1f} -> {report['energy_final']:.1f}")
assert report["energy_final"] < report["energy_initial"] / 2
PY

step "Blender: the add-on from the system add-on folder"
env -u PYTHONPATH HOME="$work" blender -b --factory-startup --python-exit-code 1 --python-expr '
import addon_utils, bpy, numpy as np, sys
mod = addon_utils.enable("elastica_blender", default_set=True, handle_error=None)
assert mod is not None, "the add-on did not enable"
assert mod.__file__ == "/usr/share/blender/scripts/addons/elastica_blender/__init__.py", mod.__file__
import elastica
assert elastica.__file__.startswith("/usr/lib/python3/dist-packages/"), elastica.__file__
bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=3, radius=1.0)
me = bpy.context.active_object.data
P = np.empty(3 * len(me.vertices), np.float32); me.vertices.foreach_get("co", P); P = P.reshape(-1, 3)
P *= (1 + 0.05 * np.random.default_rng(3).uniform(-1, 1, len(P)))[:, None]
me.vertices.foreach_set("co", P.ravel()); me.update()
def spread(P):
    r = np.linalg.norm(P - P.mean(0), axis=1); return (r.max() - r.min()) / r.mean()
before = spread(P)
assert bpy.ops.mesh.elastica_fair(feature_size=0) == {"FINISHED"}
Q = np.empty(3 * len(me.vertices), np.float32); me.vertices.foreach_get("co", Q); Q = Q.reshape(-1, 3)
print(f"  Blender: radius spread {before:.4f} -> {spread(Q):.4f}")
assert spread(Q) < before / 5
' >blender.log 2>&1 || { cat blender.log >&2; fail "Blender could not enable the add-on or run its operator"; }
grep -F "Blender: radius" blender.log

step "apt-get remove"
cd "$src"
files=()
for f in "${debs[@]}"; do
  while read -r path; do files+=("$path"); done < <(dpkg-deb -c "$f" | awk '{print substr($6, 2)}')
done
as_root apt-get remove -y -qq "${packages[@]}" >/dev/null
installed=0
after=$(dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' | sort)
[[ "$before" == "$after" ]] || { diff <(echo "$before") <(echo "$after") >&2; fail "the installed packages differ from before"; }
left=()
for path in "${files[@]}"; do
  [[ $path == / ]] && continue
  if [[ -d $path && ! -L $path ]]; then
    # A folder stays only if a package still installed owns it.
    [[ -e $path ]] && ! dpkg -S "${path%/}" >/dev/null 2>&1 && left+=("$path")
  elif [[ -e $path || -L $path ]]; then
    left+=("$path")
  fi
done
((${#left[@]} == 0)) || fail "left behind after apt-get remove: ${left[*]}"
echo "  nothing left: ${#files[@]} paths of the packages checked"

step "done"
