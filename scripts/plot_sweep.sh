#!/usr/bin/env bash
# Draw the plots of a sweep file, as PNG beside it (docs/sweeps.md): the frequency
# response (STEM_response.png), the bifurcation diagram (STEM_bifurcation.png) and, for a
# sweep with two parameters, the map (STEM_map.png).
# usage: plot_sweep.sh SWEEP.h5
# The .dat files are derived from SWEEP.h5 (STEM_sweep.dat, STEM_poincare.dat): when one
# is missing or names another run than SWEEP.h5's /run run_id, they are derived again
# with `vibrobeam --text SWEEP.h5` (vibrobeam from $VIBROBEAM, the PATH, or build/ of
# this repository).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
result=${1:?usage: plot_sweep.sh SWEEP.h5}
stem=${result%.h5}
[ -f "$result" ] || { echo "plot_sweep: no sweep file $result" >&2; exit 1; }
# a here-string, not a pipe: grep -q stops early, and under pipefail h5dump's SIGPIPE fails
listing=$(h5dump -n "$result" 2> /dev/null || true)
grep -q ' /sweep/parameter$' <<< "$listing" || {
  echo "plot_sweep: $result is not a sweep file (no /sweep/parameter); for a run use plot_results.sh" >&2; exit 1; }

run_id=$(h5dump -a /run/run_id "$result" 2> /dev/null | sed -n 's/.*(0): *"\([^"]*\)".*/\1/p')
stale=0
for kind in sweep poincare; do
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

gnuplot -e "stem='${stem}'" "$here/plot_sweep_response.gp"
drawn="${stem}_response.png"
if awk '!/^#/ && NF {n++} END {exit !(n > 0)}' "${stem}_poincare.dat"; then
  gnuplot -e "stem='${stem}'" "$here/plot_sweep_bifurcation.gp"
  drawn="$drawn ${stem}_bifurcation.png"
fi
if grep -q ' /sweep/parameter2$' <<< "$listing"; then
  gnuplot -e "stem='${stem}'" "$here/plot_sweep_map.gp"
  drawn="$drawn ${stem}_map.png"
fi
echo "plot_sweep: drew $drawn"
