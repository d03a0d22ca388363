# Largest penetration into the obstacles over all contact points against time (sampled at
# the output times), on a log axis when some is positive.
# usage: gnuplot -e "stem='results/looseness_tip_stops'" scripts/plot_dynamics_penetration.gp
# reads  stem_energy.dat (column 10: penetration (m))
# writes stem_penetration.png
# needs: energy
if (!exists("stem")) stem = 'results/vibrobeam'
# 1 if file f exists and holds at least one data line (the '#' header does not count)
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
energy_file = stem.'_energy.dat'
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_penetration.png'

set title 'Penetration into the obstacles: '.stem
set xlabel 't (s)'
set grid
set key top right opaque box Left reverse

if (!has_data(energy_file)) {
   set ylabel 'penetration (m)'
   set label 1 'no data in '.energy_file at graph 0.5, 0.5 center
   set xrange [0:1]
   set yrange [0:1]
   plot NaN notitle
   exit
}

stats energy_file using 1 nooutput
if (STATS_max > STATS_min) { set xrange [STATS_min:STATS_max] }
stats energy_file using 10 nooutput
largest = STATS_max
largest_at = NaN
positive = 0
if (largest > 0) {
   stats energy_file using ($10 == largest ? $1 : NaN) nooutput
   largest_at = STATS_min
   stats energy_file using ($10 > 0 ? 1 : NaN) nooutput
   positive = STATS_records
}
stats energy_file using 1 nooutput
samples = STATS_records

if (largest > 0) {
   set logscale y
   set format y '%.0e'
   set ylabel 'penetration (m, log scale)'
   set yrange [*:10*largest]   # headroom for the key above the largest value
   set title sprintf("Penetration into the obstacles: %s\nlargest %.3g m at t = %.4g s; > 0 at %d of %d output times (zeros not shown)", \
                     stem, largest, largest_at, positive, samples)
   plot energy_file using 1:($10 > 0 ? $10 : NaN) with impulses lw 1 lc rgb '#d62728' notitle, \
        '' using 1:($10 > 0 ? $10 : NaN) with points pt 7 ps 0.6 lc rgb '#d62728' \
           title 'penetration at an output time', \
        largest with lines dt 2 lc rgb '#555555' title sprintf('largest: %.3g m', largest)
} else {
   set ylabel 'penetration (m)'
   set yrange [-0.2:1]
   set label 1 sprintf('no penetration (all %d output times are 0)', samples) at graph 0.5, 0.75 center front
   plot energy_file using 1:10 with lines lw 2 lc rgb '#d62728' title 'penetration'
}
