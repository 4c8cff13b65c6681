#!/usr/bin/env bash
# End-to-end: 'dynpos consequence' on simulated pure-DP logs. The 2014 Gunnerus (the model's
# actuators) at heading 0 has the tunnel's loss as its worst case with a wide margin; at
# heading 90 the beam load cannot be held with a propeller lost (its rudder has no slipstream
# astern and too little ahead: `capability --failure port` holds nothing off the bow either).
# The 2015 layout (two azimuths and a tunnel) loses sway and yaw together with bus "port".
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
map=(--col north=gnss1.north --col east=gnss1.east --col roll=mru1.roll --col pitch=mru1.pitch
     --arm 0.202,-0.611,-13.891 --tp 7)
"$exe" simulate pure-dp --duration 900 --out "$out/run" > /dev/null
"$exe" consequence "$out/run/log.csv" "${map[@]}" --out "$out/points.csv" --json "$out/c.json" \
  > "$out/stdout.txt"
grep -q "smallest margin" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
jq -e '.layout == "model" and .cases == ["port", "stb", "rudder.port", "rudder.stb", "tunnel"] and
  .points == 73 and .from_s == 180 and .to_s == 900 and .step_s == 10 and .window_s == 60 and
  .smallest_margin.failure == "port" and .smallest_margin.margin == -1 and
  (.per_case | map(.failure)) == .cases and .estimate.observer == "ekf"' "$out/c.json" > /dev/null \
  || { echo "unexpected summary"; jq -c 'del(.estimate)' "$out/c.json"; exit 1; }
head -1 "$out/points.csv" | grep -q '^time \[s\],heading \[deg\],load.x \[kN\],load.y \[kN\],load.n \[kN\*m\],lambda.intact,lambda.port,lambda.stb,lambda.rudder.port,lambda.rudder.stb,lambda.tunnel,worst,lambda,margin$' \
  || { head -1 "$out/points.csv"; exit 1; }
# Heading 0 (to 430 s): the tunnel's loss is the worst, λ 4.6-12 (> 3 asserted); heading 90 (570-860 s): a
# propeller's, λ = 0. The summary's fraction is the points' own.
awk -F, 'NR > 1 && $1 <= 430 && !($12 == "tunnel" && $13 > 3) { bad = 1 }
         NR > 1 && $1 >= 570 && $1 <= 860 && !($12 == "port" && $14 == -1) { bad = 1 }
         NR > 1 { n++; if ($14 < 0) neg++ }
         END { if (bad) exit 1; printf "%.6f\n", neg / n }' "$out/points.csv" > "$out/fraction.txt" \
  || { echo "unexpected points"; cat "$out/points.csv"; exit 1; }
jq -e --argjson f "$(cat "$out/fraction.txt")" '(.fraction_negative - $f | fabs) < 1e-6' \
  "$out/c.json" > /dev/null || { echo "fraction_negative"; exit 1; }
# A [[thruster]] layout: its units and groups are the cases.
vessel="$(cd "$(dirname "$0")/../.." && pwd)/data/vessels/gunnerus-2015.toml"
"$exe" simulate pure-dp --vessel "$vessel" --duration 400 --out "$out/layout" > /dev/null
"$exe" consequence "$out/layout/log.csv" --vessel "$vessel" "${map[@]}" --json "$out/l.json" \
  > /dev/null
jq -e '.layout == "[[thruster]]" and
  .cases == ["pod_port", "pod_stb", "tunnel", "group:port", "group:stb"] and
  (.per_case[] | select(.failure == "group:port") | .min_load_factor == 0) and
  (.estimate.units | map(.angle)) == ["azimuth.pod_port", "azimuth.pod_stb", null]' \
  "$out/l.json" > /dev/null || { echo "layout"; jq -c 'del(.estimate)' "$out/l.json"; exit 1; }
# A log that ends before the first point: exit 2, naming the log and the times.
set +e
msg=$("$exe" consequence "$out/run/log.csv" "${map[@]}" --to 150 2>&1); code=$?
set -e
[ "$code" = 2 ] && printf '%s' "$msg" | grep -q "log.csv (time).*ends at 150.0 s, before the first point at 180.0 s" \
  || { echo "short log: exit $code: $msg"; exit 1; }
echo "ok"
