#!/usr/bin/env bash
# write_failures.sh DYNPOS OUT_DIR CLI_DIR: a write that fails for want of space (/dev/full:
# ENOSPC) or over the file size limit (ulimit -f: EFBIG, SIGXFSZ ignored by dynpos) names the
# path and the reason with what to do, exit 2; no temporary file or run folder is left.
set -u
dynpos="$1" out="$2" here="$3"
rm -rf "$out" && mkdir -p "$out" || exit 1
failed=0
output=$("$dynpos" compare "$here/data/compare/steps_aug.json" "$here/data/compare/steps_nov.json" \
  --json /dev/full 2>&1); code=$?
if [ "$code" != 2 ] || ! printf '%s' "$output" |
    grep -q "/dev/full: writing it failed: No space left on device; free some space or write elsewhere"; then
  echo "FAIL /dev/full: exit $code:"; echo "$output"; failed=1
fi
# 64 kB of file: the run's log.csv (about 160 kB) is larger.
output=$(bash -c 'ulimit -f 64; exec "$0" simulate "$1" --out "$2"' "$dynpos" "$here/short.toml" \
  "$out/run" 2>&1); code=$?
if [ "$code" != 2 ] || ! printf '%s' "$output" | grep -q "run/.*File too large.*ulimit -f"; then
  echo "FAIL ulimit -f: exit $code:"; echo "$output"; failed=1
fi
left=$(ls -A "$out/run" 2>/dev/null)
if [ -n "$left" ]; then echo "FAIL: left in the run folder: $left"; failed=1; fi
[ "$failed" = 0 ] && echo "ok: ENOSPC and EFBIG named, exit 2, nothing left"
exit "$failed"
