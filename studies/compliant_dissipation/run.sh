#!/bin/sh
# Does the energy lost at the stops converge under mesh refinement? The looseness scene of
# inputs/looseness_tip_stops.nml over 25 ms with dt = 1e-6 s, N = 8 .. 128, for
#   rigid:     rigid stops, e = 0.8 (Newton's law);
#   damped:    compliant stops k = 1e7 N/m, Hunt-Crossley alpha = 0.553 s/m, whose
#              one-degree-of-freedom restitution is 0.8 at the first impact speed 0.45 m/s
#              (alpha v = 0.2488, restitution.py);
#   undamped:  the same stops without damping (no physical dissipation at all).
# Then dt = 5e-7 and 2.5e-7 s at N = 128 (is dt = 1e-6 converged?).
# Writes results.txt: N, dt, model, E(0), E(25 ms), lost fraction, share of the loss taken
# by the contact damping (the rest: impacts or the time discretization).
# Usage: sh studies/compliant_dissipation/run.sh BUILD_DIR   (about 1 minute on 2 cores)
set -eu
bin=${1:-build}/vibrobeam
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
out="$here/results.txt"
echo "# N dt(s) model E0(J) E(25ms)(J) lost_fraction contact_damping_share_of_loss" > "$out"
for case in 8:1e-6 16:1e-6 32:1e-6 64:1e-6 128:1e-6 256:1e-6 512:1e-6 128:5e-7 128:2.5e-7; do
  n=${case%%:*}; dt=${case#*:}
  for model in rigid damped undamped; do
    case $model in
      rigid)    stops="" ; e=0.8 ;;
      damped)   stops=", stiffness(1) = 1e7, damping(1) = 0.553, stiffness(2) = 1e7, damping(2) = 0.553" ; e=1.0 ;;
      undamped) stops=", stiffness(1) = 1e7, stiffness(2) = 1e7" ; e=1.0 ;;
    esac
    cat > "$work/s.nml" <<NML
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9 /
&mesh      elements = $n /
&obstacles count = 2,
           side(1) = 'below', x_from(1) = 0.5, level_from(1) = -1e-3,
           side(2) = 'above', x_from(2) = 0.5, level_from(2) =  1e-3 $stops /
&impact    restitution = $e /
&time      t_end = 0.025, dt = $dt /
&initial   velocity = 'mode', velocity_mode = 1, velocity_amplitude = 0.5 /
&output    file = '$work/s.h5', every = 1000 /
NML
    "$bin" "$work/s.nml" > /dev/null 2>&1
    # energy.dat columns: t kinetic elastic work dissipated impacts damping total balance penetration numerical
    # contact damping = dissipated - impacts - damping - numerical
    awk -v n=$n -v dt=$dt -v m=$model 'NR>2 { if (e0 == "") e0 = $8; last = $8; cd = $5 - $6 - $7 - $11 } END {
      loss = e0 - last; share = 0; if (loss > 0) share = cd/loss
      printf "%4d %-7s %-9s %.6e %.6e %.5f %.4f\n", n, dt, m, e0, last, loss/e0, share }' "$work/s_energy.dat" >> "$out"
  done
done
rm -rf "$work"
cat "$out"
