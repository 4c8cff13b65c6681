#!/usr/bin/env bash
# One `dynpos montecarlo` shard per MPI rank, started by Open MPI (Debian: openmpi-bin):
#   mpirun -n 64 --hostfile hosts examples/scaling/montecarlo-mpirun.sh yaw-steps 1..6400 mc
#   dynpos montecarlo merge mc/shard-*.json --json mc.json
# The ranks do not talk to each other: mpirun only places and starts them; each writes its own
# shard document into DIR (a folder every host can write, e.g. on a shared file system).
set -euo pipefail
scenario=$1 seeds=$2 dir=$3
rank=${OMPI_COMM_WORLD_RANK:?run this under mpirun (Open MPI)}
size=${OMPI_COMM_WORLD_SIZE:?run this under mpirun (Open MPI)}
mkdir -p "$dir"
exec dynpos montecarlo "$scenario" --seeds "$seeds" --shard "$((rank + 1))/$size" --jobs 1 \
  --json "$dir/shard-$((rank + 1)).json"
