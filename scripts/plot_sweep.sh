#!/usr/bin/env bash
# Draw the plots of a sweep file, as PNG beside it (docs/sweeps.md, "Plots"): the
# frequency response (STEM_response.png), the bifurcation diagram (STEM_bifurcation.png)
# with, below it, the period, the 0-1 test and the Lyapunov exponent of each point's
# Poincare samples (STEM_chaos.png), for a sweep with two parameters the map
# (STEM_map.png) and, for a beam of two planes with obstacles, the wear at each of their
# points against the parameter (STEM_wear.png).
# usage: plot_sweep.sh SWEEP.h5 [--normalise [REFERENCE]]
#   --normalise            the parameter axis over the first natural frequency of the
#                          clamped-free beam (continuum closed form, docs/theory.md section 7,
#                          from the file's beam.k2 and beam.length): Omega/omega_1; the
#                          parameter must be a frequency (rad/s or Hz)
#   --normalise REFERENCE  the parameter axis over REFERENCE: a number in the parameter's
#                          unit, or a frequency with its unit, '27.6Hz' or '173.4rad/s'
#                          (converted when the parameter is in the other unit)
# The .dat files are derived from SWEEP.h5 (STEM_sweep.dat, STEM_poincare.dat): when one
# is missing or names another run than SWEEP.h5's /run run_id, they are derived again
# with `vibrobeam --text SWEEP.h5` (vibrobeam from $VIBROBEAM, the PATH, or build/ of
# this repository).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
usage="usage: plot_sweep.sh SWEEP.h5 [--normalise [REFERENCE]]"
result=${1:?$usage}
shift
normalise=0; reference=""
while [ $# -gt 0 ]; do
  case $1 in
    --normalise)
      normalise=1
      if [ $# -gt 1 ] && [ "${2#--}" = "$2" ]; then reference=$2; shift; fi ;;
    *) echo "plot_sweep: unknown argument '$1'; $usage" >&2; exit 1 ;;
  esac
  shift
done
stem=${result%.h5}
[ -f "$result" ] || { echo "plot_sweep: no sweep file $result" >&2; exit 1; }
# a here-string, not a pipe: grep -q stops early, and under pipefail h5dump's SIGPIPE fails
listing=$(h5dump -n "$result" 2> /dev/null || true)
grep -q ' /sweep/parameter$' <<< "$listing" || {
  echo "plot_sweep: $result is not a sweep file (no /sweep/parameter); for a run use plot_results.sh" >&2; exit 1; }

run_id=$(h5dump -a /run/run_id "$result" 2> /dev/null | sed -n 's/.*(0): *"\([^"]*\)".*/\1/p')
stale=0
# a beam of two planes with obstacles: STEM_wear.dat too
wear=""; if grep -q ' /sweep/statistics/wear/x$' <<< "$listing"; then wear=wear; fi
for kind in sweep poincare $wear; do
  file="${stem}_${kind}.dat"
  if [ ! -f "$file" ] || ! head -1 "$file" | grep -q -F "# vibrobeam run $run_id "; then stale=1; fi
done
if [ "$stale" = 1 ]; then
  vibrobeam=${VIBROBEAM:-$(command -v vibrobeam || echo "$here/../build/vibrobeam")}
  [ -x "$vibrobeam" ] || { echo "plot_sweep: the .dat files of $result are missing or stale and no vibrobeam" \
                                "program was found to derive them (set VIBROBEAM)" >&2; exit 1; }
  echo "plot_sweep: deriving the text files of $result"
  "$vibrobeam" --text "$result"
fi

# attribute NAME of OBJECT in the sweep file, as text (numbers to 17 digits)
attribute() { h5dump -m '%.17g' -a "$1/$2" "$result" 2> /dev/null | sed -n 's/.*(0): *"*\([^"]*\)"*$/\1/p' | head -1; }
# the parameters' names and units, from the sweep file (not from the .dat headers)
name=$(attribute /sweep/parameter name); unit=$(attribute /sweep/parameter unit)
label="$name ($unit)"; [ -n "$unit" ] || label=$name
label2=""
if grep -q ' /sweep/parameter2$' <<< "$listing"; then
  name2=$(attribute /sweep/parameter2 name); unit2=$(attribute /sweep/parameter2 unit)
  label2="$name2 ($unit2)"; [ -n "$unit2" ] || label2=$name2
fi
# the normalised axis: x/scale
scale=1
if [ "$normalise" = 1 ]; then
  case $unit in rad/s|Hz) frequency=1 ;; *) frequency=0 ;; esac
  if [ -z "$reference" ]; then
    [ "$frequency" = 1 ] || { echo "plot_sweep: --normalise without a reference needs a frequency parameter" \
                                   "(rad/s or Hz); $name is in '$unit': give --normalise VALUE" >&2; exit 1; }
    k2=$(attribute / beam.k2); length=$(attribute / beam.length)
    # omega_1 = (beta_1 L)^2 sqrt(k2)/L^2, beta_1 L = 1.8751040687119611664 (docs/theory.md section 7)
    scale=$(awk -v k2="$k2" -v L="$length" -v u="$unit" 'BEGIN { w = 1.8751040687119611664^2 * sqrt(k2) / L^2;
      if (u == "Hz") w = w / (2 * atan2(0, -1)); printf "%.17g", w }')
    what=$([ "$unit" = Hz ] && echo "f_1" || echo "omega_1")
    # short enough for the panels of the response plot (the first natural frequency of the beam)
    label="$name / $what ($what = $(printf '%.6g' "$scale") $unit)"
    echo "plot_sweep: the parameter axis over $what = $scale $unit"
  else
    value=$(sed -n 's/^\([-+0-9.eE]*\).*/\1/p' <<< "$reference"); given=${reference#"$value"}
    awk -v v="$value" 'BEGIN { exit !(v + 0 > 0) }' ||
      { echo "plot_sweep: --normalise '$reference': give a positive number, or one with Hz or rad/s" >&2; exit 1; }
    case $given in
      ""|"$unit") scale=$value ;;
      Hz|rad/s)
        [ "$frequency" = 1 ] || { echo "plot_sweep: --normalise '$reference' is a frequency but $name is in '$unit'" >&2; exit 1; }
        scale=$(awk -v v="$value" -v from="$given" 'BEGIN { f = 2 * atan2(0, -1);
          printf "%.17g", (from == "Hz" ? v * f : v / f) }') ;;
      *) echo "plot_sweep: --normalise '$reference': unknown unit '$given' (Hz or rad/s)" >&2; exit 1 ;;
    esac
    label="$name / $reference"
    echo "plot_sweep: the parameter axis over $reference = $scale $unit"
  fi
fi
settings="stem='${stem}'; xscale=${scale}; xlabel='${label}'; ylabel2='${label2}'"
gnuplot -e "$settings" "$here/plot_sweep_response.gp"
drawn="${stem}_response.png"
if awk '!/^#/ && NF {n++} END {exit !(n > 0)}' "${stem}_poincare.dat"; then
  gnuplot -e "$settings" "$here/plot_sweep_bifurcation.gp"
  drawn="$drawn ${stem}_bifurcation.png"
  # the diagnostics of the samples: one parameter only (a map's lines would overlap), and
  # a sweep file that has them (a 'zero_one_k' column; earlier sweep files have none)
  if [ -z "$label2" ] && grep -q '^# [0-9]*: zero_one_k ' "${stem}_sweep.dat"; then
    gnuplot -e "$settings" "$here/plot_sweep_chaos.gp"
    drawn="$drawn ${stem}_chaos.png"
  fi
fi
if [ -n "$label2" ]; then
  gnuplot -e "$settings" "$here/plot_sweep_map.gp"
  drawn="$drawn ${stem}_map.png"
fi
# a beam of two planes with obstacles
if [ -n "$wear" ]; then
  gnuplot -e "$settings" "$here/plot_sweep_wear.gp"
  drawn="$drawn ${stem}_wear.png"
fi
echo "plot_sweep: drew $drawn"
