#!/usr/bin/env bash
# montecarlo_merge_runs.sh DYNPOS OUT_DIR CLI_DIR: shards of different runs are not merged. Each shard
# records what defines its run (the scenario and vessel files' FNV-1a 64, the run length, the
# measurement, the version); merge refuses a shard of an edited scenario or of another
# --duration (exit 2, naming both files and what differs), and a shard that is not i/N with
# 1 <= i <= N (7/3, 0/0).
set -u
dynpos="$1" out="$2" scenario_dir="$3"
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1
failed=0
mc() { "$dynpos" montecarlo "$@" --jobs 1 >/dev/null 2>&1 || { echo "FAIL: montecarlo $*"; failed=1; }; }
expect() {  # expect REGEX COMMAND...
  local pattern="$1"; shift
  local output code
  output=$("$dynpos" "$@" 2>&1); code=$?
  if [ "$code" != 2 ] || ! printf '%s' "$output" | grep -Eq -- "$pattern"; then
    echo "FAIL: dynpos $*: exit $code, expected 2 and /$pattern/:"; echo "$output"; failed=1
  fi
}
cp "$scenario_dir/short.toml" run.toml
mc run.toml --seeds 1..2 --shard 1/2 --duration 30 --json s1.json
mc run.toml --seeds 1..2 --shard 2/2 --duration 30 --json s2.json
"$dynpos" montecarlo merge s1.json s2.json --json merged.json >/dev/null ||
  { echo "FAIL: the shards of one run were not merged"; failed=1; }
# The same scenario file edited (a stronger current) between the shards.
sed 's/^current_speed_mps = 0.2/current_speed_mps = 0.5/' run.toml > edited.toml
mv edited.toml run.toml
mc run.toml --seeds 1..2 --shard 2/2 --duration 30 --json s2-edited.json
expect "s2-edited.json.*another run than 's1.json'.*scenario file" \
  montecarlo merge s1.json s2-edited.json
# Another run length.
cp "$scenario_dir/short.toml" run.toml
mc run.toml --seeds 1..2 --shard 2/2 --duration 32 --json s2-longer.json
expect "s2-longer.json.*another run than 's1.json'.*run length \(--duration\) is 32 s here, 30 s there" \
  montecarlo merge s1.json s2-longer.json
# Shard numbers that do not exist.
sed 's/"index": *2/"index": 7/; s/"count": *2/"count": 3/' s2.json > s7of3.json
expect "s7of3.json.*shard 7/3 does not exist.*--shard" montecarlo merge s1.json s7of3.json
sed 's/"index": *1/"index": 0/; s/"count": *2/"count": 0/' s1.json > s0of0.json
expect "s0of0.json.*shard 0/0 does not exist" montecarlo merge s0of0.json s2.json
[ "$failed" = 0 ] && echo "ok: shards of other runs and bad shard numbers refused"
exit "$failed"
