#!/bin/sh
# SDNL32 under refinement: the published inputs (verification/published/sdnl32_18000.nml and
# sdnl32_45000.nml, N = 20, dt = 1e-6 s) with N = 5 .. 80 at dt = 2.5e-7 s and dt = 8e-6 ..
# 2.5e-7 s at N = 80: tip displacement at 1, 2, ... 12 ms, and the largest deviation from
# the VPCS table relative to the table's peak |u|. Then the sensitivity to a Timoshenko-like
# drop of the frequencies: EI lowered by 2 x 7.0e-4 (mode 1's estimated shift, REPORT.md)
# at N = 80, dt = 2.5e-7 s. Writes results.txt.
# Usage: sh studies/sdnl32/run.sh BUILD_DIR   (about a minute on 2 cores)
set -eu
bin=${1:-build}/vibrobeam
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out="$here/results.txt"
reference_18000="-2.66 -4.33 -4.92 -4.78 -3.82 -2.87 -2.71 -3.09 -3.41 -3.36 -2.64 -0.742"
reference_45000="-2.25 -2.66 -1.96 -1.15 -0.124 -0.364 -2.01 -2.74 -1.89 -0.352 1.70 4.99"
echo "# k(N/m) N dt(s) EI_factor max|u-u_ref|/peak(%) at_ms u_tip(1..12 ms)(mm)" > "$out"
run() {   # k N dt EI_factor
  every=$(awk -v dt=$3 'BEGIN { printf "%d", 1e-3/dt + 0.5 }')
  inertia=$(awk -v f=$4 'BEGIN { printf "%.17g", 3.2013333333333333e-9*f }')
  sed -e "s/elements = 20/elements = $2/" -e "s/dt = 1e-6/dt = $3/" -e "s/every = 1000/every = $every/" \
      -e "s/inertia = 3.2013333333333333e-9/inertia = $inertia/" \
      -e "s|file = 'sdnl32_$1.h5'|file = '$work/s.h5'|" "$here/../../verification/published/sdnl32_$1.nml" > "$work/s.nml"
  "$bin" "$work/s.nml" > /dev/null 2>&1
  eval reference=\$reference_$1
  awk -v k=$1 -v n=$2 -v dt=$3 -v f=$4 -v ref="$reference" '
    BEGIN { split(ref, r, " "); peak = 0; for (i = 1; i <= 12; i++) if ((r[i] < 0 ? -r[i] : r[i]) > peak) peak = (r[i] < 0 ? -r[i] : r[i]) }
    /^#/ { next }
    { i = int($1*1000 + 0.5); if (i >= 1 && i <= 12 && ($1 - i/1000)^2 < (dt/10)^2) u[i] = $2*1000 }
    END { worst = 0; at = 0; line = ""
          for (i = 1; i <= 12; i++) { d = u[i] - r[i]; if (d < 0) d = -d; if (d > worst) { worst = d; at = i }
                                       line = line sprintf(" %.5f", u[i]) }
          printf "%6d %3d %-7s %-9s %6.3f %2d%s\n", k, n, dt, f, 100*worst/peak, at, line }' "$work/s_tip.dat" >> "$out"
}
for k in 18000 45000; do
  for n in 5 10 20 40 80; do run $k $n 2.5e-7 1; done
  for dt in 8e-6 4e-6 2e-6 1e-6 5e-7; do run $k 80 $dt 1; done
  run $k 20 1e-6 1
  run $k 80 2.5e-7 0.9986
done
cat "$out"
