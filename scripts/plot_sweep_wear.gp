# The wear at the supports of a beam of two planes against a sweep's parameter
# (docs/statistics.md, "Wear at the supports"), one curve per point of the obstacles, each
# value with its standard error as an error bar: the wear work rate (W, log scale) above,
# the mean normal force (N) below; failed points left out, points without contact (0) too
# on the log scale.
# usage: gnuplot -e "stem='results/tube_support_plates_sweep'" scripts/plot_sweep_wear.gp
#        optional (scripts/plot_sweep.sh sets them): -e "xscale=210" divides the parameter
#        axis (a normalised frequency), -e "xlabel='...'" names it
# reads  stem_wear.dat (a block per point of the obstacles, the columns by name)
# writes stem_wear.png
# needs: sweep
if (!exists("stem")) stem = 'results/sweep'
if (!exists("xscale")) xscale = 1
file = stem.'_wear.dat'
set terminal pngcairo size 1000,800 noenhanced
set output stem.'_wear.png'
if (!exists("xlabel")) xlabel = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
# a column by its name: the header lines '# 5: work_rate (W)' (docs/output.md, "Text files")
col(name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
c_x = col('parameter')
status = col('status')
c_work = col('work_rate')
c_force = col('mean_force')
# the blocks' titles from their opening lines '# point 2 of the obstacles: x = 0.8 m, obstacle 2'
where = system("sed -n 's/^# point [0-9]* of the obstacles: x = \\([^ ]*\\) m, obstacle .*/\\1/p' '".file."'")
which = system("sed -n 's/^# point [0-9]* of the obstacles: x = .* m, obstacle \\([0-9]*\\)$/\\1/p' '".file."'")
blocks = words(where)
name(b) = sprintf('x = %.4g m (obstacle %s)', real(word(where, b + 1)), word(which, b + 1))
x = '(column(c_x)/xscale)'
ok(c) = column(status) == 0 ? column(c) : NaN
set multiplot layout 2, 1 title 'Wear at the supports: '.stem
set grid
set key top left opaque
set xlabel xlabel
set ylabel 'wear work rate (W)'
set logscale y
set format y '%.0e'
plot for [b = 0:blocks - 1] file index b using @x:(ok(c_work) > 0 ? ok(c_work) : NaN):(column(c_work + 1)) \
     with yerrorlines pointtype 7 pointsize 0.6 title name(b)
unset logscale y
set format y '%g'
set ylabel 'mean normal force (N)'
plot for [b = 0:blocks - 1] file index b using @x:(ok(c_force)):(column(c_force + 1)) \
     with yerrorlines pointtype 7 pointsize 0.6 title name(b)
unset multiplot
