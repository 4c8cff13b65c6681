#!/usr/bin/env bash
# End-to-end: 'dynpos demo' writes the campaign and the hybrid-integral-action section into one
# report folder, prints where the report is, and is byte-identical for a seed.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
"$exe" demo --out "$out/a" --seed 5 > "$out/stdout.txt"
grep -q "report: .*index.html" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
for f in index.html summary.md summary.json hybrid/vessel_ice.json hybrid/vessel_mooring.json \
         hybrid/hybrid_vessel_ice_position.svg dp-ice-load/log.csv turning-circle/truth.csv; do
  [ -s "$out/a/$f" ] || { echo "missing $f"; exit 1; }
done
grep -q "Hybrid integral action on the virtual Gunnerus" "$out/a/index.html" \
  || { echo "index.html lacks the hybrid section"; exit 1; }
grep -q '"peak_offset_m"' "$out/a/hybrid/vessel_ice.json" || { echo "no figures"; exit 1; }
"$exe" demo --out "$out/b" --seed 5 > /dev/null
diff -r "$out/a" "$out/b" > /dev/null || { echo "demo output differs between runs"; exit 1; }
echo "ok"
