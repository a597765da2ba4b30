#!/usr/bin/env bash
# Regenerate docs/verification.md from the `convergence` tests' own tables: each test writes its
# grids, errors, observed orders and asserted bounds to build/verification/<name>.md
# (tests/support/verification_table.hpp); this runs them and puts the tables in one file.
# Usage: bash scripts/verification_tables.sh [build-dir]   (after bash scripts/setup.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
rm -rf "$build/verification"
cmake --build "$build" -j2 >/dev/null
ctest --test-dir "$build" -L convergence -j2 --output-on-failure >/dev/null
out=docs/verification.md
{
  cat <<'HEAD'
# Verification tables

Written by `bash scripts/verification_tables.sh`, which runs the tests labelled `convergence`
(`ctest --test-dir build -L convergence`, part of CI) and collects the table each one writes: the
grids or steps, the errors against an exact answer, the observed orders, and the bounds the test
asserts. Nothing here is typed by hand; re-run the script in any commit that changes a number.
The accuracy of the 2D model against the exact 2D linear theory, which takes minutes per grid and
is not a CI test, is in twod-validation.md.

HEAD
  echo "Generated on $(date -u +%Y-%m-%d) from the tests of the commit that holds this file."
  echo
  for group in depthavg linear2d twod; do
    case $group in
      depthavg) echo "## Depth-averaged model" ;;
      linear2d) echo "## Exact 2D linear stability (Chebyshev collocation)" ;;
      twod) echo "## 2D model" ;;
    esac
    echo
    for f in "$build"/verification/"$group"_*.md; do cat "$f"; done
  done
} >"$out"
echo "wrote $out"
