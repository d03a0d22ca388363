# Phase portrait of a dynamics run: the velocity against the displacement at the tip or at
# an observation point, over the whole run (the transient lighter, before &output
# measure_from) at the output times (every `every` steps).
# usage: gnuplot -e "stem='results/forced_rattling'" scripts/plot_dynamics_phase.gp
#        optional: -e "point=2" at &output points(2) (0, the default: the tip),
#        -e "where='x = 0.25 m'" its position for the title, -e "measure_from=0.2" (s) the
#        start of the statistics window (scripts/plot_results.sh sets them)
# reads  stem_tip.dat (t, u, v at the tip), or stem_points.dat (t, then u at each point,
#        then v at each) for a point
# writes stem_phase.png
# needs: tip
if (!exists("stem")) stem = 'results/vibrobeam'
if (!exists("point")) point = 0
if (!exists("where")) where = (point == 0) ? 'the tip' : sprintf('observation point %d', point)
if (!exists("measure_from")) measure_from = 0
if (point == 0) {
   file = stem.'_tip.dat'
   u = 2
   v = 3
} else {
   file = stem.'_points.dat'
   # t, then u at each of the P points, then v at each
   fields = int(system("test -r '".file."' && awk '!/^#/ && NF {print NF; exit}' '".file."' || echo 0"))
   points = (fields - 1)/2
   u = 1 + point
   v = 1 + points + point
}
set terminal pngcairo size 900,750 noenhanced
set output stem.'_phase.png'
set title 'Phase portrait at '.where.': '.stem
set xlabel 'displacement at '.where.' (mm)'
set ylabel 'velocity at '.where.' (m/s)'
set grid
set key top right
rows = int(system("test -r '".file."' && awk '!/^#/ && NF {n++} END {print n + 0}' '".file."' || echo 0"))
if (rows == 0 || (point > 0 && point > points)) {
   set label 1 'no data for '.where.' in '.file at graph 0.5, 0.5 center front
   set xrange [0:1]
   set yrange [-1:1]
   plot NaN notitle
   exit
}
plot file using ($1 < measure_from ? column(u)*1e3 : NaN):(column(v)) with lines lw 0.6 lc rgb '#c6dbef' \
        title (measure_from > 0 ? 'transient (t < measure_from)' : ''), \
     '' using ($1 >= measure_from ? column(u)*1e3 : NaN):(column(v)) with lines lw 0.8 lc rgb '#1f77b4' \
        title (measure_from > 0 ? 'statistics window' : 'whole run')
