#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A real single-node Slurm cluster for `elastica batch`: starts munged, slurmctld and slurmd on this
# machine (Debian's slurm-wlm and munge, configured in a temporary folder, on ports of their own),
# submits examples/slurm/fair-array.sbatch (an array of 4 shards) over the libcgal-demo meshes that
# scripts/setup.sh caches, waits for it, and checks that every mesh has its output, that the merged
# logs name every mesh once with status ok, and that the small meshes' outputs are the single-file
# command's bytes. Everything it started is stopped at the end; non-zero exit on any failure.
#
#   scripts/slurm-check.sh [BUILD_BIN_DIR]      (default build/bin; run as root, or with sudo)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(dirname "$here")
bin=$(cd "${1:-$repo/build/bin}" && pwd)
elastica=$bin/elastica
[[ -x $elastica ]] || { echo "slurm-check: no $elastica (build first)" >&2; exit 1; }
log() { echo "slurm-check: $*"; }
fail() { echo "slurm-check: FAILED: $*" >&2; exit 1; }
as_root() { if ((EUID == 0)); then "$@"; else sudo "$@"; fi; }

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  log "installing slurm-wlm and munge (Debian packages)"
  for try in 1 2 3; do
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge && break
    ((try < 3)) || fail "apt-get install slurm-wlm munge"
    sleep 10  # the dpkg lock may be busy
  done
fi

cache=${ELASTICA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/elastica}
meshes=$(ls -d "$cache"/cgal-data-*/meshes 2>/dev/null | sort -V | tail -n1)
[[ -d $meshes ]] || fail "no libcgal-demo meshes under $cache (run scripts/setup.sh)"

work=$(mktemp -d "${TMPDIR:-/tmp}/elastica-slurm.XXXXXX")
chmod 755 "$work"  # slurmd runs the job as this user; munged wants no group- or world-writable folder
pids=()
stop_all() {
  # Only the daemons this script started, by the pids they wrote.
  for f in slurmd slurmctld munged; do
    [[ -f $work/$f.pid ]] && kill "$(cat "$work/$f.pid")" 2>/dev/null || true
  done
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  sleep 1
  if [[ ${KEEP:-0} != 1 ]]; then rm -rf "$work"; else log "kept $work"; fi
}
trap stop_all EXIT

node=$(hostname -s)
port=$((20000 + $$ % 20000))
mkdir -p "$work/state" "$work/spool" "$work/in" "$work/out"
cp "$meshes"/*.off "$work/in/"

log "munged (key, socket and logs in $work)"
mungekey --create --keyfile="$work/munge.key" >/dev/null
chmod 600 "$work/munge.key"
munged --force --key-file="$work/munge.key" --socket="$work/munge.socket" --pid-file="$work/munged.pid" \
  --log-file="$work/munged.log" --seed-file="$work/munged.seed"
for _ in $(seq 50); do [[ -S $work/munge.socket ]] && break; sleep 0.1; done
munge -n --socket="$work/munge.socket" | unmunge --socket="$work/munge.socket" >/dev/null || fail "munge does not round-trip"

cat >"$work/slurm.conf" <<CONF
ClusterName=elastica-check
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=check Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf

log "slurmctld and slurmd (ports $port, $((port + 1)))"
slurmctld -i -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF" -N "$node"
for _ in $(seq 100); do
  state=$(sinfo -h -N -o %T 2>/dev/null || true)
  [[ $state == idle ]] && break
  sleep 0.2
done
[[ $state == idle ]] || { tail -5 "$work/slurmctld.log" "$work/slurmd.log" >&2; fail "the node is '$state', not idle"; }
log "node $node idle: $(sinfo -h -o '%P %D %c CPUs')"

SECONDS=0
log "sbatch --wait examples/slurm/fair-array.sbatch over $(ls "$work/in" | wc -l) meshes"
if ! timeout 900 sbatch --wait --chdir="$work" --export="ALL,ELASTICA=$elastica,IN=$work/in,OUT=$work/out" \
  "$repo/examples/slurm/fair-array.sbatch"; then
  tail -n 20 "$work"/elastica-fair-*.out >&2 || true
  fail "the array job failed (its tasks' outputs above)"
fi
log "array done in $SECONDS s (submission to the last task's end)"

# Every mesh has its output; the merged logs name each once, with status ok; four logs, four shards.
status=0
nlogs=$(ls "$work/out/logs"/fair-*.jsonl | wc -l)
((nlogs == 4)) || { echo "expected 4 logs, found $nlogs" >&2; status=1; }
cat "$work/out/logs"/fair-*.jsonl >"$work/merged.jsonl"
python3 - "$work/in" "$work/out" "$work/merged.jsonl" <<'PY' || status=1
import json, os, sys
inp, out, merged = sys.argv[1:]
lines = [json.loads(l) for l in open(merged)]
names = sorted(os.path.splitext(f)[0] for f in os.listdir(inp))
logged = sorted(os.path.splitext(os.path.basename(l["input"]))[0] for l in lines)
bad = [l for l in lines if l["status"] != "ok"]
missing = [n for n in names if not os.path.isfile(os.path.join(out, n + ".ply"))]
print(f"slurm-check: {len(lines)} log lines for {len(names)} meshes; {len(bad)} not ok; {len(missing)} outputs missing")
sys.exit(0 if logged == names and not bad and not missing else 1)
PY
for f in "$work/in"/*.off; do
  (($(stat -c %s "$f") < 200000)) || continue
  name=$(basename "$f" .off)
  OMP_NUM_THREADS=2 "$elastica" fair "$f" -o "$work/single-$name.ply" >/dev/null 2>&1 || { echo "single-file fair $name failed" >&2; status=1; }
  if cmp -s "$work/single-$name.ply" "$work/out/$name.ply"; then log "$name: the array's output is the single-file command's bytes"
  else echo "$name: the array's output differs from the single-file command's" >&2; status=1; fi
done
((status == 0)) || fail "see above (KEEP=1 keeps $work)"
log "ok: 4 shards, every mesh faired once, outputs checked"
