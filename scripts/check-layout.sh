#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Checks the "Layout" section of docs/architecture.md against the tree (run by ctest as readme_layout):
#  - every path it names (a word with a slash) exists;
#  - every top-level folder, every folder of vcg_core/ and every source file of the core's public
#    headers, of vcg_core/src/, vcg_core/io/ and app/ is named there (a file by its name or its stem);
#  - the core's private tiers include only downward: support <- operators <- mesh <- flow <-
#    restoration (a file of one tier includes "T/..." headers of its own tier or lower ones only),
#    and never by a relative path ("../"), which would get past the include roots that make the
#    build enforce the same rule (vcg_core/CMakeLists.txt);
#  - the tests include only downward too: a test program tests a tier, and its files may include the
#    private headers of that tier and the tiers below it (core_tests: operators, mesh and flow, so up
#    to flow/; restoration_tests: up to restoration/); every other test program (real meshes, I/O,
#    the commands, the app, fuzzing, the plugin) tests through the public API and includes no
#    private header. A tests/support/ header counts as part of each test file that includes it; a
#    tests/support/ source is linked into every test program and includes no private header.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
page=docs/architecture.md
block=$(awk '/^## Layout/{on=1; next} on && /^```$/{n++; if (n==2) exit; next} on && n==1' "$page")
[[ -n "$block" ]] || { echo "check-layout: no Layout block in $page" >&2; exit 1; }
fail=0
missing() { echo "check-layout: $*" >&2; fail=1; }

# Paths named in the block, resolved against the folder they are indented under.
declare -a stack=()
while IFS= read -r line; do
  [[ "$line" =~ ^(\ {0,8})([^ ]+/) ]] || continue
  indent=$(( ${#BASH_REMATCH[1]} / 2 )); dir=${BASH_REMATCH[2]}
  stack=("${stack[@]:0:$indent}"); stack+=("$dir")
  path=$(printf '%s' "${stack[@]}")
  [[ -d "$path" ]] || missing "$page names $path, which is not a folder"
done <<<"$block"

words=" $(tr -s ' ,();:' '\n' <<<"$block" | tr '\n' ' ') "
named() {  # a file is named by its full name or its stem
  local f=$1 stem=${1%.*}
  [[ "$words" == *" $f "* || "$words" == *" $stem "* ]]
}
for d in $(git ls-files --cached --others --exclude-standard | cut -d/ -f1 | sort -u); do
  [[ -d "$d" && "$d" != .* ]] || continue
  [[ "$words" == *" $d/ "* ]] || missing "top-level folder $d/ is not in $page's layout"
done
for d in $(git ls-files --cached --others --exclude-standard vcg_core | cut -d/ -f2-3 | grep / | sort -u); do
  [[ -d "vcg_core/$d" ]] || continue
  [[ "$block" == *"$d/"* || "$block" == *"${d#*/}/"* ]] || missing "folder vcg_core/$d/ is not in $page's layout"
done
for f in $(git ls-files --cached --others --exclude-standard vcg_core/include/elastica vcg_core/src vcg_core/io app | grep -E '\.(h|cpp)$'); do
  named "$(basename "$f")" || missing "$f is not named in $page's layout"
done
tiers=(support operators mesh flow restoration)
for ((i = 0; i < ${#tiers[@]}; ++i)); do
  for ((j = i + 1; j < ${#tiers[@]}; ++j)); do
    while IFS= read -r hit; do
      [[ -n "$hit" ]] && missing "$hit: the ${tiers[i]} tier includes the ${tiers[j]} tier above it"
    done < <(grep -rn "#include \"${tiers[j]}/" "vcg_core/src/${tiers[i]}" 2>/dev/null || true)
  done
done

while IFS= read -r hit; do
  [[ -n "$hit" ]] && missing "$hit: a relative include in the core's tiers (spell it \"tier/name.h\")"
done < <(grep -rn '#include "\.\./' vcg_core/src 2>/dev/null || true)

# The tests. The tier of a private include "T/name.h" (its index in tiers), or nothing.
tier_of() {
  local i
  for ((i = 0; i < ${#tiers[@]}; ++i)); do [[ "$1" == "${tiers[i]}/"* ]] && { echo "$i"; return; }; done
}
# The .cpp files of test program $1 as tests/CMakeLists.txt lists them in its add_executable.
sources_of() {
  awk -v name="$1" '
    $0 ~ "add_executable\\(" name "([ )]|$)" { on = 1 }
    on { n = split($0, w, /[ \t()]+/); for (i = 1; i <= n; ++i) if (w[i] ~ /\.cpp$/) print w[i]; if ($0 ~ /\)/) on = 0 }
  ' tests/CMakeLists.txt
}
declare -A testTier=()
for program in core_tests:flow restoration_tests:restoration; do
  for f in $(sources_of "${program%%:*}"); do testTier[$f]=${program#*:}; done
done
[[ ${#testTier[@]} -gt 0 ]] || missing "no core_tests or restoration_tests sources found in tests/CMakeLists.txt"
private_includes() {  # "file:line: header" for each private include of $1
  grep -Hn -E '#include "('"$(IFS='|'; echo "${tiers[*]}")"')/' "$1" | sed -E 's/^([^:]*:[0-9]+):.*#include "([^"]*)".*/\1: \2/' || true
}
for f in $(git ls-files --cached --others --exclude-standard tests | grep -E '\.(h|cpp)$'); do
  [[ "$f" == tests/support/*.h ]] && continue   # checked as part of the files that include them
  name=${f#tests/}
  top=-1; [[ -n "${testTier[$name]:-}" ]] && top=$(tier_of "${testTier[$name]}/")
  files=("$f")   # and the tests/support/ headers it includes, directly or through one another
  for ((k = 0; k < ${#files[@]}; ++k)); do
    for h in $(grep -ho '#include "[a-z_]*\.h"' "${files[k]}" | sed -E 's/.*"(.*)"/\1/'); do
      [[ -f tests/support/$h && " ${files[*]} " != *" tests/support/$h "* ]] && files+=("tests/support/$h")
    done
  done
  for g in "${files[@]}"; do
    while IFS= read -r hit; do
      [[ -n "$hit" ]] || continue
      t=$(tier_of "${hit##*: }")
      if (( t > top )); then
        if (( top < 0 )); then missing "$hit, in $f: a test program of the public API includes a private header"
        else missing "$hit, in $f: a test of tiers up to ${tiers[top]} includes the ${tiers[t]} tier"; fi
      fi
    done < <(private_includes "$g")
  done
done

[[ $fail == 0 ]] && echo "check-layout: the layout in $page matches the tree, and the tiers and the tests include downward"
exit $fail
