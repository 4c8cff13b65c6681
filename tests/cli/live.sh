#!/usr/bin/env bash
# End-to-end: 'dynpos live' on streams made here, each ended by --idle-exit, its final result
# checked against the offline command on the same data: the --json files byte for byte, the
# last JSON line the same document with "final": true.
#  1. identify step --follow on a CSV log appended in chunks;
#  2. identify station-keeping over UDP on loopback (port 0, printed), NMEA lines of a virtual
#     trial as datagrams, with the local page asked for its routes meanwhile;
#  3. leverarm gnss --follow on a virtual turning circle's log, appended in chunks;
#  4. identify station-keeping over UDP without --idle-exit, ended by SIGTERM (as Ctrl-C): the
#     final line and --json all the same, exit 0.
set -euo pipefail
[[ -z "${LIVE_TRACE:-}" ]] || { PS4='+ $(date +%s.%N) '; set -x; }
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"

# The JSON lines of a session: every line but the last "final": false, the last true, and the
# last, without the two added keys, the offline document.
check_lines() {  # lines.jsonl offline.json
  jq -e -s 'length >= 2 and (.[:-1] | all(.final == false)) and (.[-1].final == true)' "$1" \
    > /dev/null || { echo "$1: not final only on its last line"; exit 1; }
  jq -e -n --slurpfile l "$1" --slurpfile o "$2" \
    '($l[0:] | last | del(.final, .stream_time_s)) == $o[0]' > /dev/null ||
    { echo "$1: the last line is not the offline document $2"; exit 1; }
}

# Waits until FILE has a line matching PATTERN (at most 20 s) and prints the match.
wait_for() {  # file pattern
  for _ in $(seq 200); do
    if grep -Eo "$2" "$1" 2> /dev/null; then return 0; fi
    sleep 0.1
  done
  echo "no '$2' in $1:"; cat "$1"; exit 1
}

# 1. A step test log (FOPDT K = 2, T = 3 s, dead time 0.5 s; steps at 10, 40 and 70 s) written
#    in 1-second chunks while the session follows it.
awk 'BEGIN { print "time [s],cmd [1],y [1]"
  split("10 40 70", ts, " "); split("0 1 3 2", lv, " ")
  for (i = 0; i <= 1000; i++) { t = i / 10; u = t < 10 ? 0 : t < 40 ? 1 : t < 70 ? 3 : 2; y = 0
    for (k = 1; k <= 3; k++) { s = t - ts[k] - 0.5; if (s > 0) y += 2 * (lv[k+1] - lv[k]) * (1 - exp(-s / 3)) }
    printf "%.1f,%d,%.6f\n", t, u, y + 0.002 * sin(i * 12.9898) } }' > "$out/steps.csv"
head -n 101 "$out/steps.csv" > "$out/trial.csv"
"$exe" live identify step --follow "$out/trial.csv" --col input=cmd --col output=y \
  --idle-exit 2 --json "$out/step_live.json" > "$out/step.jsonl" 2> "$out/step.err" &
live=$!
for start in $(seq 102 10 1002); do
  sed -n "${start},$((start + 9))p" "$out/steps.csv" >> "$out/trial.csv"
  sleep 0.02
done
wait "$live" || { cat "$out/step.err"; exit 1; }
"$exe" identify step "$out/trial.csv" --col input=cmd --col output=y \
  --json "$out/step_offline.json" > /dev/null
cmp "$out/step_live.json" "$out/step_offline.json"
check_lines "$out/step.jsonl" "$out/step_offline.json"
jq -e -s '[.[] | select(.final == false and (.steps | length) == 3)] | length > 0' \
  "$out/step.jsonl" > /dev/null || { echo "the third step was not reported before the end"; exit 1; }

# 2. Station keeping over UDP: the lines of a virtual trial's NMEA file as datagrams.
"$exe" simulate turning-circle --duration 120 --out "$out/run" > /dev/null
"$exe" live identify station-keeping --udp 127.0.0.1:0 --page-port 0 --duration 60 \
  --idle-exit 5 --capture "$out/udp.nmea" --json "$out/sk_live.json" \
  > "$out/sk.jsonl" 2> "$out/sk.err" &
live=$!
port=$(wait_for "$out/sk.err" 'udp 127\.0\.0\.1:[0-9]+' | sed 's/.*://')
page=$(wait_for "$out/sk.err" 'http://127\.0\.0\.1:[0-9]+' | sed 's/.*://')
send() {  # the lines FROM to TO of the capture, a datagram each
  sed -n "$1,$2p" "$out/run/gnss1.nmea" |
    while IFS= read -r line; do printf '%s\n' "$line" > "/dev/udp/127.0.0.1/$port"; done
}
send 1 240
# The page: GET / is the page, GET /latest.json the latest line, anything else refused.
ask() {  # request
  exec 3<> "/dev/tcp/127.0.0.1/$page"
  printf '%s\r\nHost: 127.0.0.1\r\n\r\n' "$1" >&3
  timeout 5 cat <&3
  exec 3<&-
}
ask "GET / HTTP/1.1" | grep -q "latest.json" || { echo "no page"; exit 1; }
for try in $(seq 40); do  # the first windows are analysed as the datagrams arrive
  if ask "GET /latest.json HTTP/1.1" | tail -n 1 | jq -e '.analysis == "station-keeping"' > /dev/null; then
    break
  fi
  [[ $try != 40 ]] || { echo "no document at /latest.json"; exit 1; }
  sleep 0.1
done
ask "GET /secret HTTP/1.1" | head -n 1 | grep -q "404" || { echo "an unknown path served"; exit 1; }
ask "DELETE / HTTP/1.1" | head -n 1 | grep -q "405" || { echo "a DELETE served"; exit 1; }
send 241 100000
wait "$live" || { cat "$out/sk.err"; exit 1; }
cmp "$out/udp.nmea" "$out/run/gnss1.nmea" ||
  { echo "the capture is not the lines sent"; exit 1; }
"$exe" identify station-keeping "$out/udp.nmea" --duration 60 --json "$out/sk_offline.json" \
  > /dev/null
cmp "$out/sk_live.json" "$out/sk_offline.json"
check_lines "$out/sk.jsonl" "$out/sk_offline.json"

# 3. GNSS lever arms from the logger (method ins) as the turn goes on.
head -n 2001 "$out/run/log.csv" > "$out/turn.csv"
"$exe" live leverarm gnss --follow "$out/turn.csv" --imu-arm 0.358,0.804,-4.321 \
  --idle-exit 3 --json "$out/arms_live.json" > "$out/arms.jsonl" 2> "$out/arms.err" &
live=$!
total=$(wc -l < "$out/run/log.csv")
for start in $(seq 2002 1000 "$total"); do
  sed -n "${start},$((start + 999))p" "$out/run/log.csv" >> "$out/turn.csv"
  sleep 0.05
done
wait "$live" || { cat "$out/arms.err"; exit 1; }
"$exe" leverarm gnss "$out/turn.csv" --imu-arm 0.358,0.804,-4.321 \
  --json "$out/arms_offline.json" > /dev/null
cmp "$out/arms_live.json" "$out/arms_offline.json"
check_lines "$out/arms.jsonl" "$out/arms_offline.json"

# 4. A UDP session has no end of its own: a signal ends it with its final result.
"$exe" live identify station-keeping --udp 127.0.0.1:0 --duration 60 \
  --capture "$out/sig.nmea" --json "$out/sig_live.json" > "$out/sig.jsonl" 2> "$out/sig.err" &
live=$!
port=$(wait_for "$out/sig.err" 'udp 127\.0\.0\.1:[0-9]+' | sed 's/.*://')
send 1 400
for _ in $(seq 100); do  # every line sent received (the capture), then the signal
  [[ $(wc -l < "$out/sig.nmea") == 400 ]] && break
  sleep 0.1
done
kill -TERM "$live"
wait "$live" || { echo "exit $? after SIGTERM"; cat "$out/sig.err"; exit 1; }
grep -q "ending the session with its final result" "$out/sig.err" ||
  { echo "no note of the signal"; cat "$out/sig.err"; exit 1; }
sed -n 1,400p "$out/run/gnss1.nmea" | cmp - "$out/sig.nmea"
"$exe" identify station-keeping "$out/sig.nmea" --duration 60 --json "$out/sig_offline.json" \
  > /dev/null
cmp "$out/sig_live.json" "$out/sig_offline.json"
check_lines "$out/sig.jsonl" "$out/sig_offline.json"
echo ok
