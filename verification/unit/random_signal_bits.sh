#!/usr/bin/env bash
# The random signals of a scene are the same bits on 1 and 2 OpenMP threads and on every
# BLAS/LAPACK library installed (docs/method.md, "Random signals"): random_signal_digest
# prints the CRC-64 of the random signals at 2^15 steps; it runs here with OMP_NUM_THREADS=1 on the
# reference BLAS/LAPACK and with OMP_NUM_THREADS=2 on OpenBLAS (each that is installed, as
# CI installs both), and all the digests must agree. Prints them.
# usage: random_signal_bits.sh DIGEST_PROGRAM SCENE.nml
set -uo pipefail
program=$1; scene=$2
multiarch=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
reference="/usr/lib/$multiarch/blas:/usr/lib/$multiarch/lapack"
openblas="/usr/lib/$multiarch/openblas-pthread"
digests=()
run() {
  local label=$1 output
  shift
  output=$(env "$@" "$program" "$scene") || { echo "FAIL $label: $output"; exit 1; }
  echo "$label: $output"
  digests+=("${output##* }")
}
run "default library, OMP_NUM_THREADS=1" OMP_NUM_THREADS=1
[ -d "/usr/lib/$multiarch/blas" ] && run "reference BLAS, OMP_NUM_THREADS=1" OMP_NUM_THREADS=1 LD_LIBRARY_PATH="$reference"
[ -d "$openblas" ] && run "OpenBLAS, OMP_NUM_THREADS=2" OMP_NUM_THREADS=2 LD_LIBRARY_PATH="$openblas"
for digest in "${digests[@]}"; do
  [ "$digest" = "${digests[0]}" ] || { echo "FAIL the digests differ"; exit 1; }
done
echo "random_signal_bits: ${#digests[@]} runs, the same bits"
