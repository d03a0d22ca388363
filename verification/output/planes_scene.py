"""What the two-plane output checks share (check_planes_points.py,
check_planes_statistics.py): their scene, a forced cantilever with two observation points
and no obstacle, run planar or with &beam planes = 2 and its load and initial velocity
along a `direction`; and the record of their checks.
"""
import os
import subprocess
import sys

SCENE = """
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 6.938018879893839e-05,
           inertia = 2.7642255353230253e-09, rayleigh_mass = 7.9193, rayleigh_stiffness = 5.9941e-06 {planes} /
&mesh      elements = 8 /
&time      t_end = 0.02, dt = 2e-5 /
&load      point_force = 5.0, point_frequency = 300.0 {direction} /
&initial   velocity = 'mode', velocity_mode = 1, velocity_amplitude = 0.3 {direction} /
&output    file = '{name}.h5', points = 0.2, 0.35 {output} /
{sweep}
"""
failures = []


def check(what, holds):
    """Print the check and its outcome; a failure is kept in `failures`."""
    print(('ok   ' if holds else 'FAIL ') + what)
    if not holds:
        failures.append(what)


def run(vibrobeam, folder, name, planes='', direction='', output='', sweep=''):
    """Run the scene as folder/name.nml (`planes`, `direction`, `output`: text added to
    &beam, to &load and &initial, to &output; `sweep`: a &sweep group); the result file's path."""
    with open(os.path.join(folder, name + '.nml'), 'w') as handle:
        handle.write(SCENE.format(planes=planes, direction=direction, name=name, output=output, sweep=sweep))
    done = subprocess.run([vibrobeam, name + '.nml'], cwd=folder, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        sys.exit(f'vibrobeam {name}.nml exited {done.returncode}: {done.stderr}')
    return os.path.join(folder, name + '.h5')
