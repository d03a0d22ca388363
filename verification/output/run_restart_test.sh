#!/usr/bin/env bash
# Checkpoint and restart (docs/output.md, "Checkpoint and restart"): for both schemes and
# both bases, a run to 2T and a run to T continued to 2T (&initial from_file) must give
# bitwise identical histories over the continued part, the same spectrum, contact
# fractions and final state (compare_continued).
# usage: run_restart_test.sh VIBROBEAM COMPARE_CONTINUED
set -uo pipefail
vibrobeam=$1; compare=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failed=0
for scheme in velocity position; do
  for basis in hermite bspline; do
    scene() {  # scene NAME T_END [FROM_FILE]
      sed -e "s|@FILE@|$1.h5|" -e "s|@T_END@|$2|" -e "s|@SCHEME@|$scheme|" -e "s|@BASIS@|$basis|" \
          -e "s|@FROM_FILE@|${3:+, from_file = '$3'}|" "$here/restart.nml.in" > "$1.nml"
    }
    scene full 0.2
    scene half 0.1
    scene continued 0.2 half.h5
    for run in full half continued; do
      "$vibrobeam" $run.nml > $run.out 2> $run.err || { echo "FAIL $scheme $basis: run $run"; cat $run.err; failed=1; }
    done
    echo "$scheme, $basis:"
    "$compare" full.h5 continued.h5 || failed=1
  done
done
exit $failed
