# Space-time picture of a dynamics run: the deflection u(x, t) as a colour map, x horizontal,
# t vertical.
# usage: gnuplot -e "stem='results/looseness_tip_stops'" scripts/plot_dynamics_field.gp
# reads  stem_field.dat (x, t, u; one block per output time, blocks separated by a blank line)
# writes stem_field.png
# needs: field
if (!exists("stem")) stem = 'results/vibrobeam'
# 1 if file f exists and holds at least one data line (the '#' header does not count)
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
field_file = stem.'_field.dat'
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_field.png'

set title 'Deflection u(x, t): '.stem
set xlabel 'x (m)'
set ylabel "t (s)" offset 1, 0
set cblabel 'u (m)'

if (!has_data(field_file)) {
   set label 1 'no data in '.field_file at graph 0.5, 0.5 center
   set xrange [0:1]
   set yrange [0:1]
   unset key
   plot NaN notitle
   exit
}

stats field_file using 1 nooutput
set xrange [STATS_min:STATS_max]
stats field_file using 2 nooutput
t_min = STATS_min
t_max = STATS_max
stats field_file using 3 nooutput
u_abs_max = (abs(STATS_min) > abs(STATS_max)) ? abs(STATS_min) : abs(STATS_max)

# A diverging palette symmetric about u = 0: blue below the rest line, red above.
set palette defined (-1 '#2c4aa8', -0.5 '#84b4e6', 0 '#f7f7f7', 0.5 '#f0a07e', 1 '#b2182b')
if (u_abs_max > 0) {
   set cbrange [-u_abs_max:u_abs_max]
} else {
   set cbrange [-1:1]
   set label 1 'u = 0 everywhere' at graph 0.5, 0.5 center front
}
set format cb '%.2g'
if (t_max > t_min) { set yrange [t_min:t_max] }
set view map
set pm3d map corners2color mean
set lmargin at screen 0.10
set rmargin at screen 0.82
set tmargin at screen 0.91
set bmargin at screen 0.11
set colorbox user origin screen 0.845, screen 0.11 size screen 0.03, screen 0.80
set tics out
unset key
splot field_file using 1:2:3 with pm3d notitle
