#!/usr/bin/env bash
# End-to-end: inputs that never end (/dev/zero) are refused after a stated amount, with an error
# naming them (exit 2), not copied to the disk or read into memory without bound. Each command
# runs with 128 MiB of file size, 4 GB of memory and 120 s, so that a reader without its bound
# fails this test instead of filling the machine. Under AddressSanitizer (4th argument
# "no-memory-limit") there is no memory limit: the sanitizer reserves terabytes of address space
# for its shadow memory, which `ulimit -v` refuses; the file size and the time still bound it.
set -uo pipefail
exe="$1"; out="$2"; src="$3"; memory="${4:-memory-limit}"
limits=(-f 131072)
[ "$memory" = no-memory-limit ] || limits+=(-v 4000000)
rm -rf "$out"; mkdir -p "$out/tmp"
main="$src/tests/data/multifile/main.csv"
result="$src/tests/cli/data/compare/steps_aug.json"
# expect CODE REGEX COMMAND...
expect() {
  local want="$1" pattern="$2"; shift 2
  (ulimit "${limits[@]}"; TMPDIR="$out/tmp" timeout 120 "$@") > "$out/out.txt" 2>&1
  local got=$?
  if [ "$got" != "$want" ] || ! grep -Eq -- "$pattern" "$out/out.txt"; then
    echo "$*: exit $got, expected $want and /$pattern/:"; head -c 2000 "$out/out.txt"; exit 1
  fi
  if [ -n "$(ls -A "$out/tmp")" ]; then echo "$*: left $(ls "$out/tmp")"; exit 1; fi
}
# A main log read once is copied to $TMPDIR up to the first 16 MiB without a line end.
expect 2 "/dev/zero:1: no line end within 16 MiB: not a text log" \
  "$exe" identify station-keeping /dev/zero
expect 2 "standard input:1: no line end within 16 MiB" \
  bash -c "'$exe' identify station-keeping - < /dev/zero"
# Binary data with line ends: no 100 text lines in a row in the first 16 MiB.
expect 2 "/dev/urandom: not a text log: its first 16 MiB hold neither 100 text lines" \
  "$exe" identify station-keeping /dev/urandom
# JSON results (compare, montecarlo merge): at most 64 MiB; a column map: at most 16 MiB.
expect 2 "/dev/zero: more than 64 MiB" "$exe" compare "$result" /dev/zero
expect 2 "/dev/zero: more than 64 MiB" "$exe" montecarlo merge /dev/zero
expect 2 "/dev/zero: more than 16 MiB" "$exe" identify station-keeping "$main" --map /dev/zero
echo ok
