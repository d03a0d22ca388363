#!/bin/bash
# Regenerates results.txt of studies/string_obstacle (REPORT.md): the plucked string against
# a point obstacle at L/4, vibrobeam's velocity scheme against the exact solution by
# characteristics. Needs a Release build with -DVIBROBEAM_STUDIES=ON in build/ (or give
# the build directory as $1). About 4 minutes on one core.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
study=$build/studies/string_obstacle/string_obstacle_study
{
  echo "## A. N and dt together (dt = h/(2c)), e = 1, 20 s (12 contact intervals)"
  "$study" 20 1280 2 1
  echo
  echo "## B. the first contact interval only (1.2 s), e = 1"
  "$study" 1.2 1280 2 1
  echo
  echo "## C. dt alone: dt = h/(8c) (compare with A at the same N), e = 1, 20 s"
  "$study" 20 320 8 1
  echo
  echo "## D. e = 0 at the node (the continuum's solution does not depend on e), 20 s"
  "$study" 20 1280 2 0
} > "$here/results.txt"
echo "wrote $here/results.txt"
