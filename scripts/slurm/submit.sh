#!/usr/bin/env bash
# submit.sh SWEEP.toml SHARDS [OUT] [CPUS]: runs a pamsim sweep on a Slurm cluster as a job
# array of SHARDS tasks (shard.sbatch: one `pamsim sweep --shard I/SHARDS` each, CPUS threads,
# default 16) and a merge job (merge.sbatch) that starts when every shard has succeeded and
# writes OUT/sweep.db (OUT default renders/<sweep name>, on a file system every node sees).
# Run it on the login node from the pamsim source folder, with `pamsim` on PATH (or PAMSIM
# naming the binary). A failed or preempted shard: resubmit just it,
#   sbatch --array=K --cpus-per-task=CPUS scripts/slurm/shard.sbatch SWEEP.toml OUT SHARDS
# (it resumes its database), then the merge: sbatch scripts/slurm/merge.sbatch OUT SHARDS.
set -euo pipefail
cd "$(dirname "$0")/../.."
sweep=${1:?usage: submit.sh SWEEP.toml SHARDS [OUT] [CPUS]}
shards=${2:?usage: submit.sh SWEEP.toml SHARDS [OUT] [CPUS]}
out=${3:-renders/$(basename "$sweep" .toml)}
cpus=${4:-16}
mkdir -p "$out/logs"
array=$(sbatch --parsable --array="0-$((shards - 1))" --cpus-per-task="$cpus" \
  --output="$out/logs/shard-%a.log" scripts/slurm/shard.sbatch "$sweep" "$out" "$shards")
# afterok: the merge waits for every shard; if one fails, Slurm cancels the merge
# (--kill-on-invalid-dep) rather than leave it pending: rerun that shard, then the merge
merge=$(sbatch --parsable --dependency="afterok:${array%%;*}" --kill-on-invalid-dep=yes \
  --output="$out/logs/merge.log" scripts/slurm/merge.sbatch "$out" "$shards")
echo "pamsim sweep: job array $array ($shards shards), merge job $merge -> $out/sweep.db"
