#!/usr/bin/env bash
# signal_cleanup.sh DYNPOS LOG WORK_DIR: Ctrl-C (SIGINT) during a run removes its temporary
# files (finding M4: an interrupted run left a ~100 MB temporary file). The run reads standard
# input, whose copy exists while the pipe is still open; the signal comes then.
set -u
dynpos="$1" log="$2" work="$3"
rm -rf "$work" && mkdir -p "$work"
export TMPDIR="$work"
(sleep 5; cat "$log") | "$dynpos" identify step - --col input=cmd --col output=response \
  >"$work/out.txt" 2>"$work/err.txt" &
pid=$!
for _ in $(seq 50); do  # the copy appears as soon as the command line is read
  compgen -G "$work/dynpos-input-*" >/dev/null && break
  sleep 0.1
done
compgen -G "$work/dynpos-input-*" >/dev/null || { echo "no copy of the input appeared"; exit 1; }
kill -INT "$pid"
wait "$pid"
code=$?
if [ "$code" != 130 ]; then echo "exit $code, expected 130"; cat "$work/err.txt"; exit 1; fi
grep -q "stopped by signal 2; 1 temporary file(s) removed" "$work/err.txt" ||
  { echo "no message:"; cat "$work/err.txt"; exit 1; }
if compgen -G "$work/dynpos-input-*" >/dev/null; then echo "temporary file left"; exit 1; fi
echo "ok: exit 130, temporary file removed"
