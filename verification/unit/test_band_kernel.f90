!> Unit test: the band kernels of bandwidth 3 (`vibrobeam_band_kernel`, reached through
!! band_factor / band_solve / band_matvec) against LAPACK/BLAS (dpbtrf, dpbtrs, dsbmv),
!! the oracle, with round-off bounds derived here (u = eps/2 the unit round-off, kd = 3):
!!
!! - product: each y_i is a sum of at most 2kd+1 products, so |fl(A x) - A x| <=
!!   gamma_(2kd+1) |A| |x| (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed.,
!!   §3.5); two such results differ by at most 2 (2kd+1) u (|A||x|)_i.
!! - solve, backward error: Cholesky or L D L^T of a band SPD matrix followed by the two
!!   triangular solves gives (A + dA) x^ = b with |dA| <= gamma_(3kd+4) |L||D||L^T| (Higham
!!   Thm 10.4 with n replaced by the kd+1 terms of a band inner product; the reciprocal
!!   pivots add one rounding to the factorization and one to the backward solve, already in
!!   3(kd+1)+1). By Cauchy-Schwarz (|L||D||L^T|)_ij <= sqrt(a_ii a_jj), and for SPD A also
!!   |a_ij| <= sqrt(a_ii a_jj). With S_i = sqrt(a_ii) sum_(|i-j|<=kd) sqrt(a_jj) |x^_j|, the
!!   residual computed in floating point (a product, then a subtraction) satisfies
!!   |b - A x^|_i <= (3kd+4 + 2kd+1 + 1) u S_i = (5kd+6) u S_i to first order in u.
!!   Checked for the kernel and for LAPACK alike.
!! - solve, forward error (Skeel): |x^ - x| <= |A^-1| |dA| |x^|, so the kernel's and
!!   LAPACK's solutions differ by at most 2 (3kd+4) u |A^-1| S componentwise. |A^-1| is
!!   formed column by column with LAPACK solves (J solves: only where J <= 2000); its own
!!   relative error, about kappa u < 1e-3 here, is a negligible second-order change to the
!!   bound.
!!
!! - fused y = A^-1 (b - P x) (`band_residual_solve`) against BLAS dsbmv + LAPACK dpbtrs:
!!   forming b - P x costs at most (2kd+2) u (|b| + |P||x|) on either side, so the two
!!   differ by at most 2 |A^-1| ((3kd+4) u S + (2kd+2) u (|b| + |P||x|)); where |A^-1| is
!!   not formed, A y - (b - P x) recomputed must stay within (5kd+6) u S +
!!   2 (2kd+2) u (|b| + |P||x|). P = K for the model's W, P = A otherwise.
!!
!! Matrices: random SPD band matrices A = R R^T (R lower band with 3 sub-diagonals, so A
!! has 3) for n = 1 ... 1000, one of them ill-conditioned (a pivot of R at 1e-6: kappa
!! about 1e12); the model's W = M + (theta dt)^2 K and K itself for both bases at
!! N = 10 ... 10000 and dt = 1e-2 ... 1e-6 s. The failure path: making the m-th pivot -1
!! must fail with stat_linear_solver_failure and a message naming m, dpbtrf's info; a NaN there too (where invalid operations do not
!! trap), which dpbtrf lets through. Bandwidths 2 and 5 take the LAPACK
!! path and must give the same residual bound.
program test_band_kernel
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_get_halting_mode, ieee_invalid
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_linear_solver_failure
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_allocate, band_combination, &
                             band_factor, band_solve, band_matvec, band_residual_solve
   use vibrobeam_lapack, only: dpbtrf, dpbtrs, dsbmv
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_test_support, only: test_counter
   implicit none
   real(dp), parameter :: u = epsilon(1.0_dp)/2   !! unit round-off
   integer, parameter :: kd = 3
   integer, parameter :: sizes(9) = [1, 2, 3, 4, 5, 7, 40, 200, 1000]
   integer, parameter :: elements(4) = [10, 100, 1000, 10000]
   real(dp), parameter :: steps(3) = [1e-2_dp, 1e-4_dp, 1e-6_dp]
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   type(test_counter) :: t
   type(symmetric_band) :: a
   type(beam_model) :: model
   integer :: k, b, d, stat, seed_size
   integer, allocatable :: seed(:)
   character(len=200) :: errmsg
   character(len=80) :: label
   !> largest error/bound seen: product, residual (kernel), residual (LAPACK), forward,
   !! fused residual solve
   real(dp) :: largest_ratio(5) = 0

   call random_seed(size=seed_size)
   seed = [(104729*k + 7, k=1, seed_size)]
   call random_seed(put=seed)

   do k = 1, size(sizes)
      write (label, '(a,i0)') 'random SPD, n = ', sizes(k)
      call random_spd(sizes(k), kd, 1.0_dp, a)
      call compare(trim(label), a, sizes(k) <= 2000)
   end do
   call random_spd(200, kd, 1e-6_dp, a)
   call compare('ill-conditioned random SPD (pivot 1e-6), n = 200', a, .true.)

   do b = 1, size(bases)
      do k = 1, size(elements)
         call build_model(bases(b), elements(k), 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
         if (stat /= 0) error stop 'build_model failed'
         do d = 1, size(steps)
            write (label, '(a,i0,a,es7.1)') trim(bases(b))//' W, N = ', elements(k), ', dt = ', steps(d)
            a = band_combination(1.0_dp, model%mass, (0.5_dp*steps(d))**2, model%stiffness)
            call compare(trim(label), a, model%unknowns <= 2000, model%stiffness)
         end do
         write (label, '(a,i0)') trim(bases(b))//' K, N = ', elements(k)
         call compare(trim(label), model%stiffness, model%unknowns <= 2000)
      end do
   end do

   call check_failure(1)
   call check_failure(2)
   call check_failure(97)
   call check_failure(200)

   ! other bandwidths take the LAPACK path
   call random_spd(50, 2, 1.0_dp, a)
   call compare('LAPACK path, kd = 2, n = 50', a, .true.)
   call random_spd(50, 5, 1.0_dp, a)
   call compare('LAPACK path, kd = 5, n = 50', a, .true.)

   write (*, '(a,5es10.2)') 'largest error / bound: product, residual (kernel), residual (LAPACK), '// &
      'kernel - LAPACK, fused residual solve:', largest_ratio
   call t%finish('test_band_kernel')

contains

   !> A = R R^T, R lower triangular with `width` sub-diagonals, entries uniform in
   !! [-1, 1] off the diagonal and in [1, 2] on it; R(m,m) = `pivot` at m = n/2 + 1 when
   !! pivot < 1 (the Cholesky factor of A is R, so that pivot sets the conditioning).
   subroutine random_spd(n, width, pivot, a, factor)
      integer, intent(in) :: n, width
      real(dp), intent(in) :: pivot
      type(symmetric_band), intent(out) :: a
      real(dp), intent(out), optional :: factor(width + 1, n)   !! R, band storage
      real(dp) :: r(width + 1, n)
      integer :: i, j, l
      call random_number(r)
      r(2:, :) = 2*r(2:, :) - 1
      r(1, :) = 1 + r(1, :)
      if (pivot < 1) r(1, n/2 + 1) = pivot
      call band_allocate(a, n, width)
      ! A(i,j) = sum_l R(i,l) R(j,l), l <= j <= i, i - l <= width
      do j = 1, n
         do i = j, min(n, j + width)
            do l = max(1, i - width), j
               a%lower(1 + i - j, j) = a%lower(1 + i - j, j) + r(1 + i - l, l)*r(1 + j - l, l)
            end do
         end do
      end do
      if (present(factor)) factor = r
   end subroutine random_spd

   !> S_i = sqrt(a_ii) sum_(|i-j|<=kd) sqrt(a_jj) |x_j| (see the header).
   function bound_scale(a, x) result(s)
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: x(:)
      real(dp) :: s(a%n)
      integer :: i, j
      do i = 1, a%n
         s(i) = 0
         do j = max(1, i - a%kd), min(a%n, i + a%kd)
            s(i) = s(i) + sqrt(a%lower(1, j))*abs(x(j))
         end do
         s(i) = sqrt(a%lower(1, i))*s(i)
      end do
   end function bound_scale

   !> (|A| |x|)_i from the band storage.
   function absolute_product(a, x) result(y)
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: x(:)
      real(dp) :: y(a%n)
      integer :: i, j
      y = 0
      do j = 1, a%n
         y(j) = y(j) + abs(a%lower(1, j))*abs(x(j))
         do i = j + 1, min(a%n, j + a%kd)
            y(i) = y(i) + abs(a%lower(1 + i - j, j))*abs(x(j))
            y(j) = y(j) + abs(a%lower(1 + i - j, j))*abs(x(i))
         end do
      end do
   end function absolute_product

   !> The checks of the header on one SPD matrix; `skeel` adds the forward-error check
   !! (J LAPACK solves).
   subroutine compare(label, a, skeel, product)
      character(len=*), intent(in) :: label
      type(symmetric_band), intent(in) :: a
      logical, intent(in) :: skeel
      type(symmetric_band), intent(in), optional :: product   !! P of y = A^-1 (b - P x) (default A)
      type(band_cholesky) :: chol
      type(symmetric_band) :: p
      real(dp) :: lapack_factor(a%kd + 1, a%n), column(a%n, 1)
      real(dp) :: x_true(a%n), rhs(a%n), x_kernel(a%n), x_lapack(a%n), y_kernel(a%n), y_blas(a%n), &
                  limit(a%n), inverse_bound(a%n), s(a%n), b(a%n), fused(a%n), separate(a%n), &
                  residual_size(a%n), inverse_residual_bound(a%n), s_fused(a%n), inverse_fused_bound(a%n)
      real(dp) :: worst
      integer :: n, info, stat, j
      character(len=200) :: errmsg
      n = a%n
      p = a
      if (present(product)) p = product
      call random_number(x_true)
      x_true = 2*x_true - 1
      ! product
      call band_matvec(a, x_true, y_kernel)
      call dsbmv('L', n, a%kd, 1.0_dp, a%lower, a%kd + 1, x_true, 1, 0.0_dp, y_blas, 1)
      limit = 2*(2*a%kd + 1)*u*absolute_product(a, x_true)
      worst = maxval(abs(y_kernel - y_blas)/limit, limit > 0)
      largest_ratio(1) = max(largest_ratio(1), worst)
      call t%check_true(label//': |A x (kernel) - A x (dsbmv)| <= 2 (2kd+1) u |A||x|', &
                        all(abs(y_kernel - y_blas) <= limit), ratio_text(worst))
      ! factorizations
      call band_factor(a, chol, stat, errmsg)
      call t%check_true(label//': factorization', stat == 0, errmsg)
      lapack_factor = a%lower
      call dpbtrf('L', n, a%kd, lapack_factor, a%kd + 1, info)
      call t%check_true(label//': dpbtrf', info == 0)
      if (stat /= 0 .or. info /= 0) return
      ! solves of A x = b, b = A x_true
      rhs = y_blas
      x_kernel = rhs
      call band_solve(chol, x_kernel)
      x_lapack = rhs
      call dpbtrs('L', n, a%kd, 1, lapack_factor, a%kd + 1, x_lapack, n, info)
      call residual_check(label//' (kernel)', a, rhs, x_kernel, largest_ratio(2))
      call residual_check(label//' (LAPACK)', a, rhs, x_lapack, largest_ratio(3))
      ! the fused y = A^-1 (b - P x) against dsbmv + dpbtrs; b of the size of P x
      call random_number(b)
      b = (2*b - 1)*maxval(abs(y_blas))
      call band_residual_solve(chol, p, x_true, b, fused)
      separate = b
      call dsbmv('L', n, p%kd, -1.0_dp, p%lower, p%kd + 1, x_true, 1, 1.0_dp, separate, 1)
      call dpbtrs('L', n, a%kd, 1, lapack_factor, a%kd + 1, separate, n, info)
      ! b - P x is formed with error <= (2kd+2) u (|b| + |P||x|) on either side
      residual_size = abs(b) + absolute_product(p, x_true)
      if (.not. skeel) then
         ! A y^ - (b - P x), recomputed: (5kd+6) u S of the solve + 2 (2kd+2) u (|b| + |P||x|)
         separate = b
         call dsbmv('L', n, p%kd, -1.0_dp, p%lower, p%kd + 1, x_true, 1, 1.0_dp, separate, 1)
         call dsbmv('L', n, a%kd, 1.0_dp, a%lower, a%kd + 1, fused, 1, -1.0_dp, separate, 1)
         limit = (5*a%kd + 6)*u*bound_scale(a, fused) + 2*(2*p%kd + 2)*u*residual_size
         worst = maxval(abs(separate)/limit, limit > 0)
         largest_ratio(5) = max(largest_ratio(5), worst)
         call t%check_true(label//': |A y - (b - P x)| of the fused solve', all(abs(separate) <= limit), &
                           ratio_text(worst))
         return
      end if
      ! |A^-1| S for the plain and the fused solves, and |A^-1| (|b| + |P||x|), one column of
      ! A^-1 at a time
      s = max(bound_scale(a, x_kernel), bound_scale(a, x_lapack))
      s_fused = max(bound_scale(a, fused), bound_scale(a, separate))
      inverse_bound = 0
      inverse_fused_bound = 0
      inverse_residual_bound = 0
      do j = 1, n
         column = 0
         column(j, 1) = 1
         call dpbtrs('L', n, a%kd, 1, lapack_factor, a%kd + 1, column, n, info)
         inverse_bound = inverse_bound + abs(column(:, 1))*s(j)
         inverse_fused_bound = inverse_fused_bound + abs(column(:, 1))*s_fused(j)
         inverse_residual_bound = inverse_residual_bound + abs(column(:, 1))*residual_size(j)
      end do
      limit = 2*(3*a%kd + 4)*u*inverse_bound
      worst = maxval(abs(x_kernel - x_lapack)/limit, limit > 0)
      largest_ratio(4) = max(largest_ratio(4), worst)
      call t%check_true(label//': |x (kernel) - x (LAPACK)| <= 2 (3kd+4) u |A^-1| S', &
                        all(abs(x_kernel - x_lapack) <= limit), ratio_text(worst))
      ! the fused solve: the same, with the error of forming b - P x
      limit = 2*((3*a%kd + 4)*u*inverse_fused_bound + (2*p%kd + 2)*u*inverse_residual_bound)
      worst = maxval(abs(fused - separate)/limit, limit > 0)
      largest_ratio(5) = max(largest_ratio(5), worst)
      call t%check_true(label//': |y (fused) - y (dsbmv + dpbtrs)| <= 2 |A^-1| ((3kd+4) u S + (2kd+2) u '// &
                        '(|b| + |P||x|))', all(abs(fused - separate) <= limit), ratio_text(worst))
   end subroutine compare

   !> |b - A x|_i <= (5kd+6) u S_i (header), the residual computed with dsbmv.
   subroutine residual_check(label, a, rhs, x, largest)
      character(len=*), intent(in) :: label
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: rhs(:), x(:)
      real(dp), intent(inout) :: largest   !! largest error/bound so far
      real(dp) :: residual(size(x)), limit(size(x)), worst
      residual = rhs
      call dsbmv('L', a%n, a%kd, -1.0_dp, a%lower, a%kd + 1, x, 1, 1.0_dp, residual, 1)
      limit = (5*a%kd + 6)*u*bound_scale(a, x)
      worst = maxval(abs(residual)/limit, limit > 0)
      largest = max(largest, worst)
      call t%check_true(label//': |b - A x| <= (5kd+6) u S', all(abs(residual) <= limit), ratio_text(worst))
   end subroutine residual_check

   !> Make the m-th pivot of A = R R^T equal to -1 (a_mm -= R(m,m)^2 + 1: the leading
   !! minors of order < m are untouched, the one of order m is negative), then NaN;
   !! both must fail (stat_linear_solver_failure) with the message naming m, dpbtrf's info.
   subroutine check_failure(m)
      integer, intent(in) :: m
      integer, parameter :: n = 200
      real(dp) :: r(kd + 1, n)
      type(symmetric_band) :: a
      type(band_cholesky) :: chol
      real(dp) :: lapack_factor(kd + 1, n)
      integer :: stat, info, attempt
      logical :: trapping
      character(len=200) :: errmsg
      character(len=20) :: order
      call random_spd(n, kd, 1.0_dp, a, r)
      write (order, '(a,i0)') 'order ', m
      do attempt = 1, 2
         if (attempt == 1) then
            a%lower(1, m) = a%lower(1, m) - r(1, m)**2 - 1
         else
            ! a NaN pivot (skipped where invalid operations trap: the Debug build)
            call ieee_get_halting_mode(ieee_invalid, trapping)
            if (trapping) cycle
            a%lower(1, m) = ieee_value(a%lower(1, m), ieee_quiet_nan)
         end if
         call band_factor(a, chol, stat, errmsg)
         lapack_factor = a%lower
         call dpbtrf('L', n, kd, lapack_factor, kd + 1, info)
         write (label, '(a,i0,a)') 'pivot ', m, merge(' = -1 ', ' = NaN', attempt == 1)
         call t%check_true(trim(label)//': stat_linear_solver_failure', stat == stat_linear_solver_failure, errmsg)
         ! dpbtrf's unblocked dpbtf2 only tests a_jj <= 0, so it lets a NaN pivot through;
         ! the kernel stops there (its test is "not > 0")
         if (attempt == 1) call t%check_true(trim(label)//': dpbtrf info = m', info == m)
         call t%check_true(trim(label)//': message names the minor', index(errmsg, trim(order)//' ') > 0, errmsg)
      end do
   end subroutine check_failure

   function ratio_text(worst) result(text)
      real(dp), intent(in) :: worst
      character(len=60) :: text
      write (text, '(a,es10.3)') 'largest error / bound = ', worst
   end function ratio_text
end program test_band_kernel
