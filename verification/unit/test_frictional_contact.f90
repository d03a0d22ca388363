!> Unit test of `vibrobeam_frictional_contact` (2-D Coulomb friction by Lemke's method on
!! Stewart & Trinkle's LCP; docs/method.md, "Frictional contact in two dimensions: the
!! solver") and of `vibrobeam_lemke`.
!!
!! References independent of the solver:
!! 1. closed forms for one contact, diagonal and coupled 2 x 2 D: separation, stick, slip
!!    in both directions and the stick/slip boundary, each computed from its formula;
!! 2. random problems with up to 50 contacts whose solution is built first (a state drawn
!!    per contact: separating, sticking or slipping; q = u* - D r*): the Coulomb conditions
!!    are checked on the result by the test's own loops, and r is compared with r* where
!!    the solution is unique (mu_max kappa(D) < 1: docs/method.md, "Frictional contact in
!!    two dimensions: the solver", uniqueness);
!! 3. positive semidefinite D = H H^T of low rank with q = H v (the structure of the
!!    scheme's problem), and degenerate ones (doubled contacts, equal q: the ratio test
!!    ties and the lexicographic rule decides): the Coulomb conditions;
!! 4. mu = 0 against `vibrobeam_lcp` (block principal pivoting, another method) on D_NN;
!! 5. the status paths: bad sizes, mu < 0, NaN, m = 0, a matrix that is not copositive.
!!
!! Tolerances (derived, written beside each check) compare violations in velocity units
!! with eps times the scale max(|q|, |D| |r|) of u: the solver's result is the LU
!! solution of its final basis (order n <= 4m), whose residual is bounded by
!! gamma_{3n} |L| |U| |x| (Higham, *Accuracy and Stability of Numerical Algorithms*,
!! 2002, Theorem 9.4); with |L||U| <= n g |B| and a growth g <= 4 for these
!! (diagonally dominated in their identity columns) bases, every condition holds to
!! 4 n gamma_{3n} of the scale, plus gamma_{2m} for recomputing u = D r + q.
program test_frictional_contact
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use vibrobeam_kinds, only: dp, int64, output_unit
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter, same_bits, use_program_blas_threads
   use vibrobeam_frictional_contact, only: solve_frictional_contact, frictional_contact_solution, &
                                           coulomb_residual, contact_separating, contact_sticking, contact_slipping
   use vibrobeam_lemke, only: solve_lemke
   use vibrobeam_lcp, only: solve_lcp
   use vibrobeam_lapack, only: dsyev
   use vibrobeam_status, only: stat_invalid_argument, stat_numerical_failure, stat_no_convergence
   implicit none

   type(test_counter) :: t
   integer(int64) :: rng_state
   real(dp) :: worst_conditions, worst_unique, worst_semidefinite
   integer :: most_pivots, states_seen(0:2)

   call use_program_blas_threads()
   rng_state = 20261127_int64
   worst_conditions = 0.0_dp
   worst_unique = 0.0_dp
   worst_semidefinite = 0.0_dp
   most_pivots = 0
   states_seen = 0

   call closed_forms(t)
   call random_built_problems(t, rng_state)
   call semidefinite_problems(t, rng_state)
   call degenerate_problems(t, rng_state)
   call frictionless_against_lcp(t, rng_state)
   call status_paths(t)

   write (output_unit, '(a, es10.3)') 'largest Coulomb violation / tolerance (built problems):   ', worst_conditions
   write (output_unit, '(a, es10.3)') 'largest |r - r*| / tolerance (unique built problems):     ', worst_unique
   write (output_unit, '(a, es10.3)') 'largest Coulomb violation / tolerance (semidefinite D):    ', worst_semidefinite
   write (output_unit, '(a, i0)') 'most Lemke pivots: ', most_pivots
   write (output_unit, '(a, 3(i0, 1x))') 'contacts separating, sticking, slipping: ', states_seen
   call t%finish('test_frictional_contact')

contains

   !> Solve one problem; the solver must return stat 0.
   subroutine solve_checked(name, d, q, mu, solution, t)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: d(:, :), q(:), mu(:)
      type(frictional_contact_solution), intent(out) :: solution
      type(test_counter), intent(inout) :: t
      integer :: stat
      character(len=512) :: errmsg
      call solve_frictional_contact(d, q, mu, solution, stat, errmsg)
      call t%check_true(name//': stat = 0', stat == 0, trim(errmsg))
      most_pivots = max(most_pivots, solution%pivots)
   end subroutine solve_checked

   !> One contact: closed forms.
   subroutine closed_forms(t)
      type(test_counter), intent(inout) :: t
      real(dp) :: d(2, 2), q(2), mu, p, r_t, u_t, tolerance, determinant, kappa
      type(frictional_contact_solution) :: s

      ! Tolerance: r comes from the LU solve of a basis of order <= 4 (above) and the
      ! closed form from one division or a 2 x 2 Cramer solve; both are within
      ! 4 n gamma_{3n} kappa of the exact value, n = 4, kappa the condition number of
      ! the 2 x 2 (or 1 x 1) system of that state (below 30 here).
      tolerance = 16.0_dp*gamma_n(12)

      ! --- separation: q_N > 0 => r = 0, u = q (exact: no pivot at all) ---------------
      d = reshape([2.0_dp, 0.7_dp, 0.7_dp, 1.0_dp], [2, 2])
      q = [0.3_dp, -5.0_dp]
      call solve_checked('separation', d, q, [0.5_dp], s, t)
      call t%check_true('separation: r = 0 exactly', all(same_bits(s%impulse, 0.0_dp)))
      call t%check_true('separation: u = q exactly', all(same_bits(s%velocity, q)))
      call t%check_true('separation: state', s%state(1) == contact_separating)

      ! --- diagonal D = diag(a, c), q_N < 0: p = -q_N/a --------------------------------
      d = reshape([2.0_dp, 0.0_dp, 0.0_dp, 4.0_dp], [2, 2])
      ! stick: |q_T|/c = 0.25 <= mu p = 0.5 * 1.5 => r_T = -q_T/c
      q = [-3.0_dp, 1.0_dp]
      call solve_checked('diagonal stick', d, q, [0.5_dp], s, t)
      call t%check_close('diagonal stick: p', s%impulse(1), 1.5_dp, tolerance)
      call t%check_close('diagonal stick: r_T', s%impulse(2), -0.25_dp, tolerance)
      call t%check_close('diagonal stick: u_T', s%velocity(2), 0.0_dp, tolerance, scale=1.0_dp)
      call t%check_true('diagonal stick: state', s%state(1) == contact_sticking)
      ! slip: |q_T|/c = 2 > mu p = 0.75 => r_T = -mu p sign(q_T), u_T = q_T + c r_T
      q = [-3.0_dp, -8.0_dp]
      call solve_checked('diagonal slip', d, q, [0.5_dp], s, t)
      call t%check_close('diagonal slip: p', s%impulse(1), 1.5_dp, tolerance)
      call t%check_close('diagonal slip: r_T', s%impulse(2), 0.75_dp, tolerance)
      call t%check_close('diagonal slip: u_T', s%velocity(2), -8.0_dp + 4.0_dp*0.75_dp, tolerance)
      call t%check_true('diagonal slip: state', s%state(1) == contact_slipping)
      ! boundary: |q_T|/c = mu p exactly (binary fractions): r_T = -mu p, u_T = 0
      q = [-3.0_dp, 3.0_dp]
      call solve_checked('diagonal boundary', d, q, [0.5_dp], s, t)
      call t%check_close('diagonal boundary: p', s%impulse(1), 1.5_dp, tolerance)
      call t%check_close('diagonal boundary: r_T', s%impulse(2), -0.75_dp, tolerance)
      call t%check_close('diagonal boundary: u_T', s%velocity(2), 0.0_dp, tolerance, scale=3.0_dp)

      ! --- coupled D = [a b; b c] --------------------------------------------------------
      d = reshape([2.0_dp, 0.6_dp, 0.6_dp, 1.0_dp], [2, 2])
      determinant = d(1, 1)*d(2, 2) - d(1, 2)**2
      kappa = 3.0_dp   ! 2-norm condition number of this D: (3 + sqrt(2.44))/(3 - sqrt(2.44)) = 3.16
      ! stick: r = -D^-1 q (Cramer), inside the cone
      q = [-1.0_dp, -0.25_dp]
      mu = 0.5_dp
      p = -(d(2, 2)*q(1) - d(1, 2)*q(2))/determinant
      r_t = -(-d(2, 1)*q(1) + d(1, 1)*q(2))/determinant
      call t%check_true('coupled stick: the closed form sticks', p > 0 .and. abs(r_t) < mu*p)
      call solve_checked('coupled stick', d, q, [mu], s, t)
      call t%check_close('coupled stick: p', s%impulse(1), p, tolerance*kappa)
      call t%check_close('coupled stick: r_T', s%impulse(2), r_t, tolerance*kappa, scale=p)
      call t%check_close('coupled stick: u_T', s%velocity(2), 0.0_dp, tolerance*kappa, scale=maxval(abs(q)))
      ! slip in +T (u_T > 0, r_T = -mu p): u_N = (a - mu b) p + q_N = 0
      q = [-1.0_dp, 2.0_dp]
      p = -q(1)/(d(1, 1) - mu*d(1, 2))
      u_t = (d(2, 1) - mu*d(2, 2))*p + q(2)
      call t%check_true('coupled slip +: the closed form slides forward', p > 0 .and. u_t > 0)
      call solve_checked('coupled slip +', d, q, [mu], s, t)
      call t%check_close('coupled slip +: p', s%impulse(1), p, tolerance*kappa)
      call t%check_close('coupled slip +: r_T', s%impulse(2), -mu*p, tolerance*kappa)
      call t%check_close('coupled slip +: u_T', s%velocity(2), u_t, tolerance*kappa)
      ! slip in -T (u_T < 0, r_T = +mu p): u_N = (a + mu b) p + q_N = 0
      q = [-1.0_dp, -2.0_dp]
      p = -q(1)/(d(1, 1) + mu*d(1, 2))
      u_t = (d(2, 1) + mu*d(2, 2))*p + q(2)
      call t%check_true('coupled slip -: the closed form slides backward', p > 0 .and. u_t < 0)
      call solve_checked('coupled slip -', d, q, [mu], s, t)
      call t%check_close('coupled slip -: p', s%impulse(1), p, tolerance*kappa)
      call t%check_close('coupled slip -: r_T', s%impulse(2), mu*p, tolerance*kappa)
      call t%check_close('coupled slip -: u_T', s%velocity(2), u_t, tolerance*kappa)
      ! boundary: the q_T for which the stick impulse is exactly on the cone's edge,
      ! r_T = -mu p with u_T = 0: q = -D (p, -mu p) with p = 1
      q = -matmul(d, [1.0_dp, -mu])
      call solve_checked('coupled boundary', d, q, [mu], s, t)
      call t%check_close('coupled boundary: p', s%impulse(1), 1.0_dp, tolerance*kappa)
      call t%check_close('coupled boundary: r_T', s%impulse(2), -mu, tolerance*kappa)
      call t%check_close('coupled boundary: u_T', s%velocity(2), 0.0_dp, tolerance*kappa, scale=1.0_dp)
      ! mu = 0: the frictionless closed form p = -q_N/a, r_T = 0
      q = [-1.0_dp, 2.0_dp]
      call solve_checked('coupled frictionless', d, q, [0.0_dp], s, t)
      call t%check_close('coupled frictionless: p', s%impulse(1), 0.5_dp, tolerance)
      call t%check_true('coupled frictionless: r_T = 0 exactly', same_bits(s%impulse(2), 0.0_dp))
   end subroutine closed_forms

   !> Random D = B^T B + delta I and a solution built first: per contact a state
   !! (separating, sticking, slipping in either direction), r* and u* obeying it, then
   !! q = u* - D r*.
   subroutine random_built_problems(t, state)
      type(test_counter), intent(inout) :: t
      integer(int64), intent(inout) :: state
      integer, parameter :: sizes(*) = [1, 2, 3, 5, 8, 10, 20, 30, 50]
      integer :: size_index, repeat, m, i, kind
      real(dp), allocatable :: d(:, :), q(:), mu(:), r_star(:), u_star(:)
      integer, allocatable :: expected_state(:)
      real(dp) :: kappa, bound, difference
      type(frictional_contact_solution) :: s
      character(len=64) :: name
      do size_index = 1, size(sizes)
         m = sizes(size_index)
         do repeat = 1, 8
            write (name, '(a, i0, a, i0)') 'built m = ', m, ', case ', repeat
            call random_spd(2*m, 0.2_dp, state, d, kappa)
            allocate (mu(m), r_star(2*m), u_star(2*m), expected_state(m))
            do i = 1, m
               mu(i) = 2.0_dp*uniform(state)
               if (repeat <= 2) mu(i) = 0.1_dp*mu(i)/kappa     ! unique solutions
               if (mod(i, 7) == 0) mu(i) = 0.0_dp               ! some frictionless contacts
               kind = min(3, int(4.0_dp*uniform(state)))
               ! the state the solver must report (a closed contact with mu = 0 slips)
               expected_state(i) = contact_slipping
               if (kind == 0) expected_state(i) = contact_separating
               if (kind == 1 .and. mu(i) > 0.0_dp) expected_state(i) = contact_sticking
               select case (kind)
               case (0)   ! separating: r = 0, u_N > 0, u_T anything
                  r_star(2*i - 1:2*i) = 0.0_dp
                  u_star(2*i - 1:2*i) = [uniform(state), 2.0_dp*uniform(state) - 1.0_dp]
               case (1)   ! sticking: u = 0, |r_T| <= mu p
                  r_star(2*i - 1) = 0.1_dp + uniform(state)
                  r_star(2*i) = (2.0_dp*uniform(state) - 1.0_dp)*mu(i)*r_star(2*i - 1)
                  u_star(2*i - 1:2*i) = 0.0_dp
               case default   ! slipping in the direction of the sign of u_T
                  r_star(2*i - 1) = 0.1_dp + uniform(state)
                  u_star(2*i - 1) = 0.0_dp
                  u_star(2*i) = sign(0.1_dp + uniform(state), uniform(state) - 0.5_dp)
                  r_star(2*i) = -mu(i)*r_star(2*i - 1)*sign(1.0_dp, u_star(2*i))
               end select
            end do
            q = u_star - matmul(d, r_star)
            call solve_checked(trim(name), d, q, mu, s, t)
            call check_coulomb(trim(name), d, q, mu, s, t, worst_conditions)
            if (repeat <= 2) then
               ! Unique solution (mu_max kappa(D) <= 0.2 < 1, docs/method.md): r = r*.
               ! Perturbation bound of the same argument: the errors e_u of u (the
               ! violation tolerance times the scale) move r by at most
               ! |e_u| / (lambda_min (1 - mu_max kappa)), i.e. relative to |r| by
               ! kappa |e_u| / (|D| |r| (1 - mu_max kappa)); sqrt(2m) turns max norms into
               ! 2-norms.
               bound = conditions_tolerance(m)*kappa*sqrt(real(2*m, dp))/(1.0_dp - maxval(mu)*kappa)
               difference = maxval(abs(s%impulse - r_star))/maxval(abs(r_star))
               worst_unique = max(worst_unique, difference/bound)
               call t%check_true(trim(name)//': r = r* (unique)', difference <= bound)
               call t%check_true(trim(name)//': states (unique)', all(s%state == expected_state))
            end if
            deallocate (mu, r_star, u_star, expected_state, d, q)
         end do
      end do
   end subroutine random_built_problems

   !> Positive semidefinite D = H H^T with H (2m x k), k < 2m, and q = H v: the form of the
   !! scheme's problem (q in the range of H), for which Lemke must still end with a solution.
   subroutine semidefinite_problems(t, state)
      type(test_counter), intent(inout) :: t
      integer(int64), intent(inout) :: state
      integer, parameter :: sizes(*) = [2, 5, 10, 20, 50]
      real(dp), allocatable :: h(:, :), d(:, :), q(:), mu(:), v(:)
      integer :: size_index, m, k, i, j
      type(frictional_contact_solution) :: s
      character(len=64) :: name
      do size_index = 1, size(sizes)
         m = sizes(size_index)
         k = max(1, m)        ! rank m of 2m: half of the directions are held by nothing
         allocate (h(2*m, k), v(k), mu(m))
         do j = 1, k
            do i = 1, 2*m
               h(i, j) = 2.0_dp*uniform(state) - 1.0_dp
            end do
            v(j) = 2.0_dp*uniform(state) - 1.0_dp
         end do
         do i = 1, m
            mu(i) = 2.0_dp*uniform(state)
         end do
         d = matmul(h, transpose(h))
         q = matmul(h, v)
         write (name, '(a, i0, a, i0)') 'semidefinite m = ', m, ', rank ', k
         call solve_checked(trim(name), d, q, mu, s, t)
         call check_coulomb(trim(name), d, q, mu, s, t, worst_semidefinite)
         deallocate (h, v, mu, d, q)   ! gfortran -O2 does not reallocate q = matmul(...) to a new size
      end do
   end subroutine semidefinite_problems

   !> Degenerate problems, where the ratio test ties and the lexicographic rule decides:
   !! every contact doubled (two identical rows of H, as two obstacles on one point), the
   !! free velocities of the pairs equal (ties from the first pivot on), D = H H^T
   !! singular, q = H v; and q_T = 0 exactly (stick and slip tie at r_T = 0).
   subroutine degenerate_problems(t, state)
      type(test_counter), intent(inout) :: t
      integer(int64), intent(inout) :: state
      integer, parameter :: sizes(*) = [2, 6, 20, 40]
      real(dp), allocatable :: h(:, :), d(:, :), q(:), mu(:), v(:)
      integer :: size_index, m, i, j
      type(frictional_contact_solution) :: s
      character(len=64) :: name
      do size_index = 1, size(sizes)
         m = sizes(size_index)
         allocate (h(2*m, 2*m), v(2*m), mu(m))
         do j = 1, 2*m
            do i = 1, m, 2          ! contacts i and i + 1 share their rows
               h(2*i - 1, j) = 2.0_dp*uniform(state) - 1.0_dp
               h(2*i, j) = 2.0_dp*uniform(state) - 1.0_dp
               h(2*i + 1:2*i + 2, j) = h(2*i - 1:2*i, j)
            end do
            v(j) = 2.0_dp*uniform(state) - 1.0_dp
         end do
         do i = 1, m, 2
            mu(i) = 2.0_dp*uniform(state)
            mu(i + 1) = mu(i)
         end do
         d = matmul(h, transpose(h))
         q = matmul(h, v)
         write (name, '(a, i0)') 'doubled contacts m = ', m
         call solve_checked(trim(name), d, q, mu, s, t)
         call check_coulomb(trim(name), d, q, mu, s, t, worst_semidefinite)
         q(2:2*m:2) = 0.0_dp
         q(1:2*m:2) = -1.0_dp
         write (name, '(a, i0)') 'doubled contacts, q_T = 0, q_N = -1, m = ', m
         call solve_checked(trim(name), d, q, mu, s, t)
         call check_coulomb(trim(name), d, q, mu, s, t, worst_semidefinite)
         deallocate (h, v, mu, d, q)
      end do
   end subroutine degenerate_problems

   !> mu = 0: the normal impulses are the solution of LCP(D_NN, q_N), which `solve_lcp`
   !! computes by block principal pivoting; the two agree to the forward error of an SPD
   !! solve, kappa(D_NN) times the residual tolerance.
   subroutine frictionless_against_lcp(t, state)
      type(test_counter), intent(inout) :: t
      integer(int64), intent(inout) :: state
      integer, parameter :: m = 30
      real(dp), allocatable :: d(:, :), q(:), z(:), w(:)
      real(dp) :: kappa, bound
      integer :: i, iterations, stat
      character(len=512) :: errmsg
      type(frictional_contact_solution) :: s
      call random_spd(2*m, 0.2_dp, state, d, kappa)
      q = [(2.0_dp*uniform(state) - 1.0_dp, i=1, 2*m)]
      call solve_checked('frictionless m = 30', d, q, [(0.0_dp, i=1, m)], s, t)
      allocate (z(m), w(m))
      call solve_lcp(d(1:2*m:2, 1:2*m:2), q(1:2*m:2), z, w, iterations, stat, errmsg)
      call t%check_true('frictionless m = 30: solve_lcp', stat == 0, trim(errmsg))
      ! kappa(D_NN) <= kappa(D) (Cauchy interlacing); both results are within
      ! conditions_tolerance of the scale in the residual, hence kappa times that in r.
      bound = 2.0_dp*conditions_tolerance(m)*kappa*sqrt(real(m, dp))
      call t%check_true('frictionless m = 30: p = solve_lcp z', &
                        maxval(abs(s%impulse(1:2*m:2) - z)) <= bound*maxval(abs(z)))
      call t%check_true('frictionless m = 30: r_T = 0 exactly', all(same_bits(s%impulse(2:2*m:2), 0.0_dp)))
      call check_coulomb('frictionless m = 30', d, q, [(0.0_dp, i=1, m)], s, t, worst_conditions)
   end subroutine frictionless_against_lcp

   !> Bad arguments and a problem without solution return a status, never stop.
   subroutine status_paths(t)
      type(test_counter), intent(inout) :: t
      type(frictional_contact_solution) :: s
      integer :: stat, pivots
      character(len=512) :: errmsg
      real(dp) :: nan, z(2), w(2)
      real(dp), allocatable :: empty(:, :)
      call solve_frictional_contact(reshape([1.0_dp], [1, 1]), [1.0_dp, 0.0_dp], [0.5_dp], s, stat, errmsg)
      call t%check_true('sizes refused', stat == stat_invalid_argument .and. index(errmsg, 'sizes') > 0, &
                        trim(errmsg))
      call solve_frictional_contact(reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2]), [-1.0_dp, 0.0_dp], &
                                    [-0.5_dp], s, stat, errmsg)
      call t%check_true('mu < 0 refused', stat == stat_invalid_argument .and. index(errmsg, 'negative') > 0, &
                        trim(errmsg))
      nan = ieee_value(1.0_dp, ieee_quiet_nan)
      call solve_frictional_contact(reshape([1.0_dp, 0.0_dp, 0.0_dp, nan], [2, 2]), [-1.0_dp, 0.0_dp], &
                                    [0.5_dp], s, stat, errmsg)
      call t%check_true('NaN refused', stat == stat_invalid_argument .and. index(errmsg, 'NaN') > 0, &
                        trim(errmsg))
      allocate (empty(0, 0))
      call solve_frictional_contact(empty, [real(dp) ::], [real(dp) ::], s, stat, errmsg)
      call t%check_true('m = 0: stat 0, empty result', stat == 0 .and. size(s%impulse) == 0 .and. &
                        size(s%state) == 0, trim(errmsg))
      ! A negative definite matrix is not copositive: LCP(-I, (-1, -1)) has no solution
      ! reachable by Lemke (secondary ray at once).
      call solve_lemke(reshape([-1.0_dp, 0.0_dp, 0.0_dp, -1.0_dp], [2, 2]), [-1.0_dp, -1.0_dp], z, w, &
                       pivots, stat, errmsg)
      call t%check_true('not copositive: ray reported', stat == stat_numerical_failure .and. &
                        index(errmsg, 'ray') > 0, trim(errmsg))
      call solve_frictional_contact(reshape([-1.0_dp, 0.0_dp, 0.0_dp, -1.0_dp], [2, 2]), [-1.0_dp, 0.5_dp], &
                                    [0.5_dp], s, stat, errmsg)
      call t%check_true('negative definite D: a status, not a stop', stat /= 0, 'stat = 0')
      ! The pivot limit: LCP(I, (-1, -1)) needs 3 pivots (z0 in, z_2 in, z_1 in for z0).
      call solve_lemke(reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2]), [-1.0_dp, -1.0_dp], z, w, &
                       pivots, stat, errmsg, max_pivots=2)
      call t%check_true('pivot limit reported', stat == stat_no_convergence .and. index(errmsg, 'limit') > 0, &
                        trim(errmsg))
      call solve_lemke(reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2]), [-1.0_dp, -1.0_dp], z, w, &
                       pivots, stat, errmsg)
      call t%check_true('LCP(I, (-1, -1)): z = (1, 1), w = 0 in 3 pivots', stat == 0 .and. pivots == 3 .and. &
                        all(abs(z - 1.0_dp) <= 4*epsilon(1.0_dp)) .and. all(abs(w) <= 4*epsilon(1.0_dp)), trim(errmsg))
      call solve_frictional_contact(reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2]), [-1.0_dp, 0.0_dp], &
                                    [0.5_dp], s, stat, errmsg, tolerance=-1.0_dp)
      call t%check_true('tolerance < 0 refused', stat == stat_invalid_argument, trim(errmsg))
   end subroutine status_paths

   !> Relative tolerance of every Coulomb condition for m contacts (module documentation):
   !! 4 n gamma_{3n} + gamma_{2m} with n = 4m the largest LCP.
   pure real(dp) function conditions_tolerance(m)
      integer, intent(in) :: m
      conditions_tolerance = 4.0_dp*(4*m)*gamma_n(3*4*m) + gamma_n(2*m)
   end function conditions_tolerance

   !> The Coulomb conditions checked one by one on the solver's result, in the test's own
   !! loops: violations in velocity units divided by the scale max(|q|, |D| |r|) and by
   !! `conditions_tolerance`; the largest ratio goes into `worst`.
   subroutine check_coulomb(name, d, q, mu, s, t, worst)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: d(:, :), q(:), mu(:)
      type(frictional_contact_solution), intent(in) :: s
      type(test_counter), intent(inout) :: t
      real(dp), intent(inout) :: worst
      real(dp) :: u(size(q)), d_norm, scale, tolerance, p, r_t, u_n, u_t, v(4)
      integer :: i, m
      character(len=160) :: detail
      m = size(mu)
      d_norm = maxval(abs(d))
      u = q
      do i = 1, 2*m
         u = u + d(:, i)*s%impulse(i)
      end do
      scale = max(maxval(abs(q)), d_norm*maxval(abs(s%impulse)))
      tolerance = conditions_tolerance(m)*scale
      do i = 1, m
         p = s%impulse(2*i - 1)
         r_t = s%impulse(2*i)
         u_n = u(2*i - 1)
         u_t = u(2*i)
         v(1) = max(-d_norm*p, -u_n, 0.0_dp)                   ! p >= 0, u_N >= 0
         v(2) = min(d_norm*abs(p), abs(u_n))                    ! p u_N = 0
         v(3) = max(d_norm*(abs(r_t) - mu(i)*p), 0.0_dp)       ! |r_T| <= mu p
         if (abs(u_t) > tolerance) then                         ! slip: r_T = -mu p sign(u_T)
            v(4) = d_norm*abs(r_t + mu(i)*p*sign(1.0_dp, u_t))
         else
            v(4) = 0.0_dp                                       ! stick: v(3) covers it
         end if
         states_seen(s%state(i)) = states_seen(s%state(i)) + 1
         worst = max(worst, maxval(v)/tolerance)
         if (maxval(v) > tolerance) then
            write (detail, '(a, i0, a, 4es10.2, a, es10.2)') 'contact ', i, ': violations ', v, &
               ' above ', tolerance
            call t%check_true(name//': Coulomb conditions', .false., trim(detail))
            return
         end if
      end do
      call t%check_true(name//': Coulomb conditions', .true.)
      call t%check_true(name//': coulomb_residual agrees', &
                        coulomb_residual(d, q, mu, s%impulse) <= 2.0_dp*conditions_tolerance(m))
   end subroutine check_coulomb

   !> Uniform number in [0, 1) (Park-Miller minimal standard generator).
   real(dp) function uniform(state)
      integer(int64), intent(inout) :: state
      state = mod(16807_int64*state, 2147483647_int64)
      uniform = real(state, dp)/2147483647.0_dp
   end function uniform

   !> B^T B + delta I with B uniform in (-1, 1)/sqrt(n), and its 2-norm condition number
   !! (dsyev).
   subroutine random_spd(n, delta, state, a, kappa)
      integer, intent(in) :: n
      real(dp), intent(in) :: delta
      integer(int64), intent(inout) :: state
      real(dp), allocatable, intent(out) :: a(:, :)
      real(dp), intent(out) :: kappa
      real(dp) :: b(n, n), copy(n, n), eigenvalues(n), work(3*n*n)
      integer :: i, j, info
      do j = 1, n
         do i = 1, n
            b(i, j) = (2.0_dp*uniform(state) - 1.0_dp)/sqrt(real(n, dp))
         end do
      end do
      allocate (a(n, n))
      a = matmul(transpose(b), b)
      do i = 1, n
         a(i, i) = a(i, i) + delta
      end do
      a = 0.5_dp*(a + transpose(a))
      copy = a
      call dsyev('N', 'U', n, copy, n, eigenvalues, work, size(work), info)
      kappa = eigenvalues(n)/eigenvalues(1)
      if (info /= 0) kappa = huge(1.0_dp)
   end subroutine random_spd

end program test_frictional_contact
