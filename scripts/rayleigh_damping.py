#!/usr/bin/env python3
"""Rayleigh damping C = a M + b K that gives chosen damping ratios to two natural modes of
the clamped-free beam: the coefficients &beam rayleigh_mass (a, 1/s) and
rayleigh_stiffness (b, s) of the bundled scenes (docs/input.md, "&beam").

Mode n of a beam with C = a M + b K has the damping ratio zeta_n = a/(2 omega_n) +
b omega_n/2 (the modes of M and K diagonalise C). Asking zeta_i and zeta_j of two modes
gives two linear equations in a and b:
    a = 2 omega_i omega_j (zeta_i omega_j - zeta_j omega_i)/(omega_j^2 - omega_i^2),
    b = 2 (zeta_j omega_j - zeta_i omega_i)/(omega_j^2 - omega_i^2),
which for zeta_i = zeta_j = zeta reduce to a = 2 zeta omega_i omega_j/(omega_i + omega_j),
b = 2 zeta/(omega_i + omega_j). Between the two modes the ratio dips below zeta, beyond
them it grows like b omega_n/2: high modes are damped more, which mass damping alone
(b = 0, zeta_n = a/(2 omega_n)) does not do (1 % at mode 1 leaves 0.16 % at mode 2).

The frequencies are the continuum closed form omega_n = (beta_n L)^2 sqrt(E I/(rho S))/L^2
(docs/theory.md section 7), the roots beta_n L quoted to 20 digits
(scripts/cantilever_roots.py); they differ from those of a mesh of 16 Hermite elements by
less than 1e-5 for modes 1 and 2 (README, "Verification: natural frequencies").

usage: python3 scripts/rayleigh_damping.py L E RHO S I ZETA [ZETA_J] [--modes I J]
       python3 scripts/rayleigh_damping.py L --k2 K2 ZETA [ZETA_J] [--modes I J]
  L, E, RHO, S, I: length (m), Young's modulus (Pa), density (kg/m^3), area (m^2) and
  second moment of area (m^4) as in &beam; or k2 = E I/(rho S) (m^4/s^2);
  ZETA: the damping ratio of mode I (and of mode J unless ZETA_J is given), e.g. 0.01;
  --modes I J: the two modes fitted (default 1 2).
Prints a and b to 17 significant digits (paste them into &beam), and the damping ratio
of modes 1 to 6 that they give.
example (the tube of inputs/tube_frequency_sweep.nml, 1 % at modes 1 and 2):
  python3 scripts/rayleigh_damping.py 0.8 200e9 8000 6.938018879893839e-5 2.7642255353230253e-9 0.01
"""
import math
import sys

ROOTS = [1.8751040687119611664, 4.6940911329741745764, 7.8547574382376125649,
         10.995540734875466990, 14.137168391046470580, 17.278759532088236333]


def frequencies(length, k2):
    """omega_n (rad/s) of modes 1..6 of the clamped-free beam."""
    return [root ** 2 * math.sqrt(k2) / length ** 2 for root in ROOTS]


def coefficients(omega_i, omega_j, zeta_i, zeta_j):
    """a (1/s) and b (s) with zeta_n = a/(2 omega_n) + b omega_n/2 at modes i and j."""
    span = omega_j ** 2 - omega_i ** 2
    a = 2 * omega_i * omega_j * (zeta_i * omega_j - zeta_j * omega_i) / span
    b = 2 * (zeta_j * omega_j - zeta_i * omega_i) / span
    return a, b


def main(arguments):
    modes = (1, 2)
    if '--modes' in arguments:
        k = arguments.index('--modes')
        modes = (int(arguments[k + 1]), int(arguments[k + 2]))
        del arguments[k:k + 3]
    try:
        if len(arguments) > 1 and arguments[1] == '--k2':
            length, k2 = float(arguments[0]), float(arguments[2])
            ratios = [float(x) for x in arguments[3:]]
        else:
            length, young, density, area, inertia = (float(x) for x in arguments[:5])
            k2 = young * inertia / (density * area)
            ratios = [float(x) for x in arguments[5:]]
    except (ValueError, IndexError):
        sys.exit(__doc__)
    if len(ratios) not in (1, 2) or not (1 <= modes[0] < modes[1] <= len(ROOTS)):
        sys.exit(__doc__)
    zeta_i, zeta_j = ratios[0], ratios[-1]
    omega = frequencies(length, k2)
    a, b = coefficients(omega[modes[0] - 1], omega[modes[1] - 1], zeta_i, zeta_j)
    if a < 0 or b < 0:
        sys.exit('these ratios need a negative coefficient (a = %.6g, b = %.6g): '
                 'vibrobeam allows a, b >= 0' % (a, b))
    print('rayleigh_mass = %.17g, rayleigh_stiffness = %.17g' % (a, b))
    for n, w in enumerate(omega, start=1):
        print('mode %d: omega = %.6g rad/s (%.6g Hz), damping ratio %.4g %%'
              % (n, w, w / (2 * math.pi), 100 * (a / (2 * w) + b * w / 2)))


if __name__ == '__main__':
    main(sys.argv[1:])
