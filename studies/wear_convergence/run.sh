#!/usr/bin/env bash
# The wear indicators of a tube in a round hole with friction under refinement: dt = 4e-5
# ... 5e-6 s at N = 16, then N = 8, 32 at dt = 1e-5 s; a whirl under a rotating harmonic
# load (whirl_in_hole.nml) and under random loads along y and z (random_in_hole.nml).
# Prints, per run, the wear work rate, mean normal force, sliding fraction and impact rate
# with their standard errors (docs/statistics.md, "Wear at the supports"); about 4 minutes.
# Writes studies/wear_convergence/results.txt (REPORT.md beside this script reads it).
#   usage: studies/wear_convergence/run.sh [BUILD_DIR]      (default: build)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-build}
case "$build" in /*) ;; *) build="$root/$build" ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {  # run SCENE ELEMENTS DT
  sed -e "s/elements = 16/elements = $2/" -e "s/dt = 1e-5/dt = $3/" "$here/$1.nml" > "$work/scene.nml"
  (cd "$work" && "$build/vibrobeam" scene.nml > /dev/null)
  set -- "$work/$1.h5" "$2" "$3"
  /usr/bin/python3 - "$1" "$2" "$3" <<'PY'
import sys, h5py
f = h5py.File(sys.argv[1], 'r')
w = lambda name: (f['/wear/' + name][0], f['/wear/' + name + '_error'][0])
print('%4s %8s' % (sys.argv[2], sys.argv[3]) + ''.join(' %12.5e %10.3e' % w(n) for n in
      ('work_rate', 'mean_force', 'sliding_fraction', 'impact_rate')))
PY
}
{
  for scene in whirl_in_hole random_in_hole; do
    echo "# studies/wear_convergence/run.sh, $(date -u +%Y-%m-%dT%H:%MZ): $scene.nml"
    echo "#  N       dt    work_rate (W)  +- s.e.   mean_force (N)  +- s.e.  sliding_frac  +- s.e.  impacts/s  +- s.e."
    for dt in 4e-5 2e-5 1e-5 5e-6; do run $scene 16 $dt; done
    for n in 8 32; do run $scene $n 1e-5; done
  done
} | tee "$here/results.txt"
