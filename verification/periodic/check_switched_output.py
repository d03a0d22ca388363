#!/usr/bin/env python3
"""The switched branch as a result file holds it (&periodic switch_branch; docs/output.md,
"Periodic orbit": /periodic/branch_2, STEM_branch_2.dat, STEM_bifurcations_2.dat), on the
scene of verification.switched_branch (period_doubling_switch.nml), whose numbers that test
checks in memory.

usage: check_switched_output.py VIBROBEAM SCENE.nml

Against references independent of the branch's own numbers:
- each point's period is k 2 pi/lambda (k = 1 on /periodic/branch, 2 on branch_2, the
  attribute period_multiple): the continuation keeps P steps of dt = T(lambda)/P per forcing
  period, so k P dt equals k T to a few roundings (bound 8 eps of the period);
- branch_2's attribute `doubling` is a located period doubling of /periodic/branch and
  `start` one of its points beyond it (the same numbers, bit for bit);
- branch_2 ends in located branch points (kind 5) at the period-1 branch's two doublings
  (kind 2), within 4.6e-3 rad/s (verification.switched_branch derives that tolerance from
  locate's stopping rules and the multipliers by differences);
- its points lie between the two doublings and are stable (the time-marching diagram of
  this scene reads period 2 there, verification.period_doubling);
- the text tables equal the HDF5 datasets to their 16 significant digits (1e-15 relative);
- every point's Floquet multipliers (floquet_multipliers, (points, 2 J, 2)): the first's
  modulus is largest_multiplier and `stable` says whether it is below 1, bit for bit;
  largest modulus first, complex ones in conjugate pairs (positive imaginary part first);
  prod(1 + mu), the period-doubling test function, changes sign exactly between the two
  points that each located doubling of /periodic/branch lies between (its `index`), and
  nowhere else; STEM_branch_multipliers.dat (and _2) equal the dataset to 16 digits.
Made to fail: branch_2 written with the period of one forcing period fails the periods;
the multipliers written in the order of another point fail the doublings' indices.
Exit status 0 when every check holds, 1 otherwise, 77 without h5py.
"""
import os
import shutil
import subprocess
import sys
import tempfile

try:
    import numpy as np
    import h5py
except ImportError:
    print('SKIP: no python3 with h5py (Debian package python3-h5py)')
    sys.exit(77)

failures = []
EPS = np.finfo(float).eps


def check(what, holds):
    print(('ok   ' if holds else 'FAIL ') + what)
    if not holds:
        failures.append(what)


def check_multipliers(label, branch, mu, table):
    """The multipliers of every point of `branch` against its other datasets and its text table."""
    points = branch['parameter'].size
    check(f'{label}/floquet_multipliers has shape (points, 2 J, 2): {mu.shape}',
          mu.ndim == 3 and mu.shape[0] == points and mu.shape[2] == 2 and mu.shape[1] % 2 == 0)
    modulus = np.hypot(mu[..., 0], mu[..., 1])
    check(f'{label}: the first multiplier\'s modulus is largest_multiplier, bit for bit',
          np.array_equal(modulus[:, 0], branch['largest_multiplier']))
    check(f'{label}: stable is 1 exactly where every |mu| < 1',
          np.array_equal(branch['stable'] == 1, np.all(modulus < 1, axis=1)))
    # largest modulus first: dgeev's pairs have equal moduli to a rounding, so allow 4 eps
    check(f'{label}: the moduli do not increase along each point\'s list (4 eps)',
          np.all(modulus[:, 1:] <= modulus[:, :-1]*(1 + 4*EPS)))
    pairs = True
    for row in mu:
        j = 0
        while j < row.shape[0]:
            if row[j, 1] != 0:
                pairs = pairs and j + 1 < row.shape[0] and row[j, 1] > 0 and row[j + 1, 0] == row[j, 0] \
                    and row[j + 1, 1] == -row[j, 1]
                j += 2
            else:
                j += 1
    check(f'{label}: complex multipliers come in conjugate pairs, positive imaginary part first', pairs)
    rows = np.loadtxt(table, comments='#', ndmin=2)
    expected = np.column_stack([np.repeat(branch['parameter'], mu.shape[1]), mu[..., 0].ravel(), mu[..., 1].ravel(),
                                modulus.ravel(), np.repeat(np.arange(1, points + 1), mu.shape[1])])
    check(f'{table.split("/")[-1]} equals {label}/floquet_multipliers to 16 digits ({rows.shape[0]} rows)',
          rows.shape == expected.shape and np.allclose(rows, expected, rtol=1e-15, atol=0))


def main():
    vibrobeam, scene = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as folder:
        shutil.copy(scene, os.path.join(folder, 'switch.nml'))
        done = subprocess.run([vibrobeam, 'switch.nml'], cwd=folder, capture_output=True, text=True, timeout=600)
        if done.returncode != 0:
            sys.exit(f'vibrobeam switch.nml exited {done.returncode}: {done.stderr}')
        stem = os.path.join(folder, 'period_doubling_switch')
        with h5py.File(stem + '.h5', 'r') as result:
            first = {name: result['periodic/branch/' + name][...] for name in
                     ['parameter', 'amplitude', 'period', 'largest_multiplier', 'stable', 'newton_iterations',
                      'minimum_gap']}
            first_multipliers = result['periodic/branch/floquet_multipliers'][...]
            first_kind = result['periodic/branch/bifurcations/kind'][...]
            first_index = result['periodic/branch/bifurcations/index'][...]
            first_where = result['periodic/branch/bifurcations/parameter'][...]
            first_located = result['periodic/branch/bifurcations/located'][...]
            check('the result holds a switched branch', 'periodic/branch_2' in result)
            if failures:
                return 1
            switched = result['periodic/branch_2']
            second = {name: switched[name][...] for name in first}
            second_multipliers = switched['floquet_multipliers'][...]
            attributes = dict(switched.attrs)
            second_bifurcations = {name: switched['bifurcations/' + name][...] for name in
                                   ['parameter', 'amplitude', 'kind', 'index', 'located']}
        for label, branch, k in [('/periodic/branch', first, 1), ('/periodic/branch_2', second, 2)]:
            expected = k*2*np.pi/branch['parameter']
            worst = np.max(np.abs(branch['period'] - expected)/expected)
            check(f'{label}: every period is {k} x 2 pi/lambda ({worst:.1e} relative, bound {8*EPS:.1e})',
                  worst <= 8*EPS)
        check('branch_2 period_multiple = 2', int(attributes['period_multiple']) == 2)
        doublings = first_where[(first_kind == 2) & (first_located == 1)]
        check('/periodic/branch has two located period doublings', doublings.size == 2)
        check('branch_2 doubling is the first located period doubling of /periodic/branch, bit for bit',
              doublings.size > 0 and attributes['doubling'] == doublings[0])
        check('branch_2 start is a point of /periodic/branch beyond the doubling, bit for bit',
              attributes['start'] in first['parameter'] and attributes['start'] < attributes['doubling'])
        kinds = second_bifurcations['kind']
        check('branch_2 ends in two located branch points (kind 5)',
              kinds.size == 2 and np.all(kinds == 5) and np.all(second_bifurcations['located'] == 1))
        if kinds.size == 2 and doublings.size == 2:
            gaps = np.abs(np.sort(second_bifurcations['parameter']) - np.sort(doublings))
            check(f'its branch points are the period-1 doublings ({gaps.max():.1e} rad/s, tolerance 4.6e-3)',
                  gaps.max() <= 4.6e-3)
        low, high = np.min(doublings), np.max(doublings)
        check('branch_2 points lie between the two doublings and are stable',
              np.all((second['parameter'] > low) & (second['parameter'] < high)) and np.all(second['stable'] == 1))
        for suffix, table, columns in [('_branch_2.dat', second, list(first)),
                                       ('_bifurcations_2.dat', second_bifurcations,
                                        ['parameter', 'amplitude', 'kind', 'index', 'located'])]:
            rows = np.loadtxt(stem + suffix, comments='#', ndmin=2)
            written = np.column_stack([table[name] for name in columns])
            same = rows.shape == written.shape and np.allclose(rows, written, rtol=1e-15, atol=0)
            check(f'STEM{suffix} equals /periodic/branch_2 to 16 digits ({rows.shape[0]} rows)', same)
        for label, branch, mu, suffix in [('/periodic/branch', first, first_multipliers, ''),
                                          ('/periodic/branch_2', second, second_multipliers, '_2')]:
            check_multipliers(label, branch, mu, stem + '_branch_multipliers' + suffix + '.dat')
        # det(M + I) = prod(1 + mu) changes sign at each located doubling of the period-1
        # branch, between its point `index` and the next, and nowhere else (a doubling after
        # the last point lies before the point beyond the bound, which is not kept)
        product = np.prod(1 + (first_multipliers[..., 0] + 1j*first_multipliers[..., 1]), axis=1).real
        flips = np.nonzero(np.sign(product[1:]) != np.sign(product[:-1]))[0] + 1
        located = np.sort(first_index[(first_kind == 2) & (first_located == 1)])
        inside = located[located < first['parameter'].size]
        check(f'prod(1 + mu) changes sign after points {list(flips)}: the doublings\' indices {list(inside)} '
              f'(and {located.size - inside.size} beyond the last point)', inside.size > 0 and np.array_equal(flips, inside))
    if failures:
        print(f'{len(failures)} check(s) failed')
        return 1
    print('every check holds')
    return 0


if __name__ == '__main__':
    sys.exit(main())
