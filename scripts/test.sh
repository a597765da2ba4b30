#!/usr/bin/env bash
# Build (installing any missing Debian packages first) and run the test suite: every test except
# the slow paper cases (ctest label "paper"), which run with: ctest --test-dir build -L paper
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

# ParaView's pvpython opens the XDMF files in two tests as a user's ParaView would (under
# xvfb-run); without it they skip, so the tests install it (not setup.sh: granbench does not need
# it to run).
viewer=(python3-paraview xvfb xauth)
missing=()
for p in "${viewer[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "test: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

ctest --test-dir build --output-on-failure -j2 -LE paper
