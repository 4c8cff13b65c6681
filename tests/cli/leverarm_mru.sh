#!/usr/bin/env bash
# End-to-end: 'dynpos leverarm mru' recovers the MRU lever arms of thesis table 4.6 from a
# 120 s turning circle of the virtual trial (motion from truth.csv, accelerations from log.csv),
# writes JSON and plots, and rejects a too-short log and NaN motion with exit 2 and no output.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate turning-circle --duration 120 --out "$out/run" > /dev/null
"$exe" leverarm mru "$out/run/truth.csv" --mru-log "mru1=$out/run/log.csv" \
  --mru-log "mru2=$out/run/log.csv" --json "$out/arms.json" --plots "$out/plots" > "$out/stdout.txt"
grep -q "^mru2 " "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
# Least squares reaches a few mm on 200 s (MRU noise 0.01 m/s²); 2 cm per axis is the target.
jq -e --slurpfile t "$out/run/truth.json" '
  [.arms[] | . as $a | $t[0].lever_arms[$a.name] as $l |
   (($a.x - $l[0]) | fabs) < 0.02 and (($a.y - $l[1]) | fabs) < 0.02 and
   (($a.z - $l[2]) | fabs) < 0.02] | length == 2 and all' "$out/arms.json" > /dev/null \
  || { echo "arms off: $(jq -c .arms "$out/arms.json")"; exit 1; }
jq -e '.method == "lsq" and (.arms[0].std | length) == 3 and .excitation.g_rank3_fraction > 0.5' \
  "$out/arms.json" > /dev/null || { echo "json shape"; exit 1; }
test -s "$out/plots/mru1.svg" && test -s "$out/plots/mru-excitation.svg"
# Too short: 3 s of log.
head -n 300 "$out/run/truth.csv" > "$out/short.csv"
set +e
"$exe" leverarm mru "$out/short.csv" --mru-log "mru1=$out/run/log.csv" --json "$out/short.json" \
  > /dev/null 2> "$out/short.err"
rc=$?
set -e
[ "$rc" = 2 ] || { echo "short log: exit $rc"; cat "$out/short.err"; exit 1; }
grep -q "too short" "$out/short.err" || { cat "$out/short.err"; exit 1; }
[ ! -e "$out/short.json" ] || { echo "half-written output"; exit 1; }
# NaN everywhere in roll: no valid sample.
awk -F, 'BEGIN{OFS=","} NR==1{for(i=1;i<=NF;i++) if($i ~ /^roll/) c=i; print; next} {$c="nan"; print}' \
  "$out/run/truth.csv" > "$out/nan.csv"
set +e
"$exe" leverarm mru "$out/nan.csv" --mru-log "mru1=$out/run/log.csv" > /dev/null 2> "$out/nan.err"
rc=$?
set -e
[ "$rc" = 2 ] && grep -q "roll" "$out/nan.err" || { echo "nan: exit $rc"; cat "$out/nan.err"; exit 1; }
echo "ok"
