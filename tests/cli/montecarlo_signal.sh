#!/usr/bin/env bash
# montecarlo_signal.sh DYNPOS OUT_DIR CLI_DIR: Ctrl-C during montecarlo removes its work
# folder (each seed's run files, hundreds of MB for long runs), not only the run being written.
set -u
dynpos="$1" out="$2" here="$3"
rm -rf "$out" && mkdir -p "$out/work" || exit 1
"$dynpos" montecarlo "$here/short.toml" --seeds 1..200 --jobs 1 --work-dir "$out/work" \
  >"$out/stdout.txt" 2>"$out/stderr.txt" &
pid=$!
for _ in $(seq 100); do  # a seed's folder appears within a second
  compgen -G "$out/work/dynpos-montecarlo-*/seed-*" >/dev/null && break
  sleep 0.1
done
compgen -G "$out/work/dynpos-montecarlo-*/seed-*" >/dev/null ||
  { echo "FAIL: no seed folder appeared"; kill "$pid"; exit 1; }
kill -INT "$pid"
wait "$pid"
code=$?
if [ "$code" != 130 ]; then echo "FAIL: exit $code, expected 130"; cat "$out/stderr.txt"; exit 1; fi
left=$(ls -A "$out/work")
if [ -n "$left" ]; then echo "FAIL: left in the work folder: $left"; exit 1; fi
echo "ok: exit 130, work folder removed"
