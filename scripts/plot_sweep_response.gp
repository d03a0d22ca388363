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
# columns: 3 direction, 4 parameter, 6 status; value, error pairs from 9 (docs/output.md)
series(value, wanted) = (column(6) == 0 && column(3) == wanted) ? column(value) : NaN
up = '#d62728'
down = '#1f77b4'
alone = '#2ca02c'
# which branches the sweep has (an empty title leaves a series out of the key)
points(test) = int(system("awk '!/^#/ && NF && ".test." {n++} END {print n + 0}' '".file."'"))
n_up = points('$3 > 0')
n_down = points('$3 < 0')
n_alone = points('$3 == 0')
t_up(s) = n_up > 0 ? s : ''
t_down(s) = n_down > 0 ? s : ''
t_alone(s) = n_alone > 0 ? s : ''
set ylabel 'RMS tip displacement (mm)'
plot file using 4:(series(9, 1)*1e3):($10*1e3) with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using 4:(series(9, -1)*1e3):($10*1e3) with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using 4:(series(9, 0)*1e3):($10*1e3) with yerrorlines lc rgb alone pt 9 title t_alone('independent')
set ylabel 'impacts and episodes per second (1/s)'
plot file using 4:(series(13, 1)):14 with yerrorlines lc rgb up pt 7 title t_up('impacts, up'), \
     '' using 4:(series(13, -1)):14 with yerrorlines lc rgb down pt 5 title t_down('impacts, down'), \
     '' using 4:(series(13, 0)):14 with yerrorlines lc rgb alone pt 9 title t_alone('impacts, independent'), \
     '' using 4:(series(15, 1)):16 with yerrorlines lc rgb up dt 2 pt 6 title t_up('episodes, up'), \
     '' using 4:(series(15, -1)):16 with yerrorlines lc rgb down dt 2 pt 4 title t_down('episodes, down'), \
     '' using 4:(series(15, 0)):16 with yerrorlines lc rgb alone dt 2 pt 8 title t_alone('episodes, independent')
set ylabel 'mean impulse per contact episode (N s)'
plot file using 4:(series(17, 1)):18 with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using 4:(series(17, -1)):18 with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using 4:(series(17, 0)):18 with yerrorlines lc rgb alone pt 9 title t_alone('independent')
set ylabel 'power dissipated, in all (W)'
plot file using 4:(series(29, 1)):30 with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using 4:(series(29, -1)):30 with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using 4:(series(29, 0)):30 with yerrorlines lc rgb alone pt 9 title t_alone('independent')
unset multiplot
