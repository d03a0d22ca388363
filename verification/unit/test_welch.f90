!> Unit test of the streaming Welch spectrum (`vibrobeam_welch`):
!! 1. a record of n <= 2^16 samples gives exactly (bit for bit) the single-record spectrum
!!    of `amplitude_spectrum` (what /spectrum held before streaming);
!! 2. a longer record gives sqrt(mean of squared segment amplitudes) over segments of 2^16
!!    samples starting every 2^15 samples, each computed here by `amplitude_spectrum` on
!!    the slice (relative 1e-12: a sum of at most 5 squares, then a square root);
!! 3. a sine of amplitude A on a bin of the segment reads A at that bin in the long
!!    record (Hann: exact on a bin, 1e-9 for the leakage of the other segments' means);
!! 4. the estimator saved into a state record half-way and restored into a fresh one
!!    ends with the same spectrum bit for bit (a continued run's spectrum).
program test_welch
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_spectrum, only: amplitude_spectrum
   use vibrobeam_welch, only: welch_estimator, welch_segment
   use vibrobeam_state_record, only: state_record
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: dt = 1e-3_dp
   real(dp), allocatable :: signal(:), frequency(:), amplitude(:), reference(:), power(:), f_ref(:)
   type(welch_estimator) :: welch, second
   type(state_record) :: record
   integer(int64) :: segments
   real(dp) :: width
   integer :: n, j, k, stat, start, count
   character(len=256) :: errmsg

   ! 1. short record: identical to the single-record spectrum
   n = 5000
   signal = [(sin(2*pi*7.3_dp*j*dt) + 0.3_dp*cos(2*pi*41.0_dp*j*dt) + 0.01_dp*j*dt, j=0, n - 1)]
   call welch%init(dt, int(n, int64))
   do j = 1, n
      call welch%add(signal(j), stat, errmsg)
   end do
   call welch%spectrum(frequency, amplitude, segments, width, stat, errmsg)
   call amplitude_spectrum(signal, dt, f_ref, reference, stat, errmsg, window='hann')
   call t%check_true('short record: no segments', segments == 0)
   call t%check_true('short record: same bins', size(amplitude) == size(reference))
   if (size(amplitude) == size(reference)) then
      call t%check_true('short record: frequencies bit for bit', all(same_bits(frequency, f_ref)))
      call t%check_true('short record: amplitudes bit for bit', all(same_bits(amplitude, reference)))
   end if
   call t%check_close('short record: bin width 1/(n dt)', width, 1/(n*dt), 1e-15_dp)

   ! 2. long record: Welch average of independently computed segments
   n = 3*welch_segment + 1234
   deallocate (signal)
   signal = [(sin(2*pi*7.3_dp*j*dt) + 0.3_dp*cos(2*pi*41.0_dp*j*dt) + 1e-6_dp*j, j=0, n - 1)]
   call welch%init(dt, int(n, int64))
   do j = 1, n
      call welch%add(signal(j), stat, errmsg)
      if (j == n/2) then   ! 4. save half-way, restore into a fresh estimator
         call welch%save_state(record)
         call second%init(dt, int(n, int64))
         call second%restore_state(record, stat, errmsg)
         call t%check_true('restore the saved state', stat == 0, errmsg)
      else if (j > n/2) then
         call second%add(signal(j), stat, errmsg)
      end if
   end do
   call welch%spectrum(frequency, amplitude, segments, width, stat, errmsg)
   allocate (power(welch_segment/2 + 1), source=0.0_dp)
   count = 0
   do start = 1, n - welch_segment + 1, welch_segment/2
      call amplitude_spectrum(signal(start:start + welch_segment - 1), dt, f_ref, reference, stat, errmsg, &
                              window='hann')
      power = power + reference**2
      count = count + 1
   end do
   call t%check_true('long record: segments of 2^16 every 2^15 samples', segments == count)
   call t%check_close('long record: largest relative difference from the segment average', &
                      maxval(abs(amplitude - sqrt(power/count))/max(sqrt(power/count), tiny(1.0_dp))), &
                      0.0_dp, 1.0_dp, 1e-12_dp)
   call t%check_close('long record: bin width 1/(2^16 dt)', width, 1/(welch_segment*dt), 1e-15_dp)
   deallocate (frequency, amplitude)
   call second%spectrum(frequency, reference, segments, width, stat, errmsg)
   call welch%init(dt, int(n, int64))
   do j = 1, n
      call welch%add(signal(j), stat, errmsg)
   end do
   call welch%spectrum(f_ref, amplitude, segments, width, stat, errmsg)
   call t%check_true('saved and restored half-way: the same spectrum bit for bit', &
                     size(amplitude) == size(reference))
   if (size(amplitude) == size(reference)) call t%check_true('... every bin', all(same_bits(amplitude, reference)))

   ! 3. a sine on bin k of the segment reads its amplitude
   k = 1000
   deallocate (signal)
   signal = [(0.25_dp*sin(2*pi*k*j/real(welch_segment, dp)), j=0, n - 1)]
   call welch%init(dt, int(n, int64))
   do j = 1, n
      call welch%add(signal(j), stat, errmsg)
   end do
   call welch%spectrum(frequency, amplitude, segments, width, stat, errmsg)
   call t%check_close('on-bin sine of amplitude 0.25 m', amplitude(k + 1), 0.25_dp, 1e-9_dp)
   call t%finish('test_welch')
contains
   !> Equal bit patterns.
   elemental logical function same_bits(a, b)
      real(dp), intent(in) :: a, b
      same_bits = transfer(a, 1_int64) == transfer(b, 1_int64)
   end function same_bits
end program test_welch
