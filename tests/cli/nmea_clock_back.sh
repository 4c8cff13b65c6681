#!/usr/bin/env bash
# End-to-end: 'dynpos identify station-keeping' on a capture of two clocks, the second 1.5 s and
# then 1 h behind (tests/data/nmea/two_clocks.nmea). Its 40 sentences are dropped and counted as
# "time back"; the figures are those of the first clock alone: north and east std 1 m and 0.5 m
# (±1 m and ±0.5 m about a point), heading std 1.000025° (91° and 89°), as for station.nmea.
set -euo pipefail
exe="$1"; capture="$2"; out="$3"
rm -rf "$out"; mkdir -p "$out"
"$exe" identify station-keeping "$capture" --json "$out/sk.json" > "$out/stdout.txt"
fail() { echo "$1"; cat "$out/sk.json"; exit 1; }
jq -e '.input.files[0] | .records == 41 and .skipped["time back"] == 40' "$out/sk.json" \
  > /dev/null || fail "input counts"
grep -q "skipped: .*40 time back" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
jq -e '.position_samples == 20
       and ((.position_std_m.north - 1.0) | fabs) < 1e-3
       and ((.position_std_m.east - 0.5) | fabs) < 1e-3
       and ((.heading_deg.mean - 90) | fabs) < 1e-6
       and ((.heading_deg.std - 1.0) | fabs) < 1e-3' "$out/sk.json" > /dev/null || fail "figures"
echo ok
