#!/usr/bin/env bash
# A Slurm job array of `dynpos montecarlo` shards: one task per shard, one core each.
#   sbatch --array=1-100 examples/scaling/montecarlo-slurm.sh surge-steps-forward 1..100000 mc
# then, when the array is done (sbatch --dependency=afterok:JOBID ... or by hand):
#   dynpos montecarlo merge mc/shard-*.json --json mc.json
#SBATCH --cpus-per-task=1
#SBATCH --mem=1G
set -euo pipefail
scenario=$1 seeds=$2 dir=$3
mkdir -p "$dir"
exec dynpos montecarlo "$scenario" --seeds "$seeds" \
  --shard "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT" --jobs 1 \
  --work-dir "${TMPDIR:-/tmp}" --json "$dir/shard-$SLURM_ARRAY_TASK_ID.json"
