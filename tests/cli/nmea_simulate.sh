#!/usr/bin/env bash
# End-to-end: dynpos simulate writes gnss1.nmea … gnss3.nmea beside log.csv: one GGA per fix of
# the antenna in log.csv, UTC = start_utc (default 2014-08-27T10:00:00Z) + t, every checksum
# right (XOR of the bytes between '$' and '*'), CR LF line ends, byte-identical for a seed.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate turning-circle --duration 30 --out "$out/a" --seed 4 > /dev/null
"$exe" simulate turning-circle --duration 30 --out "$out/b" --seed 4 > /dev/null
grep -q '"start_utc": "2014-08-27T10:00:00Z"' "$out/a/truth.json" \
  || { echo "truth.json lacks start_utc"; exit 1; }
for k in 1 2 3; do
  f="$out/a/gnss$k.nmea"
  [ -s "$f" ] || { echo "gnss$k.nmea missing or empty"; exit 1; }
  cmp "$f" "$out/b/gnss$k.nmea"
  # Fixes in log.csv: rows with a gnssK.lat value.
  col=$(head -1 "$out/a/log.csv" | tr ',' '\n' | grep -n "^gnss$k.lat " | cut -d: -f1)
  fixes=$(awk -F, -v c="$col" 'NR > 1 && $c != ""' "$out/a/log.csv" | wc -l)
  ggas=$(grep -c '^\$GNGGA,' "$f")
  [ "$fixes" -eq "$ggas" ] || { echo "gnss$k: $fixes fixes in log.csv, $ggas GGA"; exit 1; }
  for type in GNRMC GNVTG HEHDT; do
    n=$(grep -c "^\\\$$type," "$f")
    [ "$n" -eq "$ggas" ] || { echo "gnss$k: $n $type for $ggas GGA"; exit 1; }
  done
  # The first fix's UTC: 10:00:00 + its log time.
  t0=$(awk -F, -v c="$col" 'NR > 1 && $c != "" { print $1; exit }' "$out/a/log.csv")
  want=$(awk -v t="$t0" 'BEGIN { s = 36000 + t; printf "%02d%02d%06.3f", int(s / 3600),
                                  int(s / 60) % 60, s - 60 * int(s / 60) }')
  head -1 "$f" | grep -q "^\$GNGGA,$want," \
    || { echo "gnss$k: first GGA '$(head -1 "$f")' is not at $want"; exit 1; }
  grep -q '^\$GNRMC,[^,]*,A,.*,270814,' "$f" || { echo "gnss$k: RMC date is not 270814"; exit 1; }
  # Every line ends in CR LF and carries the right checksum.
  lines=0
  while IFS= read -r line; do
    [ "${line: -1}" = $'\r' ] || { echo "gnss$k: no CR LF: $line"; exit 1; }
    line="${line%$'\r'}"
    body="${line#\$}"; body="${body%\**}"
    sum=0
    for ((i = 0; i < ${#body}; i++)); do
      printf -v code '%d' "'${body:i:1}"
      sum=$((sum ^ code))
    done
    printf -v hex '%02X' "$sum"
    [ "${line##*\*}" = "$hex" ] || { echo "gnss$k: checksum ${line##*\*}, expected $hex: $line"; exit 1; }
    lines=$((lines + 1))
  done < "$f"
done
if ls -A "$out/a" | grep -q tmp; then echo "temporary files left: $(ls -A "$out/a")"; exit 1; fi
echo "ok: $ggas fixes per antenna, $lines sentences in gnss3.nmea, checksums right"
