#!/usr/bin/env bash
# Siconos side-by-side benchmark (issue 13; REPORT.md beside this file). One run, same
# scene for everyone: Hermite beam (k2 = 1, L = 1), two stops at the tip at +-gap, a
# constant uniform load, e = 1, dt = 1e-4 s, separating_points = 'restitution' (the rule
# Siconos uses), from rest.
#  - Siconos (Debian python3-siconos, MoreauJeanOSI theta = 1/2 + LCP) on vibrobeam's own
#    M, K and load vector (export_model), N = 20 ... 1000, when the package is installed;
#  - vibrobeam full, N = 20 ... 1e5, under the reference BLAS and OpenBLAS, and reduced
#    (&mesh reduction = 'craig-bampton', default cut-off) under the reference BLAS;
#  - the LAPACK floor dpbtrs + dsbmv (benchmark_kernel) in the same run.
# Time per step: Siconos, its stepping loop; vibrobeam, (wall(2 S steps) - wall(S steps))/S
# of the whole executable without output (removes set-up and output). Tip agreement: max
# |u_tip(vibrobeam) - u_tip(Siconos)| over every step, divided by the gap.
# Writes results.txt and time_per_step.png here.
#   usage: studies/siconos_benchmark/run.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
here=studies/siconos_benchmark
source scripts/build_release.sh
build_release "$build" vibrobeam export_model benchmark_kernel
vibrobeam=$(realpath "$build/vibrobeam")
export_model=$(realpath "$build/studies/siconos_benchmark/export_model")
kernel=$(realpath "$build/studies/benchmark/benchmark_kernel")
python=/usr/bin/python3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
gap=0.01 load=1000 dt=1e-4 e=1
reference=/usr/lib/x86_64-linux-gnu/blas:/usr/lib/x86_64-linux-gnu/lapack
openblas=/usr/lib/x86_64-linux-gnu/openblas-pthread
results=$here/results.txt

siconos=yes
if ! $python -c 'import siconos.kernel' 2>/dev/null; then
  siconos=no
  echo "python3-siconos is not installed (apt-get install python3-siconos): Siconos is skipped" | tee "$work/note"
fi

# scene N STEPS EVERY TEXT REDUCTION FILE: the namelist
scene() {
  cat <<NML
&beam length = 1.0, k2 = 1.0 /
&mesh elements = $1, reduction = '$5' /
&obstacles count = 2, side(1) = 'below', x_from(1) = 1.0, level_from(1) = -$gap,
                      side(2) = 'above', x_from(2) = 1.0, level_from(2) = $gap /
&impact restitution = $e, separating_points = 'restitution' /
&time t_end = $(awk -v s="$2" -v d="$dt" 'BEGIN { printf "%.10g", s*d }'), dt = $dt /
&load distributed = $load /
&output file = '$6', every = $3, text = $4 /
NML
}
# seconds per step of vibrobeam: N REDUCTION LIBRARY
vibrobeam_step() {
  local n=$1 reduction=$2 library=$3 steps t1 t2
  # about 0.3 s or more per run: /usr/bin/time resolves 10 ms
  steps=$(( 4000000 / n )); (( steps < 2000 )) && steps=2000; (( steps > 400000 )) && steps=400000
  [ "$reduction" = none ] || steps=1000000
  scene "$n" "$steps" 1000000000 .false. "$reduction" "$work/a.h5" > "$work/a.nml"
  scene "$n" $(( 2 * steps )) 1000000000 .false. "$reduction" "$work/b.h5" > "$work/b.nml"
  t1=$( { /usr/bin/time -f %e env LD_LIBRARY_PATH=$library "$vibrobeam" "$work/a.nml" > /dev/null; } 2>&1 | tail -1)
  t2=$( { /usr/bin/time -f %e env LD_LIBRARY_PATH=$library "$vibrobeam" "$work/b.nml" > /dev/null; } 2>&1 | tail -1)
  awk -v a="$t1" -v b="$t2" -v s="$steps" 'BEGIN { printf "%.4g", (b - a)/s*1e6 }'
}
# tip history of vibrobeam (every step): N STEPS REDUCTION -> $work/vb_N_REDUCTION_tip.dat
vibrobeam_tip() {
  scene "$1" "$2" 1 .true. "$3" "$work/vb_$1_$3.h5" > "$work/tip.nml"
  LD_LIBRARY_PATH=$reference "$vibrobeam" "$work/tip.nml" > /dev/null
}
# max |a - b| / gap over the common steps of two tip files (t, u columns; a's row 0 is t = 0)
tip_difference() {
  $python - "$1" "$2" "$gap" <<'PY'
import sys, numpy as np
a = np.loadtxt(sys.argv[1], comments='#')[1:, :2]
b = np.loadtxt(sys.argv[2], comments='#')
b = b[1:, :2] if b[0, 0] == 0 else b[:, :2]
n = min(len(a), len(b))
assert np.abs(a[:n, 0] - b[:n, 0]).max() < 1e-9, 'different times'
print(f"{np.abs(a[:n, 1] - b[:n, 1]).max() / float(sys.argv[3]):.2e}")
PY
}

LD_LIBRARY_PATH=$reference "$kernel" kernel > "$work/floor_reference.txt"
LD_LIBRARY_PATH=$openblas OPENBLAS_NUM_THREADS=1 "$kernel" kernel > "$work/floor_openblas.txt"
floor() {   # N FILE -> dpbtrs+dsbmv us at J = 2N, or '-'
  awk -v j=$(( 2 * $1 )) '$1 == j { print $2; found = 1 } END { if (!found) print "-" }' "$2"
}

{
  echo "# Siconos side-by-side benchmark: k2 = L = 1, Hermite, stops at +-$gap m at the tip, load $load N/m, e = $e, dt = $dt s"
  echo "# columns: N, J, Siconos us/step, steps compared, vibrobeam full us/step (reference BLAS, OpenBLAS),"
  echo "# floor dpbtrs+dsbmv us (reference, OpenBLAS; '-': J not in the kernel table), Siconos/vibrobeam (reference, OpenBLAS),"
  echo "# max |tip vibrobeam - tip Siconos| / gap, reduced us/step (reference), reduced r, max |tip reduced - tip full| / gap"
  [ -f "$work/note" ] && echo "# $(cat "$work/note")"
  for n in 20 50 100 200 400 1000 5000 50000 100000; do
    sic='-' compared='-' difference='-'
    if [ "$siconos" = yes ] && (( n <= 1000 )); then
      steps=2000; (( n >= 400 )) && steps=500; (( n >= 1000 )) && steps=200
      "$export_model" "$n" "$work/model.txt"
      sic=$($python $here/siconos_driver.py "$work/model.txt" "$gap" "$load" "$dt" "$steps" "$e" "$work/siconos_tip.txt" |
            awk '{ printf "%.4g", $2*1e6 }')
      vibrobeam_tip "$n" "$steps" none
      difference=$(tip_difference "$work/vb_${n}_none_tip.dat" "$work/siconos_tip.txt")
      compared=$steps
    fi
    full_ref=$(vibrobeam_step "$n" none "$reference")
    full_open=$(vibrobeam_step "$n" none "$openblas")
    reduced='-' r='-' reduced_difference='-'
    if (( n <= 5000 )); then
      reduced=$(vibrobeam_step "$n" craig-bampton "$reference")
      r=$("$vibrobeam" --check "$work/a.nml" | sed -n 's/^reduced model (craig-bampton): \([0-9]*\) unknowns.*/\1/p')
      vibrobeam_tip "$n" 2000 none
      vibrobeam_tip "$n" 2000 craig-bampton
      reduced_difference=$(tip_difference "$work/vb_${n}_craig-bampton_tip.dat" "$work/vb_${n}_none_tip.dat")
    fi
    ratio_ref='-' ratio_open='-'
    if [ "$sic" != '-' ]; then
      ratio_ref=$(awk -v a="$sic" -v b="$full_ref" 'BEGIN { printf "%.0f", a/b }')
      ratio_open=$(awk -v a="$sic" -v b="$full_open" 'BEGIN { printf "%.0f", a/b }')
    fi
    echo "$n $(( 2 * n )) $sic $compared $full_ref $full_open $(floor "$n" "$work/floor_reference.txt") $(floor "$n" "$work/floor_openblas.txt") $ratio_ref $ratio_open $difference $reduced $r $reduced_difference"
  done
  echo "# machine: $(nproc) processor(s), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# source: git $(git rev-parse --short HEAD 2>/dev/null || echo '?'); python3-siconos $(dpkg-query -W -f '${Version}' python3-siconos 2>/dev/null || echo 'not installed')"
} | tee "$results"

gnuplot <<GNUPLOT
set terminal pngcairo size 1100,700 font ',12' noenhanced
set output '$here/time_per_step.png'
set title 'Time per step against N (Hermite beam, two tip stops, dt = 1e-4 s)'
set logscale xy
set xlabel 'elements N'
set ylabel 'microseconds per step'
set grid
set key left top box
set datafile missing '-'
plot '$results' using 1:3 with linespoints pt 7 title 'Siconos (MoreauJeanOSI + LCP)', \
     '' using 1:5 with linespoints pt 5 title 'vibrobeam full, reference BLAS', \
     '' using 1:6 with linespoints pt 4 title 'vibrobeam full, OpenBLAS', \
     '' using 1:7 with linespoints pt 9 dt 2 title 'LAPACK floor dpbtrs + dsbmv, reference', \
     '' using 1:8 with linespoints pt 8 dt 2 title 'LAPACK floor, OpenBLAS', \
     '' using 1:12 with linespoints pt 13 title 'vibrobeam reduced (default cut-off)'
GNUPLOT
echo "wrote $results and $here/time_per_step.png"
