#!/usr/bin/env python3
"""How well the batch-means standard error (docs/statistics.md, "Sub-windows and standard
errors") describes the scatter of `power_stored` and `power_input`, measured on one long run.

The run: the forced rattling beam of verification/output/statistics.nml for 40.5 s, every
step written (2 025 000 steps, about 10 s):

    sed -e 's/t_end = 0.3/t_end = 40.5/' -e 's/measure_from = 0.1/measure_from = 0.5/' \\
        verification/output/statistics.nml > long.nml
    build/vibrobeam long.nml                              # writes statistics.h5
    /usr/bin/python3 scripts/power_stored_error.py statistics.h5

From t = 0.5 s on, the histories are cut into consecutive windows of K steps (K = 25 000,
50 000, 100 000). In each window the script computes the statistic as vibrobeam does, the
change of the running quantity over the window divided by its duration, and its batch
standard error (c blocks of L steps, L the largest power of two with floor(K/L) >= 8, the
block values (X_{b+1} - X_b)/(L dt) from the levels at the block boundaries). It prints the
scatter of the window values between windows (their sample standard deviation, an
independent measure of the statistic's sampling uncertainty), the RMS of the batch errors,
their ratio, and sqrt(c). Needs h5py and numpy (Debian: python3-h5py).
"""
import sys

import h5py
import numpy as np


def windows(series, first, steps, dt):
    """Window values and batch errors of the change of `series` per second."""
    block = 1
    while steps // (2 * block) >= 8:
        block *= 2
    batches = steps // block
    values, errors = [], []
    start = first
    while start + steps < len(series):
        values.append((series[start + steps] - series[start]) / (steps * dt))
        levels = series[start + np.arange(batches + 1) * block]
        batch = np.diff(levels) / (block * dt)
        errors.append(np.sqrt(np.sum((batch - batch.mean()) ** 2) / (batches * (batches - 1))))
        start += steps
    return batches, np.array(values), np.array(errors)


def main():
    with h5py.File(sys.argv[1], 'r') as f:
        time = f['/time'][:]
        dt = time[1] - time[0]
        first = int(np.searchsorted(time, 0.5 - 0.5 * dt))
        for name, path in [('power_stored', '/energy/total'), ('power_input', '/energy/work')]:
            series = f[path][:]
            for steps in (25000, 50000, 100000):
                batches, values, errors = windows(series, first, steps, dt)
                scatter = values.std(ddof=1)
                error = np.sqrt(np.mean(errors ** 2))
                print(f'{name:13s} K = {steps:6d}: {len(values):3d} windows, c = {batches:2d}, '
                      f'scatter {scatter:.3e} W, batch error {error:.3e} W, '
                      f'ratio {error / scatter:.2f}, sqrt(c) = {np.sqrt(batches):.2f}')


if __name__ == '__main__':
    main()
