# A periodic orbit of a 'periodic' analysis: the tip over one period, its phase portrait,
# and its Floquet multipliers: in the complex plane with the unit circle (inside: stable;
# a multiplier outside it drawn as an open red circle), the axes wide enough for the
# largest, and their moduli on a logarithmic scale, largest first, against the line
# |mu| = 1 (docs/output.md, "Periodic orbit"; those of a damped beam spread over many
# decades and crowd the origin of the complex plane).
# usage: gnuplot -e "stem='results/rattling_orbit'" scripts/plot_periodic.gp
# needs: orbit
# reads  stem_orbit.dat (t, u, v) and stem_multipliers.dat (real, imaginary, modulus);
# writes stem_periodic.png
if (!exists("stem")) stem = 'results/vibrobeam'
set terminal pngcairo size 1300,1000 noenhanced
set output stem.'_periodic.png'
multipliers = stem.'_multipliers.dat'
have_multipliers = system("test -f ".multipliers." && echo 1") eq "1"
largest = 0
count = 0
if (have_multipliers) {
   largest = real(system("awk '!/^#/ && NF {if ($3 > m) m = $3} END {print m + 0}' '".multipliers."'"))
   count = int(system("awk '!/^#/ && NF {n++} END {print n + 0}' '".multipliers."'"))
}
# (a conservative scene's autonomous orbit has every multiplier on the unit circle at best,
# to round-off or the monodromy's error: docs/method.md, "Autonomous periodic orbits")
verdict = largest < 1 ? 'stable' : (largest < 1.001 ? 'on the unit circle to 1e-3: neutral at best' : 'unstable')
set multiplot layout 2,2 title 'Periodic orbit: '.stem
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
reach = largest*1.15 > 1.2 ? largest*1.15 : 1.2
set xrange [-reach:reach]
set yrange [-reach:reach]
set key below
set parametric
set trange [0:2*pi]
if (have_multipliers) {
   set title sprintf('Floquet multipliers: largest |mu| = %.6g (%s)', largest, verdict)
   plot cos(t), sin(t) with lines dt 2 lc rgb 'gray' title 'unit circle', \
        multipliers using 1:($3 < 1 ? $2 : NaN) with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'inside (decaying)', \
        multipliers using 1:($3 >= 1 ? $2 : NaN) with points pt 6 ps 1.8 lw 2 lc rgb '#d62728' title 'on or outside'
} else {
   set title 'no multipliers written'
   plot cos(t), sin(t) with lines dt 2 lc rgb 'gray' title 'unit circle'
}
unset parametric
set size noratio
set autoscale
set logscale y
set format y '%.0e'
set xlabel 'multiplier (largest modulus first)'
set ylabel '|mu|'
set key default
set key top right
if (have_multipliers) {
   set title sprintf('%d multipliers, their moduli', count)
   set xrange [0.5:count + 0.5]
   top = largest*10 > 10 ? largest*10 : 10
   set yrange [*:top]
   plot multipliers using ($0 + 1):($3 > 0 ? $3 : NaN) with points pt 7 ps 1 lc rgb '#1f77b4' title '|mu_k|', \
        1 with lines dt 2 lc rgb '#d62728' title '|mu| = 1'
}
unset multiplot
