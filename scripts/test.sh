#!/usr/bin/env bash
# Build (installing any missing Debian packages first) and run the test suite: every test except
# the slow paper cases (ctest label "paper"), which run with: ctest --test-dir build -L paper
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

# ParaView's pvpython opens the XDMF files in two tests as a user's ParaView would (under
# xvfb-run); without it they skip, so the tests install it (not setup.sh: granbench does not need
# it to run).
bash scripts/install_missing.sh test python3-paraview xvfb xauth

ctest --test-dir build --output-on-failure -j2 -LE paper
