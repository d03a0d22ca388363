#!/bin/bash
# Regenerates results.txt of studies/string_obstacle (REPORT.md): the plucked string against
# a point obstacle at L/4, vibrobeam's velocity scheme against the exact solution by
# characteristics. Needs a Release build with -DVIBROBEAM_STUDIES=ON in build/ (or give
# the build directory as $1). About 10 minutes on one core.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
study=$build/studies/string_obstacle/string_obstacle_study
# arguments: t_end, largest N, courant (dt = h/(courant c)), e, level/d, smallest N
{
  echo "## A. N and dt together (dt = h/(2c)), e = 1, 20 s (12 contact intervals)"
  "$study" 20 1280 2 1 -0.3 20
  echo
  echo "## B. the first contact interval only (1.2 s), e = 1"
  "$study" 1.2 1280 2 1 -0.3 20
  echo
  echo "## C. dt alone at N = 320: dt = h/(4c) .. h/(32c) (dt = h/(2c) is in A), e = 1, 20 s"
  for courant in 4 8 16 32; do "$study" 20 320 $courant 1 -0.3 320; done
  echo
  echo "## D. e = 0 at the node (the continuum's solution does not depend on e), 20 s"
  "$study" 20 1280 2 0 -0.3 20
  echo
  echo "## E. the same pluck without contact (obstacle at -10 d): the free string's error, 20 s"
  "$study" 20 1280 2 1 -10 20
  echo
  echo "## F. shorter windows: 3 s (2 contact intervals), 6 s (3), 10 s (6), e = 1"
  for t_end in 3 6 10; do "$study" $t_end 1280 2 1 -0.3 80; done
  echo
  echo "## H. N refined with a small time step, dt = h/(16c), e = 1, 20 s"
  "$study" 20 320 16 1 -0.3 40
  echo
  echo "## G. the conditioning of the exact problem: the pluck's height times 1 + delta"
  "$study" sensitivity
} > "$here/results.txt"
echo "wrote $here/results.txt"
