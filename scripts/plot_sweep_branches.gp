# The branches of a sweep of continuations (&sweep with &analysis kind = 'periodic' and
# &periodic parameter; docs/sweeps.md, "Sweeps of periodic orbits and branches"): each
# point's branch, the tip amplitude against the continued parameter, in its own colour,
# stable parts solid and unstable parts dashed, its folds, period doublings, Neimark-Sacker,
# grazing and branch points marked (as plot_branch.gp draws one branch); below, the largest
# Floquet multiplier's modulus along each branch against |mu| = 1. Backbones (&periodic
# autonomous, parameter 'periodic.tip_amplitude') are drawn as frequency 1/T against the
# tip amplitude.
# usage: gnuplot -e "stem='results/S'; points='S_point0001 S_point0002'; titles='1 N|2 N'; found='2'" \
#                   scripts/plot_sweep_branches.gp
#   points  the stems of the point files whose STEM_branch.dat exists, blank-separated
#   titles  each point's legend, '|'-separated in the same order
#   found   (optional) the indices, in points, of those whose POINT_bifurcations.dat has rows
# reads  POINT_branch.dat and POINT_bifurcations.dat of each point (docs/output.md; the
#        latter's columns 1 parameter, 2 amplitude, 3 kind)
# writes stem_branches.png
if (!exists("stem")) stem = 'results/vibrobeam'
rows(file) = int(system("cat '".file."' 2> /dev/null | awk '!/^#/ && NF {n++} END {print n + 0}'"))
col(file, name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
title(k) = system("echo '".titles."' | cut -d'|' -f".k)
n = words(points)
first = word(points, 1).'_branch.dat'
p = col(first, 'parameter')
a = col(first, 'amplitude')
s = col(first, 'stable')
m = col(first, 'largest_multiplier')
xlabel = system("sed -n 's/^# [0-9]*: parameter (\\([^)]*\\)) \\(.*\\)$/\\2 (\\1)/p' '".first."'")
T = col(first, 'period')
# backbones (the parameter periodic.tip_amplitude): the frequency 1/T against the amplitude
# in mm, as plot_branch.gp draws one
backbone = strstrt(xlabel, 'periodic.tip_amplitude') > 0
xs = backbone ? 1e3 : 1
if (backbone) xlabel = 'tip amplitude A (mm), periodic.tip_amplitude'
y(k) = backbone ? 1/column(T) : column(a)*1e3
colour(k) = word("#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e #8c564b #e377c2 #17becf #bcbd22 #7f7f7f", (k - 1) % 10 + 1)
stable_y(y, flag) = flag > 0.5 ? y : NaN
unstable_y(y, flag) = flag < 0.5 ? y : NaN
marker(kind) = kind == 1 ? 7 : (kind == 2 ? 5 : (kind == 3 ? 9 : (kind == 4 ? 13 : 11)))
set terminal pngcairo size 1200,1000 noenhanced
set output stem.'_branches.png'
set multiplot layout 2,1 title 'Branches of the sweep '.stem."\n(solid stable, dashed unstable; markers: ".\
    'circle fold, square period doubling, triangle Neimark-Sacker, diamond grazing)'
set grid
set xlabel xlabel
set ylabel backbone ? 'frequency 1/T (Hz)' : 'tip amplitude (mm)'
set key top left
cmd = "plot for [k=1:n] word(points, k).'_branch.dat' using (column(p)*xs):(stable_y(y(k), column(s))) ".\
      "with lines lw 2 lc rgb colour(k) title title(k), ".\
      "for [k=1:n] word(points, k).'_branch.dat' using (column(p)*xs):(unstable_y(y(k), column(s))) ".\
      "with lines lw 2 dt 2 lc rgb colour(k) notitle"
if (exists("found") && words(found) > 0) {
   cmd = cmd.", for [j=1:words(found)] word(points, int(word(found, j))).'_bifurcations.dat' ".\
         "using 1:($2*1e3):(marker($3)) with points pt variable ps 1.6 ".\
         "lc rgb colour(int(word(found, j))) notitle"
}
eval(cmd)
set ylabel 'largest |Floquet multiplier|'
set key top right
plot for [k=1:n] word(points, k).'_branch.dat' using (column(p)*xs):(column(m)) with lines lw 1.5 lc rgb colour(k) \
        title title(k), \
     1 with lines dt 3 lc rgb 'black' title '|mu| = 1'
unset multiplot
