#!/usr/bin/env bash
# One-step set-up on Debian 12 (as root or with sudo): install the Debian packages granbench
# needs, then configure and build into ./build. Quick when everything is already in place.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config
  libsundials-dev libeigen3-dev libfftw3-dev libgsl-dev libhdf5-dev libcli11-dev
  nlohmann-json3-dev googletest libgtest-dev libopenmpi-dev openmpi-bin
  python3 python3-matplotlib python3-h5py python3-numpy)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "setup: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
