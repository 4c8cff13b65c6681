#!/usr/bin/env bash
# End-to-end: outputs on a read-only file system are refused before the run, exit 2, naming the
# option and the folder (--json exited 1 after the run). Needs a mount namespace (root, or
# unprivileged user namespaces) for a read-only tmpfs: exit 77 (skipped) without one.
set -uo pipefail
exe="$1"
if [ "${2:-}" != inside ]; then
  unshare -m true 2>/dev/null || exit 77
  exec unshare -m --propagation private bash "$0" "$exe" inside
fi
dir=$(mktemp -d) || exit 77
trap 'umount "$dir" 2>/dev/null; rmdir "$dir"' EXIT
mount -t tmpfs -o ro none "$dir" 2>/dev/null || exit 77
expect() {
  local pattern="$1"; shift
  local output status
  output=$("$exe" "$@" 2>&1); status=$?
  [ "$status" = 2 ] || { echo "FAIL: exit $status from $*: $output"; exit 1; }
  printf '%s' "$output" | grep -Eq -- "$pattern" \
    || { echo "FAIL: $* said: $output"; exit 1; }
}
expect "\\(--json\\): cannot write in folder '$dir': Read-only file system" \
  hybrid first-order --json "$dir/x.json"
expect "\\(--out\\): cannot write in folder '$dir': Read-only file system" \
  simulate surge-steps-forward --duration 5 --out "$dir"
echo ok
