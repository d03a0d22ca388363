#!/usr/bin/env bash
# A continuation's result does not depend on the number of threads (docs/method.md,
# "Continuation of periodic orbits", "Threads"): the columns of the monodromy by finite
# differences run on OpenMP threads, each an evaluation of its own, so the branch (every
# dataset and attribute of /periodic: points, multipliers, bifurcations, steps_taken)
# must be the same bit for bit on 1 and on 3 threads (3: more threads than cores here,
# and columns dealt unevenly). The scene must take its monodromy by differences (checked:
# /periodic monodromy), else the threads would not be exercised.
# usage: continuation_threads.sh VIBROBEAM SCENE.nml WORK_DIRECTORY
set -euo pipefail
vibrobeam=$1; scene=$2; work=$3
rm -rf "$work" && mkdir -p "$work"
stem=$(sed -n "s/.*file *= *'\([^']*\)\.h5'.*/\1/p" "$scene")
for threads in 1 3; do
  mkdir "$work/$threads"
  (cd "$work/$threads" && OMP_NUM_THREADS=$threads "$vibrobeam" "$scene" > run.out 2>&1) ||
    { echo "FAIL vibrobeam on $threads thread(s):"; cat "$work/$threads/run.out"; exit 1; }
done
h5dump -a /periodic/monodromy "$work/1/$stem.h5" | grep -q '"differences"' ||
  { echo "FAIL the scene's monodromy is not by differences: the threads were not exercised"; exit 1; }
if h5diff -c "$work/1/$stem.h5" "$work/3/$stem.h5" /periodic; then
  echo "ok   /periodic on 1 and 3 threads: the same, bit for bit ($(grep -o 'branch of [0-9]* periodic orbits' "$work/1/run.out"))"
else
  echo "FAIL /periodic differs between 1 and 3 threads"; exit 1
fi
