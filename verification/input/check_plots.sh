#!/usr/bin/env bash
# The plotting scripts on small results (docs/output.md and docs/sweeps.md, "Plots";
# issue 24 items 1 and 4):
#  - a 2-D sweep map (3 frequencies x 2 gaps): plot_sweep.sh --normalise draws its three
#    plots without a gnuplot warning; the axis is divided by omega_1 = (beta_1 L)^2
#    sqrt(EI/(rho S))/L^2, recomputed here from the input (beta_1 L quoted to 20 digits,
#    scripts/cantilever_roots.py), to 1e-9 relative; the response plot's key names each
#    line of the second parameter with its value ('obstacles.level_from(1) = 0.0002 m',
#    drawn as text); --normalise 27.6Hz divides by 2 pi 27.6 rad/s;
#  - a forced single run with an observation point: plot_results.sh --point 1 draws the
#    spectrum, the phase portrait and the Poincare section at that point without a
#    warning, the spectrum on log axes over the band of the response; --point 2 (no such
#    point) is refused;
#  - a one-parameter sweep with &output lyapunov: plot_sweep.sh draws STEM_chaos.png
#    without a warning, its Lyapunov panel over the points' exponents (issue 20, item 3);
#  - a periodic orbit: plot_results.sh draws its multipliers without a warning, their
#    moduli's panel from the smallest to 10 times max(1, the largest);
#  - a continued branch (verification/periodic/continuation_grazing.nml): plot_branch.gp
#    draws the branch and its multipliers in the complex plane without a warning, the
#    plane's axes reaching past the largest modulus of STEM_branch_multipliers.dat;
#  - a sweep of branches and one of single orbits (verification/periodic/continuation_sweep.nml):
#    plot_sweep.sh draws STEM_branches.png and STEM_orbits.png without a warning.
# usage: check_plots.sh VIBROBEAM SCRIPTS_DIRECTORY
set -uo pipefail
vibrobeam=$1; scripts=$2
periodic_scenes=$(cd "$(dirname "$0")/../periodic" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failed=0
fail() { echo "FAIL $*"; failed=1; }
quiet() { ! grep -i -q -E "warning|error" "$1" || { echo "  $1:"; cat "$1"; return 1; }; }
# spectrum_axes STEM POINT [BAND_BELOW]: the spectrum plot at observation point POINT is on
# logarithmic axes over the band of the response: from the first bin above 0 Hz to 1.5
# times the highest frequency whose amplitude reaches 1e-3 of the largest (at most the
# Nyquist frequency), recomputed here from STEM_spectrum.dat (column 3 + POINT); gnuplot's
# axis limits are those values to its own printing (1e-9 relative). With BAND_BELOW, that
# upper limit must also be below BAND_BELOW times the Nyquist frequency.
spectrum_axes() {
  local axes
  axes=$(gnuplot -e "stem='$1'; point=$2" "$scripts/plot_dynamics_spectrum.gp" \
           -e "show logscale; print GPVAL_X_MIN, GPVAL_X_MAX" 2>&1 | tr -s ' \t\n' ' ')
  awk -v axes="$axes" -v c=$((3 + $2)) -v below="${3:-1}" '
    !/^#/ && NF && $1 > 0 { n++; f[n] = $1; a[n] = $c; if (n == 1) low = $1; if ($c > peak) peak = $c }
    END { for (i = 1; i <= n; i++) if (a[i] >= 1e-3 * peak) high = f[i]
          top = 1.5 * high; if (top > f[n]) top = f[n]
          is_log = (axes ~ /logscaling on x y /)   # "logscaling on x y", then the two limits
          m = split(axes, g, " "); x_min = g[m - 1]; x_max = g[m]
          printf "spectrum axis: %s to %s Hz (expected %.9g to %.9g; Nyquist %.9g), logarithmic x and y: %d\n", \
                 x_min, x_max, low, top, f[n], is_log
          exit !(x_min - low <= 1e-9 * low && low - x_min <= 1e-9 * low && x_max - top <= 1e-9 * top && \
                 top - x_max <= 1e-9 * top && is_log && top <= below * f[n]) }' "$1_spectrum.dat" ||
    fail "$1: the spectrum's axes are not logarithmic over the response's band (gnuplot: $axes)"
}
beam="&beam length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4, inertia = 1.6666666666666667e-9, rayleigh_mass = 3 /"
cat > map.nml <<NML
$beam
&mesh elements = 8 /
&obstacles count = 1, side(1) = 'above', x_from(1) = 0.5, level_from(1) = 2e-4 /
&impact restitution = 0.7 /
&time dt = 4e-5 /
&load point_force = 2, point_frequency = 200 /
&output file = 'map.h5' /
&sweep parameter = 'load.point_frequency', from = 150, to = 250, count = 3, mode = 'up',
       parameter2 = 'obstacles.level_from(1)', values2 = 2e-4, 4e-4, settle_periods = 5, measure_periods = 5 /
NML
"$vibrobeam" map.nml > map.out 2> map.err || { fail "the map sweep"; cat map.err; }
VIBROBEAM=$vibrobeam bash "$scripts/plot_sweep.sh" map.h5 --normalise > plot.out 2> plot.err || fail "plot_sweep.sh --normalise"
quiet plot.err || fail "plot_sweep.sh printed a warning"
for png in map_response.png map_bifurcation.png map_map.png; do
  [ "$(stat -c %s "$png" 2> /dev/null || echo 0)" -gt 10000 ] || fail "$png not drawn"
done
scale=$(sed -n 's/^plot_sweep: the parameter axis over omega_1 = \([0-9.eE+-]*\) rad\/s$/\1/p' plot.out)
awk -v s="${scale:-0}" 'BEGIN { w = 1.8751040687119611664^2 * sqrt(210e9 * 1.6666666666666667e-9 / (7850 * 2e-4)) / 0.5^2;
  d = (s - w) / w; if (d < 0) d = -d; printf "omega_1: plot %.12g, closed form %.12g, relative difference %.1e\n", s, w, d;
  exit !(d <= 1e-9) }' || fail "the normalised axis is not over omega_1 (plot.out: $(cat plot.out))"
VIBROBEAM=$vibrobeam bash "$scripts/plot_sweep.sh" map.h5 --normalise 27.6Hz > plot2.out 2>&1 || fail "--normalise 27.6Hz"
grep -q -E "over 27.6Hz = 173.41591[0-9]* rad/s" plot2.out || fail "--normalise 27.6Hz is not 2 pi 27.6 rad/s: $(cat plot2.out)"
gnuplot -e "stem='map'; ylabel2='obstacles.level_from(1) (m)'; text_terminal=1" "$scripts/plot_sweep_response.gp" \
  2> text.err || fail "the response plot as text"
for value in 0.0002 0.0004; do
  grep -q -F "obstacles.level_from(1) = $value m" map_response.txt || fail "no key for the line at $value m"
done

cat > run.nml <<NML
$beam
&mesh elements = 8 /
&obstacles count = 2, side(1) = 'below', x_from(1) = 0.5, level_from(1) = -5e-4,
                      side(2) = 'above', x_from(2) = 0.5, level_from(2) = 5e-4 /
&impact restitution = 0.7 /
&time t_end = 0.6, dt = 4e-5 /
&load point_force = 20, point_frequency = 200 /
&output file = 'run.h5', every = 5, points = 0.25, measure_from = 0.1 /
NML
"$vibrobeam" run.nml > run.out 2> run.err || { fail "the single run"; cat run.err; }
bash "$scripts/plot_results.sh" run.h5 --point 1 > plots.out 2> plots.err || fail "plot_results.sh --point 1"
quiet plots.err || fail "plot_results.sh printed a warning"
for png in run_spectrum.png run_phase.png run_poincare.png; do
  [ "$(stat -c %s "$png" 2> /dev/null || echo 0)" -gt 10000 ] || fail "$png not drawn"
done
spectrum_axes run 1
if bash "$scripts/plot_results.sh" run.h5 --point 2 > bad.out 2>&1; then fail "--point 2 accepted"; fi
grep -q "has no &output points(2)" bad.out || fail "--point 2: $(cat bad.out)"
# without stops the response is a few modes: the spectrum's axis ends far below the
# Nyquist frequency (12.5 kHz at every = 1) that it used to reach
cat > free.nml <<NML
$beam
&mesh elements = 8 /
&time t_end = 0.6, dt = 4e-5 /
&load point_force = 20, point_frequency = 200 /
&output file = 'free.h5', every = 1, points = 0.25 /
NML
"$vibrobeam" free.nml > free.out 2> free.err || { fail "the run without stops"; cat free.err; }
spectrum_axes free 1 0.1

# the Poincare samples' diagnostics along a one-parameter sweep with the Lyapunov
# exponent (issue 20, item 3): plot_sweep.sh draws STEM_chaos.png, its last panel the
# exponent per forcing period over the points' values (gnuplot's axis reaches them)
cat > chaos.nml <<NML
$beam
&mesh elements = 8 /
&obstacles count = 2, side(1) = 'below', x_from(1) = 0.5, level_from(1) = -5e-4,
                      side(2) = 'above', x_from(2) = 0.5, level_from(2) = 5e-4 /
&impact restitution = 0.7 /
&time dt = 4e-5 /
&load point_force = 2, point_frequency = 200 /
&output file = 'chaos.h5', lyapunov = .true. /
&sweep parameter = 'load.point_frequency', values = 150, 276, settle_periods = 5, measure_periods = 20 /
NML
"$vibrobeam" chaos.nml > chaos.out 2> chaos.err || { fail "the sweep with the Lyapunov exponent"; cat chaos.err; }
VIBROBEAM=$vibrobeam bash "$scripts/plot_sweep.sh" chaos.h5 > chaos_plot.out 2> chaos_plot.err || fail "plot_sweep.sh (chaos)"
quiet chaos_plot.err || fail "plot_sweep.sh (chaos) printed a warning"
[ "$(stat -c %s chaos_chaos.png 2> /dev/null || echo 0)" -gt 10000 ] || fail "chaos_chaos.png not drawn"
range=$(gnuplot -e "stem='chaos'" "$scripts/plot_sweep_chaos.gp" -e "print GPVAL_Y_MIN, GPVAL_Y_MAX" 2>&1)
awk -v range="$range" -v c="$(sed -n 's/^# \([0-9]*\): lyapunov_exponent_per_period .*/\1/p' chaos_sweep.dat)" '
  !/^#/ && NF { n++; if (n == 1 || $c < low) low = $c; if (n == 1 || $c > high) high = $c }
  END { split(range, g, " "); printf "exponent panel: %s to %s, the exponents %.6g to %.6g\n", g[1], g[2], low, high
        exit !(n == 2 && g[1] <= low && g[2] >= high && low < 0) }' chaos_sweep.dat ||
  fail "the Lyapunov panel does not show the points' exponents ($range)"

# a periodic orbit's Floquet multipliers: the complex plane and their moduli on a log scale
cat > orbit.nml <<NML
$beam
&mesh elements = 8 /
&analysis kind = 'periodic' /
&periodic steps_per_period = 500, transient_periods = 10 /
&obstacles count = 1, side(1) = 'below', x_from(1) = 0.5, level_from(1) = -5e-4 /
&impact restitution = 0.5 /
&load point_force = 2, point_frequency = 215 /
&output file = 'orbit.h5' /
NML
"$vibrobeam" orbit.nml > orbit.out 2> orbit.err
bash "$scripts/plot_results.sh" orbit.h5 > orbit_plot.out 2> orbit_plot.err || fail "plot_results.sh (periodic)"
quiet orbit_plot.err || fail "plot_results.sh (periodic) printed a warning"
[ "$(stat -c %s orbit_periodic.png 2> /dev/null || echo 0)" -gt 10000 ] || fail "orbit_periodic.png not drawn"
# the moduli panel reaches from the smallest positive modulus to 10 times max(1, the largest)
range=$(gnuplot -e "stem='orbit'" "$scripts/plot_periodic.gp" -e "print GPVAL_Y_MIN, GPVAL_Y_MAX" 2>&1)
awk -v range="$range" '!/^#/ && NF && $3 > 0 { if (!n || $3 < low) low = $3; if ($3 > high) high = $3; n++ }
  END { split(range, g, " "); top = (10 * high > 10 ? 10 * high : 10)
        printf "moduli panel: %s to %s, the moduli %.3g to %.3g\n", g[1], g[2], low, high
        exit !(n > 0 && g[1] <= low && g[2] >= top * (1 - 1e-9)) }' orbit_multipliers.dat ||
  fail "the moduli panel does not show every multiplier and the unit line ($range)"

# a continued branch: the branch and every point's multipliers in the complex plane
sed "s/file = 'continuation_grazing.h5'/file = 'branch.h5'/" "$periodic_scenes/continuation_grazing.nml" > branch.nml
"$vibrobeam" branch.nml > branch.out 2> branch.err || fail "vibrobeam branch.nml (continuation)"
gnuplot -e "stem='branch'" "$scripts/plot_branch.gp" -e "print GPVAL_X_MAX" > branch_plot.out 2> branch_plot.err
reach=$(tail -1 branch_plot.err)
grep -v '^[-0-9.e+]*$' branch_plot.err > branch_plot_warnings.err
quiet branch_plot_warnings.err || fail "plot_branch.gp printed a warning"
for png in branch_branch.png branch_branch_multipliers.png; do
  [ "$(stat -c %s $png 2> /dev/null || echo 0)" -gt 10000 ] || fail "$png not drawn"
done
awk -v reach="$reach" '!/^#/ && NF { if ($4 > high) high = $4; n++ }
  END { printf "multipliers plane: axes to %s, %d multipliers, the largest modulus %.3g\n", reach, n, high
        exit !(n > 0 && reach + 0 > high && reach + 0 >= 1) }' branch_branch_multipliers.dat ||
  fail "the complex plane of the branch's multipliers does not reach the largest ($reach)"

# a sweep of branches (three forcing levels) and a sweep of single orbits: plot_sweep.sh
# derives each point file's text files and draws the branches on one plot, or the orbits'
# periods and multipliers, without a warning
sed "s/file = 'continuation_sweep.h5'/file = 'branches.h5'/" "$periodic_scenes/continuation_sweep.nml" > branches.nml
sed -e "s/file = 'continuation_sweep.h5'/file = 'orbits.h5'/" -e "s/parameter = 'load.point_frequency',//" \
    "$periodic_scenes/continuation_sweep.nml" > orbits.nml
for sweep in branches orbits; do
  "$vibrobeam" $sweep.nml > $sweep.out 2> $sweep.err || { fail "vibrobeam $sweep.nml (a periodic sweep)"; cat $sweep.err; }
  VIBROBEAM=$vibrobeam bash "$scripts/plot_sweep.sh" $sweep.h5 > ${sweep}_plot.out 2> ${sweep}_plot.err ||
    fail "plot_sweep.sh $sweep.h5"
  quiet ${sweep}_plot.err || fail "plot_sweep.sh $sweep.h5 printed a warning"
  [ "$(stat -c %s ${sweep}_$sweep.png 2> /dev/null || echo 0)" -gt 10000 ] || fail "${sweep}_$sweep.png not drawn"
done
ls branches_point000[123]_branch.dat > /dev/null 2>&1 || fail "plot_sweep.sh did not derive the point files' branches"

[ $failed -eq 0 ] && echo "check_plots: every plot drawn and checked"
exit $failed
