#!/usr/bin/env bash
# A numerical failure (docs/output.md, "Exit status"): exit status 3, a message naming the step, and a
# complete HDF5 file whose /run status is 'failed' and whose histories stop before t_end.
# usage: run_numerical_failure.sh VIBROBEAM INPUT.nml [STEPS [MESSAGE]]
# INPUT writes failure.h5 and asks for STEPS steps (default 1000); MESSAGE (a grep pattern,
# default none) must appear on stderr.
# (The failure is a contact solver without convergence, so Debug builds run it too.)
set -uo pipefail
vibrobeam=$1; input=$2; asked=${3:-1000}; message=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$vibrobeam" "$input" > stdout.txt 2> stderr.txt
status=$?
passed=0; failed=0
check() { if eval "$2"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL $1"; fi; }
check "exit status $status, expected 3" '[ "$status" -eq 3 ]'
check "stderr names the numerical failure" 'grep -q "numerical failure at step [0-9]" stderr.txt'
[ -z "$message" ] || check "stderr says '$message'" 'grep -q -E -- "$message" stderr.txt'
check "no temporary file left" '[ ! -e failure.h5.tmp ]'
check "/run status is failed" 'h5dump -a /run/status failure.h5 | grep -q "\"failed\""'
steps=$(h5dump -a /run/steps failure.h5 | sed -n 's/.*(0): *\([0-9]*\).*/\1/p')
check "steps before the failure ($steps) fewer than the $asked asked" '[ -n "$steps" ] && [ "$steps" -lt "$asked" ] && [ "$steps" -gt 0 ]'
samples=$(h5dump -H -d /time failure.h5 | sed -n 's/.*SIMPLE { ( \([0-9]*\) ).*/\1/p' | head -1)
check "/time holds every step up to the failure ($samples samples for $steps steps)" '[ "$samples" = "$((steps + 1))" ]'
cat stderr.txt
echo "run_numerical_failure: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
