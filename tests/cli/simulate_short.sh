#!/usr/bin/env bash
# End-to-end: dynpos simulate writes log.csv, truth.csv and truth.json, is deterministic for a seed,
# differs between seeds, and leaves no temporary files behind.
set -euo pipefail
exe="$1"; out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$out"; mkdir -p "$out"
"$exe" simulate "$here/short.toml" --out "$out/a" --seed 7
"$exe" simulate "$here/short.toml" --out "$out/b" --seed 7
"$exe" simulate "$here/short.toml" --out "$out/c" --seed 8
cmp "$out/a/log.csv" "$out/b/log.csv"
cmp "$out/a/truth.csv" "$out/b/truth.csv"
cmp "$out/a/truth.json" "$out/b/truth.json"
if cmp -s "$out/a/log.csv" "$out/c/log.csv"; then echo "seeds 7 and 8 gave the same log"; exit 1; fi
head -1 "$out/a/log.csv" | grep -q '^time \[s\],gnss1.lat \[deg\],gnss1.lon \[deg\],gnss1.height \[m\]' \
  || { echo "unexpected header: $(head -1 "$out/a/log.csv")"; exit 1; }
head -1 "$out/a/truth.csv" | grep -q '^time \[s\],north \[m\],east \[m\],down \[m\],heading \[rad\]' \
  || { echo "unexpected truth header: $(head -1 "$out/a/truth.csv")"; exit 1; }
# GNSS at 1 Hz in a 10 Hz log: the second data row (t = 0.1 s) has a blank latitude.
sed -n 3p "$out/a/log.csv" | grep -q '^0.1,,' \
  || { echo "expected a blank GNSS cell at t = 0.1 s: $(sed -n 3p "$out/a/log.csv")"; exit 1; }
rows=$(($(wc -l < "$out/a/log.csv") - 1))
[ "$rows" -eq 401 ] || { echo "expected 401 rows (40 s at 10 Hz, both ends), got $rows"; exit 1; }
for key in '"seed": 7' '"scenario"' '"vessel"' '"commands"' '"lever_arms"'; do
  grep -q "$key" "$out/a/truth.json" || { echo "truth.json lacks $key"; exit 1; }
done
if ls -A "$out"/a | grep -q tmp; then echo "temporary files left: $(ls -A "$out/a")"; exit 1; fi
echo "ok: $rows rows, deterministic per seed"
