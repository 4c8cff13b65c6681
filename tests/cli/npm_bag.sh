#!/usr/bin/env bash
# npm_bag.sh DYNPOS OUT: a chunked ROS 2 bag written by @mcap/core (an MCAP writer independent
# of dynpos; tests/bag_npm/), its chunks zstd and LZ4 frames in turn, gives `identify step` the
# same result as a CSV of the same numbers (every JSON number within 1e-12 relative). The npm
# packages are installed with `npm ci` into OUT (kept while the lock file is the same); skipped
# (exit 77) only when node or npm is absent.
set -euo pipefail
dynpos="$1"; out="$2"
src="$(cd "$(dirname "$0")/../bag_npm" && pwd)"
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  echo "skipped: node or npm is not installed; the @mcap/core bag test needs them"
  exit 77
fi
mkdir -p "$out"
cp "$src/write_bag.js" "$out/"
if ! cmp -s "$src/package-lock.json" "$out/package-lock.json" || [ ! -d "$out/node_modules" ]; then
  cp "$src/package.json" "$src/package-lock.json" "$out/"
  (cd "$out" && npm ci --no-audit --no-fund --loglevel=error)
fi
node "$out/write_bag.js" "$out"
"$dynpos" identify step "$out/steps.mcap" --col input=/cmd.data --col output=/feedback.rpm \
  --json "$out/bag.json" >/dev/null
"$dynpos" identify step "$out/steps.csv" --col input=cmd --col output=rpm \
  --json "$out/csv.json" >/dev/null
node - "$out/bag.json" "$out/csv.json" <<'JS'
const fs = require("fs");
const [bag, csv] = process.argv.slice(2).map((f) => JSON.parse(fs.readFileSync(f, "utf8")));
let numbers = 0;
const same = (a, b, at) => {
  if (typeof a === "number" && typeof b === "number") {
    numbers += 1;
    if (Math.abs(a - b) > 1e-12 * Math.max(Math.abs(a), Math.abs(b), 1e-300))
      throw new Error(`${at}: ${a} from the bag, ${b} from the CSV`);
    return;
  }
  if (typeof a !== typeof b || Array.isArray(a) !== Array.isArray(b) || (a === null) !== (b === null))
    throw new Error(`${at}: ${JSON.stringify(a)} vs ${JSON.stringify(b)}`);
  if (a === null || typeof a !== "object") {
    if (a !== b) throw new Error(`${at}: ${a} vs ${b}`);
    return;
  }
  const keys = Object.keys(a).filter((k) => k !== "input" && k !== "log");
  if (Array.isArray(a) && a.length !== b.length) throw new Error(`${at}: lengths differ`);
  for (const k of keys) same(a[k], b[k], `${at}.${k}`);
};
same(bag, csv, "step");
if (bag.steps.length !== 2) throw new Error(`${bag.steps.length} steps, not 2`);
if (bag.input.files[0].topic !== "/cmd" || bag.input.files[1].time_format !== "header.stamp")
  throw new Error("the input report does not name the topics");
console.log(`ok: ${numbers} numbers equal within 1e-12 relative`);
JS
