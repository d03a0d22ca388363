#!/usr/bin/env bash
# Every frequency `vibrobeam --check` prints is in rad/s and in Hz (issue 24 item 1;
# docs/input.md, "What --check prints"): on each line that gives one - the natural
# frequencies of the beam, omega_max of the discrete model, and for a reduced model the
# highest fixed-interface mode kept and the cut-off - the value in Hz must be the one in
# rad/s over 2 pi. Both are printed to 6 significant digits, each within 5e-6 relative of
# its exact value: 1.1e-5 relative holds them (pi from awk's atan2, to round-off).
# usage: check_frequencies_in_hz.sh VIBROBEAM INPUT.nml   (INPUT: a dynamics run of a reduced model)
set -uo pipefail
vibrobeam=$1; input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$vibrobeam" --check "$input" > "$work/check.txt" 2> "$work/check.err" ||
  { echo "FAIL: --check $input"; cat "$work/check.err"; exit 1; }
failed=0
# check NAME PATTERN EXPECTED_LINES: PATTERN (sed -E) captures the value in rad/s, then in Hz
check() {
  local values
  values=$(sed -n -E "s/$2/\1 \2/p" "$work/check.txt")
  local lines
  lines=$(grep -c . <<< "$values")
  [ -n "$values" ] && [ "$lines" -ge "$3" ] || { echo "FAIL $1: $3 line(s) with rad/s and Hz expected, found ${lines:-0}"; failed=1; return; }
  while read -r omega f; do
    awk -v w="$omega" -v f="$f" 'BEGIN { d = w / (2 * atan2(0, -1)) / f - 1; if (d < 0) d = -d;
      printf "%s rad/s, %s Hz: relative difference %.1e\n", w, f, d; exit !(d <= 1.1e-5) }' ||
      { echo "FAIL $1: $f Hz is not $omega rad/s over 2 pi"; failed=1; }
  done <<< "$values"
}
number='([-+0-9.eE]+)'
check 'natural frequencies' "^ *mode [0-9]+: omega = $number rad\/s, f = $number Hz.*" 5
check 'omega_max' ".*omega_max = $number rad\/s, f_max = $number Hz.*" 1
check 'highest fixed-interface mode kept' "^ *highest fixed-interface mode kept: *$number rad\/s, *$number Hz.*" 1
check 'cut-off' "^ *cut-off: *$number rad\/s, *$number Hz.*" 1
# the cut-off given as reduction_frequency_hz = 1000: 2 pi 1000 rad/s
grep -q -E "^ *cut-off: *6\.28319E\+03 rad/s, *1\.00000E\+03 Hz" "$work/check.txt" ||
  { echo "FAIL: the cut-off is not 2 pi 1000 rad/s, 1000 Hz:"; grep 'cut-off' "$work/check.txt"; failed=1; }
[ $failed -eq 0 ] && echo "check_frequencies_in_hz: every frequency printed in rad/s and Hz"
exit $failed
