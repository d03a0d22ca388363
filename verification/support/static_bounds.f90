!> Round-off bounds of static contact solutions and the dense helpers the tests use for
!! componentwise bounds (first order in u = eps/2; gamma_n = n u/(1 - n u), from
!! `vibrobeam_roundoff_bounds`; Higham, Accuracy and Stability of Numerical Algorithms,
!! 2nd ed., 2002). Dense inverses: for the test meshes only.
module vibrobeam_static_bounds
   use vibrobeam_kinds, only: dp
   use vibrobeam_lapack, only: dgesv, dgetrf
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_solve, band_factor
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_roundoff_bounds, only: gamma_n, abs_band_times, abs_factor_times
   implicit none
   private
   public :: static_error_bounds, dense_inverse, permuted_lu_times

contains

   !> First-order round-off bounds of a computed static contact solution (`solve_static`):
   !! K U = F + H^T R with H_c U = g_c on the held points (R_c /= 0). The computed solution
   !! solves a perturbed system, so (first order) its error is |dz| <= |KKT^-1| |d|, KKT =
   !! [K, -H^T; -H, 0] on the held points (a dense inverse: for the test meshes only), where
   !! d bounds the perturbation:
   !!  - K's entries (closed forms or quadrature) gamma_7 |K||U|, F's (quadrature) gamma_20
   !!    |F|, forming H^T R and H U gamma_{m+4}, the B-spline weights of H gamma_21 |H||U|;
   !!  - regime 'delassus': the Cholesky solves of K (K^-1 F and the columns K^-1 H_c^T),
   !!    |dK| <= gamma_{3kd+4} |L||L^T| (Higham, Thm 10.4 with kd + 1 terms per inner
   !!    product), and the dense Cholesky of A = H K^-1 H^T (m x m), which adds
   !!    |A^-1| gamma_{3m+1} |L_A||L_A^T||R| <= |A^-1| gamma_{3m+1} sqrt(a_ii) sum_j
   !!    sqrt(a_jj) |R_j| to R and K^-1 H^T times that to U;
   !!  - regime 'band': the right-hand side K x_free (x_free = K^-1 F by Cholesky, then a
   !!    band product), and the LU factorization with partial pivoting of the saddle-point
   !!    matrix in the solver's order (each multiplier after the last unknown of its row;
   !!    a band of w = 2 kd + 2 at most): |dKKT| <= gamma_{3(w+1)+1} P^T|L||U| (Thm 9.3-9.4),
   !!    with the factors of the same matrix computed here by dense LAPACK dgetrf (the band
   !!    factorization makes the same pivot choices).
   subroutine static_error_bounds(stiffness, contacts, force, u, reaction, regime, u_error, reaction_error)
      type(symmetric_band), intent(in) :: stiffness
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:), u(:), reaction(:)
      character(len=*), intent(in) :: regime        !! 'delassus' | 'band'
      real(dp), intent(out) :: u_error(:), reaction_error(:)
      type(band_cholesky) :: chol
      real(dp), allocatable :: kkt(:, :), inverse(:, :), z(:), perturbation(:), error(:), columns(:, :), &
                               schur(:, :), schur_inverse(:, :), extra(:), u_free(:), ordered(:, :), lu_term(:)
      integer, allocatable :: held(:), order(:), pivots(:)
      integer :: n, m, k, a, c, i, j, info, kd, position
      character(len=200) :: errmsg
      n = stiffness%n
      kd = stiffness%kd
      m = count(abs(reaction) > 0)
      allocate (held(m), kkt(n + m, n + m), inverse(n + m, n + m), z(n + m), error(n + m), u_free(n), &
                ordered(n + m, n + m), columns(n, m), schur(m, m), schur_inverse(m, m), extra(m))
      held = pack([(c, c=1, contacts%count)], abs(reaction) > 0)
      kkt = 0
      do j = 1, n
         do i = max(1, j - kd), min(n, j + kd)
            kkt(i, j) = band_value(stiffness, i, j)
         end do
      end do
      do k = 1, m
         do a = 1, 4
            if (contacts%dofs(a, held(k)) == 0) cycle
            kkt(contacts%dofs(a, held(k)), n + k) = -contacts%weights(a, held(k))
            kkt(n + k, contacts%dofs(a, held(k))) = -contacts%weights(a, held(k))
         end do
      end do
      inverse = dense_inverse(kkt)
      z = [abs(u), abs(reaction(held))]
      call band_factor(stiffness, chol, info, errmsg)
      allocate (perturbation(n + m))
      perturbation(1:n) = gamma_n(7)*abs_band_times(stiffness, z(1:n)) + gamma_n(20)*abs(force) &
                          + gamma_n(m + 4)*matmul(abs(kkt(1:n, n + 1:)), z(n + 1:))
      perturbation(n + 1:) = (gamma_n(m + 4) + gamma_n(21))*matmul(abs(kkt(n + 1:, 1:n)), z(1:n))
      if (regime == 'band') then
         u_free = force
         call band_solve(chol, u_free)   ! x_free
         perturbation(1:n) = perturbation(1:n) + gamma_n(3*kd + 4)*abs_factor_times(chol, abs(u_free)) &
                             + gamma_n(2*kd + 2)*abs_band_times(stiffness, abs(u_free))
         ! the solver's order: unknown i, then the multipliers whose last unknown is i
         allocate (order(n + m))
         position = 0
         do i = 1, n
            position = position + 1
            order(position) = i
            do k = 1, m
               if (maxval(contacts%dofs(:, held(k))) == i) then
                  position = position + 1
                  order(position) = n + k
               end if
            end do
         end do
         ordered = kkt(order, order)
         allocate (pivots(n + m))
         call dgetrf(n + m, n + m, ordered, n + m, pivots, info)
         allocate (lu_term(n + m))
         lu_term(order) = gamma_n(3*(2*kd + 3) + 1)*permuted_lu_times(ordered, pivots, z(order))
         perturbation = perturbation + lu_term
      else
         perturbation(1:n) = perturbation(1:n) + gamma_n(3*kd + 4)*abs_factor_times(chol, z(1:n))
      end if
      error = matmul(abs(inverse), perturbation)
      if (regime /= 'band' .and. m > 0) then
         do k = 1, m
            columns(:, k) = 0
            do a = 1, 4
               if (contacts%dofs(a, held(k)) /= 0) columns(contacts%dofs(a, held(k)), k) = contacts%weights(a, held(k))
            end do
            call band_solve(chol, columns(:, k))
         end do
         schur = matmul(transpose(-kkt(1:n, n + 1:)), columns)
         schur_inverse = dense_inverse(schur)
         extra = matmul(abs(schur_inverse), gamma_n(3*m + 1)*sqrt([(abs(schur(k, k)), k=1, m)])* &
                        sum(sqrt([(abs(schur(k, k)), k=1, m)])*z(n + 1:)))
         error(n + 1:) = error(n + 1:) + extra
         error(1:n) = error(1:n) + matmul(abs(columns), extra)
      end if
      u_error = error(1:n)
      reaction_error = 0
      reaction_error(held) = error(n + 1:)
   end subroutine static_error_bounds

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

   !> A(i,j) of a symmetric band matrix.
   pure real(dp) function band_value(a, i, j)
      type(symmetric_band), intent(in) :: a
      integer, intent(in) :: i, j
      band_value = a%lower(1 + max(i, j) - min(i, j), min(i, j))
   end function band_value

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
