#!/usr/bin/env bash
# End-to-end: 'dynpos identify step' on an hour and a half of a 2 Hz sea-trial log, written
# here: twenty azimuth orders (±35° zig-zag, ±20° turns, 10° steps; each ramped over four
# samples, with held wiggles of ±0.5°) and sixteen rpm orders with ±2 rpm of dither. The
# responses are first order: yaw K = 0.5, T = 8 s, δ = 1 s; rpm K = 1, T = 3 s, δ = 0.5 s.
# With only --col, every order is found, listed in time order and fitted; exit 0. With the
# segment fixture, only the three orders inside its stretches, named in the JSON.
set -euo pipefail
exe="$1"; out="$2"; segments="$3"
rm -rf "$out"; mkdir -p "$out"
awk 'BEGIN {
  srand(17);
  split("35 -35 35 -35 0 20 -20 0 10 20 30 20 10 0 -10 -30 -35 0 25 0", azi, " ");
  split("60 90 120 150 100 50 0 80 130 60 20 100 150 70 30 0", rpm, " ");
  print "time [s],azi_order [1],yaw [1],rpm_order [1],rpm [1]";
  ay = 0; ry = 0; wiggle = 0; a_from = 0; a_u = 0; r_u = 0;
  for (k = 0; k <= 10800; k++) {
    t = 0.5 * k;
    # Azimuth: the order of index i starts at 150 + 270 i and ramps over 2 s.
    i = int((t - 150) / 270); a = 0; ramping = 0;
    if (t >= 150) {
      a_to = azi[i + 1]; a_prev = i > 0 ? azi[i] : 0; s = t - 150 - 270 * i;
      a = s < 2 ? a_prev + (a_to - a_prev) * s / 2 : a_to; ramping = s <= 2.5;
    }
    if (k % 10 == 0) wiggle = 0.5 * (2 * rand() - 1);
    if (!ramping) a += wiggle;
    # rpm: the order of index j starts at 200 + 330 j, ramps over 3 s; dither ±2 rpm.
    j = int((t - 200) / 330); r = 0;
    if (t >= 200) {
      r_to = rpm[j + 1]; r_prev = j > 0 ? rpm[j] : 0; s = t - 200 - 330 * j;
      r = s < 3 ? r_prev + (r_to - r_prev) * s / 3 : r_to;
    }
    r += 2 * (2 * rand() - 1);
    hist_a[k] = a; hist_r[k] = r;
    printf "%.1f,%.4f,%.5f,%.3f,%.4f\n", t, a, ay + 0.05 * (2 * rand() - 1), r, ry + 0.5 * (2 * rand() - 1);
    # Exact for an input held over each 0.5 s sample, delayed by 2 and 1 samples.
    ua = k >= 2 ? hist_a[k - 2] : 0; ur = k >= 1 ? hist_r[k - 1] : 0;
    ay += (1 - exp(-0.5 / 8)) * (0.5 * ua - ay);
    ry += (1 - exp(-0.5 / 3)) * (1.0 * ur - ry);
  }
}' > "$out/trial.csv"

"$exe" identify step "$out/trial.csv" --col input=azi_order --col output=yaw \
  --json "$out/azi.json" > "$out/azi.txt"
grep -q "20 step(s)" "$out/azi.txt" || { cat "$out/azi.txt"; echo "azimuth: not 20 steps"; exit 1; }
grep -Eq "step threshold 3\.[45]" "$out/azi.txt" || { cat "$out/azi.txt"; echo "no threshold"; exit 1; }
# Sorted, all ok, T within 15 % of 8 s: the wiggles' response (≤ 0.25) is 10 % of the smallest
# Δy, 2.5 for the 5° order from −30 to −35° (measured: 7.14 s there, within 6 % elsewhere).
awk '$1 == "\"t_step\":" { v = $2 + 0; if (n++ && v <= last) { print "not sorted at " v; bad = 1 } last = v }
     $1 == "\"status\":" && $2 != "\"ok\"," && $2 != "\"ok\"" { print "status " $2; bad = 1 }
     $1 == "\"T\":" && /^      "/ { v = $2 + 0; if (v < 6.8 || v > 9.2) { print "T " v; bad = 1 } }
     END { if (n != 20) { print n " steps"; bad = 1 } exit bad }' "$out/azi.json"

"$exe" identify step "$out/trial.csv" --col input=rpm_order --col output=rpm \
  --json "$out/rpm.json" > "$out/rpm.txt"
grep -q "16 step(s)" "$out/rpm.txt" || { cat "$out/rpm.txt"; echo "rpm: not 16 steps"; exit 1; }
# Each order timed at its ramp's start within one sample (0.5 s) through ±2 rpm of dither, and
# δ = 0.5 s + 0.25 s (the order held over each sample) + 1.5 s (half the 3 s ramp) = 2.25 s
# within one sample.
awk '$1 == "\"t_step\":" { v = $2 + 0; want = 200 + 330 * n++; d = v - want;
       if (d < -0.5 || d > 0.5) { print "rpm step at " v " (want " want ")"; bad = 1 } }
     $1 == "\"delay\":" && /^      "/ { v = $2 + 0; if (v < 1.75 || v > 2.75) { print "delay " v; bad = 1 } }
     END { exit bad }' "$out/rpm.json"

"$exe" identify step "$out/trial.csv" --col input=azi_order --col output=yaw \
  --segments "$segments" --json "$out/seg.json" > "$out/seg.txt"
grep -q "3 step(s)" "$out/seg.txt" || { cat "$out/seg.txt"; echo "segments: not 3 steps"; exit 1; }
[ "$(grep -c '"segment": "zigzag 35/35"' "$out/seg.json")" = 2 ] || { echo "no zigzag"; exit 1; }
[ "$(grep -c '"segment": "turn stb"' "$out/seg.json")" = 1 ] || { echo "no turn stb"; exit 1; }
echo "ok"
