!> The dense helpers the tests use for componentwise round-off bounds (first order in
!! u = eps/2; Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002):
!! dense inverses and the backward error of Gaussian elimination. Dense: for the test
!! meshes only. (The static solver derives its own bounds, `static_report`.)
module vibrobeam_static_bounds
   use vibrobeam_kinds, only: dp
   use vibrobeam_lapack, only: dgesv
   implicit none
   private
   public :: dense_inverse, permuted_lu_times

contains

   !> P^T |L| |U| x for the factors of LAPACK dgetrf (PA = LU, unit lower L below the
   !! diagonal): the componentwise backward error of Gaussian elimination (Higham, Thm 9.3).
   pure function permuted_lu_times(factors, pivots, x) result(y)
      real(dp), intent(in) :: factors(:, :), x(:)
      integer, intent(in) :: pivots(:)
      real(dp) :: y(size(x)), z(size(x)), swap
      integer :: i, n
      n = size(x)
      do i = 1, n
         z(i) = sum(abs(factors(i, i:n))*x(i:n))
      end do
      do i = 1, n
         y(i) = z(i) + sum(abs(factors(i, 1:i - 1))*z(1:i - 1))
      end do
      do i = n, 1, -1   ! P = P_n ... P_1, so P^T applies the interchanges in reverse
         swap = y(i)
         y(i) = y(pivots(i))
         y(pivots(i)) = swap
      end do
   end function permuted_lu_times

   !> A^-1 of a small dense matrix (LAPACK dgesv on the identity).
   function dense_inverse(a) result(inverse)
      real(dp), intent(in) :: a(:, :)
      real(dp) :: inverse(size(a, 1), size(a, 1))
      real(dp), allocatable :: work(:, :)
      integer :: pivots(size(a, 1)), info, i
      allocate (work, source=a)
      inverse = 0
      do i = 1, size(a, 1)
         inverse(i, i) = 1
      end do
      call dgesv(size(a, 1), size(a, 1), work, size(a, 1), pivots, inverse, size(a, 1), info)
   end function dense_inverse
end module vibrobeam_static_bounds
