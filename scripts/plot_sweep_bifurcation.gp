# Bifurcation diagram of a sweep: the tip displacement at phase 0 of the forcing (the
# Poincare samples the sweep file keeps, the latest 256 of each point) against the
# parameter; up and down branches in two colours. One dot per period: a periodic response
# of period 1 gives one dot per parameter value, period 2 two, chaos a smear.
# usage: gnuplot -e "stem='results/rattling_bifurcation'" scripts/plot_sweep_bifurcation.gp
# reads  stem_poincare.dat (docs/output.md, "Text files")
# writes stem_bifurcation.png
# needs: poincare
if (!exists("stem")) stem = 'results/sweep'
file = stem.'_poincare.dat'
set terminal pngcairo size 1100,650 noenhanced
set output stem.'_bifurcation.png'
label = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
set title 'Poincare samples of the tip displacement (phase 0 of the forcing): '.stem
set xlabel label
set ylabel 'tip displacement at phase 0 (mm)'
set grid
set key top left
# which branches the sweep has (an empty title leaves a series out of the key)
points(test) = int(system("awk '!/^#/ && NF && ".test." {n++} END {print n + 0}' '".file."'"))
# a column by its name: the header lines '# 13: impact_rate (1/s)' (docs/output.md, "Text files")
col(name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
direction = col('direction')
c_x = col('parameter')
c_u = col('tip_displacement')
t_up = points(sprintf('$%d > 0', direction)) > 0 ? 'up' : ''
t_down = points(sprintf('$%d < 0', direction)) > 0 ? 'down' : ''
t_alone = points(sprintf('$%d == 0', direction)) > 0 ? 'independent' : ''
plot file using (column(c_x)):(column(direction) > 0 ? column(c_u)*1e3 : NaN) with points pt 7 ps 0.35 lc rgb '#d62728' title t_up, \
     '' using (column(c_x)):(column(direction) < 0 ? column(c_u)*1e3 : NaN) with points pt 7 ps 0.35 lc rgb '#1f77b4' \
        title t_down, \
     '' using (column(c_x)):(column(direction) == 0 ? column(c_u)*1e3 : NaN) with points pt 7 ps 0.35 lc rgb '#2ca02c' \
        title t_alone
