#!/usr/bin/env bash
# Gathers the seed corpus of each fuzz target into DIR/TARGET/: the hand-written seeds of
# fuzz/corpus/TARGET/ and the test fixtures of its format (logs, captures, maps, scenario and
# vessel files, compare results), so the fuzzers start from what the tests already read.
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:?usage: fuzz/gather-seeds.sh DIR}"
rm -rf "$dir"
for t in csv_reader nmea_reader column_map time_stamp scenario vessel compare_json load_table \
    mcap_reader cdr_decoder msg_set db3_reader; do
  mkdir -p "$dir/$t"
  [ -d "fuzz/corpus/$t" ] && cp fuzz/corpus/"$t"/* "$dir/$t/"
done
for f in tests/data/io/*.csv tests/data/multifile/*.csv tests/data/step_segments.csv; do
  cp "$f" "$dir/csv_reader/$(basename "$(dirname "$f")")_$(basename "$f")"
  # The time column alone, one stamp per line, for the time-stamp parsers.
  grep -v '^#' "$f" | cut -d, -f1 >"$dir/time_stamp/$(basename "$f" .csv).txt"
done
# The two-file example of docs/log-format.md with its map.
{ printf '[roles]\ntime = "time"\nnorth = "north"\neast = "east"\n%%%%\n'
  cat tests/data/multifile/main.csv; } >"$dir/csv_reader/mapped_main.txt"
cp tests/data/nmea/*.nmea "$dir/nmea_reader/"
cp data/scenarios/*.toml tests/cli/short.toml tests/cli/bad_sensor_rate.toml "$dir/scenario/"
cp data/vessels/*.toml tests/cli/bad_vessel.toml tests/cli/data/osv_layout.toml "$dir/vessel/"
cp tests/cli/bad_loads.csv "$dir/load_table/"
cp tests/cli/data/compare/*.json "$dir/compare_json/"
for pair in steps_aug:steps_nov legs_before:legs_after generic_a:generic_b; do
  a="${pair%%:*}" b="${pair##*:}"
  { cat "tests/cli/data/compare/$a.json"; printf '\n%%%%\n'; cat "tests/cli/data/compare/$b.json"; } \
    >"$dir/compare_json/$a-$b.txt"
done
