#!/usr/bin/env bash
# The stability and rattling map of a tube in cross-flow (studies/flow_rattling/REPORT.md):
# runs inputs/tube_cross_flow.nml (a sweep over flow.velocity: turbulence plus the
# fluid-elastic force of &flow, compliant supports at the tip) and writes the table of
# flow_rattling.txt: per velocity, the RMS tip displacement, the contact episodes per
# second, the RMS and mean contact force and the power the supports dissipate, each with
# its 95 % interval t(0.975, c - 1) x error (docs/statistics.md, "Ensembles of
# realisations": c batches, Student's quantile). Also copies the sweep's plot to
# docs/figures/. Needs python3 with h5py and gnuplot.
#   usage: studies/flow_rattling/flow_rattling.sh [BUILD_DIR]     (about a minute)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
source scripts/build_release.sh
build_release "$build" vibrobeam
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && "$OLDPWD/$build/vibrobeam" "$OLDPWD/inputs/tube_cross_flow.nml" > run.txt)
cat "$work/run.txt"
bash scripts/plot_sweep.sh "$work/results/tube_cross_flow.h5" > /dev/null
cp "$work/results/tube_cross_flow_response.png" docs/figures/tube_cross_flow_response.png
python=$(bash verification/support/python_h5py.sh) || { echo "flow_rattling: no python3 with h5py"; exit 1; }
"$python" - "$work/results/tube_cross_flow.h5" > studies/flow_rattling/flow_rattling.txt <<'PYTHON'
import sys
import h5py
# Student's t quantile 0.975 for nu = 1..30 degrees of freedom
T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145, 2.131,
        2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042]
with h5py.File(sys.argv[1], 'r') as f:
    s = f['/sweep/statistics']
    velocity = f['/sweep/parameter'][:]
    batches = f['/sweep/batches'][:]
    columns = [('RMS tip displacement (mm)', 'points/displacement_rms', 1e3, True),
               ('contact episodes (1/s)', 'beam/episode_rate', 1, False),
               ('RMS contact force in contact (N)', 'contacts/force_contact_rms', 1, True),
               ('mean contact force (N)', 'contacts/force_mean', 1, True),
               ('power dissipated by the supports (mW)', 'energy/power_contact_damping', 1e3, False)]
    print('# inputs/tube_cross_flow.nml: per flow velocity U, each statistic +- its 95 % interval')
    print('# t(0.975, c - 1) x error (c batches); the contact force at the upper support (contact point 1,')
    print('# both supports act there)')
    print('# ' + ' | '.join(['U (m/s)'] + [c[0] for c in columns]))
    for k, u in enumerate(velocity):
        t = T975[min(batches[k] - 1, 30) - 1]
        cells = [f'{u:5.2f}']
        for _, path, scale, per_point in columns:
            value = s[path][k, 0] if per_point else s[path][k]
            error = s[path + '_error'][k, 0] if per_point else s[path + '_error'][k]
            cells.append(f'{scale * value:.4g} +- {scale * t * error:.2g}')
        print(' | '.join(cells))
PYTHON
cat studies/flow_rattling/flow_rattling.txt
