#!/usr/bin/env bash
# End-to-end: 'dynpos identify station-keeping' on a raw NMEA 0183 capture with no options
# (tests/data/nmea/station.nmea: 20 GGA fixes alternating 1 m north + 0.5 m east and as far
# south-west of a fixed point, HDT alternating 91° and 89°, and the traps of a real capture).
set -euo pipefail
exe="$1"; capture="$2"; out="$3"
rm -rf "$out"; mkdir -p "$out"
"$exe" identify station-keeping "$capture" --json "$out/sk.json" > "$out/stdout.txt"
fail() { echo "$1"; cat "$out/sk.json"; exit 1; }
# The input block: format, time stamps, origin, and every skipped line by kind.
jq -e '.input.files[0] | .format == "nmea" and .time_format == "nmea utc" and .records == 44
       and .skipped.truncated == 2 and .skipped["bad checksum"] == 1 and .skipped.comment == 1
       and .skipped["other talker"] == 1 and .skipped["unknown sentence"] == 1
       and .accepted["no checksum"] == 1' "$out/sk.json" > /dev/null || fail "input counts"
jq -e '.input.origin == "2024-05-01T23:59:50.000Z" and .input.origin_zone == "UTC"' \
  "$out/sk.json" > /dev/null || fail "origin"
grep -q "input: .*station.nmea (nmea, time stamps: nmea utc, 44 records, skipped: 1 bad checksum" \
  "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
# Figures: population std of ±1 m and ±0.5 m is exactly 1 and 0.5 m; the 10⁻⁷ minute rounding
# of the fixture's latitudes and longitudes moves a position by at most 0.2 mm. Heading: the
# circular mean of 91° and 89° is 90°, the circular std √(−2 ln cos 1°) = 1.000025°.
jq -e '.position_samples == 20
       and ((.position_std_m.north - 1.0) | fabs) < 1e-3
       and ((.position_std_m.east - 0.5) | fabs) < 1e-3
       and ((.heading_deg.mean - 90) | fabs) < 1e-6
       and ((.heading_deg.std - 1.0) | fabs) < 1e-3' "$out/sk.json" > /dev/null || fail "figures"
echo ok
