#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The add-on's ctest entries; exit 77 (ctest SKIP_RETURN_CODE) when Blender (or Xvfb) is missing.
#   run.sh headless            test_addon.py in blender -b (PYTHONPATH: the module and the add-on)
#   run.sh gui OUT.png         shot.py in Blender's window under Xvfb, the screenshot into OUT.png
#   run.sh install             docs/blender.md's install line into a scratch HOME, then the installed
#                              add-on (enabled from the saved preferences, module from scripts/modules)
# Environment (set by CMake): ELASTICA_SOURCE_DIR, ELASTICA_BUILD_DIR, ELASTICA_DATA_DIR, PYTHONPATH.
set -euo pipefail
command -v blender >/dev/null || { echo "blender not installed: skipped (apt-get install blender)"; exit 77; }
here=$(cd "$(dirname "$0")" && pwd)
case "$1" in
  headless)
    exec blender -b --factory-startup --python-exit-code 1 --python-use-system-env --python "$here/test_addon.py" ;;
  gui)
    command -v Xvfb >/dev/null || { echo "Xvfb not installed: skipped"; exit 77; }
    mkdir -p "$(dirname "$2")"
    rm -f "$2"
    export HOME=$(mktemp -d)
    trap 'rm -rf "$HOME"' EXIT
    "$ELASTICA_SOURCE_DIR/scripts/with-xvfb.sh" -s "-screen 0 1280x800x24" blender --factory-startup --python-use-system-env \
      --python "$here/shot.py" -- "$2" ;;
  install)
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    # docs/blender.md's install lines as written, with this build folder for `build` and a scratch HOME.
    block=$(awk '/^## Install/{on=1; next} on && /^## /{exit} on && /^```sh$/{b=1; next} b && /^```$/{exit} b' \
      "$ELASTICA_SOURCE_DIR/docs/blender.md")
    [[ -n "$block" ]] || { echo "no sh block in docs/blender.md's Install section"; exit 1; }
    # The README shows the same line.
    grep -qF "$block" "$ELASTICA_SOURCE_DIR/README.md" || { echo "README.md's Blender line differs from docs/blender.md's"; exit 1; }
    echo "$block"
    (cd "$ELASTICA_SOURCE_DIR" && env -u PYTHONPATH HOME="$scratch" \
       bash -euo pipefail -c "${block//install.sh build/install.sh \"$ELASTICA_BUILD_DIR\"}")
    # A fresh Blender of that user: the add-on is enabled and finds the module without PYTHONPATH.
    env -u PYTHONPATH HOME="$scratch" BLENDER_USER_SCRIPTS="$scratch/blender-scripts" blender -b --python-exit-code 1 \
      --python-expr 'import bpy, elastica
assert "elastica_blender" in bpy.context.preferences.addons, "not enabled"
assert elastica.__file__.startswith("'"$scratch"'"), elastica.__file__
bpy.ops.mesh.primitive_ico_sphere_add(radius=2)
assert bpy.ops.mesh.elastica_curvature() == {"FINISHED"}
print("installed add-on: ok")' ;;
  *) echo "usage: $0 headless | gui OUT.png | install" >&2; exit 2 ;;
esac
