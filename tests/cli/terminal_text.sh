#!/usr/bin/env bash
# End-to-end: what the output echoes of the user's input (a scenario's name, compare's labels
# and JSON keys, an error's file name) reaches the terminal as text: no ESC (C0), no CSI
# (U+009B, C1) and no invalid UTF-8 byte is written raw, each is shown escaped.
set -euo pipefail
exe="$1"; out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
esc=$'\x1b'; csi=$'\xc2\x9b'; bad=$'\xff'
# Raw control bytes in a file of output: ESC, the C1 block's UTF-8 form, or a byte 0xff.
raw() { LC_ALL=C grep -q -e "$esc" -e "$csi" -e "$bad" "$1"; }

sed "s/^name = .*/name = \"red\\\\u001b[31m csi\\\\u009b2J\"/" "$here/short.toml" > "$out/named.toml"
"$exe" simulate "$out/named.toml" --duration 2 --out "$out/run" > "$out/simulate.txt" 2>&1
raw "$out/simulate.txt" && fail "simulate sent a control sequence: $(cat -v "$out/simulate.txt")"
grep -qF "simulated 'red\\x1b[31m csi\\u009b2J'" "$out/simulate.txt" \
  || fail "the name is not shown escaped: $(cat -v "$out/simulate.txt")"

printf '{"k\\u001b[2Jey": {"x": 1.0}, "plain": 1}\n' > "$out/a.json"
printf '{"k\\u001b[2Jey": {"x": 2.0}, "plain": 2}\n' > "$out/b.json"
"$exe" compare "$out/a.json" "$out/b.json" --labels "A${esc}[5m,B${csi}1m${bad}" \
  > "$out/compare.txt" 2>&1
raw "$out/compare.txt" && fail "compare sent a control sequence: $(cat -v "$out/compare.txt")"
grep -qF 'k\x1b[2Jey.x' "$out/compare.txt" || fail "the key is not shown: $(cat "$out/compare.txt")"
grep -qF 'A\x1b[5m' "$out/compare.txt" || fail "label A is not shown: $(cat "$out/compare.txt")"
grep -qF 'B\u009b1m\xff' "$out/compare.txt" || fail "label B is not shown: $(cat "$out/compare.txt")"

# An error message naming a file whose name holds a C1 control and an invalid byte.
cp "$here/short_steps.csv" "$out/log${csi}${bad}.csv"
status=0
"$exe" identify step "$out/log${csi}${bad}.csv" --col input=cmd --col output=nothing \
  > "$out/error.txt" 2>&1 || status=$?
[ "$status" = 2 ] || fail "exit $status"
raw "$out/error.txt" && fail "the error sent a control sequence: $(cat -v "$out/error.txt")"
grep -qF 'log\u009b\xff.csv' "$out/error.txt" || fail "the file is not named: $(cat "$out/error.txt")"
echo ok
