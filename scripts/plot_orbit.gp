# The tip's orbit in the cross-section of a beam bending in two planes (&beam planes = 2):
# its deflection in z against its deflection in y over the run, the transient lighter
# (before &output measure_from), with the start marked. Equal axes: a circle is a circle.
# usage: gnuplot -e "stem='results/whirling_tube'" scripts/plot_orbit.gp
#        optional: -e "measure_from=0.2" (s) the start of the statistics window
# reads  stem_tip.dat of a two-plane run (docs/output.md, "Text files": column 2 u_tip in
#        y, column 6 u_tip in z)
# writes stem_orbit.png
if (!exists("stem")) stem = 'results/vibrobeam'
if (!exists("measure_from")) measure_from = 0
file = stem.'_tip.dat'
set terminal pngcairo size 900,900 noenhanced
set output stem.'_orbit.png'
set title 'Tip orbit in the cross-section: '.stem
set xlabel 'u_tip in y (mm)'
set ylabel 'u_tip in z (mm)'
set size ratio -1
set grid
set key top right
plot file using ($1 < measure_from ? 1e3*$2 : 1/0):(1e3*$6) with lines lc rgb '#bbbbbb' title 'transient', \
     file using ($1 >= measure_from ? 1e3*$2 : 1/0):(1e3*$6) with lines lc rgb '#1f77b4' title 'orbit', \
     file every ::0::0 using (1e3*$2):(1e3*$6) with points pt 7 ps 1.5 lc rgb '#d62728' title 'start'
