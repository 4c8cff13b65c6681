#!/usr/bin/env bash
# Builds the libFuzzer targets of the parsers (preset "fuzz") and runs them.
#   scripts/fuzz.sh                    each target for DYNPOS_FUZZ_SECONDS (default 15) s (CI)
#   scripts/fuzz.sh runs N [TARGET…]   each (or each named) target for N executions
#   scripts/fuzz.sh time S [TARGET…]   each (or each named) target for S seconds
# Targets: csv_reader nmea_reader column_map time_stamp scenario vessel compare_json load_table
# mcap_reader cdr_decoder msg_set db3_reader.
# Every target first runs its regression inputs (fuzz/regressions/TARGET/); then it fuzzes from
# its seed corpus (fuzz/corpus/TARGET/ and the test fixtures of its format, gathered into
# build/fuzz/seeds/) and the corpus grown by earlier runs (build/fuzz/corpus/TARGET/, kept). A
# finding stops the script (exit 1) and is saved as build/fuzz/findings/TARGET-crash-…; add it
# to fuzz/regressions/TARGET/ with a test of the fix. The executions of each run are written to
# build/fuzz/report.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-brief}"
amount="${2:-}"
shift $(( $# > 2 ? 2 : $# ))
all_targets=(csv_reader nmea_reader column_map time_stamp scenario vessel compare_json load_table
  mcap_reader cdr_decoder msg_set db3_reader)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "unknown target '$t' (${all_targets[*]})" >&2; exit 2; }
done
case "$mode" in
  brief) limit=(-max_total_time="${DYNPOS_FUZZ_SECONDS:-15}") ;;
  runs) limit=(-runs="${amount:?give the number of executions}") ;;
  time) limit=(-max_total_time="${amount:?give the seconds}") ;;
  *) echo "usage: scripts/fuzz.sh [brief | runs N | time SECONDS] [TARGET…]" >&2; exit 2 ;;
esac

bash scripts/install-deps.sh
need=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${need[@]}"
fi
source scripts/ccache-env.sh
cmake --preset fuzz "${launcher[@]}" >/dev/null
# Only the targets to run (all of them without names).
cmake --build --preset fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}"

out=build/fuzz
bash fuzz/gather-seeds.sh "$out/seeds"
mkdir -p "$out/findings"
declare -A dict=([csv_reader]=csv [nmea_reader]=nmea [column_map]=toml [time_stamp]=time
  [scenario]=toml [vessel]=toml [compare_json]=json [load_table]=csv [mcap_reader]=mcap
  [cdr_decoder]=cdr [msg_set]=cdr [db3_reader]=db3)
for t in "${targets[@]}"; do
  [ -n "${dict[$t]:-}" ] || { echo "unknown target '$t' (${all_targets[*]})" >&2; exit 2; }
  bin="$out/fuzz/fuzz_$t"
  if compgen -G "fuzz/regressions/$t/*" >/dev/null; then
    "$bin" -rss_limit_mb=2048 -timeout=10 fuzz/regressions/"$t"/* 2>"$out/$t.regressions.log" ||
      { tail -30 "$out/$t.regressions.log"; echo "fuzz: a regression input of $t fails" >&2; exit 1; }
  fi
  mkdir -p "$out/corpus/$t"
  log="$out/$t.log"
  if ! "$bin" "${limit[@]}" -dict="fuzz/dict/${dict[$t]}.dict" -max_len=16384 -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$out/findings/$t-" \
      "$out/corpus/$t" "$out/seeds/$t" >"$log" 2>&1; then
    tail -40 "$log"
    echo "fuzz: $t found a crash, hang or leak; see $out/findings/" >&2
    exit 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log")
  line="$(date -u +%FT%TZ) $t: ${runs:-?} executions in ${secs:-?} s, corpus $(ls "$out/corpus/$t" | wc -l) inputs, no finding"
  echo "$line" | tee -a "$out/report.txt"
done
