# Response of a sweep against its parameter: RMS tip displacement, impact and episode
# rates, impulse per episode, power dissipated, each value with its standard error
# (docs/statistics.md). One parameter: the up branch, the down branch and independent
# points drawn apart. Two parameters (a map): each line of the second parameter in its own
# colour with its value in the key, the down branch of a line dashed.
# usage: gnuplot -e "stem='results/tube_frequency_sweep'" scripts/plot_sweep_response.gp
#        optional (scripts/plot_sweep.sh sets them from the sweep file): -e "xscale=173.4"
#        divides the parameter axis (a normalised frequency), -e "xlabel='...'" and
#        -e "ylabel2='...'" name the parameters; -e "text_terminal=1" draws as text into
#        stem_response.txt (for the tests)
# reads  stem_sweep.dat (docs/output.md, "Text files")
# writes stem_response.png
# needs: sweep
if (!exists("stem")) stem = 'results/sweep'
if (!exists("xscale")) xscale = 1
file = stem.'_sweep.dat'
if (exists("text_terminal")) {
   # as text, STEM_response.txt (the tests read the keys)
   set terminal dumb size 200,80
   set output stem.'_response.txt'
} else {
   set terminal pngcairo size 1200,850 noenhanced
   set output stem.'_response.png'
}
# the parameter's name and unit, from the column header (line 2) unless given
if (!exists("xlabel")) xlabel = system("sed -n '2s/.*parameter: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
if (!exists("ylabel2")) ylabel2 = system("sed -n '2s/.*parameter2: \\([^ ]*\\) (\\([^)]*\\)).*/\\1 (\\2)/p' '".file."'")
set multiplot layout 2,2 title 'Sweep: '.stem
set grid
set xlabel xlabel
set key top left
# a column by its name: the header lines '# 13: impact_rate (1/s)' (docs/output.md, "Text files")
col(name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
c_line = col('line')
direction = col('direction')
c_x = col('parameter')
c_y = col('parameter2')
status = col('status')
rms = col('tip_displacement_rms')
impacts = col('impact_rate')
episodes = col('episode_rate')
impulse = col('episode_impulse_mean')
dissipated = col('power_dissipated')
x = '(column(c_x)/xscale)'
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
# the lines of a map and the value of the second parameter on each
lines = int(system(sprintf("awk '!/^#/ && NF {if ($%d > n) n = $%d} END {print n + 0}' '", c_line, c_line).file."'"))
map = lines > 1 || strlen(ylabel2) > 0
line_value(j) = real(system(sprintf("awk '!/^#/ && NF && $%d == %d {print $%d; exit}' '", c_line, j, c_y).file."'"))
# a colour per line, from a palette that stays distinguishable (ColorBrewer Set1-like)
line_colour(j) = word('#e41a1c #377eb8 #4daf4a #984ea3 #ff7f00 #a65628 #f781bf #999999 #17becf #bcbd22', \
                      1 + (j - 1) % 10)
on_line(value, j, wanted) = (column(status) == 0 && column(c_line) == j && column(direction) == wanted) ? \
                            column(value) : NaN
# the key names the second parameter: 'obstacles.level_from(1) = 5e-05 m' from its label
name2 = strlen(ylabel2) > 0 ? ylabel2 : 'line'
unit2 = (strstrt(name2, ' (') > 0) ? name2[strstrt(name2, ' (') + 2:strlen(name2) - 1] : ''
name2 = (strstrt(name2, ' (') > 0) ? name2[1:strstrt(name2, ' (') - 1] : name2
line_title(j, wanted) = (wanted >= 0 && points(sprintf('$%d == %d && $%d == %d', c_line, j, direction, wanted)) > 0) ? \
                        sprintf('%s = %g %s', name2, line_value(j), unit2) : \
                        (wanted < 0 && j == 1 && n_down > 0 ? 'down branches (dashed)' : '')

if (map) {
   # one key, in the first panel: a colour per line of the map, in room left above the
   # data (about 7 % of the panel per line of the key) so that it hides none of them
   set key top left font ',9' spacing 0.9 box
   set offsets 0, 0, graph (lines < 12 ? 0.07*lines + 0.05 : 0.9), 0
   set ylabel 'RMS tip displacement (mm)'
   plot for [j = 1:lines] file using @x:(on_line(rms, j, 1)*1e3):(column(rms + 1)*1e3) with yerrorlines \
           lc rgb line_colour(j) pt 7 title line_title(j, 1), \
        for [j = 1:lines] '' using @x:(on_line(rms, j, 0)*1e3):(column(rms + 1)*1e3) with yerrorlines \
           lc rgb line_colour(j) pt 9 title line_title(j, 0), \
        for [j = 1:lines] '' using @x:(on_line(rms, j, -1)*1e3):(column(rms + 1)*1e3) with yerrorlines \
           lc rgb line_colour(j) dt 2 pt 5 title line_title(j, -1)
   unset key
   set offsets 0, 0, 0, 0
   set ylabel 'impacts per second (1/s)'
   plot for [j = 1:lines] file using @x:(on_line(impacts, j, 1)):(column(impacts + 1)) with yerrorlines \
           lc rgb line_colour(j) pt 7 title line_title(j, 1), \
        for [j = 1:lines] '' using @x:(on_line(impacts, j, 0)):(column(impacts + 1)) with yerrorlines \
           lc rgb line_colour(j) pt 9 title line_title(j, 0), \
        for [j = 1:lines] '' using @x:(on_line(impacts, j, -1)):(column(impacts + 1)) with yerrorlines \
           lc rgb line_colour(j) dt 2 pt 5 title line_title(j, -1)
   set ylabel 'mean impulse per contact episode (N s)'
   plot for [j = 1:lines] file using @x:(on_line(impulse, j, 1)):(column(impulse + 1)) with yerrorlines \
           lc rgb line_colour(j) pt 7 title line_title(j, 1), \
        for [j = 1:lines] '' using @x:(on_line(impulse, j, 0)):(column(impulse + 1)) with yerrorlines \
           lc rgb line_colour(j) pt 9 title line_title(j, 0), \
        for [j = 1:lines] '' using @x:(on_line(impulse, j, -1)):(column(impulse + 1)) with yerrorlines \
           lc rgb line_colour(j) dt 2 pt 5 title line_title(j, -1)
   set ylabel 'power dissipated, in all (W)'
   plot for [j = 1:lines] file using @x:(on_line(dissipated, j, 1)):(column(dissipated + 1)) with yerrorlines \
           lc rgb line_colour(j) pt 7 title line_title(j, 1), \
        for [j = 1:lines] '' using @x:(on_line(dissipated, j, 0)):(column(dissipated + 1)) with yerrorlines \
           lc rgb line_colour(j) pt 9 title line_title(j, 0), \
        for [j = 1:lines] '' using @x:(on_line(dissipated, j, -1)):(column(dissipated + 1)) with yerrorlines \
           lc rgb line_colour(j) dt 2 pt 5 title line_title(j, -1)
   unset multiplot
   exit
}

set ylabel 'RMS tip displacement (mm)'
plot file using @x:(series(rms, 1)*1e3):(column(rms + 1)*1e3) with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using @x:(series(rms, -1)*1e3):(column(rms + 1)*1e3) with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using @x:(series(rms, 0)*1e3):(column(rms + 1)*1e3) with yerrorlines lc rgb alone pt 9 \
        title t_alone('independent')
set ylabel 'impacts and episodes per second (1/s)'
plot file using @x:(series(impacts, 1)):(column(impacts + 1)) with yerrorlines lc rgb up pt 7 title t_up('impacts, up'), \
     '' using @x:(series(impacts, -1)):(column(impacts + 1)) with yerrorlines lc rgb down pt 5 title t_down('impacts, down'), \
     '' using @x:(series(impacts, 0)):(column(impacts + 1)) with yerrorlines lc rgb alone pt 9 \
        title t_alone('impacts, independent'), \
     '' using @x:(series(episodes, 1)):(column(episodes + 1)) with yerrorlines lc rgb up dt 2 pt 6 title t_up('episodes, up'), \
     '' using @x:(series(episodes, -1)):(column(episodes + 1)) with yerrorlines lc rgb down dt 2 pt 4 \
        title t_down('episodes, down'), \
     '' using @x:(series(episodes, 0)):(column(episodes + 1)) with yerrorlines lc rgb alone dt 2 pt 8 \
        title t_alone('episodes, independent')
set ylabel 'mean impulse per contact episode (N s)'
plot file using @x:(series(impulse, 1)):(column(impulse + 1)) with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using @x:(series(impulse, -1)):(column(impulse + 1)) with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using @x:(series(impulse, 0)):(column(impulse + 1)) with yerrorlines lc rgb alone pt 9 title t_alone('independent')
set ylabel 'power dissipated, in all (W)'
plot file using @x:(series(dissipated, 1)):(column(dissipated + 1)) with yerrorlines lc rgb up pt 7 title t_up('up'), \
     '' using @x:(series(dissipated, -1)):(column(dissipated + 1)) with yerrorlines lc rgb down pt 5 title t_down('down'), \
     '' using @x:(series(dissipated, 0)):(column(dissipated + 1)) with yerrorlines lc rgb alone pt 9 \
        title t_alone('independent')
unset multiplot
