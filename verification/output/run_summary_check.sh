#!/usr/bin/env bash
# Run vibrobeam on INPUT in a fresh directory, keep what it prints, and check it with
# check_run_summary against the result file.   usage: run_summary_check.sh VIBROBEAM INPUT CHECKER
set -euo pipefail
vibrobeam=$1; input=$2; checker=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$vibrobeam" "$input" > screen.txt
"$checker" screen.txt summary.h5
