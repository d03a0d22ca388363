#!/usr/bin/env python3
"""A sweep of periodic analyses against single runs (docs/sweeps.md, "Sweeps of periodic
orbits and branches"): each point of the sweep is the periodic analysis of its scene, run
as one task of the sweep; its point file must hold, bit for bit, what a single run of that
scene (the &sweep group removed, the swept input set to the point's value) writes under
/periodic, and the sweep file's /sweep/statistics/periodic must say what each point file
holds (its branch's points and bifurcations, its first orbit's period, Newton iterations and
largest multiplier modulus, the steps taken: /periodic's attributes first_newton_iterations
and steps_taken).

usage: check_branch_sweep.py VIBROBEAM SCENE.nml WORKDIR [--shift] [--mpi MPIRUN]

SCENE has a &sweep over one input of &load (`parameter = 'load.NAME'`, `values = ...`,
keep_runs = .true.). The sweep runs on 2 threads (with --mpi: on 2 MPI ranks of one thread
each); the single runs on one thread, which changes nothing (the monodromy's columns are the
same bits on any number of threads).
--shift compares point k with the single run of point k + 1 (cyclically): that must find a
difference, so a test of it marked WILL_FAIL shows this check can fail; in that mode every
other failure exits 0 (so the WILL_FAIL test does not pass by accident).
"""
import os
import re
import shutil
import subprocess
import sys

import h5py
import numpy as np


def datasets(group, prefix=''):
    found = {}
    for name, item in group.items():
        if isinstance(item, h5py.Dataset):
            found[prefix + name] = item[()]
        else:
            found.update(datasets(item, prefix + name + '/'))
    return found


def main():
    args = sys.argv[1:]
    vibrobeam, scene, work = os.path.abspath(args[0]), os.path.abspath(args[1]), args[2]
    shift = '--shift' in args
    mpirun = args[args.index('--mpi') + 1] if '--mpi' in args else None
    setup_failure = 0 if shift else 1   # --shift: only the comparison may fail

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    os.chdir(work)
    text = open(scene).read()
    shutil.copy(scene, 'sweep.nml')
    env = dict(os.environ, OMP_NUM_THREADS='2')
    command = [vibrobeam, 'sweep.nml']
    if mpirun:
        env['OMP_NUM_THREADS'] = '1'
        command = [mpirun, '--allow-run-as-root', '--oversubscribe', '-n', '2'] + command
    run = subprocess.run(command, env=env, capture_output=True, text=True)
    if run.returncode != 0:
        print('FAIL: the sweep exited', run.returncode, run.stderr)
        return setup_failure
    stem = re.search(r"file\s*=\s*'([^']+)\.h5'", text.split('&output')[1]).group(1)
    sweep = h5py.File(stem + '.h5', 'r')
    name = sweep['/sweep/parameter'].attrs['name']
    name = name.decode() if isinstance(name, bytes) else str(name)
    group, variable = name.split('.')
    values = sweep['/sweep/parameter'][()]
    status = sweep['/sweep/status'][()]
    summary = {k: sweep['/sweep/statistics/periodic/' + k][()] for k in sweep['/sweep/statistics/periodic']}
    if not np.all(status == 0):
        print('FAIL: points not ok:', status)
        return setup_failure
    print(f'sweep of {len(values)} branches in {name}: status {status.tolist()}, '
          f'branch points {summary["branch_points"].astype(int).tolist()}, '
          f'bifurcations {summary["bifurcations"].astype(int).tolist()}')

    failures = 0
    without_sweep = re.sub(r'&sweep\b.*?/\s*\n', '', text, flags=re.S)
    for k, value in enumerate(values):
        single = re.sub(r"(&output\s+file\s*=\s*')[^']+(')", rf"\g<1>single{k + 1}.h5\g<2>", without_sweep)
        block = re.search(rf'&{group}\b.*?/', single, flags=re.S).group(0)
        changed = re.sub(rf'\b{variable}\s*=\s*[^,/\s]+', f'{variable} = {value!r}', block, count=1)
        if changed == block and f'{variable} = {value!r}' not in block:
            print(f'FAIL: cannot set {name} in &{group}')
            return setup_failure
        single = single.replace(block, changed)
        open(f'single{k + 1}.nml', 'w').write(single)
        run = subprocess.run([vibrobeam, f'single{k + 1}.nml'], env=dict(os.environ, OMP_NUM_THREADS='1'),
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(f'FAIL: single run {k + 1} exited', run.returncode, run.stderr)
            return setup_failure

    for k in range(len(values)):
        other = (k + 1) % len(values) if shift else k
        point_group = h5py.File(f'{stem}_point{k + 1:04d}.h5', 'r')['/periodic']
        single_group = h5py.File(f'single{other + 1}.h5', 'r')['/periodic']
        point, single = datasets(point_group), datasets(single_group)
        for key, value in point_group.attrs.items():   # the attributes of /periodic too
            point['@' + key] = np.asarray(value)
        for key, value in single_group.attrs.items():
            single['@' + key] = np.asarray(value)
        differing = sorted(key for key in set(point) | set(single)
                           if key not in point or key not in single
                           or point[key].shape != single[key].shape
                           or not np.array_equal(point[key], single[key]))
        if differing:
            print(f'FAIL: point {k + 1} ({name} = {values[k]}) differs from the single run of {values[other]} in',
                  ', '.join(differing))
            failures += 1
        else:
            print(f'point {k + 1} ({name} = {values[k]}): its /periodic equals the single run\'s, '
                  f'{len(point)} datasets and attributes, bit for bit')
        if shift:
            continue
        branch = point
        attributes = h5py.File(f'{stem}_point{k + 1:04d}.h5', 'r')['/periodic'].attrs
        bifurcations = len(branch['branch/bifurcations/kind']) if 'branch/bifurcations/kind' in branch else 0
        first_multiplier = branch['branch/floquet_multipliers'][0, 0]
        expected = {'branch_points': len(branch['branch/parameter']), 'bifurcations': bifurcations,
                    'period': branch['branch/period'][0], 'newton_iterations': attributes['first_newton_iterations'],
                    'steps': attributes['steps_taken'],
                    'largest_multiplier': np.hypot(first_multiplier[0], first_multiplier[1])}
        for key, value in expected.items():
            # hypot of the same two numbers in Fortran and numpy: within 1 ulp (C99 hypot is
            # correctly rounded to < 1 ulp); every other entry is copied, exactly
            tolerance = 2 * np.spacing(value) if key == 'largest_multiplier' else 0
            if abs(summary[key][k] - value) > tolerance:
                print(f'FAIL: /sweep/statistics/periodic/{key}[{k}] = {summary[key][k]!r}, its point file says '
                      f'{value!r}')
                failures += 1
    if shift:
        return 1 if failures else 0
    print('PASS' if failures == 0 else f'{failures} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
