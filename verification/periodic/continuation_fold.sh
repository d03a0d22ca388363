#!/bin/bash
# The folds of a continued branch against the jumps of an up-down time-marching sweep
# (issue 20, acceptance "Agreement with time marching"; docs/method.md, "Continuation of
# periodic orbits"). The scene of continuation_fold.nml (a cantilever between two
# compliant stops, a hardening response) is continued in its forcing frequency; the same
# scene is swept up and down in time (continuation_fold_sweep.nml, spacing h = 2.5 rad/s).
# Checked:
# - the branch holds two folds and two grazings (the tip's smallest clearance to the
#   stops through zero), all located, in this order along it: a grazing where the orbit
#   first reaches the stops, the upper fold, the lower fold, and the grazing where the
#   lower branch leaves them just beyond it (the unstable middle branch and the stable
#   lower one between the lower fold and that grazing press into the stops);
# - the upper fold lies where the up sweep drops off the upper branch (its largest drop
#   of the tip's largest displacement between two consecutive points, Omega_i to
#   Omega_i+1) and the lower fold where the down sweep jumps up onto it (its largest
#   rise), each within the sweep's resolution: Omega_i - h <= fold <= Omega_i+1 + h (the
#   sweep marches from the point before, so near a fold it may leave the thinning basin
#   of the upper branch one point early; its fixed dt differs from the continuation's
#   T/200 by up to 20 %, which moves the folds by far less than h);
# - the points between the two folds are unstable (a multiplier outside the unit circle)
#   and those outside them stable: the middle branch of a hysteresis band.
# usage: continuation_fold.sh VIBROBEAM CONTINUATION.nml SWEEP.nml
set -u
vibrobeam=$1; continuation=$2; sweep=$3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cp "$continuation" "$work/continuation.nml"; cp "$sweep" "$work/sweep.nml"
cd "$work" || exit 1
"$vibrobeam" continuation.nml > run.txt 2> run.err || { echo "FAIL: the continuation exited $?"; cat run.err; exit 1; }
"$vibrobeam" sweep.nml > sweep.txt 2> sweep.err || { echo "FAIL: the sweep exited $?"; cat sweep.err; exit 1; }
stem=$(sed -n "s/^&output *file = '\(.*\)\.h5'.*/\1/p" continuation.nml)
sweep_stem=$(sed -n "s/^&output *file = '\(.*\)\.h5'.*/\1/p" sweep.nml)
# a column's number from its header line '# n: name (unit)'
col() { sed -n "s/^# \([0-9]*\): $2 .*/\1/p" "$1"; }
branch=${stem}_branch.dat; found=${stem}_bifurcations.dat; swept=${sweep_stem}_sweep.dat
failed=0
fail() { echo "FAIL: $*"; failed=1; }
kinds=$(awk -v k="$(col "$found" kind)" -v l="$(col "$found" located)" '!/^#/ && NF {printf "%d%d ", $k, $l}' "$found")
[ "$kinds" = "41 11 11 41 " ] ||
  fail "the branch's bifurcations (kind, located) are '$kinds', not a grazing, two folds and a grazing, located ('41 11 11 41 ')"
read -r upper lower upper_index lower_index <<< "$(awk -v p="$(col "$found" parameter)" -v i="$(col "$found" index)" \
  -v k="$(col "$found" kind)" '
  BEGIN {n = 0} !/^#/ && NF && $k == 1 {v[n] = $p + 0; j[n] = $i + 0; n++}
  END {if (v[0] > v[1]) print v[0], v[1], j[0], j[1]; else print v[1], v[0], j[1], j[0]}' "$found")"
echo "folds of the branch: upper ${upper} rad/s (after point ${upper_index}), lower ${lower} rad/s (after point ${lower_index})"
read -r first_grazing last_grazing <<< "$(awk -v p="$(col "$found" parameter)" -v k="$(col "$found" kind)" '
  !/^#/ && NF && $k == 4 {v[n++] = $p} END {print v[0], v[n - 1]}' "$found")"
echo "grazings of the branch: ${first_grazing} and ${last_grazing} rad/s"
awk -v a="$first_grazing" -v b="$lower" -v c="$last_grazing" -v d="$upper" 'BEGIN {exit !(a < b && b < c && c < d)}' ||
  fail "the grazings ${first_grazing} and ${last_grazing} rad/s do not bound the contact on both sides of the lower fold"
# the sweep's jumps: the largest drop going up, the largest rise going down
jump() {  # jump DIRECTION -> Omega_i Omega_i+1 h
  awk -v d="$1" -v c="$(col "$swept" direction)" -v p="$(col "$swept" parameter)" \
      -v a="$(col "$swept" tip_displacement_max)" '
    !/^#/ && NF && $c == d {
      if (n > 0) {change = d * (last_a - $a); if (change > best) {best = change; from = last_p; to = $p}
                  h = (last_p > $p ? last_p - $p : $p - last_p)}
      last_a = $a; last_p = $p; n++}
    END {print from, to, h}' "$swept"
}
read -r up_from up_to h <<< "$(jump 1)"
read -r down_from down_to _ <<< "$(jump -1)"
echo "up sweep drops between ${up_from} and ${up_to} rad/s; down sweep rises between ${down_from} and ${down_to} rad/s (h = ${h})"
within() {  # within VALUE A B H: min(A, B) - H <= VALUE <= max(A, B) + H
  awk -v v="$1" -v a="$2" -v b="$3" -v h="$4" 'BEGIN {lo = (a < b ? a : b) - h; hi = (a > b ? a : b) + h; exit !(v >= lo && v <= hi)}'
}
within "$upper" "$up_from" "$up_to" "$h" || fail "the upper fold ${upper} rad/s is not where the up sweep drops (${up_from} to ${up_to} rad/s, h = ${h})"
within "$lower" "$down_from" "$down_to" "$h" || fail "the lower fold ${lower} rad/s is not where the down sweep rises (${down_from} to ${down_to} rad/s, h = ${h})"
# stability: points after the first fold and up to the second are unstable, the others stable
bad=$(awk -v s="$(col "$branch" stable)" -v first="$upper_index" -v second="$lower_index" '
  !/^#/ && NF {k++; inside = (k > first && k <= second); if (inside == $s) printf "%d ", k}' "$branch")
[ -z "$bad" ] || fail "branch points whose stability contradicts the folds (unstable only between them): $bad"
points=$(awk '!/^#/ && NF' "$branch" | wc -l)
echo "branch: ${points} points, $(awk -v s="$(col "$branch" stable)" '!/^#/ && NF && $s == 0' "$branch" | wc -l) unstable"
[ $failed -eq 0 ] && echo "continuation_fold: the folds bound the sweep's hysteresis band"
exit $failed
