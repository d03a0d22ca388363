# Energy budget of a dynamics run and the relative drift of its balance.
# usage: gnuplot -e "stem='results/looseness_tip_stops'" scripts/plot_dynamics_energy.gp
# reads  stem_energy.dat (t, kinetic, elastic, work, dissipated, by impacts, by damping,
#        total = kinetic + elastic, balance = total - work + dissipated, penetration)
# writes stem_energy.png
# needs: energy
if (!exists("stem")) stem = 'results/vibrobeam'
# 1 if file f exists and holds at least one data line (the '#' header does not count)
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
energy_file = stem.'_energy.dat'
set terminal pngcairo size 1000,700 noenhanced
set output stem.'_energy.png'

if (!has_data(energy_file)) {
   set title 'Energy budget: '.stem
   set label 1 'no data in '.energy_file at graph 0.5, 0.5 center
   set xrange [0:1]
   set yrange [-1:1]
   set xlabel 't (s)'
   set ylabel 'energy (J)'
   plot NaN notitle
   exit
}

# Values of the first row (t = 0): balance(0) and total(0).
stats energy_file every ::0::0 using 9 nooutput
balance0 = STATS_min
stats energy_file every ::0::0 using 8 nooutput
total0 = STATS_min
# Energy scale of the drift: |total(0)|, or when the beam starts at rest the largest |total|
# or |work| of the run (a start from rest under loads), or 1 J when everything is zero.
tiny = 1e-300
scale = abs(total0)
scale_name = '|total(0)|'
if (scale <= tiny) {
   stats energy_file using (abs($8) > abs($4) ? abs($8) : abs($4)) nooutput
   scale = STATS_max
   scale_name = 'max(|total|, |work|)'
}
if (scale <= tiny) { scale = 1; scale_name = '1 J' }
drift(b) = (b - balance0)/scale
stats energy_file using (abs(drift($9))) nooutput
largest_drift = STATS_max

set multiplot title 'Energy budget: '.stem
set lmargin at screen 0.10
set rmargin at screen 0.64
set grid
set key at screen 0.65, graph 1 left top Left reverse

# Upper panel: the energies.
set tmargin at screen 0.93
set bmargin at screen 0.42
set format x ''
set xlabel ''
set ylabel 'energy (J)'
plot energy_file using 1:2 with lines lw 1 lc rgb '#1f77b4' title 'kinetic', \
     '' using 1:3 with lines lw 1 lc rgb '#ff7f0e' title 'elastic', \
     '' using 1:8 with lines lw 2.5 lc rgb '#000000' title 'total = kinetic + elastic', \
     '' using 1:4 with lines lw 2 lc rgb '#2ca02c' title 'work of loads', \
     '' using 1:5 with lines lw 2 lc rgb '#d62728' title 'dissipated (impacts + damping)', \
     '' using 1:9 with lines lw 2 dt 2 lc rgb '#9467bd' title 'balance = total - work + dissipated'

# Lower panel: the relative drift |balance - balance(0)| / scale on a log axis (round-off
# sits near 1e-16 .. 1e-12, a real leak shows orders of magnitude above it).
set tmargin at screen 0.36
set bmargin at screen 0.09
set format x '% g'
set xlabel 't (s)'
set ylabel 'relative drift (log scale)'
set label 2 "relative drift =\n|balance - balance(0)| / ".scale_name at screen 0.655, graph 0.78 left
if (largest_drift > 0) {
   set logscale y
   set format y '%.0e'
   set label 3 sprintf("largest: %.3g", largest_drift) at screen 0.655, graph 0.50 left
   plot energy_file using 1:(abs(drift($9)) > 0 ? abs(drift($9)) : NaN) \
        with lines lw 1 lc rgb '#9467bd' \
        title 'relative drift of the balance'
} else {
   set ylabel 'relative drift (linear)'
   set yrange [-1:1]
   set label 1 'balance exactly constant (drift 0)' at graph 0.5, 0.7 center front
   plot energy_file using 1:(drift($9)) with lines lw 1 lc rgb '#9467bd' \
        title 'relative drift' 
}
unset multiplot
