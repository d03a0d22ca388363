#!/usr/bin/env bash
# Work-precision study (issue 4): error against CPU time for {Hermite, B-spline} x
# {velocity, position} x {theta = 1/2, 1} over a range of N and dt, on (a) free vibration
# against the closed form and (b) inputs/looseness_tip_stops.nml over [0, 10 ms] against a
# converged fine run. Builds the study program (Release), runs it and regenerates the
# committed results in studies/work_precision/: work_precision_{free,impacts}.txt
# (tables), .dat (gnuplot blocks) and .png. Discussion: studies/work_precision/REPORT.md.
#
# usage: studies/work_precision/work_precision.sh [BUILD_DIR]   (default: build, relative to the repository
#        root like the other scripts; the study itself takes about 3 min on one core)
# needs: cmake, a Fortran compiler, the project's libraries, gnuplot (pngcairo terminal)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
results=studies/work_precision

source scripts/build_release.sh
build_release "$build" work_precision
program=$build/studies/work_precision/work_precision

# The machine the timings come from (appended to both tables).
machine_notes() {
  echo "# machine: $(nproc) processor(s), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')," \
       "load average before the study: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "# compiler: $(gfortran --version | head -1) (Release, -O2); source: git $(git rev-parse --short HEAD 2>/dev/null || echo '?')" \
       "$(git status --porcelain -- src 2>/dev/null | grep -q . && echo '+ uncommitted changes in src/' || true)"
}

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
start=$(date +%s)
# one part after the other, so that they do not compete for the two cores and every
# run is timed on the same machine (other users aside)
"$program" free verification/dynamics/free_flight.nml "$results"
machine_notes >> "$results/work_precision_free.txt"
"$program" impacts inputs/looseness_tip_stops.nml "$results"
machine_notes >> "$results/work_precision_impacts.txt"
elapsed=$(( $(date +%s) - start ))
echo "# whole study (both parts): ${elapsed} s wall" | tee -a "$results/work_precision_free.txt" \
  >> "$results/work_precision_impacts.txt"

# The plots: one curve per combination (its Pareto front, best error for a given cost),
# every run as a small point of the same colour. Colour: basis x scheme; solid/filled:
# theta = 1/2, dashed/open: theta = 1. Blocks of the .dat: 0-7 every run of combination
# 1-8, 8-15 their Pareto fronts (same order), 16 (impacts only) the reference's levels.
plot_study() {
  local data=$1 output=$2 title=$3 ylabel=$4 extra=$5
  gnuplot <<EOF
data = '$data'
set terminal pngcairo size 1400,900 font ',12' noenhanced
set output '$output'
set title "$title"
set logscale xy
set format x '%.0e'
set format y '%.0e'
set xlabel 'CPU time of the stepping loop (s), median of 3 when < 0.1 s'
set ylabel "$ylabel"
set grid xtics ytics mxtics mytics lc rgb 'gray85'
set key outside right top box opaque spacing 1.4
names = 'Hermite/velocity/θ=1/2 Hermite/velocity/θ=1 Hermite/position/θ=1/2 Hermite/position/θ=1 B-spline/velocity/θ=1/2 B-spline/velocity/θ=1 B-spline/position/θ=1/2 B-spline/position/θ=1'
colors = '#1f5fbf #1f5fbf #c0392b #c0392b #1e8449 #1e8449 #d68910 #d68910'
points = '7 6 7 6 5 4 5 4'
dashes = '1 2 1 2 1 2 1 2'
$extra
plot for [i=1:8] data index (i+7) using 5:6 with linespoints lw 2.2 dt int(word(dashes,i)) \
       pt int(word(points,i)) ps 1.3 lc rgb word(colors,i) title word(names,i), \
     for [i=1:8] data index (i-1) using 5:6 with points pt int(word(points,i)) ps 0.55 \
       lc rgb word(colors,i) notitle
EOF
}

plot_study "$results/work_precision_free.dat" "$results/work_precision_free.png" \
  "(a) Free vibration, L = k2 = 1, mode-1 velocity + mode-2 displacement, t in [0, 8]: N = 4..64, dt = 2^-5..2^-16\nlines: Pareto front of each combination; small points: every run" \
  'max_k |u_h(L,t_k) - u(L,t_k)| / max_k |u(L,t_k)|  (closed form)' \
  "set yrange [1e-7:2]
set xrange [3e-5:5]"

plot_study "$results/work_precision_impacts.dat" "$results/work_precision_impacts.png" \
  "(b) Looseness, inputs/looseness_tip_stops.nml, t in [0, 10 ms] (2 contact episodes): N = 8..64, dt = 2e-5..3.125e-7 s\nlines: Pareto front of each combination; small points: every run; gray: within 3x the reference's own uncertainty" \
  'max_k |u_h(L,t_k) - u_ref(L,t_k)| / max_k |u_ref(L,t_k)|  (reference N = 1024)' \
  "stats data index 16 using 1 nooutput
uncertainty = STATS_max
set yrange [2e-3:0.3]
set xrange [1e-4:0.3]
set object 1 rectangle from graph 0, first 2e-3 to graph 1, first 3*uncertainty behind fc rgb 'gray90' fs solid noborder
set arrow 1 from graph 0, first uncertainty to graph 1, first uncertainty nohead dt 3 lw 2 lc rgb 'black' front
set label 1 sprintf('reference vs its next-coarser level (N = 512): %.1e', uncertainty) at graph 0.02, first uncertainty*1.15 front"

echo "work_precision: wrote $results/work_precision_{free,impacts}.{txt,dat,png} in ${elapsed} s (study)"
