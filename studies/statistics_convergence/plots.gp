# Plots of the statistics convergence study (run by run_study.sh after tables.sh):
# convergence_<scene>.png, each statistic divided by its value at the finest level of the
# path, with error bars of 2 standard errors (batch means), against N (joint and N paths)
# or dt (dt path).
set terminal pngcairo size 1500,1000 font ',10' noenhanced
set datafile commentschars '#'
set key top left font ',9' spacing 0.9
set grid
set logscale x 2
set ylabel 'value / finest value'
do for [scene in 'tube_1g forced_rattling'] {
   set output 'convergence_'.scene.'.png'
   set multiplot layout 3,3 title 'Statistics against refinement, scene '.scene.' (error bars: 2 standard errors)'
   do for [path in 'joint N dt'] {
      f = 'convergence_'.scene.'_'.path.'.dat'
      if (path eq 'dt') { set xlabel 'dt (s), N = 16'; xc = 2; unset logscale x; set logscale x 2; set xrange [*:*] reverse; set format x '%.2g' } \
      else { set xlabel (path eq 'joint' ? 'N (dt = 3.2e-4/N s)' : 'N (dt = 5e-6 s)'); xc = 1; set xrange [*:*] noreverse; set format x '%g' }
      set title path.': RMS, contact force, power input'
      set yrange [0.8:1.2]
      plot f u (column(xc)):3:(2*$4) w yerrorlines t 'RMS tip displacement', \
           f u (column(xc)):5:(2*$6) w yerrorlines t 'RMS tip velocity', \
           f u (column(xc)):17:(2*$18) w yerrorlines t 'contact force', \
           f u (column(xc)):19:(2*$20) w yerrorlines t 'power input', \
           f u (column(xc)):9:(2*$10) w yerrorlines t 'episode rate'
      set title path.': counts and impulses'
      set yrange [0:3]
      plot f u (column(xc)):7:(2*$8) w yerrorlines t 'impact rate', \
           f u (column(xc)):15:(2*$16) w yerrorlines t 'contact fraction', \
           f u (column(xc)):11:(2*$12) w yerrorlines t 'impulse per episode, mean', \
           f u (column(xc)):13:(2*$14) w yerrorlines t 'impulse per episode, max'
      set title path.': dissipated powers'
      set yrange [0.5:1.5]
      plot f u (column(xc)):21:(2*$22) w yerrorlines t 'at the stops', \
           f u (column(xc)):23:(2*$24) w yerrorlines t 'by damping', \
           f u (column(xc)):25:(2*$26) w yerrorlines t 'in all'
   }
   unset multiplot
}
