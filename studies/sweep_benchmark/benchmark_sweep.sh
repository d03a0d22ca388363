#!/usr/bin/env bash
# Benchmark of a sweep's parallel runs (studies/sweep_benchmark/REPORT.md): the
# 19-frequency tube sweep of studies/sweep_benchmark/tube_sweep_1g.nml ('independent'
# points) run serially (OMP_NUM_THREADS=1), on every core (OMP_NUM_THREADS=nproc) and on
# 2 MPI ranks of one thread each (mpirun -n 2, the MPI build), each timed as a whole
# command by farm-bench against the serial run (pairs run in turn, the median of 5);
# parallel efficiency = serial time / (workers x parallel time). The three sweep files are
# checked to be identical bit for bit (compare_sweep same). The load of the machine
# (/proc/loadavg, and the CPU time of the other processes during the runs) is recorded.
# Writes studies/sweep_benchmark/sweep_benchmark.txt.
#   usage: studies/sweep_benchmark/benchmark_sweep.sh [BUILD_DIR] [MPI_BUILD_DIR]
#          (directories relative to the repository; default: build, build-mpi)
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
build=${1:-build}
mpi_build=${2:-build-mpi}
table=studies/sweep_benchmark/sweep_benchmark.txt
input=$root/studies/sweep_benchmark/tube_sweep_1g.nml
cores=$(nproc)

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j "$cores" --target vibrobeam compare_sweep > /dev/null
cmake -S . -B "$mpi_build" -DCMAKE_BUILD_TYPE=Release -DVIBROBEAM_MPI=ON > /dev/null
cmake --build "$mpi_build" -j "$cores" --target vibrobeam > /dev/null
vibrobeam=$root/$build/vibrobeam
vibrobeam_mpi=$root/$mpi_build/vibrobeam
compare=$root/$build/verification/compare_sweep

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for name in serial threads mpi; do sed "s|tube_sweep_1g.h5|$name.h5|" "$input" > $name.nml; done

# CPU time (user + system, clock ticks) of every process but ours, from /proc/stat and our own
busy() { awk '/^cpu / {print $2 + $3 + $4 + $7 + $8}' /proc/stat; }
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
busy_before=$(busy); start=$(date +%s.%N)

{
  echo "# sweep benchmark, $(date -u +%Y-%m-%dT%H:%MZ), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $cores cores"
  echo "# input: studies/sweep_benchmark/tube_sweep_1g.nml (19 independent points, 40 + 40 forcing periods each)"
  echo "# load average before: $load_before"
  echo
  echo "## all cores (OMP_NUM_THREADS=$cores) against serial (OMP_NUM_THREADS=1)"
  farm-bench -n 5 --warmup 1 --timeout 1500 \
    --vs "sh -c 'OMP_NUM_THREADS=1 $vibrobeam serial.nml'" \
    -- sh -c "OMP_NUM_THREADS=$cores $vibrobeam threads.nml"
  echo
  echo "## 2 MPI ranks, one thread each (mpirun -n 2, the MPI build) against serial"
  farm-bench -n 5 --warmup 1 --timeout 1500 \
    --vs "sh -c 'OMP_NUM_THREADS=1 $vibrobeam serial.nml'" \
    -- sh -c "OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -n 2 $vibrobeam_mpi mpi.nml"
} > "$work/timings.txt" 2>&1
cat "$work/timings.txt"

busy_after=$(busy); stop=$(date +%s.%N)
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
ticks=$(getconf CLK_TCK)
{
  cat "$work/timings.txt"
  echo
  echo "# load average after: $load_after"
  awk -v b0="$busy_before" -v b1="$busy_after" -v t0="$start" -v t1="$stop" -v hz="$ticks" -v c="$cores" \
    'BEGIN {printf "# all processes used %.2f cores on average over the %.0f s of the benchmark (of %d)\n", (b1 - b0)/hz/(t1 - t0), t1 - t0, c}'
  echo
  echo "## the three sweep files are the same bit for bit"
  "$compare" same serial.h5 threads.h5 | tail -1
  "$compare" same serial.h5 mpi.h5 | tail -1
} > "$root/$table"
echo "benchmark_sweep: written to $table"
