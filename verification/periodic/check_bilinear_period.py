#!/usr/bin/env python3
"""The autonomous orbit of a bilinear oscillator against its closed-form period
(&periodic autonomous; docs/method.md, "Autonomous periodic orbits", where the closed form
is derived; bilinear_reference.py computes it), and the discrete map's second order in the
steps per period.

usage: check_bilinear_period.py VIBROBEAM SCENE.nml [STIFFNESS_FACTOR]

SCENE (free_bilinear.nml) is a one-unknown scene: mass m = 33/140 rho A L and stiffness
k = 3 EI/L^3 of the cantilever condensed on its tip, a stop of stiffness k_s (exponent 1)
at the gap g above it, the orbit's tip amplitude A > g given. The reference (numbers of
the scene alone, no vibrobeam):
  w0 = sqrt(k/m), w1 = sqrt((k + k_s)/m), q_e = k_s g/(k + k_s),
  t_c = arccos((g - q_e)/(A - q_e))/w1            (from q = A down to the stop),
  v_g = (A - q_e) w1 sin(w1 t_c),  B = sqrt(g^2 + (v_g/w0)^2),
  T = 2 t_c + 2 (pi - arccos(g/B))/w0.
Checks, at P = 100, 200, 400, 800 steps per period (each run must converge, exit 0):
- the error e(P) = T_P - T is below the trapezoidal rule's leading phase error of the
  stiffer arc, T (w1 T/P)^2/12, times 1.1 (the expansion's next terms, below);
- e(P)/e(2P) = 4 within 4 eta, eta = (3/10)(pi/P)^2 + 1/P: (3/10)(pi/P)^2 is what the
  next term of the rule's phase error, tan(pi/P) = pi/P (1 + (pi/P)^2/3 + 2 (pi/P)^4/15),
  adds to the ratio, and 1/P bounds the step in which the tip crosses the stop (a local
  error O(dt^3) against the arcs' O(dt^2) global one: relatively O(1/P)).
Then along the backbone, P = 400, the tip amplitude A = 0.4 (below the gap: the orbit never
touches the stop), 0.75, 1.5, 3 and 6 mm:
- below the gap the orbit is the discrete linear oscillator's, T = 2 P tan(pi/P)/w0
  (docs/method.md, "The linear reference"), to round-off: |dT|/T <= c (tol + 2 noise)/
  (2 pi cos^2(pi/P)), c = sqrt(2) (the energy norm at the guess against the mode's own),
  noise = 8 eps P (one evaluation's round-off);
- above it each period errs from the closed form by less than the leading-order bound.
STIFFNESS_FACTOR (default 1) multiplies k_s in the reference: 1.001 must fail.
Exit status 0 when every check holds, 1 otherwise, 77 without h5py.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

try:
    import h5py
except ImportError:
    print('SKIP: no python3 with h5py (Debian package python3-h5py)')
    sys.exit(77)

from bilinear_reference import from_command_line

vibrobeam, text, oscillator = from_command_line(sys.argv)
number = oscillator.number
w0, w1, g = oscillator.w0, oscillator.w1, oscillator.g


def run(work, name, variant):
    """Run vibrobeam on `variant` (a scene's text) as NAME.nml in `work`: its /periodic
    period, or None (a failure recorded) when the run fails."""
    variant = re.sub(r"file\s*=\s*'[^']*'", f"file = '{name}.h5'", variant)
    path = os.path.join(work, f'{name}.nml')
    with open(path, 'w') as out:
        out.write(variant)
    result = subprocess.run([vibrobeam, path], cwd=work, capture_output=True, text=True)
    if result.returncode != 0:
        failures.append(f'{name}: vibrobeam exit {result.returncode}: {result.stderr.strip()}')
        return None
    with h5py.File(os.path.join(work, f'{name}.h5'), 'r') as f:
        if int(f['/periodic'].attrs.get('autonomous', 0)) != 1:
            failures.append(f'{name}: /periodic autonomous is not 1')
        return float(f['/periodic'].attrs['period'])


amplitude = number('tip_amplitude')
reference = oscillator.period(amplitude)
print(f'closed form: T = {reference:.16e} s (w0 {w0:.6f}, w1 {w1:.6f} rad/s, free amplitude '
      f'{oscillator.free_amplitude(amplitude):.6e} m)')

failures = []
errors = {}
with tempfile.TemporaryDirectory() as work:
    for steps in (100, 200, 400, 800):
        variant = re.sub(r'steps_per_period\s*=\s*\d+', f'steps_per_period = {steps}', text)
        period = run(work, f'P{steps}', variant)
        if period is None:
            continue
        error = period - reference
        errors[steps] = error
        bound = oscillator.leading_bound(reference, steps)
        print(f'P = {steps:4d}: T = {period:.16e} s, error {error:.3e} s, leading-order bound {bound:.3e} s')
        if not abs(error) <= bound:
            failures.append(f'P = {steps}: |error| {abs(error):.3e} s above {bound:.3e} s')
    for steps in (100, 200, 400):
        if steps in errors and 2 * steps in errors:
            ratio = errors[steps] / errors[2 * steps]
            eta = 0.3 * (math.pi / steps)**2 + 1.0 / steps
            print(f'e({steps})/e({2 * steps}) = {ratio:.6f}, allowed 4 +- {4 * eta:.4f}')
            if not abs(ratio - 4) <= 4 * eta:
                failures.append(f'e({steps})/e({2 * steps}) = {ratio:.6f} is not 4 within {4 * eta:.4f}')

    # the backbone: period against amplitude at P = 400
    steps = 400
    tolerance = number('tolerance')
    print(f'backbone at P = {steps}: A (m), T (s), closed form (s), error (s), bound (s)')
    for amplitude in (0.4e-3, 0.75e-3, 1.5e-3, 3e-3, 6e-3):
        variant = re.sub(r'steps_per_period\s*=\s*\d+', f'steps_per_period = {steps}', text)
        variant = re.sub(r'tip_amplitude\s*=\s*[-+0-9.eE]+', f'tip_amplitude = {amplitude!r}', variant)
        variant = re.sub(r'displacement_amplitude\s*=\s*[-+0-9.eE]+', f'displacement_amplitude = {amplitude!r}',
                         variant)
        period = run(work, f'A{amplitude:g}', variant)
        if period is None:
            continue
        expected, bound = oscillator.reference(amplitude, steps, tolerance)
        error = period - expected
        print(f'  {amplitude:.2e}  {period:.12e}  {expected:.12e}  {error:+.3e}  {bound:.3e}')
        if not abs(error) <= bound:
            failures.append(f'backbone A = {amplitude:g} m: |T - reference| = {abs(error):.3e} s above {bound:.3e} s')

for failure in failures:
    print('FAIL ' + failure)
print(f'check_bilinear_period: {"ok" if not failures else str(len(failures)) + " failed"}')
sys.exit(1 if failures else 0)
