#!/usr/bin/env bash
# One-step set-up on Debian 12 (as root or with sudo): install the Debian packages granbench
# needs, then configure and build into ./build. Quick when everything is already in place.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_missing.sh setup build-essential cmake pkg-config \
  libsundials-dev libeigen3-dev libfftw3-dev libgsl-dev libhdf5-dev libcli11-dev \
  nlohmann-json3-dev googletest libgtest-dev libopenmpi-dev openmpi-bin \
  python3 python3-matplotlib python3-h5py python3-numpy

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
