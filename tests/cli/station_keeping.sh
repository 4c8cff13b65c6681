#!/usr/bin/env bash
# End-to-end: 'dynpos identify station-keeping' on a simulated pure-DP log, per setpoint hold,
# checked against the same analysis of the exact motion and actuator states (truth.csv, SI).
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate pure-dp --duration 900 --out "$out/run" > /dev/null
"$exe" identify station-keeping "$out/run/log.csv" --col north=gnss1.north --col east=gnss1.east \
  --per-setpoint --waves "Hs 2 m from N" --json "$out/log.json" > "$out/stdout.txt"
"$exe" identify station-keeping "$out/run/truth.csv" --per-setpoint --json "$out/truth.json" \
  > /dev/null
grep -q "heading 90" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
jq -e '.windows | length == 2' "$out/log.json" > /dev/null || { echo "expected 2 windows"; exit 1; }
jq -e '.observed.waves == "Hs 2 m from N" and .observed.current == null' "$out/log.json" \
  > /dev/null || { echo "observed conditions not kept"; exit 1; }
for key in position_std_m heading_deg wind_speed_mps wind_dir_deg thrust_kN energy_kJ; do
  jq -e ".windows[0] | has(\"$key\")" "$out/log.json" > /dev/null || { echo "no $key"; exit 1; }
done
# Logger vs truth, per window:
# - total energy within 1 % plus 5 % of the tunnel's share, and total mean thrust within 1 %: the
#   logger adds 1 kW / 0.2 rpm white noise (averages out) and samples the tunnel at 1 Hz instead
#   of 10 Hz, while the tunnel's power follows the DP demand within seconds (3 % measured on the
#   tunnel's energy in a light-weather window, where it is a third of the total);
# - heading mean within 0.3° and std within 0.15°: gyro noise 0.1° white on a ~1° spread.
jq -e -n --slurpfile a "$out/log.json" --slurpfile b "$out/truth.json" '
  [range(0; $a[0].windows | length) as $i | $a[0].windows[$i] as $l | $b[0].windows[$i] as $t |
   (($l.energy_kJ.total - $t.energy_kJ.total) | fabs) <
     0.01 * $t.energy_kJ.total + 0.05 * $t.energy_kJ.tunnel and
   (($l.thrust_kN.total / $t.thrust_kN.total - 1) | fabs) < 0.01 and
   (($l.heading_deg.mean - $t.heading_deg.mean) | fabs) < 0.3 and
   (($l.heading_deg.std - $t.heading_deg.std) | fabs) < 0.15] | all' > /dev/null \
  || { echo "logger and truth disagree:"; jq -c '.windows[] | [.energy_kJ.total, .thrust_kN.total, .heading_deg]' "$out/log.json" "$out/truth.json"; exit 1; }
# The true position spread of the control origin is in the thesis range (0.3–0.9 m, widened to
# 0.2–1.5 m for one seed).
jq -e '[.windows[].position_std_m | (.north * .north + .east * .east) | sqrt | . > 0.2 and . < 1.5] | all' \
  "$out/truth.json" > /dev/null || { echo "position spread out of range"; exit 1; }
echo "ok"
