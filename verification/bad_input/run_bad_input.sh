#!/usr/bin/env bash
# A bad input must make vibrobeam exit with status 2, print a message on stderr that
# contains EXPECTED (the offending variable), and write no output at all.
# usage: run_bad_input.sh VIBROBEAM INPUT.nml EXPECTED  (INPUT may be a missing file)
set -uo pipefail
vibrobeam=$1; input=$2; expected=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -f "$input" ]; then cp "$input" "$work/input.nml"; fi
cd "$work"
"$vibrobeam" input.nml > stdout.txt 2> stderr.txt
status=$?
fail=0
if [ "$status" -ne 2 ]; then echo "FAIL exit status $status, expected 2"; fail=1; fi
if ! grep -q -F -- "$expected" stderr.txt; then echo "FAIL stderr does not name '$expected'"; fail=1; fi
extra=$(ls -A | grep -v -x -e input.nml -e stdout.txt -e stderr.txt || true)
if [ -n "$extra" ]; then echo "FAIL files written: $extra"; fail=1; fi
echo "stderr: $(cat stderr.txt)"
if [ $fail -eq 0 ]; then echo "run_bad_input: 3 passed, 0 failed"; else echo "run_bad_input: failed"; fi
exit $fail
