#!/usr/bin/env bash
# The load test: identify step and identify station-keeping on the logs of make-logs.sh, whole
# and with a window, each timed with its peak memory (GNU time: wall s, peak RSS kB).
#   bench/load/run.sh [DIR]     DIR as given to make-logs.sh
# The figures are in docs/reliability.md ("Load").
set -euo pipefail
cd "$(dirname "$0")/../.."
dir="${1:-${TMPDIR:-/tmp}}"
dynpos=build/release/bin/dynpos
step=(--col input=command --col output=fast)
sk=(--col north=aux0 --col east=aux1 --unit north=m --unit east=m)
for log in "$dir/day_60cols.csv" "$dir/ten_days_60cols.csv"; do
  size=$(stat -c %s "$log")
  mid=$(awk -v s="$size" 'BEGIN { print (s > 1e10 ? 432000 : 43200) }')
  for run in "identify step|${step[*]}" "identify step|${step[*]} --from $((mid - 100)) --to $((mid + 200))" \
             "identify station-keeping|${sk[*]}" \
             "identify station-keeping|${sk[*]} --from $mid --to $((mid + 200))"; do
    cmd="${run%%|*}" args="${run#*|}"
    # shellcheck disable=SC2086
    /usr/bin/time -f "%e %M" -o /tmp/dynpos-load-time $dynpos $cmd "$log" $args >/dev/null
    read -r wall rss </tmp/dynpos-load-time
    window=$(echo "$args" | grep -o -- '--from.*' || echo "whole")
    awk -v f="$(basename "$log")" -v s="$size" -v c="$cmd" -v w="$window" -v t="$wall" -v m="$rss" \
      'BEGIN { printf "%-20s %5.1f GB  %-25s %-24s %7.1f s  %7.0f MB\n", f, s / 1e9, c, w, t, m / 1024 }'
  done
done
