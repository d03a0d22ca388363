# Bifurcation diagram of a sweep: the tip displacement at phase 0 of the forcing (the
# Poincare samples the sweep file keeps, the latest 256 of each point) against the
# parameter; up and down branches in two colours. One dot per period: a periodic response
# of period 1 gives one dot per parameter value, period 2 two, chaos a smear.
# usage: gnuplot -e "stem='results/rattling_bifurcation'" scripts/plot_sweep_bifurcation.gp
#        optional (scripts/plot_sweep.sh sets them): -e "xscale=210" divides the parameter
#        axis (a normalised frequency), -e "xlabel='...'" names it
# reads  stem_poincare.dat (docs/output.md, "Text files")
# writes stem_bifurcation.png
# needs: poincare
if (!exists("stem")) stem = 'results/sweep'
if (!exists("xscale")) xscale = 1
file = stem.'_poincare.dat'
set terminal pngcairo size 1100,650 noenhanced
set output stem.'_bifurcation.png'
if (!exists("xlabel")) xlabel = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
set title 'Poincare samples of the tip displacement (phase 0 of the forcing): '.stem
set xlabel xlabel
set ylabel 'tip displacement at phase 0 (mm)'
set grid
set key top left
# which branches the sweep has (an empty title leaves a series out of the key)
points(test) = int(system("awk '!/^#/ && NF && ".test." {n++} END {print n + 0}' '".file."'"))
t_up = points('$3 > 0') > 0 ? 'up' : ''
t_down = points('$3 < 0') > 0 ? 'down' : ''
t_alone = points('$3 == 0') > 0 ? 'independent' : ''
# columns: 1 parameter, 3 direction, 6 tip displacement (m)
plot file using ($1/xscale):($3 > 0 ? $6*1e3 : NaN) with points pt 7 ps 0.35 lc rgb '#d62728' title t_up, \
     '' using ($1/xscale):($3 < 0 ? $6*1e3 : NaN) with points pt 7 ps 0.35 lc rgb '#1f77b4' title t_down, \
     '' using ($1/xscale):($3 == 0 ? $6*1e3 : NaN) with points pt 7 ps 0.35 lc rgb '#2ca02c' title t_alone
