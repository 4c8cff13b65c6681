#!/usr/bin/env bash
# End-to-end: 'dynpos capability' on the virtual Gunnerus. Level 1 with every single failure:
# 36 directions, the worst case never above intact, the rose written; the table's notation;
# then a short level-3 rose (time domain) head-on and astern.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
"$exe" capability --json "$out/l1.json" --out "$out/rose" > "$out/l1.txt"
jq -e '.level == 1 and .failure == "worst" and (.points | length) == 36' "$out/l1.json" \
  > /dev/null || fail "level 1 document"
jq -e '[.points, .intact] | transpose | all(.[0].max_wind_mps <= .[1].max_wind_mps)' \
  "$out/l1.json" > /dev/null || fail "a failure above intact"
jq -e '(.cases | keys) == ["port", "rudder.port", "rudder.stb", "stb", "tunnel"]' "$out/l1.json" \
  > /dev/null || fail "single failures"
grep -q "^DP capability, level 1 .*DP capability-L1(" "$out/l1.txt" || fail "notation line"
grep -q "<svg" "$out/rose/rose.svg" || fail "no rose"
# JSON on stdout, the table on stderr.
"$exe" capability --failure none --direction-step 90 --json - 2> /dev/null > "$out/stdout.json"
jq -e '(.points | length) == 4 and .cases == {}' "$out/stdout.json" > /dev/null \
  || fail "--json -"
"$exe" capability --level 3 --failure none --direction-step 180 --duration 60 --settle 40 \
  --wind-tolerance 1 --json "$out/l3.json" > /dev/null
jq -e '.level == 3 and (.points | length) == 2 and .dynamic_allowance == 1 and
       .time_domain.footprint_m == 5 and
       all(.points[]; .limiting == "none" or .limiting == "position" or .limiting == "heading")' \
  "$out/l3.json" > /dev/null || fail "level 3 document"
echo ok
