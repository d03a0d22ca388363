!> Unit test of `vibrobeam_lcp` (theory §3, step 3: the contact LCP with an SPD Delassus
!! matrix).
!!
!! Reference: brute-force enumeration of all 2^n complementary index sets I. For each I the
!! test solves A_II z_I = -q_I with LAPACK dgesv (LU with partial pivoting, deliberately not
!! the solver's Cholesky path), sets z_J = 0, w = A z + q, w_I = 0, and keeps the set with
!! the smallest violation of z_I >= 0, w_J >= 0. For a symmetric positive definite A the LCP
!! has exactly one solution, so the enumeration finds it. Closed forms are used on top of
!! the enumeration where they exist (diagonal A, q >= 0, a solution built from z*, w*).
!!
!! Matrices and vectors come from a fixed Park-Miller generator, so every run checks the
!! same problems. Failed checks are written to stderr (case, n, quantity, value, reference,
!! tolerance); the program ends with "test_lcp: N passed, M failed" and `error stop 1` when
!! any check failed.
program test_lcp
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_kinds, only: dp, int64, error_unit, output_unit
   use vibrobeam_lapack, only: dgeqrf, dgesv, dorgqr, dsyev
   use vibrobeam_lcp, only: solve_lcp, lcp_residual
   use vibrobeam_test_support, only: use_program_blas_threads
   use vibrobeam_status, only: stat_no_convergence, stat_linear_solver_failure, stat_residual_check_failed, &
                               stat_invalid_argument
   implicit none

   !> Counts of passed and failed checks.
   type :: check_tally
      integer :: passed = 0
      integer :: failed = 0
   end type check_tally

   !> Worst measured values over a group of cases, printed when the group is done.
   type :: group_record
      character(len=32) :: name = ''
      integer :: cases = 0
      real(dp) :: max_condition = 0.0_dp       ! largest 2-norm condition number of A
      real(dp) :: max_z_error = 0.0_dp         ! max |z - z_ref| / max(z_floor, |z_ref|_inf)
      real(dp) :: max_z_tolerance = 0.0_dp     ! largest tolerance applied to that quantity
      real(dp) :: max_w_error = 0.0_dp         ! max |w - w_ref| / scale of w
      real(dp) :: max_residual = 0.0_dp        ! lcp_residual of the solver's z
      integer :: max_iterations = 0
   end type group_record


   !> Default tolerance of solve_lcp's residual check, and the relative z tolerance for
   !! well-conditioned problems.
   real(dp), parameter :: base_tolerance = 1.0e-10_dp
   !> A brute-force set is accepted as the reference if its normalized violation is below this.
   real(dp), parameter :: reference_acceptance = 1.0e-8_dp
   integer, parameter :: random_q_per_size = 20

   type(check_tally) :: tally
   type(group_record) :: group
   integer(int64) :: rng_state
   real(dp), allocatable :: a(:, :), q(:), z_star(:), w_star(:)
   integer :: n, k, i
   real(dp) :: scale_a, scale_q
   integer(int64) :: clock_start, clock_end, clock_rate

   call use_program_blas_threads()
   call system_clock(clock_start, clock_rate)
   rng_state = 20240607_int64

   ! --- empty problem ------------------------------------------------------------------
   call check_empty_problem(tally)

   ! --- lcp_residual on hand-computed values -------------------------------------------
   call check_residual_function(tally)

   ! --- status paths -------------------------------------------------------------------
   call check_status_paths(rng_state, tally)

   ! --- random SPD A = B^T B + delta I, q uniform in (-1, 1) ----------------------------
   call start_group('random_spd', group)
   do n = 1, 12
      do k = 1, random_q_per_size
         a = random_spd(n, 0.5_dp, rng_state)
         q = random_vector(n, -1.0_dp, 1.0_dp, rng_state)
         call run_case('random_spd', a, q, 1.0_dp, group, tally)
      end do
   end do
   call print_group(group)

   ! --- the same, with A and q scaled by independent powers of ten ----------------------
   ! z is measured relative to its own natural scale |q|_inf/|A|_inf, not to 1.
   call start_group('random_spd_scaled', group)
   do n = 1, 12
      do k = 1, 5
         scale_a = 10.0_dp**nint(uniform(rng_state, -6.0_dp, 6.0_dp))
         scale_q = 10.0_dp**nint(uniform(rng_state, -6.0_dp, 6.0_dp))
         a = scale_a*random_spd(n, 0.5_dp, rng_state)
         q = scale_q*random_vector(n, -1.0_dp, 1.0_dp, rng_state)
         call run_case('random_spd_scaled', a, q, maxval(abs(q))/infinity_norm(a), group, tally)
      end do
   end do
   call print_group(group)

   ! --- ill-conditioned: A = Q diag(1, ..., 1e-8) Q^T, spectrum geometric ---------------
   ! These cases also drive the block pivots into cycling, so they exercise the fallback to
   ! Murty's rule (up to ~30 pivots for n = 12; pure block pivoting fails on some of them).
   call start_group('ill_conditioned_1e8', group)
   do n = 4, 12, 4
      do k = 1, 10
         a = spd_with_spectrum(n, 1.0e8_dp, rng_state)
         q = random_vector(n, -1.0_dp, 1.0_dp, rng_state)
         call run_case('ill_conditioned_1e8', a, q, 1.0_dp, group, tally)
      end do
   end do
   call print_group(group)

   ! --- nearly singular: A = G G^T + delta I with rows of G repeated and scaled ----------
   ! (a contact matrix H with proportional rows gives a singular Delassus matrix; delta
   ! restores definiteness, condition number ~1e6-1e7)
   call start_group('repeated_rows', group)
   do n = 4, 12, 4
      do k = 1, 10
         a = spd_with_repeated_rows(n, 1.0e-6_dp, rng_state)
         q = random_vector(n, -1.0_dp, 1.0_dp, rng_state)
         call run_case('repeated_rows', a, q, 1.0_dp, group, tally)
      end do
   end do
   call print_group(group)

   ! --- q with exact zero entries (degenerate candidates z_i = w_i = 0) ------------------
   call start_group('q_exact_zeros', group)
   do n = 2, 12
      do k = 1, 10
         a = random_spd(n, 0.5_dp, rng_state)
         q = random_vector(n, -1.0_dp, 1.0_dp, rng_state)
         do i = 1, n
            if (uniform(rng_state, 0.0_dp, 1.0_dp) < 0.4_dp) q(i) = 0.0_dp
         end do
         call run_case('q_exact_zeros', a, q, 1.0_dp, group, tally)
      end do
   end do
   call print_group(group)

   ! --- q = 0: z = 0 exactly after zero pivots ----------------------------------------
   call start_group('q_zero', group)
   do n = 1, 12
      a = random_spd(n, 0.5_dp, rng_state)
      q = [(0.0_dp, i=1, n)]
      call run_case('q_zero', a, q, 1.0_dp, group, tally, trivial=.true.)
   end do
   call print_group(group)

   ! --- all q > 0: z = 0, w = q exactly after zero pivots --------------------------------
   call start_group('q_positive', group)
   do n = 1, 12
      do k = 1, 3
         a = random_spd(n, 0.5_dp, rng_state)
         q = random_vector(n, 0.01_dp, 1.0_dp, rng_state)
         call run_case('q_positive', a, q, 1.0_dp, group, tally, trivial=.true.)
      end do
   end do
   call print_group(group)

   ! --- all q < 0 -------------------------------------------------------------------------
   call start_group('q_negative', group)
   do n = 1, 12
      do k = 1, 5
         a = random_spd(n, 0.5_dp, rng_state)
         q = random_vector(n, -1.0_dp, -0.01_dp, rng_state)
         call run_case('q_negative', a, q, 1.0_dp, group, tally)
      end do
   end do
   call print_group(group)

   ! --- diagonal A (entries 1e-3..1e3): closed form z_i = max(0, -q_i/a_ii); q has exact
   ! zeros too, which makes those indices doubly degenerate (z_i = w_i = 0) -----------------
   call start_group('diagonal', group)
   do n = 1, 12
      do k = 1, 5
         a = diagonal_matrix(10.0_dp**random_vector(n, -3.0_dp, 3.0_dp, rng_state))
         q = random_vector(n, -1.0_dp, 1.0_dp, rng_state)
         do i = 1, n
            if (uniform(rng_state, 0.0_dp, 1.0_dp) < 0.3_dp) q(i) = 0.0_dp
         end do
         z_star = [(max(0.0_dp, -q(i)/a(i, i)), i=1, n)]
         ! kappa(A) reaches ~1e6 here, but each z_i is one division: z_star rounds once, the
         ! solver's Cholesky of a diagonal block at most 7 times (a square root, possibly its
         ! reciprocal, two divisions or products, the sign)
         call run_case('diagonal', a, q, 1.0_dp, group, tally, z_expected=z_star, &
                       z_tolerance=gamma_n(8))
      end do
   end do
   call print_group(group)

   ! --- built from a known solution with doubly degenerate indices ------------------------
   ! z* >= 0 and w* >= 0 with z*_i w*_i = 0 and both zero on about a quarter of the
   ! indices; q = w* - A z*. Up to the rounding of q, z* is the solution.
   call start_group('constructed_degenerate', group)
   do n = 3, 12
      do k = 1, 5
         a = random_spd(n, 0.5_dp, rng_state)
         z_star = [(0.0_dp, i=1, n)]
         w_star = z_star
         do i = 1, n
            select case (int(uniform(rng_state, 0.0_dp, 4.0_dp)))
            case (0)
               continue                     ! z*_i = w*_i = 0
            case (1)
               z_star(i) = uniform(rng_state, 0.1_dp, 1.0_dp)
            case default
               w_star(i) = uniform(rng_state, 0.1_dp, 1.0_dp)
            end select
         end do
         q = w_star - matmul(a, z_star)
         call run_case('constructed_degenerate', a, q, 1.0_dp, group, tally, z_expected=z_star)
      end do
   end do
   call print_group(group)

   call system_clock(clock_end)
   write (output_unit, '(a, f8.3, a)') 'test_lcp: wall time ', &
      real(clock_end - clock_start, dp)/real(clock_rate, dp), ' s'
   write (output_unit, '(a, i0, a, i0, a)') 'test_lcp: ', tally%passed, ' passed, ', &
      tally%failed, ' failed'
   if (tally%failed > 0) error stop 1

contains

   ! ===================================================================================
   ! Checks
   ! ===================================================================================

   !> Solve one LCP, compare with the brute-force reference (and `z_expected` if given),
   !! and check the invariants the solver documents for stat = 0.
   !!
   !! Tolerances. A backward-stable solve of A_II z_I = -q_I has a forward error of about
   !! c m kappa(A_II) eps |z|; kappa(A_II) <= kappa(A) by eigenvalue interlacing; the solver
   !! (Cholesky) and the reference (LU) each carry such an error. Hence for z
   !!     tol_z = 10 n kappa(A) eps   relative to max(z_floor, |z_ref|_inf),
   !! about 2.7e-6 for kappa = 1e8, n = 12. w = A z + q is better determined: an error
   !! dz_I with A_II dz_I = r gives |A_JI dz_I| <= |r| sqrt(|A|_2 / lambda_min(A_II))
   !! (A is SPD), so
   !!     tol_w = 10 n sqrt(kappa(A)) eps   relative to max(|q|_inf, |A|_inf |z|_inf).
   subroutine run_case(case_name, a, q, z_floor, group, tally, z_expected, trivial, z_tolerance)
      character(len=*), intent(in) :: case_name
      real(dp), intent(in) :: a(:, :), q(:)
      real(dp), intent(in) :: z_floor                 !! absolute floor of the z scale
      type(group_record), intent(inout) :: group
      type(check_tally), intent(inout) :: tally
      real(dp), intent(in), optional :: z_expected(:) !! closed-form solution
      logical, intent(in), optional :: trivial        !! q >= 0: z = 0, w = q, zero pivots
      real(dp), intent(in), optional :: z_tolerance   !! replaces the kappa-based tol_z

      real(dp) :: z(size(q)), w(size(q)), z_ref(size(q)), w_ref(size(q)), w_recomputed(size(q))
      real(dp) :: condition, tol_z, tol_w, z_scale, w_scale, violation, residual, a_norm, slack, solve_residual
      integer :: n, iterations, stat, n_accepted, worst, iteration_limit
      character(len=512) :: errmsg

      n = size(q)
      group%cases = group%cases + 1
      call solve_lcp(a, q, z, w, iterations, stat, errmsg)

      call check_int(stat == 0, case_name, n, 'stat', stat, 0, '==', tally)
      if (stat /= 0) then
         write (error_unit, '(2a)') '    errmsg: ', trim(errmsg)
         return
      end if
      call check_int(len_trim(errmsg) == 0, case_name, n, 'len_trim(errmsg)', len_trim(errmsg), &
                     0, '==', tally)
      ! The documented default limit of solve_lcp.
      iteration_limit = max(100, n*n)
      call check_int(iterations <= iteration_limit, case_name, n, 'iterations', iterations, &
                     iteration_limit, '<=', tally)
      group%max_iterations = max(group%max_iterations, iterations)

      condition = condition_number(a)
      group%max_condition = max(group%max_condition, condition)
      tol_z = 10.0_dp*real(n, dp)*condition*epsilon(1.0_dp)
      tol_w = 10.0_dp*real(n, dp)*sqrt(condition)*epsilon(1.0_dp)
      ! what solve_lcp itself accepts: a pivoting solution whose z_I or w_J is negative by
      ! up to slack w_scale (then clipped to 0), slack = max(tolerance/100, 16 n eps); and
      ! on the held set I it returns w_I = 0 where A z + q is the residual of the Cholesky
      ! solve, |A_II z_I + q_I| <= gamma_{3n+1} |L||L^T||z| + gamma_{n+1}(|A||z| + |q|)
      ! <= (n gamma_{3n+1} + gamma_{n+1}) w_scale (|L||L^T| <= max a_ii entrywise for SPD A)
      slack = max(0.01_dp*base_tolerance, 16*real(n, dp)*epsilon(1.0_dp))
      solve_residual = n*gamma_n(3*n + 1) + gamma_n(n + 1)
      if (present(z_tolerance)) tol_z = z_tolerance
      group%max_z_tolerance = max(group%max_z_tolerance, tol_z)

      ! Exact sign and complementarity properties of the returned pair.
      call check_real(minval(z) >= 0.0_dp, case_name, n, 'min(z)', minval(z), 0.0_dp, 0.0_dp, tally)
      call check_real(minval(w) >= 0.0_dp, case_name, n, 'min(w)', minval(w), 0.0_dp, 0.0_dp, tally)
      call check_real(maxval(abs(z*w)) <= 0.0_dp, case_name, n, 'max|z_i w_i|', maxval(abs(z*w)), &
                      0.0_dp, 0.0_dp, tally)

      ! Returned w against A z + q recomputed here (independent residual).
      a_norm = infinity_norm(a)
      w_recomputed = product_plus(a, z, q)
      w_scale = max(maxval(abs(q)), a_norm*maxval(abs(z)))
      worst = maxloc(abs(w - w_recomputed), dim=1)
      ! off the held set both are A z + q, the returned one clipped at 0 (slack); on it the
      ! returned w_I = 0 and the recomputed one is the solve's residual (plus its own gamma_{n+1})
      call check_real(abs(w(worst) - w_recomputed(worst)) <= (max(slack, solve_residual) + gamma_n(n + 1))*w_scale, &
                      case_name, n, 'w(i) against (A z + q)(i)', w(worst), w_recomputed(worst), &
                      (max(slack, solve_residual) + gamma_n(n + 1))*w_scale, tally)
      residual = lcp_residual(a, q, z)
      group%max_residual = max(group%max_residual, residual)
      ! the residual (w recomputed) is below what the solver accepts and its solve's residual
      call check_real(residual <= max(slack, solve_residual) + gamma_n(n + 1), case_name, n, 'lcp_residual', residual, &
                      0.0_dp, max(slack, solve_residual) + gamma_n(n + 1), tally)

      if (present(trivial)) then
         if (trivial) then
            call check_int(iterations == 0, case_name, n, 'iterations', iterations, 0, '==', tally)
            call check_real(maxval(abs(z)) <= 0.0_dp, case_name, n, 'max|z|', maxval(abs(z)), &
                            0.0_dp, 0.0_dp, tally)
            call check_real(maxval(abs(w - q)) <= 0.0_dp, case_name, n, 'max|w - q|', &
                            maxval(abs(w - q)), 0.0_dp, 0.0_dp, tally)
         end if
      end if

      ! Brute-force reference.
      call brute_force(a, q, z_ref, w_ref, violation, n_accepted)
      call check_real(violation <= reference_acceptance, case_name, n, &
                      'violation of the brute-force reference', violation, 0.0_dp, &
                      reference_acceptance, tally)
      z_scale = max(z_floor, maxval(abs(z_ref)))
      worst = maxloc(abs(z - z_ref), dim=1)
      group%max_z_error = max(group%max_z_error, abs(z(worst) - z_ref(worst))/z_scale)
      call check_real(abs(z(worst) - z_ref(worst)) <= tol_z*z_scale, case_name, n, &
                      'z(i) against brute force', z(worst), z_ref(worst), tol_z*z_scale, tally)
      w_scale = max(maxval(abs(q)), a_norm*maxval(abs(z_ref)))
      worst = maxloc(abs(w - w_ref), dim=1)
      ! (w_scale = 0 only for q = 0, where w and w_ref must both be exactly 0)
      if (w_scale > 0.0_dp) then
         group%max_w_error = max(group%max_w_error, abs(w(worst) - w_ref(worst))/w_scale)
      else
         group%max_w_error = max(group%max_w_error, abs(w(worst) - w_ref(worst)))
      end if
      call check_real(abs(w(worst) - w_ref(worst)) <= tol_w*w_scale, case_name, n, &
                      'w(i) against brute force', w(worst), w_ref(worst), tol_w*w_scale, tally)

      if (present(z_expected)) then
         worst = maxloc(abs(z - z_expected), dim=1)
         z_scale = max(z_floor, maxval(abs(z_expected)))
         group%max_z_error = max(group%max_z_error, abs(z(worst) - z_expected(worst))/z_scale)
         call check_real(abs(z(worst) - z_expected(worst)) <= tol_z*z_scale, case_name, n, &
                         'z(i) against closed form', z(worst), z_expected(worst), &
                         tol_z*z_scale, tally)
      end if
   end subroutine run_case

   !> n = 0: immediate return with stat = 0 and zero iterations.
   subroutine check_empty_problem(tally)
      type(check_tally), intent(inout) :: tally
      real(dp) :: a(0, 0), q(0), z(0), w(0)
      integer :: iterations, stat
      character(len=512) :: errmsg

      call solve_lcp(a, q, z, w, iterations, stat, errmsg)
      call check_int(stat == 0, 'empty', 0, 'stat', stat, 0, '==', tally)
      call check_int(iterations == 0, 'empty', 0, 'iterations', iterations, 0, '==', tally)
      call check_real(lcp_residual(a, q, z) <= 0.0_dp, 'empty', 0, 'lcp_residual', &
                      lcp_residual(a, q, z), 0.0_dp, 0.0_dp, tally)
   end subroutine check_empty_problem

   !> lcp_residual against values computed by hand from its documented normalization
   !! res = max(-|A| z_i, -w_i, min(|A| z_i^+, w_i^+), 0) / max(|q|, |A| |z|, tiny).
   subroutine check_residual_function(tally)
      type(check_tally), intent(inout) :: tally
      real(dp) :: a1(1, 1), a2(2, 2)

      a1 = 2.0_dp
      ! z = 1 solves 2 z - 2 = 0 exactly.
      call check_residual_value(a1, [-2.0_dp], [1.0_dp], 0.0_dp, 'exact solution', tally)
      ! z = 0.5: w = -1, scale max(2, 1) = 2 -> 0.5.
      call check_residual_value(a1, [-2.0_dp], [0.5_dp], 0.5_dp, 'w < 0', tally)
      ! z = -1: w = -4, -|A| z = 2, scale max(2, 2) = 2 -> 2.
      call check_residual_value(a1, [-2.0_dp], [-1.0_dp], 2.0_dp, 'z < 0', tally)
      ! A = I, q = (1, 1), z = (1, 0): w = (2, 1), z_1 w_1 /= 0, min(1, 2) = 1, scale 1 -> 1.
      a2 = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
      call check_residual_value(a2, [1.0_dp, 1.0_dp], [1.0_dp, 0.0_dp], 1.0_dp, 'z_i w_i > 0', &
                                tally)
   end subroutine check_residual_function

   subroutine check_residual_value(a, q, z, expected, label, tally)
      real(dp), intent(in) :: a(:, :), q(:), z(:), expected
      character(len=*), intent(in) :: label
      type(check_tally), intent(inout) :: tally
      real(dp), parameter :: tol = 1.0e-15_dp
      real(dp) :: residual
      residual = lcp_residual(a, q, z)
      call check_real(abs(residual - expected) <= tol, 'residual_function', size(q), &
                      'lcp_residual ('//label//')', residual, expected, tol, tally)
   end subroutine check_residual_value

   !> Every non-zero status of solve_lcp, and the optional arguments.
   subroutine check_status_paths(rng_state, tally)
      integer(int64), intent(inout) :: rng_state
      type(check_tally), intent(inout) :: tally
      real(dp) :: a2(2, 2), z2(2), w2(2), z3(3), residual
      real(dp), allocatable :: a(:, :), q(:), z(:), w(:)
      integer :: iterations, stat
      character(len=512) :: errmsg
      character(len=20) :: short_message

      ! A = [1 0.9; 0.9 1], q = (-1, -0.5): the start set I = {1, 2} gives z_2 < 0, one
      ! pivot to I = {1} gives z = (1, 0), w = (0, 0.4).
      a2 = reshape([1.0_dp, 0.9_dp, 0.9_dp, 1.0_dp], [2, 2])
      call solve_lcp(a2, [-1.0_dp, -0.5_dp], z2, w2, iterations, stat, errmsg, max_iterations=0)
      call check_int(stat == stat_no_convergence, 'max_iterations=0', 2, 'stat', stat, &
                     stat_no_convergence, '==', tally)
      call check_int(len_trim(errmsg) > 0, 'max_iterations=0', 2, 'len_trim(errmsg)', &
                     len_trim(errmsg), 0, '>', tally)
      call solve_lcp(a2, [-1.0_dp, -0.5_dp], z2, w2, iterations, stat, errmsg, max_iterations=1)
      call check_int(stat == 0, 'max_iterations=1', 2, 'stat', stat, 0, '==', tally)
      call check_int(iterations == 1, 'max_iterations=1', 2, 'iterations', iterations, 1, '==', &
                     tally)
      call check_real(abs(z2(1) - 1.0_dp) <= 1.0e-15_dp, 'max_iterations=1', 2, 'z(1)', z2(1), &
                      1.0_dp, 1.0e-15_dp, tally)
      call check_real(abs(z2(2)) <= 0.0_dp, 'max_iterations=1', 2, 'z(2)', z2(2), 0.0_dp, &
                      0.0_dp, tally)
      call check_real(abs(w2(2) - 0.4_dp) <= 1.0e-15_dp, 'max_iterations=1', 2, 'w(2)', w2(2), &
                      0.4_dp, 1.0e-15_dp, tally)

      ! A short errmsg is filled, truncated, without a runtime error.
      call solve_lcp(a2, [-1.0_dp, -0.5_dp], z2, w2, iterations, stat, short_message, &
                     max_iterations=0)
      call check_int(stat == stat_no_convergence, 'short errmsg', 2, 'stat', stat, &
                     stat_no_convergence, '==', tally)

      ! Indefinite A: the Cholesky factor of A_II fails -> stat_linear_solver_failure.
      a2 = reshape([1.0_dp, 2.0_dp, 2.0_dp, 1.0_dp], [2, 2])
      call solve_lcp(a2, [-1.0_dp, -1.0_dp], z2, w2, iterations, stat, errmsg)
      call check_int(stat == stat_linear_solver_failure, 'indefinite', 2, 'stat', stat, &
                     stat_linear_solver_failure, '==', tally)
      call check_int(len_trim(errmsg) > 0, 'indefinite', 2, 'len_trim(errmsg)', len_trim(errmsg), &
                     0, '>', tally)

      ! A tolerance below round-off makes the residual check fail -> stat_residual_check_failed.
      a = random_spd(8, 0.5_dp, rng_state)
      q = random_vector(8, -1.0_dp, 1.0_dp, rng_state)
      allocate (z(8), w(8))
      call solve_lcp(a, q, z, w, iterations, stat, errmsg)
      residual = lcp_residual(a, q, z)
      call check_real(residual > 0.0_dp, 'tight tolerance', 8, &
                      'lcp_residual (must be > 0 for this case to test stat_residual_check_failed)', residual, 0.0_dp, &
                      0.0_dp, tally)
      call solve_lcp(a, q, z, w, iterations, stat, errmsg, tolerance=0.5_dp*residual)
      call check_int(stat == stat_residual_check_failed, 'tight tolerance', 8, 'stat', stat, &
                     stat_residual_check_failed, '==', tally)
      call solve_lcp(a, q, z, w, iterations, stat, errmsg, tolerance=1.0e-6_dp)
      call check_int(stat == 0, 'loose tolerance', 8, 'stat', stat, 0, '==', tally)

      ! Invalid arguments -> stat_invalid_argument.
      call solve_lcp(a2, [-1.0_dp, -1.0_dp], z3, w2, iterations, stat, errmsg)
      call check_int(stat == stat_invalid_argument, 'size mismatch', 2, 'stat', stat, &
                     stat_invalid_argument, '==', tally)
      a2 = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
      call solve_lcp(a2, [-1.0_dp, -1.0_dp], z2, w2, iterations, stat, errmsg, max_iterations=-1)
      call check_int(stat == stat_invalid_argument, 'max_iterations=-1', 2, 'stat', stat, &
                     stat_invalid_argument, '==', tally)
      call solve_lcp(a2, [-1.0_dp, -1.0_dp], z2, w2, iterations, stat, errmsg, tolerance=0.0_dp)
      call check_int(stat == stat_invalid_argument, 'tolerance=0', 2, 'stat', stat, &
                     stat_invalid_argument, '==', tally)
   end subroutine check_status_paths

   !> Record a check on a real quantity; on failure write the case, the size, the quantity,
   !! its value, the reference and the tolerance to stderr.
   subroutine check_real(passed, case_name, n, quantity, value, reference, tolerance, tally)
      logical, intent(in) :: passed
      character(len=*), intent(in) :: case_name, quantity
      integer, intent(in) :: n
      real(dp), intent(in) :: value, reference, tolerance
      type(check_tally), intent(inout) :: tally
      if (passed) then
         tally%passed = tally%passed + 1
      else
         tally%failed = tally%failed + 1
         write (error_unit, '(3a, i0, 3a, es24.16, a, es24.16, a, es10.3)') 'FAIL ', case_name, &
            ' (n = ', n, '): ', quantity, ' = ', value, ', reference ', reference, &
            ', tolerance ', tolerance
      end if
   end subroutine check_real

   !> Record a check on an integer quantity (`relation` names the expected relation).
   subroutine check_int(passed, case_name, n, quantity, value, reference, relation, tally)
      logical, intent(in) :: passed
      character(len=*), intent(in) :: case_name, quantity, relation
      integer, intent(in) :: n, value, reference
      type(check_tally), intent(inout) :: tally
      if (passed) then
         tally%passed = tally%passed + 1
      else
         tally%failed = tally%failed + 1
         write (error_unit, '(3a, i0, 3a, i0, 3a, i0)') 'FAIL ', case_name, ' (n = ', n, &
            '): ', quantity, ' = ', value, ', expected ', relation, ' ', reference
      end if
   end subroutine check_int

   subroutine start_group(name, group)
      character(len=*), intent(in) :: name
      type(group_record), intent(out) :: group
      group%name = name
   end subroutine start_group

   subroutine print_group(group)
      type(group_record), intent(in) :: group
      write (output_unit, '(a, 1x, a, i4, 5(a, es9.2), a, i0)') &
         'group', group%name, group%cases, ' cases; cond <=', group%max_condition, &
         '; max|dz|/zscale', group%max_z_error, ' (tol <=', group%max_z_tolerance, &
         '); max|dw|/wscale', group%max_w_error, '; max residual', group%max_residual, &
         '; max iterations ', group%max_iterations
   end subroutine print_group

   ! ===================================================================================
   ! Reference solution
   ! ===================================================================================

   !> Enumerate all 2^n complementary sets I (bit i-1 of `mask` set <=> i in I), solve
   !! A_II z_I = -q_I with dgesv and keep the set with the smallest normalized violation
   !! max(-|A|_inf z_I, -w_J)^+ / max(|q|_inf, |A|_inf |z|_inf). `n_accepted` counts the
   !! sets within `reference_acceptance` (more than one only for degenerate problems,
   !! where they all give the same z).
   subroutine brute_force(a, q, z_ref, w_ref, best_violation, n_accepted)
      real(dp), intent(in) :: a(:, :), q(:)
      real(dp), intent(out) :: z_ref(:), w_ref(:)
      real(dp), intent(out) :: best_violation
      integer, intent(out) :: n_accepted

      real(dp) :: submatrix(size(q), size(q)), rhs(size(q), 1), z(size(q)), w(size(q))
      integer :: set_index(size(q)), pivots(size(q))
      integer :: n, m, mask, i, j, info
      real(dp) :: a_norm, w_scale, violation

      n = size(q)
      a_norm = infinity_norm(a)
      best_violation = huge(1.0_dp)
      n_accepted = 0
      z_ref = 0.0_dp
      w_ref = 0.0_dp
      do mask = 0, 2**n - 1
         m = 0
         do i = 1, n
            if (btest(mask, i - 1)) then
               m = m + 1
               set_index(m) = i
            end if
         end do
         z = 0.0_dp
         if (m > 0) then
            do j = 1, m
               do i = 1, m
                  submatrix(i, j) = a(set_index(i), set_index(j))
               end do
               rhs(j, 1) = -q(set_index(j))
            end do
            call dgesv(m, 1, submatrix, n, pivots, rhs, n, info)
            if (info /= 0) cycle
            z(set_index(1:m)) = rhs(1:m, 1)
         end if
         w = product_plus(a, z, q)
         w(set_index(1:m)) = 0.0_dp
         w_scale = max(maxval(abs(q)), a_norm*maxval(abs(z)), tiny(1.0_dp))
         violation = max(0.0_dp, maxval(-a_norm*z), maxval(-w))/w_scale
         if (violation <= reference_acceptance) n_accepted = n_accepted + 1
         if (violation < best_violation) then
            best_violation = violation
            z_ref = z
            w_ref = w
         end if
      end do
   end subroutine brute_force

   ! ===================================================================================
   ! Test matrices
   ! ===================================================================================

   !> Park-Miller minimal standard generator (x <- 16807 x mod (2^31 - 1)), mapped to
   !! (low, high). Own generator so that the cases do not depend on the compiler's.
   function uniform(state, low, high) result(x)
      integer(int64), intent(inout) :: state
      real(dp), intent(in) :: low, high
      real(dp) :: x
      integer(int64), parameter :: multiplier = 16807_int64, modulus = 2147483647_int64
      state = mod(multiplier*state, modulus)
      x = low + (high - low)*real(state, dp)/real(modulus, dp)
   end function uniform

   function random_vector(n, low, high, state) result(v)
      integer, intent(in) :: n
      real(dp), intent(in) :: low, high
      integer(int64), intent(inout) :: state
      real(dp) :: v(n)
      integer :: i
      do i = 1, n
         v(i) = uniform(state, low, high)
      end do
   end function random_vector

   function random_matrix(m, n, state) result(b)
      integer, intent(in) :: m, n
      integer(int64), intent(inout) :: state
      real(dp) :: b(m, n)
      integer :: j
      do j = 1, n
         b(:, j) = random_vector(m, -1.0_dp, 1.0_dp, state)
      end do
   end function random_matrix

   !> A = B^T B + delta I with B uniform in (-1, 1), exactly symmetric.
   function random_spd(n, delta, state) result(a)
      integer, intent(in) :: n
      real(dp), intent(in) :: delta
      integer(int64), intent(inout) :: state
      real(dp) :: a(n, n)
      real(dp) :: b(n, n)
      integer :: i
      b = random_matrix(n, n, state)
      a = matmul(transpose(b), b)
      do i = 1, n
         a(i, i) = a(i, i) + delta
      end do
      call symmetrize(a)
   end function random_spd

   !> A = Q diag(lambda) Q^T with lambda_k = condition^(-(k-1)/(n-1)) (1 down to
   !! 1/condition) and Q the orthogonal factor of a random matrix (dgeqrf + dorgqr).
   function spd_with_spectrum(n, condition, state) result(a)
      integer, intent(in) :: n
      real(dp), intent(in) :: condition
      integer(int64), intent(inout) :: state
      real(dp) :: a(n, n)
      real(dp) :: orthogonal(n, n), tau(n), work(64*n), lambda(n)
      integer :: k, info

      orthogonal = random_matrix(n, n, state)
      call dgeqrf(n, n, orthogonal, n, tau, work, size(work), info)
      if (info /= 0) error stop 'test_lcp: dgeqrf failed'
      call dorgqr(n, n, n, orthogonal, n, tau, work, size(work), info)
      if (info /= 0) error stop 'test_lcp: dorgqr failed'
      do k = 1, n
         lambda(k) = condition**(-real(k - 1, dp)/real(n - 1, dp))
      end do
      a = matmul(orthogonal, matmul(diagonal_matrix(lambda), transpose(orthogonal)))
      call symmetrize(a)
   end function spd_with_spectrum

   !> A = G G^T + delta |G G^T|_inf I where every other row of G is a scaled copy of the
   !! previous one, so that G G^T alone has exactly proportional rows (rank ~ n/2).
   function spd_with_repeated_rows(n, delta, state) result(a)
      integer, intent(in) :: n
      real(dp), intent(in) :: delta
      integer(int64), intent(inout) :: state
      real(dp) :: a(n, n)
      real(dp) :: g(n, n), shift
      integer :: i
      g = random_matrix(n, n, state)
      do i = 2, n, 2
         g(i, :) = uniform(state, -2.0_dp, 2.0_dp)*g(i - 1, :)
      end do
      a = matmul(g, transpose(g))
      shift = delta*infinity_norm(a)
      do i = 1, n
         a(i, i) = a(i, i) + shift
      end do
      call symmetrize(a)
   end function spd_with_repeated_rows

   !> Diagonal matrix with the given diagonal.
   pure function diagonal_matrix(diagonal) result(a)
      real(dp), intent(in) :: diagonal(:)
      real(dp) :: a(size(diagonal), size(diagonal))
      integer :: i
      a = 0.0_dp
      do i = 1, size(diagonal)
         a(i, i) = diagonal(i)
      end do
   end function diagonal_matrix

   !> Copy the lower triangle onto the upper one.
   pure subroutine symmetrize(a)
      real(dp), intent(inout) :: a(:, :)
      integer :: i, j
      do j = 1, size(a, 2)
         do i = 1, j - 1
            a(i, j) = a(j, i)
         end do
      end do
   end subroutine symmetrize

   ! ===================================================================================
   ! Small helpers
   ! ===================================================================================

   pure function infinity_norm(a) result(norm)
      real(dp), intent(in) :: a(:, :)
      real(dp) :: norm
      integer :: i
      norm = 0.0_dp
      do i = 1, size(a, 1)
         norm = max(norm, sum(abs(a(i, :))))
      end do
   end function infinity_norm

   !> A z + q by explicit loops (not the solver's matmul path).
   pure function product_plus(a, z, q) result(w)
      real(dp), intent(in) :: a(:, :), z(:), q(:)
      real(dp) :: w(size(q))
      integer :: i, j
      w = q
      do j = 1, size(z)
         do i = 1, size(q)
            w(i) = w(i) + a(i, j)*z(j)
         end do
      end do
   end function product_plus

   !> 2-norm condition number lambda_max/lambda_min of a symmetric matrix (dsyev).
   function condition_number(a) result(condition)
      real(dp), intent(in) :: a(:, :)
      real(dp) :: condition
      real(dp) :: copy(size(a, 1), size(a, 1)), eigenvalues(size(a, 1)), work(64*size(a, 1))
      integer :: n, info
      n = size(a, 1)
      condition = 1.0_dp
      if (n == 0) return
      copy = a
      call dsyev('N', 'L', n, copy, n, eigenvalues, work, size(work), info)
      if (info /= 0) error stop 'test_lcp: dsyev failed'
      if (eigenvalues(1) <= 0.0_dp) error stop 'test_lcp: test matrix is not positive definite'
      condition = eigenvalues(n)/eigenvalues(1)
   end function condition_number

end program test_lcp
