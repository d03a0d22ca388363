#!/usr/bin/env bash
# The linear algebra of a two-plane free-flight step (issue 21; docs/method.md, "Two bending
# planes and tube-support contact"; studies/benchmark/KERNEL_REPORT.md, section 4): per J,
# `benchmark_kernel planes` times, in one run and in interleaved batches, the planar LAPACK
# floor of a step (dsbmv + dpbtrs), the two planes stacked (two dsbmv, one dpbtrs with two
# right-hand sides), the two planes interleaved (dsbmv and dpbtrs of order 2J, half-width
# 7) and a planar free-flight step, and prints their medians and ratios. Under the
# reference BLAS/LAPACK and under OpenBLAS (LD_LIBRARY_PATH, same binary); about 2 minutes.
# Writes studies/benchmark/benchmark_planes.txt.
#   usage: studies/benchmark/benchmark_planes.sh [BUILD_DIR]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
table=studies/benchmark/benchmark_planes.txt
source scripts/build_release.sh
build_release "$build" benchmark_kernel
program=$build/studies/benchmark/benchmark_kernel
libraries=(reference /usr/lib/x86_64-linux-gnu/blas:/usr/lib/x86_64-linux-gnu/lapack
           openblas /usr/lib/x86_64-linux-gnu/openblas-pthread)
{
  echo "# benchmark_kernel planes: studies/benchmark/benchmark_planes.sh, $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores"
  for ((l = 0; l < ${#libraries[@]}; l += 2)); do
    export LD_LIBRARY_PATH=${libraries[l + 1]}
    echo "## ${libraries[l]} BLAS/LAPACK (load average before: $(cut -d' ' -f1-3 /proc/loadavg))"
    OPENBLAS_NUM_THREADS=1 "$program" planes
  done
} | tee "$table"
