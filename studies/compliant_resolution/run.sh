#!/bin/sh
# How many steps per contact time scale does a compliant stop need? The normalized
# cantilever (k2 = 1, L = 1, N = 16) released with mode-1 tip velocity 1 into a linear
# stop k = 1e4 at +0.05 above the tip; dt = T_c/s with T_c = pi sqrt(m_eff/(k + k_b)) the
# --check estimate (m_eff = 0.242672, k_b = 3) and s = 2.5 .. 640. The first episode's
# start, end, duration and impulse (/episodes), against s = 640.
# Usage: sh studies/compliant_resolution/run.sh BUILD_DIR   (20 s)
set -eu
bin=${1:-build}/vibrobeam
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
out="$here/results.txt"
echo "# steps_per_Tc dt(s) start(s) end(s) duration(s) impulse(N s, per unit rho S)" > "$out"
for s in 2.5 5 10 20 40 80 640; do
  dt=$(awk -v s=$s 'BEGIN { printf "%.15e", 3.141592653589793*sqrt(0.242672/(1e4 + 3))/s }')
  cat > "$work/s.nml" <<NML
&beam      length = 1.0, k2 = 1.0 /
&mesh      elements = 16 /
&obstacles count = 1, side(1) = 'above', x_from(1) = 1.0, level_from(1) = 0.05, stiffness(1) = 1e4 /
&time      t_end = 0.15, dt = $dt /
&initial   velocity = 'mode', velocity_mode = 1, velocity_amplitude = 1.0 /
&output    file = '$work/s.h5', every = 1 /
NML
  "$bin" "$work/s.nml" > /dev/null 2>&1
  awk -v s=$s -v dt=$dt '!/^#/ && NF { printf "%s %s %.6f %.6f %.6f %.6e\n", s, dt, $2, $3, $3 - $2, $4; exit }' \
      "$work/s_episodes.dat" >> "$out"
done
rm -rf "$work"
cat "$out"
