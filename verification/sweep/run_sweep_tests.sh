#!/usr/bin/env bash
# Sweep tests (docs/sweeps.md); each compares results bit for bit with compare_sweep.
# usage: run_sweep_tests.sh MODE VIBROBEAM COMPARE_SWEEP [MPIRUN]
#   point    every point of an 'independent' sweep equals a single run with its parameter
#            value and window (both schemes; and a sweep over a frequency in Hz)
#   files    keep_runs with steady-state detection and continuation ('up'): each point's
#            result file holds the statistics of the sweep file's row
#   threads  the same sweeps (independent points; a 2-D map of up-down lines; independent
#            points of a Craig-Bampton model) with 1 and 2 OpenMP threads
#   mpi      the same with 1 and 2 MPI ranks (mpirun --oversubscribe -n 2), one thread each
#   failure  a point whose contact solver fails is marked failed, the sweep goes on and
#            exits with status 3 (independent points, and a continuation branch)
#   interrupt SIGINT during a sweep: exit status 4, the sweep file published with /run
#            status 'interrupted' and the points not finished marked, the points done
#            kept in the partial directory
#   planes   a beam of two planes in a round hole with friction and a wear coefficient:
#            every point of an 'independent' sweep equals the single run (its wear and
#            friction power with the rest), also with steady-state detection (the window
#            after the transient it found), and keep_runs with steady-state detection and
#            continuation ('up') holds each point's statistics in its file
set -uo pipefail
mode=$1; vibrobeam=$2; compare=$3; mpirun=${4:-mpirun}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failed=0

# shellcheck source=sweep_common.sh
. "$here/sweep_common.sh"

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
  # a sweep over a frequency's twin in Hz (docs/input.md, "Frequencies in Hz"): point k
  # equals the single run that gives that frequency in Hz
  scene sweep_hz 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency_hz', values = 25.0, 35.0, settle = 0.05, measure = 0.05 /"
  run sweep_hz
  k=0
  for hz in 25.0 35.0; do
    k=$((k + 1))
    scene single_hz$k 200 velocity ", t_end = 0.1" ", measure_from = 0.05" ""
    sed -i "s|point_frequency = 200|point_frequency_hz = $hz|" single_hz$k.nml
    run single_hz$k
    echo "sweep over load.point_frequency_hz, point $k ($hz Hz):"
    "$compare" point sweep_hz.h5 $k single_hz$k.h5 || failed=1
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
planes)
  # tube_in_round_hole.nml, coarser: 8 elements, a frictional hole (mu = 0.3) with a wear
  # coefficient; the sweep's windows of 0.05 s, the single runs' the same
  tube() {
    cat > "$1.nml" <<END
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 6.938018879893839e-05,
           inertia = 2.7642255353230253e-09, rayleigh_mass = 7.9193, rayleigh_stiffness = 5.9941e-06,
           planes = 2 /
&mesh      elements = 8 /
&obstacles count = 1, shape(1) = 'circle', x_from(1) = 0.5, radius(1) = 0.5e-3, friction(1) = 0.3,
           wear_coefficient(1) = 1e-14 /
&impact    restitution = 0.7 /
&time      dt = 2e-5 $3 /
&load      base_acceleration = 30.0, base_frequency = $2, direction = 45 /
&initial   velocity = 'mode', velocity_mode = 1, velocity_amplitude = 0.3, direction = -45 /
&output    file = '$1.h5', text = .false. $4 /
$5
END
  }
  tube sweep 413.0 "" "" "&sweep parameter = 'load.base_frequency', values = 300.0, 413.0, 500.0, settle = 0.05, measure = 0.05 /"
  run sweep
  k=0
  for frequency in 300.0 413.0 500.0; do
    k=$((k + 1))
    tube single$k $frequency ", t_end = 0.1" ", measure_from = 0.05" ""
    run single$k
    echo "two planes, point $k ($frequency rad/s):"
    "$compare" point sweep.h5 $k single$k.h5 || failed=1
  done
  # steady-state detection without keep_runs: the statistics (the wear's too) are those of
  # the last window, from the transient the point found; the single run measures the same
  tube steady 413.0 "" "" "&sweep parameter = 'load.base_frequency', values = 380.0, 420.0, settle = 0.02, measure = 0.03, steady_tolerance = 0.05 /"
  run steady
  transients=$(h5dump -A 0 -m '%.17g' -d /sweep/transient -y -w 0 steady.h5 | sed -n '/DATA {/,/}/{/DATA {/d;/}/d;p;}' | tr -d ' \n')
  k=0
  for frequency in 380.0 420.0; do
    k=$((k + 1))
    transient=$(cut -d, -f$k <<< "$transients")
    tube steady_single$k $frequency ", t_end = $(awk -v t="$transient" 'BEGIN { printf "%.17g", t + 0.03 }')" \
      ", measure_from = $transient" ""
    run steady_single$k
    echo "two planes, steady point $k ($frequency rad/s, transient $transient s):"
    "$compare" point steady.h5 $k steady_single$k.h5 || failed=1
  done
  tube kept 413.0 "" "" "&sweep parameter = 'load.base_frequency', from = 380, to = 420, count = 3, mode = 'up', settle = 0.02, measure = 0.03, steady_tolerance = 0.05, keep_runs = .true. /"
  run kept
  for k in 1 2 3; do
    echo "two planes, kept point $k: kept_point000$k.h5"
    "$compare" point kept.h5 $k kept_point000$k.h5 || failed=1
  done
  ;;
threads|mpi)
  scene independent 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 150, to = 250, count = 5, settle = 0.03, measure = 0.03 /"
  scene map 200 position "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 180, to = 220, count = 3, mode = 'up-down', parameter2 = 'obstacles.level_from(2)', values2 = 4e-4, 5e-4, 6e-4, settle = 0.02, measure = 0.03 /"
  # each point prepares its Craig-Bampton model: on 80 unknowns its fixed-interface modes
  # come from ARPACK (Lanczos), whose iterations the points' threads must not share;
  # 20-step windows, so that the points' preparations overlap
  scene reduced 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 150, to = 250, count = 192, settle = 0, measure = 0.0004 /"
  sed -i "s|elements = 8 /|elements = 40, reduction = 'craig-bampton' /|" reduced.nml
  for name in independent map reduced; do
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
failure)
  # the scene of verification/dynamics/numerical_failure.nml: a contact solver allowed
  # one pivoting iteration ('pivoting') fails once the load presses the beam onto its floor
  for sweep_mode in independent down; do
    cat > failure.nml <<END
&beam      length = 1.0, k2 = 1.0 /
&mesh      elements = 8 /
&obstacles count = 1, side(1) = 'below', x_from(1) = 0.0, x_to(1) = 1.0, level_from(1) = -1e-3 /
&time      dt = 1e-2 /
&load      distributed = -10.0 /
&solver    contact_method = 'pivoting', contact_max_iterations = 1 /
&output    file = 'failure.h5', text = .false. /
&sweep     parameter = 'load.distributed', values = -0.0005, -10.0, -0.001, mode = '$sweep_mode', measure = 10.0 /
END
    "$vibrobeam" failure.nml > failure.out 2> failure.err
    status=$?
    statuses=$(statuses failure.h5)
    echo "$sweep_mode: exit status $status, /sweep/status $statuses"
    if [ $status -ne 3 ]; then echo "FAIL exit status $status, expected 3"; cat failure.err; failed=1; fi
    case $sweep_mode in
      independent) expected=0,1,0 ;;   # the order given
      down) expected=0,0,1 ;;          # -0.0005, -0.001, -10
    esac
    if [ "$statuses" != "$expected" ]; then echo "FAIL /sweep/status $statuses, expected $expected"; failed=1; fi
    grep -q "point [0-9]: numerical failure at step" failure.err || { echo "FAIL no failure message"; cat failure.err; failed=1; }
  done
  ;;
interrupt)
  scene long 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 150, to = 250, count = 6, settle = 20, measure = 20 /"
  "$vibrobeam" long.nml > long.out 2> long.err &
  pid=$!
  # SIGINT once points are running, whatever the machine's speed or load: the journal is
  # made after the signal handlers are installed and just before the points start; once
  # the process has used 0.5 s of CPU time more, its first points (40 s of simulated time,
  # 2e6 steps each) are running and far from their end
  cpu() { awk '{print $14 + $15}' /proc/$pid/stat 2> /dev/null || echo 0; }
  ticks=$(getconf CLK_TCK)
  deadline=$((SECONDS + 120))
  until ls long.h5.partial/journal.h5.*.tmp > /dev/null 2>&1 || [ $SECONDS -ge $deadline ]; do sleep 0.05; done
  start=$(cpu)
  until [ "$(cpu)" -ge $((start + ticks / 2)) ] || ! kill -0 $pid 2> /dev/null || [ $SECONDS -ge $deadline ]; do
    sleep 0.05
  done
  kill -INT $pid
  wait $pid
  status=$?
  echo "exit status $status"
  if [ $status -ne 4 ]; then echo "FAIL exit status $status, expected 4"; cat long.err; failed=1; fi
  h5dump -a /run/status long.h5 | grep -q '"interrupted"' || { echo "FAIL /run status is not 'interrupted'"; failed=1; }
  statuses=$(statuses long.h5)
  echo "/sweep/status $statuses"
  case ",$statuses," in *,2,*) ;; *) echo "FAIL no point marked interrupted"; failed=1 ;; esac
  case ",$statuses," in *,3,*) ;; *) echo "FAIL no point marked not run"; failed=1 ;; esac
  ls long.h5.*.tmp > /dev/null 2>&1 && { echo "FAIL a temporary file is left"; failed=1; }
  [ -d long.h5.partial ] || { echo "FAIL the points done are not kept for a rerun (long.h5.partial)"; failed=1; }
  ;;
*)
  echo "unknown mode $mode"; exit 2 ;;
esac
exit $failed
