#!/usr/bin/env bash
# outputs_before_run.sh DYNPOS OUT_DIR: every output is checked before any is written. hybrid
# vessel with --json naming a folder once wrote its plots into --out, then failed (exit 1).
set -u
dynpos="$1" out="$2"
rm -rf "$out" && mkdir -p "$out/a-folder" || exit 1
output=$("$dynpos" hybrid vessel --scenario ice --out "$out/plots" --json "$out/a-folder" 2>&1)
code=$?
if [ "$code" != 2 ] || ! printf '%s' "$output" | grep -q -- "--json.*a-folder.*folder"; then
  echo "FAIL: exit $code, expected 2 naming --json and the folder:"; echo "$output"; exit 1
fi
if [ -e "$out/plots" ]; then echo "FAIL: plots written before the refusal: $(ls "$out/plots")"; exit 1; fi
echo "ok: refused before anything was written"
