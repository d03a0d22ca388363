!> Order statistics of short lists of reals: the sorted copy of a list (a sweep's
!! parameter values) and its median (the benchmarks' repeated timings).
module vibrobeam_sorting
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: sorted, median

contains

   !> `values` in increasing order (insertion sort: the lists here are short).
   pure function sorted(values) result(out)
      real(dp), intent(in) :: values(:)
      real(dp) :: out(size(values)), key
      integer :: i, j
      out = values
      do i = 2, size(out)
         key = out(i)
         j = i - 1
         do while (j >= 1)
            if (out(j) <= key) exit
            out(j + 1) = out(j)
            j = j - 1
         end do
         out(j + 1) = key
      end do
   end function sorted

   !> The median of `values` (the mean of the two middle values for an even count).
   pure real(dp) function median(values)
      real(dp), intent(in) :: values(:)
      real(dp) :: ordered(size(values))
      integer :: n
      n = size(values)
      ordered = sorted(values)
      median = ordered((n + 1)/2)
      if (mod(n, 2) == 0) median = 0.5_dp*(ordered(n/2) + ordered(n/2 + 1))
   end function median
end module vibrobeam_sorting
