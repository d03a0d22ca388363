#!/usr/bin/env bash
# Memory does not grow with the length of a run (docs/output.md, "Streaming"): the peak
# resident set size (getrusage, /run peak_memory_kb) of a run of LONG steps stays within
# RATIO times that of a run of SHORT steps of the same scene (the fault-test scene: an
# output row every 3 steps, a field snapshot every 20, two observation points, impacts).
# usage: run_memory_test.sh VIBROBEAM SHORT LONG RATIO
set -euo pipefail
vibrobeam=$1; short=$2; long=$3; ratio=$4
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
peak() {  # peak STEPS: run the scene for STEPS steps, print its peak RSS (kB)
  sed -e "s|@FILE@|run$1.h5|" -e "s|@T_END@|$(awk "BEGIN {print $1 * 2e-5}")|" -e "s|@RESTITUTION@|0.8|" \
      -e "s|@TEXT@|.false.|" -e "s|@CHECKPOINT@|0|" -e "s|@FROM_FILE@||" -e "s|progress = .true.|progress = .false.|" \
      "$here/../faults/scene.nml.in" > run$1.nml
  "$vibrobeam" run$1.nml > /dev/null
  h5dump -a /run/peak_memory_kb run$1.h5 | sed -n 's/.*(0): *\([0-9]*\).*/\1/p'
}
small=$(peak "$short")
large=$(peak "$long")
echo "peak resident set: $small kB for $short steps, $large kB for $long steps (ratio $(awk "BEGIN {printf \"%.3f\", $large / $small}"), limit $ratio)"
awk "BEGIN {exit !($large <= $ratio * $small)}" || { echo "FAIL memory grows with the number of steps"; exit 1; }
echo "run_memory_test: 1 passed, 0 failed"
