#!/usr/bin/env python3
"""The backbone of a bilinear oscillator against its closed-form period (&periodic
autonomous with parameter = 'periodic.tip_amplitude'; docs/method.md, "The backbone").

usage: check_backbone.py VIBROBEAM SCENE.nml [STIFFNESS_FACTOR]

SCENE (backbone_bilinear.nml) is the one-unknown bilinear scene of free_bilinear.nml
continued in its tip amplitude A from below the gap to several gaps; one run. Checks:
- the run exits 0, /periodic/branch's parameter is periodic.tip_amplitude, and the branch
  reaches the end asked for: its first point at the scene's tip_amplitude, A increasing
  point by point, its last exactly at parameter_max, with fewer than max_points points
  (the bound, not the count, ended it), and STEM_branch.dat has one row per point;
- every point's period meets the reference of check_bilinear_period.py
  (bilinear_reference.py): below the gap the discrete linear period 2 P tan(pi/P)/w0 to
  its round-off bound, above it the closed form within the trapezoidal rule's leading phase
  error of the stiffer arc, T (w1 T/P)^2/12, times 1.1;
- every point is stable (a conservative orbit: its multipliers on the unit circle, to the
  stable_margin written beside them).
STIFFNESS_FACTOR (default 1) multiplies k_s in the reference: 1.001 must fail.
Exit status 0 when every check holds, 1 otherwise, 77 without h5py.
"""
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
steps = int(number('steps_per_period'))
tolerance = number('tolerance')
start, end, max_points = number('tip_amplitude'), number('parameter_max'), int(number('max_points'))

failures = []
worst = 0.0
with tempfile.TemporaryDirectory() as work:
    variant = re.sub(r"file\s*=\s*'[^']*'", "file = 'backbone.h5'", text)
    path = os.path.join(work, 'backbone.nml')
    with open(path, 'w') as out:
        out.write(variant)
    result = subprocess.run([vibrobeam, path], cwd=work, capture_output=True, text=True)
    print(result.stdout.strip())
    if result.returncode != 0:
        print(f'FAIL vibrobeam exit {result.returncode}: {result.stderr.strip()}')
        sys.exit(1)
    with h5py.File(os.path.join(work, 'backbone.h5'), 'r') as f:
        branch = f['/periodic/branch']
        name = branch.attrs['parameter']
        name = name.decode() if isinstance(name, bytes) else str(name)
        amplitudes, periods = branch['parameter'][()], branch['period'][()]
        stable, margin = branch['stable'][()], branch['stable_margin'][()]
    with open(os.path.join(work, 'backbone_branch.dat')) as table:
        rows = sum(1 for line in table if line.strip() and not line.startswith('#'))

count = len(amplitudes)
print(f'{count} points, A from {amplitudes[0]:.6e} to {amplitudes[-1]:.6e} m (asked {start:g} to {end:g} m, '
      f'at most {max_points} points)')
if name != 'periodic.tip_amplitude':
    failures.append(f'/periodic/branch parameter is {name!r}, not periodic.tip_amplitude')
if not (2 <= count < max_points):
    failures.append(f'{count} points: not between 2 and max_points = {max_points} (exclusive)')
if count and amplitudes[0] != start:
    failures.append(f'the first point is at A = {amplitudes[0]!r}, not the scene\'s tip_amplitude {start!r}')
if count and amplitudes[-1] != end:
    failures.append(f'the last point is at A = {amplitudes[-1]!r}, not parameter_max = {end!r}')
if any(b <= a for a, b in zip(amplitudes, amplitudes[1:])):
    failures.append('A does not increase point by point')
if rows != count:
    failures.append(f'backbone_branch.dat has {rows} rows for {count} points')
print('A (m), T (s), reference (s), error (s), bound (s), |error|/bound, stable_margin')
for amplitude, period, point_stable, point_margin in zip(amplitudes, periods, stable, margin):
    expected, bound = oscillator.reference(amplitude, steps, tolerance)
    error = period - expected
    worst = max(worst, abs(error) / bound)
    print(f'  {amplitude:.4e}  {period:.12e}  {expected:.12e}  {error:+.3e}  {bound:.3e}  {abs(error) / bound:.3f}'
          f'  {point_margin:.1e}')
    if not abs(error) <= bound:
        failures.append(f'A = {amplitude:g} m: |T - reference| = {abs(error):.3e} s above {bound:.3e} s')
    if point_stable != 1:
        failures.append(f'A = {amplitude:g} m: not stable (a conservative orbit)')
print(f'worst |error|/bound {worst:.3f}')
for failure in failures:
    print('FAIL ' + failure)
print(f'check_backbone: {"ok" if not failures else str(len(failures)) + " failed"}')
sys.exit(1 if failures else 0)
