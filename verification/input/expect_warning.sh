#!/usr/bin/env bash
# A valid input with a doubtful value: --check exits 0, says "is valid", and prints on
# stderr a line "vibrobeam: warning: ..." matching EXPECTED (an extended regular expression).
# usage: expect_warning.sh VIBROBEAM INPUT EXPECTED
set -uo pipefail
vibrobeam=$1; input=$2; expected=$3
"$vibrobeam" --check "$input" > /tmp/expect_warning_$$.out 2> /tmp/expect_warning_$$.err
status=$?
fail=0
[ $status -eq 0 ] || { echo "FAIL exit status $status"; fail=1; }
grep -q "is valid" /tmp/expect_warning_$$.out || { echo "FAIL not valid"; fail=1; }
grep -q -E -- "^vibrobeam: warning: .*$expected" /tmp/expect_warning_$$.err || { echo "FAIL no warning matching '$expected'"; fail=1; }
cat /tmp/expect_warning_$$.err
rm -f /tmp/expect_warning_$$.out /tmp/expect_warning_$$.err
[ $fail -eq 0 ] && echo "expect_warning: passed"
exit $fail
