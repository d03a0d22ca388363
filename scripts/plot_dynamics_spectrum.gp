# Amplitude spectrum of the tip displacement of a dynamics run (single-sided, mean removed,
# Hann window, scaled so that a sine of amplitude A on a bin peaks at A; see
# src/analysis/statistics/vibrobeam_spectrum.f90), on a logarithmic amplitude axis.
# usage: gnuplot -e "stem='results/looseness_tip_stops'" scripts/plot_dynamics_spectrum.gp
#        optional: -e "fmax=20" to fix the upper frequency (Hz); by default the axis ends a
#        little beyond the last frequency whose amplitude exceeds 1e-4 of the largest one
# reads  stem_spectrum.dat (frequency (Hz), amplitude (m); may hold only the header line)
# writes stem_spectrum.png
# needs: spectrum
if (!exists("stem")) stem = 'results/vibrobeam'
# 1 if file f exists and holds at least one data line (the '#' header does not count)
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
spectrum_file = stem.'_spectrum.dat'
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_spectrum.png'
set xlabel 'frequency (Hz)'
set ylabel 'tip displacement amplitude (m)'
set grid xtics ytics mytics

# number of amplitudes > 0 in file f (a log axis cannot show zeros; stats fails on none)
positive_count(f) = int(system("test -r '".f."' && awk '!/^#/ && NF && $2 > 0 {n++} END {print n + 0}' '".f."' || echo 0"))
if (positive_count(spectrum_file) == 0) {
   set title 'Tip displacement spectrum: '.stem
   if (has_data(spectrum_file)) {
      set label 1 'zero spectrum in '.spectrum_file at graph 0.5, 0.5 center front
   } else {
      set label 1 'no data in '.spectrum_file at graph 0.5, 0.5 center front
   }
   set xrange [0:1]
   set yrange [-1:1]
   unset key
   plot NaN notitle
   exit
}

# Largest peak, for the title and the amplitude range (8 decades below it).
stats spectrum_file using 2 nooutput
amplitude_max = STATS_max
peak_index = STATS_index_max
stats spectrum_file every ::peak_index::peak_index using 1 nooutput
peak_frequency = STATS_max
stats spectrum_file using 1 nooutput
nyquist = STATS_max
stats spectrum_file using ($2 > 1e-4*amplitude_max ? $1 : NaN) nooutput
f_high = (STATS_records > 0 && STATS_max > 0) ? 1.2*STATS_max : nyquist
if (exists("fmax")) { f_high = fmax }
if (f_high > nyquist) { f_high = nyquist }
if (f_high <= 0) { f_high = (nyquist > 0) ? nyquist : 1 }

set title sprintf('Tip displacement spectrum: %s   (largest peak %.4g m at %.5g Hz)', stem, amplitude_max, peak_frequency)
set logscale y
set format y '%.0e'
set xrange [0:f_high]
set yrange [amplitude_max*1e-8:amplitude_max*2]
set key top right
plot spectrum_file using 1:($2 > 0 ? $2 : NaN) with lines lw 1.5 lc rgb '#1f77b4' title 'amplitude (Hann window)', \
     '+' using (peak_frequency):(amplitude_max) every ::0::0 with points pt 7 ps 1.2 lc rgb '#d62728' \
        title sprintf('peak %.5g Hz', peak_frequency)
