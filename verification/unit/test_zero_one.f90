!> Unit test of the streamed 0-1 test for chaos (`vibrobeam_zero_one`; docs/statistics.md,
!! "Period, Lyapunov exponent and the 0-1 test"), on sequences that are not vibrobeam's:
!! 1. the logistic map x -> 4 x (1 - x) (chaotic, Lyapunov exponent ln 2): K > 0.9;
!! 2. a periodic sequence (period 7, values drawn once): K < 0.1; a quasi-periodic one
!!    (a circle rotation by the golden mean): K < 0.1; a constant one: K < 0.1;
!! 3. the streamed sums against the definition computed here directly from the whole
!!    sequence (p_c(n), q_c(n) summed anew for every lag, O(N n_cut) per frequency): the
!!    same K to round-off (each M_c(n) is a mean of N sums of at most max_lag products,
!!    evaluated in another order: a relative 1e-9 of K's terms bounds it with a margin of
!!    1e4 over max_lag eps);
!! 4. a sequence too short (N < min_samples): K = 0 with no lags;
!! 5. the state saved half-way and restored into a fresh test gives K bit for bit.
program test_zero_one
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_zero_one, only: zero_one_test, frequencies, max_lag, min_samples
   use vibrobeam_sorting, only: median
   use vibrobeam_state_record, only: state_record
   use vibrobeam_test_support, only: test_counter, same_bits
   implicit none
   type(test_counter) :: t
   type(zero_one_test) :: test, second
   type(state_record) :: record
   real(dp), allocatable :: sequence(:)
   real(dp) :: k, k_direct, x
   integer :: lags, n, j, stat
   character(len=256) :: errmsg

   ! 1. the logistic map at r = 4
   n = 2000
   allocate (sequence(n))
   x = 0.3_dp
   do j = 1, n
      x = 4*x*(1 - x)
      sequence(j) = x
   end do
   call run(sequence, k, lags)
   write (*, '(a,f8.5,a,i0,a)') 'logistic map (r = 4): K = ', k, ' (', lags, ' lags)'
   call t%check_true('logistic map r = 4: K > 0.9 (chaotic)', k > 0.9_dp)
   call t%check_true('n_cut = min(max_lag, N/10)', lags == min(max_lag, n/10))
   ! 3. against the definition
   k_direct = direct(sequence)
   write (*, '(a,es10.3)') 'streamed K - direct K: ', k - k_direct
   call t%check_close('logistic map: streamed K against the direct definition', k, k_direct, 1e-9_dp, scale=1.0_dp)

   ! 2. regular sequences
   sequence = [(cos(2*pi*j/7.0_dp) + 0.4_dp*sin(4*pi*j/7.0_dp + 1), j=1, n)]
   call run(sequence, k, lags)
   write (*, '(a,f8.5)') 'period 7: K = ', k
   call t%check_true('periodic sequence (period 7): K < 0.1', abs(k) < 0.1_dp)
   call t%check_close('period 7: streamed K against the direct definition', k, direct(sequence), 1e-9_dp, scale=1.0_dp)
   sequence = [(sin(2*pi*j*0.5_dp*(sqrt(5.0_dp) - 1)), j=1, n)]
   call run(sequence, k, lags)
   write (*, '(a,f8.5)') 'quasi-periodic (golden rotation): K = ', k
   call t%check_true('quasi-periodic sequence: K < 0.1', abs(k) < 0.1_dp)
   sequence = 0.37_dp
   call run(sequence, k, lags)
   call t%check_true('constant sequence: K < 0.1', abs(k) < 0.1_dp)

   ! 4. too short
   call run(sequence(1:min_samples - 1), k, lags)
   call t%check_true('fewer than min_samples: K = 0, no lags', abs(k) <= 0 .and. lags == 0)

   ! 5. saved and restored half-way
   x = 0.3_dp
   do j = 1, n
      x = 4*x*(1 - x)
      sequence(j) = x
   end do
   call test%init()
   call second%init()
   do j = 1, n
      call test%add(sequence(j))
      if (j == n/2) then
         call test%save_state(record, 'zero_one')
         call second%restore_state(record, 'zero_one', stat, errmsg)
         call t%check_true('restore the saved state', stat == 0, errmsg)
      else if (j > n/2) then
         call second%add(sequence(j))
      end if
   end do
   call test%result(k, lags)
   call second%result(k_direct, lags)
   call t%check_true('restored half-way: the same K bit for bit', same_bits(k, k_direct))
   call t%finish('test_zero_one')

contains

   subroutine run(values, k, lags)
      real(dp), intent(in) :: values(:)
      real(dp), intent(out) :: k
      integer, intent(out) :: lags
      integer :: i
      call test%init()
      do i = 1, size(values)
         call test%add(values(i))
      end do
      call test%result(k, lags)
   end subroutine run

   !> K by the definition (module documentation of vibrobeam_zero_one) from the whole
   !! sequence, with the frequencies the streamed test drew.
   real(dp) function direct(values)
      real(dp), intent(in) :: values(:)
      real(dp) :: phi(size(values)), p(0:size(values)), q(0:size(values)), d(max_lag), correlation(frequencies), mean
      integer :: c, lag, i, nn, cut
      nn = size(values)
      cut = min(max_lag, nn/10)
      phi = values - values(1)
      mean = sum(phi)/nn
      call test%init()
      do c = 1, frequencies
         p(0) = 0
         q(0) = 0
         do i = 1, nn
            p(i) = p(i - 1) + phi(i)*cos(i*test%c(c))
            q(i) = q(i - 1) + phi(i)*sin(i*test%c(c))
         end do
         do lag = 1, cut
            d(lag) = sum((p(lag:nn) - p(0:nn - lag))**2 + (q(lag:nn) - q(0:nn - lag))**2)/(nn - lag + 1) - &
                     mean**2*(1 - cos(lag*test%c(c)))/(1 - cos(test%c(c)))
         end do
         correlation(c) = pearson(d(1:cut))
      end do
      direct = median(correlation)
   end function direct

   !> The correlation coefficient of (1, 2, ..., n) and y.
   pure real(dp) function pearson(y)
      real(dp), intent(in) :: y(:)
      real(dp) :: xs(size(y)), ym
      integer :: i
      xs = [(real(i, dp), i=1, size(y))]
      xs = xs - sum(xs)/size(y)
      ym = sum(y)/size(y)
      if (sum((y - ym)**2) > 0) then
         pearson = sum(xs*(y - ym))/sqrt(sum(xs**2)*sum((y - ym)**2))
      else
         pearson = 0
      end if
   end function pearson
end program test_zero_one
