#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# CI's check of the MeshLab 2022.02 plugin API (Debian 13's MeshLab), which this machine cannot
# install: the shared filter code (meshlab_plugin/filter_common.cpp, view_shading.cpp) and the 2022 plugin class
# (filter_elastica_2022.cpp) are compiled with -fsyntax-only against the headers and the vcglib of
# Debian 13's meshlab source package (fetched by scripts/setup.sh), -Werror for our code; moc runs
# on filter_elastica_2022.h with ELASTICA_MESHLAB_API=2022, as AUTOMOC does in a 2022 build, its
# output must carry FilterPlugin's IID and compile too. Nothing is linked (no 2022.02
# libmeshlab-common here). A missing tree is a failure, not a skip. Usage (ctest passes these):
#   meshlab2022_compile_check.sh TREE CXX MOC SOURCE_DIR WORK_DIR -- COMPILER_FLAGS...
set -euo pipefail
tree=$1 cxx=$2 moc=$3 src=$4 work=$5
shift 5
[[ ${1:-} == -- ]] && shift
flags=("$@")
fail() { printf 'FAIL: %s\n' "$*" >&2; exit 1; }

[[ -n $tree && -f $tree/.elastica-complete ]] ||
  fail "no MeshLab 2022.02 source tree${tree:+ at $tree} (Debian 13's meshlab source package): run scripts/setup.sh, or configure with -DMESHLAB_2022_SOURCE_DIR=<tree>"
version=$(tr -d '[:space:]' <"$tree/ML_VERSION")
[[ $version == 2022.02 ]] || fail "$tree is MeshLab $version, not 2022.02"
[[ -f $tree/src/common/plugins/interfaces/filter_plugin.h && -f $tree/src/vcglib/vcg/complex/complex.h ]] ||
  fail "$tree lacks src/common/plugins/interfaces/filter_plugin.h or src/vcglib"

api=(-DELASTICA_MESHLAB_API=2022 -DMESHLAB_SCALAR=float "-DMESHLAB_VERSION=$version")
includes=(-I"$src/meshlab_plugin" -I"$src/app/include" -I"$src/vcg_core/include" -isystem "$tree/src" -isystem "$tree/src/vcglib")
mkdir -p "$work"
start=$SECONDS
for file in filter_common.cpp view_shading.cpp filter_elastica_2022.cpp; do
  "$cxx" -std=c++17 -fPIC -fsyntax-only -Wall -Wextra -Werror "${api[@]}" "${includes[@]}" "${flags[@]}" \
    "$src/meshlab_plugin/$file" || fail "meshlab_plugin/$file does not compile against MeshLab $version ($tree)"
  echo "compiles against MeshLab $version: meshlab_plugin/$file"
done
"$moc" "${api[@]}" -I"$src/meshlab_plugin" -I"$tree/src" "$src/meshlab_plugin/filter_elastica_2022.h" \
  -o "$work/moc_filter_elastica_2022.cpp" || fail "moc failed on meshlab_plugin/filter_elastica_2022.h"
grep -q '"vcg.meshlab.FilterPlugin/1.0"' "$work/moc_filter_elastica_2022.cpp" ||
  fail "moc's output for filter_elastica_2022.h lacks the IID vcg.meshlab.FilterPlugin/1.0"
"$cxx" -std=c++17 -fPIC -fsyntax-only "${api[@]}" "${includes[@]}" "${flags[@]}" "$work/moc_filter_elastica_2022.cpp" ||
  fail "moc's output for filter_elastica_2022.h does not compile"
echo "moc output carries IID vcg.meshlab.FilterPlugin/1.0 and compiles"
echo "PASS: the MeshLab $version plugin API compiles ($tree; $((SECONDS - start)) s)"
