#!/usr/bin/env bash
# Benchmark of the velocity-based time stepper (studies/benchmark/REPORT.md): time
# per step against N = 16..1024 for (a) free flight above a tip obstacle and (b) a beam
# in persistent contact with an obstacle under its whole length, beside one band solve +
# one band matrix-vector product of the same size. Then a cross-check: the vibrobeam
# executable timed with /usr/bin/time on two generated inputs at N = 1024.
#
# Builds Release (-O2) in BUILD_DIR (an existing build directory is switched to
# Release), runs for about a minute and writes studies/benchmark/benchmark_steps.txt.
# The numbers are medians of repeated wall-clock timings: run it on an otherwise idle machine.
#   usage: studies/benchmark/benchmark_steps.sh [BUILD_DIR]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
table=studies/benchmark/benchmark_steps.txt
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

source scripts/build_release.sh
build_release "$build" benchmark_steps vibrobeam
program=$build/studies/benchmark/benchmark_steps
fortran=$(sed -n 's/^CMAKE_Fortran_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")

echo "benchmark_steps: timing (about a minute) ..." >&2
"$program" "$table"

# --- cross-check: the whole executable on generated inputs ----------------------------
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/tip_free_flight.nml" <<NML
! case (a) at N = 1024: free flight in mode 1 above a tip obstacle that is never reached
&mesh      elements = 1024 /
&obstacles count = 1, side(1) = 'below', x_from(1) = 1.0, level_from(1) = -1.0 /
&time      t_end = 0.5, dt = 1e-4 /
&initial   velocity = 'mode', velocity_mode = 1, velocity_amplitude = 0.1 /
&output    file = '$work/tip_free_flight.h5', every = 1000, text = .false. /
NML
cat >"$work/pressed_on_floor.nml" <<NML
! case (b) at N = 1024: pressed onto a floor under the whole beam, from the static equilibrium
&mesh      elements = 1024 /
&obstacles count = 1, side(1) = 'below', x_from(1) = 0.0, x_to(1) = 1.0, level_from(1) = 0.0 /
&load      distributed = -1.0 /
&impact    restitution = 0.0 /
&time      t_end = 0.05, dt = 1e-4 /
&initial   displacement = 'static' /
&output    file = '$work/pressed_on_floor.h5', every = 100, text = .false. /
NML
# run NAME STEPS LABEL [ENV...]: time the executable three times on NAME.nml
run() {
  local name=$1 steps=$2 label=$3 wall user system
  shift 3
  for attempt in 1 2 3; do
    env "$@" /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$build/vibrobeam" "$work/$name.nml" \
      >"$work/run.txt" 2>&1 || echo "(exit status $?)" >>"$work/run.txt"
    read -r wall user system < <(tail -n 1 "$work/time.txt")
    echo "#   $label run $attempt: wall $wall s, user $user s, system $system s," \
      "$(awk -v w="$wall" -v n="$steps" 'BEGIN { printf "%.0f us per step", 1e6 * w / n }');" \
      "$(sed 's/^vibrobeam: //; s/; written to.*//' "$work/run.txt" | tr '\n' ' ')"
  done
}
{
  echo "#"
  echo "# cross-check: $build/vibrobeam on generated inputs, /usr/bin/time, 3 runs each"
  run tip_free_flight 5000 "(a) N = 1024, 5000 steps"
  run tip_free_flight 5000 "(a) N = 1024, 5000 steps, MALLOC_TRIM_THRESHOLD_=256MiB" \
    MALLOC_TRIM_THRESHOLD_=268435456
  run pressed_on_floor 500 "(b) N = 1024, 500 steps"
  # persistent contact: every point's one impact is its onset of contact in the first step
  if command -v h5dump >/dev/null; then
    echo "#   (b) impacts after the first step (t > dt): $(h5dump -d /impacts/time -y -w 1 \
      "$work/pressed_on_floor.h5" | awk '/^ *[0-9]/ { sub(",", ""); if ($1 + 0 > 1.5e-4) n++ } END { print n + 0 }')"
  fi
  echo "#"
  echo "# machine: $(nproc) processors, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')," \
    "load average before the run: $load_before"
  echo "# compiler: $("${fortran:-gfortran}" --version | head -1), Release (-O2)"
  echo "# BLAS/LAPACK: $(ldd "$program" | awk '/blas|lapack/ { print $3 }' | xargs -r readlink -f | tr '\n' ' ')"
  edits=$([ -z "$(git status --porcelain -- src)" ] || echo ' with uncommitted changes in src/')
  echo "# source: git $(git rev-parse --short HEAD)$edits, $(date -u +%Y-%m-%dT%H:%MZ)"
} >>"$table"
echo "benchmark_steps: table written to $table" >&2
