#!/usr/bin/env bash
# demo_interrupted.sh DYNPOS OUT_DIR CLI_DIR SOURCE_DIR: Ctrl-C during a demo over the report of
# another seed leaves no summary (index.html, summary.md, summary.json) naming the runs of two
# seeds: the old summary goes before the first run is replaced. A data folder of one scenario
# keeps the test quick; the signal comes while its run is written.
set -u
dynpos="$1" out="$2" here="$3" source="$4"
rm -rf "$out" && mkdir -p "$out/data/scenarios" "$out/data/vessels" "$out/report" || exit 1
# The short scenario made 1500 s long, so its run is still being written (a second or more)
# when the signal comes, however fast the machine: at 40 s the run could end before the loop
# below saw its folder.
sed 's/^duration_s = 40$/duration_s = 1500/' "$here/short.toml" >"$out/data/scenarios/short.toml"
grep -q '^duration_s = 1500$' "$out/data/scenarios/short.toml" || { echo "FAIL: short.toml"; exit 1; }
cp "$source/data/vessels/gunnerus.toml" "$out/data/vessels/"
for f in index.html summary.md summary.json; do echo "the report of seed 1" > "$out/report/$f"; done
DYNPOS_DATA_DIR="$out/data" "$dynpos" demo --out "$out/report" --seed 2 >/dev/null 2>&1 &
pid=$!
for _ in $(seq 200); do  # the run's hidden folder appears as soon as it starts
  compgen -G "$out/report/short-steps/.run.tmp-*" >/dev/null && break
  sleep 0.05
done
kill -INT "$pid" || { echo "FAIL: the demo ended before the signal"; exit 1; }
wait "$pid"
left=$(grep -l "seed 1" "$out/report/index.html" "$out/report/summary.md" \
  "$out/report/summary.json" 2>/dev/null)
if [ -n "$left" ]; then echo "FAIL: the old summary is left beside the new runs: $left"; exit 1; fi
echo "ok: no summary of the other seed left"
