#!/usr/bin/env bash
# End-to-end: 'dynpos simulate campaign' runs every built-in scenario into its own folder with a
# summary and an index page; each scenario's log is the same as when run alone with its seed.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate campaign --out "$out/all" --seed 3 --duration 20 > "$out/stdout.txt"
grep -q "report: .*index.html" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
for f in index.html summary.md summary.json; do
  [ -s "$out/all/$f" ] || { echo "missing $f"; exit 1; }
done
count=$(ls -d "$out"/all/*/ | wc -l)
[ "$count" -ge 7 ] || { echo "expected >= 7 scenario folders, got $count"; exit 1; }
for d in "$out"/all/*/; do
  [ -s "$d/log.csv" ] && [ -s "$d/truth.csv" ] && [ -s "$d/truth.json" ] \
    || { echo "incomplete $d"; exit 1; }
  rows=$(($(wc -l < "$d/log.csv") - 1))
  # 20 s at the scenario's log rate, both ends: 10 Hz, or 100 Hz for the lever-arm maneuver.
  expected=201
  [ "$(basename "$d")" = turning-circle ] && expected=2001
  [ "$rows" -eq "$expected" ] || { echo "$d: expected $expected rows, got $rows"; exit 1; }
done
# The seed a scenario gets in the campaign is in its truth; rerunning alone reproduces the log.
seed=$(grep -o '"seed": [0-9]*' "$out/all/yaw-steps/truth.json" | grep -o '[0-9]*$')
"$exe" simulate yaw-steps --out "$out/alone" --seed "$seed" --duration 20 > /dev/null
cmp "$out/all/yaw-steps/log.csv" "$out/alone/log.csv"
echo "ok: $count scenarios"
