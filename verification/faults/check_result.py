#!/usr/bin/env python3
"""Independent checks of vibrobeam result files for the fault tests (h5py, not our reader).

usage:
  check_result.py complete FILE.h5 STATUS [--no-text]
      FILE.h5 opens as a plain HDF5 file, /run status is STATUS, the histories of each kind
      have one length (outputs, field snapshots, impacts, episodes) equal to the counts in
      /run, and (unless --no-text) every .dat file of its stem names the run id of /run and
      holds as many rows as its datasets, with the same first and last values.
  check_result.py partial TEMP.h5 REFERENCE.h5
      TEMP.h5 (the temporary file of a killed run) opens as a SWMR reader; every history
      holds at least the rows /run says were flushed, the histories of one kind agree in
      length up to the rows of one flush, and each equals the start of the uninterrupted
      run REFERENCE.h5 bit for bit.
  check_result.py continued CONTINUED.h5 REFERENCE.h5
      every history of CONTINUED.h5 (a run continued from a checkpoint) equals the end of
      the uninterrupted run REFERENCE.h5 bit for bit, and so do the spectrum and the
      contact fractions.
  check_result.py flushed_step TEMP.h5
      print /run flushed_step and /checkpoint step of a killed run's temporary file.
Exit status 0 when every check holds, 1 otherwise (one line per failed check).
"""
import glob
import sys

import numpy as np
import h5py

KINDS = {
    'outputs': ['time', 'tip/displacement', 'tip/velocity', 'tip/reaction', 'tip/impulse',
                'energy/kinetic', 'energy/elastic', 'energy/total', 'energy/work',
                'energy/dissipated', 'energy/dissipated_impacts', 'energy/dissipated_damping',
                'energy/dissipated_numerical', 'energy/balance', 'contact/penetration',
                'points/displacement', 'points/velocity'],
    'field_outputs': ['field/time', 'field/displacement'],
    'impacts': ['impacts/time', 'impacts/x', 'impacts/impulse', 'impacts/velocity_before',
                'impacts/velocity_after'],
    'episodes': ['episodes/x', 'episodes/start', 'episodes/end', 'episodes/impulse',
                 'episodes/approach_speed', 'episodes/impacts', 'episodes/open_at_end'],
}
# .dat file -> datasets of its columns (the first and last rows are compared)
TEXT = {
    'tip': ['time', 'tip/displacement', 'tip/velocity', 'tip/reaction', 'tip/impulse'],
    'energy': ['time', 'energy/kinetic', 'energy/elastic', 'energy/work', 'energy/dissipated'],
    'impacts': KINDS['impacts'],
    'spectrum': ['spectrum/frequency', 'spectrum/tip_amplitude'],
}

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print('FAIL ' + message)


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def histories(f):
    for kind, paths in KINDS.items():
        yield kind, [p for p in paths if p in f]


def complete(name, status, with_text):
    f = h5py.File(name, 'r')
    run = f['run'].attrs
    check(text(run['status']) == status, f"/run status is '{text(run['status'])}', expected '{status}'")
    for kind, paths in histories(f):
        lengths = {p: f[p].shape[0] for p in paths}
        check(len(set(lengths.values())) <= 1, f'{kind}: histories of different lengths {lengths}')
        for p, n in lengths.items():
            check(n == run['flushed_' + kind], f'{p}: {n} rows, /run flushed_{kind} = {run["flushed_" + kind]}')
    if 'time' in f:
        steps, dt = int(run['steps']), float(f.attrs['time.dt'])
        check(f['time'][-1] == steps * dt, f'last output time {f["time"][-1]} is not steps*dt = {steps * dt}')
    if not with_text:
        return
    stem = name[:-3] if name.endswith('.h5') else name
    run_id = text(run['run_id'])
    dat_files = glob.glob(glob.escape(stem) + '_*.dat')
    check(len(dat_files) > 0, 'no .dat file beside ' + name)
    for dat in dat_files:
        suffix = dat[len(stem) + 1:-4]
        with open(dat) as handle:
            first = handle.readline()
            if suffix not in TEXT:
                continue
            count, head, tail = 0, None, None
            for line in handle:
                if line.startswith('#') or not line.strip():
                    continue
                count += 1
                tail = line
                if head is None:
                    head = line
        check(first.startswith('# vibrobeam run ' + run_id + ' '),
              f'{dat} names another run: {first.strip()} (/run run_id {run_id})')
        if TEXT[suffix][0] in f:
            columns = [f[p][...] for p in TEXT[suffix]]
            n = len(columns[0])
            check(count == n, f'{dat}: {count} rows, the HDF5 file has {n}')
            if n and count == n:
                for row, line in ((0, head), (n - 1, tail)):
                    values = [float(v) for v in line.split()[:len(columns)]]
                    expected = [c[row] for c in columns]
                    check(np.allclose(values, expected, rtol=1e-14, atol=0),
                          f'{dat} row {row}: {values} differs from {expected}')


def partial(name, reference):
    f = h5py.File(name, 'r', swmr=True)
    g = h5py.File(reference, 'r')
    run = f['run'].attrs
    for kind, paths in histories(f):
        flushed = int(run['flushed_' + kind])
        lengths = [f[p].shape[0] for p in paths]
        check(min(lengths) >= flushed, f'{kind}: {min(lengths)} rows, fewer than the {flushed} flushed')
        for p in paths:
            a = f[p][...]
            b = g[p][:len(a)]
            check(len(b) == len(a), f'{p}: {len(a)} rows, the reference has only {len(b)}')
            check(a.tobytes() == b.tobytes(), f'{p}: differs from the uninterrupted run')


def continued(name, reference):
    f = h5py.File(name, 'r')
    g = h5py.File(reference, 'r')
    for kind, paths in histories(f):
        for p in paths:
            a = f[p][...]
            b = g[p][...][len(g[p]) - len(a):]
            check(len(a) > 0 or kind in ('impacts', 'episodes'), f'{p}: the continued run wrote no rows')
            check(a.tobytes() == b.tobytes(), f'{p}: differs from the end of the uninterrupted run')
    for p in ['spectrum/frequency', 'spectrum/tip_amplitude', 'contact/fraction']:
        check(f[p][...].tobytes() == g[p][...].tobytes(), f'{p}: differs from the uninterrupted run')
    check(int(f['run'].attrs['steps']) == int(g['run'].attrs['steps']), 'the runs end at different steps')


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    if argv[1] == 'complete':
        complete(argv[2], argv[3], '--no-text' not in argv)
    elif argv[1] == 'partial':
        partial(argv[2], argv[3])
    elif argv[1] == 'continued':
        continued(argv[2], argv[3])
    elif argv[1] == 'flushed_step':
        f = h5py.File(argv[2], 'r', swmr=True)
        print(int(f['run'].attrs['flushed_step']), int(f['checkpoint'].attrs['step']),
              int(f['checkpoint'].attrs['current']))
        return 0
    else:
        print(__doc__)
        return 2
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
