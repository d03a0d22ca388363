# Amplitude spectrum of the displacement at the tip or at an observation point of a
# dynamics run (single-sided, mean removed, Hann window, scaled so that a sine of amplitude A
# on a bin peaks at A; see src/analysis/statistics/vibrobeam_spectrum.f90), on logarithmic
# axes, limited to the band that holds the response: from the first bin above 0 to a
# little beyond the highest frequency whose amplitude reaches 1e-3 of the largest (above
# it, the response is gone and only round-off and the scheme's highest modes remain).
# usage: gnuplot -e "stem='results/forced_rattling'" scripts/plot_dynamics_spectrum.gp
#        optional: -e "point=2" the spectrum at &output points(2) (0, the default: the tip),
#        -e "where='x = 0.25 m'" its position for the title (scripts/plot_results.sh
#        --point sets both), -e "fmax=20" the upper frequency (Hz)
# reads  stem_spectrum.dat (frequency (Hz), tip amplitude (m), frequency (rad/s), then the
#        amplitude at each observation point; may hold only the header lines)
# writes stem_spectrum.png
# needs: spectrum
if (!exists("stem")) stem = 'results/vibrobeam'
if (!exists("point")) point = 0
if (!exists("where")) where = (point == 0) ? 'the tip' : sprintf('observation point %d', point)
# 1 if file f exists and holds at least one data line (the '#' header does not count)
has_data(f) = int(system("test -r '".f."' && awk '!/^#/ && NF {n = 1; exit} END {print n + 0}' '".f."' || echo 0"))
spectrum_file = stem.'_spectrum.dat'
# the amplitude's column: 2 at the tip, 3 + k at observation point k
a = (point == 0) ? 2 : 3 + point
set terminal pngcairo size 1000,600 noenhanced
set output stem.'_spectrum.png'
set xlabel 'frequency (Hz)'
set ylabel 'displacement amplitude at '.where.' (m)'
set grid xtics ytics

# number of amplitudes > 0 in column a past the zero frequency (a log axis cannot show zeros)
columns = int(system("test -r '".spectrum_file."' && awk '!/^#/ && NF {print NF; exit}' '".spectrum_file."' || echo 0"))
positive_count(f) = int(system("test -r '".f."' && awk '!/^#/ && NF && $1 > 0 && $".a." > 0 {n++} END {print n + 0}' '".f."' || echo 0"))
if (columns < a || positive_count(spectrum_file) == 0) {
   set title 'Displacement spectrum at '.where.': '.stem
   if (columns > 0 && columns < a) {
      set label 1 sprintf('no observation point %d in %s', point, spectrum_file) at graph 0.5, 0.5 center front
   } else {
      if (has_data(spectrum_file)) {
         set label 1 'zero spectrum in '.spectrum_file at graph 0.5, 0.5 center front
      } else {
         set label 1 'no data in '.spectrum_file at graph 0.5, 0.5 center front
      }
   }
   set xrange [0:1]
   set yrange [-1:1]
   unset key
   plot NaN notitle
   exit
}

# the largest peak (above 0 Hz), for the title and the amplitude range (5 decades below it)
stats spectrum_file using ($1 > 0 ? column(a) : NaN) nooutput
amplitude_max = STATS_max
stats spectrum_file using ($1 > 0 && column(a) >= amplitude_max ? $1 : NaN) nooutput
peak_frequency = STATS_min
stats spectrum_file using ($1 > 0 ? $1 : NaN) nooutput
f_low = STATS_min
nyquist = STATS_max
# the band: up to 1.5 times the highest frequency whose amplitude reaches 1e-3 of the peak (60 dB)
stats spectrum_file using ($1 > 0 && column(a) >= 1e-3*amplitude_max ? $1 : NaN) nooutput
f_high = 1.5*STATS_max
if (exists("fmax")) { f_high = fmax }
if (f_high > nyquist) { f_high = nyquist }
if (f_high <= f_low) { f_high = (nyquist > f_low) ? nyquist : 10*f_low }

set title sprintf('Displacement spectrum at %s: %s   (largest peak %.4g m at %.5g Hz, %.5g rad/s)', \
                  where, stem, amplitude_max, peak_frequency, 2*pi*peak_frequency)
set logscale xy
set format y '%.0e'
set xrange [f_low:f_high]
set yrange [amplitude_max*1e-5:amplitude_max*2]
set key top right
plot spectrum_file using ($1 > 0 ? $1 : NaN):(column(a) > 0 ? column(a) : NaN) with lines lw 1.5 \
        lc rgb '#1f77b4' title 'amplitude (Hann window)', \
     '+' using (peak_frequency):(amplitude_max) every ::0::0 with points pt 7 ps 1.2 lc rgb '#d62728' \
        title sprintf('peak %.5g Hz', peak_frequency)
