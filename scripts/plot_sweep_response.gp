# Response of a sweep against its parameter: RMS tip displacement, impact and episode
# rates, impulse per episode, power dissipated; the up branch, the down branch and
# independent points drawn apart, each value with its standard error (docs/statistics.md).
# usage: gnuplot -e "stem='results/tube_frequency_sweep'" scripts/plot_sweep_response.gp
# reads  stem_sweep.dat (docs/output.md, "Text files")
# writes stem_response.png
# needs: sweep
if (!exists("stem")) stem = 'results/sweep'
file = stem.'_sweep.dat'
set terminal pngcairo size 1200,850 noenhanced
set output stem.'_response.png'
# the parameter's name and unit, from the column header (line 2)
label = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
set multiplot layout 2,2 title 'Sweep: '.stem
set grid
set xlabel label
set key top left
# a column by its name: the header lines '# 13: impact_rate (1/s)' (docs/output.md, "Text files")
col(name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
direction = col('direction')
c_x = col('parameter')
status = col('status')
rms = col('tip_displacement_rms')
impacts = col('impact_rate')
episodes = col('episode_rate')
impulse = col('episode_impulse_mean')
dissipated = col('power_dissipated')
# a value where the point succeeded and runs in the direction wanted (its error: the column after)
series(value, wanted) = (column(status) == 0 && column(direction) == wanted) ? column(value) : NaN
up = '#d62728'
down = '#1f77b4'
alone = '#2ca02c'
# which branches the sweep has (an empty title leaves a series out of the key)
points(test) = int(system("awk '!/^#/ && NF && ".test." {n++} END {print n + 0}' '".file."'"))
n_up = points(sprintf('$%d > 0', direction))
n_down = points(sprintf('$%d < 0', direction))
n_alone = points(sprintf('$%d == 0', direction))
t_up(s) = n_up > 0 ? s : ''
t_down(s) = n_down > 0 ? s : ''
t_alone(s) = n_alone > 0 ? s : ''
set ylabel 'RMS tip displacement (mm)'
plot file using (column(c_x)):(series(rms, 1)*1e3):(column(rms + 1)*1e3) with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using (column(c_x)):(series(rms, -1)*1e3):(column(rms + 1)*1e3) with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using (column(c_x)):(series(rms, 0)*1e3):(column(rms + 1)*1e3) with yerrorlines lc rgb alone pt 9 \
        title t_alone('independent')
set ylabel 'impacts and episodes per second (1/s)'
plot file using (column(c_x)):(series(impacts, 1)):(column(impacts + 1)) with yerrorlines lc rgb up pt 7 title t_up('impacts, up'), \
     '' using (column(c_x)):(series(impacts, -1)):(column(impacts + 1)) with yerrorlines lc rgb down pt 5 title t_down('impacts, down'), \
     '' using (column(c_x)):(series(impacts, 0)):(column(impacts + 1)) with yerrorlines lc rgb alone pt 9 \
        title t_alone('impacts, independent'), \
     '' using (column(c_x)):(series(episodes, 1)):(column(episodes + 1)) with yerrorlines lc rgb up dt 2 pt 6 title t_up('episodes, up'), \
     '' using (column(c_x)):(series(episodes, -1)):(column(episodes + 1)) with yerrorlines lc rgb down dt 2 pt 4 \
        title t_down('episodes, down'), \
     '' using (column(c_x)):(series(episodes, 0)):(column(episodes + 1)) with yerrorlines lc rgb alone dt 2 pt 8 \
        title t_alone('episodes, independent')
set ylabel 'mean impulse per contact episode (N s)'
plot file using (column(c_x)):(series(impulse, 1)):(column(impulse + 1)) with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using (column(c_x)):(series(impulse, -1)):(column(impulse + 1)) with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using (column(c_x)):(series(impulse, 0)):(column(impulse + 1)) with yerrorlines lc rgb alone pt 9 title t_alone('independent')
set ylabel 'power dissipated, in all (W)'
plot file using (column(c_x)):(series(dissipated, 1)):(column(dissipated + 1)) with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using (column(c_x)):(series(dissipated, -1)):(column(dissipated + 1)) with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using (column(c_x)):(series(dissipated, 0)):(column(dissipated + 1)) with yerrorlines lc rgb alone pt 9 \
        title t_alone('independent')
unset multiplot
