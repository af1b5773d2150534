#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The Blender add-on as an Extension, built, validated, installed and run in Blender 5.2 (Debian sid's
# blender 5.2.2, Python 3.14), on a Debian 12 machine (as root):
#
#   scripts/blender5.sh [--screenshot OUT.png]
#
# 1. The sid root of scripts/meshlab2025.sh (scripts/sid-build.sh; cached in $cache/sid-root), and in it
#    the Python module built for sid's Python 3.14 (pybind11 3.1).
# 2. The Extension: blender_addon/elastica_blender, the module as a wheel its staged manifest lists
#    (blender_addon/make_wheel.py; `wheels = [...]`), checked by `extension validate`, packed by `extension
#    build`, installed by `extension install-file -r user_default -e`; no "Policy violation" in any run.
# 3. Headless: blender_addon/tests/test_addon.py against the installed Extension
#    (bl_ext.user_default.elastica_blender): every operator on its meshes (fair, a selection, fill on the
#    bunny scan with its flank cut away, curvature, bad input, time limit, cancel).
# 4. Under Xvfb: blender_addon/tests/shot.py (the fairing invoked from the menu with its progress, the redo
#    panel, undo, Esc on a long run), its screenshot kept (and copied to OUT.png with --screenshot).
# Leaves $cache/blender5/: elastica_blender-<version>-linux_x64.zip, the screenshot. Exit 1 on any failure.
# First run on the development machine (2 shared cores): see docs/blender.md.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/debian-root.sh
root_script blender5 '3,19p' sid-root "$@"
source scripts/sid-build.sh

step "sid root ($root) and the Python module for its Blender"
sid_root_and_build elastica_python || fail "the sid root or the build failed"
module=$(cd "$root" && ls build/sid/python/elastica*.so | head -n1)
[[ -n $module ]] || fail "no module in /build/sid/python"
echo "module: /$module; Blender $(in_root blender --version 2>/dev/null | head -n1)"

step "the Extension: validate, build, install-file"
rm -rf "$root/work/blender5" && mkdir -p "$root/work/blender5/stage" "$out"
cp -r "$src/blender_addon/elastica_blender" "$root/work/blender5/stage/"
rm -rf "$root/work/blender5/stage/elastica_blender/__pycache__"
# The module as a wheel the staged manifest lists (a top-level module the add-on put into sys.modules
# itself was a policy violation for Blender 5.2); Blender installs it onto its own path.
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' "$src/blender_addon/elastica_blender/blender_manifest.toml")
wheel=$(in_root python3 /src/elastica/blender_addon/make_wheel.py "/$module" "$version" /work/blender5/stage/elastica_blender/wheels) \
  || fail "no wheel made from /$module"
sed -i "/^\[build\]/i wheels = [\"./wheels/$(basename "$wheel")\"]\n" "$root/work/blender5/stage/elastica_blender/blender_manifest.toml"
echo "wheel: $wheel ($(grep '^wheels' "$root/work/blender5/stage/elastica_blender/blender_manifest.toml"))"
b5() { in_root env HOME=/work/blender5/home OMP_NUM_THREADS=1 "$@"; }
b5 blender --command extension validate /work/blender5/stage/elastica_blender 2>&1 | tee "$root/work/blender5/validate.log" | grep -v 'WARNING Could not get a list of mounted'
grep -q '^Success' "$root/work/blender5/validate.log" || fail "extension validate did not succeed"
b5 blender --command extension build --source-dir /work/blender5/stage/elastica_blender --output-dir /work/blender5 --split-platforms \
  2>&1 | grep -v 'WARNING Could not get a list of mounted' || fail "extension build failed"
zip=$(cd "$root" && ls work/blender5/elastica_blender-*.zip | head -n1)
[[ -n $zip ]] || fail "extension build wrote no package"
b5 blender --command extension validate "/$zip" >/dev/null 2>&1 || fail "extension validate refused the package /$zip"
b5 blender --command extension install-file -r user_default -e "/$zip" 2>&1 | tee "$root/work/blender5/install.log" \
  | grep -v 'WARNING Could not get a list of mounted' || fail "extension install-file failed"
b5 blender --command extension list 2>/dev/null | tee "$root/work/blender5/list.log" | grep -i elastica || fail "the Extension is not listed after install-file"
cp "$root/$zip" "$out/"
# The add-on's `import elastica` must find the wheel Blender installed, not a copy in the Extension's folder.
from=$(b5 blender -b --python-exit-code 1 --python-expr 'import elastica; print("ELASTICA_FROM=" + elastica.__file__)' 2>/dev/null \
  | sed -n 's/^ELASTICA_FROM=//p')
[[ $from == */extensions/.local/lib/python3*/site-packages/elastica.* ]] || fail "elastica is imported from '$from', not from the installed wheel"
echo "elastica imported from $from"

step "the operators headless in Blender 5.2 (test_addon.py against the installed Extension)"
addon_env=(ELASTICA_ADDON_MODULE=bl_ext.user_default.elastica_blender ELASTICA_DATA_DIR=/src/elastica/data
  ELASTICA_SOURCE_DIR=/src/elastica ELASTICA_BUILD_DIR=/build/sid PYTHONDONTWRITEBYTECODE=1)
b5 env "${addon_env[@]}" blender -b --python-exit-code 1 --python /src/elastica/blender_addon/tests/test_addon.py \
  >"$out/headless.log" 2>&1 || { tail -n 30 "$out/headless.log" >&2; fail "the add-on's tests failed in Blender 5.2 (log: $out/headless.log)"; }
grep -E '^\[ +(OK|FAIL) +\]|passed' "$out/headless.log"

step "Blender 5.2's window under Xvfb: menu, progress, redo panel, undo, Esc"
b5 env "${addon_env[@]}" ELASTICA_X_SCREENSHOT=/work/blender5/window.png xvfb-run -a -n "$(free_display)" -s "-screen 0 1280x800x24" \
  blender --python /src/elastica/blender_addon/tests/shot.py -- /work/blender5/redo_panel.png >"$out/gui.log" 2>&1 \
  || { tail -n 30 "$out/gui.log" >&2; fail "the GUI run failed in Blender 5.2 (log: $out/gui.log)"; }
grep '^shot' "$out/gui.log" || true
cp "$root/work/blender5/redo_panel.png" "$root/work/blender5/window.png" "$out/"
# The X server's picture (import): Blender 5.2's own screenshot operator wrote a black image under Xvfb.
[[ -z $shot ]] || { mkdir -p "$(dirname "$shot")" && cp "$root/work/blender5/window.png" "$shot" && echo "screenshot: $shot"; }
# Blender's policy: no top-level module put into sys.modules by the add-on, in any of its runs.
! grep -h 'Policy violation' "$root"/work/blender5/{validate,install,list}.log "$out/headless.log" "$out/gui.log" \
  || fail "Blender reported a policy violation"
echo "no policy violation in validate, install-file, extension list, the headless and the GUI runs"
step "done"
