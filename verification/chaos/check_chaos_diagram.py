#!/usr/bin/env python3
"""The Poincare diagnostics on a reduced bifurcation diagram of the rattling beam (issue 20,
item 3, acceptance; docs/statistics.md "Period, Lyapunov exponent and the 0-1 test";
the full diagram: studies/chaos_diagnostics/REPORT.md).

usage: check_chaos_diagram.py VIBROBEAM

The rattling beam of inputs/rattling_bifurcation.nml on 8 elements (dt = 4e-5 s) between
compliant stops (1e7 N/m, Hunt-Crossley 6 s/m: the map is smooth, so its Lyapunov exponent
is the beam's), swept over four forcing frequencies as independent points, 200 periods to
settle and 200 measured, with &output lyapunov and every Poincare sample kept. For each
point, from the sweep file:
 - regular points (150 and 200 rad/s: a free response and a rattling one whose samples
   repeat): lambda T < 0 by more than 3 standard errors and K < 0.2;
 - chaotic points (240 and 276 rad/s): lambda T > 0 by more than 3 standard errors and
   K > 0.8;
 - the period the program finds equals the period the diagram shows: computed here from
   the point's samples of the tip displacement alone, the smallest p <= 64 with
   |u_{k+p} - u_k| below the diagram's resolution (a thousandth of the range of every
   sample of the diagram, what the bifurcation plot tells apart), 0 when none.
The same two frequencies 150 and 276 rad/s with rigid stops (e = 0.7): there K (< 0.2 and
> 0.8) and the period (1 and none) read the response as with compliant stops, but the
Lyapunov exponent is the discrete map's, negative by more than 3 standard errors at both
(the map is piecewise affine and contracting: docs/method.md, "Chaos diagnostics: why
twin runs do not separate").
The thresholds 0.2 and 0.8 are Gottwald and Melbourne's reading of K (regular near 0,
chaotic near 1); 3 standard errors keep the sign of lambda beyond its sampling error.
Exit status 0 when every check holds, 1 otherwise, 77 without h5py.
"""
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
    import h5py
except ImportError:
    print('SKIP: no python3 with h5py (Debian package python3-h5py)')
    sys.exit(77)

SCENE = """
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9, rayleigh_mass = 1.8109, rayleigh_stiffness = 6.5532e-6 /
&mesh      elements = 8 /
&obstacles count = 2,
           side(1) = 'below', x_from(1) = 0.5, level_from(1) = -0.5e-3, stiffness(1) = 1e7, damping(1) = 6,
           side(2) = 'above', x_from(2) = 0.5, level_from(2) =  0.5e-3, stiffness(2) = 1e7, damping(2) = 6 /
&time      dt = 4e-5 /
&load      point_force = 2.0, point_position = 0.5, point_frequency = 200.0 /
&output    file = 'diagram.h5', text = .false., lyapunov = .true. /
&sweep     parameter = 'load.point_frequency', values = 150, 200, 240, 276, mode = 'independent',
           settle_periods = 200, measure_periods = 200, poincare_samples = 'all' /
"""
RIGID = SCENE.replace(", stiffness(1) = 1e7, damping(1) = 6,", ",").replace(
    ", stiffness(2) = 1e7, damping(2) = 6 /", " /\n&impact    restitution = 0.7 /").replace(
    "values = 150, 200, 240, 276", "values = 150, 276")
REGULAR = (150.0, 200.0)
CHAOTIC = (240.0, 276.0)


def diagram_period(u, resolution, longest=64):
    for p in range(1, min(longest, len(u) // 3) + 1):
        if np.max(np.abs(u[p:] - u[:-p])) <= resolution:
            return p
    return 0


def sweep(vibrobeam, work, scene, failures):
    """parameter, period, K, lambda T, its error and the period the diagram shows, per point."""
    with open(os.path.join(work, 'diagram.nml'), 'w') as handle:
        handle.write(scene)
    done = subprocess.run([vibrobeam, 'diagram.nml'], cwd=work, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        failures.append(f'vibrobeam diagram.nml exits {done.returncode}: {done.stderr}')
        return []
    with h5py.File(os.path.join(work, 'diagram.h5'), 'r') as result:
        parameter = result['/sweep/parameter'][:]
        group = result['/sweep/statistics/poincare']
        period = group['period'][:]
        k = group['zero_one_k'][:]
        lam = group['lyapunov_exponent_per_period'][:]
        error = group['lyapunov_exponent_per_period_error'][:]
        point = result['/sweep/poincare/point'][:]
        tip = result['/sweep/poincare/displacement'][:, 0]
    resolution = 1e-3 * (tip.max() - tip.min())
    return [(parameter[j], int(period[j]), k[j], lam[j], error[j], diagram_period(tip[point == j + 1], resolution))
            for j in range(len(parameter))]


def main():
    vibrobeam = os.path.abspath(sys.argv[1])
    failures = []
    with tempfile.TemporaryDirectory() as work:
        for stops, scene in (('compliant', SCENE), ('rigid', RIGID)):
            for omega, period, k, lam, error, shown in sweep(vibrobeam, work, scene, failures):
                print(f'{stops} stops, {omega:6.1f} rad/s: period {period} (the diagram shows {shown}), K = {k:.3f}, '
                      f'lambda T = {lam:+.4f} +- {error:.4f}')
                where = f'{stops} stops, {omega} rad/s'
                if stops == 'rigid' and not lam < -3 * error:
                    failures.append(f'{where}: the discrete map exponent should be negative: {lam:.4f} +- {error:.4f}')
                elif stops == 'compliant' and omega in REGULAR and not lam < -3 * error:
                    failures.append(f'{where} should be regular: lambda T = {lam:.4f} +- {error:.4f}')
                elif stops == 'compliant' and omega in CHAOTIC and not lam > 3 * error:
                    failures.append(f'{where} should be chaotic: lambda T = {lam:.4f} +- {error:.4f}')
                if omega in REGULAR and not k < 0.2:
                    failures.append(f'{where} should be regular: K = {k:.3f}')
                if omega in CHAOTIC and not k > 0.8:
                    failures.append(f'{where} should be chaotic: K = {k:.3f}')
                if period != shown:
                    failures.append(f'{where}: period {period}, the diagram shows {shown}')
    for failure in failures:
        print('FAIL: ' + failure)
    print(f'check_chaos_diagram: {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
