#!/usr/bin/env bash
# The files of a sweep (docs/sweeps.md, "The sweep file" and "Resuming a sweep"): the
# sweep file, its text files and its keep_runs point files are one set, published at once
# beside each other; nothing a sweep writes or removes is its input or the file &initial
# from_file continues; a file that cannot be written is an I/O error. Point files are
# checked against their sweep file's rows bit for bit (compare_sweep point).
# usage: run_sweep_file_tests.sh MODE VIBROBEAM COMPARE_SWEEP
#   protect   a from_file or an input named like a point file (STEM_pointNNNN.h5) is refused
#             (exit status 2, by --check too), and it is left as it was
#   io_error  point files that cannot be written (ulimit -f, a directory in the partial
#             directory): exit status 1, the earlier set untouched, the points done kept for
#             a rerun; a point file lost from the partial directory: exit status 1, the
#             message says what the journal and the directory hold; a directory in the way
#             of a point file: exit status 2
#   set       a smaller sweep replaces a larger one's set (its extra point files removed);
#             two sweeps started together on one file: one runs, the other stops at once
#             (exit status 1) or runs after it, and the set is always one sweep's
#   check     --check judges a sweep as the run does: the size of what it writes from its
#             points' windows (not &time t_end, which it ignores) and its keep_runs files,
#             and whether its &initial from_file can be continued
set -uo pipefail
mode=$1; vibrobeam=$2; compare=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failed=0
# shellcheck source=sweep_common.sh
. "$here/sweep_common.sh"

# keep NAME FILE COUNT [RESTITUTION] [SETTLE]: a keep_runs sweep of COUNT frequencies into
# FILE, its point files with an output row every step
keep() {
  scene "$1" 200 velocity "" ", every = 1" \
    "\&sweep parameter = 'load.point_frequency', from = 180, to = 220, count = $3, settle = ${5:-0.01}, measure = 0.04, keep_runs = .true. /"
  sed -i -e "s|'$1.h5'|'$2'|" -e "s|restitution = 0.7|restitution = ${4:-0.7}|" "$1.nml"
}
# consistent FILE COUNT: FILE is a sweep file whose set is exactly its COUNT point files,
# each holding the statistics of its row
consistent() {
  local k files
  files=$(ls "${1%.h5}"_point*.h5 2> /dev/null | wc -l)
  [ "$files" -eq "$2" ] || { echo "  $files point files beside $1, expected $2: $(ls "$(dirname "$1")")"; return 1; }
  for k in $(seq 1 "$2"); do
    "$compare" point "$1" "$k" "$(printf '%s_point%04d.h5' "${1%.h5}" "$k")" > compare.log || { cat compare.log; return 1; }
  done
}
# snapshot DIR / intact DIR: every file of DIR unchanged since the snapshot, none added
# (the partial directory of a sweep that could not finish excepted)
snapshot() { rm -rf snapshot; cp -a "$1" snapshot; }
intact() {
  diff -r -q -x '*.partial' snapshot "$1" || { echo "  $1 changed"; return 1; }
}

case $mode in
protect)
  mkdir out
  # the result of a single run named like point 1 of the sweep, with its text files
  scene earlier 200 velocity ", t_end = 0.01" "" ""
  sed -i -e "s|'earlier.h5'|'out/s_point0001.h5'|" -e "s|text = .false.|text = .true.|" earlier.nml
  run earlier
  snapshot out
  keep continues out/s.h5 3
  sed -i "s|^&output |\&initial from_file = 'out/s_point0001.h5' /\n\&output |" continues.nml
  for option in --check ''; do
    "$vibrobeam" $option continues.nml > continues.out 2> continues.err
    expect "keep_runs over from_file ($option): exit status 2" exit_is $? 2
    expect "keep_runs over from_file ($option): message" says continues.err \
      "&sweep keep_runs = .true. would write the result of point 1 over &initial from_file 'out/s_point0001.h5'"
  done
  expect 'the file from_file continues and its text files are unchanged' intact out
  # without keep_runs the publication removes the point files of an earlier set
  sed -i "s|keep_runs = .true.|keep_runs = .false.|" continues.nml
  "$vibrobeam" continues.nml > continues.out 2> continues.err
  expect 'removal of from_file: exit status 2' exit_is $? 2
  expect 'removal of from_file: message' says continues.err \
    "publishing the sweep removes the point files 's_pointNNNN.h5' beside it that are not part of its set"
  expect 'the file from_file continues is unchanged' intact out
  # the input itself named like point 2
  keep input out/s.h5 3
  cp input.nml out/s_point0002.h5
  snapshot out
  "$vibrobeam" out/s_point0002.h5 > input.out 2> input.err
  expect 'keep_runs over the input: exit status 2' exit_is $? 2
  expect 'keep_runs over the input: message' says input.err \
    "would write the result of point 2 over the input file 'out/s_point0002.h5'"
  expect 'the input is unchanged' intact out
  ;;
io_error)
  mkdir out
  keep earlier out/s.h5 3 0.5
  run earlier
  expect 'the earlier set is consistent' consistent out/s.h5 3
  snapshot out
  # a point file holds 2500 output rows and field snapshots (about 600 kB): a 120 kB
  # file-size limit lets the journal (about 10 kB) be written, not a point file
  keep limited out/s.h5 3 0.8
  # (PMIX_MCA_gds=hash: an MPI build's MPI_Init keeps its data in shared-memory files,
  # which the limit would refuse)
  (ulimit -f 120; PMIX_MCA_gds=hash exec "$vibrobeam" limited.nml > limited.out 2> limited.err)
  expect 'point file beyond ulimit -f: exit status 1' exit_is $? 1
  expect 'point file beyond ulimit -f: message' says limited.err "File too large"
  expect 'point file beyond ulimit -f: message names the point file' says limited.err "cannot be written"
  expect 'point file beyond ulimit -f: the earlier set is intact' intact out
  expect 'the points done are kept' test -d out/s.h5.partial
  # without the limit the same input finishes; its set replaces the earlier one
  run limited
  expect 'the new set is consistent' consistent out/s.h5 3
  expect 'the partial directory is removed' test ! -e out/s.h5.partial
  # a point file lost from the partial directory: a directory in the way of point 2's
  # stops the sweep (one thread: point 1 done) with an I/O error; without it, and without
  # point 1's file, the rerun runs points 2 and 3 but cannot publish the set: its message
  # says which file is missing, what the directory holds and which journal names the file
  keep lost out/s.h5 3 0.9
  mkdir -p out/s.h5.partial/point0002.h5
  OMP_NUM_THREADS=1 "$vibrobeam" lost.nml > lost.out 2> lost.err
  expect 'a directory in the way in the partial directory: exit status 1' exit_is $? 1
  expect 'a directory in the way in the partial directory: message' says lost.err \
    "the result of point 2 ('out/s_point0002.h5') cannot be written: cannot rename"
  rmdir out/s.h5.partial/point0002.h5 && rm out/s.h5.partial/point0001.h5
  snapshot out
  "$vibrobeam" lost.nml > lost.out 2> lost.err
  expect 'a lost point file: exit status 1' exit_is $? 1
  expect 'a lost point file: message' says lost.err "cannot publish the result of point 1: \
'out/s.h5.partial/point0001.h5' is missing (the directory holds 2 of the 3 point files of the set (missing: 1), \
no temporary file of point 1); the journal 'journal.h5."
  expect 'a lost point file: the journal that names it' says lost.err \
    "(generation 1) holds point 1 (ok) with its file written; the points done are kept in 'out/s.h5.partial'"
  expect 'a lost point file: nothing published' intact out
  rm -rf out/s.h5.partial
  # a directory in the way of point 2
  rm out/s_point0002.h5 && mkdir out/s_point0002.h5
  snapshot out
  keep blocked out/s.h5 3 0.6
  "$vibrobeam" blocked.nml > blocked.out 2> blocked.err
  expect 'a directory in the way: exit status 2' exit_is $? 2
  expect 'a directory in the way: message' says blocked.err "the result file of point 2, 'out/s_point0002.h5', is a directory"
  expect 'a directory in the way: nothing changed' intact out
  ;;
set)
  mkdir out
  keep five out/s.h5 5 0.5
  run five
  expect 'five points: the set is consistent' consistent out/s.h5 5
  keep three out/s.h5 3 0.6
  run three
  expect 'three points after five: the set is the three' consistent out/s.h5 3
  scene none 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', values = 190, 210, settle = 0.01, measure = 0.02 /"
  sed -i "s|'none.h5'|'out/s.h5'|" none.nml
  run none
  expect 'a sweep without keep_runs removes the earlier point files' consistent out/s.h5 0
  # two sweeps of different inputs started together, three times
  keep first out/s.h5 4 0.7 0.3
  keep second out/s.h5 4 0.5 0.3
  for trial in 1 2 3; do
    "$vibrobeam" first.nml > first.out 2> first.err &
    one=$!
    "$vibrobeam" second.nml > second.out 2> second.err &
    two=$!
    wait $one; first_status=$?
    wait $two; second_status=$?
    echo "trial $trial: exit status $first_status and $second_status"
    case "$first_status,$second_status" in
      0,0) ;;
      0,1) expect "trial $trial: the second says why" says second.err "another vibrobeam process is running a sweep" ;;
      1,0) expect "trial $trial: the first says why" says first.err "another vibrobeam process is running a sweep" ;;
      *) echo "FAIL trial $trial: exit status $first_status and $second_status"; cat first.err second.err; failed=1 ;;
    esac
    expect "trial $trial: the set is one sweep's" consistent out/s.h5 4
    rm -rf out/s.h5.partial
  done
  ;;
check)
  # &time t_end = 1e6 s with an output row every step would be 5e10 rows (8 TB) for a run;
  # a sweep ignores it, and its points write nothing but the sweep file
  scene ignored 200 velocity ", t_end = 1e6" ", every = 1" \
    "\&sweep parameter = 'load.point_frequency', values = 190, 210, settle = 0.01, measure = 0.02 /"
  "$vibrobeam" --check ignored.nml > ignored.out 2> ignored.err
  expect 'a t_end the sweep ignores: valid' exit_is $? 0
  # 100 points of 2e4 s with keep_runs and a row every step: 1e11 rows of results
  scene huge 200 velocity "" ", every = 1" \
    "\&sweep parameter = 'load.point_frequency', from = 150, to = 250, count = 100, settle = 1e4, measure = 1e4, keep_runs = .true. /"
  "$vibrobeam" --check huge.nml > huge.out 2> huge.err
  expect 'keep_runs files beyond the size limit: exit status 2' exit_is $? 2
  expect 'keep_runs files beyond the size limit: message' says huge.err "the points' result files of keep_runs"
  # from_file: the result of a scene of 4 elements, which the sweep's 8 cannot continue
  scene four 200 velocity ", t_end = 0.001" "" ""
  sed -i "s|elements = 8|elements = 4|" four.nml
  run four
  scene continues 200 velocity "" "" \
    "\&sweep parameter = 'load.point_frequency', values = 190, 210, settle = 0.01, measure = 0.02 /"
  sed -i "s|^&output |\&initial from_file = 'four.h5' /\n\&output |" continues.nml
  for option in --check ''; do
    "$vibrobeam" $option continues.nml > continues.out 2> continues.err
    expect "from_file it cannot continue ($option): exit status 2" exit_is $? 2
    expect "from_file it cannot continue ($option): message" says continues.err "&initial from_file = 'four.h5'"
  done
  ;;
*)
  echo "unknown mode $mode"; exit 2 ;;
esac
[ $failed -eq 0 ] && echo "run_sweep_file_tests $mode: passed"
exit $failed
