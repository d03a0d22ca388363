# What the Poincare samples of a sweep's points say, against the parameter, in four panels
# sharing its axis (docs/statistics.md, "Period, Lyapunov exponent and the 0-1 test"): the
# samples of the tip displacement (the bifurcation diagram), the period of the sequence
# (1..64; points without one at 0), K of the 0-1 test with the lines K = 0.2 and 0.8
# (regular below, chaotic above), and, when the sweep asked for it (&output lyapunov), the
# largest Lyapunov exponent per forcing period with its standard error and the line 0.
# Up and down branches in two colours (independent points in a third); failed points left out.
# usage: gnuplot -e "stem='results/rattling_bifurcation'" scripts/plot_sweep_chaos.gp
#        optional (scripts/plot_sweep.sh sets them): -e "xscale=210" divides the parameter
#        axis (a normalised frequency), -e "xlabel='...'" names it
# reads  stem_sweep.dat (the columns period, zero_one_k, lyapunov_exponent_per_period and
#        lyapunov_periods by name) and stem_poincare.dat
# writes stem_chaos.png
# needs: sweep
if (!exists("stem")) stem = 'results/sweep'
if (!exists("xscale")) xscale = 1
file = stem.'_sweep.dat'
samples = stem.'_poincare.dat'
set terminal pngcairo size 1000,1250 noenhanced
set output stem.'_chaos.png'
if (!exists("xlabel")) xlabel = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
# a column by its name: the header lines '# 13: impact_rate (1/s)' (docs/output.md, "Text files")
col(name, in) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".in."'"))
direction = col('direction', file)
c_x = col('parameter', file)
status = col('status', file)
c_period = col('period', file)
c_k = col('zero_one_k', file)
c_lags = col('zero_one_lags', file)
c_lambda = col('lyapunov_exponent_per_period', file)
c_periods = col('lyapunov_periods', file)
s_direction = col('direction', samples)
s_x = col('parameter', samples)
s_u = col('tip_displacement', samples)
x = '(column(c_x)/xscale)'
# which branches the sweep has (an empty title leaves a series out of the key)
points(test) = int(system("awk '!/^#/ && NF && ".test." {n++} END {print n + 0}' '".file."'"))
t_up = points(sprintf('$%d > 0', direction)) > 0 ? 'up' : ''
t_down = points(sprintf('$%d < 0', direction)) > 0 ? 'down' : ''
t_alone = points(sprintf('$%d == 0', direction)) > 0 ? 'independent' : ''
lyapunov = points(sprintf('$%d > 0', c_periods)) > 0
# a value where the point succeeded and runs in the direction wanted
ok(wanted) = column(status) == 0 && (wanted > 0 ? column(direction) > 0 : (wanted < 0 ? column(direction) < 0 : \
             column(direction) == 0))
up = '#d62728'
down = '#1f77b4'
alone = '#2ca02c'
set multiplot layout (lyapunov ? 4 : 3), 1 title 'Period, 0-1 test and Lyapunov exponent of the Poincare samples: '.stem
set grid
set key top left
set lmargin 12
set xlabel xlabel

set ylabel 'tip u at phase 0 (mm)'
plot samples using (column(s_x)/xscale):(column(s_direction) > 0 ? column(s_u)*1e3 : NaN) with points pt 7 ps 0.3 \
        lc rgb up title t_up, \
     '' using (column(s_x)/xscale):(column(s_direction) < 0 ? column(s_u)*1e3 : NaN) with points pt 7 ps 0.3 \
        lc rgb down title t_down, \
     '' using (column(s_x)/xscale):(column(s_direction) == 0 ? column(s_u)*1e3 : NaN) with points pt 7 ps 0.3 \
        lc rgb alone title t_alone

set ylabel 'period (forcing periods; 0: none)'
set yrange [-0.5:*]
plot file using @x:(ok(1) && column(c_period) >= 0 ? column(c_period) : NaN) with points pt 7 ps 0.8 lc rgb up \
        title t_up, \
     '' using @x:(ok(-1) && column(c_period) >= 0 ? column(c_period) : NaN) with points pt 6 ps 1.2 lc rgb down \
        title t_down, \
     '' using @x:(ok(0) && column(c_period) >= 0 ? column(c_period) : NaN) with points pt 7 ps 0.8 lc rgb alone \
        title t_alone
set autoscale y

set ylabel '0-1 test K'
set yrange [-0.3:1.1]
plot 0.2 with lines dt 2 lc rgb 'gray' title 'K = 0.2 (regular below)', \
     0.8 with lines dt 3 lc rgb 'gray' title 'K = 0.8 (chaotic above)', \
     file using @x:(ok(1) && column(c_lags) > 0 ? column(c_k) : NaN) with linespoints pt 7 ps 0.8 lc rgb up notitle, \
     '' using @x:(ok(-1) && column(c_lags) > 0 ? column(c_k) : NaN) with linespoints pt 6 ps 1.2 lc rgb down notitle, \
     '' using @x:(ok(0) && column(c_lags) > 0 ? column(c_k) : NaN) with linespoints pt 7 ps 0.8 lc rgb alone notitle
set autoscale y

if (lyapunov) {
   set ylabel 'Lyapunov exponent per forcing period'
   plot 0 with lines lc rgb 'gray' notitle, \
        file using @x:(ok(1) && column(c_periods) > 0 ? column(c_lambda) : NaN):(column(c_lambda + 1)) \
           with yerrorlines pt 7 ps 0.8 lc rgb up notitle, \
        '' using @x:(ok(-1) && column(c_periods) > 0 ? column(c_lambda) : NaN):(column(c_lambda + 1)) \
           with yerrorlines pt 6 ps 1.2 lc rgb down notitle, \
        '' using @x:(ok(0) && column(c_periods) > 0 ? column(c_lambda) : NaN):(column(c_lambda + 1)) \
           with yerrorlines pt 7 ps 0.8 lc rgb alone notitle
}
unset multiplot
