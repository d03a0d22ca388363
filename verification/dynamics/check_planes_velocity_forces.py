#!/usr/bin/env python3
"""The velocity-dependent forces on the modes of a beam of two planes, against the planar
runs of the same beam, where each is verified against closed forms elsewhere:
- 'modal': damping per mode (&beam modal_damping, modal_damping_ratios; docs/method.md,
  "Damping per mode"; verification.modal_damping*), ratios given for the first two modes
  and 1 % for the rest;
- 'flow': the fluid-elastic force of a cross-flow (&flow; docs/theory.md section 10;
  verification.flow_connors), U = 1.5 m/s over the outer 0.3 m on the 3 lowest modes,
  above the critical velocity of mode 1 (the tip's obstacle-free motion grows).

usage: check_planes_velocity_forces.py VIBROBEAM modal|flow

A cantilever with Rayleigh damping, a point force at the tip and an initial velocity in
mode 1, free of obstacles, with that force:
- planes = 2 with the load and the initial velocity along y (direction 0) and along z
  (direction 90, exact): the plane of the data equals the planar run bit for bit (tip and
  energy histories), the other is exactly 0;
- the z plane with a stiffness of its own (inertia_z = 2.5 inertia, so its own modes):
  along z it equals the planar run of a beam whose inertia is that inertia_z, along y the
  planar run of the beam itself; each plane is damped on its own modes.
Made to fail: taking the y plane's modes for the z plane of its own stiffness fails the
third case (both forces).
Exit status 0 when every check holds, 1 otherwise (one line per failure), 77 without h5py.
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

INERTIA = 2.7642255353230253e-09
FORCES = {'modal': ('modal_damping = 0.01, modal_damping_ratios = 0.02, 0.05', ''),
          'flow': ('rayleigh_mass = 4, rayleigh_stiffness = 2e-6',
                   '&flow velocity = 1.5, x_from = 0.2, modes = 3 /'),
          'none': ('rayleigh_mass = 4, rayleigh_stiffness = 2e-6', '')}
SCENE = """
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 6.938018879893839e-05,
           inertia = {inertia!r}, {beam} {planes} /
{flow}
&mesh      elements = 8 /
&time      t_end = 0.03, dt = 2e-5 /
&load      point_force = 5.0, point_frequency = 300.0 {direction} /
&initial   velocity = 'mode', velocity_mode = 1, velocity_amplitude = 0.3 {direction} /
&output    file = '{name}.h5', text = .false. /
"""
PATHS = ['tip/displacement', 'tip/velocity']
failures = []


def check(what, holds):
    print(('ok   ' if holds else 'FAIL ') + what)
    if not holds:
        failures.append(what)


def run(vibrobeam, folder, name, inertia=INERTIA, planes='', direction='', force=None):
    beam, flow = FORCES[force or KIND]
    with open(os.path.join(folder, name + '.nml'), 'w') as handle:
        handle.write(SCENE.format(inertia=inertia, planes=planes, direction=direction, name=name, beam=beam,
                                  flow=flow))
    done = subprocess.run([vibrobeam, name + '.nml'], cwd=folder, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        sys.exit(f'vibrobeam {name}.nml exited {done.returncode}: {done.stderr}')
    with h5py.File(os.path.join(folder, name + '.h5'), 'r') as result:
        return {path: result[path][...] for path in PATHS + ['energy/total', 'energy/dissipated_damping',
                                                              'energy/work']}


def compare(name, turned, planar, carrier):
    for path in PATHS:
        values = turned[path]
        check(f'{name}: /{path} has the shape (outputs, 2)', values.shape == planar[path].shape + (2,))
        if values.shape != planar[path].shape + (2,):
            continue
        check(f'{name}: /{path} in the plane of the data equals the planar run bit for bit',
              np.array_equal(values[..., carrier], planar[path]))
        check(f'{name}: /{path} in the other plane is exactly 0', not np.any(values[..., 1 - carrier]))
    for path in ['energy/total', 'energy/dissipated_damping', 'energy/work']:
        check(f'{name}: /{path} equals the planar run bit for bit', np.array_equal(turned[path], planar[path]))


KIND = 'modal'


def main():
    global KIND
    vibrobeam, KIND = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as folder:
        planar = run(vibrobeam, folder, 'planar')
        stiff = run(vibrobeam, folder, 'planar_stiff', inertia=2.5 * INERTIA)
        check('the planar runs move', np.abs(planar['tip/displacement']).max() > 0)
        if KIND == 'modal':
            check('the damping per mode takes energy', planar['energy/dissipated_damping'][-1] > 0)
        else:   # without the flow the same beam moves otherwise (the force acts)
            still = run(vibrobeam, folder, 'planar_still', force='none')
            check('the flow changes the motion (its force acts)',
                  not np.array_equal(planar['tip/displacement'], still['tip/displacement']))
        check('the stiffer beam is another motion',
              not np.array_equal(planar['tip/displacement'], stiff['tip/displacement']))
        for name, direction, carrier in [('along_y', ', direction = 0', 0), ('along_z', ', direction = 90', 1)]:
            compare(name, run(vibrobeam, folder, name, planes=', planes = 2', direction=direction), planar, carrier)
        own = f', planes = 2, inertia_z = {2.5 * INERTIA!r}'
        compare('own z stiffness, along y', run(vibrobeam, folder, 'own_y', planes=own, direction=', direction = 0'),
                planar, 0)
        compare('own z stiffness, along z', run(vibrobeam, folder, 'own_z', planes=own, direction=', direction = 90'),
                stiff, 1)
    if failures:
        print(f'{len(failures)} check(s) failed')
        return 1
    print('every check holds')
    return 0


if __name__ == '__main__':
    sys.exit(main())
