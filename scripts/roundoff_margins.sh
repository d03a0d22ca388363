#!/usr/bin/env bash
# How much room the test suite's round-off tolerances leave on each BLAS/LAPACK library:
# runs the fast suite of a build (default build/) with VIBROBEAM_CHECK_RATIOS=1 on the
# reference BLAS and on OpenBLAS (its own kernel choice, then the Haswell and SkylakeX
# kernels when this processor has them; 1 thread, then 2), and prints for every test the
# largest |value - reference| / tolerance over its checks (1 would be a failure).
# usage: bash scripts/roundoff_margins.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
multiarch=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
reference="/usr/lib/$multiarch/blas:/usr/lib/$multiarch/lapack"
openblas="/usr/lib/$multiarch/openblas-pthread"
runs=("reference|$reference||1")
if [ -d "$openblas" ]; then
  runs+=("openblas|$openblas||1" "openblas-2-threads|$openblas||0")
  if grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then runs+=("openblas-haswell|$openblas|Haswell|1"); fi
  if grep -qw avx512f /proc/cpuinfo; then runs+=("openblas-skylakex|$openblas|SkylakeX|1" "openblas-skylakex-2-threads|$openblas|SkylakeX|0"); fi
fi
table=$(mktemp)
trap 'rm -f "$table"' EXIT
for run in "${runs[@]}"; do
  IFS='|' read -r name path core threads <<< "$run"
  environment=(env -u OPENBLAS_CORETYPE LD_LIBRARY_PATH="$path" VIBROBEAM_CHECK_RATIOS=1 VIBROBEAM_BLAS_THREADS="$threads"
               OPENBLAS_NUM_THREADS=2)
  [ -n "$core" ] && environment+=(OPENBLAS_CORETYPE="$core")
  "${environment[@]}" ctest --test-dir "$build" -LE long -V 2>/dev/null |
    awk -v run="$name" '
      $2 == "ratio" { id = $1; sub(/:$/, "", id); if ($3 + 0 > worst[id]) worst[id] = $3 + 0 }
      $2 == "Test" && $3 ~ /^#/ { id = $3; sub(/^#/, "", id); sub(/:$/, "", id); name[id] = $4 }
      END { for (k in name) printf "%s %s %.3e\n", name[k], run, worst[k] + 0 }' >> "$table"
done
printf '%-60s' test
for run in "${runs[@]}"; do printf ' %12.12s' "${run%%|*}"; done
printf '\n'
for test in $(cut -d' ' -f1 "$table" | sort -u); do
  printf '%-60s' "$test"
  for run in "${runs[@]}"; do
    printf ' %12s' "$(awk -v t="$test" -v r="${run%%|*}" '$1 == t && $2 == r { print $3 }' "$table")"
  done
  printf '\n'
done
