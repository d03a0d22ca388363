# Static equilibrium of a 'static' run: the deflection and the contact reactions.
# usage: gnuplot -e "stem='results/static_tip_contact'" scripts/plot_static.gp
# reads  stem_static.dat (x, u) and stem_reactions.dat (x, reaction); writes stem_static.png
if (!exists("stem")) stem = 'results/vibrobeam'
set terminal pngcairo size 1000,700 noenhanced
set output stem.'_static.png'
stats stem.'_static.dat' using 1 nooutput
beam_length = STATS_max
set multiplot layout 2,1 title 'Static equilibrium: '.stem
set xlabel 'x (m)'
set xrange [0:beam_length]
set grid
set ylabel 'u (mm)'
plot stem.'_static.dat' using 1:($2*1e3) with linespoints pt 7 ps 0.5 title 'deflection'
set ylabel 'reaction (N, positive upwards)'
stats stem.'_reactions.dat' using 2 nooutput
if (STATS_records > 0) {
   plot stem.'_reactions.dat' using 1:2 with impulses lw 3 title 'contact reactions', \
        '' using 1:2 with points pt 7 notitle
} else {
   set label 1 'no contact point' at graph 0.5, graph 0.5 center
   plot 0 notitle
}
unset multiplot
