#!/usr/bin/env bash
# Run vibrobeam on one input inside a fresh work directory, then a checker program there.
# usage: run_case.sh WORKDIR VIBROBEAM INPUT.nml CHECKER [CHECKER ARGS...]
# The checker reads the result file the run wrote (its name is given in the input) and
# compares it with an independent reference; this script fails if either step fails.
set -euo pipefail
workdir=$1; vibrobeam=$2; input=$3; shift 3
rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
"$vibrobeam" "$input"
"$@"
