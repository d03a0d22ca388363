# 2-D map of a sweep with two parameters: the impact rate and the power dissipated as
# colour over the (parameter, parameter2) plane, one square per point (the up branch's
# points when lines run up and down).
# usage: gnuplot -e "stem='results/frequency_gap_map'" scripts/plot_sweep_map.gp
# reads  stem_sweep.dat (docs/output.md, "Text files")
# writes stem_map.png
# needs: sweep
if (!exists("stem")) stem = 'results/sweep'
file = stem.'_sweep.dat'
first = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
second = system("sed -n '2s/.*parameter2: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
set terminal pngcairo size 1300,560 noenhanced
set output stem.'_map.png'
set multiplot layout 1,2 title 'Map: '.stem
set xlabel first
set ylabel second
set palette rgbformulae 33,13,10
set offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06
# a column by its name: the header lines '# 13: impact_rate (1/s)' (docs/output.md, "Text files")
col(name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
direction = col('direction')
c_x = col('parameter')
c_y = col('parameter2')
status = col('status')
impacts = col('impact_rate')
dissipated = col('power_dissipated')
# the points that succeeded (the down branch of 'up-down' left out)
keep(c) = (column(status) == 0 && column(direction) >= 0) ? column(c) : NaN
set title 'impacts per second (1/s)'
plot file using (column(c_x)):(column(c_y)):(keep(impacts)) with points pt 5 ps 4 palette notitle
set title 'power dissipated, in all (W)'
plot file using (column(c_x)):(column(c_y)):(keep(dissipated)) with points pt 5 ps 4 palette notitle
unset multiplot
