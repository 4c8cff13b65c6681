#!/usr/bin/env bash
# End-to-end: 'dynpos identify thrust-map' back-calculates c₊ of the virtual Gunnerus' main
# propellers (8.13 kN/rps², table 3.2) from a simulated surge step log, and '--apply' puts the
# thrust back from shaft speed alone.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate surge-steps-forward --duration 60 --out "$out/run" > /dev/null
"$exe" identify thrust-map "$out/run/log.csv" --json "$out/map.json" > "$out/stdout.txt"
grep -q "^port .*8.130" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
# The logged thrust is the feedback of the map at the measured shaft speed, quantised to
# 0.01 kN: c₊ must come back within 0.1 %.
jq -e '.thrusters[] | select(.name == "stb") | (.c_pos - 8130 | fabs) < 8.13' "$out/map.json" > /dev/null \
  || { echo "stb c_pos off: $(jq -c '.thrusters' "$out/map.json")"; exit 1; }
# The tunnel did not run: its coefficients are missing (null), never 0.
jq -e '.thrusters[] | select(.name == "tunnel") | .c_pos == null and .c_neg == null' \
  "$out/map.json" > /dev/null || { echo "tunnel should be null"; exit 1; }
# Apply the vessel file's map to the shaft speed alone: the logged thrust comes back to within
# its quantisation (0.01 kN) plus the shaft-speed quantisation (0.1 rpm ≈ 0.02 kN at 57 rpm).
"$exe" identify thrust-map "$out/run/log.csv" --col time=time --apply --out "$out/applied.csv" \
  > /dev/null
paste -d, <(cut -d, -f1 "$out/run/log.csv") <(awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i ~ /^thrust.stb/) c=i} {print $c}' "$out/run/log.csv") \
  > "$out/logged.csv"
awk -F, 'NR==FNR { if (FNR > 1) logged[$1] = $2; next }
  FNR == 1 { for (i = 1; i <= NF; i++) if ($i ~ /^thrust.stb/) c = i; next }
  ($1 in logged) && logged[$1] != "" && $c != "" { n++; d = $c - logged[$1]; if (d < 0) d = -d;
    if (d > 0.05) { print "t=" $1 ": applied " $c " vs logged " logged[$1]; bad = 1; exit 1 } }
  END { if (n < 100) { print "compared only " n " rows"; exit 1 } exit bad }' \
  "$out/logged.csv" "$out/applied.csv"
echo "ok"
