#!/usr/bin/env bash
# Installs dependencies, builds dynpos and runs the main job on the built-in virtual Gunnerus.
#   scripts/demo.sh [OUT_DIR]   (default: out/demo)
# Until the whole campaign and report land in 'dynpos demo', the main job is one virtual sea
# trial: the forward surge step programme of thesis section 3.5.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/demo}"
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target dynpos_cli
./build/release/bin/dynpos simulate surge-steps-forward --out "$out"
echo "virtual sea trial written to $out (log.csv, truth.json); see docs/log-format.md"
