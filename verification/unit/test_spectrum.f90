!> Unit test of vibrobeam_spectrum (SPEC §5, the spectrum of a point's response) on
!! synthetic signals with closed-form spectra:
!! (1) three sines exactly on bins plus a constant, window 'none', even and odd n: peaks at
!!     the right bins, amplitudes to 1e-10, every other bin below 1e-10 of the largest;
!!     with window 'hann' the same on-bin amplitudes to 1e-10 (coherent gain 1/2 corrected);
!! (2) three sines off the bins (offsets 0.5, 0.3, -0.25 bin), window 'hann', even and odd
!!     n: peak within one bin of the true frequency, amplitude between the worst Hann
!!     scalloping loss 8/(3 pi) = 0.8488 (-1.42 dB, half-way between bins) and 1, within 1%;
!!     the half-bin one at 8/(3 pi) A to 1%;
!! (3) a constant signal: the mean is removed, so the spectrum is zero (to round-off);
!! (4) an arbitrary signal against a direct O(n^2) DFT written here (independent of FFTW);
!! (5) the error paths (n = 0, 1, dt <= 0, non-finite sample, unknown window), n = 2, and
!!     the edge cases of spectral_peaks.
!! Round-off allowances (u = eps/2, gamma_n = n u/(1 - n u)), derived, not chosen:
!! - a frequency k/(n dt) and its reference each round twice: gamma_4 relative;
!! - an amplitude a_k = c |X_k|/sum(w): an error |dx_j| <= E in every sample moves it by
!!   at most 2E (w >= 0); the FFT by at most 2/sum(w) gamma_{4 log2(n) + 8} sqrt(n) ||w (x -
!!   mean)||_2 (the O(u log n) normwise bound of a fast transform, Higham, Accuracy and
!!   Stability of Numerical Algorithms, 2002, §24.1, with 8 roundings more for FFTW's
!!   mixed-radix codelets); a window value, (1 - cos(2 pi j/n))/2, is off by (2 pi gamma_4
!!   + gamma_2)/2, which moves a_k by 4 times that times max |x - mean|; the final
!!   abs, division and doubling by gamma_4 a_k (`amplitude_bound`);
!! - a sample sin(2 pi b j/n + phi) is off by gamma_5 times its argument (up to 2 pi b)
!!   plus gamma_2: at bin 251 the samples themselves carry 1e-12 A, the largest term.
program test_spectrum
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_spectrum, only: amplitude_spectrum, spectral_peaks, bin_width
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: dt = 0.01_dp                     ! s
   real(dp), parameter :: amplitudes(3) = [1.5_dp, 0.4_dp, 0.025_dp]
   real(dp), parameter :: phases(3) = [0.3_dp, -1.1_dp, 2.0_dp]
   real(dp), parameter :: hann_worst_scalloping = 8/(3*pi)  ! sinc(1/2)/(1 - 1/4)
   integer, parameter :: sizes(2) = [1000, 999]
   integer :: i

   do i = 1, size(sizes)
      call on_bin_sines(sizes(i), 'none')
      call on_bin_sines(sizes(i), 'hann')
      call off_bin_sines(sizes(i) + 24)
   end do
   call constant_signal(512, 'none')
   call constant_signal(511, 'hann')
   call against_direct_dft(37, 'none')
   call against_direct_dft(37, 'hann')
   call against_direct_dft(64, 'hann')
   call two_samples()
   call error_paths()
   call peak_edge_cases()
   call t%finish('test_spectrum')

contains

   !> sum_m A_m sin(2 pi k_m j/n + phi_m) + 3.7 with k_m = 37, 120, 251 (bins well inside
   !! 2..n/2-2, so Hann's exactness holds), n samples.
   subroutine on_bin_sines(n, window)
      integer, intent(in) :: n
      character(len=*), intent(in) :: window
      integer, parameter :: bins(3) = [37, 120, 251]
      real(dp), allocatable :: signal(:), frequency(:), amplitude(:)
      integer, allocatable :: peaks(:)
      logical :: other(n/2 + 1)
      integer :: stat, j, m
      character(len=256) :: errmsg
      character(len=64) :: title
      real(dp) :: sample_error
      write (title, '(a,i0,a)') 'on-bin sines, n = ', n, ', window '//window
      allocate (signal(n))
      allocate (peaks(0))   ! gfortran 12 -fcheck=bounds: else a false -Wmaybe-uninitialized on peaks = ...
      do j = 0, n - 1
         signal(j + 1) = 3.7_dp + sum(amplitudes*sin(2*pi*bins*j/n + phases))
      end do
      sample_error = sum(amplitudes*(gamma_n(5)*(2*pi*bins + abs(phases)) + gamma_n(6))) + gamma_n(4)*(3.7_dp + sum(amplitudes))
      call amplitude_spectrum(signal, dt, frequency, amplitude, stat, errmsg, window)
      call t%check_true(trim(title)//': stat', stat == 0, trim(errmsg))
      if (stat /= 0) return
      call t%check_true(trim(title)//': number of bins n/2+1', size(frequency) == n/2 + 1 .and. &
                        size(amplitude) == n/2 + 1)
      call t%check_close(trim(title)//': bin width = frequency(2)', frequency(2), 1/(n*dt), gamma_n(4))
      call t%check_close(trim(title)//': last frequency floor(n/2)/(n dt)', frequency(size(frequency)), &
                         (n/2)/(n*dt), gamma_n(4))
      call t%check_close(trim(title)//': bin_width(n, dt)', bin_width(n, dt), 1/(n*dt), gamma_n(4))
      peaks = spectral_peaks(frequency, amplitude, 3, 1e-3_dp)
      call t%check_true(trim(title)//': three peaks found', size(peaks) == 3)
      if (size(peaks) /= 3) return
      other = .true.
      do m = 1, 3
         ! peaks come by decreasing amplitude, and amplitudes(:) decreases
         call t%check_true(trim(title)//': peak '//char(48 + m)//' at its bin', peaks(m) == bins(m) + 1, &
                           'index '//integer_text(peaks(m))//', expected '//integer_text(bins(m) + 1))
         call t%check_close(trim(title)//': peak '//char(48 + m)//' frequency', frequency(peaks(m)), &
                            bins(m)/(n*dt), gamma_n(4))
         call t%check_close(trim(title)//': peak '//char(48 + m)//' amplitude', abs(amplitude(bins(m) + 1) - &
                            amplitudes(m)), 0.0_dp, 1.0_dp, amplitude_bound(signal, window, sample_error, amplitudes(m)))
         other(bins(m) + 1) = .false.
         ! the Hann window spreads each sine over its two neighbouring bins
         if (window == 'hann') other(bins(m):bins(m) + 2) = .false.
      end do
      call t%check_close(trim(title)//': largest amplitude off the sines (mean removed)', &
                         maxval(amplitude, mask=other), 0.0_dp, 1.0_dp, amplitude_bound(signal, window, sample_error, 0.0_dp))
   end subroutine on_bin_sines

   !> Sines at (k + delta)/(n dt) with delta = 0.5, 0.3, -0.25, window 'hann'.
   subroutine off_bin_sines(n)
      integer, intent(in) :: n
      real(dp), parameter :: positions(3) = [40.5_dp, 130.3_dp, 299.75_dp]   ! in bins
      real(dp), allocatable :: signal(:), frequency(:), amplitude(:)
      integer, allocatable :: peaks(:)
      real(dp) :: width, f_true, tolerance
      integer :: stat, j, m
      character(len=256) :: errmsg
      character(len=64) :: title, label
      write (title, '(a,i0,a)') 'off-bin sines, n = ', n, ', window hann'
      allocate (signal(n))
      allocate (peaks(0))   ! see on_bin_sines
      do j = 0, n - 1
         signal(j + 1) = sum(amplitudes*sin(2*pi*positions*j/n + phases))
      end do
      call amplitude_spectrum(signal, dt, frequency, amplitude, stat, errmsg)   ! default window
      call t%check_true(trim(title)//': stat', stat == 0, trim(errmsg))
      if (stat /= 0) return
      width = bin_width(n, dt)
      peaks = spectral_peaks(frequency, amplitude, 3, 1e-3_dp)
      call t%check_true(trim(title)//': three peaks found', size(peaks) == 3)
      if (size(peaks) /= 3) return
      tolerance = 1e-2_dp
      do m = 1, 3
         write (label, '(a,a,i0,a,f5.2,a)') trim(title), ': sine ', m, ' (', positions(m), ' bins)'
         f_true = positions(m)/(n*dt)
         call t%check_close(trim(label)//' peak frequency within one bin', abs(frequency(peaks(m)) - f_true), &
                            0.0_dp, 1.0_dp, width)
         ! amplitude in [8/(3 pi), 1] A, 1% allowed for leakage of the other components
         call t%check_true(trim(label)//' peak amplitude within the Hann scalloping loss', &
                           amplitude(peaks(m)) >= (1 - tolerance)*hann_worst_scalloping*amplitudes(m) .and. &
                           amplitude(peaks(m)) <= (1 + tolerance)*amplitudes(m), &
                           'value '//real_text(amplitude(peaks(m)))//', reference interval ['// &
                           real_text(hann_worst_scalloping*amplitudes(m))//', '//real_text(amplitudes(m))// &
                           '], tolerance '//real_text(tolerance))
      end do
      ! half-way between bins: the worst title, 8/(3 pi) A
      call t%check_close(trim(title)//': half-bin sine amplitude = 8/(3 pi) A', amplitude(peaks(1)), &
                         hann_worst_scalloping*amplitudes(1), tolerance)
   end subroutine off_bin_sines

   subroutine constant_signal(n, window)
      integer, intent(in) :: n
      character(len=*), intent(in) :: window
      real(dp), allocatable :: signal(:), frequency(:), amplitude(:)
      integer :: stat
      character(len=256) :: errmsg
      character(len=64) :: title
      write (title, '(a,i0,a)') 'constant signal 3.7, n = ', n, ', window '//window
      allocate (signal(n), source=3.7_dp)
      call amplitude_spectrum(signal, dt, frequency, amplitude, stat, errmsg, window)
      call t%check_true(trim(title)//': stat', stat == 0, trim(errmsg))
      if (stat /= 0) return
      ! the computed mean is off by at most gamma_n 3.7 and x_j - mean is then exact
      ! (Sterbenz): a constant c, |c| <= gamma_n 3.7, whose amplitude is |c| in bin 0 (and
      ! bin 1 with Hann); the FFT of a constant adds a relative gamma_{4 log2(n) + 8}
      call t%check_close(trim(title)//': largest amplitude (mean removed)', maxval(amplitude), 0.0_dp, 1.0_dp, &
                         gamma_n(n)*3.7_dp*(1 + gamma_n(4*ceiling(log(real(n, dp))/log(2.0_dp)) + 8)))
   end subroutine constant_signal

   !> An arbitrary signal against the definition (module documentation) evaluated by a
   !! direct sum here: a_k = c_k |sum_j w_j (x_j - mean) exp(-2 pi i jk/n)| / sum_j w_j.
   subroutine against_direct_dft(n, window)
      integer, intent(in) :: n
      character(len=*), intent(in) :: window
      real(dp) :: signal(n), weights(n), centred(n), reference
      complex(dp) :: sum_k
      real(dp), allocatable :: frequency(:), amplitude(:)
      integer :: stat, j, k
      character(len=256) :: errmsg
      character(len=64) :: title
      write (title, '(a,i0,a)') 'direct DFT, n = ', n, ', window '//window
      do j = 1, n
         signal(j) = cos(0.37_dp*j**2) + 0.01_dp*j   ! deterministic, no structure
      end do
      weights = 1
      if (window == 'hann') weights = [(0.5_dp - 0.5_dp*cos(2*pi*j/n), j = 0, n - 1)]
      centred = signal - sum(signal)/n
      call amplitude_spectrum(signal, dt, frequency, amplitude, stat, errmsg, window)
      call t%check_true(trim(title)//': stat', stat == 0, trim(errmsg))
      if (stat /= 0) return
      do k = 0, n/2
         sum_k = 0
         do j = 0, n - 1
            sum_k = sum_k + weights(j + 1)*centred(j + 1)*exp(cmplx(0.0_dp, -2*pi*j*k/n, dp))
         end do
         reference = abs(sum_k)/sum(weights)
         if (k > 0 .and. 2*k /= n) reference = 2*reference
         ! the direct sum: each phase 2 pi j k/n (< pi n) rounds 4 times, each complex term
         ! and the sum of n add gamma_{n+8}; scaled like an amplitude (2/sum(w))
         call t%check_close(trim(title)//': amplitude of bin '//integer_text(k), abs(amplitude(k + 1) - reference), &
                            0.0_dp, 1.0_dp, 2/sum(weights)*sum(abs(weights*centred))*(gamma_n(4)*pi*n + gamma_n(n + 8)) &
                            + amplitude_bound(signal, window, 0.0_dp, reference))
      end do
   end subroutine against_direct_dft

   !> n = 2, the smallest record: frequencies 0 and Nyquist; [1, -1] is a cosine at
   !! Nyquist of amplitude 1 (not doubled: it has no mirror image).
   subroutine two_samples()
      real(dp), allocatable :: frequency(:), amplitude(:)
      integer :: stat
      character(len=256) :: errmsg
      call amplitude_spectrum([1.0_dp, -1.0_dp], dt, frequency, amplitude, stat, errmsg, 'none')
      call t%check_true('n = 2: stat', stat == 0, trim(errmsg))
      if (stat /= 0) return
      call t%check_true('n = 2: two bins', size(frequency) == 2)
      if (size(frequency) /= 2) return
      ! every operation on [1, -1] is exact (mean 0, X_1 = 2, 2/2 = 1); the frequency
      ! k/(n dt) and 1/(2 dt) round twice each
      call t%check_close('n = 2: Nyquist frequency 1/(2 dt)', frequency(2), 1/(2*dt), gamma_n(4))
      call t%check_close('n = 2: Nyquist amplitude', amplitude(2), 1.0_dp, gamma_n(2))
      call t%check_close('n = 2: zero-frequency amplitude', amplitude(1), 0.0_dp, 1.0_dp, gamma_n(2))
   end subroutine two_samples

   !> Round-off bound of an amplitude a (module comment): samples off by sample_error,
   !! the window's values, the FFT, and the final scaling.
   function amplitude_bound(signal, window, sample_error, a) result(bound)
      real(dp), intent(in) :: signal(:), sample_error, a
      character(len=*), intent(in) :: window
      real(dp) :: bound, weights(size(signal)), centred(size(signal)), window_error
      integer :: n, j
      n = size(signal)
      weights = 1
      window_error = 0
      if (window == 'hann') then
         weights = [(0.5_dp - 0.5_dp*cos(2*pi*j/n), j=0, n - 1)]
         window_error = (2*pi*gamma_n(4) + gamma_n(2))/2
      end if
      centred = signal - sum(signal)/n
      bound = 2*sample_error + 2/sum(weights)*gamma_n(4*ceiling(log(real(n, dp))/log(2.0_dp)) + 8)*sqrt(real(n, dp))* &
              norm2(weights*centred) + 4*window_error*maxval(abs(centred)) + gamma_n(4)*a
   end function amplitude_bound

   subroutine error_paths()
      real(dp), allocatable :: frequency(:), amplitude(:)
      real(dp) :: empty(0), signal(8)
      integer :: stat, j
      character(len=256) :: errmsg
      call amplitude_spectrum([1.0_dp], dt, frequency, amplitude, stat, errmsg)
      call expect_failure('n = 1', stat, errmsg, frequency, amplitude)
      call amplitude_spectrum(empty, dt, frequency, amplitude, stat, errmsg)
      call expect_failure('n = 0', stat, errmsg, frequency, amplitude)
      signal = [(real(j, dp), j = 1, 8)]
      call amplitude_spectrum(signal, 0.0_dp, frequency, amplitude, stat, errmsg)
      call expect_failure('dt = 0', stat, errmsg, frequency, amplitude)
      call amplitude_spectrum(signal, -dt, frequency, amplitude, stat, errmsg)
      call expect_failure('dt < 0', stat, errmsg, frequency, amplitude)
      call amplitude_spectrum(signal, dt, frequency, amplitude, stat, errmsg, 'hamming')
      call expect_failure('unknown window', stat, errmsg, frequency, amplitude)
      signal(5) = ieee_value(signal(5), ieee_quiet_nan)
      call amplitude_spectrum(signal, dt, frequency, amplitude, stat, errmsg)
      call expect_failure('NaN sample', stat, errmsg, frequency, amplitude)
   end subroutine error_paths

   subroutine expect_failure(title, stat, errmsg, frequency, amplitude)
      character(len=*), intent(in) :: title, errmsg
      integer, intent(in) :: stat
      real(dp), allocatable, intent(in) :: frequency(:), amplitude(:)
      call t%check_true(title//': stat /= 0', stat /= 0, 'stat = '//integer_text(stat))
      call t%check_true(title//': error message', len_trim(errmsg) > 0)
      call t%check_true(title//': empty results', allocated(frequency) .and. allocated(amplitude))
      if (allocated(frequency) .and. allocated(amplitude)) &
         call t%check_true(title//': empty results', size(frequency) == 0 .and. size(amplitude) == 0)
   end subroutine expect_failure

   subroutine peak_edge_cases()
      real(dp), parameter :: f(7) = [0.0_dp, 1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 5.0_dp, 6.0_dp]
      real(dp), parameter :: a(7) = [9.0_dp, 1.0_dp, 5.0_dp, 2.0_dp, 2.0_dp, 3.0_dp, 4.0_dp]
      integer, allocatable :: peaks(:)
      allocate (peaks(0))   ! see on_bin_sines
      ! maxima: index 3 (5.0) and 7 (4.0, last entry); index 1 is at frequency 0
      peaks = spectral_peaks(f, a, 5, 0.0_dp)
      call t%check_true('peaks: more wanted than exist', size(peaks) == 2)
      if (size(peaks) == 2) call t%check_true('peaks: order by amplitude', all(peaks == [3, 7]), &
                                              'got '//integer_text(peaks(1))//', '//integer_text(peaks(2)))
      peaks = spectral_peaks(f, a, 1, 0.0_dp)
      call t%check_true('peaks: count = 1', size(peaks) == 1)
      if (size(peaks) == 1) call t%check_true('peaks: count = 1 gives the largest', peaks(1) == 3)
      ! threshold relative to max = 9: 0.5 -> 4.5, only index 3 remains
      peaks = spectral_peaks(f, a, 3, 0.5_dp)
      call t%check_true('peaks: min_relative filters', size(peaks) == 1)
      peaks = spectral_peaks(f, [2.0_dp, 1.0_dp, 3.0_dp, 3.0_dp, 1.0_dp, 0.5_dp, 0.0_dp], 3, 0.0_dp)
      call t%check_true('peaks: a flat top counts once', size(peaks) == 1)
      if (size(peaks) == 1) call t%check_true('peaks: a flat top at its first entry', peaks(1) == 3)
      peaks = spectral_peaks(f, spread(0.0_dp, 1, 7), 3, 0.0_dp)
      call t%check_true('peaks: zero spectrum has none', size(peaks) == 0)
      peaks = spectral_peaks(f(1:6), a, 3, 0.0_dp)
      call t%check_true('peaks: sizes differ -> none', size(peaks) == 0)
      peaks = spectral_peaks(f, a, 0, 0.0_dp)
      call t%check_true('peaks: count = 0 -> none', size(peaks) == 0)
   end subroutine peak_edge_cases


end program test_spectrum
