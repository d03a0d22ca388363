!> Band kernels specialised to 3 sub-diagonals, the bandwidth of M, K and W for both bases
!! (Hermite cubics and cubic B-splines, theory §2): the square-root-free Cholesky
!! factorization A = L D L^T, the solve with it, and the product y = A x.
!!
!! Why: each time step makes one solve with the factor of W and one product with K
!! (theory §3). LAPACK's dpbtrs and BLAS's dsbmv serve any bandwidth through loops of
!! length kd and a call per column; at kd = 3 that bookkeeping costs as much as the
!! arithmetic. Here each kernel is one loop over the rows with the band held in scalars,
!! and the solve does no division: the reciprocal pivots 1/d_j are stored at
!! factorization. LAPACK (dpbtrf, dpbtrs, dsbmv) stays the fall-back for other bandwidths
!! and the oracle of the tests (`test_band_kernel`); docs/method.md, "The band kernel",
!! gives the measured gain and the round-off bounds.
!!
!! Storage. The matrix comes in LAPACK lower band storage, A(i,j) = ab(1+i-j, j) for
!! j <= i <= j+3, ab(4, n). The factor overwrites it: ab(1, j) = 1/d_j and
!! ab(1+k, j) = L(j+k, j), k = 1..3 (L has a unit diagonal). Entries that would fall
!! below row n (the "not referenced" corner of the last 3 columns) are set to zero.
!! All arrays are explicit-shape: no temporary and no heap allocation inside a kernel.
module vibrobeam_band_kernel
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: kernel_bandwidth, ldl_factor_kd3, ldl_solve_kd3, band_matvec_kd3, ldl_residual_solve_kd3

   integer, parameter :: kernel_bandwidth = 3   !! the kd these kernels are written for

contains

   !> A = L D L^T in place (Cholesky without square roots, column by column). stat = 0 on
   !! success; stat = j if the pivot d_j is not positive (or not a number), i.e. the leading
   !! minor of order j is not positive definite, as LAPACK dpbtrf's info (its Cholesky
   !! pivot is sqrt(d_j)). The columns before j are then factored, the others untouched.
   pure subroutine ldl_factor_kd3(n, ab, stat)
      integer, intent(in) :: n
      real(dp), intent(inout) :: ab(4, n)
      integer, intent(out) :: stat
      ! Column j needs, from the three columns before it, the multipliers l of L and the
      ! products w = l d of the same entries: "1" is column j-1 (rows j, j+1, j+2), "2"
      ! column j-2 (rows j, j+1), "3" column j-3 (row j). Zero before column 1.
      real(dp) :: l1j, l1j1, l1j2, l2j, l2j1, l3j, w1j, w1j1, w1j2, w2j, w2j1, w3j
      real(dp) :: pivot, reciprocal, below1, below2, below3
      integer :: j
      stat = 0
      if (n >= 1) ab(2:4, n) = 0
      if (n >= 2) ab(3:4, n - 1) = 0
      if (n >= 3) ab(4, n - 2) = 0
      l1j = 0; l1j1 = 0; l1j2 = 0; l2j = 0; l2j1 = 0; l3j = 0
      w1j = 0; w1j1 = 0; w1j2 = 0; w2j = 0; w2j1 = 0; w3j = 0
      do j = 1, n
         ! d_j = a_jj - sum_k L(j,k) d_k L(j,k);  L(j+i,j) d_j = a_(j+i)j - sum_k L(j+i,k) d_k L(j,k)
         pivot = ab(1, j) - w3j*l3j - w2j*l2j - w1j*l1j
         if (.not. pivot > 0) then
            stat = j
            return
         end if
         reciprocal = 1/pivot
         below1 = ab(2, j) - w2j1*l2j - w1j1*l1j
         below2 = ab(3, j) - w1j2*l1j
         below3 = ab(4, j)
         ab(1, j) = reciprocal
         ab(2, j) = below1*reciprocal
         ab(3, j) = below2*reciprocal
         ab(4, j) = below3*reciprocal
         ! shift: column j becomes "1", j-1 becomes "2", j-2 becomes "3"
         l3j = l2j1; w3j = w2j1
         l2j = l1j1; w2j = w1j1; l2j1 = l1j2; w2j1 = w1j2
         l1j = ab(2, j); w1j = below1; l1j1 = ab(3, j); w1j1 = below2; l1j2 = ab(4, j); w1j2 = below3
      end do
   end subroutine ldl_factor_kd3

   !> Overwrite x with A^{-1} x, given the factor of `ldl_factor_kd3`: L z = x forward,
   !! then x = D^{-1} z - L^T x backward, the scaling by the stored 1/d_j fused into the
   !! backward loop. Each loop carries three running values in scalars; the one that
   !! depends on the previous row is subtracted last, so the chain from row to row is one
   !! multiplication and one subtraction.
   pure subroutine ldl_solve_kd3(n, ab, x)
      integer, intent(in) :: n
      real(dp), intent(in) :: ab(4, n)
      real(dp), intent(inout) :: x(n)
      real(dp) :: pending1, pending2, pending3, z
      integer :: j
      if (n < 1) return
      ! forward: pendingk = x(j+k-1) minus the columns of L already done
      pending1 = x(1)
      pending2 = 0
      pending3 = 0
      if (n >= 2) pending2 = x(2)
      if (n >= 3) pending3 = x(3)
      do j = 1, n - 3
         z = pending1
         x(j) = z
         pending1 = pending2 - ab(2, j)*z
         pending2 = pending3 - ab(3, j)*z
         pending3 = x(j + 3) - ab(4, j)*z
      end do
      call substitute_forward_last(n, ab, pending1, pending2, pending3, x)
      call substitute_backward(n, ab, x)
   end subroutine ldl_solve_kd3

   !> The last rows of the forward substitution (no row j+3 below them), from the running
   !! values pending1..3 of row n-2 on (fewer rows when n < 3).
   pure subroutine substitute_forward_last(n, ab, pending1, pending2, pending3, x)
      integer, intent(in) :: n
      real(dp), intent(in) :: ab(4, n)
      real(dp), intent(inout) :: pending1, pending2, pending3
      real(dp), intent(inout) :: x(n)
      real(dp) :: z
      integer :: j
      do j = max(1, n - 2), n   ! (the factor's corner below row n is zero)
         z = pending1
         x(j) = z
         pending1 = pending2 - ab(2, j)*z
         pending2 = pending3 - ab(3, j)*z
         pending3 = 0
      end do
   end subroutine substitute_forward_last

   !> Backward substitution x = D^-1 z - L^T x in place (z in, x out), the three following
   !! x in scalars (nextk = x(j+k), zero past row n).
   pure subroutine substitute_backward(n, ab, x)
      integer, intent(in) :: n
      real(dp), intent(in) :: ab(4, n)
      real(dp), intent(inout) :: x(n)
      real(dp) :: z, next1, next2, next3
      integer :: j
      next1 = 0
      next2 = 0
      next3 = 0
      do j = n, 1, -1
         z = (x(j)*ab(1, j) - ab(4, j)*next3 - ab(3, j)*next2) - ab(2, j)*next1
         x(j) = z
         next3 = next2
         next2 = next1
         next1 = z
      end do
   end subroutine substitute_backward

   !> y = A x for a symmetric A in lower band storage, one pass over the columns: column j
   !! gives y_j its diagonal and lower-triangle terms (read down column j) and adds its
   !! transpose terms to three running sums for y_(j+1..j+3). The corner below row n is
   !! not read.
   pure subroutine band_matvec_kd3(n, ab, x, y)
      integer, intent(in) :: n
      real(dp), intent(in) :: ab(4, n), x(n)
      real(dp), intent(out) :: y(n)
      real(dp) :: carry1, carry2, carry3, xj
      integer :: j
      ! carryk: what columns before j have added to y(j+k-1)
      carry1 = 0
      carry2 = 0
      carry3 = 0
      do j = 1, n - 3
         xj = x(j)
         y(j) = carry1 + ab(1, j)*xj + ab(2, j)*x(j + 1) + ab(3, j)*x(j + 2) + ab(4, j)*x(j + 3)
         carry1 = carry2 + ab(2, j)*xj
         carry2 = carry3 + ab(3, j)*xj
         carry3 = ab(4, j)*xj
      end do
      do j = max(1, n - 2), n
         call matvec_row(n, ab, x, j, carry1, carry2, carry3, y(j))
      end do
   end subroutine band_matvec_kd3

   !> Row i of y = A x with the running sums of `band_matvec_kd3` (carryk: what columns
   !! before i have added to y(i+k-1)), for any i: the terms below row n are left out.
   pure subroutine matvec_row(n, ab, x, i, carry1, carry2, carry3, value)
      integer, intent(in) :: n, i
      real(dp), intent(in) :: ab(4, n), x(n)
      real(dp), intent(inout) :: carry1, carry2, carry3
      real(dp), intent(out) :: value
      real(dp) :: xi
      xi = x(i)
      value = carry1 + ab(1, i)*xi
      carry1 = carry2
      carry2 = carry3
      carry3 = 0
      if (i + 1 <= n) then
         value = value + ab(2, i)*x(i + 1)
         carry1 = carry1 + ab(2, i)*xi
      end if
      if (i + 2 <= n) then
         value = value + ab(3, i)*x(i + 2)
         carry2 = carry2 + ab(3, i)*xi
      end if
      if (i + 3 <= n) then
         value = value + ab(4, i)*x(i + 3)
         carry3 = ab(4, i)*xi
      end if
   end subroutine matvec_row

   !> y = W^-1 (b - A x), W given by the factor of `ldl_factor_kd3`, A in lower band storage:
   !! the product runs three rows ahead of the forward substitution in the same loop, so its
   !! arithmetic fills the time the substitution waits on its chain from row to row; the
   !! operations and their order are those of `band_matvec_kd3`, a subtraction and
   !! `ldl_solve_kd3`. y must not overlap x or b.
   pure subroutine ldl_residual_solve_kd3(n, factor, ab, x, b, y)
      integer, intent(in) :: n
      real(dp), intent(in) :: factor(4, n)   !! L D L^T of W
      real(dp), intent(in) :: ab(4, n)       !! A
      real(dp), intent(in) :: x(n), b(n)
      real(dp), intent(out) :: y(n)
      real(dp) :: carry1, carry2, carry3, product, pending1, pending2, pending3, z, xi
      integer :: j, i
      if (n < 1) return
      carry1 = 0
      carry2 = 0
      carry3 = 0
      pending1 = 0
      pending2 = 0
      pending3 = 0
      ! rows 1..3 of b - A x start the forward substitution's running values
      call matvec_row(n, ab, x, 1, carry1, carry2, carry3, product)
      pending1 = b(1) - product
      if (n >= 2) then
         call matvec_row(n, ab, x, 2, carry1, carry2, carry3, product)
         pending2 = b(2) - product
      end if
      if (n >= 3) then
         call matvec_row(n, ab, x, 3, carry1, carry2, carry3, product)
         pending3 = b(3) - product
      end if
      ! row j of the substitution with row i = j + 3 of the product (all of it inside)
      do j = 1, n - 6
         i = j + 3
         xi = x(i)
         product = carry1 + ab(1, i)*xi + ab(2, i)*x(i + 1) + ab(3, i)*x(i + 2) + ab(4, i)*x(i + 3)
         carry1 = carry2 + ab(2, i)*xi
         carry2 = carry3 + ab(3, i)*xi
         carry3 = ab(4, i)*xi
         z = pending1
         y(j) = z
         pending1 = pending2 - factor(2, j)*z
         pending2 = pending3 - factor(3, j)*z
         pending3 = (b(i) - product) - factor(4, j)*z
      end do
      do j = max(1, n - 5), n - 3   ! product rows n-2..n: their band ends at row n
         i = j + 3
         call matvec_row(n, ab, x, i, carry1, carry2, carry3, product)
         z = pending1
         y(j) = z
         pending1 = pending2 - factor(2, j)*z
         pending2 = pending3 - factor(3, j)*z
         pending3 = (b(i) - product) - factor(4, j)*z
      end do
      call substitute_forward_last(n, factor, pending1, pending2, pending3, y)
      call substitute_backward(n, factor, y)
   end subroutine ldl_residual_solve_kd3
end module vibrobeam_band_kernel
