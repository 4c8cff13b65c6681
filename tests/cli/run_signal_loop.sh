#!/usr/bin/env bash
# run_signal_loop.sh DYNPOS OUT_DIR CLI_DIR [TRIES]: SIGTERM at many points of `simulate` over
# the folder of another run (seed 1 under a run of seed 2, delays spread over the run's length):
# every time, the folder holds the files of one run (all of seed 1 or all of seed 2, compared
# byte for byte) and no hidden run folder or temporary file. Bounded: TRIES (default 24) kills.
set -u
dynpos="$1" out="$2" here="$3" tries="${4:-24}"
rm -rf "$out" && mkdir -p "$out" || exit 1
run() { "$dynpos" simulate "$here/short.toml" --duration 20 --seed "$1" --out "$2" >/dev/null; }
run 1 "$out/ref1" && run 2 "$out/ref2" || { echo "FAIL: reference runs"; exit 1; }
start=$(date +%s%N); run 2 "$out/timing"; end=$(date +%s%N)
length_ms=$(( (end - start) / 1000000 + 20 ))
failed=0 stopped=0
for i in $(seq "$tries"); do
  rm -rf "$out/victim" && cp -r "$out/ref1" "$out/victim"
  "$dynpos" simulate "$here/short.toml" --duration 20 --seed 2 --out "$out/victim" \
    >/dev/null 2>&1 &
  pid=$!  # dynpos itself, not a subshell
  delay_ms=$(( length_ms * i / tries ))
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -TERM "$pid" 2>/dev/null
  wait "$pid"; code=$?
  [ "$code" = 143 ] && stopped=$((stopped + 1))
  if ! diff -r -q "$out/victim" "$out/ref1" >/dev/null && ! diff -r -q "$out/victim" "$out/ref2" >/dev/null; then
    echo "FAIL: kill after ${delay_ms} ms (exit $code) left the files of two runs:"
    for f in $(cd "$out/victim" && find . -type f); do
      if cmp -s "$out/victim/$f" "$out/ref1/$f"; then echo "  $f: seed 1";
      elif cmp -s "$out/victim/$f" "$out/ref2/$f"; then echo "  $f: seed 2";
      else echo "  $f: neither"; fi
    done
    failed=1
  fi
  hidden=$(ls -A "$out/victim" | grep '^\.' || true)
  if [ -n "$hidden" ]; then echo "FAIL: kill after ${delay_ms} ms left $hidden"; failed=1; fi
done
[ "$failed" = 0 ] && echo "ok: $tries kills ($stopped during the run), one run's files every time"
exit "$failed"
