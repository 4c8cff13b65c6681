#!/usr/bin/env bash
# Installs the Debian packages dynpos needs to build, test and benchmark (run as root).
set -euo pipefail
packages=(
  g++ cmake ninja-build ccache clang-format jq
  libeigen3-dev libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libgeographiclib-dev
  libzstd-dev liblz4-dev zlib1g-dev libsqlite3-dev
  libceres-dev libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-pandas python3-matplotlib python3-scipy
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
