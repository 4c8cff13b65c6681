#!/usr/bin/env bash
# End-to-end: 'dynpos estimate' on a simulated pure-DP log (the GNSS antenna's fixes moved to
# the control origin): the time series' columns and units, one row per observer step, and the
# summary's mean bias against the true environmental load of truth.csv.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate pure-dp --duration 400 --observer ekf --out "$out/run" > /dev/null
map=(--col north=gnss1.north --col east=gnss1.east --col roll=mru1.roll --col pitch=mru1.pitch
     --arm 0.202,-0.611,-13.891 --tp 7)
"$exe" estimate "$out/run/log.csv" "${map[@]}" --out "$out/estimate.csv" --json "$out/estimate.json" \
  > "$out/stdout.txt"
grep -q "ekf observer at 10 Hz, T_p 7 s" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
header='time [s],lf.north [m],lf.east [m],lf.heading [deg],lf.u [m/s],lf.v [m/s],lf.r [deg/s],bias.north [kN],bias.east [kN],bias.yaw [kN*m],position.age [s]'
[ "$(head -1 "$out/estimate.csv")" = "$header" ] || { head -1 "$out/estimate.csv"; exit 1; }
rows=$(($(wc -l < "$out/estimate.csv") - 1))
jq -e --argjson rows "$rows" '.steps == $rows and .steps == 4000 and .observer == "ekf" and
  .measurement == "fresh" and .position == "north/east" and .attitude == true and
  (.units | map(.name)) == ["port", "stb", "tunnel"] and .bias.from_s == 120 and
  .coasting_steps == 9 * .position_steps and
  (.longest_without_position_s - 1.0 | fabs) < 1e-6 and
  .bridge.mru == "mru1" and .bridge.rows == 0' "$out/estimate.json" > /dev/null \
  || { echo "unexpected summary"; jq -c 'del(.input)' "$out/estimate.json"; exit 1; }
# The heading 0 hold, weather from the bow: the mean bias within 10 % of the true load's
# horizontal magnitude in north and east, 15 % in yaw (tests/validation/estimate_test.cpp
# measures the same on the last 600 s of a 900 s run).
truth=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $1 >= 120 { n += $c["env_load.north [N]"]; e += $c["env_load.east [N]"];
              y += $c["env_load.yaw [N*m]"]; k++ }
  END { printf "[%f, %f, %f]", n / k, e / k, y / k }' "$out/run/truth.csv")
jq -e --argjson t "$truth" '.bias.mean as $b | (($t[0] * $t[0] + $t[1] * $t[1]) | sqrt) as $h |
  (($b.north_N - $t[0]) | fabs) < 0.1 * $h and (($b.east_N - $t[1]) | fabs) < 0.1 * $h and
  (($b.yaw_Nm - $t[2]) | fabs) < 0.15 * ($t[2] | fabs)' "$out/estimate.json" > /dev/null \
  || { echo "bias mean off the truth $truth:"; jq -c '.bias' "$out/estimate.json"; exit 1; }
# The passive observer runs on the held fix: it never coasts.
"$exe" estimate "$out/run/log.csv" "${map[@]}" --observer passive --json - 2> /dev/null \
  | jq -e '.measurement == "held" and .coasting_steps == 0' > /dev/null \
  || { echo "passive observer"; exit 1; }
echo "ok"
