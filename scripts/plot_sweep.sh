#!/usr/bin/env bash
# Draw the plots of a sweep file, as PNG beside it (docs/sweeps.md, "Plots"): the
# frequency response (STEM_response.png), the bifurcation diagram (STEM_bifurcation.png)
# with, below it, the period, the 0-1 test and the Lyapunov exponent of each point's
# Poincare samples (STEM_chaos.png), for a sweep with two parameters the map
# (STEM_map.png) and, for a beam of two planes with obstacles, the wear at each of their
# points against the parameter (STEM_wear.png); for a sweep of periodic analyses
# (&analysis kind = 'periodic') the branches of its points (STEM_branches.png,
# plot_sweep_branches.gp) or, without continuation, its orbits' period and largest Floquet
# multiplier (STEM_orbits.png, plot_sweep_orbits.gp).
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
vibrobeam=${VIBROBEAM:-$(command -v vibrobeam || echo "$here/../build/vibrobeam")}
derive() {  # derive RESULT.h5: its text files, with vibrobeam --text
  [ -x "$vibrobeam" ] || { echo "plot_sweep: the .dat files of $1 are missing or stale and no vibrobeam" \
                                "program was found to derive them (set VIBROBEAM)" >&2; exit 1; }
  echo "plot_sweep: deriving the text files of $1"
  "$vibrobeam" --text "$1"
}
# a sweep of periodic analyses (docs/sweeps.md, "Sweeps of periodic orbits and branches"):
# the branches of its point files on one plot; without continuation, the orbits' period
# and largest multiplier against the parameter
if grep -q ' /sweep/statistics/periodic$' <<< "$listing"; then
  file="${stem}_sweep.dat"
  if [ ! -f "$file" ] || ! head -1 "$file" | grep -q -F "# vibrobeam run $run_id "; then derive "$result"; fi
  points=""; titles=""; found=""; count=0
  unit=$(h5dump -a /sweep/parameter/unit "$result" 2> /dev/null | sed -n 's/.*(0): *"\([^"]*\)".*/\1/p')
  while read -r k value; do
    point=$(printf '%s_point%04d' "$stem" "$k")
    [ -f "$point.h5" ] || continue
    if h5dump -n "$point.h5" 2> /dev/null | grep -q ' /periodic/branch/parameter$'; then
      id=$(h5dump -a /run/run_id "$point.h5" 2> /dev/null | sed -n 's/.*(0): *"\([^"]*\)".*/\1/p')
      if [ ! -f "${point}_branch.dat" ] || ! head -1 "${point}_branch.dat" | grep -q -F "# vibrobeam run $id "; then
        derive "$point.h5" > /dev/null
      fi
      points="$points $point"; titles="$titles|$value $unit"; count=$((count + 1))
      # (a file without rows would make gnuplot warn)
      if awk '!/^#/ && NF {n++} END {exit !(n > 0)}' "${point}_bifurcations.dat" 2> /dev/null; then
        found="$found $count"
      fi
    fi
  done < <(awk '!/^#/ && NF {printf "%d %.6g\n", $1, $4}' "$file")
  if [ -n "$points" ]; then
    gnuplot -e "stem='${stem}'; points='${points# }'; titles='${titles#|}'; found='${found# }'" \
            "$here/plot_sweep_branches.gp"
    echo "plot_sweep: drew ${stem}_branches.png"
  else
    gnuplot -e "stem='${stem}'" "$here/plot_sweep_orbits.gp"
    echo "plot_sweep: drew ${stem}_orbits.png"
  fi
  exit 0
fi
stale=0
# a beam of two planes with obstacles: STEM_wear.dat too
wear=""; if grep -q ' /sweep/statistics/wear/x$' <<< "$listing"; then wear=wear; fi
for kind in sweep poincare $wear; do
  file="${stem}_${kind}.dat"
  if [ ! -f "$file" ] || ! head -1 "$file" | grep -q -F "# vibrobeam run $run_id "; then stale=1; fi
done
if [ "$stale" = 1 ]; then derive "$result"; fi

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
