#!/usr/bin/env bash
# Benchmark of the 2-D frictional contact solver (studies/benchmark/FRICTION_REPORT.md):
# one solve for m = 1 ... 50 closed contacts (half sticking, half slipping), the same
# solver with mu = 0, and the frictionless solve_lcp on the same mu = 0 problems as the
# baseline, all in one run.
#
# Builds Release (-O2) in BUILD_DIR (an existing build directory is switched to Release),
# runs for about 30 s and writes studies/benchmark/benchmark_friction.txt. Timings are
# medians; the machine is shared, so repeat the script and compare.
#   usage: studies/benchmark/benchmark_friction.sh [BUILD_DIR] [quick]   (default: build; 'quick':
#          a smoke run in a second, written to standard output only)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
mode=${2:-}
table=studies/benchmark/benchmark_friction.txt
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

source scripts/build_release.sh
build_release "$build" benchmark_friction
program=$build/studies/benchmark/benchmark_friction

if [ "$mode" = quick ]; then
  "$program" "" quick
  exit 0
fi
echo "benchmark_friction: timing (about 30 s) ..." >&2
start=$(date +%s)
"$program" "$table"
describe_study_run "$table" "$build" "$program" "$start" "$load_before"
echo "benchmark_friction: table written to $table" >&2
