!> Amplitude spectrum of a uniformly sampled response (docs/output.md: "the spectrum (FFT) of a
!! point's response"), through FFTW's real-to-complex transform (`fftw3.f03` interface).
!!
!! Conventions. A record x_j = x(j dt), j = 0..n-1, of n >= 2 samples with step dt (s).
!! The mean of the record is subtracted, the window w_j is applied, and FFTW computes
!!
!!     X_k = sum_j w_j (x_j - mean) exp(-2 pi i j k / n),   k = 0..n/2  (n/2 rounded down)
!!
!! at the frequencies f_k = k/(n dt) (Hz), k = 0..n/2: the bin width is 1/(n dt) and the
!! last frequency is the Nyquist frequency 1/(2 dt) when n is even, just below it when n
!! is odd. The single-sided amplitude spectrum is
!!
!!     a_k = c_k |X_k| / sum_j w_j,   c_k = 2 for 0 < k < n/2,  c_k = 1 for k = 0 and k = n/2,
!!
!! in the unit of the signal (m for a displacement). Dividing by sum_j w_j = n * (coherent
!! gain of the window) corrects the window's coherent gain, so that a sinusoid
!! A sin(2 pi f_k t + phi) whose frequency is a bin frequency gives a_k = A exactly with
!! window 'none' (coherent gain 1) and with window 'hann' when 2 <= k <= n/2 - 2 (the Hann
!! window spreads the component over bins k-1..k+1 only, so the mirror component at -k does
!! not reach bin k). Off-bin, the Hann peak is lower by the scalloping loss, at most
!! sinc(1/2)/(1 - 1/4) = 8/(3 pi) = 0.8488 (-1.42 dB) half-way between two bins.
!!
!! Windows: 'hann' (default), the periodic (DFT-even) Hann window
!! w_j = (1 - cos(2 pi j/n))/2, j = 0..n-1, whose coherent gain sum(w)/n is exactly 1/2
!! (so amplitudes are multiplied by 2); 'none', the rectangular window w_j = 1 (coherent
!! gain 1). Hann is the default because a response of a beam is never periodic in the
!! record length: its side lobes decay like 1/k^3 instead of 1/k, so a weak mode is not
!! buried in the leakage of a strong one.
module vibrobeam_spectrum
   use, intrinsic :: iso_c_binding
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_status, only: stat_failure, stat_invalid_argument
   implicit none
   private
   public :: amplitude_spectrum, spectral_peaks, interpolated_peaks, bin_width

   include 'fftw3.f03'

contains

   !> Width of one frequency bin (Hz) of the transform of `n` samples with step `dt` (s):
   !! 1/(n dt). Zero when n < 1 or dt <= 0 (no bins).
   elemental function bin_width(n, dt) result(width)
      integer, intent(in) :: n        !! number of samples
      real(dp), intent(in) :: dt      !! sampling step (s)
      real(dp) :: width               !! bin width (Hz)
      width = 0
      if (n >= 1 .and. dt > 0) width = 1/(n*dt)
   end function bin_width

   !> Single-sided amplitude spectrum of `signal`, sampled every `dt` seconds, after
   !! removing its mean and applying `window` (module documentation: frequencies, scaling,
   !! windows). One FFTW real-to-complex transform of size n = size(signal).
   !!
   !! stat = stat_invalid_argument with a message when n < 2, dt is not a positive finite number, the signal
   !! holds a non-finite value, or the window is unknown; stat = stat_failure when FFTW cannot
   !! make a plan. On failure `frequency` and `amplitude` are allocated with size 0, so a caller
   !! may write them as empty results.
   subroutine amplitude_spectrum(signal, dt, frequency, amplitude, stat, errmsg, window)
      real(dp), intent(in) :: signal(:)                 !! samples x(j dt), j = 0..n-1 (any unit)
      real(dp), intent(in) :: dt                        !! sampling step (s), > 0
      real(dp), allocatable, intent(out) :: frequency(:)  !! (n/2+1) f_k = k/(n dt) (Hz)
      real(dp), allocatable, intent(out) :: amplitude(:)  !! (n/2+1) a_k (unit of the signal)
      integer, intent(out) :: stat                      !! 0 on success
      character(len=*), intent(out) :: errmsg           !! reason of the failure, blank on success
      character(len=*), intent(in), optional :: window  !! 'hann' (default) or 'none'
      character(len=:), allocatable :: window_name
      real(c_double), pointer :: windowed(:)
      complex(c_double_complex), pointer :: transform(:)
      type(c_ptr) :: windowed_memory, transform_memory
      real(dp), allocatable :: weights(:)
      real(dp) :: mean, weight_sum
      type(c_ptr) :: plan
      integer :: n, bins, j, k

      stat = 0
      errmsg = ''
      allocate (frequency(0), amplitude(0))
      n = size(signal)
      window_name = 'hann'
      if (present(window)) window_name = trim(adjustl(window))
      if (n < 2) then
         stat = stat_invalid_argument
         write (errmsg, '(a,i0,a)') 'amplitude spectrum: the signal has ', n, ' sample(s); at least 2 are needed'
         return
      end if
      if (.not. (ieee_is_finite(dt) .and. dt > 0)) then
         stat = stat_invalid_argument
         write (errmsg, '(a,g0,a)') 'amplitude spectrum: sampling step dt = ', dt, ' s is not a positive finite number'
         return
      end if
      if (.not. all(ieee_is_finite(signal))) then
         stat = stat_invalid_argument
         write (errmsg, '(a,i0,a)') 'amplitude spectrum: sample ', findloc(ieee_is_finite(signal), .false., dim=1), &
            ' of the signal is not finite'
         return
      end if
      allocate (weights(n))
      select case (window_name)
      case ('hann')
         ! periodic Hann: sum(weights) = n/2 exactly, coherent gain 1/2
         weights = [(0.5_dp*(1 - cos(2*pi*j/n)), j = 0, n - 1)]
      case ('none')
         weights = 1
      case default
         stat = stat_invalid_argument
         errmsg = 'amplitude spectrum: unknown window '''//window_name//''' (expected ''hann'' or ''none'')'
         return
      end select
      weight_sum = sum(weights)

      bins = n/2 + 1
      ! FFTW's own allocation: always aligned for its SIMD code, so the plan (and the
      ! rounding of the transform) never depends on where the arrays happen to lie; a
      ! sweep's results do not depend on its threads (docs/sweeps.md)
      windowed_memory = fftw_alloc_real(int(n, c_size_t))
      transform_memory = fftw_alloc_complex(int(bins, c_size_t))
      call c_f_pointer(windowed_memory, windowed, [n])
      call c_f_pointer(transform_memory, transform, [bins])
      ! Plan before filling the input: the planner may use the arrays as scratch space
      ! (their interface declares them intent(out)); FFTW_ESTIMATE does not time transforms.
      ! The planner is not thread-safe (FFTW manual, "Thread safety"): one thread at a time.
      !$omp critical (vibrobeam_fftw_planner)
      plan = fftw_plan_dft_r2c_1d(int(n, c_int), windowed, transform, FFTW_ESTIMATE)
      !$omp end critical (vibrobeam_fftw_planner)
      if (.not. c_associated(plan)) then
         stat = stat_failure
         write (errmsg, '(a,i0)') 'amplitude spectrum: FFTW could not plan a real-to-complex transform of size ', n
         call fftw_free(windowed_memory)
         call fftw_free(transform_memory)
         return
      end if
      mean = sum(signal)/n
      windowed = real(weights*(signal - mean), c_double)
      call fftw_execute_dft_r2c(plan, windowed, transform)
      !$omp critical (vibrobeam_fftw_planner)
      call fftw_destroy_plan(plan)
      !$omp end critical (vibrobeam_fftw_planner)

      deallocate (frequency, amplitude)
      allocate (frequency(bins), amplitude(bins))
      do k = 0, bins - 1
         frequency(k + 1) = k/(n*dt)
         amplitude(k + 1) = real(abs(transform(k + 1)), dp)/weight_sum
         ! negative frequencies fold onto positive ones, except at 0 and at Nyquist (n even)
         if (k > 0 .and. 2*k /= n) amplitude(k + 1) = 2*amplitude(k + 1)
      end do
      call fftw_free(windowed_memory)
      call fftw_free(transform_memory)
   end subroutine amplitude_spectrum

   !> Indices into `amplitude` of the `count` largest local maxima whose amplitude is
   !! larger than min_relative * maxval(amplitude), by decreasing amplitude (fewer when
   !! fewer qualify). A local maximum is an entry larger than its left neighbour and not
   !! smaller than its right one (the last entry needs only the first condition), so a
   !! flat stretch yields at most one peak. Entries at frequency <= 0 are never peaks: the
   !! zero-frequency bin holds only the leakage of the removed mean. Empty when `frequency`
   !! and `amplitude` differ in size or count < 1.
   pure function spectral_peaks(frequency, amplitude, count, min_relative) result(peaks)
      real(dp), intent(in) :: frequency(:)   !! bin frequencies (Hz), ascending
      real(dp), intent(in) :: amplitude(:)   !! amplitude at each frequency
      integer, intent(in) :: count           !! largest number of peaks wanted
      real(dp), intent(in) :: min_relative   !! threshold relative to the largest amplitude, in [0, 1)
      integer, allocatable :: peaks(:)       !! indices, by decreasing amplitude
      logical :: candidate(size(amplitude))
      real(dp) :: threshold
      integer :: n, i, found
      allocate (peaks(0))
      n = size(amplitude)
      if (size(frequency) /= n .or. count < 1 .or. n < 2) return
      threshold = min_relative*maxval(amplitude)
      candidate = .false.
      do i = 2, n
         if (frequency(i) <= 0) cycle
         if (amplitude(i) <= amplitude(i - 1) .or. amplitude(i) <= threshold) cycle
         if (i < n) then
            if (amplitude(i) < amplitude(i + 1)) cycle
         end if
         candidate(i) = .true.
      end do
      ! the dummy `count` hides the intrinsic of that name
      found = 0
      do i = 1, n
         if (candidate(i)) found = found + 1
      end do
      found = min(count, found)
      deallocate (peaks)
      allocate (peaks(found))
      ! selection of the largest remaining candidate: count is small (a few modes)
      do i = 1, found
         peaks(i) = maxloc(amplitude, dim=1, mask=candidate)
         candidate(peaks(i)) = .false.
      end do
   end function spectral_peaks

   !> The size(peak_frequency) largest local maxima of a spectrum (`spectral_peaks`), each
   !! refined by a parabola through the amplitudes of its bin and its two neighbours
   !! (`bin_width` apart; not at the last bin, nor where the parabola does not open
   !! downwards); 0 where there are fewer peaks.
   pure subroutine interpolated_peaks(frequency, amplitude, bin_width, peak_frequency, peak_amplitude)
      real(dp), intent(in) :: frequency(:), amplitude(:), bin_width
      real(dp), intent(out) :: peak_frequency(:), peak_amplitude(:)
      integer :: j, i
      real(dp) :: left, middle, right, curvature, shift
      peak_frequency = 0
      peak_amplitude = 0
      associate (found => spectral_peaks(frequency, amplitude, size(peak_frequency), 0.0_dp))
         do j = 1, size(found)
            i = found(j)
            peak_frequency(j) = frequency(i)
            peak_amplitude(j) = amplitude(i)
            if (i >= size(amplitude)) cycle
            left = amplitude(i - 1)
            middle = amplitude(i)
            right = amplitude(i + 1)
            curvature = left - 2*middle + right
            if (curvature >= 0) cycle
            shift = 0.5_dp*(left - right)/curvature
            peak_frequency(j) = frequency(i) + shift*bin_width
            peak_amplitude(j) = middle - 0.25_dp*(left - right)*shift
         end do
      end associate
   end subroutine interpolated_peaks
end module vibrobeam_spectrum
