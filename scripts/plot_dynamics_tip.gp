# Tip displacement (with the obstacle levels acting at the tip) and tip velocity of a dynamics run.
# usage: gnuplot -e "stem='results/looseness_tip_stops'" scripts/plot_dynamics_tip.gp
# reads  stem_tip.dat (t, u_tip, v_tip, tip force); optional: stem_obstacles.dat (x, g1, g2)
#        and the first block of stem_field.dat (to locate the beam tip)
# writes stem_tip.png
# needs: tip
if (!exists("stem")) stem = 'results/vibrobeam'
# 1 if file f exists and holds at least one data line (the '#' header does not count)
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
tip_file = stem.'_tip.dat'
obstacle_file = stem.'_obstacles.dat'
field_file = stem.'_field.dat'
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_tip.png'

# Obstacle levels at the tip: the contact point with the largest x, when it is the beam tip.
none = 1e29                       # |level| >= none: no obstacle on that side (the file writes +-1e30)
g1 = NaN
g2 = NaN
note = ''
if (has_data(obstacle_file)) {
   stats obstacle_file using 1 nooutput
   x_obstacle = STATS_max
   x_tip = x_obstacle
   if (has_data(field_file)) {
      stats field_file every :::0::0 using 1 nooutput
      x_tip = STATS_max
   }
   if (abs(x_obstacle - x_tip) <= 1e-9*(abs(x_tip) > 1 ? abs(x_tip) : 1)) {
      stats obstacle_file using ($1 == x_obstacle ? $2 : NaN) nooutput
      if (STATS_max > -none) { g1 = STATS_max }
      stats obstacle_file using ($1 == x_obstacle ? $3 : NaN) nooutput
      if (STATS_min < none) { g2 = STATS_min }
      if (g1 != g1 && g2 != g2) { note = 'no obstacle acts at the tip' }
   } else {
      note = sprintf('no contact point at the tip (x = %g m); outermost one at x = %g m', x_tip, x_obstacle)
   }
} else {
   note = 'no obstacles'
}
defined(g) = (g == g)             # false for NaN

if (!has_data(tip_file)) {
   set title 'Tip response: '.tip_file
   set label 1 'no data in '.tip_file at graph 0.5, 0.5 center
   set xrange [0:1]
   set yrange [-1:1]
   set xlabel 't (s)'
   unset key
   plot NaN notitle
   exit
}

set multiplot layout 2,1 title 'Tip response: '.stem
set grid
set key at screen 0.73, graph 1 left top Left reverse
set lmargin at screen 0.09
set rmargin at screen 0.72
set format x ''
set xlabel ''
set ylabel 'tip displacement u_tip (mm)'
if (strlen(note) > 0) { set title note }
plot tip_file using 1:($2*1e3) with lines lw 1 lc rgb '#1f77b4' title 'u_tip', \
     (defined(g2) ? g2*1e3 : NaN) with lines dt 2 lw 2 lc rgb '#d62728' \
        title (defined(g2) ? sprintf('upper stop g2 = %g mm', g2*1e3) : ''), \
     (defined(g1) ? g1*1e3 : NaN) with lines dt 2 lw 2 lc rgb '#2ca02c' \
        title (defined(g1) ? sprintf('lower stop g1 = %g mm', g1*1e3) : '')
unset title
set format x '% g'
set xlabel 't (s)'
set ylabel 'tip velocity v_tip (m/s)'
plot tip_file using 1:3 with lines lw 1 lc rgb '#ff7f0e' title 'v_tip'
unset multiplot
