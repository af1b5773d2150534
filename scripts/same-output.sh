#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Same input, same output: runs scripts/golden-outputs.sh at each thread count given (default 1
# and 2) and fails on any byte that differs between them (meshes and transcripts). CI runs it.
#
#   scripts/same-output.sh BUILD_BIN_DIR [THREADS...]
#
# The outputs stay in ${TMPDIR:-/tmp}/elastica-same-output/threads-N for a look after a failure.
set -euo pipefail
bin=${1:?usage: same-output.sh BUILD_BIN_DIR [THREADS...]}
shift
counts=("$@")
((${#counts[@]} > 0)) || counts=(1 2)
here=$(cd "$(dirname "$0")" && pwd)
work=${TMPDIR:-/tmp}/elastica-same-output
rm -rf "$work"
for n in "${counts[@]}"; do
  echo "same-output: golden outputs on $n thread(s)"
  "$here/golden-outputs.sh" "$bin" "$work/threads-$n" "$n"
done
status=0
first=${counts[0]}
for n in "${counts[@]:1}"; do
  if ! diff "$work/threads-$first/SHA256SUMS" "$work/threads-$n/SHA256SUMS"; then
    echo "same-output: FAILED: outputs on $first and $n threads differ (lines above; files in $work)" >&2
    status=1
  fi
done
((status == 0)) && echo "same-output: $(wc -l <"$work/threads-$first/SHA256SUMS") files byte-identical on ${counts[*]} threads"
exit $status
