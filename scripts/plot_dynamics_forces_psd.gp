# One-sided power spectral density of each random load of a run (&forces signal =
# 'random'): the target S and the density of the signal the run generated, measured by
# Welch's method, with its 95 % confidence band (docs/output.md, "/forces"), on
# logarithmic axes; one curve set per load (the blocks of the .dat file).
# usage: gnuplot -e "stem='results/random_rattling'" scripts/plot_dynamics_forces_psd.gp
# reads  stem_forces_psd.dat (one block per random load: frequency (Hz), target, measured,
#        lower and upper end of the band)
# writes stem_forces_psd.png
# needs: forces_psd
if (!exists("stem")) stem = 'results/vibrobeam'
psd_file = stem.'_forces_psd.dat'
blocks = int(system("awk '/^# load /{n++} END {print n + 0}' '".psd_file."'"))
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_forces_psd.png'
set xlabel 'frequency (Hz)'
set ylabel 'one-sided density (unit^2/Hz)'
set grid xtics ytics
if (blocks == 0) {
   set title 'Random loads: '.stem
   set label 1 'no random load in '.psd_file at graph 0.5, 0.5 center front
   set xrange [0:1]
   set yrange [-1:1]
   unset key
   plot NaN notitle
   exit
}
stats psd_file using ($1 > 0 && $2 > 0 ? $2 : NaN) nooutput
target_max = STATS_max
stats psd_file using ($1 > 0 ? $1 : NaN) nooutput
set logscale xy
set format y '%.0e'
set xrange [STATS_min:STATS_max]
set yrange [target_max*1e-4:target_max*10]
set key bottom left
set title 'Random loads: target and measured density (95 % band): '.stem
set style fill transparent solid 0.25 noborder
colors = "#1f77b4 #d62728 #2ca02c #9467bd"
color(i) = word(colors, i % 4 + 1)
plot for [i=0:blocks-1] psd_file index i using ($1 > 0 ? $1 : NaN):4:5 with filledcurves \
        lc rgb color(i) title sprintf('random load %d: 95 %% band', i + 1), \
     for [i=0:blocks-1] psd_file index i using ($1 > 0 ? $1 : NaN):($3 > 0 ? $3 : NaN) with lines lw 1 \
        lc rgb color(i) title sprintf('random load %d: measured (Welch)', i + 1), \
     for [i=0:blocks-1] psd_file index i using ($1 > 0 ? $1 : NaN):($2 > 0 ? $2 : NaN) with lines lw 2.5 dt 2 \
        lc rgb 'black' title sprintf('random load %d: target', i + 1)
