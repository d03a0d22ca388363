#!/usr/bin/env bash
# The cost of one periodic orbit by shooting against the time-marching transient it
# replaces (studies/periodic_cost/REPORT.md; issue 20, "Cost"): the rattling beam against
# one stop at resonance (8 and 32 Hermite elements, and the 32 reduced by Craig-Bampton),
# medians of REPEATS runs of each. Builds Release (-O2) in BUILD_DIR, runs for about a
# minute and writes studies/periodic_cost/periodic_cost.txt (the machine is shared:
# repeat the script and compare).
#   usage: studies/periodic_cost/periodic_cost.sh [BUILD_DIR] [REPEATS]   (default: build 5)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
repeats=${2:-5}
table=studies/periodic_cost/periodic_cost.txt
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

source scripts/build_release.sh
build_release "$build" periodic_cost
program=$build/studies/periodic_cost/periodic_cost
start=$(date +%s)
: > "$table"
"$program" "$table" "$repeats" 2000 verification/periodic/rattling_resonance.nml \
  verification/periodic/rattling_period_two.nml studies/periodic_cost/rattling_resonance_n32.nml \
  studies/periodic_cost/rattling_resonance_n32_reduced.nml studies/periodic_cost/rattling_resonance_light.nml
echo "# medians of $repeats runs" >> "$table"
describe_study_run "$table" "$build" "$program" "$start" "$load_before"
echo "periodic_cost: wrote $table" >&2
