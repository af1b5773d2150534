#!/usr/bin/env bash
# Checks the "Layout" section of docs/architecture.md against the tree (run by ctest as readme_layout):
#  - every path it names (a word with a slash) exists;
#  - every top-level folder, every folder of vcg_core/ and every source file of the core's public
#    headers, of vcg_core/src/, vcg_core/io/ and app/ is named there (a file by its name or its stem);
#  - the core's private tiers include only downward: support <- operators <- mesh <- flow <-
#    restoration (a file of one tier includes "T/..." headers of its own tier or lower ones only).
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

[[ $fail == 0 ]] && echo "check-layout: the layout in $page matches the tree and the tiers include downward"
exit $fail
