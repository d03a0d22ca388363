#!/usr/bin/env bash
# Benchmark of the band kernel of bandwidth 3 and of the natural modes
# (studies/benchmark/KERNEL_REPORT.md). Under the reference BLAS/LAPACK and under
# OpenBLAS (chosen with LD_LIBRARY_PATH, same binary):
#  1. wall clock: LAPACK dpbtrs + BLAS dsbmv against band_solve + band_matvec (the kd = 3
#     kernels), against band_residual_solve (the two fused in one pass) and against one
#     free-flight step of the velocity stepper as it is today, J = 40 ... 1e5;
#  2. callgrind: instructions per call of the same three workloads (repeatable where the
#     wall clock is not), as (Ir(2C calls) - Ir(C calls))/C, which removes the set-up;
#  3. memcheck: heap allocations per call, counted the same way, at J = 400;
#  4. natural modes: compute_modes by Lanczos (N = 1e3, 1e4, 1e5) and by the dense path
#     (N = 100, 300, 1000, 3000), wall time and peak memory (/usr/bin/time), and
#     `kind = 'modes'` runs of the vibrobeam executable at N = 1000, 3000, 1e4, 1e5;
#  5. the crossover table of the two modes paths (dense_is_cheaper).
# Builds Release (-O2) in BUILD_DIR, runs for about 10 minutes (valgrind, the dense path at
# N = 3000) and writes studies/benchmark/benchmark_kernel.txt.
#   usage: studies/benchmark/benchmark_kernel.sh [BUILD_DIR]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
table=studies/benchmark/benchmark_kernel.txt
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

source scripts/build_release.sh
build_release "$build" benchmark_kernel vibrobeam
program=$build/studies/benchmark/benchmark_kernel
fortran=$(sed -n 's/^CMAKE_Fortran_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
libraries=(reference /usr/lib/x86_64-linux-gnu/blas:/usr/lib/x86_64-linux-gnu/lapack
           openblas /usr/lib/x86_64-linux-gnu/openblas-pthread)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# instructions WORKLOAD J CALLS: callgrind's instruction count of `count WORKLOAD J CALLS`
instructions() {
  OPENBLAS_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" \
    "$program" count "$@" 2>&1 | sed -n 's/.*Collected : *//p'
}
# allocations WORKLOAD J CALLS: memcheck's count of heap allocations of the same run
allocations() {
  OPENBLAS_NUM_THREADS=1 valgrind --tool=memcheck "$program" count "$@" 2>&1 |
    sed -n 's/.*total heap usage: \([0-9,]*\) allocs.*/\1/p' | tr -d ,
}
# median of the numbers on standard input
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# timed RUNS COMMAND...: "median wall s (min .. max), median peak RSS MB" over RUNS runs
timed() {
  local runs=$1 r
  shift
  : >"$work/times"
  for ((r = 0; r < runs; r++)); do
    /usr/bin/time -f "%e %M" -o "$work/time" "$@" >"$work/out" 2>&1 || { cat "$work/out" >&2; return 1; }
    cat "$work/time" >>"$work/times"
  done
  printf '%s s (%s .. %s), peak %s MB' "$(cut -d' ' -f1 "$work/times" | median)" \
    "$(cut -d' ' -f1 "$work/times" | sort -g | head -1)" "$(cut -d' ' -f1 "$work/times" | sort -g | tail -1)" \
    "$(cut -d' ' -f2 "$work/times" | median | awk '{ printf "%.1f", $1 / 1024 }')"
}

{
  echo "# benchmark_kernel: studies/benchmark/benchmark_kernel.sh, $(date -u +%Y-%m-%dT%H:%MZ)"
  for ((l = 0; l < ${#libraries[@]}; l += 2)); do
    name=${libraries[l]}
    export LD_LIBRARY_PATH=${libraries[l + 1]}
    echo "#"
    echo "## $name BLAS/LAPACK: $(ldd "$program" | awk '/libblas|liblapack/ { print $3 }' | xargs -r readlink -f | tr '\n' ' ')"
    echo "### 1. wall clock (load average before: $(cut -d' ' -f1-3 /proc/loadavg))"
    "$program" kernel
    echo "### 2. callgrind: instructions per call (OPENBLAS_NUM_THREADS=1)"
    printf '%8s %8s %14s %14s %14s %14s %13s %13s %13s\n' J calls dpbtrs+dsbmv solve+matvec fused step \
      'ratio kernel' 'ratio fused' 'ratio step'
    for J in 40 200 400 2000 10000 100000; do
      calls=$((400000 / J))
      ((calls < 10)) && calls=10
      per=()
      for w in lapack kernel fused step; do
        one=$(instructions $w $J $calls)
        two=$(instructions $w $J $((2 * calls)))
        per+=("$(awk -v a="$one" -v b="$two" -v c="$calls" 'BEGIN { printf "%.0f", (b - a) / c }')")
      done
      awk -v J=$J -v c=$calls -v l="${per[0]}" -v k="${per[1]}" -v f="${per[2]}" -v s="${per[3]}" \
        'BEGIN { printf "%8d %8d %14d %14d %14d %14d %13.3f %13.3f %13.3f\n", J, c, l, k, f, s, k / l, f / l, s / l }'
    done
    echo "### 3. memcheck: heap allocations per call at J = 400 ((allocs(200 calls) - allocs(100 calls))/100)"
    for w in lapack kernel fused step; do
      one=$(allocations $w 400 100)
      two=$(allocations $w 400 200)
      echo "$w: $(awk -v a="$one" -v b="$two" 'BEGIN { printf "%g", (b - a) / 100 }') per call ($one allocations for 100 calls, $two for 200)"
    done
    echo "### 4. natural modes, 6 modes, k2 = 1, L = 1 (/usr/bin/time; compute_modes alone in benchmark_kernel)"
    for N in 1000 10000 100000; do
      echo "lanczos hermite N = $N: $(timed 5 "$program" modes lanczos hermite $N 6)"
    done
    echo "lanczos bspline N = 100000: $(timed 5 "$program" modes lanczos bspline 100000 6)"
    for N in 100 300 1000; do
      echo "dense hermite N = $N: $(timed 3 "$program" modes dense hermite $N 6)"
    done
    echo "dense hermite N = 3000: $(timed 1 "$program" modes dense hermite 3000 6)"
    echo "#### kind = 'modes', steel cantilever (inputs/cantilever_modes.nml with N elements), whole executable, 3 runs"
    for N in 1000 3000 10000 100000; do
      for text in .true. .false.; do
        cat >"$work/modes.nml" <<NML
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9 /
&mesh      elements = $N /
&analysis  kind = 'modes', modes = 6 /
&output    file = '$work/modes.h5', text = $text /
NML
        echo "N = $N, text = $text: $(timed 3 "$build/vibrobeam" "$work/modes.nml")"
      done
    done
    echo "### 5. crossover of the modes paths"
    "$program" crossover
  done
  echo "#"
  echo "# machine: $(nproc) processors, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')," \
    "load average before the run: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# compiler: $("${fortran:-gfortran}" --version | head -1), Release (-O2)"
  edits=$([ -z "$(git status --porcelain -- src)" ] || echo ' with uncommitted changes in src/')
  echo "# source: git $(git rev-parse --short HEAD)$edits"
} | tee "$table"
echo "benchmark_kernel: written to $table" >&2
