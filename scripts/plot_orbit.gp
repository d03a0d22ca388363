# The tip's orbit in the cross-section of a beam bending in two planes (&beam planes = 2):
# its deflection in z against its deflection in y over the run, the transient lighter
# (before &output measure_from), with the start marked. Equal axes: a circle is a circle.
# With -e "point=k", the orbit of observation point k instead (&output points: a support
# plate along the tube).
# usage: gnuplot -e "stem='results/whirling_tube'" scripts/plot_orbit.gp
#        optional: -e "measure_from=0.2" (s) the start of the statistics window,
#        -e "radius=5e-4; center_y=0; center_z=0" (m) a round hole to draw
#        (scripts/plot_results.sh sets them from the result's attributes),
#        -e "point=2" observation point 2 (written to stem_orbit_point2.png)
# reads  stem_tip.dat of a two-plane run (docs/output.md, "Text files": column 2 u_tip in
#        y, column 6 u_tip in z), or stem_points.dat (with P points: column 1 + k u in y
#        at point k, column 1 + 2P + k u in z)
# writes stem_orbit.png (the hole, when given, drawn as a grey circle)
if (!exists("stem")) stem = 'results/vibrobeam'
if (!exists("measure_from")) measure_from = 0
if (!exists("center_y")) center_y = 0
if (!exists("center_z")) center_z = 0
if (exists("radius")) {
   set object 1 circle at 1e3*center_y, 1e3*center_z size 1e3*radius fs empty border lc rgb '#444444' lw 2
}
file = stem.'_tip.dat'
c_y = 2
c_z = 6
what = 'Tip'
label = 'u_tip'
picture = stem.'_orbit.png'
if (exists("point")) {
   file = stem.'_points.dat'
   # the columns of a row: t, then u and v in y at the P points, then u and v in z
   P = int(system("awk '!/^#/ && NF {print (NF - 1)/4; exit}' '".file."'"))
   c_y = 1 + point
   c_z = 1 + 2*P + point
   where = system("sed -n '2s/.*x = \\([^m]*\\) m.*/\\1/p' '".file."' | tr -d ','")
   what = sprintf('Orbit of observation point %d (x = %s m)', point, word(where, point))
   label = sprintf('u at point %d', point)
   picture = sprintf('%s_orbit_point%d.png', stem, point)
}
set terminal pngcairo size 900,900 noenhanced
set output picture
set title (exists("point") ? what : 'Tip orbit in the cross-section').': '.stem
set xlabel label.' in y (mm)'
set ylabel label.' in z (mm)'
set size ratio -1
set grid
set key top right
plot file using ($1 < measure_from ? 1e3*column(c_y) : 1/0):(1e3*column(c_z)) with lines lc rgb '#bbbbbb' \
          title 'transient', \
     file using ($1 >= measure_from ? 1e3*column(c_y) : 1/0):(1e3*column(c_z)) with lines lc rgb '#1f77b4' \
          title 'orbit', \
     file every ::0::0 using (1e3*column(c_y)):(1e3*column(c_z)) with points pt 7 ps 1.5 lc rgb '#d62728' \
          title 'start'
