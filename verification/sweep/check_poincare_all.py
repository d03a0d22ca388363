#!/usr/bin/env python3
"""Every Poincare sample of a sweep's points (&sweep poincare_samples = 'all', docs/sweeps.md
"The sweep file"), checked against what the points' own result files hold.

usage: check_poincare_all.py VIBROBEAM

A small sweep of the forced rattling beam (3 frequencies, windows of 270 forcing periods,
more than the 256 samples 'latest' keeps) runs
 1. independent, on 2 threads, with 'all' and keep_runs: for every point, /sweep/poincare
    holds exactly (bit for bit, time, u and v at the tip and at an observation point) the
    samples of its point file's /statistics/poincare, and their count is
    /sweep/poincare_samples;
 2. 'up' with steady_tolerance (window after window) with 'all' and without keep_runs, on
    1 and on 2 threads: the same samples as that sweep with keep_runs (whose point files
    hold the reported window), so the samples of the earlier windows are left out, and the
    same sweep file whatever the threads;
 3. 'latest' (the default): the last 256 samples of each point of the 'all' sweep.
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

SCENE = """
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9, rayleigh_mass = 1.8109, rayleigh_stiffness = 6.5532e-6 /
&mesh      elements = 8 /
&obstacles count = 2,
           side(1) = 'below', x_from(1) = 0.5, level_from(1) = -0.5e-3,
           side(2) = 'above', x_from(2) = 0.5, level_from(2) =  0.5e-3 /
&impact    restitution = 0.7 /
&time      dt = 1e-4 /
&load      point_force = 2.0, point_position = 0.5, point_frequency = 200.0 /
&output    file = '{name}.h5', points = 0.25, text = .false. /
&sweep     parameter = 'load.point_frequency', values = 150, 276, 320, mode = '{mode}',
           settle_periods = 20, measure_periods = 270 {extra} /
"""
STEADY = ", steady_tolerance = 0.2"


def run(vibrobeam, work, name, mode, extra, threads, failures):
    with open(os.path.join(work, name + '.nml'), 'w') as handle:
        handle.write(SCENE.format(name=name, mode=mode, extra=extra))
    environment = dict(os.environ, OMP_NUM_THREADS=str(threads))
    done = subprocess.run([vibrobeam, name + '.nml'], cwd=work, capture_output=True, text=True, timeout=300,
                          env=environment)
    if done.returncode != 0:
        failures.append(f'vibrobeam {name}.nml exits {done.returncode}: {done.stderr}')
        return None
    return os.path.join(work, name + '.h5')


def samples(sweep, k):
    """time, u and v of point k's rows of /sweep/poincare."""
    rows = sweep['/sweep/poincare/point'][:] == k
    return (sweep['/sweep/poincare/time'][rows], sweep['/sweep/poincare/displacement'][rows],
            sweep['/sweep/poincare/velocity'][rows])


def same(a, b):
    return all(x.shape == y.shape and x.tobytes() == y.tobytes() for x, y in zip(a, b))


def main():
    vibrobeam = os.path.abspath(sys.argv[1])
    failures = []
    with tempfile.TemporaryDirectory() as work:
        files = {}
        for name, mode, extra, threads in [('all_files', 'independent', ", poincare_samples = 'all', keep_runs = .true.", 2),
                                           ('latest', 'independent', '', 2),
                                           ('steady_files', 'up', STEADY + ", poincare_samples = 'all', keep_runs = .true.",
                                            1),
                                           ('steady_1', 'up', STEADY + ", poincare_samples = 'all'", 1),
                                           ('steady_2', 'up', STEADY + ", poincare_samples = 'all'", 2)]:
            files[name] = run(vibrobeam, work, name, mode, extra, threads, failures)
        if failures:
            print('\n'.join('FAIL: ' + failure for failure in failures))
            return 1
        counted = 0
        with h5py.File(files['all_files'], 'r') as sweep, h5py.File(files['latest'], 'r') as latest:
            window = sweep['/sweep/poincare_samples'][:]
            for k in (1, 2, 3):
                with h5py.File(os.path.join(work, f'all_files_point{k:04d}.h5'), 'r') as point:
                    own = (point['/statistics/poincare/time'][:], point['/statistics/poincare/displacement'][:],
                           point['/statistics/poincare/velocity'][:])
                kept = samples(sweep, k)
                counted += kept[0].size
                if not same(kept, own):
                    failures.append(f'independent, point {k}: /sweep/poincare holds {kept[0].size} samples, not the '
                                    f'{own[0].size} of its point file')
                if kept[0].size != window[k - 1] or kept[0].size <= 256:
                    failures.append(f'independent, point {k}: {kept[0].size} samples, /sweep/poincare_samples says '
                                    f'{window[k - 1]} (and more than 256 are wanted here)')
                if not same(samples(latest, k), tuple(x[-256:] for x in kept)):
                    failures.append(f"'latest', point {k}: not the last 256 samples of the point's window")
        with h5py.File(files['steady_files'], 'r') as reference, h5py.File(files['steady_1'], 'r') as one, \
                h5py.File(files['steady_2'], 'r') as two:
            # transient = settle + (windows - 1) window: at least 2 windows at every point, so
            # that the samples of earlier windows are there to be left out
            if np.any(reference['/sweep/transient'][:] < reference['/sweep/window'][:]):
                failures.append('steady_tolerance: every point should measure window after window')
            for k in (1, 2, 3):
                with h5py.File(os.path.join(work, f'steady_files_point{k:04d}.h5'), 'r') as point:
                    own = (point['/statistics/poincare/time'][:], point['/statistics/poincare/displacement'][:],
                           point['/statistics/poincare/velocity'][:])
                if not same(samples(reference, k), own) or not same(samples(one, k), own):
                    failures.append(f'steady_tolerance, point {k}: the samples are not those of the reported window '
                                    f'({samples(one, k)[0].size} kept, {own[0].size} in its point file)')
                counted += own[0].size
            for path in ('/sweep/poincare/time', '/sweep/poincare/displacement', '/sweep/poincare/velocity',
                         '/sweep/poincare/point', '/sweep/poincare_samples'):
                if one[path][:].tobytes() != two[path][:].tobytes():
                    failures.append(f'{path}: differs between 1 and 2 threads')
    for failure in failures:
        print('FAIL: ' + failure)
    print(f'check_poincare_all: {counted} samples compared, {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
