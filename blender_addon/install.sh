#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Blender add-on elastica_blender for the current user (no root) and enables it.
#
#   blender_addon/install.sh BUILD_DIR
#
# Copies blender_addon/elastica_blender/ to <scripts>/addons/ with the built Python module
# (BUILD_DIR/python/elastica*.so) inside it, and the module to <scripts>/modules/ too (on Blender's
# module path, for scripts; `blender --factory-startup` leaves that folder off the path and the
# add-on then loads its own copy), then enables the add-on in Blender's saved preferences. <scripts> is $BLENDER_USER_SCRIPTS if set (then keep it set
# when you start Blender), else Blender's own user scripts folder (~/.config/blender/3.4/scripts).
# $BLENDER names the blender executable (default: blender). Run it again after a rebuild.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: $0 BUILD_DIR (the CMake build folder, e.g. build)}
blender=${BLENDER:-blender}
command -v "$blender" >/dev/null || { echo "install.sh: '$blender' not found (apt-get install blender)" >&2; exit 1; }
shopt -s nullglob
modules=("$build"/python/elastica*.so)
((${#modules[@]} == 1)) || { echo "install.sh: no built module in $build/python (build the project first)" >&2; exit 1; }
scripts=${BLENDER_USER_SCRIPTS:-$("$blender" -b --factory-startup --python-expr \
  'import bpy; print("SCRIPTS=" + bpy.utils.script_path_user())' 2>/dev/null | sed -n 's/^SCRIPTS=//p')}
[[ -n "$scripts" ]] || { echo "install.sh: could not ask $blender for its user scripts folder" >&2; exit 1; }
mkdir -p "$scripts/addons" "$scripts/modules"
rm -rf "$scripts/addons/elastica_blender"
mkdir "$scripts/addons/elastica_blender"
cp "$here"/elastica_blender/*.py "$scripts/addons/elastica_blender/"
cp "${modules[0]}" "$scripts/addons/elastica_blender/"
cp "${modules[0]}" "$scripts/modules/"
BLENDER_USER_SCRIPTS="$scripts" "$blender" -b --python-exit-code 1 --python-expr \
  'import bpy; bpy.ops.preferences.addon_enable(module="elastica_blender"); bpy.ops.wm.save_userpref()' >/dev/null
echo "install.sh: elastica_blender installed into $scripts and enabled"
