#!/bin/bash
# A period doubling of a continued branch against the doubling of a time-marching
# bifurcation diagram (issue 20, acceptance "Bifurcations"; docs/method.md, "Continuation of
# periodic orbits"). The scene of period_doubling.nml (a cantilever against one compliant
# stop) is continued in its forcing frequency from 200 rad/s downwards; the same scene is
# swept down in time (period_doubling_sweep.nml, spacing h = 0.5 rad/s), each point's
# period read from its Poincare samples (docs/statistics.md, "Period, Lyapunov exponent and
# the 0-1 test"). Checked:
# - the branch holds exactly one bifurcation, a period doubling (a multiplier through -1),
#   located, at Omega_PD; the points before it are stable and those after it unstable;
# - the sweep's diagram doubles once: going down, every point is of period 1 down to
#   Omega_1, then every point of period 2 from Omega_2 on (no other period, no point
#   without one), Omega_2 = Omega_1 - h (adjacent points);
# - Omega_2 <= Omega_PD <= Omega_1 + h: the doubling of the diagram brackets the branch's,
#   to the sweep's resolution h on the side where the diagram cannot see it. The period of
#   the samples is found to a tolerance of what the tip moves in one step (dt does not
#   divide the forcing period: about Omega A dt = 8.7e-6 m here), and the period-2 orbit's two Poincare points
#   part like the square root of Omega_PD - Omega (1.0e-5 m 0.42 rad/s below the doubling,
#   measured), so the diagram reads period 1 down to about 0.3 rad/s below Omega_PD: its
#   last period-1 point may lie below Omega_PD, by less than h. Its first period-2 point
#   cannot lie above it (the period-1 orbit is stable there; its transient, 5e-8 m after
#   300 periods 0.08 rad/s above it, is far below the tolerance). The sweep's fixed dt
#   differs from the continuation's T/400 by at most 3 % over the range, which moves the
#   doubling by about 2e-3 rad/s (twice the dt, 300 instead of 600 steps a period, moves it
#   by 0.065 rad/s). Measured: 183.418 rad/s, between 183.0 and 183.5. A stop of 4.5e5 N/m
#   in the continuation (its doubling at 182.93 rad/s) fails it.
# usage: period_doubling.sh VIBROBEAM CONTINUATION.nml SWEEP.nml
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
[ "$kinds" = "21 " ] || fail "the branch's bifurcations (kind, located) are '$kinds', not one located period doubling ('21 ')"
read -r doubling index <<< "$(awk -v p="$(col "$found" parameter)" -v i="$(col "$found" index)" '!/^#/ && NF {print $p, $i; exit}' "$found")"
echo "period doubling of the branch: ${doubling} rad/s (after point ${index})"
bad=$(awk -v s="$(col "$branch" stable)" -v first="$index" '
  !/^#/ && NF {k++; if ((k <= first) != $s) printf "%d ", k}' "$branch")
[ -z "$bad" ] || fail "branch points whose stability contradicts the doubling (stable before it, unstable after): $bad"
# the sweep's periods in the order swept (down): 1 ... 1 2 ... 2
read -r pattern omega_1 omega_2 h <<< "$(awk -v p="$(col "$swept" parameter)" -v q="$(col "$swept" period)" '
  !/^#/ && NF {
    if (n > 0) h = (last > $p ? last - $p : $p - last)
    if ($q + 0 == 1) {one = $p; if (two != "") bad = 1}
    else if ($q + 0 == 2) {if (two == "") two = $p}
    else bad = 1
    pattern = pattern sprintf("%d", $q); last = $p; n++}
  END {print (bad ? "bad:" : "") pattern, (one == "" ? "none" : one), (two == "" ? "none" : two), h}' "$swept")"
echo "sweep (down, h = ${h} rad/s), periods ${pattern#bad:}: period 1 down to ${omega_1} rad/s, period 2 from ${omega_2} rad/s"
case $pattern in
  bad:*) fail "the sweep's periods are not period 1 then period 2: ${pattern#bad:}" ;;
  *) awk -v a="$omega_1" -v b="$omega_2" -v h="$h" 'BEGIN {exit !(a - b > 0 && a - b < 1.5*h)}' ||
       fail "the sweep's last period-1 point ${omega_1} and first period-2 point ${omega_2} are not adjacent (h = ${h})" ;;
esac
awk -v v="$doubling" -v a="$omega_1" -v b="$omega_2" -v h="$h" 'BEGIN {exit !(v >= b && v <= a + h)}' ||
  fail "the branch's period doubling ${doubling} rad/s is not between the sweep's first period-2 point ${omega_2} and its last period-1 point ${omega_1} rad/s plus h = ${h}"
awk -v v="$doubling" -v a="$omega_1" -v b="$omega_2" 'BEGIN {exit !(v >= b && v <= a)}' &&
  echo "the branch's doubling lies between the sweep's two points ${omega_2} and ${omega_1} rad/s"
[ $failed -eq 0 ] && echo "period_doubling: the diagram doubles where the branch's multiplier passes -1"
exit $failed
