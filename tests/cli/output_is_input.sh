#!/usr/bin/env bash
# output_is_input.sh DYNPOS OUT_DIR CLI_DIR: an output that is one of the command's inputs is
# refused before anything runs (exit 2, naming both), and the input is left as it was: the
# log, a FILE of --col ROLE=COLUMN@FILE, --segments, --map, compare's A, a shard of merge, a
# hard link and a symbolic link to the input.
set -u
dynpos="$1" out="$2" here="$3"
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
cp "$here/short_steps.csv" victim.csv
cp "$here/short_steps.csv" other.csv
cp "$here/data/compare/steps_aug.json" a.json
cp "$here/data/compare/steps_nov.json" b.json
printf 'name,start,end\nall,0,100\n' > segments.csv
printf '[roles]\ninput = "cmd"\noutput = "response"\n' > map.toml
ln victim.csv hard.csv
ln -s victim.csv soft.csv
sums() { md5sum victim.csv other.csv a.json b.json segments.csv map.toml; }
before=$(sums)
failed=0
expect() {  # expect REGEX COMMAND...: exit 2 and REGEX in the message
  local pattern="$1"; shift
  local output code
  output=$("$dynpos" "$@" 2>&1); code=$?
  if [ "$code" != 2 ] || ! printf '%s' "$output" | grep -Eq -- "$pattern"; then
    echo "FAIL: dynpos $*: exit $code, expected 2 and /$pattern/:"; echo "$output"; failed=1
  fi
}
step=(identify step victim.csv --col input=cmd --col output=response)
expect "\(--json\): 'victim.csv' is the input 'victim.csv' \(log\)" "${step[@]}" --json victim.csv
expect "'other.csv' is the input 'other.csv' \(--col\)" identify step victim.csv --col input=cmd \
  --col output=response@other.csv --json other.csv
expect "\(--json\): 'segments.csv' is the input" "${step[@]}" --segments segments.csv \
  --json segments.csv
expect "\(--json\): 'map.toml' is the input" identify step victim.csv --map map.toml --json map.toml
expect "\(--json\): 'hard.csv' is the input 'victim.csv'" "${step[@]}" --json hard.csv
expect "\(--json\): 'soft.csv' is the input 'victim.csv'" "${step[@]}" --json soft.csv
expect "\(--plot\): 'victim.csv' is the input" identify four-corner victim.csv --plot victim.csv
expect "\(--json\): 'a.json' is the input 'a.json' \(A\)" compare a.json b.json --json a.json
expect "\(--json\): 'b.json' is the input" montecarlo merge a.json b.json --json b.json
after=$(sums)
if [ "$before" != "$after" ]; then echo "FAIL: an input was changed"; failed=1; fi
[ "$failed" = 0 ] && echo "ok: every output that is an input refused, the inputs kept"
exit "$failed"
