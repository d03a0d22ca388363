#!/usr/bin/env bash
# Sweep tests (docs/sweeps.md); each compares results bit for bit with compare_sweep.
# usage: run_sweep_tests.sh MODE VIBROBEAM COMPARE_SWEEP [MPIRUN]
#   point    every point of an 'independent' sweep equals a single run with its parameter
#            value and window (both schemes)
#   files    keep_runs with steady-state detection and continuation ('up'): each point's
#            result file holds the statistics of the sweep file's row
#   threads  the same sweeps (independent points; a 2-D map of up-down lines) with 1 and
#            2 OpenMP threads
#   mpi      the same with 1 and 2 MPI ranks (mpirun --oversubscribe -n 2), one thread each
set -uo pipefail
mode=$1; vibrobeam=$2; compare=$3; mpirun=${4:-mpirun}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failed=0

scene() {  # scene NAME FREQUENCY SCHEME T_END OUTPUT SWEEP
  sed -e "s|@FILE@|$1.h5|" -e "s|@FREQUENCY@|$2|" -e "s|@SCHEME@|$3|" -e "s|@T_END@|$4|" \
      -e "s|@OUTPUT@|$5|" -e "s|@SWEEP@|$6|" "$here/scene.nml.in" > "$1.nml"
}
run() {  # run NAME [ENVIRONMENT...]: exit status 0 expected
  local name=$1; shift
  if ! env "$@" "$vibrobeam" "$name.nml" > "$name.out" 2> "$name.err"; then
    echo "FAIL: vibrobeam $name.nml"; cat "$name.err"; failed=1
  fi
}

case $mode in
point)
  for scheme in velocity position; do
    scene sweep 200 $scheme "" "" \
      "\&sweep parameter = 'load.point_frequency', values = 150.0, 200.0, 250.0, settle = 0.05, measure = 0.05 /"
    run sweep
    k=0
    for frequency in 150.0 200.0 250.0; do
      k=$((k + 1))
      scene single$k $frequency $scheme ", t_end = 0.1" ", measure_from = 0.05" ""
      run single$k
      echo "$scheme, point $k ($frequency rad/s):"
      "$compare" point sweep.h5 $k single$k.h5 || failed=1
    done
  done
  ;;
files)
  scene sweep 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 180, to = 220, count = 3, mode = 'up', settle = 0.02, measure = 0.03, steady_tolerance = 0.05, keep_runs = .true. /"
  run sweep
  for k in 1 2 3; do
    echo "point $k: sweep_point000$k.h5"
    "$compare" point sweep.h5 $k sweep_point000$k.h5 || failed=1
  done
  ;;
threads|mpi)
  scene independent 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 150, to = 250, count = 5, settle = 0.03, measure = 0.03 /"
  scene map 200 position "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 180, to = 220, count = 3, mode = 'up-down', parameter2 = 'obstacles.level_from(2)', values2 = 4e-4, 5e-4, 6e-4, settle = 0.02, measure = 0.03 /"
  for name in independent map; do
    if [ "$mode" = threads ]; then
      cp $name.nml ${name}_1.nml; sed -i "s|$name.h5|${name}_1.h5|" ${name}_1.nml
      cp $name.nml ${name}_2.nml; sed -i "s|$name.h5|${name}_2.h5|" ${name}_2.nml
      run ${name}_1 OMP_NUM_THREADS=1
      run ${name}_2 OMP_NUM_THREADS=2
      grep -q "on 2 threads" ${name}_2.out || { echo "FAIL: ${name}_2 did not run on 2 threads"; cat ${name}_2.out; failed=1; }
    else
      for ranks in 1 2; do
        cp $name.nml ${name}_$ranks.nml; sed -i "s|$name.h5|${name}_$ranks.h5|" ${name}_$ranks.nml
        if ! OMP_NUM_THREADS=1 "$mpirun" --allow-run-as-root --oversubscribe -n $ranks "$vibrobeam" ${name}_$ranks.nml \
             > ${name}_$ranks.out 2> ${name}_$ranks.err; then
          echo "FAIL: mpirun -n $ranks vibrobeam ${name}_$ranks.nml"; cat ${name}_$ranks.err; failed=1
        fi
      done
      grep -q "x 2 processes" ${name}_2.out || { echo "FAIL: ${name}_2 did not run on 2 ranks"; cat ${name}_2.out; failed=1; }
    fi
    echo "$name:"
    "$compare" same ${name}_1.h5 ${name}_2.h5 || failed=1
  done
  ;;
*)
  echo "unknown mode $mode"; exit 2 ;;
esac
exit $failed
