#!/usr/bin/env bash
# HDF5 never prints its error stack, in any thread (docs/output.md, "Exit status"): the
# switch that turns the printing off is per thread in a thread-safe HDF5, so every thread
# that calls HDF5 must turn it off for itself. A sweep on 2 OpenMP threads keeps its
# points' result files (keep_runs) under a file-size limit (`ulimit -f`) that every point
# file exceeds, so that HDF5 writes fail in the worker thread as well as in the main one;
# vibrobeam must report the failures in its own words ('File too large', the C library's
# reason) with no 'HDF5-DIAG' stack on stderr. Three runs: which thread runs which point
# varies from run to run.
# usage: run_hdf5_silent_threads.sh VIBROBEAM
set -uo pipefail
vibrobeam=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# the forced rattling cantilever of the sweep tests, every step written: a point file
# holds 2500 rows of histories, about 1.6 MB, far above the 400 kB limit
cat > sweep.nml <<'END'
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9, rayleigh_mass = 3.0 /
&mesh      elements = 8 /
&obstacles count = 2,
           side(1) = 'below', x_from(1) = 0.5, level_from(1) = -0.5e-3,
           side(2) = 'above', x_from(2) = 0.5, level_from(2) =  0.5e-3 /
&impact    restitution = 0.7 /
&time      dt = 2e-5 /
&load      point_force = 20.0, point_frequency = 200 /
&output    file = 'sweep.h5', every = 1, text = .false. /
&sweep     parameter = 'load.point_frequency', from = 150, to = 250, count = 6, settle = 0.02,
           measure = 0.03, keep_runs = .true. /
END
failed=0
for run in 1 2 3; do
  rm -f sweep*.h5*
  (ulimit -f 400; OMP_NUM_THREADS=2 exec "$vibrobeam" sweep.nml > run.out 2> run.err)
  status=$?
  echo "run $run: exit status $status, $(grep -c 'HDF5-DIAG' run.err) HDF5 error stacks on stderr"
  if [ $status -eq 0 ]; then echo "FAIL run $run: exit status 0, but no point file fits"; failed=1; fi
  if ! grep -q 'File too large' run.err; then
    echo "FAIL run $run: no failure reported with its reason ('File too large'):"; cat run.err; failed=1
  fi
  if grep -q -E 'HDF5-DIAG|^ +#[0-9]+: ' run.err; then
    echo "FAIL run $run: HDF5 printed its error stack:"; head -12 run.err; failed=1
  fi
done
[ $failed -eq 0 ] && echo "run_hdf5_silent_threads: passed"
exit $failed
