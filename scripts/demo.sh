#!/usr/bin/env bash
# Installs dependencies, builds dynpos and runs the main job on the built-in virtual Gunnerus.
#   scripts/demo.sh [OUT_DIR]   (default: out/demo)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/demo}"
bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target dynpos_cli _dynpos
bash scripts/install-python.sh build/release
./build/release/bin/dynpos demo --out "$out"
