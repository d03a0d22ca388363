#!/usr/bin/env bash
# The resolution advice of `vibrobeam --check` (docs/statistics.md, "Which statistics
# converge") for single runs and sweeps: it appears for a dynamics scene with obstacles and
# a statistics window and nowhere else, and its numbers follow from the scene. The dt it
# asks for is recomputed here from the inputs: dt = 2 pi/(S omega_1) with omega_1 =
# (beta_1 L)^2 sqrt(EI/(rho S))/L^2 (beta_1 L = 1.87510406871196, the first root of
# 1 + cos b cosh b = 0) and S = 1400 steps per period of mode 1, the threshold of
# studies/statistics_convergence/REPORT.md; printed rounded down to 3 significant digits,
# so the comparison is of strings (the two computations differ by a few ulp, far from a
# rounding boundary for these scenes: checked below). Elements asked for: 8.
# usage: check_resolution_advice.sh VIBROBEAM
set -uo pipefail
vibrobeam=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
steps_wanted=1400
elements_wanted=8

# dt the advice asks for, printed as the program prints it: L E I rho S -> 'd.dde<exp>'
dt_wanted() {
   awk -v L="$1" -v E="$2" -v I="$3" -v rho="$4" -v S="$5" -v steps=$steps_wanted 'BEGIN {
      w1 = 1.87510406871196^2*sqrt(E*I/(rho*S))/L^2; dt = 2*atan2(0, -1)/(steps*w1)
      e = int(log(dt)/log(10)); if (10^e > dt) e--
      m = dt/10^e*100
      if (m - int(m) < 1e-9 || m - int(m) > 1 - 1e-9) { print "ROUNDING_BOUNDARY"; exit }
      printf "%.2fe%d\n", int(m)/100, e }'
}
steps_of() {   # L E I rho S dt -> whole steps per period of mode 1
   awk -v L="$1" -v E="$2" -v I="$3" -v rho="$4" -v S="$5" -v dt="$6" 'BEGIN {
      w1 = 1.87510406871196^2*sqrt(E*I/(rho*S))/L^2; printf "%d\n", 2*atan2(0, -1)/(w1*dt) }'
}
scene() {   # file L E I rho S N dt obstacles [extra lines]; $beam_extra is added to &beam
            # (obstacles and the point force at the tip: x_from and point_position follow L)
   local f=$1
   {
      echo "&beam length = $2, youngs_modulus = $3, inertia = $4, density = $5, area = $6${beam_extra:-} /"
      echo "&mesh elements = $7 /"
      if [[ $9 == 1 ]]; then
         echo "&obstacles count = 2, side(1) = 'below', level_from(1) = -0.5e-3,"
         echo "           side(2) = 'above', level_from(2) = 0.5e-3 /"
         echo "&impact restitution = 0.7 /"
      fi
      echo "&time dt = $8, t_end = 0.01 /"
      echo "&load point_force = 20.0, point_frequency = 200.0 /"
      echo "&output file = 'out.h5' /"
      shift 9
      for line in "$@"; do echo "$line"; done
   } > "$f"
}
advice_of() { "$vibrobeam" --check "$1" 2>/dev/null | sed -n '/^resolution advice/,$p'; }
expect() {   # name advice-text pattern
   if grep -q -e "$3" <<< "$2"; then echo "ok   $1: $3"; else fail "$1: no line matching '$3' in:"; echo "$2"; fi
}

# 1. the steel strip of inputs/forced_rattling.nml, resolved (dt well below the threshold)
p=(0.5 210e9 1.6666666666666667e-9 7850 2e-4)
want=$(dt_wanted "${p[@]}")
scene a.nml "${p[@]}" 16 1e-5 1
a=$(advice_of a.nml)
expect resolved "$a" "with dt <= $want s ($steps_wanted steps per period of mode 1) and elements >= $elements_wanted"
expect resolved "$a" "this run: dt = 1.00e-5 s ($(steps_of "${p[@]}" 1e-5) steps per period of mode 1), elements = 16: resolved"
expect resolved "$a" "impact rate and contact fraction"

# 2. the same beam, dt 1.01 times and 0.99 times the threshold (computed here), N = 4 and 8
over=$(awk -v d="$want" 'BEGIN { printf "%.6e", d*1.01 }')
under=$(awk -v d="$want" 'BEGIN { printf "%.6e", d*0.99 }')
scene b.nml "${p[@]}" 4 "$over" 1
expect "dt and N too coarse" "$(advice_of b.nml)" "not resolved: take dt <= $want s and elements >= $elements_wanted"
scene c.nml "${p[@]}" 8 "$under" 1
expect "just resolved" "$(advice_of c.nml)" "elements = 8: resolved"
scene d.nml "${p[@]}" 8 "$over" 1
expect "dt just too coarse" "$(advice_of d.nml)" "elements = 8: not resolved: take dt <= $want s\$"

# 3. another beam (the tube of the study: 19.05 x 1.24 mm, L = 0.8 m): the threshold moves with omega_1
q=(0.8 200e9 2.7642255353230253e-9 8000 6.938018879893839e-5)
want_q=$(dt_wanted "${q[@]}")
[[ $want_q != "$want" ]] || fail "the two beams should ask for different dt"
beam_extra=", rayleigh_mass = 3.47" scene e.nml "${q[@]}" 16 2e-5 1
e=$(advice_of e.nml)
expect tube "$e" "with dt <= $want_q s"
expect tube "$e" "elements = 16: resolved"
expect "tube, damped, e < 1" "$e" "between the stops (e < 1) and damping"

# 4. no advice without obstacles, and none when the window is empty (measure_from >= t_end)
scene f.nml "${p[@]}" 16 1e-5 0
[[ -z $(advice_of f.nml) ]] && echo "ok   no obstacles: no advice" || fail "advice printed for a scene without obstacles"
scene g.nml "${p[@]}" 16 1e-5 1 "&output measure_from = 0.01 /"
[[ -z $(advice_of g.nml) ]] && echo "ok   empty window: no advice" || fail "advice printed for an empty statistics window"

# 5. sweeps: printed once, for the least resolved point (largest dt against the threshold)
scene h.nml "${p[@]}" 16 1e-5 1 "&sweep parameter = 'time.dt', values = 1e-5, $over, 2e-6, settle = 0.005, measure = 0.005 /"
h=$(advice_of h.nml)
expect "dt sweep" "$h" "point 2 (the least resolved of the sweep): .*not resolved: take dt <= $want s\$"
[[ $(grep -c '^resolution advice' <<< "$h") == 1 ]] && echo "ok   dt sweep: printed once" || fail "sweep advice printed $(grep -c '^resolution advice' <<< "$h") times"
scene i.nml "${p[@]}" 16 1e-5 1 "&sweep parameter = 'beam.length', values = 0.5, 0.4, settle = 0.005, measure = 0.005 /"
want_short=$(dt_wanted 0.4 210e9 1.6666666666666667e-9 7850 2e-4)
expect "length sweep" "$(advice_of i.nml)" "with dt <= $want_short s"
expect "length sweep" "$(advice_of i.nml)" "point 2 (the least resolved"
scene j.nml "${p[@]}" 16 1e-5 1 "&sweep parameter = 'load.point_frequency', values = 150, 200, settle = 0.005, measure = 0.005 /"
expect "frequency sweep" "$(advice_of j.nml)" "every point of the sweep: .*resolved"

exit $((failures > 0))
