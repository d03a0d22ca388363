#!/usr/bin/env bash
# Sweeps against their number of points (studies/sweep_scaling/REPORT.md): the CPU time of
# `vibrobeam --check` (resolving and listing every point) and the peak resident set of a
# run (/run peak_memory_kb), for sweeps of 10^3 .. 10^5 points of the sweep tests' scene
# (verification/sweep/scene.nml.in, 8 elements): independent points of 5 steps each, and
# points of 260 forcing periods each (4 082 steps, the 256 Poincare samples a point keeps).
# Writes studies/sweep_scaling/sweep_scaling.txt.
#   usage: studies/sweep_scaling/sweep_scaling.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
build=${1:-build}
table=$root/studies/sweep_scaling/sweep_scaling.txt
# shellcheck source=../../scripts/build_release.sh
. scripts/build_release.sh
build_release "$build" vibrobeam
vibrobeam=$root/$build/vibrobeam
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# sweep NAME FREQUENCY SWEEP: the scene of the sweep tests with the &sweep group SWEEP
sweep() {
  sed -e "s|@FILE@|$1.h5|" -e "s|@FREQUENCY@|$2|" -e "s|@SCHEME@|velocity|" -e "s|@T_END@||" \
      -e "s|@OUTPUT@||" -e "s|@SWEEP@|$3|" "$root/verification/sweep/scene.nml.in" > "$1.nml"
}
peak() { h5dump -a /run/peak_memory_kb "$1.h5" | sed -n 's/.*(0): *\([0-9]*\).*/\1/p'; }

{
  echo "# sweep_scaling.sh $(git -C "$root" rev-parse --short HEAD) on $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# --check: CPU time (user + system) and peak resident set of resolving and listing every point"
  echo "# points  check_cpu_s  check_wall_s  check_peak_kB"
  for points in 1000 10000 30000 100000; do
    sweep check$points 200 "\\&sweep parameter = 'load.point_frequency', from = 100, to = 300, count = $points, settle = 0, measure = 1e-4 /"
    /usr/bin/time -f "%U %S %e %M" -o time.txt "$vibrobeam" --check check$points.nml > /dev/null
    read -r user system wall kb < time.txt
    echo "$points $(awk "BEGIN {print $user + $system}") $wall $kb"
  done
  echo "# run (OMP_NUM_THREADS=1): peak resident set (kB), /run peak_memory_kb"
  echo "# points  steps_per_point  peak_kB  wall_s"
  for points in 1000 10000 100000; do
    sweep run$points 200 "\\&sweep parameter = 'load.point_frequency', from = 100, to = 300, count = $points, settle = 0, measure = 1e-4 /"
    /usr/bin/time -f "%e" -o time.txt env OMP_NUM_THREADS=1 "$vibrobeam" run$points.nml > /dev/null
    echo "$points 5 $(peak run$points) $(cat time.txt)"
  done
  for points in 100 1000 10000; do
    sweep poincare$points 20000 "\\&sweep parameter = 'load.point_frequency', from = 20000, to = 20100, count = $points, settle = 0, measure_periods = 260 /"
    /usr/bin/time -f "%e" -o time.txt env OMP_NUM_THREADS=1 "$vibrobeam" poincare$points.nml > /dev/null
    echo "$points 4082 $(peak poincare$points) $(cat time.txt)"
  done
} | tee "$table"
