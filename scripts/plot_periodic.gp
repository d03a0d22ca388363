# A periodic orbit of a 'periodic' analysis: the tip over one period, its phase portrait,
# and the Floquet multipliers in the complex plane with the unit circle (inside: stable).
# usage: gnuplot -e "stem='results/rattling_orbit'" scripts/plot_periodic.gp
# needs: orbit
# reads  stem_orbit.dat (t, u, v) and stem_multipliers.dat (real, imaginary, modulus);
# writes stem_periodic.png
if (!exists("stem")) stem = 'results/vibrobeam'
set terminal pngcairo size 1500,500 noenhanced
set output stem.'_periodic.png'
set multiplot layout 1,3 title 'Periodic orbit: '.stem
set grid
set xlabel 't (ms)'
set ylabel 'tip u (mm)'
plot stem.'_orbit.dat' using ($1*1e3):($2*1e3) with lines lw 2 title 'tip displacement over one period'
set xlabel 'tip u (mm)'
set ylabel 'tip v (m/s)'
plot stem.'_orbit.dat' using ($2*1e3):3 with lines lw 2 title 'phase portrait'
set xlabel 'Re'
set ylabel 'Im'
set size ratio -1
set xrange [-1.2:1.2]
set yrange [-1.2:1.2]
set parametric
set trange [0:2*pi]
if (system("test -f ".stem."_multipliers.dat && echo 1") eq "1") {
   plot cos(t), sin(t) with lines dt 2 lc rgb 'gray' title 'unit circle', \
        stem.'_multipliers.dat' using 1:2 with points pt 7 ps 1.2 title 'Floquet multipliers'
} else {
   plot cos(t), sin(t) with lines dt 2 lc rgb 'gray' title 'unit circle (no multipliers written)'
}
unset multiplot
