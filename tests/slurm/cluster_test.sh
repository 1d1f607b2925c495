#!/usr/bin/env bash
# cluster_test.sh PAMSIM: the cluster path against a real Slurm. Starts a
# one-node cluster of its own under a temp folder (munged, slurmctld, slurmd from Debian's
# munge and slurm-wlm, on free loopback ports, with a config that touches nothing of the
# machine's), then as a cluster user would:
#   1. scripts/slurm/submit.sh submits tests/slurm/sweep.toml as a 2-task job array and the
#      merge job; the merged database must export exactly what a one-process sweep exports;
#   2. the same again, but shard 1 is cancelled with scancel part way (after some of its
#      trials are stored, before all), resubmitted alone (sbatch --array=1, as submit.sh's
#      comment says) and merged by hand: it resumes, and the merge again equals the
#      one-process sweep.
# Exit 0 passed, 1 failed, 77 skipped (one line saying why: not root, a daemon missing or not
# starting), which CTest reports as skipped, never as passed. Every wait is bounded.
set -euo pipefail
pamsim=$(realpath "${1:?usage: cluster_test.sh PAMSIM}")
root=$(cd "$(dirname "$0")/../.." && pwd)
sweep=$root/tests/slurm/sweep.toml
started=$SECONDS

skip() { echo "SKIP: slurm cluster test: $*"; exit 77; }
fail() { echo "FAIL: slurm cluster test: $*" >&2; exit 1; }

[ "$(id -u)" = 0 ] || skip "needs root to run munged, slurmctld and slurmd"
for tool in munged slurmctld slurmd sbatch squeue scancel sinfo; do
  command -v "$tool" > /dev/null || skip "$tool is not installed (make deps installs munge and slurm-wlm)"
done

work=$(mktemp -d /tmp/pamsim_slurm.XXXXXX)
stop_daemons() {
  for pid_file in "$work"/slurmd.pid "$work"/slurmctld.pid "$work"/munge/munged.pid; do
    [ -f "$pid_file" ] && kill "$(cat "$pid_file")" 2> /dev/null || true
  done
  sleep 0.5
  rm -rf "$work"
}
trap stop_daemons EXIT

# two free loopback ports, from the kernel
read -r ctld_port slurmd_port < <(/usr/bin/python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')

mkdir -p "$work"/{munge,spool,state,log}
chmod 700 "$work/munge"
head -c 1024 /dev/urandom > "$work/munge/munge.key"
chmod 400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/log/munged.log" \
  --seed-file="$work/munge/seed" || skip "munged did not start"

node=$(hostname)
cat > "$work/slurm.conf" << EOF
ClusterName=pamsimtest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$work/slurm.conf PAMSIM=$pamsim
slurmctld -f "$SLURM_CONF" || skip "slurmctld did not start: $(tail -n 1 "$work/log/slurmctld.log" 2> /dev/null)"
slurmd -f "$SLURM_CONF" || skip "slurmd did not start: $(tail -n 1 "$work/log/slurmd.log" 2> /dev/null)"
for _ in $(seq 60); do
  sinfo -h -o %t 2> /dev/null | grep -q idle && break
  sleep 0.5
done
sinfo -h -o %t 2> /dev/null | grep -q idle ||
  skip "the node did not come up: $(tail -n 1 "$work/log/slurmd.log" 2> /dev/null)"

# waits (at most 300 s) until no job of this cluster is pending or running
wait_for_jobs() {
  for _ in $(seq 600); do
    [ -z "$(squeue -h -o %i)" ] && return 0
    sleep 0.5
  done
  fail "jobs still queued after 300 s: $(squeue -h)"
}

# the number of trials stored in a sweep database (0 while it does not exist yet)
trials_in() {
  /usr/bin/python3 -c '
import sqlite3, sys
try:
    db = sqlite3.connect("file:" + sys.argv[1] + "?mode=ro", uri=True, timeout=5)
    print(db.execute("SELECT COUNT(*) FROM trials").fetchone()[0])
except sqlite3.Error:
    print(0)' "$1"
}

exported() { "$pamsim" export "$1" --csv "$1.csv" > /dev/null 2>&1 && cat "$1.csv"; }

"$pamsim" sweep "$sweep" --threads 2 --db "$work/ref.db" --quiet > /dev/null 2>&1 ||
  fail "the one-process sweep failed"
reference=$(exported "$work/ref.db")
total=$(($(wc -l <<< "$reference") - 1))

# 1. the job array and the merge job, as submit.sh submits them
cd "$root"
bash scripts/slurm/submit.sh "$sweep" 2 "$work/out" 1 > "$work/submit.log"
wait_for_jobs
[ -f "$work/out/sweep.db" ] || fail "no merged database: $(cat "$work/out/logs/"*.log)"
[ "$(exported "$work/out/sweep.db")" = "$reference" ] ||
  fail "the merged database differs from the one-process sweep"
echo "slurm cluster test: 2 shards and the merge equal the one-process sweep ($total trials)"

# 2. shard 1 cancelled part way, resubmitted alone, merged by hand
bash scripts/slurm/submit.sh "$sweep" 2 "$work/out2" 1 > "$work/submit2.log"
array=$(sed -n 's/.*job array \([0-9]*\).*/\1/p' "$work/submit2.log")
shard=$work/out2/sweep.shard-1-of-2.db
for _ in $(seq 600); do
  [ "$(trials_in "$shard")" -ge 5 ] && break
  sleep 0.1
done
scancel "${array}_1"
wait_for_jobs
kept=$(trials_in "$shard")
[ "$kept" -ge 5 ] && [ "$kept" -lt $((total / 2)) ] ||
  fail "shard 1 was not cancelled part way: $kept of $((total / 2)) trials stored"
[ ! -f "$work/out2/sweep.db" ] || fail "the merge ran although shard 1 was cancelled"
sbatch --parsable --array=1 --cpus-per-task=1 --output="$work/out2/logs/shard-1-again.log" \
  scripts/slurm/shard.sbatch "$sweep" "$work/out2" 2 > /dev/null
wait_for_jobs
[ "$(trials_in "$shard")" -eq $((total / 2)) ] ||
  fail "the resubmitted shard did not finish: $(cat "$work/out2/logs/shard-1-again.log")"
sbatch --parsable --output="$work/out2/logs/merge-again.log" scripts/slurm/merge.sbatch \
  "$work/out2" 2 > /dev/null
wait_for_jobs
[ "$(exported "$work/out2/sweep.db")" = "$reference" ] ||
  fail "after the cancelled shard's resumption the merge differs from the one-process sweep"
echo "slurm cluster test: shard 1 cancelled after $kept of $((total / 2)) trials, resubmitted," \
  "resumed; the merge equals the one-process sweep"
echo "slurm cluster test: passed in $((SECONDS - started)) s"
