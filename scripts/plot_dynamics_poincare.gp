# Poincare section of a dynamics run driven by a harmonic load: the displacement against
# the velocity at the tip or at an observation point, sampled once per forcing period at
# phase 0 of the forcing (the samples of the statistics window, /statistics/poincare,
# docs/statistics.md), over the phase portrait of the window in grey. A periodic response
# of period n shows n dots, a quasi-periodic one a closed curve, chaos a folded cloud.
# usage: gnuplot -e "stem='results/forced_rattling'" scripts/plot_dynamics_poincare.gp
#        optional: -e "point=2" at &output points(2) (0, the default: the tip),
#        -e "where='x = 0.25 m'" its position for the title, -e "measure_from=0.2" (s) the
#        start of the statistics window (scripts/plot_results.sh sets them)
# reads  stem_poincare.dat (t, then u at the tip and at each observation point, then v at
#        each) and stem_tip.dat or stem_points.dat for the portrait
# writes stem_poincare.png
# needs: poincare
if (!exists("stem")) stem = 'results/vibrobeam'
if (!exists("point")) point = 0
if (!exists("where")) where = (point == 0) ? 'the tip' : sprintf('observation point %d', point)
if (!exists("measure_from")) measure_from = 0
file = stem.'_poincare.dat'
fields = int(system("test -r '".file."' && awk '!/^#/ && NF {print NF; exit}' '".file."' || echo 0"))
observations = (fields - 1)/2          # the tip and the observation points
samples = int(system("test -r '".file."' && awk '!/^#/ && NF {n++} END {print n + 0}' '".file."' || echo 0"))
# the portrait of the window, from the histories
if (point == 0) {
   portrait = stem.'_tip.dat'
   pu = 2
   pv = 3
} else {
   portrait = stem.'_points.dat'
   pu = 1 + point
   pv = 1 + (observations - 1) + point
}
set terminal pngcairo size 900,750 noenhanced
set output stem.'_poincare.png'
set xlabel 'displacement at '.where.' (mm)'
set ylabel 'velocity at '.where.' (m/s)'
set grid
set key top right
if (samples == 0 || point + 1 > observations) {
   set title 'Poincare section at '.where.': '.stem
   set label 1 'no Poincare samples for '.where.' in '.file at graph 0.5, 0.5 center front
   set xrange [0:1]
   set yrange [-1:1]
   plot NaN notitle
   exit
}
set title sprintf('Poincare section at %s (phase 0 of the forcing, %d periods): %s', where, samples, stem)
plot portrait using ($1 >= measure_from ? column(pu)*1e3 : NaN):(column(pv)) with lines lw 0.5 lc rgb '#d0d0d0' \
        title 'phase portrait (window)', \
     file using (column(2 + point)*1e3):(column(2 + observations + point)) with points pt 7 ps 0.5 \
        lc rgb '#d62728' title 'once per forcing period'
