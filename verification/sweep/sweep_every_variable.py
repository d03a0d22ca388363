#!/usr/bin/env python3
"""Every real input of the schema can be swept (docs/sweeps.md, "The parameter").

usage: sweep_every_variable.py VIBROBEAM LIST_INPUT_VARIABLES

The variables come from the schema itself (`list_input_variables` prints the table every
reader, check and listing is derived from), so a new real variable is swept here without
editing this file. Each real variable (each element of an array, up to the obstacles or
points the scene gives) is swept over two values in a small scene with `keep_runs`, and
each point's resolved input, the root attribute `group.variable(i)` of its point file
(docs/output.md, "Attributes"), must hold the value swept, bit for bit; so must
/sweep/parameter of the sweep file. The two values: the scene's own (its root attribute
from a plain run) and 0.95 times it (1.05 times when that leaves the variable's range;
1e-6 when the scene's value is 0). The scene is built so that such a change keeps every
point valid and the contact points in place (obstacle ends between nodes, observation
points inside the shorter beam).

A variable whose sweep a documented rule refuses must be refused, exit 2 and nothing
written, with the message naming the rule (EXPECTED: a rule text instead of None). Where
a rule between inputs refuses the sweep in the first scene, the variable is also swept
in the second scene, where the rule does not apply, and must pass there: k2 (the first
scene's beam is given by E, rho, S, I), base_amplitude (the first scene gives
base_acceleration), the damping of obstacle 1 (a rigid stop in the first scene); and the
reduction's cut-off (in rad/s and its twin in Hz) is swept in the reduced second scene.
Every frequency's twin in Hz (docs/input.md, "Frequencies in Hz") is a real variable of the
table, swept like the others: each point must record the value swept in Hz. The variables
of the structures (supports, springs, masses, damping per mode) are swept in the third
scene, those of &sections and the axial force in the fourth (the last section's end,
which must stay L, is refused).
Exit status 0 when every check holds, 1 otherwise (one line per failure), 77 without h5py.
"""
import concurrent.futures
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

# The first scene: a steel cantilever of 4 elements (h = 0.125 m), a rigid stop below and a
# compliant one above, both along [0.3, 0.45] m (ends between nodes: 0.95 x either end
# covers the same node 0.375 m), harmonic loads of every kind with a frequency, and two
# loads of &forces: a random distributed one with a spatial coherence (its band far enough
# from 0 Hz for a short filter) and a harmonic point force; a cross-flow over part of it.
SCENE_A = """
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9, rayleigh_mass = 3.0, rayleigh_stiffness = 1e-6 /
&mesh      elements = 4 /
&obstacles count = 2,
           side(1) = 'below', x_from(1) = 0.3, x_to(1) = 0.45, level_from(1) = -1e-3, level_to(1) = -1.2e-3,
           side(2) = 'above', x_from(2) = 0.3, x_to(2) = 0.45, level_from(2) = 1e-3, level_to(2) = 1.2e-3,
           stiffness(2) = 1e6, exponent(2) = 1.5, damping(2) = 0.1 /
&impact    restitution = 0.7 /
&time      dt = 2e-5 @TIME@ /
&initial   displacement = 'mode', displacement_mode = 1, displacement_amplitude = 1e-4,
           velocity = 'mode', velocity_mode = 1, velocity_amplitude = 1e-3 /
&load      point_force = 20.0, point_frequency = 300, base_acceleration = 2.0, base_frequency = 200,
           distributed = 1.0, distributed_frequency = 100, distributed_phase = 0.5 /
&forces    count = 2,
           kind(1) = 'distributed', x_from(1) = 0.1, x_to(1) = 0.45, signal(1) = 'random', psd_level(1) = 0.5,
           band_from(1) = 50.0, band_to(1) = 5000.0, correlation_length(1) = 0.05,
           position(2) = 0.4, amplitude(2) = 3.0, frequency(2) = 250.0, phase(2) = 0.3 /
&flow      velocity = 0.2, density = 1000, diameter = 0.02, x_to = 0.45, connors_constant = 3.0 /
&output    file = 'scene.h5', points = 0.25, 0.4, text = .false., episode_gap = 1e-3 @OUTPUT@ /
"""
# The second scene: the beam given by k2 (rho S = 1), a reduced model, both stops compliant.
SCENE_B = """
&beam      length = 0.5, k2 = 222.9 /
&mesh      elements = 4, reduction = 'craig-bampton', reduction_frequency = 1e5 /
&obstacles count = 2,
           side(1) = 'below', x_from(1) = 0.3, x_to(1) = 0.45, level_from(1) = -1e-3,
           stiffness(1) = 1e3, damping(1) = 0.2,
           side(2) = 'above', x_from(2) = 0.3, x_to(2) = 0.45, level_from(2) = 1e-3,
           stiffness(2) = 1e3, damping(2) = 0.1 /
&time      dt = 2e-5 @TIME@ /
&load      point_force = 0.1, point_frequency = 300, base_frequency = 200 /
&output    file = 'scene.h5', points = 0.25, text = .false. @OUTPUT@ /
"""
# The third scene: the structures of issue 18 (end supports and springs, an intermediate
# spring support, a point mass with rotary inertia, damping per mode); the support and the
# mass stay nearest their nodes when moved by 5 %.
SCENE_C = """
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9, left_end = 'pinned', left_spring = 1e4, left_rotational_spring = 100.0,
           right_spring = 1e4, right_rotational_spring = 10.0, modal_damping = 0.01,
           modal_damping_ratios(1) = 0.02 /
&mesh      elements = 4 /
&supports  count = 1, x(1) = 0.26, kind(1) = 'spring', stiffness(1) = 1e4, rotational_stiffness(1) = 5.0 /
&masses    count = 1, x(1) = 0.4, mass(1) = 0.05, rotary_inertia(1) = 1e-6 /
&obstacles count = 1, side(1) = 'below', x_from(1) = 0.3, x_to(1) = 0.45, level_from(1) = -1e-3 /
&time      dt = 2e-5 @TIME@ /
&load      base_acceleration = 2.0, base_frequency = 200 /
&output    file = 'scene.h5', text = .false. @OUTPUT@ /
"""
# The fourth scene: a beam of two sections under an axial force (issue 18, items 4 and 5),
# pinned at both ends; the first section's end stays nearest its node when moved by 5 %.
SCENE_D = """
&beam      length = 0.5, left_end = 'pinned', right_end = 'pinned', axial_force = 500.0 /
&mesh      elements = 4 /
&sections  count = 2, x_to(1) = 0.26, youngs_modulus(1) = 210e9, density(1) = 7850, area(1) = 2e-4,
           inertia(1) = 1.6666666666666667e-9, x_to(2) = 0.5, youngs_modulus(2) = 70e9, density(2) = 2700,
           area(2) = 3e-4, inertia(2) = 2.5e-9 /
&obstacles count = 1, side(1) = 'below', x_from(1) = 0.3, x_to(1) = 0.45, level_from(1) = -1e-3 /
&time      dt = 2e-5 @TIME@ /
&load      base_acceleration = 2.0, base_frequency = 200 /
&output    file = 'scene.h5', text = .false. @OUTPUT@ /
"""
# The fifth scene: a beam of two bending planes in a round hole and a hexagonal one
# (issue 21), with friction, wear and loads turned from y.
SCENE_E = """
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9, inertia_z = 2e-9, planes = 2 /
&mesh      elements = 4 /
&obstacles count = 2, shape(1) = 'circle', x_from(1) = 0.5, radius(1) = 1e-3, center_y(1) = 1e-4,
           center_z(1) = -1e-4, friction(1) = 0.2, wear_coefficient(1) = 1e-14,
           shape(2) = 'polygon', sides(2) = 6, orientation(2) = 10, x_from(2) = 0.25, radius(2) = 1e-3 /
&time      dt = 2e-5 @TIME@ /
&load      point_force = 0.1, point_frequency = 300, direction = 30, point_direction = 60 /
&forces    count = 1, kind(1) = 'distributed', x_from(1) = 0.1, x_to(1) = 0.45, signal(1) = 'random',
           psd_level(1) = 0.5, band_from(1) = 50.0, band_to(1) = 5000.0, direction(1) = 45 /
&output    file = 'scene.h5', text = .false. @OUTPUT@ /
"""
SCENES = {'A': SCENE_A, 'B': SCENE_B, 'C': SCENE_C, 'D': SCENE_D, 'E': SCENE_E}
# (scene, None: the sweep runs, or the text of the rule that refuses it); every other real
# variable: [(the first scene that gives it, None)]. The rules: docs/sweeps.md, "The parameter"; docs/input.md.
EXPECTED = {
    'time.t_end': [('A', 'is set by the sweep itself')],
    'output.measure_from': [('A', 'is set by the sweep itself')],
    'output.checkpoint_seconds': [('A', 'is wall-clock time')],
    'beam.k2': [('A', 'youngs_modulus, density, area and inertia are given, so k2 = EI/(rho S)'), ('B', None)],
    'load.base_amplitude': [('A', 'are both given: give one of them'), ('B', None)],
    'obstacles.damping(1)': [('A', 'contact damping needs a compliant stop'), ('B', None)],
    'mesh.reduction_frequency': [('B', None)],
    'mesh.reduction_frequency_hz': [('B', None)],
    # swept over whole numbers it is an ensemble (verification.random_point_force)
    'forces.realisation': [('A', 'is not a whole number')],
    'periodic.tolerance': [('A', "belongs to &periodic, the settings of the periodic analysis itself")],
    'periodic.step': [('A', "belongs to &periodic, the settings of the periodic analysis itself")],
    'periodic.parameter_min': [('A', "belongs to &periodic, the settings of the periodic analysis itself")],
    'periodic.parameter_max': [('A', "belongs to &periodic, the settings of the periodic analysis itself")],
    'periodic.period': [('A', "belongs to &periodic, the settings of the periodic analysis itself")],
    'periodic.tip_amplitude': [('A', "belongs to &periodic, the settings of the periodic analysis itself")],
    # a second moment for bending in z and the directions need two bending planes (issue 21;
    # docs/input.md, "&beam"): refused in the planar scene A, swept in scene E
    'beam.inertia_z': [('A', 'is given with planes = 1'), ('E', None)],
    'load.direction': [('A', 'is given with &beam planes = 1'), ('E', None)],
    'load.point_direction': [('A', 'is given with &beam planes = 1'),
                             ('E', None)],
    'obstacles.radius(1)': [('E', None)],
    'obstacles.center_y(1)': [('E', None)],
    'obstacles.center_z(1)': [('E', None)],
    'obstacles.friction(1)': [('E', None)],
    'obstacles.wear_coefficient(1)': [('E', None)],
    'obstacles.radius(2)': [('E', None)],
    'forces.direction(1)': [('E', None)],
    'obstacles.orientation(2)': [('E', None)],
    'initial.direction': [('A', 'is given with &beam planes = 1')],
    'initial.displacement_direction': [('A', 'is given with &beam planes = 1')],
    # the sections cover the whole beam: the last one ends at L
    'sections.x_to(2)': [('D', 'the last section must end at the end of the beam')],
}
SWEEP = ("&sweep parameter = '{name}', values = {v1!r}, {v2!r}, mode = 'independent', "
         "settle = 1e-4, measure = 1e-4, keep_runs = .true. /\n")


def run(vibrobeam, folder, text):
    with open(os.path.join(folder, 'scene.nml'), 'w') as handle:
        handle.write(text)
    # one thread each (two sweeps run at a time)
    environment = dict(os.environ, OMP_NUM_THREADS='1')
    done = subprocess.run([vibrobeam, 'scene.nml'], cwd=folder, capture_output=True, text=True, timeout=120,
                          env=environment)
    return done.returncode, done.stderr


def scene_text(key, sweep=''):
    # a plain run of the scene: 2 steps
    time = '' if sweep else ', t_end = 4e-5'
    return SCENES[key].replace('@TIME@', time).replace('@OUTPUT@', '') + sweep


def sweep_one(vibrobeam, work, values, key, name, rule, lowest, highest):
    """Sweep `name` over its value in scene `key` and a second one; the failures."""
    if name not in values and rule is None:
        return [f'{name}: the result file of scene {key} does not record it']
    # (a variable the scene's kind does not list, refused by a rule: its range's upper end)
    v1 = float(values[name]) if name in values else highest
    v2 = 0.95 * v1 if v1 != 0 else 1e-6
    if not lowest <= v2 <= highest:
        v2 = 1.05 * v1
    folder = os.path.join(work, key + '_' + name.replace('(', '_').replace(')', ''))
    os.mkdir(folder)
    status, message = run(vibrobeam, folder, scene_text(key, SWEEP.format(name=name, v1=v1, v2=v2)))
    if rule is not None:
        if status != 2 or rule not in message or os.listdir(folder) != ['scene.nml']:
            return [f'{name} in scene {key}: expected exit 2, nothing written, and the rule "{rule}"; got exit '
                    f'{status}, {sorted(os.listdir(folder))}: {message.strip()}']
        return []
    if status != 0:
        return [f'{name} = {v1!r}, {v2!r} in scene {key}: exit {status}: {message.strip()}']
    failures = []
    with h5py.File(os.path.join(folder, 'scene.h5'), 'r') as sweep:
        parameter = [float(x) for x in sweep['/sweep/parameter'][:]]
        if parameter != [v1, v2]:
            failures.append(f'{name}: /sweep/parameter holds {parameter}, swept {[v1, v2]}')
    for point, value in ((1, v1), (2, v2)):
        with h5py.File(os.path.join(folder, f'scene_point{point:04d}.h5'), 'r') as result:
            held = result['/'].attrs.get(name)
            if held is None or float(held) != value:
                failures.append(f'{name}: point {point} of scene {key} resolves it to {held!r}, swept {value!r}')
    return failures


def main():
    vibrobeam, lister = os.path.abspath(sys.argv[1]), sys.argv[2]
    table = []
    for line in subprocess.run([lister], capture_output=True, text=True, check=True).stdout.splitlines():
        group, name, kind, extent, _, lowest, highest = line.split()
        if kind == 'real' and group != 'sweep':
            table.append((group + '.' + name, int(extent), float(lowest), float(highest)))
    failures = []
    jobs = []
    with tempfile.TemporaryDirectory() as work:
        values = {}
        for key in SCENES:
            folder = os.path.join(work, 'plain' + key)
            os.mkdir(folder)
            status, message = run(vibrobeam, folder, scene_text(key))
            if status != 0:
                print(f'FAIL: the plain run of scene {key} exits {status}: {message}')
                return 1
            with h5py.File(os.path.join(folder, 'scene.h5'), 'r') as result:
                values[key] = {k: v for k, v in result['/'].attrs.items() if not k.endswith('.unit')}
        for variable, extent, lowest, highest in table:
            if extent == 0:
                names = [variable]
            else:
                # every element a scene gives (its obstacles, observation points, supports, ...)
                names = [f'{variable}({i})' for i in range(1, extent + 1)
                         if any(f'{variable}({i})' in values[key] for key in SCENES)]
                if not names:
                    failures.append(f'{variable}: no scene gives an element of it to sweep')
            for name in names:
                first = next((key for key in SCENES if name in values[key]), 'A')
                for key, rule in EXPECTED.get(name, [(first, None)]):
                    jobs.append((vibrobeam, work, values[key], key, name, rule, lowest, highest))
        # two at a time: a sweep of two points spends most of its time syncing its files
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            for found in pool.map(lambda job: sweep_one(*job), jobs):
                failures += found
        swept = len(jobs)
    for failure in failures:
        print('FAIL: ' + failure)
    print(f'sweep_every_variable: {swept} sweeps of {len(table)} real variables, {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
