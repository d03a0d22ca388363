#!/usr/bin/env bash
# What `vibrobeam --check` estimates against what the run then does (docs/input.md, "What
# --check prints"; issue 24 item 6), for each input given:
#  - the result size: within 30 % of the bytes of every file the run leaves (the HDF5
#    file, its .dat files, a sweep's point files); for a sweep of branches at most 30 %
#    below them (each branch is sized at max_points points, and may end sooner);
#  - the steps: exactly those the run made (a run's /run steps; a sweep's sum of
#    (transient + window)/dt over its points, which --check prints as 'steps in all');
#  - the time: the estimated CPU seconds against the CPU time the run took (user + system,
#    bash's `time`), printed, not asserted: a timing on a shared machine is no test
#    (CONTRIBUTING.md); docs/input.md keeps the measured table.
# usage: check_estimates.sh VIBROBEAM [--reduce] INPUT.nml...   (one table row per input)
#   --reduce  a sweep runs 3 values of its parameter (2 of parameter2) over windows of 10
#             forcing periods, a sweep of branches 5 points a branch (the fast suite's
#             version of the bundled sweeps)
set -uo pipefail
vibrobeam=$1; shift
reduce=0
if [ "${1:-}" = --reduce ]; then reduce=1; shift; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
printf '%-28s %12s %12s %6s %12s %12s %9s %9s %6s\n' input 'size est' 'size real' ratio 'steps est' 'steps real' 'CPU est' 'CPU real' ratio
for input in "$@"; do
  name=$(basename "$input" .nml)
  rm -rf "$work"/* && mkdir -p "$work/results" && cp "$input" "$work/input.nml"
  # the tables a scene reads (&forces table, psd_table) lie beside it, named relative to
  # it; they are copied beside the copy and not counted as written
  tables=()
  for table in "$(dirname "$input")"/*.dat; do
    [ -e "$table" ] && cp "$table" "$work/" && tables+=(! -name "$(basename "$table")")
  done
  if [ $reduce = 1 ] && grep -q '^&sweep' "$input"; then
    sed -i -e '/^&sweep/,$ s/\bcount = [0-9]*/count = 3/' -e '/^&sweep/,$ s/count2 = [0-9]*/count2 = 2/' \
           -e '/^&sweep/,$ s/settle_periods = [0-9]*/settle_periods = 10/' \
           -e '/^&sweep/,$ s/measure_periods = [0-9]*/measure_periods = 10/' "$work/input.nml"
    # a sweep of branches: 5 points a branch
    sed -i -e 's/max_points = [0-9]*/max_points = 5/' "$work/input.nml"
    name="$name (reduced)"
  fi
  cd "$work" || exit 1
  "$vibrobeam" --check input.nml > check.txt 2> check.err || { echo "FAIL $name: --check failed"; cat check.err; failed=1; continue; }
  size=$(sed -n 's/^estimated result size: \([0-9.e+]*\) bytes.*/\1/p' check.txt)
  steps=$(sed -n 's/^cost: \([0-9.e+]*\) steps in all.*/\1/p' check.txt)
  cpu=$(sed -n 's/^cost: .*, about \([0-9.e+-]*\) s of CPU on one core.*/\1/p' check.txt)
  kind=$(sed -n "s/^ *analysis.kind *= *'\([a-z]*\)'.*/\1/p" check.txt)
  TIMEFORMAT='%U %S'
  { time "$vibrobeam" input.nml > run.txt 2> run.err; } 2> time.txt
  status=$?
  [ $status -eq 0 ] || { echo "FAIL $name: the run exited $status"; cat run.err; failed=1; cd - > /dev/null; continue; }
  cpu_real=$(tail -1 time.txt | awk '{print $1 + $2}')
  # the files the run left: every file but the input and what this script keeps
  written=$(find . -type f ! -name input.nml ! -name check.txt ! -name check.err ! -name run.txt ! -name run.err \
            ! -name time.txt "${tables[@]}" -exec cat {} + | wc -c)
  result=$(sed -n "s/^ *output.file *= *'\(.*\)'.*/\1/p" check.txt)
  listing=$(h5dump -n "$result" 2> /dev/null || true)   # (a here-string: grep -q would cut a pipe, pipefail)
  if grep -q ' /sweep/parameter$' <<< "$listing" && [ "$kind" != periodic ]; then
    dt=$(h5dump -m '%.17g' -a '/time.dt' "$result" | sed -n 's/.*(0): *\(.*\)$/\1/p')
    real_steps=$(h5dump -m '%.17g' -d /sweep/transient -d /sweep/window -y -w 1 "$result" |
                 awk -v dt="$dt" '/^ *[0-9.eE+-]+,? *$/ {gsub(",", ""); s += $1} END {printf "%d", s / dt + 0.5}')
  elif [ "$kind" = dynamics ] || [ -z "$kind" ]; then
    real_steps=$(h5dump -a /run/steps "$result" | sed -n 's/.*(0): *\(.*\)$/\1/p')
    steps=$(sed -n 's/^estimated result size: .*): \([0-9.e+]*\) steps, .*/\1/p' check.txt)
  else
    real_steps=0; steps=0
  fi
  ratio=$(awk -v e="$size" -v w="$written" 'BEGIN {printf "%.3f", (e > 0 ? w / e : 0)}')
  time_ratio=$(awk -v e="${cpu:-0}" -v w="$cpu_real" 'BEGIN {if (e > 0) printf "%.2f", w / e; else printf "-"}')
  printf '%-28s %12.4g %12d %6s %12s %12s %9s %9.2f %6s\n' "$name" "$size" "$written" "$ratio" "$steps" "$real_steps" \
    "${cpu:--}" "$cpu_real" "$time_ratio"
  # a sweep of branches: --check sizes each branch at max_points points, and a branch may
  # end sooner (at its bound), so its estimate is an upper bound only
  lowest=$(awk 'BEGIN {printf "%.6f", 1/1.3}')
  if [ "$kind" = periodic ] && grep -q ' /sweep/parameter$' <<< "$listing"; then lowest=0; fi
  if ! awk -v r="$ratio" -v low="$lowest" 'BEGIN {exit !(r >= low && r <= 1.3)}'; then
    echo "FAIL $name: the run wrote $written bytes, --check estimated $size (ratio $ratio, allowed [$lowest, 1.3])"
    failed=1
  fi
  # (a periodic analysis steps as many orbits as Newton's method needs: not estimated)
  if [ "$kind" != modes ] && [ "$kind" != static ] && [ "$kind" != periodic ]; then
    if ! awk -v a="$steps" -v b="$real_steps" 'BEGIN {exit !(a + 0 == b + 0 && b > 0)}'; then
      echo "FAIL $name: --check counted $steps steps, the run made $real_steps"; failed=1
    fi
  fi
  cd - > /dev/null || exit 1
done
[ $failed -eq 0 ] && echo "check_estimates: every estimate within its bound"
exit $failed
