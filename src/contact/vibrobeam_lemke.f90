!> Dense linear complementarity problems LCP(M, q) with a general (not necessarily
!! symmetric) matrix M, by Lemke's complementary pivoting method.
!!
!! Find z such that
!!
!!     w = M z + q,   z >= 0,   w >= 0,   z_i w_i = 0  (i = 1..n).
!!
!! `vibrobeam_lcp` solves the symmetric positive definite case (block principal pivoting);
!! this module is for matrices it does not accept, in vibrobeam the non-symmetric LCP of
!! 2-D Coulomb friction (`vibrobeam_frictional_contact`, docs/method.md "Frictional contact
!! in two dimensions: the solver").
!!
!! Method (Lemke, Manage. Sci. 11 (1965) 681-689; Cottle, Pang & Stone, *The Linear
!! Complementarity Problem*, 1992, §4.4, "Scheme I"): an artificial variable z0 with the
!! covering vector d = (1, ..., 1) gives the augmented system w = q + M z + d z0. Starting
!! from the basis of all w and z0 = -min q, the method pivots along an almost complementary
!! path: the variable that enters the basis is the complement of the one that left, the one
!! that leaves is chosen by the minimum ratio test, until z0 leaves (a solution) or the
!! entering column has no positive entry (a secondary ray: the method stops without a
!! solution).
!!
!! Anti-cycling: ties of the ratio test are broken by the lexicographic rule (Cottle, Pang
!! & Stone §4.9): among the rows with the smallest ratio, the one whose row of B^-1
!! divided by its pivot entry is lexicographically smallest, with z0 preferred when it
!! ties. The starting tableau [q, I] has lexicographically positive rows after the first
!! pivot, every later pivot keeps them so, hence no basis repeats and the path is finite
!! (at most the number of almost complementary bases) even on degenerate problems.
!!
!! Termination with a solution (not a ray) holds when M is copositive and q lies in the
!! dual of SOL(0, M), i.e. z >= 0, M z >= 0, z^T M z = 0 imply z^T q >= 0 (Cottle, Pang &
!! Stone, Theorem 4.4.13); in particular for every q when M is copositive-plus and
!! the LCP is feasible (§4.4), and for every q when M is positive definite.
!!
!! Implementation: a dense tableau B^-1 [I, -M, -d, q] updated by Gauss-Jordan pivots
!! (the rank-one updates by BLAS dger) chooses the basis; the solution of the final basis is then recomputed from the original
!! data by one LU solve (LAPACK dgesv), so the round-off accumulated along the pivoting
!! path does not reach the result. Cost O(n^2) per pivot, typically O(n) pivots.
module vibrobeam_lemke
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: fail => set_failure, stat_invalid_argument, stat_no_convergence, stat_numerical_failure, &
                               stat_linear_solver_failure, stat_residual_check_failed
   use vibrobeam_lapack, only: dgesv, dger
   implicit none
   private
   public :: solve_lemke

   !> Entries of a pivot column below `pivot_threshold` n eps times the column's largest
   !! entry are round-off of the tableau updates, not pivots.
   real(dp), parameter :: pivot_threshold = 64.0_dp
   !> Ratios closer than `tie_threshold` n eps times the scale of z are ties (degeneracy);
   !! the lexicographic rule decides between them.
   real(dp), parameter :: tie_threshold = 64.0_dp
   !> Length of the local message buffer.
   integer, parameter :: buffer_length = 512

contains

   !> Solve LCP(M, q) by Lemke's method (module documentation).
   !!
   !! Status codes (vibrobeam_status; `errmsg` empty when stat = 0):
   !!
   !! * stat_ok: z >= 0, w >= 0 and z_i w_i = 0 exactly (w_i = 0 for basic z_i, z_i = 0
   !!   otherwise), w = M z + q to the round-off of one LU solve (checked: every violation
   !!   below `tolerance` times max(|q|_inf, |M|_inf |z|_inf)).
   !! * stat_numerical_failure: the path ended on a secondary ray (no positive entry in the
   !!   entering column): M or q violate the termination conditions, e.g. M not copositive
   !!   or the LCP infeasible; z = w = 0.
   !! * stat_no_convergence: more than `max_pivots` pivots; z = w = 0.
   !! * stat_linear_solver_failure: the final basis matrix is singular to LAPACK; z = w = 0.
   !! * stat_residual_check_failed: the recomputed solution of the final basis violates
   !!   z >= 0 or w >= 0 by more than the tolerance (round-off dominates); z, w hold it.
   !! * stat_invalid_argument: inconsistent sizes, a non-finite entry, max_pivots < 0 or a
   !!   tolerance that is not positive; z = w = 0.
   subroutine solve_lemke(m, q, z, w, pivots, stat, errmsg, max_pivots, tolerance, basic)
      real(dp), intent(in) :: m(:, :)   !! (n, n) LCP matrix
      real(dp), intent(in) :: q(:)      !! (n) LCP vector
      real(dp), intent(out) :: z(:)     !! (n) solution z >= 0
      real(dp), intent(out) :: w(:)     !! (n) w = M z + q >= 0, complementary to z
      integer, intent(out) :: pivots    !! pivots performed (0 when q >= 0)
      integer, intent(out) :: stat      !! status code (above)
      character(len=*), intent(out) :: errmsg  !! empty when stat = 0, else one sentence
      !> Largest number of pivots; default max(100, 20 n). Lemke's path is finite, but
      !! its length is not bounded by a polynomial in n; the limit only bounds the work.
      integer, intent(in), optional :: max_pivots
      !> Relative tolerance of the final check; default 1e-10.
      real(dp), intent(in), optional :: tolerance
      !> (n) on return with stat = 0 or stat_residual_check_failed: .true. where z_i is
      !! basic (z_i >= 0, w_i = 0), .false. where w_i is basic (z_i = 0)
      logical, intent(out), optional :: basic(:)

      real(dp), allocatable :: tableau(:, :)
      integer, allocatable :: basis(:)   ! basis(row): 1..n w_j, n+1..2n z_j, 2n+1 z0
      integer :: n, limit, entering, leaving_row, leaving, i
      real(dp) :: check_tolerance, z_unit
      character(len=buffer_length) :: message

      n = size(q)
      z = 0.0_dp
      w = 0.0_dp
      pivots = 0
      stat = 0
      errmsg = ''
      if (present(basic)) basic = .false.
      limit = max(100, 20*n)
      if (present(max_pivots)) limit = max_pivots
      check_tolerance = 1.0e-10_dp
      if (present(tolerance)) check_tolerance = tolerance
      if (size(m, 1) /= n .or. size(m, 2) /= n .or. size(z) /= n .or. size(w) /= n) then
         write (message, '(a, 4(i0, a))') 'solve_lemke: inconsistent sizes: m is ', size(m, 1), ' x ', &
            size(m, 2), ', q has ', n, ', z has ', size(z), ' entries.'
         call fail(stat_invalid_argument, message, stat, errmsg)
         return
      end if
      if (present(basic)) then
         if (size(basic) /= n) then
            call fail(stat_invalid_argument, 'solve_lemke: basic has not the size of q.', stat, errmsg)
            return
         end if
      end if
      if (limit < 0 .or. .not. (check_tolerance > 0.0_dp .and. ieee_is_finite(check_tolerance))) then
         call fail(stat_invalid_argument, 'solve_lemke: max_pivots is negative or tolerance is not a '// &
                   'positive finite number.', stat, errmsg)
         return
      end if
      if (.not. (all(ieee_is_finite(m)) .and. all(ieee_is_finite(q)))) then
         call fail(stat_invalid_argument, 'solve_lemke: m or q has a NaN or infinite entry.', stat, errmsg)
         return
      end if
      if (n == 0) return
      if (all(q >= 0.0_dp)) then       ! z = 0 solves it
         w = q
         return
      end if

      ! The natural unit of z, for the tie test of the ratios (which are values of the
      ! entering variable): |q| / |M|.
      z_unit = maxval(abs(q))/max(maxval(abs(m)), tiny(1.0_dp))
      call initial_tableau(m, q, tableau, basis)

      ! First pivot: z0 enters (column 2n+1, entries -1) in the row of the most negative q
      ! (the largest index among ties, which keeps the other rows of [q, I]
      ! lexicographically positive after the pivot).
      leaving_row = n + 1 - minloc(q(n:1:-1), dim=1)
      entering = 2*n + 1
      do
         leaving = basis(leaving_row)
         call pivot_on(tableau, leaving_row, entering)
         basis(leaving_row) = entering
         pivots = pivots + 1
         if (leaving == 2*n + 1) exit                      ! z0 left: complementary basis
         if (pivots >= limit) then
            write (message, '(a, i0, a, i0, a)') 'solve_lemke: no solution after ', pivots, &
               ' pivots (the limit) for n = ', n, '.'
            call fail(stat_no_convergence, message, stat, errmsg)
            return
         end if
         entering = complement(leaving, n)
         leaving_row = ratio_test(tableau, basis, entering, n, z_unit)
         if (leaving_row == 0) then
            write (message, '(a, i0, a, i0, a)') 'solve_lemke: secondary ray after ', pivots, &
               ' pivots (n = ', n, '): the matrix is not copositive, or the problem has no solution.'
            call fail(stat_numerical_failure, message, stat, errmsg)
            return
         end if
      end do
      call basis_solution(m, q, basis, check_tolerance, z, w, stat, errmsg)
      if (present(basic) .and. (stat == 0 .or. stat == stat_residual_check_failed)) &
         basic = [(any(basis == n + i), i=1, n)]
   end subroutine solve_lemke

   !> The tableau [I, -M, -d, q] of w - M z - d z0 = q with d = 1, and the basis of all w.
   pure subroutine initial_tableau(m, q, tableau, basis)
      real(dp), intent(in) :: m(:, :), q(:)
      real(dp), allocatable, intent(out) :: tableau(:, :)
      integer, allocatable, intent(out) :: basis(:)
      integer :: n, i
      n = size(q)
      allocate (tableau(n, 2*n + 2), source=0.0_dp)
      do i = 1, n
         tableau(i, i) = 1.0_dp
      end do
      tableau(:, n + 1:2*n) = -m
      tableau(:, 2*n + 1) = -1.0_dp
      tableau(:, 2*n + 2) = q
      basis = [(i, i=1, n)]
   end subroutine initial_tableau

   !> The complement of a variable: w_j <-> z_j (z0 has none and never enters twice).
   pure integer function complement(variable, n)
      integer, intent(in) :: variable, n
      if (variable <= n) then
         complement = variable + n
      else
         complement = variable - n
      end if
   end function complement

   !> Gauss-Jordan pivot on tableau(row, column): that row divided by the pivot, the
   !! column eliminated from every other row (a rank-one update, BLAS dger).
   subroutine pivot_on(tableau, row, column)
      real(dp), intent(inout) :: tableau(:, :)
      integer, intent(in) :: row, column
      real(dp) :: pivot_column(size(tableau, 1)), pivot_row(size(tableau, 2))
      pivot_column = tableau(:, column)/tableau(row, column)
      pivot_column(row) = 0.0_dp
      pivot_row = tableau(row, :)
      call dger(size(tableau, 1), size(tableau, 2), -1.0_dp, pivot_column, 1, pivot_row, 1, tableau, &
                size(tableau, 1))
      tableau(row, :) = pivot_row/pivot_row(column)
      tableau(:, column) = 0.0_dp
      tableau(row, column) = 1.0_dp
   end subroutine pivot_on

   !> Leaving row of the minimum ratio test for the entering column, 0 when the column has
   !! no positive entry (a ray). Ties within the round-off of the ratios go to z0 if it is
   !! one of them, otherwise to the lexicographically smallest row of B^-1 (the first n
   !! columns of the tableau) divided by its pivot entry.
   pure integer function ratio_test(tableau, basis, entering, n, z_unit) result(leaving_row)
      real(dp), intent(in) :: tableau(:, :), z_unit
      integer, intent(in) :: basis(:), entering, n
      logical :: candidate(n)
      real(dp) :: ratio(n), column(n), smallest, threshold, tie
      integer :: i, k
      leaving_row = 0
      column = tableau(:, entering)
      threshold = pivot_threshold*n*epsilon(1.0_dp)*maxval(abs(column))
      candidate = column > threshold
      if (.not. any(candidate)) return
      where (candidate)
         ratio = tableau(:, 2*n + 2)/column
      elsewhere
         ratio = huge(1.0_dp)
      end where
      ! Basic variables are >= 0 in exact arithmetic; a round-off negative counts as 0.
      ratio = max(ratio, 0.0_dp)
      smallest = minval(ratio, mask=candidate)
      tie = tie_threshold*n*epsilon(1.0_dp)*max(z_unit, smallest)
      candidate = candidate .and. ratio <= smallest + tie
      do i = 1, n
         if (candidate(i) .and. basis(i) == 2*n + 1) then
            leaving_row = i
            return
         end if
      end do
      ! Lexicographic rule on the rows of B^-1 / pivot entry, column by column.
      do k = 1, n
         if (count(candidate) == 1) exit
         where (candidate)
            ratio = tableau(:, k)/column
         end where
         smallest = minval(ratio, mask=candidate)
         tie = tie_threshold*n*epsilon(1.0_dp)*max(1.0_dp, maxval(abs(ratio), mask=candidate))
         candidate = candidate .and. ratio <= smallest + tie
      end do
      leaving_row = findloc(candidate, .true., dim=1)
   end function ratio_test

   !> The solution of the final complementary basis recomputed from the original data:
   !! B x_B = q with B's columns e_j (w_j basic) or -M(:, j) (z_j basic), by dgesv; then
   !! the check of z >= 0, w >= 0 (round-off negatives within the tolerance set to 0) and
   !! w = M z + q with w_i = 0 where z_i is basic.
   subroutine basis_solution(m, q, basis, check_tolerance, z, w, stat, errmsg)
      real(dp), intent(in) :: m(:, :), q(:), check_tolerance
      integer, intent(in) :: basis(:)
      real(dp), intent(out) :: z(:), w(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: basis_matrix(size(q), size(q)), values(size(q), 1), scale, violation
      integer :: pivot_order(size(q)), n, row, variable, info
      character(len=buffer_length) :: message
      n = size(q)
      stat = 0
      z = 0.0_dp
      w = 0.0_dp
      basis_matrix = 0.0_dp
      do row = 1, n
         variable = basis(row)
         if (variable <= n) then
            basis_matrix(variable, row) = 1.0_dp
         else
            basis_matrix(:, row) = -m(:, variable - n)
         end if
      end do
      values(:, 1) = q
      call dgesv(n, 1, basis_matrix, n, pivot_order, values, n, info)
      if (info /= 0) then
         write (message, '(a, i0, a)') 'solve_lemke: the final basis matrix is singular (dgesv info ', info, ').'
         call fail(stat_linear_solver_failure, message, stat, errmsg)
         return
      end if
      do row = 1, n
         variable = basis(row)
         if (variable > n) z(variable - n) = values(row, 1)
      end do
      scale = max(maxval(abs(q)), maxval(sum(abs(m), dim=2))*maxval(abs(z)))
      violation = max(0.0_dp, -minval(z)*maxval(sum(abs(m), dim=2)))
      z = max(z, 0.0_dp)
      w = matmul(m, z) + q
      do row = 1, n
         if (basis(row) > n) w(basis(row) - n) = 0.0_dp
      end do
      violation = max(violation, -minval(w))
      w = max(w, 0.0_dp)
      if (violation > check_tolerance*scale) then
         write (message, '(a, es10.3, a, es10.3, a, i0, a)') 'solve_lemke: the solution of the final basis '// &
            'violates z >= 0 or w >= 0 by ', violation/scale, ' (relative), above the tolerance ', &
            check_tolerance, ' (n = ', n, '; the basis is too ill-conditioned).'
         call fail(stat_residual_check_failed, message, stat, errmsg)
      end if
   end subroutine basis_solution


end module vibrobeam_lemke
