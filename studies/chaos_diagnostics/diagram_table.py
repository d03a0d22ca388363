#!/usr/bin/env python3
"""The Poincare diagnostics along a bifurcation diagram (studies/chaos_diagnostics/REPORT.md).

usage: diagram_table.py SWEEP.h5     (a sweep with poincare_samples = 'all' and &output lyapunov)

One row per point: the parameter, the impact rate, the period the program found
(/sweep/statistics/poincare/period, 0 none) and its mismatch, the period the DIAGRAM shows,
K of the 0-1 test, the Lyapunov exponent per forcing period with its standard error, and
the verdict: 'regular' when lambda T < 0 and K < 0.2, 'chaotic' when lambda T > 0 and
K > 0.8, 'undecided' otherwise. The period the diagram shows is computed here from the
samples of the tip displacement alone: the smallest p <= 64 with |u_{k+p} - u_k| below the
plot's resolution, a thousandth of the range of every sample of the diagram (what the
bifurcation plot can tell apart), over the point's window; 0 when none. Then the counts of
each verdict, and of the points where the two periods agree.
Needs h5py and numpy (Debian python3-h5py).
"""
import sys

import h5py
import numpy as np


def diagram_period(u, resolution, longest=64):
    for p in range(1, min(longest, len(u) // 3) + 1):
        if np.max(np.abs(u[p:] - u[:-p])) <= resolution:
            return p
    return 0


def main(path):
    with h5py.File(path, 'r') as sweep:
        parameter = sweep['/sweep/parameter'][:]
        status = sweep['/sweep/status'][:]
        rate = sweep['/sweep/statistics/beam/impact_rate'][:]
        group = sweep['/sweep/statistics/poincare']
        period = group['period'][:]
        mismatch = group['period_mismatch'][:]
        k = group['zero_one_k'][:]
        lags = group['zero_one_lags'][:]
        lam = group['lyapunov_exponent_per_period'][:]
        lam_error = group['lyapunov_exponent_per_period_error'][:]
        point = sweep['/sweep/poincare/point'][:]
        tip = sweep['/sweep/poincare/displacement'][:, 0]
    resolution = 1e-3 * (tip.max() - tip.min())
    print(f'# {path}: {len(parameter)} points; the diagram\'s resolution {resolution:.3e} m '
          f'(1e-3 of the samples\' range)')
    print('# parameter  impacts/s  period  mismatch  diagram  samples      K  lags   lambda T   +- error  verdict')
    counts = {'regular': 0, 'chaotic': 0, 'undecided': 0}
    periods_agree = periods_shown = 0
    for j in range(len(parameter)):
        u = tip[point == j + 1]
        shown = diagram_period(u, resolution)
        if lam[j] < 0 and k[j] < 0.2:
            verdict = 'regular'
        elif lam[j] > 0 and k[j] > 0.8:
            verdict = 'chaotic'
        else:
            verdict = 'undecided'
        if status[j] == 0:
            counts[verdict] += 1
            if shown > 0:
                periods_shown += 1
                periods_agree += int(period[j] == shown)
        print(f'{parameter[j]:11.3f} {rate[j]:10.1f} {int(period[j]):7d} {mismatch[j]:9.3g} {shown:8d} {len(u):8d} '
              f'{k[j]:6.3f} {int(lags[j]):5d} {lam[j]:10.4f} {lam_error[j]:9.4f}  {verdict}')
    print(f'# verdicts: {counts["regular"]} regular (lambda T < 0, K < 0.2), {counts["chaotic"]} chaotic '
          f'(lambda T > 0, K > 0.8), {counts["undecided"]} undecided')
    print(f'# periods: the program finds the period the diagram shows at {periods_agree} of the {periods_shown} '
          f'points where the diagram shows one')


if __name__ == '__main__':
    main(sys.argv[1])
