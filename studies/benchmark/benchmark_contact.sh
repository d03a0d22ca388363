#!/usr/bin/env bash
# Benchmark of the contact projection (studies/benchmark/REPORT.md, "The contact
# projection"): the slap for N = 500 ... 16000 (time per step, its exponent, the largest
# number of linear solves in one step), the old ('pivoting') and the new ('newton') method
# side by side on every stress scene of verification/stress at N = 200, 2000, 8000, the
# static lift-off up to N = 1e5, and the 'delassus' / 'band' regime threshold.
#
# Builds Release (-O2) in BUILD_DIR (an existing build directory is switched to Release),
# runs for 10-20 minutes and writes studies/benchmark/benchmark_contact.txt. Timings
# are medians of 3 runs; the machine is shared, so repeat the script and compare.
#   usage: studies/benchmark/benchmark_contact.sh [BUILD_DIR] [quick]   (default: build; 'quick': a
#          smoke run of every part in a few seconds, written to standard output only)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
mode=${2:-}
table=studies/benchmark/benchmark_contact.txt
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

source scripts/build_release.sh
build_release "$build" benchmark_contact
program=$build/studies/benchmark/benchmark_contact

if [ "$mode" = quick ]; then
  "$program" verification/stress "" quick
  exit 0
fi
echo "benchmark_contact: timing (10-20 minutes) ..." >&2
start=$(date +%s)
"$program" verification/stress "$table"
describe_study_run "$table" "$build" "$program" "$start" "$load_before"
echo "benchmark_contact: table written to $table" >&2
