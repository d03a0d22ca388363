#!/usr/bin/env bash
# The structural damping &flow's critical velocities use (docs/theory.md §10, Connors:
# U_c,n = K f_n sqrt(2 pi zeta_n m/(rho J_n))): with &beam modal_damping_ratios the ratio
# of a mode is the one given, not the Rayleigh ratio. `vibrobeam --check` of the same tube
# at U = 0.6 m/s, without stops, with its Rayleigh damping (zeta = 0.01 in modes 1 and 2)
# and with modal_damping_ratios(1) = 0.03 beside it:
#  - mode 1 lists zeta = 0.03 and U_c sqrt(0.03/0.01) = sqrt(3) times the Rayleigh scene's
#    (Connors' U_c goes as sqrt(zeta); both printed to 6 digits: 2e-5 relative allowed);
#  - mode 2, which has no ratio of its own, is the same in both;
#  - the unbounded-motion warning names mode 1 in the Rayleigh scene (0.6 > 0.489 m/s) and
#    is absent with the ratio (0.6 < 0.847 m/s).
# Before, --check and the warning took the Rayleigh ratio whatever the damping per mode.
# usage: check_flow_modal_damping.sh VIBROBEAM
set -uo pipefail
vibrobeam=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cat > rayleigh.nml <<'NML'
&beam      length = 0.8, youngs_modulus = 200e9, density = 8000,
           area = 6.938018879893839e-5, inertia = 2.7642255353230253e-9,
           rayleigh_mass = 2.9904964512035113, rayleigh_stiffness = 1.5873454345743495e-05 /
&mesh      elements = 16 /
&time      dt = 1e-4, t_end = 0.1 /
&flow      velocity = 0.6, density = 1000, diameter = 0.01905, connors_constant = 3.0 /
&output    file = 'rayleigh.h5' /
NML
sed -e 's/rayleigh_stiffness = 1.5873454345743495e-05 \//rayleigh_stiffness = 1.5873454345743495e-05, modal_damping_ratios(1) = 0.03 \//' \
    -e 's/rayleigh.h5/modal.h5/' rayleigh.nml > modal.nml
"$vibrobeam" --check rayleigh.nml > rayleigh.txt 2>&1 || { echo "FAIL --check rayleigh.nml"; cat rayleigh.txt; exit 1; }
"$vibrobeam" --check modal.nml > modal.txt 2>&1 || { echo "FAIL --check modal.nml"; cat modal.txt; exit 1; }
# mode n's zeta and U_c from the fluid-elastic lines ('  mode 1: f = ... Hz, zeta = Z, ... U_c = U m/s ...')
mode() { sed -n "s/^  mode $2: f = .* Hz, zeta = \([^,]*\), .*critical velocity U_c = \([^ ]*\) m\/s.*/\1 \2/p" "$1"; }
read -r zeta_r1 critical_r1 < <(mode rayleigh.txt 1)
read -r zeta_m1 critical_m1 < <(mode modal.txt 1)
read -r zeta_r2 critical_r2 < <(mode rayleigh.txt 2)
read -r zeta_m2 critical_m2 < <(mode modal.txt 2)
failed=0
verdict() { if [ "$1" = 0 ]; then echo "ok   $2"; else echo "FAIL $2"; failed=1; fi; }
awk -v z="$zeta_m1" 'BEGIN {exit !(z == 0.03)}'
verdict $? "mode 1 with modal_damping_ratios(1) = 0.03 lists zeta = $zeta_m1"
awk -v a="$critical_r1" -v b="$critical_m1" -v za="$zeta_r1" \
  'BEGIN {r = b/a/sqrt(0.03/za); printf "     U_c %s -> %s m/s: ratio / sqrt(0.03/%s) = %.7f\n", a, b, za, r; exit !(r > 1 - 2e-5 && r < 1 + 2e-5)}'
verdict $? "mode 1's U_c is sqrt(zeta_given/zeta_Rayleigh) times the Rayleigh scene's"
[ "$zeta_r2 $critical_r2" = "$zeta_m2 $critical_m2" ] && [ -n "$critical_r2" ]
verdict $? "mode 2 (no ratio of its own) is the same: zeta $zeta_m2, U_c $critical_m2 m/s"
grep -q 'exceeds the critical velocity of mode 1' rayleigh.txt
verdict $? "the Rayleigh scene warns that U = 0.6 m/s exceeds mode 1's U_c"
! grep -q 'exceeds the critical velocity' modal.txt
verdict $? "the scene with the ratio does not (U_c = $critical_m1 m/s)"
exit $failed
