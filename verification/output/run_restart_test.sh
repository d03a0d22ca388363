#!/usr/bin/env bash
# Checkpoint and restart (docs/output.md, "Checkpoint and restart"): for both schemes and
# both bases, a run to 2T and a run to T continued to 2T (&initial from_file) must give
# bitwise identical histories over the continued part, the same spectrum, contact
# fractions, statistics and final state (compare_continued); also a scene with a compliant
# stop, continued inside a compliant episode. Then a file that does not match the
# scene is refused with exit status 2 and a message naming the mismatch.
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

# a compliant stop with its force statistics, the checkpoint taken inside a compliant
# episode (the force is nonzero at t = 0.1712 s) and inside the statistics window
base="$here/statistics_compliant.nml"
sed -e "s/'statistics.h5'/'full_compliant.h5'/" "$base" > full_compliant.nml
sed -e "s/'statistics.h5'/'half_compliant.h5'/" -e "s/t_end = 0.3/t_end = 0.1712/" "$base" > half_compliant.nml
{ sed -e "s/'statistics.h5'/'continued_compliant.h5'/" "$base"; echo "&initial from_file = 'half_compliant.h5' /"; } \
  > continued_compliant.nml
for run in full half continued; do
  "$vibrobeam" ${run}_compliant.nml > $run.out 2> $run.err || { echo "FAIL compliant: run $run"; cat $run.err; failed=1; }
done
echo "compliant stop:"
"$compare" full_compliant.h5 continued_compliant.h5 || failed=1

# mismatches: exit status 2, the message names what differs, nothing is written
refused() {  # refused DESCRIPTION EXPECTED_TEXT SED_EXPRESSION
  sed -e "$3" continued.nml > refused.nml
  rm -f refused.h5
  "$vibrobeam" refused.nml > refused.out 2> refused.err
  local code=$?
  if [ $code -ne 2 ] || ! grep -q -F -- "$2" refused.err || [ -e refused.h5 ]; then
    echo "FAIL $1: exit status $code, expected 2 with '$2':"
    cat refused.err
    failed=1
  else
    echo "refused as expected ($1): $(head -1 refused.err)"
  fi
}
refused 'another mesh' 'mesh.elements is 8 in the file and 16 in this scene' \
  "s/elements = 8/elements = 16/; s/continued.h5/refused.h5/"
refused 'another scheme' "time.scheme is 'position' in the file and 'velocity' in this scene" \
  "s/scheme = 'position'/scheme = 'velocity'/; s/continued.h5/refused.h5/"
refused 'another basis' "mesh.basis is 'bspline' in the file and 'hermite' in this scene" \
  "s/basis = 'bspline'/basis = 'hermite'/; s/continued.h5/refused.h5/"
refused 'another time step' 'time.dt is 2e-5 in the file and 1e-5 in this scene' \
  "s/dt = 2e-5/dt = 1e-5/; s/continued.h5/refused.h5/"
refused 'both stops moved to another node' 'contact point 1 x is 0.5 in the file and 0.4375 in this scene' \
  "s/x_from(1) = 0.5/x_from(1) = 0.4375/; s/x_from(2) = 0.5/x_from(2) = 0.4375/; s/continued.h5/refused.h5/"
refused 'one stop moved' 'contact points is 1 in the file and 2 in this scene' \
  "s/x_from(1) = 0.5/x_from(1) = 0.4375/; s/continued.h5/refused.h5/"
refused 'the stops moved onto the beam position' 'outside the changed obstacles there' \
  "s/level_from(1) = -1e-3/level_from(1) = -1e-9/; s/level_from(2) = 1e-3/level_from(2) = 1e-9/; s/continued.h5/refused.h5/"
refused 'an end before the checkpoint' 't_end = 0.05 s is not after the checkpoint' \
  "s/t_end = 0.2/t_end = 0.05/; s/continued.h5/refused.h5/"
refused 'the output is the file continued' 'is the file that &initial from_file continues' \
  "s/continued.h5/half.h5/"
exit $failed
