#!/usr/bin/env bash
# End-to-end: 'dynpos identify failure-test' on a log this script writes: 400 s at 10 Hz, GNSS
# antenna 1 at 1 Hz with the lever arm (10, -2) m, port tripping at 200 s (dead time 0.2 s, then
# a first-order decay, T = 1 s), the others taking over 0.5 s later, and the control origin
# pushed 2.5 m off (a half sine of 40 s, peak 20 s after the trip) with the heading 1.5° off.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
awk 'BEGIN {
  pi = atan2(0, -1); d = pi / 180; t0 = 200; A = 2.5; D = 40; ax = 10; ay = -2
  print "time [s],gnss1.north [m],gnss1.east [m],heading [deg],thrust.port [kN]," \
        "thrust.stb [kN],thrust.tunnel [kN],rpm.azimuth [rpm]"
  for (i = 0; i <= 4000; i++) {
    t = i / 10; s = t - t0
    bump = (s > 0 && s < D) ? A * sin(pi * s / D) : 0
    # Deterministic "noise": incommensurate sines, a few cm and tenths of a kN.
    nn = 0.02 * sin(i * 1.7) + 0.01 * sin(i * 2.9); ne = 0.02 * sin(i * 2.3) + 0.01 * sin(i * 0.7)
    psi = (45 + 1.5 * bump / A + 0.03 * sin(i * 1.1)) * d
    port = 40 + 2 * sin(2 * pi * t / 40) + 0.2 * sin(i * 1.3)
    if (s >= 0.2) port = (40 + 2 * sin(2 * pi * (t0 + 0.2) / 40)) * exp(-(s - 0.2)) + 0.2 * sin(i * 1.3)
    k = s < 0.5 ? 0 : (s > 2.5 ? 1 : (s - 0.5) / 2)
    stb = 30 + 20 * k + 0.2 * sin(i * 0.9); tunnel = 10 + 8 * k + 0.2 * sin(i * 2.1)
    azi = 150 + 50 * k + sin(i * 1.9)
    n = ""; e = ""
    if (i % 10 == 0) {
      n_co = bump * cos(60 * d) + nn; e_co = bump * sin(60 * d) + ne
      n = sprintf("%.4f", 7000000 + n_co + cos(psi) * ax - sin(psi) * ay)
      e = sprintf("%.4f", 500000 + e_co + sin(psi) * ax + cos(psi) * ay)
    }
    printf "%.1f,%s,%s,%.4f,%.4f,%.4f,%.4f,%.3f\n", t, n, e, psi / d, port, stb, tunnel, azi
  }
}' > "$out/trial.csv"
map=(--col north=gnss1.north --col east=gnss1.east)
"$exe" identify failure-test "$out/trial.csv" "${map[@]}" --arm 10,-2 --json "$out/ft.json" \
  > "$out/stdout.txt"
fail() { echo "$1"; cat "$out/stdout.txt"; jq -c '.events' "$out/ft.json"; exit 1; }
grep -q "failure test, 1 event(s)" "$out/stdout.txt" || fail "text"
jq -e '.analysis == "failure-test" and .arm_m == [10, -2, 0] and .position == "north/east" and
       .windows.pre_window_s == 60 and .windows.hold_s == 10' "$out/ft.json" > /dev/null \
  || fail "context"
jq -e '[.units[].channel] == ["thrust.port", "thrust.stb", "thrust.tunnel", "rpm.azimuth"]' \
  "$out/ft.json" > /dev/null || fail "units"
jq -e '.events | length == 1' "$out/ft.json" > /dev/null || fail "expected 1 event"
# The failure instant within 0.5 s; the peak within max(5 %, 0.1 m) and 2 s; the heading
# within 0.1°; recovery within 2 s of where the half sine is back within the footprint.
jq -e '.events[0] | .unit == "port" and .units == ["port"] and (.time_s - 200 | fabs) < 0.5 and
       (.peak_excursion_m - 2.5 | fabs) < 0.125 and (.time_s + .time_to_peak_s - 220 | fabs) < 2 and
       (.peak_heading_deg - 1.5 | fabs) < 0.1 and
       (.time_s + .recovery_s - (240 - 40 / 3.141592653589793 * (.footprint_m / 2.5 | asin))
        | fabs) < 2' "$out/ft.json" > /dev/null || fail "event figures"
# The others: 30 s means before and after (the 2 s ramp starts 0.3 s into the 30 s after).
jq -e '.events[0].redistribution | (.stb.change - 20 * (1 - 1.3 / 30) | fabs) < 0.5 and
       .stb.took_over and .stb.unit == "kN" and .azimuth.unit == "rpm" and
       (.azimuth.after - .azimuth.before - 50 * (1 - 1.3 / 30) | fabs) < 2 and
       (has("port") | not)' "$out/ft.json" > /dev/null || fail "redistribution"
# Without the lever arm the antenna's track is not the control origin's: 10 m × 1.5° more.
"$exe" identify failure-test "$out/trial.csv" "${map[@]}" --json "$out/antenna.json" > /dev/null
jq -e '.arm_m == null and (.events[0].peak_excursion_m - 2.5 | fabs) > 0.15' "$out/antenna.json" \
  > /dev/null || { echo "the arm made no difference"; jq -c '.events' "$out/antenna.json"; exit 1; }
# No trip before 150 s: zero events, exit 0.
"$exe" identify failure-test "$out/trial.csv" "${map[@]}" --to 150 --json "$out/none.json" \
  > "$out/none.txt"
jq -e '.events == []' "$out/none.json" > /dev/null || { echo "events before the trip"; exit 1; }
grep -q "failure test, 0 event(s)" "$out/none.txt" || { cat "$out/none.txt"; exit 1; }
# A log without position: exit 2 naming the roles, and no JSON.
cut -d, -f1,4- "$out/trial.csv" > "$out/no_position.csv"
set +e
"$exe" identify failure-test "$out/no_position.csv" --json "$out/bad.json" 2> "$out/bad.err"
code=$?
set -e
[ "$code" = 2 ] || { echo "no position: exit $code"; cat "$out/bad.err"; exit 1; }
grep -q "no_position.csv.*no position in the log" "$out/bad.err" || { cat "$out/bad.err"; exit 1; }
[ ! -e "$out/bad.json" ] || { echo "wrote JSON on bad input"; exit 1; }
echo "ok"
