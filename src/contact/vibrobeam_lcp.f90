!> Dense linear complementarity problems LCP(A, q) with a symmetric positive definite A.
!!
!! Find z such that
!!
!!     w = A z + q,   z >= 0,   w >= 0,   z_i w_i = 0  (i = 1..n).
!!
!! In vibrobeam A is the Delassus matrix H_I W^-1 H_I^T of the contact projection
!! (theory §3, step 3), symmetric positive definite and small (n = number of active contact
!! points). For such a matrix (a P-matrix) the LCP has exactly one solution.
!!
!! Method: block principal pivoting in the form of Júdice & Pires ("A block principal
!! pivoting algorithm for large-scale strictly monotone linear complementarity problems",
!! Comput. Oper. Res. 21, 1994), with Murty's least-index single principal pivot as the
!! safeguard (K. G. Murty, Opsearch 11, 1974, 123-130; Cottle, Pang & Stone, *The Linear
!! Complementarity Problem*, 1992, ch. 4). A trial set I (the indices with z_i basic)
!! defines the complementary solution
!!
!!     A_II z_I = -q_I,   z_J = 0,   w_J = A_JI z_I + q_J,   w_I = 0     (J = complement of I)
!!
!! computed with a Cholesky factorization of A_II (LAPACK dpotrf/dpotrs). The iteration
!! starts from I = {i : q_i < 0} and exchanges indices between I and J until the trial
!! solution is feasible (z_I >= 0, w_J >= 0).
!!
!! Termination: every infeasible index is exchanged at once (block pivot) while the number
!! of infeasibilities keeps reaching new minima; when it has failed to do so for
!! `block_pivot_tries` consecutive block pivots, only the smallest infeasible index is
!! exchanged (Murty's rule) until a new minimum is reached. New minima can occur at most n
!! times, so after finitely many block pivots only Murty pivots remain, and Murty's rule
!! terminates finitely for every P-matrix from any starting set. In exact arithmetic the
!! method therefore ends after finitely many (in the worst case about 2^n) pivots; the
!! iteration limit below only guards against round-off pathologies.
module vibrobeam_lcp
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: fail => set_failure, stat_invalid_argument, stat_no_convergence, &
      stat_residual_check_failed, stat_linear_solver_failure
   use vibrobeam_lapack, only: dpotrf, dpotrs
   implicit none
   private
   public :: solve_lcp, lcp_residual

   !> Consecutive block pivots without a new minimum of the number of infeasible indices
   !! before falling back to single (Murty) pivots. Júdice & Pires suggest a small
   !! number; 3 keeps the fast block steps for well-behaved problems.
   integer, parameter :: block_pivot_tries = 3

   !> Default relative tolerance of the final residual check (see `lcp_residual`).
   real(dp), parameter :: default_tolerance = 1.0e-10_dp

   !> Length of the local message buffer; `errmsg` receives it truncated to its length.
   integer, parameter :: buffer_length = 512


contains

   !> Solve LCP(A, q) for a symmetric positive definite A by block principal pivoting
   !! with Murty's least-index fallback (see the module documentation).
   !!
   !! Status codes (vibrobeam_status; `errmsg` is empty when `stat` = 0, otherwise one sentence):
   !!
   !! * stat_ok (0): converged; z >= 0 and w >= 0 hold exactly, z_i w_i = 0 exactly (w_i = 0 on the
   !!   final set I, z_i = 0 off it), and `lcp_residual(a, q, z) <= tolerance`.
   !! * stat_no_convergence: no feasible set within `max_iterations` pivots; z, w hold the last trial
   !!   solution (not feasible).
   !! * stat_linear_solver_failure: the Cholesky factorization of a principal submatrix A_II failed (A is not
   !!   numerically positive definite) or LAPACK reported an argument error; z = w = 0.
   !! * stat_residual_check_failed: a feasible set was found but the residual check failed (round-off dominates,
   !!   e.g. A far too ill-conditioned for `tolerance`); z, w hold that solution.
   !! * stat_invalid_argument: invalid arguments: inconsistent sizes, `max_iterations` < 0, `tolerance` not a
   !!   positive finite number, or a non-finite entry in a or q; z = w = 0.
   !!
   !! Feasibility test of a trial solution: index i is infeasible when
   !! |A|_inf z_i < -f s (i in I) or w_i < -f s (i in J), with
   !! s = max(|q|_inf, |A|_inf |z|_inf) the scale of w and
   !! f = max(tolerance/100, 16 n eps). The slack keeps degenerate indices
   !! (q_i = 0, z_i = w_i = 0) from being exchanged back and forth because of round-off;
   !! it is 100 times below the residual tolerance, so clipping the accepted tiny
   !! negatives to zero (which moves w by at most f s) keeps the residual well inside it.
   subroutine solve_lcp(a, q, z, w, iterations, stat, errmsg, max_iterations, tolerance)
      real(dp), intent(in) :: a(:, :)   !! (n, n) symmetric positive definite matrix
      real(dp), intent(in) :: q(:)      !! (n) constant vector
      real(dp), intent(out) :: z(:)     !! (n) solution z >= 0
      real(dp), intent(out) :: w(:)     !! (n) w = A z + q >= 0, complementary to z
      integer, intent(out) :: iterations  !! pivoting iterations (changes of the set I) performed
      !> 0 ok, 1 no convergence, 2 factorization failure, 3 residual check failed,
      !! 4 invalid arguments (see above)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg  !! empty when stat = 0, else one sentence
      !> Largest number of pivots; default max(100, n^2). The method is finite, but its
      !! worst case (Murty's rule) is about 2^n pivots, so the limit only bounds the work
      !! when round-off disturbs the exact-arithmetic argument. Measured on random SPD A,
      !! n = 20..100: at most 5 pivots for kappa(A) = 1e2; for kappa(A) = 1e8 a mean of
      !! 15-45 and a worst case of about 5n. 0 is allowed (only the starting set is tried).
      integer, intent(in), optional :: max_iterations
      !> Relative tolerance of the final residual check `lcp_residual(a, q, z) <= tolerance`
      !! (violations measured in units of w and divided by max(|q|_inf, |A|_inf |z|_inf)).
      !! Default 1e-10.
      real(dp), intent(in), optional :: tolerance

      logical, allocatable :: in_set(:)       ! .true. for i in I (z_i basic, w_i = 0)
      integer :: iteration_limit
      real(dp) :: residual_tolerance

      z = 0.0_dp
      w = 0.0_dp
      iterations = 0
      errmsg = ''
      call check_arguments(a, q, z, w, iteration_limit, residual_tolerance, stat, errmsg, max_iterations, tolerance)
      if (stat /= 0 .or. size(q) == 0) return
      call pivot(a, q, iteration_limit, residual_tolerance, in_set, z, w, iterations, stat, errmsg)
      if (stat /= 0) return
      call accept_solution(a, q, in_set, residual_tolerance, z, w, stat, errmsg)
   end subroutine solve_lcp

   !> The argument checks of `solve_lcp` (stat_invalid_argument) and the limits it uses:
   !! `iteration_limit` (max_iterations, default max(100, n^2)) and `residual_tolerance`
   !! (tolerance, default 1e-10).
   subroutine check_arguments(a, q, z, w, iteration_limit, residual_tolerance, stat, errmsg, max_iterations, tolerance)
      real(dp), intent(in) :: a(:, :), q(:), z(:), w(:)
      integer, intent(out) :: iteration_limit
      real(dp), intent(out) :: residual_tolerance
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer, intent(in), optional :: max_iterations
      real(dp), intent(in), optional :: tolerance
      character(len=buffer_length) :: message
      integer :: n
      n = size(q)
      stat = 0
      iteration_limit = max(100, n*n)
      residual_tolerance = default_tolerance
      if (size(a, 1) /= n .or. size(a, 2) /= n .or. size(z) /= n .or. size(w) /= n) then
         write (message, '(a, 5(i0, a))') 'solve_lcp: inconsistent sizes: a is ', size(a, 1), &
            ' x ', size(a, 2), ', q has ', n, ', z has ', size(z), ', w has ', size(w), ' entries.'
         call fail(stat_invalid_argument, message, stat, errmsg)
         return
      end if
      if (present(max_iterations)) then
         if (max_iterations < 0) then
            write (message, '(a, i0, a)') 'solve_lcp: max_iterations = ', max_iterations, &
               ' is negative.'
            call fail(stat_invalid_argument, message, stat, errmsg)
            return
         end if
         iteration_limit = max_iterations
      end if
      if (present(tolerance)) then
         if (.not. ieee_is_finite(tolerance)) then
            call fail(stat_invalid_argument, 'solve_lcp: tolerance is not a finite number.', stat, errmsg)
            return
         end if
         if (tolerance <= 0.0_dp) then
            write (message, '(a, es10.3, a)') 'solve_lcp: tolerance = ', tolerance, &
               ' is not positive.'
            call fail(stat_invalid_argument, message, stat, errmsg)
            return
         end if
         residual_tolerance = tolerance
      end if
      if (.not. (all(ieee_is_finite(a)) .and. all(ieee_is_finite(q)))) then
         call fail(stat_invalid_argument, 'solve_lcp: a or q has a NaN or infinite entry.', stat, errmsg)
         return
      end if
   end subroutine check_arguments

   !> The pivoting of `solve_lcp` (module documentation) from I = {i : q_i < 0} until the
   !! trial solution (z, w) of the set `in_set` is feasible; stat_no_convergence after
   !! `iteration_limit` pivots, stat_linear_solver_failure (z = w = 0) when a trial set
   !! cannot be solved.
   subroutine pivot(a, q, iteration_limit, residual_tolerance, in_set, z, w, iterations, stat, errmsg)
      real(dp), intent(in) :: a(:, :), q(:)
      integer, intent(in) :: iteration_limit
      real(dp), intent(in) :: residual_tolerance
      logical, allocatable, intent(out) :: in_set(:)
      real(dp), intent(out) :: z(:), w(:)
      integer, intent(inout) :: iterations
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      logical :: infeasible(size(q))   ! indices violating z_I >= 0 or w_J >= 0
      integer :: n, n_infeasible, fewest_infeasible, block_tries_left, index
      real(dp) :: feasibility_tolerance, a_norm, w_scale
      character(len=buffer_length) :: message
      n = size(q)
      feasibility_tolerance = max(0.01_dp*residual_tolerance, 16.0_dp*real(n, dp)*epsilon(1.0_dp))
      a_norm = maxval(sum(abs(a), dim=2))   ! |A|_inf, converts z into the units of w

      ! Júdice & Pires: start from I = {i : q_i < 0}. If q >= 0 this set is empty and
      ! z = 0, w = q is the solution after zero pivots.
      in_set = q < 0.0_dp
      fewest_infeasible = n + 1
      block_tries_left = block_pivot_tries
      do
         call complementary_solution(a, q, in_set, z, w, stat, errmsg)
         if (stat /= 0) then
            z = 0.0_dp
            w = 0.0_dp
            return
         end if

         ! Scale of w (no tiny floor: it is only multiplied, and 0 is a valid scale when
         ! q = 0, z = 0).
         w_scale = max(maxval(abs(q)), a_norm*maxval(abs(z)))
         infeasible = (in_set .and. a_norm*z < -feasibility_tolerance*w_scale) .or. &
                      (.not. in_set .and. w < -feasibility_tolerance*w_scale)
         n_infeasible = count(infeasible)
         if (n_infeasible == 0) exit

         if (iterations >= iteration_limit) then
            write (message, '(a, i0, a, i0, a)') &
               'solve_lcp: no feasible complementary set after ', iterations, &
               ' pivots (the iteration limit); ', n_infeasible, ' indices still infeasible.'
            call fail(stat_no_convergence, message, stat, errmsg)
            return
         end if

         if (n_infeasible < fewest_infeasible) then
            ! New minimum: block pivot, and restart the counter of unsuccessful block pivots.
            fewest_infeasible = n_infeasible
            block_tries_left = block_pivot_tries
            in_set = in_set .neqv. infeasible
         else if (block_tries_left > 0) then
            ! No new minimum yet: still exchange all infeasible indices, but count it.
            block_tries_left = block_tries_left - 1
            in_set = in_set .neqv. infeasible
         else
            ! Safeguard: Murty's least-index principal pivot (finite for P-matrices).
            index = findloc(infeasible, .true., dim=1)
            in_set(index) = .not. in_set(index)
         end if
         iterations = iterations + 1
      end do
   end subroutine pivot

   !> The accepted set: clip the round-off negatives allowed by the feasibility test, then
   !! make w consistent with the clipped z (w_I = 0 exactly, w_J = A_J z + q_J >= 0), and
   !! check the residual (stat_residual_check_failed).
   subroutine accept_solution(a, q, in_set, residual_tolerance, z, w, stat, errmsg)
      real(dp), intent(in) :: a(:, :), q(:), residual_tolerance
      logical, intent(in) :: in_set(:)
      real(dp), intent(inout) :: z(:), w(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: residual
      character(len=buffer_length) :: message
      stat = 0
      z = max(z, 0.0_dp)
      w = matmul(a, z) + q
      where (in_set) w = 0.0_dp
      w = max(w, 0.0_dp)

      residual = lcp_residual(a, q, z)
      if (residual > residual_tolerance) then
         write (message, '(a, es10.3, a, es10.3, a, i0, a)') 'solve_lcp: residual ', residual, &
            ' of the computed solution exceeds the tolerance ', residual_tolerance, &
            ' (n = ', size(q), '; A may be too ill-conditioned).'
         call fail(stat_residual_check_failed, message, stat, errmsg)
      end if
   end subroutine accept_solution

   !> Normalized violation of the LCP conditions by z, with w = A z + q recomputed:
   !!
   !!     res = max_i max( -|A|_inf z_i, -w_i, min(|A|_inf z_i^+, w_i^+), 0 ) / s,
   !!     s   = max( |q|_inf, |A|_inf |z|_inf, tiny(1.0_dp) ),
   !!
   !! i.e. the largest violation of z >= 0, of w >= 0 and of z_i w_i = 0, all in the units
   !! of w (|A|_inf converts z), relative to the scale s of w. The complementarity term
   !! min(|A| z_i^+, w_i^+) vanishes exactly when z_i w_i = 0 and, unlike the product
   !! z_i w_i, is invariant under scaling of A and q. Zero for n = 0. Sizes must agree
   !! (a: n x n, q and z: n); this is not checked.
   pure function lcp_residual(a, q, z) result(res)
      real(dp), intent(in) :: a(:, :)  !! (n, n) LCP matrix
      real(dp), intent(in) :: q(:)     !! (n) LCP vector
      real(dp), intent(in) :: z(:)     !! (n) candidate solution
      real(dp) :: res                  !! normalized largest violation (dimensionless)

      real(dp) :: w(size(q))
      real(dp) :: a_norm, w_scale, violation

      res = 0.0_dp
      if (size(q) == 0) return
      a_norm = maxval(sum(abs(a), dim=2))
      w = matmul(a, z) + q
      w_scale = max(maxval(abs(q)), a_norm*maxval(abs(z)), tiny(1.0_dp))
      violation = max(0.0_dp, maxval(-a_norm*z), maxval(-w), &
                      maxval(min(a_norm*max(z, 0.0_dp), max(w, 0.0_dp))))
      res = violation/w_scale
   end function lcp_residual

   !> Complementary solution of the trial set I (Júdice & Pires, step 1):
   !! A_II z_I = -q_I by Cholesky (dpotrf/dpotrs, lower triangle of A_II), z_J = 0,
   !! w = A z + q with w_I = 0 exactly. stat = stat_linear_solver_failure if the factorization or solve fails.
   subroutine complementary_solution(a, q, in_set, z, w, stat, errmsg)
      real(dp), intent(in) :: a(:, :), q(:)
      logical, intent(in) :: in_set(:)
      real(dp), intent(out) :: z(:), w(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg

      real(dp), allocatable :: submatrix(:, :), rhs(:, :)
      integer, allocatable :: set_index(:)
      integer :: n, m, i, j, info
      character(len=buffer_length) :: message

      stat = 0
      n = size(q)
      m = count(in_set)
      z = 0.0_dp
      if (m > 0) then
         set_index = pack([(i, i=1, n)], in_set)
         allocate (submatrix(m, m), rhs(m, 1))
         do j = 1, m
            do i = 1, m
               submatrix(i, j) = a(set_index(i), set_index(j))
            end do
            rhs(j, 1) = -q(set_index(j))
         end do
         call dpotrf('L', m, submatrix, m, info)
         if (info > 0) then
            write (message, '(a, i0, a, i0, a)') &
               'solve_lcp: the principal submatrix of A on a trial set of ', m, &
               ' indices is not positive definite (dpotrf: leading minor ', info, &
               ' not positive); A must be symmetric positive definite.'
            call fail(stat_linear_solver_failure, message, stat, errmsg)
            return
         else if (info < 0) then
            write (message, '(a, i0, a)') 'solve_lcp: LAPACK dpotrf rejected argument ', -info, '.'
            call fail(stat_linear_solver_failure, message, stat, errmsg)
            return
         end if
         call dpotrs('L', m, 1, submatrix, m, rhs, m, info)
         if (info /= 0) then
            write (message, '(a, i0, a)') 'solve_lcp: LAPACK dpotrs rejected argument ', -info, '.'
            call fail(stat_linear_solver_failure, message, stat, errmsg)
            return
         end if
         z(set_index) = rhs(:, 1)
      end if
      w = matmul(a, z) + q
      where (in_set) w = 0.0_dp
   end subroutine complementary_solution


end module vibrobeam_lcp
