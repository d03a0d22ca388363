# A continued branch of periodic orbits (&periodic parameter, docs/method.md
# "Continuation of periodic orbits"): the tip's amplitude (largest |u| over the orbit)
# against the parameter, stable points joined by a solid line, unstable ones by a dashed
# line, the folds, period doublings, Neimark-Sacker, grazing and branch points located on it
# marked; with &periodic switch_branch the branch of twice the period (stem_branch_2.dat,
# stem_bifurcations_2.dat) on the same axes, green stable and orange dashed unstable, its
# branch points marked; and the largest Floquet multiplier's modulus along the branches
# against |mu| = 1; and (stem_branch_multipliers.png) every multiplier of every point in
# the complex plane, coloured by the parameter, with the unit circle: a fold or a
# period doubling is a multiplier leaving it through +1 or -1, a Neimark-Sacker point a
# complex pair leaving it elsewhere. With
# -e "sweep='STEM2'" the points of a time-marching sweep of the same scene
# (STEM2_sweep.dat, its tip_displacement_max, up and down branches apart) are drawn over
# the branch: they lie on its stable parts and jump at its folds.
# The backbone of an autonomous orbit (the parameter periodic.tip_amplitude, docs/method.md
# "The backbone") is drawn as a backbone: its frequency 1/T (Hz) against the tip amplitude
# A (mm), and the largest |mu| against A.
# usage: gnuplot -e "stem='results/compliant_stop_branch'" scripts/plot_branch.gp
# needs: branch
# reads  stem_branch.dat and stem_bifurcations.dat (docs/output.md, "Text files"),
#        stem_branch_2.dat and stem_bifurcations_2.dat when they exist, and
#        stem_branch_multipliers.dat (and _2) when they exist;
# writes stem_branch.png and, with the multipliers, stem_branch_multipliers.png
if (!exists("stem")) stem = 'results/vibrobeam'
branch = stem.'_branch.dat'
found = stem.'_bifurcations.dat'
# the data rows of a file, 0 when it does not exist (awk reads a pipe: a missing file
# argument would end it before its END block prints)
rows(file) = int(system("cat '".file."' 2> /dev/null | awk '!/^#/ && NF {n++} END {print n + 0}'"))
# a column's number from its header line '# n: name (unit)'
col(file, name) = int(system("sed -n 's/^# \\([0-9]*\\): ".name." .*/\\1/p' '".file."'"))
p = col(branch, 'parameter')
a = col(branch, 'amplitude')
s = col(branch, 'stable')
m = col(branch, 'largest_multiplier')
xlabel = system("sed -n 's/^# [0-9]*: parameter (\\([^)]*\\)) \\(.*\\)$/\\2 (\\1)/p' '".branch."'")
# a backbone: the amplitude in mm on x, the frequency 1/T on y
backbone = strstrt(xlabel, 'periodic.tip_amplitude') > 0
xs = backbone ? 1e3 : 1
if (backbone) xlabel = 'tip amplitude A (mm), periodic.tip_amplitude'
have_found = rows(found) > 0
branch2 = stem.'_branch_2.dat'
found2 = stem.'_bifurcations_2.dat'
have_branch2 = rows(branch2) > 0
have_found2 = rows(found2) > 0
set terminal pngcairo size 1200,1000 noenhanced
set output stem.'_branch.png'
set multiplot layout 2,1 title (backbone ? 'Backbone: ' : 'Continued branch: ').stem
set grid
set xlabel xlabel
set ylabel 'tip amplitude (mm)'
set key top left
# stable and unstable parts: a segment is drawn in the style of its two ends (NaN breaks it)
stable_y(y, flag) = flag > 0.5 ? y : NaN
unstable_y(y, flag) = flag < 0.5 ? y : NaN
plot_cmd = "branch using (column(p)):(stable_y(column(a)*1e3, column(s))) with lines lw 2 lc rgb '#1f77b4' title 'stable', ".\
           "branch using (column(p)):(unstable_y(column(a)*1e3, column(s))) with lines lw 2 dt 2 lc rgb '#d62728' title 'unstable'"
if (have_found) {
   k = col(found, 'kind')
   fp = col(found, 'parameter')
   fa = col(found, 'amplitude')
   plot_cmd = plot_cmd.", found using (column(fp)):(column(k) == 1 ? column(fa)*1e3 : NaN) with points pt 7 ps 1.6 lc rgb 'black' title 'fold', ".\
              "found using (column(fp)):(column(k) == 2 ? column(fa)*1e3 : NaN) with points pt 5 ps 1.6 lc rgb '#2ca02c' title 'period doubling', ".\
              "found using (column(fp)):(column(k) == 3 ? column(fa)*1e3 : NaN) with points pt 9 ps 1.8 lc rgb '#9467bd' title 'Neimark-Sacker', ".\
              "found using (column(fp)):(column(k) == 4 ? column(fa)*1e3 : NaN) with points pt 13 ps 1.6 lc rgb '#e377c2' title 'grazing'"
}
if (have_branch2) {
   plot_cmd = plot_cmd.", branch2 using (column(p)):(stable_y(column(a)*1e3, column(s))) with lines lw 2 lc rgb '#2ca02c' title 'twice the period, stable', ".\
              "branch2 using (column(p)):(unstable_y(column(a)*1e3, column(s))) with lines lw 2 dt 2 lc rgb '#ff7f0e' title 'twice the period, unstable'"
}
if (have_found2) {
   k = col(found2, 'kind')
   fp = col(found2, 'parameter')
   fa = col(found2, 'amplitude')
   plot_cmd = plot_cmd.", found2 using (column(fp)):(column(k) == 5 ? column(fa)*1e3 : NaN) with points pt 11 ps 1.8 lc rgb '#17becf' title 'branch point'"
}
if (exists("sweep")) {
   swept = sweep.'_sweep.dat'
   sp = col(swept, 'parameter')
   sd = col(swept, 'direction')
   sa = col(swept, 'tip_displacement_max')
   plot_cmd = plot_cmd.", swept using (column(sp)):(column(sd) > 0 ? column(sa)*1e3 : NaN) with points pt 8 ps 1 lc rgb '#ff7f0e' title 'sweep up', ".\
              "swept using (column(sp)):(column(sd) < 0 ? column(sa)*1e3 : NaN) with points pt 10 ps 1 lc rgb '#8c564b' title 'sweep down'"
}
if (backbone) {
   T = col(branch, 'period')
   set ylabel 'frequency 1/T (Hz)'
   plot_cmd = "branch using (column(p)*xs):(stable_y(1/column(T), column(s))) with linespoints pt 7 ps 0.6 lw 2 lc rgb '#1f77b4' title 'backbone, stable', ".\
              "branch using (column(p)*xs):(unstable_y(1/column(T), column(s))) with linespoints pt 7 ps 0.6 lw 2 dt 2 lc rgb '#d62728' title 'unstable'"
}
eval('plot '.plot_cmd)
set ylabel 'largest |mu|'
set key top right
multipliers = "branch using (column(p)*xs):(column(m)) with linespoints pt 7 ps 0.6 lw 1 lc rgb '#1f77b4' title 'largest Floquet multiplier modulus', ".\
              "1 with lines dt 2 lc rgb '#d62728' title '|mu| = 1'"
if (have_branch2) {
   multipliers = multipliers.", branch2 using (column(p)):(column(m)) with linespoints pt 7 ps 0.6 lw 1 lc rgb '#2ca02c' title 'twice the period'"
}
eval('plot '.multipliers)
unset multiplot
# the multipliers in the complex plane, the axes wide enough for the largest
table = stem.'_branch_multipliers.dat'
table2 = stem.'_branch_multipliers_2.dat'
have_table = rows(table) > 0
have_table2 = rows(table2) > 0
if (have_table) {
   set output stem.'_branch_multipliers.png'
   set terminal pngcairo size 1000,900 noenhanced
   mp = col(table, 'parameter')
   mr = col(table, 'real')
   mi = col(table, 'imaginary')
   mm = col(table, 'modulus')
   largest = real(system("awk '!/^#/ && NF {if ($".mm." > m) m = $".mm."} END {print m + 0}' '".table."'"))
   reach = largest*1.15 > 1.2 ? largest*1.15 : 1.2
   set title 'Floquet multipliers along the branch: '.stem
   set xlabel 'Re'
   set ylabel 'Im'
   set size ratio -1
   set xrange [-reach:reach]
   set yrange [-reach:reach]
   set cblabel xlabel
   set palette rgbformulae 33,13,10
   set key below
   set parametric
   set trange [0:2*pi]
   multipliers = "cos(t), sin(t) with lines dt 2 lc rgb 'gray' title 'unit circle', ".\
                 "table using (column(mr)):(column(mi)):(column(mp)) with points pt 7 ps 0.7 lc palette title 'multipliers (colour: the parameter)'"
   if (have_table2) {
      multipliers = multipliers.", table2 using (column(mr)):(column(mi)):(column(mp)) with points pt 6 ps 1.0 lc palette title 'twice the period'"
   }
   eval('plot '.multipliers)
   unset parametric
}
