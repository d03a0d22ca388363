#!/bin/sh
# Rigid limit of compliant stops: the normalized cantilever of
# verification/dynamics/elastic_two_stops.nml (k2 = 1, L = 1, N = 16, tip stops at +-0.05,
# released with mode-1 tip velocity 1) with undamped linear tip springs of growing k,
# against the rigid e = 1 stops on the same mesh. The tip stiffness is k_b = 3 and the
# contact time scale pi sqrt(0.243/k): dt = 1e-6 s resolves it by more than 300 steps up
# to k = 1e7 (and the rigid run uses the same dt).
# For each k: the largest tip-displacement difference over the first contact episode
# [0, W] (default 1 s) and over [0, T] with T = 6 s (several episodes), and the energy at T
# (which for springs includes the stored part).
# Usage: sh studies/compliant_rigid_limit/run.sh BUILD_DIR [T [W [STIFFNESSES [OUT]]]]
# (defaults 6 s, 1 s, "1e2 ... 1e7", studies/compliant_rigid_limit/results.txt)
set -eu
bin=${1:-build}/vibrobeam
t_end=${2:-6.0}
window=${3:-1.0}
stiffnesses=${4:-"1e2 1e3 1e4 1e5 1e6 1e7"}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
out=${5:-"$here/results.txt"}
run() {  # $1 label, $2 obstacle extra, $3 dt
  cat > "$work/$1.nml" <<NML
&beam      length = 1.0, k2 = 1.0 /
&mesh      elements = 16 /
&obstacles count = 2, side(1) = 'below', x_from(1) = 1.0, level_from(1) = -0.05 $2,
                      side(2) = 'above', x_from(2) = 1.0, level_from(2) =  0.05 $(echo "$2" | sed 's/(1)/(2)/g') /
&impact    restitution = 1.0 /
&time      t_end = $t_end, dt = $3 /
&initial   velocity = 'mode', velocity_mode = 1, velocity_amplitude = 1.0 /
&output    file = '$work/$1.h5', every = 100 /
NML
  "$bin" "$work/$1.nml" > /dev/null 2>&1
}
run rigid "" 1e-6
echo "# k  max|u_tip - u_rigid| over [0,$window s]  over [0,$t_end s]  E(T)/E(0) (rigid: E is conserved)" > "$out"
for k in $stiffnesses; do
  run "k$k" ", stiffness(1) = $k" 1e-6
  paste "$work/rigid_tip.dat" "$work/k${k}_tip.dat" | awk -v k=$k -v T=$t_end -v W=$window '
    /^#/ { next }
    { d = $2 - $7; if (d < 0) d = -d; if ($1 <= W && d > m1) m1 = d; if (d > mT) mT = d }
    END { printf "%s %.4e %.4e", k, m1, mT }' >> "$out"
  awk 'NR>2 { if (e0 == "") e0 = $8; e = $8 } END { printf " %.12f\n", e/e0 }' "$work/k${k}_energy.dat" >> "$out"
done
rm -rf "$work"
cat "$out"
