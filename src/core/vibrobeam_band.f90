!> Symmetric band matrices in LAPACK lower band storage: assembly, products, Cholesky
!! factorization and solves.
!!
!! Storage convention (Reference-LAPACK, UPLO = 'L'): the entry A(i,j), j <= i <= j+kd, is
!! held in `lower(1+i-j, j)`; `lower` has kd+1 rows and n columns. The mass, stiffness and
!! iteration matrices of vibrobeam (theory §2, §3) all live in this form; no dense n x n
!! matrix is ever formed from them.
!!
!! Products, factorizations and solves of bandwidth 3 (every matrix of the model) go to the
!! specialised kernels of `vibrobeam_band_kernel`; any other bandwidth to LAPACK/BLAS
!! (dsbmv, dpbtrf, dpbtrs), which also serve as the kernels' test oracle. Neither
!! `band_solve` nor `band_matvec` allocates (for contiguous arguments).
module vibrobeam_band
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_linear_solver_failure
   use vibrobeam_band_kernel, only: kernel_bandwidth, ldl_factor_kd3, ldl_solve_kd3, band_matvec_kd3, &
                                    ldl_residual_solve_kd3
   use vibrobeam_lapack, only: dpbtrf, dpbtrs, dsbmv, poison_failed_solve
   implicit none
   private
   public :: symmetric_band, band_cholesky
   public :: band_allocate, band_add, band_entry, band_matvec, band_combination
   public :: band_factor, band_solve, band_residual_solve, band_to_dense

   !> A symmetric n x n matrix with kd sub-diagonals, lower band storage.
   type :: symmetric_band
      integer :: n = 0              !! order of the matrix
      integer :: kd = 0             !! number of sub-diagonals
      real(dp), allocatable :: lower(:,:)  !! (kd+1, n) lower band storage
   end type symmetric_band

   !> Cholesky factorization of a symmetric positive definite band matrix. For kd = 3 the
   !! square-root-free form A = L D L^T of `ldl_factor_kd3` (unit L, reciprocal pivots
   !! 1/d_j on the first row); for any other kd LAPACK dpbtrf's A = L L^T (UPLO = 'L').
   type :: band_cholesky
      integer :: n = 0
      integer :: kd = 0
      real(dp), allocatable :: factor(:,:)  !! (kd+1, n), in the form kd selects
   end type band_cholesky


contains

   !> Make `a` the n x n zero matrix with kd sub-diagonals.
   pure subroutine band_allocate(a, n, kd)
      type(symmetric_band), intent(out) :: a
      integer, intent(in) :: n, kd
      a%n = n
      a%kd = kd
      allocate (a%lower(kd + 1, n), source=0.0_dp)
   end subroutine band_allocate

   !> Add `value` to A(i,j) (and implicitly to A(j,i)); only the lower triangle is stored,
   !! so a call with i < j adds to A(j,i). Entries outside the band are an error of the
   !! caller and are caught by -fcheck=bounds in debug builds.
   pure subroutine band_add(a, i, j, value)
      type(symmetric_band), intent(inout) :: a
      integer, intent(in) :: i, j
      real(dp), intent(in) :: value
      a%lower(1 + max(i, j) - min(i, j), min(i, j)) = a%lower(1 + max(i, j) - min(i, j), min(i, j)) + value
   end subroutine band_add

   !> A(i,j) of a symmetric band matrix (zero outside the band).
   pure function band_entry(a, i, j) result(value)
      type(symmetric_band), intent(in) :: a
      integer, intent(in) :: i, j
      real(dp) :: value
      if (abs(i - j) > a%kd) then
         value = 0.0_dp
      else
         value = a%lower(1 + max(i, j) - min(i, j), min(i, j))
      end if
   end function band_entry

   !> y = A x (kd = 3: `band_matvec_kd3`; otherwise BLAS dsbmv).
   subroutine band_matvec(a, x, y)
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: x(:)   !! (n)
      real(dp), intent(out) :: y(:)  !! (n)
      if (a%n == 0) return
      if (a%kd == kernel_bandwidth) then
         call band_matvec_kd3(a%n, a%lower, x, y)
      else
         call dsbmv('L', a%n, a%kd, 1.0_dp, a%lower, a%kd + 1, x, 1, 0.0_dp, y, 1)
      end if
   end subroutine band_matvec

   !> c = alpha a + beta b for two band matrices of the same order (the band of c is the
   !! wider of the two).
   pure function band_combination(alpha, a, beta, b) result(c)
      real(dp), intent(in) :: alpha, beta
      type(symmetric_band), intent(in) :: a, b
      type(symmetric_band) :: c
      call band_allocate(c, a%n, max(a%kd, b%kd))
      c%lower(1:a%kd + 1, :) = alpha*a%lower
      c%lower(1:b%kd + 1, :) = c%lower(1:b%kd + 1, :) + beta*b%lower
   end function band_combination

   !> Cholesky factorization of A (kd = 3: `ldl_factor_kd3`; otherwise LAPACK dpbtrf).
   !! stat = 0 on success, stat_linear_solver_failure if the leading minor of order k is not
   !! positive definite (errmsg names k; both forms find the same k).
   subroutine band_factor(a, chol, stat, errmsg)
      type(symmetric_band), intent(in) :: a
      type(band_cholesky), intent(out) :: chol
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      chol%n = a%n
      chol%kd = a%kd
      chol%factor = a%lower
      errmsg = ''
      stat = 0
      if (a%n == 0) return
      if (a%kd == kernel_bandwidth) then
         call ldl_factor_kd3(a%n, chol%factor, stat)
      else
         call dpbtrf('L', a%n, a%kd, chol%factor, a%kd + 1, stat)
      end if
      if (stat > 0) then
         write (errmsg, '(a,i0,a)') 'band Cholesky factorization failed: leading minor of order ', &
            stat, ' is not positive definite'
         stat = stat_linear_solver_failure
      else if (stat < 0) then
         write (errmsg, '(a,i0)') 'dpbtrf rejected argument ', -stat
         stat = stat_linear_solver_failure
      end if
   end subroutine band_factor

   !> Overwrite x with A^{-1} x, given the factorization of A (kd = 3: `ldl_solve_kd3`;
   !! otherwise LAPACK dpbtrs).
   subroutine band_solve(chol, x)
      type(band_cholesky), intent(in) :: chol
      real(dp), intent(inout) :: x(:)  !! (n) right-hand side in, solution out
      integer :: info
      if (chol%n == 0) return
      if (chol%kd == kernel_bandwidth) then
         call ldl_solve_kd3(chol%n, chol%factor, x)
      else
         call dpbtrs('L', chol%n, chol%kd, 1, chol%factor, chol%kd + 1, x, chol%n, info)
         call poison_failed_solve(info, x)
      end if
   end subroutine band_solve

   !> y = W^-1 (b - A x), W given by its factorization `chol`: the solve of a step of the
   !! velocity scheme (theory §3) with its product by K. With both bandwidths 3 one fused
   !! pass (`ldl_residual_solve_kd3`, the same operations as band_matvec, a subtraction and
   !! band_solve); otherwise BLAS dsbmv then LAPACK dpbtrs. No allocation.
   subroutine band_residual_solve(chol, a, x, b, y)
      type(band_cholesky), intent(in) :: chol   !! factorization of W (n x n)
      type(symmetric_band), intent(in) :: a     !! A (n x n)
      real(dp), intent(in) :: x(:), b(:)        !! (n)
      real(dp), intent(out) :: y(:)             !! (n), not overlapping x or b
      integer :: info
      if (chol%n == 0) return
      if (chol%kd == kernel_bandwidth .and. a%kd == kernel_bandwidth) then
         call ldl_residual_solve_kd3(chol%n, chol%factor, a%lower, x, b, y)
      else
         y = b
         call dsbmv('L', a%n, a%kd, -1.0_dp, a%lower, a%kd + 1, x, 1, 1.0_dp, y, 1)
         if (chol%kd == kernel_bandwidth) then
            call ldl_solve_kd3(chol%n, chol%factor, y)
         else
            call dpbtrs('L', chol%n, chol%kd, 1, chol%factor, chol%kd + 1, y, chol%n, info)
            call poison_failed_solve(info, y)
         end if
      end if
   end subroutine band_residual_solve

   !> The dense n x n form of a symmetric band matrix (small matrices: the reduced model's
   !! dense paths and tests).
   pure function band_to_dense(a) result(dense)
      type(symmetric_band), intent(in) :: a
      real(dp) :: dense(a%n, a%n)
      integer :: i, j
      dense = 0
      do j = 1, a%n
         do i = j, min(a%n, j + a%kd)
            dense(i, j) = a%lower(1 + i - j, j)
            dense(j, i) = dense(i, j)
         end do
      end do
   end function band_to_dense
end module vibrobeam_band
