#!/usr/bin/env python3
"""The statistics and spectra of a beam of two planes (docs/statistics.md, "At each
observation point" and "Dominant response frequencies"; docs/output.md:
/statistics/points/<name> and <name>_error of shape (1 + points, 2) and
/statistics/spectrum/peak_* (3, 2), y then z; /spectrum/tip_amplitude (bins, 2) and
point_amplitude (bins, points, 2); the sweep file's /sweep/statistics/points/<name> and
spectrum/peak_* (sweep points, n, 2); STEM_sweep.dat with the tip's z columns after the
planar ones).

usage: check_planes_statistics.py VIBROBEAM

1. A forced cantilever with two observation points, free of obstacles, runs planar, then
   with &beam planes = 2 and its load and initial velocity along y (direction 0) and along
   z (direction 90): directions that are multiples of 90 degrees are exact (docs/input.md,
   "&beam"), so the plane that carries the motion equals the planar statistics and their
   standard errors, the spectral peaks and the spectra bit for bit and the other holds
   exact zeros (also in STEM_spectrum.dat, whose z columns follow the planar ones); along y
   every other statistic of the run equals the planar one bit for bit.
2. The same beam loaded along 30 degrees moves in both planes: every points statistic and
   its standard error, in y and in z, is recomputed here from the histories the run writes
   at every step (/time, /tip, /points) with the window and the batch rule of
   docs/statistics.md, independently of vibrobeam's accumulators. min and max are sampled
   values: equal exactly. A mean or an RMS sums K terms in another order than numpy: each
   sum is within (K - 1) u sum|x_n| of the exact one (u = 2^-53, any order), so
   |mean - reference| <= 2 K u mean|x| and |rms - reference| <= 2 K u rms (the square root
   halves a relative error, the squares and the division add 2 u); a standard error
   differences block values x_b (L samples each) within 2 L u max|x_b| each, so its bound
   is 4 L u max|x_b|. The tip's spectrum in each plane (/spectrum, every row) and the
   statistics' peaks (the window's samples) are recomputed with numpy's FFT within the
   bound of `amplitude_spectrum` and, for the peaks, that bound carried through the
   parabolic refinement (`refined_peaks`).
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
# the statistics with a value in y and in z: the points' (with standard errors) and the peaks
TWO_PLANES = ([f'points/{name}{suffix}' for name in NAMES for suffix in ['', '_error']] +
              [f'spectrum/peak_{name}' for name in ['frequency', 'amplitude', 'frequency_rad_s']])
MEASURE_FROM = 0.0051   # not a multiple of dt: the window starts at the next step
UNIT = 2.0**-53


def run(vibrobeam, folder, name, planes='', direction='', sweep='', text=False):
    output = f", text = {'.true.' if sweep or text else '.false.'}, every = 1, measure_from = {MEASURE_FROM}"
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


def carrier_and_other(name, where, turned, planar, paths, carrier):
    """Each dataset of `paths` has the planar shape and (y, z) last, the plane of the motion
    (`carrier`) equal to the planar one bit for bit and the other exactly 0."""
    for path in paths:
        values, shape = turned[path], planar[path].shape + (2,)
        check(f'{name}: {where}{path} has the shape {shape}', values.shape == shape)
        if values.shape != shape:
            continue
        check(f'{name}: {where}{path} in the plane of the motion equals the planar one bit for bit',
              np.array_equal(values[..., carrier], planar[path]))
        check(f'{name}: {where}{path} in the other plane is exactly 0', not np.any(values[..., 1 - carrier]))


def planes_against_planar(vibrobeam, folder):
    planar_file = run(vibrobeam, folder, 'planar', text=True)
    planar_text = np.loadtxt(os.path.join(folder, 'planar_spectrum.dat'), comments='#', ndmin=2)
    planar, planar_spectrum = statistics(planar_file), statistics(planar_file, 'spectrum')
    observation = planar['points/x'].size
    check('the planar run has the tip and 2 observation points, moving, with spectral peaks',
          observation == 3 and np.abs(planar['points/displacement_rms']).min() > 0 and
          np.all(planar['spectrum/peak_amplitude'] > 0))
    for name, direction, carrier in [('along_y', ', direction = 0', 0), ('along_z', ', direction = 90', 1)]:
        result = run(vibrobeam, folder, name, ', planes = 2', direction, text=True)
        turned = statistics(result)
        carrier_and_other(name, '/statistics/', turned, planar, TWO_PLANES, carrier)
        carrier_and_other(name, '/spectrum/', statistics(result, 'spectrum'), planar_spectrum,
                          ['tip_amplitude', 'point_amplitude'], carrier)
        # STEM_spectrum.dat: f, tip, f (rad/s), each point's, then the tip's and the points' in z
        table = np.loadtxt(os.path.join(folder, f'{name}_spectrum.dat'), comments='#', ndmin=2)
        columns = planar_text.shape[1]
        amplitudes = [1] + list(range(3, columns))
        check(f'{name}: {name}_spectrum.dat has the planar {columns} columns and {len(amplitudes)} in z',
              table.shape == (planar_text.shape[0], columns + len(amplitudes)))
        if table.shape == (planar_text.shape[0], columns + len(amplitudes)):
            y_part, z_part = table[:, amplitudes], table[:, columns:]
            data, other = (y_part, z_part) if carrier == 0 else (z_part, y_part)
            check(f'{name}: {name}_spectrum.dat, the frequencies and the plane of the motion equal the planar file',
                  np.array_equal(table[:, [0, 2]], planar_text[:, [0, 2]]) and
                  np.array_equal(data, planar_text[:, amplitudes]))
            check(f'{name}: {name}_spectrum.dat, the other plane is 0', not np.any(other))
        if carrier == 0:
            others = [path for path in planar if path not in TWO_PLANES]
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
    two_planes_spectra(result, first_step)
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


def amplitude_spectrum(x):
    """docs/method.md, "Spectra": single-sided, mean removed, periodic Hann window, one
    record; the frequencies in units of the bin width, and the round-off bound of each
    amplitude against another conforming FFT: both transforms within 6 log2(n) u sqrt(n)
    ||w (x - mean)||_2 of the exact one (Higham, "Accuracy and Stability of Numerical
    Algorithms", 2nd ed., Thm. 24.2, with a twiddle error of u), plus the mean's own round-off
    n u mean|x| in each of the n windowed terms, scaled as the amplitudes (c_k / sum w)."""
    n = x.size
    w = 0.5 * (1 - np.cos(2 * np.pi * np.arange(n) / n))
    centred = x - x.mean()
    scale = np.full(n // 2 + 1, 2.0)
    scale[0] = 1.0
    if n % 2 == 0:
        scale[-1] = 1.0
    amplitude = scale * np.abs(np.fft.rfft(w * centred)) / w.sum()
    bound = scale / w.sum() * (2 * 6 * math.ceil(math.log2(n)) * UNIT * math.sqrt(n) * np.linalg.norm(w * centred) +
                               w.sum() * n * UNIT * np.abs(x).mean())
    return amplitude, bound


def refined_peaks(amplitude, bound, count=3):
    """docs/statistics.md, "Dominant response frequencies": the `count` local maxima with
    the largest bin amplitudes, refined by a parabola (in bins from bin 0), each with the
    bound of its refined frequency (bins) and amplitude propagated from the amplitudes'
    (`bound`) through the partial derivatives of the refinement, doubled for its own
    rounding."""
    n = amplitude.size
    candidates = [i for i in range(1, n) if amplitude[i] > amplitude[i - 1] and
                  (i == n - 1 or amplitude[i] >= amplitude[i + 1])]
    found = sorted(candidates, key=lambda i: -amplitude[i])[:count]
    peaks = []
    for i in found:
        if i >= n - 1:
            peaks.append((i, amplitude[i], 0.0, bound[i]))
            continue
        left, middle, right = amplitude[i - 1:i + 2]
        curvature = left - 2 * middle + right
        if curvature >= 0:
            peaks.append((i, middle, 0.0, bound[i]))
            continue
        half = 0.5 * (left - right)
        shift = half / curvature
        epsilon = bound[i - 1:i + 2].max()
        shift_bound = epsilon * (abs(0.5 * curvature - half) + abs(2 * half) + abs(0.5 * curvature + half)) / curvature**2
        peaks.append((i + shift, middle - 0.5 * half * shift,
                      2 * shift_bound + 4 * UNIT * (i + abs(shift)),
                      2 * (epsilon + 0.5 * (epsilon * abs(shift) + abs(half) * shift_bound)) + 4 * UNIT * middle))
    return peaks


def two_planes_spectra(result, first_step):
    """At 30 degrees: /spectrum (every output row, every = 1) and the statistics' peaks (the
    window's samples) of the tip displacement in y and in z, recomputed with numpy."""
    tip = result['tip/displacement'][...]
    written = result['spectrum/tip_amplitude'][...]
    width = result['statistics/spectrum'].attrs['bin_width']
    for plane, label in [(0, 'y'), (1, 'z')]:
        amplitude, bound = amplitude_spectrum(tip[:, plane])
        if written.shape != (amplitude.size, 2):
            check(f'along_30: /spectrum/tip_amplitude has the shape {(amplitude.size, 2)}', False)
            return
        deviation = np.abs(written[:, plane] - amplitude)
        check(f'along_30: /spectrum/tip_amplitude in {label} recomputed with numpy over {tip.shape[0]} samples: '
              f'largest deviation {deviation.max():.3e} m, bound {bound.min():.3e} .. {bound.max():.3e} m',
              np.all(deviation <= bound))
        amplitude, bound = amplitude_spectrum(tip[first_step + 1:, plane])
        peaks = refined_peaks(amplitude, bound)
        frequency = result['statistics/spectrum/peak_frequency'][...][:, plane]
        peak = result['statistics/spectrum/peak_amplitude'][...][:, plane]
        for j, (bin_at, value, bin_bound, value_bound) in enumerate(peaks):
            check(f'along_30: statistics peak {j + 1} in {label}: {frequency[j]:.6f} Hz, {peak[j]:.6e} m against '
                  f'numpy\'s {bin_at * width:.6f} Hz, {value:.6e} m (deviations {abs(frequency[j] - bin_at * width):.2e} '
                  f'Hz, {abs(peak[j] - value):.2e} m; bounds {bin_bound * width:.2e}, {value_bound:.2e})',
                  abs(frequency[j] - bin_at * width) <= bin_bound * width and abs(peak[j] - value) <= value_bound)


def sweeps(vibrobeam, folder):
    planar = statistics(run(vibrobeam, folder, 'sweep_planar', sweep=SWEEP), 'sweep/statistics')
    planar_text = read_sweep_text(os.path.join(folder, 'sweep_planar_sweep.dat'))
    check('the planar sweep has 2 points of 3 observation points', planar['points/displacement_rms'].shape == (2, 3))
    for name, direction, carrier in [('sweep_y', ', direction = 0', 0), ('sweep_z', ', direction = 90', 1)]:
        turned = statistics(run(vibrobeam, folder, name, ', planes = 2', direction, SWEEP), 'sweep/statistics')
        carrier_and_other(name, '/sweep/statistics/', turned, planar, TWO_PLANES, carrier)
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
