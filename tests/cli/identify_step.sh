#!/usr/bin/env bash
# End-to-end: 'dynpos identify step' on an analytic FOPDT log (K = 2, T = 3 s, δ = 1 s, steps at
# 10 s and 40 s) finds both steps and recovers the parameters; JSON has the contract keys.
set -euo pipefail
exe="$1"; out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$out"; mkdir -p "$out"
"$exe" identify step "$here/short_steps.csv" --col input=cmd --col output=response \
  --json "$out/steps.json" > "$out/stdout.txt"
grep -q "2 step(s)" "$out/stdout.txt" || { cat "$out/stdout.txt"; exit 1; }
for key in t_step u_before u_after y_before y_after '"K"' '"T"' '"delay"'; do
  grep -q "$key" "$out/steps.json" || { echo "JSON lacks $key"; exit 1; }
done
# Noise-free FOPDT sampled at 10 Hz: least squares recovers T and δ to well within 1 %.
check() {  # check KEY EXPECTED TOLERANCE: each step's KEY (6-space indent; σ's are deeper)
  awk -v key="\"$1\":" -v want="$2" -v tol="$3" '
    $1 == key && /^      "/ { v = $2; sub(/,$/, "", v); n++; d = v - want; if (d < 0) d = -d;
                if (d > tol) { print "step " n ": " key " " v " (want " want ")"; bad = 1 } }
    END { if (n != 2) { print key " found " n " times"; bad = 1 } exit bad }' "$out/steps.json"
}
check T 3.0 0.03
check delay 1.0 0.01
check K 2.0 0.02
echo "ok"
