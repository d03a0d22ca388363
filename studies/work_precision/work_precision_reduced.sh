#!/usr/bin/env bash
# Work-precision of the reduced model (issue 13, &mesh reduction = 'craig-bampton'): error
# of the statistics against the full model and time per step for several numbers of
# fixed-interface modes, at N = 256, on the forced rattling scene (inputs/forced_rattling.nml,
# t in [0, 5] s, statistics over [0.5, 5] s) and on the first-impact test
# (verification/dynamics/first_impact.nml, t in [0, 0.3] s); plus the full model's own mesh
# dependence (N/2 and 2N). Writes studies/work_precision/work_precision_reduced_*.txt
# and work_precision_reduced.png. Discussion: studies/work_precision/REPORT.md, "The
# reduced model". About 6 minutes on one core.
#   usage: studies/work_precision/work_precision_reduced.sh [BUILD_DIR]     (default: build)
# needs: cmake, a Fortran compiler, the project's libraries, gnuplot (pngcairo terminal)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
results=studies/work_precision

source scripts/build_release.sh
build_release "$build" work_precision_reduced
program=$build/studies/work_precision/work_precision_reduced

notes() {
  echo "# machine: $(nproc) processor(s), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')," \
       "load average after: $(cut -d' ' -f1-3 /proc/loadavg); BLAS: the system default (libblas.so.3)"
  echo "# compiler: $(gfortran --version | head -1) (Release, -O2); source: git $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
}

"$program" inputs/forced_rattling.nml 256 0.5 5.0 "$results/work_precision_reduced_rattling.txt"
notes >> "$results/work_precision_reduced_rattling.txt"
"$program" inputs/forced_rattling.nml 256 0.5 5.0 "$results/work_precision_reduced_rattling_mesh.txt" full
notes >> "$results/work_precision_reduced_rattling_mesh.txt"
"$program" verification/dynamics/first_impact.nml 256 0.0 0.3 "$results/work_precision_reduced_first_impact.txt"
notes >> "$results/work_precision_reduced_first_impact.txt"
"$program" verification/dynamics/first_impact.nml 256 0.0 0.3 "$results/work_precision_reduced_first_impact_mesh.txt" full
notes >> "$results/work_precision_reduced_first_impact_mesh.txt"

# error (the largest of RMS tip and energy lost, and of RMS tip alone) against time per step
# (columns: r = 2, err_rms = 9, max_err(rms, energy, episodes) = 14, us/step = 15; rows 0
# and 1 are the full model and its perturbed copy)
gnuplot <<GNUPLOT
set terminal pngcairo size 1200,700 font ',12' noenhanced
set output '$results/work_precision_reduced.png'
set title "Reduced model (Craig-Bampton) against the full model, N = 256 (J = 512): error of the statistics vs time per step"
set logscale xy
set xlabel 'CPU time per step (us), median of 3 runs'
set ylabel 'relative error against the full model'
set grid
set key outside bottom center box
set yrange [1e-4:2]
plot '$results/work_precision_reduced_rattling.txt' using 15:(\$14 > 0 ? \$14 : 1/0) every ::2 with points pt 7 ps 1.5 \
       title 'forced rattling: max of RMS tip, energy lost, episode rate', \
     '$results/work_precision_reduced_rattling.txt' using 15:(\$9 > 0 ? \$9 : 1/0) every ::2 with points pt 6 ps 1.5 \
       title 'forced rattling: RMS tip', \
     '$results/work_precision_reduced_first_impact.txt' using 15:(\$9 > 0 ? \$9 : 1/0) every ::2 with points pt 5 ps 1.5 \
       title 'first impact: RMS tip', \
     0.01 with lines lw 2 lc rgb "black" dt 3 title '1 %'
GNUPLOT
echo "wrote $results/work_precision_reduced_*.txt and work_precision_reduced.png"
