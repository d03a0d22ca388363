#!/usr/bin/env bash
# Run vibrobeam on one scene of verification/output in a fresh directory, then
# check_outputs MODE on its result.   usage: run_output_checks.sh VIBROBEAM CHECKER MODE
set -euo pipefail
vibrobeam=$1; checker=$2; mode=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$vibrobeam" "$here/$mode.nml"
"$checker" "$mode" "$mode.h5"
