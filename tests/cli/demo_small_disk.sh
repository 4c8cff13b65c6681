#!/usr/bin/env bash
# demo_small_disk.sh DYNPOS OUT_DIR: on a disk too small for the campaign's logs (a 16 MB
# tmpfs), demo refuses before it starts, with the figures (exit 2), and writes nothing. Mounting
# needs root and a system that permits it: elsewhere the test is skipped (exit 77).
set -u
dynpos="$1" out="$2"
rm -rf "$out" && mkdir -p "$out/disk" || exit 1
mount -t tmpfs -o size=16m tmpfs "$out/disk" 2>/dev/null || { echo "skipped: cannot mount a tmpfs"; exit 77; }
trap 'umount "$out/disk"' EXIT
output=$(timeout 120 "$dynpos" demo --out "$out/disk/report" 2>&1); code=$?
failed=0
if [ "$code" != 2 ] || ! printf '%s' "$output" |
    grep -Eq -- "\(--out\): the files would take about [0-9.]+ [MG]B; [0-9]+ MB is free"; then
  echo "FAIL: exit $code, expected 2 with the figures:"; printf '%s\n' "$output" | tail -5; failed=1
fi
left=$(ls -A "$out/disk")
if [ -n "$left" ]; then echo "FAIL: left on the disk: $left"; failed=1; fi
[ "$failed" = 0 ] && echo "ok: refused before it started, nothing written"
exit "$failed"
