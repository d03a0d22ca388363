#!/usr/bin/env bash
# vibrobeam on INPUT must exit with STATUS, say EXPECTED on stderr and write nothing.
# usage: run_exit_status.sh VIBROBEAM INPUT STATUS EXPECTED
set -uo pipefail
vibrobeam=$1; input=$2; status=$3; expected=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$vibrobeam" "$input" > stdout.txt 2> stderr.txt
code=$?
cat stderr.txt
fail=0
[ $code -eq "$status" ] || { echo "FAIL exit status $code, expected $status"; fail=1; }
grep -q -F -- "$expected" stderr.txt || { echo "FAIL stderr does not say '$expected'"; fail=1; }
[ -z "$(ls -A | grep -v -x -e stdout.txt -e stderr.txt)" ] || { echo "FAIL files written: $(ls)"; fail=1; }
[ $fail -eq 0 ] && echo "run_exit_status: 3 passed, 0 failed"
exit $fail
