#!/usr/bin/env bash
# Build (installing any missing Debian packages first) and run the test suite: every test except
# the slow paper cases (ctest label "paper"), which run with: ctest --test-dir build -L paper
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir build --output-on-failure -j2 -LE paper
