#!/usr/bin/env bash
# Random impacting (studies/random_impacting/REPORT.md): a tube against a zero-gap
# compliant stop under a band-limited random force, at three resolutions (N, dt) =
# (8, 4e-5 s), (16, 2e-5 s), (32, 1e-5 s), each an ensemble of 8 realisations (a sweep
# over forces.realisation). Writes random_impacting.txt: per resolution the ensemble mean
# of each statistic +- its 95 % interval t(0.975, 7) s/sqrt(8) (s the standard deviation
# of the 8 values), and the mean of the 8 runs' own 95 % intervals t(0.975, c - 1) error.
# Needs python3 with h5py.   usage: studies/random_impacting/random_impacting.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
source scripts/build_release.sh
build_release "$build" vibrobeam
python=$(bash verification/support/python_h5py.sh) || { echo "random_impacting: no python3 with h5py"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for level in "8 4e-5" "16 2e-5" "32 1e-5"; do
  set -- $level
  mkdir -p "$work/$1"
  sed -e "s/@ELEMENTS@/$1/" -e "s/@DT@/$2/" studies/random_impacting/random_impacting.nml.in > "$work/$1/level.nml"
  (cd "$work/$1" && "$OLDPWD/$build/vibrobeam" level.nml | tail -1)
done
"$python" - "$work" > studies/random_impacting/random_impacting.txt <<'PYTHON'
import math
import sys
import h5py
T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145, 2.131]
columns = [('RMS tip displacement (um)', 'points/displacement_rms', 1e6, True),
           ('contact episodes (1/s)', 'beam/episode_rate', 1, False),
           ('contact fraction (%)', 'contacts/force_contact_fraction', 100, True),
           ('RMS contact force in contact (N)', 'contacts/force_contact_rms', 1, True),
           ('mean contact force (N)', 'contacts/force_mean', 1, True),
           ('peak contact force (N)', 'contacts/force_peak', 1, True)]
print('# random impacting: per resolution (N, dt), ensemble mean of 8 realisations +- t(0.975, 7) s/sqrt(8)')
print('# [mean of the runs\' own intervals t(0.975, c - 1) error]')
print('# ' + ' | '.join(['N', 'dt (s)'] + [c[0] for c in columns]))
for n, dt in ((8, '4e-5'), (16, '2e-5'), (32, '1e-5')):
    with h5py.File(f'{sys.argv[1]}/{n}/level.h5', 'r') as f:
        s = f['/sweep/statistics']
        batches = f['/sweep/batches'][:]
        status = f['/sweep/status'][:]
        assert all(status == 0), f'points failed at N = {n}'
        cells = [str(n), dt]
        for _, path, scale, per_point in columns:
            values = [scale * (s[path][k, 0] if per_point else s[path][k]) for k in range(len(batches))]
            errors = [scale * (s[path + '_error'][k, 0] if per_point else s[path + '_error'][k]) for k in range(len(batches))]
            r = len(values)
            mean = sum(values) / r
            sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (r - 1))
            own = sum(T975[b - 2] * e for b, e in zip(batches, errors)) / r
            cells.append(f'{mean:.4g} +- {T975[r - 2] * sd / math.sqrt(r):.2g} [{own:.2g}]')
        print(' | '.join(cells))
PYTHON
cat studies/random_impacting/random_impacting.txt
