#!/usr/bin/env bash
# package.layering_detects: the layering check must fail when a use against the layer order
# is introduced. Copies src/ to a temporary folder, adds to a core module a use of an app
# module, and expects check_layering.py to exit 1 naming that use; the untouched copy must
# pass (exit 0) so that the failure is the injected use's. Then the same for a folder's map
# (README.md) from which one source file is removed.
# usage: run_layering_tests.sh CHECKER SRC
set -euo pipefail
checker=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$src" "$work/src"
if ! python3 "$checker" "$work/src" > "$work/clean.txt"; then
  echo "layering_detects: the untouched copy of src/ already fails:"; cat "$work/clean.txt"; exit 1
fi
# a use from core/ (the lowest layer) of the check report (app/, the highest)
sed -i 's/^\(\s*\)use vibrobeam_kinds, only: dp$/&\n\1use vibrobeam_check_report, only: check_report/' "$work/src/core/vibrobeam_band.f90"
grep -q 'use vibrobeam_check_report' "$work/src/core/vibrobeam_band.f90" || { echo "layering_detects: could not inject the use"; exit 1; }
if python3 "$checker" "$work/src" > "$work/injected.txt"; then
  echo "layering_detects: a use of app/ from core/ passed the check:"; cat "$work/injected.txt"; exit 1
fi
grep -q 'core/vibrobeam_band.f90:[0-9]*: uses vibrobeam_check_report, which is in app/' "$work/injected.txt" || {
  echo "layering_detects: the check failed without naming the injected use:"; cat "$work/injected.txt"; exit 1; }
echo "layering_detects: the injected use core -> app is reported:"
grep 'vibrobeam_check_report' "$work/injected.txt"
# a folder's map (README.md) that misses a source file
cp -r "$src" "$work/src2"
sed -i '/`vibrobeam_lcp\.f90`/d' "$work/src2/contact/README.md"
if python3 "$checker" "$work/src2" > "$work/unnamed.txt"; then
  echo "layering_detects: a map missing vibrobeam_lcp.f90 passed the check:"; cat "$work/unnamed.txt"; exit 1
fi
grep -q 'contact/README.md: does not name vibrobeam_lcp.f90' "$work/unnamed.txt" || {
  echo "layering_detects: the check failed without naming the missing file:"; cat "$work/unnamed.txt"; exit 1; }
echo "layering_detects: a map missing a file is reported:"
cat "$work/unnamed.txt"
