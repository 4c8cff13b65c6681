#!/usr/bin/env bash
# montecarlo_shards.sh DYNPOS OUT_DIR SHARDS_SCRIPT: the turning circle over seeds 1..3 as two
# shard processes merged (examples/scaling/montecarlo-shards.sh) against one run with two jobs:
# the documents must be the same, byte for byte.
set -euo pipefail
dynpos=$1 out=$2 script=$3
rm -rf "$out"
mkdir -p "$out"
DYNPOS=$dynpos bash "$script" turning-circle 1..3 2 "$out/mc-sharded.json" > /dev/null
"$dynpos" montecarlo turning-circle --seeds 1..3 --jobs 2 --json "$out/mc-one.json" > /dev/null
cmp "$out/mc-one.json" "$out/mc-sharded.json"
echo IDENTICAL
