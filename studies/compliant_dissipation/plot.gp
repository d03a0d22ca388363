# Energy lost over 25 ms against N (dt = 1e-6 s): rigid e = 0.8 against damped compliant
# stops with equivalent restitution 0.8. Run: gnuplot studies/compliant_dissipation/plot.gp
# (from the repository root, after run.sh).
set terminal pngcairo size 800,500
set output 'studies/compliant_dissipation/dissipation.png'
set logscale x 2
set xlabel 'elements N'
set ylabel 'energy lost over 25 ms / E(0)'
set key bottom right
set grid
plot "< awk '$2==\"1e-6\" && $3==\"rigid\"' studies/compliant_dissipation/results.txt" using 1:6 with linespoints title 'rigid stops, e = 0.8', \
     "< awk '$2==\"1e-6\" && $3==\"damped\"' studies/compliant_dissipation/results.txt" using 1:6 with linespoints title 'compliant k = 1e7 N/m, Hunt-Crossley e_{eq} = 0.8'
