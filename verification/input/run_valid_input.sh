#!/usr/bin/env bash
# A valid input must pass --check (exit 0, "is valid") with every EXPECTED extended
# regular expression matching its output (the values read), then run (exit 0) and leave
# RESULT, and no temporary file.
# usage: run_valid_input.sh VIBROBEAM INPUT RESULT [--crlf] [EXPECTED ...]
#   --crlf   give the input Windows line ends (CR LF) first
set -uo pipefail
vibrobeam=$1; input=$2; result=$3; shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ "${1:-}" = "--crlf" ]; then sed 's/$/\r/' "$input" > "$work/input.nml"; shift; else cp "$input" "$work/input.nml"; fi
cd "$work"
fail=0
"$vibrobeam" --check input.nml > check.txt 2> check_stderr.txt
status=$?
if [ $status -ne 0 ]; then echo "FAIL --check exit status $status: $(cat check_stderr.txt)"; fail=1; fi
grep -q "is valid" check.txt || { echo "FAIL --check does not say 'is valid'"; fail=1; }
for expected in "$@"; do
  grep -q -E -- "$expected" check.txt || { echo "FAIL --check output does not match '$expected'"; fail=1; }
done
"$vibrobeam" input.nml > run.txt 2> run_stderr.txt
status=$?
if [ $status -ne 0 ]; then echo "FAIL run exit status $status: $(cat run_stderr.txt)"; fail=1; fi
[ -f "$result" ] || { echo "FAIL no result file '$result'"; fail=1; }
stray=$(find . -name '*.tmp*')
[ -z "$stray" ] || { echo "FAIL temporary files left: $stray"; fail=1; }
cat run.txt
if [ $fail -eq 0 ]; then echo "run_valid_input: passed"; else echo "run_valid_input: failed"; fi
exit $fail
