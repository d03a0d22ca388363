# Force of the compliant stops at each contact point against time (sampled at the output
# times; docs/output.md, /contact/force). Points whose force stays 0 are left out.
# usage: gnuplot -e "stem='results/looseness_compliant_stops'" scripts/plot_dynamics_force.gp
# reads  stem_force.dat (column 1: t (s), then one column per contact point (N))
# writes stem_force.png
# needs: force
if (!exists("stem")) stem = 'results/vibrobeam'
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
force_file = stem.'_force.dat'
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_force.png'
set title 'Compliant stops: contact force at each contact point: '.stem
set xlabel 't (s)'
set ylabel 'force on the beam (N, positive upwards)'
set grid
set key top right opaque box Left reverse
if (!has_data(force_file)) {
   set label 1 'no data in '.force_file at graph 0.5, 0.5 center
   set xrange [0:1]
   set yrange [0:1]
   plot NaN notitle
   exit
}
columns = int(system("awk '!/^#/ && NF {print NF; exit}' '".force_file."'"))
# the contact points' positions, from the header line
positions = system("sed -n 2p '".force_file."' | sed 's/.*x = //; s/ m$//'")
used = system("awk '!/^#/ {for (i = 2; i <= NF; i++) if ($i != 0) u[i] = 1} END {for (i = 2; i <= NF; i++) if (u[i]) printf \"%d \", i}' '".force_file."'")
if (strlen(used) == 0) {
   set label 1 'the force is 0 at every contact point' at graph 0.5, 0.5 center
   plot force_file using 1:(0) with lines notitle
   exit
}
plot for [c in used] force_file using 1:int(c) with lines lw 1.5 title sprintf('x = %s m', word(positions, int(c) - 1))
