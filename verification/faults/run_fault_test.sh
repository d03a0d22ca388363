#!/usr/bin/env bash
# Fault tests of the result files (docs/output.md, "How a result is published", "After a
# kill"): each case puts an earlier complete result set at the target, runs vibrobeam into
# a fault, and checks the exit status and message, that the earlier results are intact
# or a complete new set replaced them, and that no temporary file is left (the documented
# files of a SIGKILL excepted). Result files are checked with h5py (check_result.py).
#
# usage: run_fault_test.sh CASE VIBROBEAM
# CASE: output_is_input | output_is_directory | full_disk | concurrent | sigint_stepping |
#       sigterm_stepping | sigkill_stepping | sigint_publishing | sigkill_publishing
# Exit status 0 pass, 1 fail, 77 skipped (no python3 with h5py; ctest SKIP_RETURN_CODE).
set -uo pipefail
case_name=$1
vibrobeam=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
here=$(cd "$(dirname "$0")" && pwd)

python=$("$here/../support/python_h5py.sh") || exit 77   # (it says why)

work=$(mktemp -d)
mounted=''
cleanup() {
  [ -n "$mounted" ] && umount "$mounted" 2> /dev/null
  rm -rf "$work"
}
trap cleanup EXIT
cd "$work"

passed=0
failed=0
check() {  # check DESCRIPTION COMMAND...
  local description=$1
  shift
  if "$@"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAIL $description"
  fi
}
finish() {
  echo "run_fault_test $case_name: $passed passed, $failed failed"
  [ "$failed" -eq 0 ]
  exit $?
}

# scene FILE NAME T_END [RESTITUTION TEXT CHECKPOINT FROM_FILE]: write NAME.nml
scene() {
  sed -e "s|@FILE@|$1|" -e "s|@T_END@|$3|" -e "s|@RESTITUTION@|${4:-0.8}|" \
      -e "s|@TEXT@|${5:-.true.}|" -e "s|@CHECKPOINT@|${6:-0}|" \
      -e "s|@FROM_FILE@|${7:+, from_file = '$7'}|" "$here/scene.nml.in" > "$2.nml"
}

# An earlier complete result set at TARGET (a short run, e = 0.5), and a copy to compare.
earlier() {  # earlier TARGET
  scene "$1" earlier 0.02 0.5
  "$vibrobeam" earlier.nml > /dev/null 2> earlier.err || { echo "FAIL earlier run"; cat earlier.err; exit 1; }
  mkdir -p snapshot
  cp "${1%.h5}".h5 "${1%.h5}"_*.dat snapshot/
}
intact() {  # intact TARGET: every file of the earlier set unchanged, no other file beside it
  local file ok=0
  for file in snapshot/*; do
    cmp -s "$file" "$(dirname "$1")/$(basename "$file")" || { echo "  changed: $(basename "$file")"; ok=1; }
  done
  [ "$(ls "$(dirname "$1")" | grep -c -v '\.tmp$')" -eq "$(ls snapshot | wc -l)" ] || \
    { echo "  files now: $(ls "$(dirname "$1")")"; ok=1; }
  return $ok
}
no_temporary() {  # no_temporary DIR
  [ -z "$(find "$1" -name '*.tmp')" ] || { echo "  left: $(find "$1" -name '*.tmp')"; return 1; }
}
status_is() { [ "$1" -eq "$2" ] || { echo "  exit status $1, expected $2"; return 1; }; }
says() { grep -q -F -- "$2" "$1" || { echo "  $1 does not say '$2':"; cat "$1"; return 1; }; }
not_says() { ! grep -q -F -- "$2" "$1" || { echo "  $1 says '$2':"; cat "$1"; return 1; }; }

# Start vibrobeam on NAME.nml in the background; wait until its stderr says PATTERN.
start_until() {  # start_until NAME PATTERN TIMEOUT_S
  "$vibrobeam" "$1.nml" > "$1.out" 2> "$1.err" &
  pid=$!
  local waited=0
  until grep -q -- "$2" "$1.err" 2> /dev/null; do
    sleep 0.05
    waited=$((waited + 1))
    if [ $waited -gt $(($3 * 20)) ] || ! kill -0 $pid 2> /dev/null; then
      echo "FAIL '$2' did not appear in $1.err"
      cat "$1.err"
      return 1
    fi
  done
}

case $case_name in
output_is_input)
  mkdir out
  scene out/input.nml out/input 0.02
  cp out/input.nml before.nml
  "$vibrobeam" out/input.nml > run.out 2> run.err
  check 'exit status 2' status_is $? 2
  check 'message names &output file and the input' says run.err "&output file = 'out/input.nml' is the input file"
  check 'the input is unchanged' cmp -s out/input.nml before.nml
  check 'nothing else written' test "$(ls out)" = input.nml
  ;;
output_is_directory)
  earlier out/run.h5
  mkdir out/run_dir.h5
  scene out/run_dir.h5 run 0.02
  "$vibrobeam" run.nml > run.out 2> run.err
  check 'exit status 2' status_is $? 2
  check 'message says it is a directory' says run.err "&output file = 'out/run_dir.h5' is a directory"
  rmdir out/run_dir.h5
  check 'earlier results intact' intact out/run.h5
  ;;
full_disk)
  # Three moments: the temporary file cannot grow at all (a file-size limit, `ulimit -f`),
  # the disk fills while stepping, and while the result is published. The disk is a tmpfs
  # holding earlier results, filled up (fallocate) once the run is at that moment, so that
  # a check of the free space before the run cannot see it coming; where mounting is not
  # allowed, a file-size limit below the HDF5 file (stepping) or below a .dat file
  # (publishing) instead.
  scene probe/run.h5 probe 1.0 0.8 .true. 0.2   # the ulimit run below, on a disk with room
  "$vibrobeam" probe.nml > /dev/null 2>&1 || { echo "FAIL probe run"; exit 1; }
  h5_kb=$(( $(stat -c %s probe/run.h5) / 1024 + 1 ))
  largest_dat_kb=$(( $(ls -S probe/run_*.dat | head -1 | xargs stat -c %s) / 1024 ))
  mkdir disk
  # (FULL_DISK_METHOD=ulimit tries the fall-back where mounting works)
  if [ "${FULL_DISK_METHOD:-tmpfs}" = tmpfs ] && mount -t tmpfs -o size=256m tmpfs disk 2> /dev/null; then
    mounted=$work/disk
    method=tmpfs
  else
    method=ulimit
  fi
  echo "full disk by $method"
  for moment in start stepping publishing; do
    rm -rf snapshot
    [ $method = tmpfs ] && { umount disk; mount -t tmpfs -o size=256m tmpfs disk; }
    earlier disk/run.h5
    if [ $method = tmpfs ] && [ $moment != start ]; then
      if [ $moment = stepping ]; then   # a long run with few outputs: still stepping after 1 s (and
                                        # far longer: it ends at the first flush after the disk is full)
        scene disk/run.h5 run 400 0.8 .true. 0.2
        sed -i 's/every = 3, field_every = 20/every = 3000, field_every = 30000/' run.nml
        start_until run '%  t =' 60 || exit 1
      else                              # many outputs: the text takes seconds to derive
        scene disk/run.h5 run 1.0 0.8 .true. 0.2
        sed -i 's/every = 3, field_every = 20/every = 1, field_every = 1/' run.nml
        start_until run 'publishing' 60 || exit 1
      fi
      fallocate -l "$(df -k --output=avail disk | tail -1)k" disk/filler 2> /dev/null ||
        dd if=/dev/zero of=disk/filler bs=64k 2> /dev/null
      wait $pid
      code=$?
      rm -f disk/filler
      reason='No space left on device'
    else
      case $moment in
        start) limit=1 ;;
        stepping) limit=$((h5_kb / 2)) ;;
        publishing) limit=$((h5_kb + 4)) ;;   # the result fits, its largest .dat does not
      esac
      if [ $moment = publishing ] && [ $largest_dat_kb -le $limit ]; then
        echo "FAIL the largest .dat file ($largest_dat_kb kB) fits under the limit"
        failed=$((failed + 1))
        continue
      fi
      scene disk/run.h5 run 1.0 0.8 .true. 0.2
      (ulimit -f $limit; exec "$vibrobeam" run.nml > run.out 2> run.err)
      code=$?
      reason='File too large'
    fi
    check "$moment: exit status 1" status_is $code 1
    check "$moment: message gives the reason" says run.err "$reason"
    check "$moment: message says nothing was published" says run.err "nothing published"
    check "$moment: earlier results intact" intact disk/run.h5
    check "$moment: no temporary file left" no_temporary disk
    case $moment in
      stepping) check "$moment: the failure came while stepping" not_says run.err "publishing" ;;
      publishing) check "$moment: the failure came while publishing" says run.err "publishing" ;;
    esac
  done
  ;;
concurrent)
  earlier out/run.h5
  for k in 1 2 3; do
    scene out/run.h5 run$k 0.4 0.$((k + 5))
    "$vibrobeam" run$k.nml > run$k.out 2> run$k.err &
    pids[$k]=$!
  done
  for k in 1 2 3; do
    wait ${pids[$k]}
    check "run $k: exit status 0" status_is $? 0
  done
  check 'one complete, consistent set' "$python" "$here/check_result.py" complete out/run.h5 ok
  run_id=$("$python" -c "import h5py; print(h5py.File('out/run.h5')['run'].attrs['run_id'].decode())")
  check 'the set is one of the three runs' grep -q -F "$run_id" run1.out run2.out run3.out
  check 'no temporary file left' no_temporary out
  ;;
sigint_stepping | sigterm_stepping)
  signal=${case_name%_stepping}
  earlier out/run.h5
  scene out/run.h5 run 100
  start_until run '%  t =' 20 || exit 1
  kill -${signal^^} $pid
  wait $pid
  code=$?
  check 'exit status 4' status_is $code 4
  check 'message names the signal' says run.err "interrupted by ${signal^^}"
  check 'a complete new set, status interrupted' "$python" "$here/check_result.py" complete out/run.h5 interrupted
  check 'no temporary file left' no_temporary out
  ;;
sigkill_stepping)
  # Kills at three moments; checkpoints (and so flushes) every 0.1 s. The temporary file
  # must open and hold the start of the uninterrupted run; a run continued from the
  # checkpoint of the latest kill that left one must end like the uninterrupted run.
  earlier out/run.h5
  # the continuation below uses the latest kill whose file holds a checkpoint (on a loaded
  # machine the last kill may still come before the run's first one; a fourth kill, 2 s in,
  # is made only when none of the three left a checkpoint)
  kept_checkpoint=''
  for kill_after in 0.$((RANDOM % 2 + 3)) 0.$((RANDOM % 3 + 5)) 0.$((RANDOM % 2 + 8)) 2; do
    [ "$kill_after" = 2 ] && [ -n "$kept_checkpoint" ] && break
    rm -f out/*.tmp
    scene out/run.h5 run 100 0.8 .true. 0.1
    "$vibrobeam" run.nml > run.out 2> run.err &
    pid=$!
    # the moment counts from the run's temporary file (it exists once the run has read and
    # checked its input and created its datasets): on a loaded machine 0.3 s after the
    # start the run may not have got that far, and a kill then tests nothing (no file)
    for _ in $(seq 200); do
      compgen -G 'out/run.h5.*.tmp' > /dev/null && break
      sleep 0.05
    done
    sleep "$kill_after"
    kill -KILL $pid
    wait $pid 2> /dev/null
    partial=$(ls out/run.h5.*.tmp 2> /dev/null | head -1)
    check "kill after $kill_after s: earlier results intact" intact out/run.h5
    check "kill after $kill_after s: only the documented partial file is left" \
      test "$(find out -name '*.tmp' | wc -l)" -eq 1
    [ -n "$partial" ] || continue
    read -r flushed checkpoint current < <("$python" "$here/check_result.py" flushed_step "$partial")
    echo "killed after $kill_after s: flushed at step $flushed, checkpoint at step $checkpoint (slot $current)"
    if [ "$current" -gt 0 ]; then
      cp "$partial" killed.h5
      kept_checkpoint=$checkpoint
    fi
    # the uninterrupted run, a little beyond the flushed part
    scene reference/run.h5 reference "$(echo "($flushed + 1000) * 0.00002" | bc -l)" 0.8 .false.
    "$vibrobeam" reference.nml > /dev/null 2>&1
    check "kill after $kill_after s: the partial file is the start of the uninterrupted run" \
      "$python" "$here/check_result.py" partial "$partial" reference/run.h5
  done
  if [ -n "$kept_checkpoint" ]; then
    t_end=$(echo "($kept_checkpoint + 5000) * 0.00002" | bc -l)
    scene continued/run.h5 continued "$t_end" 0.8 .false. 0 killed.h5
    "$vibrobeam" continued.nml > continued.out 2> continued.err
    check 'the continued run succeeds' status_is $? 0
    scene reference/full.h5 full "$t_end" 0.8 .false.
    "$vibrobeam" full.nml > /dev/null 2>&1
    check 'the continued run ends like the uninterrupted run' \
      "$python" "$here/check_result.py" continued continued/run.h5 reference/full.h5
  else
    check 'a kill came after a checkpoint (the last, 2 s after the start)' false
  fi
  ;;
sigint_publishing | sigkill_publishing)
  # every output of a long run makes the text derivation last long enough to be hit
  earlier out/run.h5
  scene out/run.h5 run 0.4
  sed -i 's/every = 3, field_every = 20/every = 1, field_every = 1/' run.nml
  start_until run 'publishing' 60 || exit 1
  if [ $case_name = sigint_publishing ]; then
    kill -INT $pid
    wait $pid
    check 'exit status 4' status_is $? 4
    check 'message says the text files were skipped' says run.err 'published without them'
    check 'the message came while deriving' says run.err 'while deriving the text files'
    check 'the new result is published, complete, status ok' \
      "$python" "$here/check_result.py" complete out/run.h5 ok --no-text
    check 'no .dat file of the earlier run is left beside it' test -z "$(ls out/*.dat 2> /dev/null)"
    check 'no temporary file left' no_temporary out
    "$vibrobeam" --text out/run.h5 > text.out 2> text.err
    check 'vibrobeam --text derives them afterwards' "$python" "$here/check_result.py" complete out/run.h5 ok
  else
    kill -KILL $pid
    wait $pid 2> /dev/null
    check 'earlier results intact' intact out/run.h5
    left=$(find out -name '*.tmp' | grep -v -E '/run\.h5\.[0-9]+-[0-9a-f]{8}\.tmp$|/run_[a-z]+\.dat\.[0-9]+-[0-9a-f]{8}\.tmp$')
    check 'only the documented temporary files are left' test -z "$left"
  fi
  ;;
*)
  echo "unknown case $case_name"
  exit 2
  ;;
esac
finish
