# Impacts of a dynamics run: the impulse of every impact against time, coloured by the
# position x of the contact point.
# usage: gnuplot -e "stem='results/looseness_tip_stops'" scripts/plot_dynamics_impacts.gp
# reads  stem_impacts.dat (t, x, impulse, velocity before, velocity after; may hold only the
#        header line) and, for the time axis, stem_tip.dat (optional)
# writes stem_impacts.png
# needs: impacts
if (!exists("stem")) stem = 'results/vibrobeam'
# 1 if file f exists and holds at least one data line (the '#' header does not count)
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
impact_file = stem.'_impacts.dat'
tip_file = stem.'_tip.dat'
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_impacts.png'

set xlabel 't (s)'
set ylabel 'impulse (N s)   [> 0: push upwards, from a lower obstacle]'
set grid
# Time axis over the whole run when the tip series tells its length.
if (has_data(tip_file)) {
   stats tip_file using 1 nooutput
   if (STATS_max > STATS_min) { set xrange [STATS_min:STATS_max] }
}

if (!has_data(impact_file)) {
   set title 'Impacts: '.stem.' (none)'
   set label 1 'no impacts' at graph 0.5, 0.5 center front font ',20'
   set yrange [-1:1]
   if (!has_data(tip_file)) { set xrange [0:1] }
   unset key
   plot NaN notitle
   exit
}

stats impact_file using 1 nooutput
count = STATS_records
stats impact_file using 2 nooutput
x_min = STATS_min
x_max = STATS_max
stats impact_file using 3 nooutput
impulse_sum = STATS_sum
impulse_abs_max = (abs(STATS_min) > abs(STATS_max)) ? abs(STATS_min) : abs(STATS_max)

set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#c8d419')
set cblabel 'contact point x (m)'
if (x_max > x_min) {
   set cbrange [x_min:x_max]
   set colorbox
   where = sprintf('x from %g to %g m', x_min, x_max)
} else {
   # a single contact point: its colour is the middle of the palette, no colour bar needed
   d = (abs(x_min) > 0) ? 0.01*abs(x_min) : 1e-3
   set cbrange [x_min - d:x_max + d]
   unset colorbox
   where = sprintf('all at x = %g m', x_min)
}
set yrange [-1.08*impulse_abs_max:1.08*impulse_abs_max]
set xzeroaxis lt -1 lw 1
set title sprintf('Impacts: %s  (%d impacts, %s; sum of impulses %.4g N s)', stem, count, where, impulse_sum)
set key top right opaque box
plot impact_file using 1:3:2 with impulses lw 1.5 lc palette notitle, \
     '' using 1:3:2 with points pt 7 ps 0.6 lc palette title 'impulse of one impact'
