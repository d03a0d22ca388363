!> The random signals (src/model/vibrobeam_random_signal.f90) against their definition:
!! - the applied density 2 tau |G(f)|^2 (G the filter's response, on the grid of its 2L-point
!!   transform) equals the target S inside the band, 8 filter bins (1/(L tau)) or more from
!!   its edges: the Hann window's kernel, which smooths the edges, falls like 1/d^3, and its
!!   leakage there is below 1e-4 of the level (measured 4e-5); the variance sum h^2 equals
!!   the integral of S to the edges' smoothing, within 2 of the band's 2L tau (b_to - b_from)
!!   filter bins (measured 0.2 % for 195 bins);
!! - a record's measured density (Welch: periodic Hann segments of 2L samples overlapping
!!   by half, K segments, computed here with FFTW) against the applied density: the band's
!!   mean ratio within 5 standard errors sqrt(2.2/(K M)) (M bins, each of variance 1.1/K
!!   with Hann's overlap, neighbours correlated: the factor 2), and 95 % intervals
!!   1 +- 1.96 sqrt(1.1/K) that cover at least 95 % - 5 binomial errors of the bins;
!! - the sample variance against sum h^2 within 5 standard errors 1/sqrt(W T) (band W,
!!   record T: 2 W T independent values);
!! - the coherence of two channels x = 0 and 0.3 m apart with l = 0.2 m, against
!!   exp(-0.3/0.2): the band's mean coherence Re C_13/sqrt(P_11 P_33) within 5 (1 - g^2)
!!   sqrt(2.2/(2 K M)); and the equal-time correlation within 5 (1 - g^2)/sqrt(2 W T);
!! - the same bits whatever the order of evaluation: a record computed sequentially, one
!!   computed from a restart in the middle of a block, and one on two threads at once;
!!   between samples the value is the linear interpolation (exactly, to its rounding).
program test_random_signal
   use, intrinsic :: iso_c_binding
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_random, only: random_key
   use vibrobeam_random_signal, only: spectrum_shape, random_signal
   use vibrobeam_test_support, only: test_counter, same_bits
   use vibrobeam_test_fftw
   implicit none
   type(test_counter) :: t
   type(spectrum_shape) :: shape
   type(random_signal) :: signal, copy, field, threads(2)
   real(dp), parameter :: tau = 1e-3_dp, f_from = 5, f_to = 100, level = 2.0_dp, ell = 0.2_dp
   integer, parameter :: segments = 200
   integer :: stat, l, n, j, k, m, inside
   character(len=200) :: errmsg
   real(dp), allocatable :: record(:), again(:), parallel(:, :), q(:, :), applied(:), p11(:), p33(:), c13(:), &
                            window(:), measured(:)
   real(dp) :: f, ratio_mean, width, v(1), v2(1), a, g, coherence, correlation, values3(3)

   shape%level = level
   shape%band_from = f_from
   shape%band_to = f_to
   call signal%design(shape, tau, random_key(3, 0_int64), stat, errmsg)
   call t%check_true('design', stat == 0, errmsg)
   l = signal%taps
   width = 1/(l*tau)
   ! the applied density on the 2L grid, f_j = j/(2 L tau)
   allocate (applied(0:l))
   do j = 0, l
      applied(j) = 2*tau*abs(signal%response(j + 1))**2
      f = j/(2*l*tau)
      if (f > f_from + 8*width .and. f < f_to - 8*width) &
         call t%check_close('applied density in the band', applied(j), level, 1e-4_dp)
      if (f < f_from - 8*width .or. f > f_to + 8*width) &
         call t%check_close('applied density outside the band', applied(j), 0.0_dp, 1e-4_dp, scale=level)
   end do
   call t%check_close('variance sum h^2 against the integral of S', signal%rms**2, shape%variance(), &
                      2/((f_to - f_from)/width))

   ! a record of K segments of 2L samples overlapping by half, sequentially
   n = (segments + 1)*l
   allocate (record(n), again(n))
   do k = 1, n
      call signal%values((k - 1)*tau, v)
      record(k) = v(1)
   end do
   ! from a restart in the middle of a block: a fresh signal, first asked at sample n/2 + 17
   copy = signal
   copy%block_index = -huge(1_int64)
   m = n/2 + 17
   do k = m, n
      call copy%values((k - 1)*tau, v)
      again(k) = v(1)
   end do
   call t%check_true('the same bits after a restart inside a block', all(same_bits(again(m:), record(m:))))
   ! between samples: linear
   ! (the weight as the signal computes it from t: (1000 + 0.3) tau / tau - 1000)
   a = (1000 + 0.3_dp)*tau/tau - 1000
   call signal%values((1000 + 0.3_dp)*tau, v2)
   call t%check_close('value between samples', v2(1), (1 - a)*record(1001) + a*record(1002), &
                      4*epsilon(1.0_dp), scale=maxval(abs(record(1001:1002))))
   ! two threads at once, each its own copy
   allocate (parallel(n, 2))
   threads = signal
   threads(1)%block_index = -huge(1_int64)
   threads(2)%block_index = -huge(1_int64)
   !$omp parallel do num_threads(2) private(k, v)
   do j = 1, 2
      do k = 1, n
         call threads(j)%values((k - 1)*tau, v)
         parallel(k, j) = v(1)
      end do
   end do
   !$omp end parallel do
   call t%check_true('the same bits on two threads', all(same_bits(parallel(:, 1), record)) .and. &
                     all(same_bits(parallel(:, 2), record)))

   ! the measured density against the applied one
   allocate (window(2*l))
   window = [(0.5_dp*(1 - cos(2*acos(-1.0_dp)*(k - 1)/(2*l))), k=1, 2*l)]
   call welch(record, record, p11, c13)
   measured = p11
   ratio_mean = 0
   inside = 0
   m = 0
   do j = 1, l - 1
      f = j/(2*l*tau)
      if (f < f_from + 8*width .or. f > f_to - 8*width) cycle
      m = m + 1
      ratio_mean = ratio_mean + measured(j)/applied(j)
      if (abs(measured(j)/applied(j) - 1) <= 1.96_dp*sqrt(1.1_dp/segments)) inside = inside + 1
   end do
   ratio_mean = ratio_mean/m
   call t%check_close('measured density / applied, band mean', ratio_mean, 1.0_dp, 5*sqrt(2.2_dp/(segments*m)))
   call t%check_true('95 % intervals of the measured density cover the applied one', &
                     inside >= nint(m*(0.95_dp - 5*sqrt(0.05_dp*0.95_dp/(m/2.0_dp)))), &
                     'covered in '//trim(number(real(inside, dp)))//' of '//trim(number(real(m, dp)))//' bins')
   call t%check_close('sample variance', sum(record**2)/n, signal%rms**2, 5/sqrt((f_to - f_from)*n*tau))

   ! coherence of a field: channels at 0, 0.1, 0.3 m
   call field%design(shape, tau, random_key(3, 0_int64), stat, errmsg, [0.0_dp, 0.1_dp, 0.3_dp], ell)
   allocate (q(n, 3))
   do k = 1, n
      call field%values((k - 1)*tau, values3)
      q(k, :) = values3
   end do
   call t%check_true('channel 1 of a field is the signal of stream 0', all(same_bits(q(:, 1), record)))
   g = exp(-0.3_dp/ell)
   call welch(q(:, 1), q(:, 1), p11, c13)
   call welch(q(:, 3), q(:, 3), p33, c13)
   call welch(q(:, 1), q(:, 3), measured, c13)
   coherence = 0
   m = 0
   do j = 1, l - 1
      f = j/(2*l*tau)
      if (f < f_from + 8*width .or. f > f_to - 8*width) cycle
      m = m + 1
      coherence = coherence + c13(j)/sqrt(p11(j)*p33(j))
   end do
   coherence = coherence/m
   call t%check_close('coherence at 0.3 m, band mean', coherence, g, 5*(1 - g**2)*sqrt(2.2_dp/(2*segments*m))/g)
   correlation = sum(q(:, 1)*q(:, 3))/sqrt(sum(q(:, 1)**2)*sum(q(:, 3)**2))
   call t%check_close('correlation at 0.3 m', correlation, g, 5*(1 - g**2)/sqrt(2*(f_to - f_from)*n*tau)/g)
   call t%check_close('variance of channel 3', sum(q(:, 3)**2)/n, signal%rms**2, 5/sqrt((f_to - f_from)*n*tau))
   call t%finish('test_random_signal')

contains

   !> Welch's one-sided densities of x and y: real part of the cross density (`cross`)
   !! and, in `power`, the same for x = y; bins j = 0..L of segments of 2L samples.
   subroutine welch(x, y, power, cross)
      real(dp), intent(in) :: x(:), y(:)
      real(dp), allocatable, intent(out) :: power(:), cross(:)
      real(c_double), pointer :: segment(:)
      complex(c_double_complex), pointer :: spectrum(:)
      complex(dp), allocatable :: sx(:)
      type(c_ptr) :: plan, memory_in, memory_out
      integer :: s, start
      memory_in = fftw_alloc_real(int(2*l, c_size_t))
      memory_out = fftw_alloc_complex(int(l + 1, c_size_t))
      call c_f_pointer(memory_in, segment, [2*l])
      call c_f_pointer(memory_out, spectrum, [l + 1])
      plan = fftw_plan_dft_r2c_1d(int(2*l, c_int), segment, spectrum, FFTW_ESTIMATE)
      allocate (power(0:l), cross(0:l), source=0.0_dp)
      do s = 1, segments
         start = (s - 1)*l
         segment = window*x(start + 1:start + 2*l)
         call fftw_execute_dft_r2c(plan, segment, spectrum)
         sx = spectrum
         segment = window*y(start + 1:start + 2*l)
         call fftw_execute_dft_r2c(plan, segment, spectrum)
         ! one-sided: 2 tau |X|^2 / sum w^2 (the interior bins)
         cross = cross + 2*tau*real(sx*conjg(spectrum), dp)/sum(window**2)
      end do
      cross = cross/segments
      power = cross
      call fftw_destroy_plan(plan)
      call fftw_free(memory_in)
      call fftw_free(memory_out)
   end subroutine welch


   function number(x) result(text)
      real(dp), intent(in) :: x
      character(len=24) :: text
      write (text, '(g0)') nint(x)
   end function number
end program test_random_signal
