#!/usr/bin/env bash
# End-to-end: when the system cannot start a thread, every subcommand used to abort (an uncaught
# std::system_error, exit 134: `ulimit -v 32768`, or a limit of processes); now the work is
# done on the threads there are (the calling one): the same results as without the limit.
# Deterministic: a thread's default stack is the soft stack limit, here 4 GiB, which does not fit
# the 1 GiB of address space allowed, while the calling thread has the memory it needs.
set -euo pipefail
exe="$1"; out="$2"
rm -rf "$out"; mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
limited() { (ulimit -s 4194304; ulimit -v 1048576; exec "$exe" "$@"); }

# simulate: the signal thread and the run's writing thread. A log of 3 MB (three blocks of
# 1 MiB, read on several threads below).
"$exe" simulate surge-steps-forward --duration 200 --out "$out/free" > /dev/null
limited simulate surge-steps-forward --duration 200 --out "$out/limited" > /dev/null \
  || fail "simulate exit $?"
cmp "$out/free/log.csv" "$out/limited/log.csv" || fail "simulate: another log"
cmp "$out/free/truth.json" "$out/limited/truth.json" || fail "simulate: another truth"

# identify step: the log read in blocks and the steps fitted on --jobs threads.
step=(identify step "$out/free/log.csv" --col input=command.rpm.stb --col output=rpm.stb)
"$exe" "${step[@]}" --jobs 4 --json "$out/step_free.json" > /dev/null
limited "${step[@]}" --jobs 4 --json "$out/step_limited.json" > /dev/null || fail "identify step exit $?"
cmp "$out/step_free.json" "$out/step_limited.json" || fail "identify step: another result"

# --jobs far beyond the threads there are.
limited "${step[@]}" --jobs 256 --json "$out/step_256.json" > /dev/null || fail "--jobs 256 exit $?"
cmp "$out/step_free.json" "$out/step_256.json" || fail "identify step --jobs 256: another result"

# capability level 3: the directions on --jobs threads.
cap=(capability --level 3 --failure none --direction-step 90 --duration 60 --settle 60
     --wind-tolerance 2 --jobs 4)
"$exe" "${cap[@]}" --json "$out/cap_free.json" > /dev/null
limited "${cap[@]}" --json "$out/cap_limited.json" > /dev/null || fail "capability exit $?"
cmp "$out/cap_free.json" "$out/cap_limited.json" || fail "capability: another result"
echo ok
