#!/usr/bin/env python3
"""The statistics of the observation points of a beam of two planes (docs/statistics.md, "At
each observation point"; docs/output.md: /statistics/points/<name> and <name>_error of
shape (1 + points, 2), y then z; the sweep file's /sweep/statistics/points/<name>
(sweep points, 1 + points, 2); STEM_sweep.dat with the tip's z columns after the planar
ones).

usage: check_planes_statistics.py VIBROBEAM

1. A forced cantilever with two observation points, free of obstacles, runs planar, then
   with &beam planes = 2 and its load and initial velocity along y (direction 0) and along
   z (direction 90): directions that are multiples of 90 degrees are exact (docs/input.md,
   "&beam"), so the plane that carries the motion equals the planar statistics and their
   standard errors bit for bit and the other holds exact zeros; along y every other
   statistic of the run equals the planar one bit for bit too.
2. The same beam loaded along 30 degrees moves in both planes: every points statistic and
   its standard error, in y and in z, is recomputed here from the histories the run writes
   at every step (/time, /tip, /points) with the window and the batch rule of
   docs/statistics.md, independently of vibrobeam's accumulators. min and max are sampled
   values: equal exactly. A mean or an RMS sums K terms in another order than numpy: each
   sum is within (K - 1) u sum|x_n| of the exact one (u = 2^-53, any order), so
   |mean - reference| <= 2 K u mean|x| and |rms - reference| <= 2 K u rms (the square root
   halves a relative error, the squares and the division add 2 u); a standard error
   differences block values x_b (L samples each) within 2 L u max|x_b| each, so its bound
   is 4 L u max|x_b|.
3. A sweep of two load frequencies, planar and with planes = 2 along y and along z: the
   plane of the motion equals the planar sweep's statistics bit for bit, the other is 0;
   STEM_sweep.dat keeps the planar columns in their places (along y: equal to the planar
   file's) and ends with the tip's z columns (along z: equal to the planar tip columns).
Exit status 0 when every check holds, 1 otherwise (one line per failure), 77 without h5py.
"""
import math
import os
import sys
import tempfile

try:
    import numpy as np
    import h5py
except ImportError:
    print('SKIP: no python3 with h5py (Debian package python3-h5py)')
    sys.exit(77)

from planes_scene import check, failures, run as run_scene

SWEEP = "&sweep parameter = 'load.point_frequency', values = 250, 300, settle = 0.004, measure = 0.006 /"
NAMES = [f'{kind}_{stat}' for kind in ['displacement', 'velocity'] for stat in ['mean', 'rms', 'min', 'max']]
MEASURE_FROM = 0.0051   # not a multiple of dt: the window starts at the next step
UNIT = 2.0**-53


def run(vibrobeam, folder, name, planes='', direction='', sweep=''):
    output = f", text = {'.true.' if sweep else '.false.'}, every = 1, measure_from = {MEASURE_FROM}"
    return h5py.File(run_scene(vibrobeam, folder, name, planes, direction, output, sweep), 'r')


def statistics(result, prefix='statistics'):
    """Every dataset under /<prefix>, by its path below it."""
    found = {}

    def take(path, item):
        if isinstance(item, h5py.Dataset):
            found[path] = item[...]

    result[prefix].visititems(take)
    return found


def read_sweep_text(name):
    with open(name) as handle:
        rows = [[float(x) for x in line.split()] for line in handle if line.strip() and not line.startswith('#')]
    return np.array(rows)


def planes_against_planar(vibrobeam, folder):
    planar_file = run(vibrobeam, folder, 'planar')
    planar = statistics(planar_file)
    observation = planar['points/x'].size
    check('the planar run has the tip and 2 observation points, moving',
          observation == 3 and np.abs(planar['points/displacement_rms']).min() > 0)
    for name, direction, carrier in [('along_y', ', direction = 0', 0), ('along_z', ', direction = 90', 1)]:
        turned = statistics(run(vibrobeam, folder, name, ', planes = 2', direction))
        for statistic in NAMES:
            for path in [f'points/{statistic}', f'points/{statistic}_error']:
                values = turned[path]
                check(f'{name}: /statistics/{path} has the shape (3, 2)', values.shape == (observation, 2))
                if values.shape != (observation, 2):
                    continue
                check(f'{name}: /statistics/{path} in the plane of the motion equals the planar run bit for bit',
                      np.array_equal(values[:, carrier], planar[path]))
                check(f'{name}: /statistics/{path} in the other plane is exactly 0', not np.any(values[:, 1 - carrier]))
        if carrier == 0:
            others = [path for path in planar if not path.startswith('points/')]
            same = [path for path in others if path in turned and np.array_equal(turned[path], planar[path])]
            check(f'{name}: the {len(others)} other statistics equal the planar run\'s bit for bit '
                  f'(differ: {sorted(set(others) - set(same))})', len(same) == len(others))


def window_statistics(values, first_step):
    """Value and standard error of each points statistic of the history `values` (rows:
    steps 0 .. N) over the samples first_step + 1 .. N, and their round-off bounds."""
    samples = values[first_step + 1:]
    count = samples.shape[0]
    length = 1
    while count // (2 * length) >= 8:
        length *= 2
    batches = count // length

    def four(x):
        return [x.mean(axis=0), np.sqrt((x**2).mean(axis=0)), x.min(axis=0), x.max(axis=0)]

    def bounds(x, n):
        return [2 * n * UNIT * np.abs(x).mean(axis=0), 2 * n * UNIT * np.sqrt((x**2).mean(axis=0)),
                np.zeros_like(x[0]), np.zeros_like(x[0])]

    whole = four(samples)
    whole_bound = bounds(samples, count)
    blocks = [four(samples[b * length:(b + 1) * length]) for b in range(batches)]
    errors, error_bounds = [], []
    for j in range(4):
        block_values = np.array([block[j] for block in blocks])
        spread = ((block_values - block_values.mean(axis=0))**2).sum(axis=0)
        errors.append(np.sqrt(spread / (batches * (batches - 1))) if batches > 1 else np.zeros_like(whole[j]))
        error_bounds.append(4 * length * UNIT * np.abs(block_values).max(axis=0) + 4 * UNIT * errors[-1])
    return whole, whole_bound, errors, error_bounds, count


def two_planes_recomputed(vibrobeam, folder):
    result = run(vibrobeam, folder, 'along_30', ', planes = 2', ', direction = 30')
    time = result['time'][...]
    dt = time[1] - time[0]
    steps = time.size - 1
    first_step = max(0, math.ceil(MEASURE_FROM / dt - 1e-9))
    check(f'along_30: a history row at every step (N = {steps}), the window from step {first_step} '
          f'(attribute window_steps {result["statistics"].attrs["window_steps"]})',
          np.allclose(time, np.arange(steps + 1) * dt, rtol=0, atol=1e-12 * time[-1]) and
          result['statistics'].attrs['window_steps'] == steps - first_step)
    for kind in ['displacement', 'velocity']:
        # (steps, 1 + points, 2): the tip first, as /statistics/points/x
        history = np.concatenate([result[f'tip/{kind}'][...][:, None, :], result[f'points/{kind}'][...]], axis=1)
        values, value_bounds, errors, error_bounds, count = window_statistics(history, first_step)
        rms = values[1]
        check(f'along_30: {kind} moves in both planes (RMS z/y at the tip {rms[0, 1] / rms[0, 0]:.6f}, '
              f'tan 30 deg = {math.tan(math.radians(30)):.6f})', np.all(rms[:, 1] > 0.1 * rms[:, 0]))
        for j, stat in enumerate(['mean', 'rms', 'min', 'max']):
            for suffix, reference, bound in [('', values[j], value_bounds[j]), ('_error', errors[j], error_bounds[j])]:
                written = result[f'statistics/points/{kind}_{stat}{suffix}'][...]
                if written.shape != reference.shape:
                    check(f'along_30: /statistics/points/{kind}_{stat}{suffix} has the shape {reference.shape}', False)
                    continue
                deviation = np.abs(written - reference)
                check(f'along_30: {kind}_{stat}{suffix} (y and z) recomputed from the histories over {count} '
                      f'samples: largest deviation {deviation.max():.3e}, bound {bound.min():.3e} .. {bound.max():.3e}',
                      np.all(deviation <= bound))


def sweeps(vibrobeam, folder):
    planar = statistics(run(vibrobeam, folder, 'sweep_planar', sweep=SWEEP), 'sweep/statistics')
    planar_text = read_sweep_text(os.path.join(folder, 'sweep_planar_sweep.dat'))
    check('the planar sweep has 2 points of 3 observation points', planar['points/displacement_rms'].shape == (2, 3))
    for name, direction, carrier in [('sweep_y', ', direction = 0', 0), ('sweep_z', ', direction = 90', 1)]:
        turned = statistics(run(vibrobeam, folder, name, ', planes = 2', direction, SWEEP), 'sweep/statistics')
        for statistic in NAMES:
            for path in [f'points/{statistic}', f'points/{statistic}_error']:
                values = turned[path]
                shape = planar[path].shape + (2,)
                check(f'{name}: /sweep/statistics/{path} has the shape {shape}', values.shape == shape)
                if values.shape != shape:
                    continue
                check(f'{name}: /sweep/statistics/{path} in the plane of the motion equals the planar sweep bit '
                      f'for bit', np.array_equal(values[..., carrier], planar[path]))
                check(f'{name}: /sweep/statistics/{path} in the other plane is exactly 0',
                      not np.any(values[..., 1 - carrier]))
        text = read_sweep_text(os.path.join(folder, f'{name}_sweep.dat'))
        columns = planar_text.shape[1]
        check(f'{name}: {name}_sweep.dat has the planar {columns} columns and 4 in z',
              text.shape == (planar_text.shape[0], columns + 4))
        if text.shape != (planar_text.shape[0], columns + 4):
            continue
        tip = slice(8, 12)   # columns 9 .. 12: RMS and largest tip displacement with their errors
        if carrier == 0:
            check(f'{name}: {name}_sweep.dat, the planar columns equal the planar sweep\'s',
                  np.array_equal(text[:, :columns], planar_text))
            check(f'{name}: {name}_sweep.dat, the z columns are 0', not np.any(text[:, columns:]))
        else:
            check(f'{name}: {name}_sweep.dat, the z columns equal the planar tip columns',
                  np.array_equal(text[:, columns:], planar_text[:, tip]))
            check(f'{name}: {name}_sweep.dat, the tip y columns are 0', not np.any(text[:, tip]))


def main():
    vibrobeam = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        planes_against_planar(vibrobeam, folder)
        two_planes_recomputed(vibrobeam, folder)
        sweeps(vibrobeam, folder)
    print(f'check_planes_statistics: {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
