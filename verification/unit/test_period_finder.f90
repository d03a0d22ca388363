!> Unit test of the period of a Poincare sequence (`vibrobeam_poincare_period`;
!! docs/statistics.md, "Period, Lyapunov exponent and the 0-1 test"), on made-up sequences
!! of two components whose periods are known:
!! 1. exact periods 1, 2, 3 and 14 (values drawn once, distinct) with P whole: found, with
!!    a mismatch of 0;
!! 2. period 2 plus a deterministic wobble of 1e-9 of the amplitude: none with P whole (the
!!    round-off tolerance 8 eps P s is 3e-12 s for P = 1571), period 2 with P not whole (the
!!    slip tolerance: the largest change in one of the 1000 steps between two samples, about
!!    1e-3 here, exceeds the wobble); a wobble of 0.1 exceeds it: none;
!! 3. the logistic map (chaotic): none, however many samples;
!! 4. fewer than 3 samples: not determined (-1); period 7 in 20 samples (< 3 x 7): none
!!    (the longest period 20 samples can show is 6);
!! 5. the state saved half-way and restored gives the same period and mismatch.
program test_period_finder
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_poincare_period, only: period_finder, max_period
   use vibrobeam_state_record, only: state_record
   use vibrobeam_test_support, only: test_counter, same_bits
   implicit none
   type(test_counter) :: t
   type(period_finder) :: finder, second
   type(state_record) :: record
   real(dp), parameter :: whole = 1571, not_whole = 1570.8_dp
   integer, parameter :: exact_periods(4) = [1, 2, 3, 14]
   real(dp) :: values(2, max_period), mismatch, mismatch2, x
   integer :: period, period2, p, j, k, stat
   character(len=256) :: errmsg

   ! distinct values for a cycle of up to max_period samples
   do j = 1, max_period
      values(:, j) = [sin(1.7_dp*j) + 2, cos(2.3_dp*j) - 0.5_dp]
   end do

   ! 1. exact periods, P whole
   do k = 1, 4
      p = exact_periods(k)
      call feed(p, 256, 0.0_dp)
      call finder%find(whole, period, mismatch)
      call t%check_true('an exact period: found', period == p)
      call t%check_true('exact period: mismatch 0', abs(mismatch) <= 0)
   end do

   ! 2. period 2 with a wobble of 1e-9
   call feed(2, 256, 1e-9_dp)
   call finder%find(whole, period, mismatch)
   call t%check_true('period 2 + wobble 1e-9, P whole: none (round-off tolerance)', period == 0)
   call t%check_true('its mismatch is that of the wobble: > 1', mismatch > 1)
   call finder%find(not_whole, period, mismatch)
   call t%check_true('period 2 + wobble 1e-9, P not whole: period 2 (slip tolerance)', period == 2)
   call feed(2, 256, 0.1_dp)
   call finder%find(not_whole, period, mismatch)
   call t%check_true('period 2 + wobble 0.1, P not whole: none', period == 0)

   ! 3. the logistic map
   call finder%init(2)
   x = 0.3_dp
   do j = 1, 1000
      call finder%observe_step([x, 1 - x])
      x = 4*x*(1 - x)
      call finder%add_sample([x, 1 - x])
   end do
   call finder%find(whole, period, mismatch)
   call t%check_true('logistic map: no period', period == 0)

   ! 4. short sequences
   call feed(1, 2, 0.0_dp)
   call finder%find(whole, period, mismatch)
   call t%check_true('2 samples: not determined', period == -1)
   call feed(7, 20, 0.0_dp)
   call finder%find(whole, period, mismatch)
   call t%check_true('period 7 in 20 samples: none', period == 0)
   call feed(7, 21, 0.0_dp)
   call finder%find(whole, period, mismatch)
   call t%check_true('period 7 in 21 samples: 7', period == 7)

   ! 5. saved and restored half-way
   call finder%init(2)
   call second%init(2)
   do j = 1, 300
      x = 1e-9_dp*sin(0.37_dp*j)
      call finder%observe_step(values(:, mod(j, 3) + 1) + x)
      call finder%add_sample(values(:, mod(j, 3) + 1) + x)
      if (j == 150) then
         call finder%save_state(record, 'period')
         call second%restore_state(record, 'period', stat, errmsg)
         call t%check_true('restore the saved state', stat == 0, errmsg)
      else if (j > 150) then
         call second%observe_step(values(:, mod(j, 3) + 1) + x)
         call second%add_sample(values(:, mod(j, 3) + 1) + x)
      end if
   end do
   call finder%find(whole, period, mismatch)
   call second%find(whole, period2, mismatch2)
   call t%check_true('restored half-way: the same period and mismatch', period == period2 .and. &
                     same_bits(mismatch, mismatch2))
   call t%finish('test_period_finder')

contains

   !> A fresh finder fed `count` samples of period p (the cycle values(:, 1:p)) plus a
   !! wobble of `wobble` times the amplitude, each reached from the one before in 1000
   !! steps along the straight line (a change of about 1e-3 per step).
   subroutine feed(p, count, wobble)
      integer, intent(in) :: p, count
      real(dp), intent(in) :: wobble
      real(dp) :: sample(2), last(2)
      integer :: i, n
      call finder%init(2)
      last = values(:, 1)
      call finder%start(last)
      do i = 1, count
         sample = values(:, mod(i - 1, p) + 1)*(1 + wobble*sin(0.61_dp*i*pi))
         do n = 1, 1000
            call finder%observe_step(last + (sample - last)*(n/1000.0_dp))
         end do
         call finder%add_sample(sample)
         last = sample
      end do
   end subroutine feed
end program test_period_finder
