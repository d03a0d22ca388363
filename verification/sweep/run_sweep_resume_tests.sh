#!/usr/bin/env bash
# A sweep streams its points into its partial directory and a rerun of the same input goes
# on from there (docs/sweeps.md, "Resuming a sweep"): killed (SIGKILL) or interrupted
# (SIGINT) and run again, it ends with the same sweep file, bit for bit (compare_sweep same;
# the wall-clock times excepted), as a run that was never stopped; memory does not grow
# with the number of points.
# usage: run_sweep_resume_tests.sh MODE VIBROBEAM COMPARE_SWEEP [MPIRUN]
#   threads  independent points on 2 threads, killed; a continuation map (up-down lines,
#            position scheme) on 2 threads, interrupted; a partial sweep of another input
#            is refused (exit status 2, by --check too)
#   mpi      the continuation map on 2 MPI ranks, every process killed, resumed on 2 ranks;
#            SIGTERM to one rank and SIGUSR1 to mpirun: exit status 4 and the sweep file
#            published as 'interrupted'; SIGTERM to mpirun (which then exits 1 whatever its
#            ranks do): never published as 'ok' with points not run, and resumable
#   memory   the peak resident set of a sweep of 600 points with Poincare samples stays
#            within 10 % of that of 60 points
set -uo pipefail
mode=$1; vibrobeam=$2; compare=$3; mpirun=${4:-mpirun}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
background=''
cleanup() {
  [ -n "$background" ] && kill -9 -- "-$background" 2> /dev/null
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work"
failed=0
# shellcheck source=sweep_common.sh
. "$here/sweep_common.sh"
mpi=("$mpirun" --allow-run-as-root --oversubscribe -n 2)

# twin NAME COPY: COPY.nml, the input NAME.nml writing COPY.h5 (and reporting progress)
twin() {
  sed -e "s|'$1.h5'|'$2.h5'|" -e "s|text = .false.|text = .false., progress = .true.|" "$1.nml" > "$2.nml"
}
# start NAME [COMMAND...]: run COMMAND (default vibrobeam) on NAME.nml in a process group of
# its own (`background` is its id), stdout and stderr into NAME.out and NAME.err; the input
# is named by its full path, which no other test's processes have (pgrep below)
start() {
  local name=$1; shift
  [ $# -eq 0 ] && set -- "$vibrobeam"
  setsid "$@" "$work/$name.nml" > "$name.out" 2> "$name.err" &
  background=$!
}
# reference MAKER NAME [COMMAND...]: make NAME.nml with `MAKER NAME COUNT` and run it whole,
# with more values (COUNT) until it lasts at least 3 s on this machine (a stopped run must
# have had a journal commit, every second, and not have ended); sets `count` and `seconds`
reference() {
  local maker=$1 name=$2 start; shift 2
  [ $# -eq 0 ] && set -- "$vibrobeam"
  count=10
  while :; do
    $maker "$name" $count
    start=$(date +%s.%N)
    "$@" "$name.nml" > "$name.out" 2> "$name.err" || { echo "FAIL $name"; cat "$name.err"; failed=1; return 1; }
    seconds=$(awk "BEGIN {print $(date +%s.%N) - $start}")
    echo "$name: $count values a line, $seconds s"
    awk "BEGIN {exit !($seconds >= 3)}" && return 0
    count=$(awk "BEGIN {print int($count * 4 / ($seconds + 0.2)) + 1}")
  done
}
# halfway NAME: wait half the reference's time (`seconds`, at least 1.5 s: past a commit),
# then return 0 if the run started on NAME.nml is still going, 1 if it ended
halfway() {
  sleep "$(awk "BEGIN {print $seconds / 2}")"
  kill -0 "$background" 2> /dev/null || { echo "FAIL $1 ended before it could be stopped:"; cat "$1.err"; return 1; }
}
# stop_all NAME: SIGKILL to the process group of the run on NAME.nml, and to any of its
# processes still there (an MPI rank may have left the group)
stop_all() {
  local waited=0 pids
  kill -9 -- "-$background" 2> /dev/null
  wait "$background" 2> /dev/null
  background=''
  while pids=$(pgrep -f "vibrobeam $work/$1.nml"); do
    kill -9 $pids 2> /dev/null
    sleep 0.1
    waited=$((waited + 1))
    [ $waited -lt 100 ] || { echo "  processes of $1 survive SIGKILL: $pids"; return 1; }
  done
}
# resumed NAME REFERENCE [COMMAND...]: run NAME.nml again to its end and compare its sweep
# file with REFERENCE.h5; the run must have started from points done before
resumed() {
  local name=$1 reference=$2; shift 2
  [ $# -eq 0 ] && set -- "$vibrobeam"
  expect "$name: --check announces the resumption" \
    bash -c "'$vibrobeam' --check '$name.nml' | grep -q \"resume: '$name.h5.partial' holds [1-9]\""
  if ! "$@" "$name.nml" > "$name.out" 2> "$name.err"; then echo "FAIL $name resumed"; cat "$name.err"; failed=1; fi
  cat "$name.out"
  expect "$name: the run went on from the points done" grep -q -E "\\([1-9][0-9]* done before" "$name.out"
  expect "$name: the partial directory is removed" test ! -e "$name.h5.partial"
  echo "$name resumed against $reference:"
  "$compare" same "$reference.h5" "$name.h5" || failed=1
}

# independent NAME COUNT: COUNT independent points; map NAME COUNT: 4 up-down lines of COUNT
# values (each a task of 2 COUNT points)
independent() {
  scene "$1" 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 150, to = 250, count = $2, settle = 0.5, measure = 0.5 /"
}
map() {
  scene "$1" 200 position "" "" \
    "\&sweep parameter = 'load.point_frequency', from = 180, to = 220, count = $2, mode = 'up-down', parameter2 = 'obstacles.level_from(2)', values2 = 4e-4, 5e-4, 6e-4, 7e-4, settle = 0.4, measure = 0.4 /"
}

case $mode in
threads)
  reference independent independent env OMP_NUM_THREADS=2 "$vibrobeam"
  twin independent killed
  start killed env OMP_NUM_THREADS=2 "$vibrobeam"
  if halfway killed; then
    stop_all killed
    # another input into the same file: refused, the partial sweep left as it is
    sed -e "s|restitution = 0.7|restitution = 0.6|" killed.nml > other.nml
    for option in --check ''; do
      "$vibrobeam" $option other.nml > other.out 2> other.err
      expect "another input ($option): exit status 2" exit_is $? 2
      expect "another input ($option): message" says other.err "'killed.h5.partial' holds a partial sweep of another input"
    done
    resumed killed independent env OMP_NUM_THREADS=2 "$vibrobeam"
  else
    failed=1
  fi
  reference map map env OMP_NUM_THREADS=2 "$vibrobeam"
  twin map interrupted
  start interrupted env OMP_NUM_THREADS=2 "$vibrobeam"
  if halfway interrupted; then
    kill -INT "$background"; wait "$background"; status=$?; background=''
    expect 'SIGINT: exit status 4' exit_is $status 4
    expect "SIGINT: published as 'interrupted'" test "$(run_status interrupted.h5)" = interrupted
    expect 'SIGINT: the points done are kept' test -d interrupted.h5.partial
    resumed interrupted map env OMP_NUM_THREADS=2 "$vibrobeam"
  else
    failed=1
  fi
  ;;
mpi)
  reference map map env OMP_NUM_THREADS=1 "${mpi[@]}" "$vibrobeam"
  twin map killed
  start killed env OMP_NUM_THREADS=1 "${mpi[@]}" "$vibrobeam"
  if halfway killed; then
    stop_all killed
    resumed killed map env OMP_NUM_THREADS=1 "${mpi[@]}" "$vibrobeam"
  else
    failed=1
  fi
  for signal in rank usr1 term; do
    twin map $signal
    start $signal env OMP_NUM_THREADS=1 "${mpi[@]}" "$vibrobeam"
    halfway $signal || { failed=1; continue; }
    # (the process group's leader is mpirun; the other processes running the input are the ranks)
    case $signal in
      rank) kill -TERM "$(pgrep -f "vibrobeam $work/$signal.nml" | grep -v -x "$background" | tail -1)" ;;
      usr1) kill -USR1 "$background" ;;
      term) kill -TERM "$background" ;;
    esac
    wait "$background"; status=$?; background=''
    published=$(run_status $signal.h5)
    echo "$signal: exit status $status, /run status '$published', /sweep/status $(statuses $signal.h5 2> /dev/null)"
    if [ $signal = term ]; then
      # OpenMPI's mpirun exits 1 when it is signalled; the ranks publish within its grace time or are killed
      expect "$signal: not published as 'ok' with points not run" test "$published" != ok
    else
      expect "$signal: exit status 4" exit_is $status 4
      expect "$signal: published as 'interrupted'" test "$published" = interrupted
    fi
    resumed $signal map env OMP_NUM_THREADS=1 "${mpi[@]}" "$vibrobeam"
  done
  ;;
memory)
  # 260 periods of 2 pi/20000 s a point: the 256 Poincare samples a point keeps
  for points in 60 600; do
    scene memory$points 20000 velocity "" "" \
      "\&sweep parameter = 'load.point_frequency', from = 20000, to = 20100, count = $points, settle = 0, measure_periods = 260 /"
    run memory$points OMP_NUM_THREADS=1
    eval "peak$points=\$(h5dump -a /run/peak_memory_kb memory$points.h5 | sed -n 's/.*(0): *\\([0-9]*\\).*/\\1/p')"
  done
  # before streaming a sweep kept every point (33 kB each with its samples): 600 points
  # then needed 20 MB more than 60, on about 24 MB; streamed, the points leave nothing behind
  echo "peak resident set: $peak60 kB for 60 points, $peak600 kB for 600 points (limit 1.10 times)"
  expect 'memory flat in the number of points' awk "BEGIN {exit !($peak600 <= 1.10 * $peak60)}"
  ;;
*)
  echo "unknown mode $mode"; exit 2 ;;
esac
[ $failed -eq 0 ] && echo "run_sweep_resume_tests $mode: passed"
exit $failed
