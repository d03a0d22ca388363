# 2-D map of a sweep with two parameters: the impact rate and the power dissipated as
# colour over the (parameter, parameter2) plane, one square per point (the up branch's
# points when lines run up and down).
# usage: gnuplot -e "stem='results/frequency_gap_map'" scripts/plot_sweep_map.gp
#        optional (scripts/plot_sweep.sh sets them): -e "xscale=173.4" divides the first
#        parameter's axis, -e "xlabel='...'" and -e "ylabel2='...'" name the axes
# reads  stem_sweep.dat (docs/output.md, "Text files")
# writes stem_map.png
# needs: sweep
if (!exists("stem")) stem = 'results/sweep'
if (!exists("xscale")) xscale = 1
file = stem.'_sweep.dat'
if (!exists("xlabel")) xlabel = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
if (!exists("ylabel2")) ylabel2 = system("sed -n '2s/.*parameter2: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
set terminal pngcairo size 1300,560 noenhanced
set output stem.'_map.png'
set multiplot layout 1,2 title 'Map: '.stem
set xlabel xlabel
set ylabel ylabel2
set palette rgbformulae 33,13,10
set offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06
# columns: 3 direction (the down branch of 'up-down' left out), 4, 5 parameters, 6 status
keep(c) = (column(6) == 0 && column(3) >= 0) ? column(c) : NaN
set title 'impacts per second (1/s)'
plot file using ($4/xscale):5:(keep(13)) with points pt 5 ps 4 palette notitle
set title 'power dissipated, in all (W)'
plot file using ($4/xscale):5:(keep(29)) with points pt 5 ps 4 palette notitle
unset multiplot
