#!/usr/bin/env bash
# End-to-end: a log spread over two files. main.csv holds the position at 1 Hz; nav.csv the
# heading and wind speed at 0.5 Hz on a clock 1000 s behind, with its own time column. The
# heading swings 358° ↔ 2° across north (11 samples at 358°, 10 at 2°): along the shorter arc
# the main-log times between are 0°, so the circular mean is ≈ −2°/41 = −0.05° and the standard
# deviation √(21·2²/41) = 1.43°; a straight line through 358° and 2° would put them at 180°.
set -euo pipefail
exe="$1"; data="$2"; out="$3"
rm -rf "$out"; mkdir -p "$out"
"$exe" identify station-keeping "$data/main.csv" --col heading=HDG@"$data/nav.csv" \
  --col wind_speed=WS@"$data/nav.csv" --col time=stamp@"$data/nav.csv" \
  --clock-offset "$data/nav.csv=-1000" --from 0 --to 40 --json "$out/sk.json" > "$out/stdout.txt"
jq -e '(.heading_deg.mean | ((. + 0.0488) | fabs < 0.002) or ((. - 359.9512) | fabs < 0.002)) and
       ((.heading_deg.std - 1.431) | fabs < 0.002) and
       ((.wind_speed_mps.mean - 5.1) | fabs < 0.02)' "$out/sk.json" > /dev/null \
  || { echo "unexpected figures:"; jq -c '{heading_deg, wind_speed_mps}' "$out/sk.json"; exit 1; }
# Once the report carries the input block, each role names its file and rate.
if jq -e 'has("input")' "$out/sk.json" > /dev/null; then
  jq -e '(.input.files | length == 2) and
         (.input.roles[] | select(.role == "heading") | (.file | endswith("nav.csv")) and
           ((.rate_hz - 0.5) | fabs < 1e-9)) and
         (.input.roles[] | select(.role == "north") | ((.rate_hz - 1) | fabs < 1e-9))' \
    "$out/sk.json" > /dev/null || { echo "unexpected input block:"; jq -c .input "$out/sk.json"; exit 1; }
fi
echo ok
