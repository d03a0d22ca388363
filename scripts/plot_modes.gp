# Mode shapes (tip value 1) of a 'modes' run.
# usage: gnuplot -e "stem='results/cantilever_modes'" scripts/plot_modes.gp
# reads  stem_shapes.dat (x, mode 1, mode 2, ...) and stem_modes.dat (mode, omega, Hz)
# writes stem_shapes.png
if (!exists("stem")) stem = 'results/vibrobeam'
set terminal pngcairo size 900,600 noenhanced
set output stem.'_shapes.png'
stats stem.'_shapes.dat' using 1 nooutput
columns = STATS_columns
shown = (columns - 1 < 4) ? columns - 1 : 4
set title 'Natural mode shapes (normalized to tip displacement 1)'
set xlabel 'x (m)'
set ylabel 'shape'
set grid
set key outside right
freq(k) = real(system(sprintf("awk '!/^#/ && $1 == %d {print $3}' %s_modes.dat", k, stem)))
plot for [k=1:shown] stem.'_shapes.dat' using 1:(column(k+1)) with linespoints pt 7 ps 0.5 \
     title sprintf('mode %d: %.4g Hz', k, freq(k))
