#!/usr/bin/env bash
# End-to-end: a short virtual zig-zag identified (yaw and sway values at 6 kn), the identified
# vessel file written, read back by simulate, and the test re-simulated by compare-trial.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate zig-zag --duration 200 --out "$out/run" > /dev/null
"$exe" identify vessel "$out/run/log.csv" --holdout none --out "$out/my-vessel.toml" \
    --json "$out/vessel.json" --report "$out/report" > "$out/stdout.txt"
grep -q "values determined" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
grep -q '"key": "hull.n_r_Nms"' "$out/vessel.json" || { echo "no hull.n_r_Nms"; exit 1; }
grep -q "identified: sigma" "$out/my-vessel.toml" || { echo "nothing identified"; exit 1; }
[ -s "$out/report/index.html" ] && [ -s "$out/report/test-1.svg" ] || { echo "no report"; exit 1; }
"$exe" simulate zig-zag --duration 5 --vessel "$out/my-vessel.toml" --out "$out/again" > /dev/null
"$exe" compare-trial "$out/run/log.csv" --vessel "$out/my-vessel.toml" --json "$out/cmp.json" \
    --plot "$out/cmp.svg" > "$out/cmp.txt"
grep -q "NRMSE u" "$out/cmp.txt" || { cat "$out/cmp.txt"; exit 1; }
[ -s "$out/cmp.svg" ] || { echo "no plot"; exit 1; }
echo ok
