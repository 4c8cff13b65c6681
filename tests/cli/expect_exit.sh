#!/usr/bin/env bash
# expect_exit.sh CODE REGEX COMMAND...: passes when COMMAND exits with CODE and its stderr
# (or stdout) matches the extended regular expression REGEX.
set -u
want="$1"; pattern="$2"; shift 2
output=$("$@" 2>&1)
got=$?
if [ "$got" != "$want" ]; then
  echo "expected exit $want, got $got; output:"; echo "$output"; exit 1
fi
if ! printf '%s' "$output" | grep -Eq -- "$pattern"; then
  echo "output does not match /$pattern/:"; echo "$output"; exit 1
fi
echo "ok: exit $got, output matches /$pattern/"
