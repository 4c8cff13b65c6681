#!/usr/bin/env bash
# Runs `dynpos montecarlo` as N shards, each its own process (as N jobs of a batch scheduler's
# job array or N ranks of mpirun would), then merges them. On one machine the shards run side by
# side; the merged document is the one a single run of the whole range writes.
#
#   examples/scaling/montecarlo-shards.sh SCENARIO A..B N OUT.json [dynpos options...]
#
# Each shard runs with --jobs 1 (one core per shard, as a scheduler gives each job its own);
# its document goes to OUT.json.shards/shard-i.json, kept for inspection.
set -euo pipefail
if [[ $# -lt 4 ]]; then
  echo "usage: $0 SCENARIO A..B N OUT.json [dynpos montecarlo options]" >&2
  exit 2
fi
scenario=$1 seeds=$2 shards=$3 out=$4
shift 4
dynpos=${DYNPOS:-dynpos}
dir="$out.shards"
mkdir -p "$dir"
pids=()
for ((i = 1; i <= shards; i++)); do
  "$dynpos" montecarlo "$scenario" --seeds "$seeds" --shard "$i/$shards" --jobs 1 "$@" \
    --json "$dir/shard-$i.json" > /dev/null &
  pids+=($!)
done
status=0
for pid in "${pids[@]}"; do wait "$pid" || status=$?; done
if [[ $status -ne 0 ]]; then
  echo "$0: a shard failed (exit $status)" >&2
  exit "$status"
fi
"$dynpos" montecarlo merge "$dir"/shard-*.json --json "$out"
