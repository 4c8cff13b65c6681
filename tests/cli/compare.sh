#!/usr/bin/env bash
# End-to-end: 'dynpos compare' on hand-written step and four-corner results, and on two real
# 'identify step' results of one log (least squares vs Smith): the items pair by their natural
# key and every difference is B − A of the two inputs.
set -euo pipefail
exe="$1"; out="$2"
here="$(cd "$(dirname "$0")" && pwd)"
data="$here/data/compare"
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
row() {  # row FILE FIGURE FIELD: one field of one row of a comparison JSON
  jq -r --arg f "$2" --arg k "$3" '.rows[] | select(.figure == $f) | .[$k]' "$1"
}
near() {  # near GOT WANT TOL
  awk -v g="$1" -v w="$2" -v t="$3" 'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g != "null" && d <= t) }'
}

# Steps pair by the nearest step time (within 5 s): 20 ↔ 20.5, 420 ↔ 419; 820 only in A,
# 300 only in B. The fixtures hold binary fractions, so the differences are exact.
"$exe" compare "$data/steps_aug.json" "$data/steps_nov.json" --labels "Aug 2014,Nov 2014" \
  --json "$out/steps.json" > "$out/steps.txt"
grep -q "Aug 2014" "$out/steps.txt" || fail "labels missing from the table"
grep -Eq "^step results" "$out/steps.txt" || fail "kind not named"
j="$out/steps.json"
[ "$(jq -r .kind "$j")" = step ] || fail "kind"
[ "$(row "$j" 'steps[t_step=20].T' a)" = 2 ] || fail "A of T at 20 s"
[ "$(row "$j" 'steps[t_step=20].T' b)" = 2.5 ] || fail "B of T at 20 s"
[ "$(row "$j" 'steps[t_step=20].T' difference)" = 0.5 ] || fail "B − A of T at 20 s"
[ "$(row "$j" 'steps[t_step=20].T' relative_difference_pct)" = 25 ] || fail "% of T at 20 s"
[ "$(row "$j" 'steps[t_step=20].delay' relative_difference_pct)" = -16.666666666666664 ] ||
  near "$(row "$j" 'steps[t_step=20].delay' relative_difference_pct)" -16.6667 1e-3 ||
  fail "% of delay at 20 s"
[ "$(row "$j" 'steps[t_step=420].T' difference)" = -1 ] || fail "B − A of T at 420 s"
[ "$(row "$j" 'steps[t_step=420].t_step' difference)" = -1 ] || fail "step time shift"
# A null stays null: delay at 420 s is missing in A, so no difference.
[ "$(row "$j" 'steps[t_step=420].delay' a)" = null ] || fail "null delay in A"
[ "$(row "$j" 'steps[t_step=420].delay' b)" = 1 ] || fail "delay in B"
[ "$(row "$j" 'steps[t_step=420].delay' difference)" = null ] || fail "difference of a null"
[ "$(row "$j" 'steps[t_step=820].T' b)" = null ] || fail "step only in A"
[ "$(row "$j" 'steps[t_step=300].T' a)" = null ] || fail "step only in B"
[ "$(row "$j" 'steps[t_step=420].status' b)" = poor_fit ] || fail "status change not shown"
grep -E "steps\[t_step=420\]\.delay +— +1 +— +—" "$out/steps.txt" > /dev/null ||
  fail "text table does not show missing as —"

# Four-corner legs pair by name, whatever their order.
"$exe" compare "$data/legs_before.json" "$data/legs_after.json" --format markdown \
  --json "$out/legs.json" > "$out/legs.md"
grep -q '|---|' "$out/legs.md" || fail "markdown table"
j="$out/legs.json"
[ "$(jq -r .kind "$j")" = four-corner ] || fail "kind four-corner"
[ "$(row "$j" 'legs[name=2 starboard].energy_kJ.tunnel' difference)" = -6000 ] || fail "tunnel"
[ "$(row "$j" 'legs[name=2 starboard].energy_kJ.tunnel' relative_difference_pct)" = -20 ] ||
  fail "tunnel %"
[ "$(row "$j" 'legs[name=1 forward].energy_kJ.tunnel' b)" = null ] || fail "null tunnel"
[ "$(row "$j" 'total.energy_kJ.port' difference)" = -500 ] || fail "total"

# Two real results of one log: every difference is B − A of the two files' own values.
"$exe" identify step "$here/short_steps.csv" --col input=cmd --col output=response \
  --json "$out/lsq.json" > /dev/null
"$exe" identify step "$here/short_steps.csv" --col input=cmd --col output=response \
  --method smith --json "$out/smith.json" > /dev/null
"$exe" compare "$out/lsq.json" "$out/smith.json" --json - > "$out/methods.json" 2> /dev/null
j="$out/methods.json"
[ "$(jq -r '.rows[] | select(.figure == "method") | .b' "$j")" = smith ] || fail "method row"
n=0
for k in 1 2; do
  for key in T delay K; do
    a=$(jq ".steps[$((k - 1))].$key" "$out/lsq.json")
    b=$(jq ".steps[$((k - 1))].$key" "$out/smith.json")
    t=$(jq ".steps[$((k - 1))].t_step" "$out/lsq.json")
    fig="steps[t_step=$(awk -v t="$t" 'BEGIN { printf "%g", t }')].$key"
    got=$(row "$j" "$fig" difference)
    want=$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.12g", b - a }')
    # Both sides are the same doubles, so B − A agrees to rounding (1e-9 of values ~1).
    near "$got" "$want" 1e-9 || fail "$fig: difference $got, want $want"
    n=$((n + 1))
  done
done
[ "$n" = 6 ] || fail "compared $n figures"
echo "ok"
