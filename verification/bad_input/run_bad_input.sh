#!/usr/bin/env bash
# A bad input must make vibrobeam exit with status 2 and print on stderr a message that
# matches EXPECTED (an extended regular expression naming the group and the variable, or
# the line, for file-structure errors), with no run-time library report (no backtrace, no
# "Fortran runtime error"), and write nothing at all: no result file, no temporary file,
# no directory.
#
# usage: run_bad_input.sh VIBROBEAM INPUT EXPECTED [NAME]
#   INPUT     a namelist file copied into an empty directory as NAME (default input.nml),
#             or generate:CASE to have generate_bad_input.sh write it, or a missing path
#   NAME      the name the input gets there (a case may need e.g. run_tip.dat)
set -uo pipefail
vibrobeam=$1; input=$2; expected=$3; name=${4:-input.nml}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'chmod -R u+w "$work" 2>/dev/null; rm -rf "$work"' EXIT
case "$input" in
  generate:*) (cd "$work" && bash "$here/generate_bad_input.sh" "${input#generate:}" "$name") || exit 1 ;;
  *) if [ -f "$input" ]; then cp "$input" "$work/$name"; fi ;;
esac
cd "$work"
before=$(ls -A | sort)
"$vibrobeam" "$name" > stdout.txt 2> stderr.txt
status=$?
fail=0
if [ "$status" -ne 2 ]; then echo "FAIL exit status $status, expected 2"; fail=1; fi
if ! grep -q -E -- "$expected" stderr.txt; then echo "FAIL stderr does not match '$expected'"; fail=1; fi
if grep -q -i -E -- "backtrace|runtime error|error termination|floating-point exception|segmentation" stderr.txt; then
  echo "FAIL stderr holds a run-time library report"; fail=1
fi
after=$(ls -A | grep -v -x -e stdout.txt -e stderr.txt | sort)
if [ "$before" != "$after" ]; then echo "FAIL files written: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"; fail=1; fi
echo "stderr: $(head -c 2000 stderr.txt)"
if [ $fail -eq 0 ]; then echo "run_bad_input: 4 passed, 0 failed"; else echo "run_bad_input: failed"; fi
exit $fail
