#!/usr/bin/env bash
# The cost and accuracy of the static solve against N (studies/static_cost/REPORT.md): the
# scenes of verification/statics, both bases, N = 1e3 ... 1e5, the statics of this version
# against the one it replaced, side by side. Builds Release (-O2) in BUILD_DIR, runs for
# about a minute and writes studies/static_cost/static_cost.txt (medians of 3 solves; the
# machine is shared, so repeat the script and compare).
#   usage: studies/static_cost/static_cost.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
table=studies/static_cost/static_cost.txt
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

source scripts/build_release.sh
build_release "$build" static_cost
program=$build/studies/static_cost/static_cost
start=$(date +%s)
"$program" verification/statics "$table" 3
describe_study_run "$table" "$build" "$program" "$start" "$load_before"
echo "static_cost: wrote $table" >&2
