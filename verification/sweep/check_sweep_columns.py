#!/usr/bin/env python3
"""The named columns of a sweep's text files (docs/output.md, "Text files").

usage: check_sweep_columns.py VIBROBEAM

Runs a small map (two parameters, up-down, a rigid and a compliant stop, so that every
column holds something) with `text = .true.` and reads STEM_sweep.dat and
STEM_poincare.dat as a user would: line 1 names the run, line 2 is the one-line header
the plot scripts read the parameters' names from, then one line per column,
'# 13: impact_rate (1/s)'. For EVERY column the statistic its name says is looked up in
the sweep file with h5py, by a mapping written here and not taken from vibrobeam
(`expected`), and the column must hold it at every point (sample): its unit is the
dataset's 'unit' attribute, its values those of the dataset to the rounding of the text
format. The format %24.15E keeps 16 significant digits: |text - value| <= 0.5e-15 |value|,
plus the rounding of reading the text back (2^-53 |value|).
Exit status 0 when every check holds, 1 otherwise (one line per failure), 77 without h5py.
"""
import os
import re
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
           inertia = 1.6666666666666667e-9, rayleigh_mass = 3.0 /
&mesh      elements = 8 /
&obstacles count = 2,
           side(1) = 'below', x_from(1) = 0.5, level_from(1) = -0.5e-3,
           side(2) = 'above', x_from(2) = 0.5, level_from(2) = 0.5e-3, stiffness(2) = 1e6 /
&impact    restitution = 0.7 /
&time      dt = 2e-5 /
&load      point_force = 20.0, point_frequency = 300 /
&output    file = 'map.h5', points = 0.3, text = .true. /
&sweep     parameter = 'load.point_frequency', values = 250, 300, 350, mode = 'up-down',
           parameter2 = 'obstacles.level_from(1)', values2 = -0.5e-3, -0.8e-3,
           settle = 0.01, measure = 0.02 /
"""
TOLERANCE = 0.5e-15 + 2.0**-53
HEADER = re.compile(r'^# (\d+): (\S+) \(([^)]*)\)(?: (.*))?$')


def read_text(name):
    """The header lines and the rows (blank lines between the lines of a map skipped)."""
    with open(name) as handle:
        lines = handle.read().splitlines()
    header = [line for line in lines if line.startswith('#')]
    rows = [[float(x) for x in line.split()] for line in lines if line.strip() and not line.startswith('#')]
    return header, np.array(rows).reshape(len(rows), -1)


def unit_of(dataset):
    unit = dataset.attrs.get('unit', b'1')
    return unit.decode() if isinstance(unit, bytes) else str(unit)


def most_loaded(sweep):
    """The contact point whose force_peak summed over the points is largest (-1: none)."""
    peaks = sweep['/sweep/statistics/contacts/force_peak'][:]
    if peaks.size == 0:
        return -1
    sums = peaks.sum(axis=0)
    return int(np.argmax(sums)) if sums.max() > 0 else -1


def expected(sweep, kind, name, rows):
    """(values, unit, note) of the statistic `name` names in the sweep file."""
    if kind == 'poincare':
        if name in ('tip_displacement', 'tip_velocity'):
            data = sweep['/sweep/poincare/' + name[4:]]
            return data[:, 0], unit_of(data), ''
        path = '/sweep/poincare/' + name
    else:
        if name == 'point':
            return np.arange(1, rows + 1, dtype=float), '1', ''
        if name.startswith('tip_'):
            data = sweep['/sweep/statistics/points/' + name[4:]]
            return data[:, 0], unit_of(data), ''
        if name == 'peak_frequency_1':
            data = sweep['/sweep/statistics/spectrum/peak_frequency']
            return data[:, 0], unit_of(data), ''
        if name.startswith('stop_'):
            data = sweep['/sweep/statistics/contacts/' + name[5:]]
            loaded = most_loaded(sweep)
            return (data[:, loaded] if loaded >= 0 else np.zeros(rows)), unit_of(data), ''
        if name in ('line', 'direction', 'status', 'settled', 'transient', 'parameter', 'parameter2'):
            path = '/sweep/' + name
        else:
            found = [group + '/' + name for group in ('beam', 'energy', 'poincare')
                     if name in sweep['/sweep/statistics/' + group]]
            if len(found) != 1:
                raise KeyError(f'{name}: {len(found)} statistics of that name in /sweep/statistics/beam, energy, '
                               'poincare')
            path = '/sweep/statistics/' + found[0]
    if name == 'parameter2' and path not in sweep:
        return np.zeros(rows), '1', 'none'
    data = sweep[path]
    axis = '/sweep/' + name if name.startswith('parameter') else None
    note = sweep[axis].attrs['name'].decode() if axis else ''
    return data[:], unit_of(data), note


def check_file(sweep, stem, kind, run_id, failures):
    header, table = read_text(f'{stem}_{kind}.dat')
    if not header[0].startswith(f'# vibrobeam run {run_id} '):
        failures.append(f'{kind}.dat line 1 does not name the run {run_id}: {header[0]}')
    # the plot scripts read the parameters' names and units from line 2
    if not re.search(r'parameter: load\.point_frequency \(rad/s\)  parameter2: obstacles\.level_from\(1\) \(m\)',
                     header[1]):
        failures.append(f'{kind}.dat line 2 lost the parameters: {header[1]}')
    named = [HEADER.match(line) for line in header[2:]]
    if not all(named) or [int(m.group(1)) for m in named] != list(range(1, table.shape[1] + 1)):
        failures.append(f'{kind}.dat: {table.shape[1]} columns, but the column lines are {header[2:]}')
        return 0
    for match in named:
        column, name, unit, note = int(match.group(1)), match.group(2), match.group(3), match.group(4) or ''
        try:
            values, wanted_unit, wanted_note = expected(sweep, kind, name, table.shape[0])
        except KeyError as error:
            failures.append(f'{kind}.dat column {column} ({name}): no such statistic in the sweep file: {error}')
            continue
        if (unit, note) != (wanted_unit, wanted_note):
            failures.append(f'{kind}.dat column {column} ({name}): unit and note "{unit}" "{note}", '
                            f'the sweep file says "{wanted_unit}" "{wanted_note}"')
        values = np.asarray(values, dtype=float)
        held = table[:, column - 1]
        if values.shape != held.shape or np.any(np.abs(held - values) > TOLERANCE * np.abs(values)):
            failures.append(f'{kind}.dat column {column} ({name}) holds {held[:4]}..., the sweep file {values[:4]}...')
    return len(named)


def main():
    vibrobeam = os.path.abspath(sys.argv[1])
    failures = []
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, 'map.nml'), 'w') as handle:
            handle.write(SCENE)
        done = subprocess.run([vibrobeam, 'map.nml'], cwd=work, capture_output=True, text=True, timeout=300)
        if done.returncode != 0:
            print(f'FAIL: vibrobeam map.nml exits {done.returncode}: {done.stderr}')
            return 1
        stem = os.path.join(work, 'map')
        with h5py.File(stem + '.h5', 'r') as sweep:
            run_id = sweep['/run'].attrs['run_id'].decode()
            if most_loaded(sweep) < 0 or sweep['/sweep/poincare/time'].shape[0] == 0:
                failures.append('the scene should load its compliant stop and keep Poincare samples')
            columns = check_file(sweep, stem, 'sweep', run_id, failures)
            columns += check_file(sweep, stem, 'poincare', run_id, failures)
    for failure in failures:
        print('FAIL: ' + failure)
    print(f'check_sweep_columns: {columns} named columns checked, {len(failures)} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
