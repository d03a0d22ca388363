# A sweep of single periodic orbits (&sweep with &analysis kind = 'periodic', no &periodic
# parameter; docs/sweeps.md, "Sweeps of periodic orbits and branches"): each point's orbit
# period and the largest modulus of its Floquet multipliers against the swept parameter
# (from STEM_sweep.dat), |mu| = 1 marked; failed points (status 1) are left out.
# usage: gnuplot -e "stem='results/S'" scripts/plot_sweep_orbits.gp
# reads  stem_sweep.dat; writes stem_orbits.png
if (!exists("stem")) stem = 'results/vibrobeam'
file = stem.'_sweep.dat'
col(name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
xlabel = system("sed -n 's/^# [0-9]*: parameter (\\([^)]*\\)) \\(.*\\)$/\\2 (\\1)/p' '".file."'")
p = col('parameter')
st = col('status')
T = col('period')
m = col('largest_multiplier')
ok(y) = column(st) == 0 ? y : NaN
set terminal pngcairo size 1000,800 noenhanced
set output stem.'_orbits.png'
set multiplot layout 2,1 title 'Periodic orbits of the sweep '.stem
set grid
set xlabel xlabel
set ylabel 'period (s)'
# a period the same at every point (a forcing level swept) gets a range around it
stats file using (ok(column(T))) nooutput
if (STATS_max - STATS_min <= 1e-9 * abs(STATS_max)) set yrange [STATS_min * (1 - 1e-3):STATS_max * (1 + 1e-3)]
plot file using (column(p)):(ok(column(T))) with linespoints pt 7 lw 2 lc rgb '#1f77b4' notitle
set ylabel 'largest |Floquet multiplier|'
set autoscale y
stats file using (ok(column(m))) nooutput
if (STATS_max - STATS_min <= 1e-9 * abs(STATS_max)) set yrange [STATS_min * (1 - 1e-3):STATS_max * (1 + 1e-3)]
plot file using (column(p)):(ok(column(m))) with linespoints pt 7 lw 2 lc rgb '#d62728' title 'orbit', \
     1 with lines dt 3 lc rgb 'black' title '|mu| = 1 (stability limit)'
unset multiplot
