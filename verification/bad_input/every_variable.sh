#!/usr/bin/env bash
# Hostile values in every variable of the input table (printed by list_input_variables):
# NaN, infinities, magnitudes beyond any range, overflowing integers, strings one
# character too long, values of the wrong kind. Each must make vibrobeam exit 2 with a
# message naming &group and the variable, no run-time library report, and nothing
# written.
# usage: every_variable.sh VIBROBEAM LIST_INPUT_VARIABLES
set -uo pipefail
vibrobeam=$1; lister=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0; failed=0
try() {   # try GROUP LABEL VALUE
  local group=$1 label=$2 value=$3 status
  rm -rf -- * 2>/dev/null
  printf '&%s %s = %s /\n' "$group" "$label" "$value" > input.nml
  "$vibrobeam" input.nml > stdout.txt 2> stderr.txt
  status=$?
  local problem=""
  [ $status -eq 2 ] || problem="exit status $status"
  grep -q -F -- "&$group $label" stderr.txt || problem="$problem; message does not name &$group $label"
  grep -q -i -E "backtrace|runtime error|error termination|floating-point exception" stderr.txt && problem="$problem; run-time report"
  local extra
  extra=$(ls -A | grep -v -x -e input.nml -e stdout.txt -e stderr.txt)
  [ -z "$extra" ] || problem="$problem; files written: $extra"
  if [ -z "$problem" ]; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL &$group $label = ${value:0:40}: $problem"; echo "  stderr: $(head -c 300 stderr.txt)"
  fi
}
# every variable: the values that must never get through (NaN and both infinities in
# every real, an overflowing integer, a string one character too long, an index beyond
# the array)
while read -r group name kind extent max_length lowest highest; do
  label=$name
  [ "$extent" -gt 0 ] && label="$name(1)"
  case $kind in
    real) for value in NaN Inf -Inf; do try "$group" "$label" "$value"; done ;;
    integer) try "$group" "$label" 99999999999 ;;
    logical) try "$group" "$label" yes ;;
    string) try "$group" "$label" "'$(head -c $((max_length + 1)) /dev/zero | tr '\0' 'a')'" ;;
  esac
  if [ "$extent" -gt 0 ]; then try "$group" "$name($((extent + 1)))" 0; fi   # beyond the array
done < <("$lister")
# every other spelling once, in one variable of each kind
for value in nan -NaN +Inf Infinity -infinity 1e400 -1e400 1d999 1e-400 "'1.0'" .true. abc 1.0+3; do
  try beam length "$value"
done
try obstacles "level_from(1)" 1e-400
for value in -99999999999 2147483648 1.5 1e3 NaN "'3'" .true.; do try mesh elements "$value"; done
for value in 2 "'t'" NaN; do try output text "$value"; done
for value in 1 abc .true.; do try mesh basis "$value"; done
echo "every_variable: $passed passed, $failed failed"
[ $failed -eq 0 ]
