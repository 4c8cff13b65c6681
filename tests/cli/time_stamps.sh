#!/usr/bin/env bash
# End-to-end: 'dynpos identify step' on short_steps.csv with its time column rewritten as ISO 8601
# stamps at +02:00 that cross midnight (23:59:30 → 00:00:40 the next day): the same steps and
# time constant as with plain seconds. A repeated stamp is an error naming the line and the
# detected form; --time-order drop-duplicates reads on.
set -euo pipefail
exe="$1"; out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$out"; mkdir -p "$out"
# t [s] → 2024-05-01T23:59:30+02:00 + t, to the millisecond.
awk -F, 'NR == 1 { $1 = "Time (local)"; print; next }
  { s = 86370 + $1; day = 1 + int(s / 86400); r = s - 86400 * int(s / 86400);
    h = int(r / 3600); m = int((r - 3600 * h) / 60); sec = r - 3600 * h - 60 * m;
    $1 = sprintf("2024-05-%02dT%02d:%02d:%06.3f+02:00", day, h, m, sec); print }' OFS=, \
  "$here/short_steps.csv" > "$out/iso_steps.csv"
grep -q "^2024-05-02T00:00:00.000+02:00," "$out/iso_steps.csv" || { echo "no midnight row"; exit 1; }
"$exe" identify step "$out/iso_steps.csv" --col time="Time (local)" --col input=cmd \
  --col output=response --json "$out/steps.json" > "$out/stdout.txt"
grep -q "2 step(s)" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
# The same noise-free FOPDT (T = 3 s) as identify_step.sh: 1 % as there.
awk '$1 == "\"T\":" && /^      "/ { v = $2; sub(/,$/, "", v); n++; if (v < 2.97 || v > 3.03) bad = 1 }
     END { exit (n == 2 && !bad) ? 0 : 1 }' "$out/steps.json" || { echo "T off"; exit 1; }

# Row 40 repeated: an error with the line, the column and the detected form.
awk 'NR == 41 { print } { print }' "$out/iso_steps.csv" > "$out/iso_repeat.csv"
set +e
"$exe" identify step "$out/iso_repeat.csv" --col time="Time (local)" --col input=cmd \
  --col output=response > "$out/repeat.txt" 2>&1
code=$?
set -e
[ "$code" = 2 ] || { echo "exit code $code"; cat "$out/repeat.txt"; exit 1; }
grep -q "iso_repeat.csv:42:1 (Time (local)): time '2024-05-01T23:59:33.900+02:00' (3.9 s) repeats.*read as iso8601" \
  "$out/repeat.txt" || { cat "$out/repeat.txt"; exit 1; }
"$exe" identify step "$out/iso_repeat.csv" --col time="Time (local)" --col input=cmd \
  --col output=response --time-order drop-duplicates > "$out/dropped.txt"
grep -q "2 step(s)" "$out/dropped.txt" || { cat "$out/dropped.txt"; exit 1; }
echo "ok"
