#!/usr/bin/env bash
# A failed static solve (docs/output.md, "Exit status"; issue 23, item 12): exit status 3,
# the reason and advice for statics on stderr (no time step: statics has none), and a
# complete published file marked failed: /run status 'failed', /static failure holding the
# reason, /static/displacement and /static/reaction holding the last iterate, the text
# files derived, no temporary file left.
# usage: run_static_failure.sh VIBROBEAM INPUT.nml REASON ADVICE
#   (REASON, ADVICE: what stderr and /static failure must say)
set -uo pipefail
vibrobeam=$1; input=$2; reason=$3; advice=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$vibrobeam" "$input" > stdout.txt 2> stderr.txt
status=$?
file=$(sed -n "s/^&output *file = '\(.*\)'.*/\1/p" "$input")
stem=${file%.h5}
passed=0; failed=0
check() { if eval "$2"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL $1"; fi; }
check "exit status $status, expected 3" '[ "$status" -eq 3 ]'
check "stderr says the static equilibrium failed and why" 'grep -q -F "static equilibrium failed: $reason" stderr.txt'
check "stderr gives its advice" 'grep -q -F "$advice" stderr.txt'
check "stderr gives no time-step advice" '! grep -q -i -E "(^|[^a-z])dt([^a-z]|$)|time step" stderr.txt'
check "stderr says where the last iterate went" 'grep -q "last iterate, not an equilibrium, written to $file" stderr.txt'
check "no temporary file left" '[ -z "$(ls -A | grep tmp)" ]'
check "/run status is failed" 'h5dump -a /run/status $file | grep -q "\"failed\""'
check "/static failure holds the reason" 'h5dump -a /static/failure $file | grep -q -F "$reason"'
check "/static/displacement holds every node" 'h5dump -H -d /static/displacement $file | grep -q "SIMPLE"'
check "/static/reaction holds every contact point" 'h5dump -H -d /static/reaction $file | grep -q "SIMPLE"'
check "the text files are derived" '[ -s ${stem}_static.dat ] && [ -s ${stem}_reactions.dat ]'
check "nothing on stdout claims an equilibrium" '! grep -q "static equilibrium with" stdout.txt'
cat stderr.txt
echo "run_static_failure: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
