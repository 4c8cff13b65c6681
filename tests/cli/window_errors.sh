#!/usr/bin/env bash
# One window rule for every windowed analysis (LogSource::load): the same bad --from/--to gives
# the same message, up to the command, in each one named after the log. A window without a row
# of the log, and an empty one.
set -uo pipefail
exe="$1"; log="$2"
pos=(--col north=response --col east=response)
commands=("identify four-corner $log ${pos[*]} --col heading=flat --unit heading=rad"
          "identify station-keeping $log ${pos[*]}")
check() {  # WINDOW_ARGS EXPECTED_MESSAGE
  for command in "${commands[@]}"; do
    # shellcheck disable=SC2086
    err=$("$exe" $command $1 2>&1 >/dev/null); code=$?
    if [ "$code" != 2 ] || [ "$err" != "$2" ]; then
      printf '%s %s: exit %s\n got: %s\nwant: %s\n' "$command" "$1" "$code" "$err" "$2"; exit 1
    fi
  done
}
where="dynpos: error: $log (--from/--to)"
check "--from 5000 --to 6000" \
  "$where: the window 5000 … 6000 s starts after the log's last row at 70 s; choose a window inside the logged time"
check "--from 50 --to 10" "$where: the window 50 … 10 s is empty; give a start before the end"
echo "ok"
