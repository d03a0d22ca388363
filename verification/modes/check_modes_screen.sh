#!/usr/bin/env bash
# A modes run prints the frequencies it found, in rad/s and in Hz (docs/output.md, "What a
# run prints"): one line '  mode n: omega = W rad/s, f = F Hz' for each of the modes the
# input asks for. Run on the steel cantilever (verification/modes/steel_cantilever.nml,
# N = 64, 6 modes) and compared with the closed form omega_n = (beta_n L)^2 sqrt(EI/(rho S))/L^2
# (docs/theory.md section 7), the roots beta_n L of 1 + cos b cosh b = 0 quoted to 20 digits
# (scripts/cantilever_roots.py). Tolerances: the discretization error of Hermite cubics,
# (beta_n h)^4/1440 relative, 3.7e-6 for mode 6 at N = 64 (verification.modes_steel_cantilever
# bounds it by 5e-6), plus the rounding of 9 printed digits (5e-9 relative); f = omega/(2 pi)
# to the rounding of both printed numbers, 1e-8 relative.
# usage: check_modes_screen.sh VIBROBEAM INPUT.nml
set -uo pipefail
vibrobeam=$1; input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$input" "$work/input.nml"
cd "$work"
"$vibrobeam" input.nml > screen.txt 2> errors.txt || { echo "FAIL the run failed:"; cat errors.txt; exit 1; }
cat screen.txt
awk '
  BEGIN {
    split("1.8751040687119611664 4.6940911329741745764 7.8547574382376125649 " \
          "10.995540734875466990 14.137168391046470580 17.278759532088236333", root, " ")
    L = 0.5; E = 210e9; rho = 7850; S = 2e-4; I = 1.6666666666666667e-9
    pi = atan2(0, -1); wanted = 6; failed = 0; found = 0
  }
  $1 == "mode" && $3 == "omega" {
    n = $2; sub(":", "", n); omega = $5; f = $9
    if ($6 != "rad/s," || $10 != "Hz") { print "FAIL units of line: " $0; failed = 1; next }
    exact = root[n]^2 * sqrt(E * I / (rho * S)) / L^2
    error = (omega - exact) / exact; if (error < 0) error = -error
    printf "mode %d: omega %.9g rad/s, closed form %.9g, relative difference %.2e (tolerance 5.005e-6)\n", n, omega, exact, error
    if (error > 5.005e-6) { print "FAIL mode " n " omega"; failed = 1 }
    ratio = f * 2 * pi / omega - 1; if (ratio < 0) ratio = -ratio
    if (ratio > 1e-8) { printf "FAIL mode %d: f = %.9g Hz is not omega/(2 pi) = %.9g\n", n, f, omega / (2 * pi); failed = 1 }
    if (n != found + 1) { print "FAIL mode " n " out of order"; failed = 1 }
    found = n
  }
  END {
    if (found != wanted) { printf "FAIL %d modes printed, %d asked for\n", found, wanted; failed = 1 }
    if (failed) exit 1
    print "the printed frequencies agree with the closed form"
  }' screen.txt
