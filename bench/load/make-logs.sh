#!/usr/bin/env bash
# Writes the load-test logs into DIR (default: the temporary folder):
#   day_60cols.csv   24 h at 100 Hz, 60 columns (time, command, fast, slow, aux0 … aux55), ~3.5 GB
#   ten_days_60cols.csv  the same day ten times over, times running on (240 h), ~35 GB
# The day comes from the benchmark log24h_bench (BM_Day24hCsv/56); build the release preset
# first. Needs about 40 GB free.
set -euo pipefail
cd "$(dirname "$0")/../.."
dir="${1:-${TMPDIR:-/tmp}}"
day="$dir/day_60cols.csv"
if [ ! -s "$day" ]; then
  (cd "$dir" && TMPDIR="$dir" DYNPOS_BENCH_KEEP_CSV=1 "$OLDPWD/build/release/bench/log24h_bench" \
    --benchmark_filter='BM_Day24hCsv/56' >/dev/null)
  mv "$dir/dynpos_bench_day_60cols.csv" "$day"
fi
ten="$dir/ten_days_60cols.csv"
if [ ! -s "$ten" ]; then
  head -1 "$day" >"$ten.part"
  for k in 0 1 2 3 4 5 6 7 8 9; do
    # Only the time cell is rewritten: day k runs from k·86400 s.
    tail -n +2 "$day" | awk -v off=$((k * 86400)) \
      '{ i = index($0, ","); printf "%.2f%s\n", substr($0, 1, i - 1) + off, substr($0, i) }' \
      >>"$ten.part"
  done
  mv "$ten.part" "$ten"
fi
ls -l "$day" "$ten"
