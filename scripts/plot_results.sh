#!/usr/bin/env bash
# Draw every plot that a result allows, as PNG beside it (docs/output.md, "Plots").
# usage: plot_results.sh RESULT.h5 [--point K]
#   --point K   the spectrum, the phase portrait and the Poincare section at &output
#               points(K) instead of the tip (K = 0, the default)
# The .dat files are derived from RESULT.h5: when one is missing or names another run
# than RESULT.h5's /run run_id (an earlier run's, or none with &output text = .false.),
# they are derived again with `vibrobeam --text RESULT.h5` (vibrobeam from $VIBROBEAM,
# the PATH, the installation this script belongs to, or build/ of this repository).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
usage="usage: plot_results.sh RESULT.h5 [--point K]"
result=${1:?$usage}
shift
point=0
while [ $# -gt 0 ]; do
  case $1 in
    --point)
      point=${2:-}
      [[ "$point" =~ ^[0-9]+$ ]] || { echo "plot_results: --point takes a whole number, 0 for the tip; $usage" >&2; exit 1; }
      shift ;;
    *) echo "plot_results: unknown argument '$1'; $usage" >&2; exit 1 ;;
  esac
  shift
done
stem=${result%.h5}
[ -f "$result" ] || { echo "plot_results: no result file $result" >&2; exit 1; }

run_id=$(h5dump -a /run/run_id "$result" 2> /dev/null | sed -n 's/.*(0): *"\([^"]*\)".*/\1/p')
stale=0
needed=$(ls "$here"/plot_*.gp | xargs sed -n 's/^# needs: *//p' | sort -u)
for kind in $needed shapes static; do
  [ -n "$run_id" ] || break
  file="${stem}_${kind}.dat"
  [ -f "$file" ] || continue
  head -1 "$file" | grep -q -F "# vibrobeam run $run_id " || stale=2
done
if [ -n "$run_id" ]; then
  # a result holds some of these; its .dat files must exist for what it holds
  h5dump -n "$result" 2> /dev/null | grep -q ' /time$' && [ ! -f "${stem}_tip.dat" ] && stale=2
  h5dump -n "$result" 2> /dev/null | grep -q ' /modes/shape$' && [ ! -f "${stem}_shapes.dat" ] && stale=2
  h5dump -n "$result" 2> /dev/null | grep -q ' /static/displacement$' && [ ! -f "${stem}_static.dat" ] && stale=2
  h5dump -n "$result" 2> /dev/null | grep -q ' /periodic/orbit/time$' && [ ! -f "${stem}_orbit.dat" ] && stale=2
fi
if [ "$stale" = 2 ]; then
  # installed, this script is PREFIX/share/vibrobeam/plot/plot_results.sh
  vibrobeam=${VIBROBEAM:-$(command -v vibrobeam || { [ -x "$here/../../../bin/vibrobeam" ] &&
                                                      echo "$here/../../../bin/vibrobeam"; } ||
                           echo "$here/../build/vibrobeam")}
  [ -x "$vibrobeam" ] || { echo "plot_results: the .dat files of $result are missing or stale and no vibrobeam" \
                                "program was found to derive them (set VIBROBEAM)" >&2; exit 1; }
  echo "plot_results: deriving the text files of $result"
  "$vibrobeam" --text "$result"
fi

# the observation point of the spectrum, phase portrait and Poincare section, and the
# start of the statistics window (from the result's attributes)
attribute() { h5dump -m '%.17g' -a "$1" "$result" 2> /dev/null | sed -n 's/.*(0): *\(.*\)$/\1/p' | head -1; }
where="the tip"
if [ "$point" -gt 0 ]; then
  x=$(h5dump -m '%.6g' -d /points/x -y -w 1 "$result" 2> /dev/null |
      awk -v k="$point" '/^ *[-0-9.eE+]+,? *$/ {n++; gsub("[ ,]", ""); if (n == k) print}')
  [ -n "$x" ] || { echo "plot_results: --point $point: $result has no &output points($point)" >&2; exit 1; }
  where="x = $x m"
fi
measure_from=$(attribute /output.measure_from); measure_from=${measure_from:-0}
drawn=0
plot() {  # plot SCRIPT REQUIRED_DAT
  if [ -f "${stem}_$2.dat" ]; then
    gnuplot -e "stem='${stem}'; point=${point}; where='${where}'; measure_from=${measure_from}" "$here/$1"
    drawn=$((drawn + 1))
  fi
}
plot plot_modes.gp shapes
plot plot_static.gp static
plot plot_periodic.gp orbit
plot plot_branch.gp branch
# a beam of two bending planes: the tip's orbit in the cross-section (tip.dat's z columns),
# with the round hole that covers the tip, if any (&obstacles shape = 'circle')
if [ -f "${stem}_tip.dat" ] && head -2 "${stem}_tip.dat" | grep -q -F 'then u_tip in z'; then
  hole=''
  length=$(attribute /beam.length)
  count=$(attribute /obstacles.count); count=${count:-0}
  for ((i = 1; i <= count; i++)); do
    [ "$(attribute "/obstacles.shape($i)")" = '"circle"' ] || continue
    awk -v a="$(attribute "/obstacles.x_to($i)")" -v l="$length" 'BEGIN {exit !(a >= l - 1e-9 * l)}' || continue
    cy=$(attribute "/obstacles.center_y($i)" || true); cz=$(attribute "/obstacles.center_z($i)" || true)
    hole="; radius=$(attribute "/obstacles.radius($i)"); center_y=${cy:-0}; center_z=${cz:-0}"
    break
  done
  gnuplot -e "stem='${stem}'; measure_from=${measure_from}${hole}" "$here/plot_orbit.gp"
  drawn=$((drawn + 1))
fi
for gp in "$here"/plot_dynamics_*.gp; do
  [ -e "$gp" ] || continue
  name=$(basename "$gp" .gp)
  plot "$name.gp" "$(sed -n 's/^# needs: *//p' "$gp")"
done
if [ "$drawn" -eq 0 ]; then
  echo "plot_results: nothing to draw for $result" >&2
  exit 1
fi
echo "plot_results: $drawn plot script(s) run; PNG files are beside ${stem}.h5"
