#!/usr/bin/env bash
# Draw every plot that the .dat files of a result set allow, as PNG beside them.
# usage: plot_results.sh RESULT.h5   (needs the .dat files: &output text = .true., the default)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
result=${1:?usage: plot_results.sh RESULT.h5}
stem=${result%.h5}
drawn=0
plot() {  # plot SCRIPT REQUIRED_DAT
  if [ -f "${stem}_$2.dat" ]; then
    gnuplot -e "stem='${stem}'" "$here/$1"
    drawn=$((drawn + 1))
  fi
}
plot plot_modes.gp shapes
plot plot_static.gp static
for gp in "$here"/plot_dynamics_*.gp; do
  [ -e "$gp" ] || continue
  name=$(basename "$gp" .gp)
  plot "$name.gp" "$(sed -n 's/^# needs: *//p' "$gp")"
done
echo "plot_results: $drawn plot script(s) run; PNG files are beside ${stem}.h5"
