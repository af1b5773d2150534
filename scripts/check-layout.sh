#!/usr/bin/env bash
# Checks the README's "Layout" section against the tree (run by ctest as readme_layout):
#  - every path it names (a word with a slash) exists;
#  - every top-level folder, every folder of vcg_core/ and every source file of the core's public
#    headers, of vcg_core/src/, vcg_core/io/ and app/ is named there (a file by its name or its stem).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
block=$(awk '/^## Layout/{on=1; next} on && /^```$/{n++; if (n==2) exit; next} on && n==1' README.md)
[[ -n "$block" ]] || { echo "check-layout: no Layout block in README.md" >&2; exit 1; }
fail=0
missing() { echo "check-layout: $*" >&2; fail=1; }

# Paths named in the block, resolved against the folder they are indented under.
declare -a stack=()
while IFS= read -r line; do
  [[ "$line" =~ ^(\ {0,8})([^ ]+/) ]] || continue
  indent=$(( ${#BASH_REMATCH[1]} / 2 )); dir=${BASH_REMATCH[2]}
  stack=("${stack[@]:0:$indent}"); stack+=("$dir")
  path=$(printf '%s' "${stack[@]}")
  [[ -d "$path" ]] || missing "README names $path, which is not a folder"
done <<<"$block"

words=" $(tr -s ' ,();:' '\n' <<<"$block" | tr '\n' ' ') "
named() {  # a file is named by its full name or its stem
  local f=$1 stem=${1%.*}
  [[ "$words" == *" $f "* || "$words" == *" $stem "* ]]
}
for d in $(git ls-files --cached --others --exclude-standard | cut -d/ -f1 | sort -u); do
  [[ -d "$d" && "$d" != .* ]] || continue
  [[ "$words" == *" $d/ "* ]] || missing "top-level folder $d/ is not in the README's layout"
done
for d in $(git ls-files --cached --others --exclude-standard vcg_core | cut -d/ -f2-3 | grep / | sort -u); do
  [[ -d "vcg_core/$d" ]] || continue
  [[ "$block" == *"$d/"* || "$block" == *"${d#*/}/"* ]] || missing "folder vcg_core/$d/ is not in the README's layout"
done
for f in $(git ls-files --cached --others --exclude-standard vcg_core/include/elastica vcg_core/src vcg_core/io app | grep -E '\.(h|cpp)$'); do
  named "$(basename "$f")" || missing "$f is not named in the README's layout"
done
[[ $fail == 0 ]] && echo "check-layout: README layout matches the tree"
exit $fail
