#!/usr/bin/env bash
# Self-convergence study of the velocity-based stepper on inputs/looseness_tip_stops.nml:
# builds the study program (Release), runs it, and regenerates the committed results in
# studies/convergence/: self_convergence.txt (tables), self_convergence.dat (gnuplot
# blocks) and self_convergence.png. Discussion: studies/convergence/REPORT.md.
#
# usage: studies/convergence/convergence_study.sh [BUILD_DIR]   (default: build, relative to the
#        repository root like the other scripts; the study itself takes about 30 s)
# needs: cmake, a Fortran compiler, the project's libraries, gnuplot (pngcairo terminal)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
results=studies/convergence
scene=inputs/looseness_tip_stops.nml

source scripts/build_release.sh
build_release "$build" self_convergence
program=$build/studies/convergence/self_convergence

start=$(date +%s)
"$program" "$scene" "$results"
echo "convergence_study: the study took $(( $(date +%s) - start )) s"

# The plot: relative errors against the reference (studies 2 to 4) and the successive
# differences along the joint path (study 6), log-log, with reference slopes.
gnuplot <<EOF
data = '$results/self_convergence.dat'
set terminal pngcairo size 1400,1000 font ',10' noenhanced
set output '$results/self_convergence.png'
set multiplot layout 2,2 title 'Self-convergence, inputs/looseness_tip_stops.nml, window [0, 0.025 s] (4 impact events)'
set logscale xy
set format x '%.0e'
set format y '%.0e'
set grid
set key top left box opaque
set ylabel 'relative error'
# each slope line goes through the centroid, in log-log, of the tip errors it compares with
set xlabel 'dt (s)'

stats data index 'joint refinement' using (log(\$1)):(log(\$7)) nooutput
c1 = exp(STATS_mean_y - STATS_mean_x)
set title "Joint refinement dt = dt0/2^k, N = nint(N0 2^(k/2)) (dt0 = 4e-5 s, N0 = 16)\\nagainst the reference dt0/16, 4 N0 (acceptance item)"
plot data index 'joint refinement' using 1:7 with linespoints pt 7 title 'tip: max in time / max |u_tip|', \
     ''   index 'joint refinement' using 1:8 with linespoints pt 5 title 'field at 11 points: L2 in time / its norm', \
     ''   index 'joint refinement' using 1:9 with linespoints pt 9 title 'energy at T / E(T)', \
     c1*x with lines dt 2 lc rgb 'black' title 'slope 1'

stats data index 'dt alone' using (log(\$1)):(log(\$7)) nooutput
c2 = exp(STATS_mean_y - STATS_mean_x)
set title 'dt alone, N = 32, against dt = 4e-5/256 s'
plot data index 'dt alone' using 1:7 with linespoints pt 7 title 'tip', \
     ''   index 'dt alone' using 1:8 with linespoints pt 5 title 'field', \
     ''   index 'dt alone' using 1:9 with linespoints pt 9 title 'energy', \
     c2*x with lines dt 2 lc rgb 'black' title 'slope 1'

stats data index 'N alone' using (log(\$3)):(log(\$7)) nooutput
c3 = exp(STATS_mean_y - STATS_mean_x)
set title 'h alone, dt = 6.25e-7 s, against N = 256'
set xlabel 'h = L/N (m)'
plot data index 'N alone' using 3:7 with linespoints pt 7 title 'tip', \
     ''   index 'N alone' using 3:8 with linespoints pt 5 title 'field', \
     ''   index 'N alone' using 3:9 with linespoints pt 9 title 'energy', \
     c3*x with lines dt 2 lc rgb 'black' title 'slope 1'

scene_block = 'successive differences, theta = 0.50, e = 0.80'
stats data index scene_block using (log(\$2)):(log(\$5)) nooutput
c4 = exp(STATS_mean_y - STATS_mean_x)
stats data index scene_block using (log(\$2)):(log(\$4)) nooutput
c5 = 5*exp(STATS_mean_y - 2*STATS_mean_x)   # drawn 5 times above the free-flight points
set title 'Successive differences, level k against k + 1 of the joint path (tip, max in time)'
set xlabel 'dt of level k (s)'
set ylabel 'difference (m)'
set key bottom right
set yrange [1e-16:1e-2]
plot data index scene_block using 2:6 with linespoints pt 7 lc 1 title 'scene, window [0, 25 ms]', \
     ''   index 'successive differences, theta = 0.55' using 2:6 with linespoints pt 4 lc 2 title 'theta = 0.55, [0, 25 ms]', \
     ''   index 'successive differences, theta = 0.50, e = 1.00' using 2:6 with linespoints pt 6 lc 3 title 'e = 1, [0, 25 ms]', \
     ''   index scene_block using 2:5 with linespoints pt 5 lc 4 title 'scene, [0, 2.5 ms] (first contact)', \
     ''   index scene_block using 2:4 with linespoints pt 9 lc 7 title 'scene, [0, 2 ms] (free flight)', \
     c4*x with lines dt 2 lc rgb 'black' title 'slope 1', \
     c5*x**2 with lines dt 3 lw 1.5 lc rgb 'gray30' title 'slope 2'
unset multiplot
EOF
echo "convergence_study: wrote $results/self_convergence.txt, .dat and .png"
