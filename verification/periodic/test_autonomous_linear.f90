!> Linear exactness of the autonomous orbit (issue 20; docs/method.md, "Autonomous periodic
!! orbits"). Without contact, damping or load and with theta = 1/2 the velocity scheme on
!! a mode q of (K, M) (K phi = w^2 M phi) is the trapezoidal rule
!!   p' - p = -dt w^2 (q + q')/2,  q' - q = dt (p + p')/2,
!! whose one-step amplification has the eigenvalues (1 + i w dt/2)/(1 - i w dt/2): modulus
!! 1, argument 2 arctan(w dt/2). An orbit of P steps of dt = T/P through mode k therefore
!! has P 2 arctan(w_k T/(2 P)) = 2 pi, i.e.
!!   T = 2 P tan(pi/P)/w_k,
!! with w_k^2 the generalized eigenvalues of the stepped system's dense K and M (LAPACK
!! dsygv: no stepper, no period map). The test checks that closed form against the
!! eigenvalues of the scheme's one-step matrix (`amplification_matrix`, dgeevx), then the
!! period `find_autonomous_orbit` returns against it, the orbit's shape against mode k
!! (U along phi_k, V = 0: the orbit starts where the tip turns) and the two Floquet
!! multipliers of the mode (both 1: the mode's plane is fixed by the map), each to a
!! round-off bound derived below.
!!
!! Usage: test_autonomous_linear SCENE.nml K [SHIFT]: a scene of &periodic autonomous =
!! .true. starting near mode K; SHIFT (default 0) changes w_k by that relative amount in
!! the reference (1e-6 must fail the test: it can fail).
program test_autonomous_linear
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_lapack, only: dsygv
   use vibrobeam_periodic_reference, only: energy_gram, energy_norm, cancellation, amplification_matrix, &
      eigenvalues_with_conditions, solve_dense
   use vibrobeam_periodic_analysis, only: periodic_orbit
   use vibrobeam_autonomous_orbit, only: find_autonomous_orbit
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   use vibrobeam_progress, only: progress_meter
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(periodic_orbit) :: orbit
   type(progress_meter) :: quiet   ! (a default meter reports nothing)
   character(len=512) :: path, argument, errmsg
   real(dp), allocatable :: mass(:, :), stiffness(:, :), modes(:, :), lambda(:), work(:), gram(:, :), a(:, :), &
                            wr(:), wi(:), rconde(:), vectors(:, :), u(:), v(:), other(:), inverse_mass(:, :)
   real(dp) :: shift, omega_k, period_ref, period, steps, dt, residual_bound, noise, reference_error, bound, error, &
               weight, coupling, nearest, argument_k, smallest_gap, along, omega_guess, scale, query(1)
   integer :: n, k, stat, info, j

   call get_command_argument(1, path)
   call get_command_argument(2, argument)
   read (argument, *) k
   shift = 0
   if (command_argument_count() >= 3) then
      call get_command_argument(3, argument)
      read (argument, *) shift
   end if
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call find_autonomous_orbit(scene, prepared, orbit, stat, errmsg, quiet)
   call t%check_true('find_autonomous_orbit runs', stat == 0, trim(errmsg))
   if (stat /= 0) call t%finish('test_autonomous_linear')
   call t%check_true('Gauss-Newton converged', orbit%converged, trim(orbit%failure))
   steps = real(orbit%map%steps, dp)
   period = orbit%dt*steps
   dt = orbit%dt

   ! ---- the modes of (K, M), dense, independently of the solver ----
   n = prepared%system%model%unknowns
   mass = band_to_dense(prepared%system%model%mass)
   stiffness = band_to_dense(prepared%system%model%stiffness)
   modes = stiffness
   inverse_mass = mass
   allocate (lambda(n))
   call dsygv(1, 'V', 'U', n, modes, n, inverse_mass, n, lambda, query, -1, info)
   allocate (work(int(query(1))))
   inverse_mass = mass
   call dsygv(1, 'V', 'U', n, modes, n, inverse_mass, n, lambda, work, size(work), info)
   call t%check_true('dsygv solves K phi = w^2 M phi', info == 0)
   omega_k = sqrt(lambda(k))*(1 + shift)
   period_ref = 2*steps*tan(pi/steps)/omega_k
   write (*, '(a,i0,a,es23.16,a,es23.16,a,f0.1)') 'mode ', k, ': w = ', sqrt(lambda(k)), ' rad/s, reference T = ', &
      period_ref, ' s, P = ', steps

   ! ---- the closed form against the scheme's one-step matrix at dt = T_ref/P: one of
   ! its eigenvalues has argument 2 pi/P. dgeevx's eigenvalue errs by eps ||A||_F/s
   ! (s its reciprocal condition number), an argument by that over |lambda| = 1 ----
   a = amplification_matrix(mass, stiffness, 0*mass, period_ref/steps, scene%time%theta)
   allocate (wr(2*n), wi(2*n), rconde(2*n), vectors(2*n, 2*n))
   call eigenvalues_with_conditions(a, wr, wi, rconde, vectors)
   j = minloc(abs(atan2(wi, wr) - 2*pi/steps), dim=1)
   argument_k = atan2(wi(j), wr(j))
   bound = 4*epsilon(1.0_dp)*sqrt(sum(a**2))/rconde(j)
   write (*, '(a,es10.3,a,es10.3)') 'closed form against the one-step matrix: argument error ', &
      abs(argument_k - 2*pi/steps), ', bound ', bound
   call t%check_close('an eigenvalue of the one-step matrix has argument 2 pi/P at dt = T_ref/P', argument_k, &
                      2*pi/steps, bound, scale=1.0_dp)
   call t%check_close('... and modulus 1 (theta = 1/2 conserves the mode''s energy)', hypot(wr(j), wi(j)), 1.0_dp, &
                      bound, scale=1.0_dp)

   ! ---- the period. In mode k's coordinates (q, p) the map is a rotation by
   ! phi(T) = 2 P arctan(w_k T/(2 P)) of (w_k q, p), so a relative residual rho of the map
   ! (energy norm weighted at the guess's Omega) means |2 sin((phi - 2 pi)/2)| <=
   ! rho c, c = sqrt(1 + Omega^2/w_k^2) (the energy norm against w_k^2 q^2 + p^2), and
   ! |T - T_ref| <= c (rho + 2 noise)/phi'(T), phi' = w_k cos^2(pi/P) near T_ref, with rho
   ! <= tolerance and noise = 8 eps P rho_x the round-off of one evaluation (as
   ! test_periodic_linear: each step rounds each unknown relative to itself, weighed by the
   ! cancellation rho_x of the energy norm). The reference: dsygv's eigenvalue errs by
   ! about eps ||K|| ||M^-1|| (backward stable on the Cholesky-reduced problem), so w_k
   ! relatively by half of that over w_k^2, and T as much. That a priori bound is far too
   ! wide for the Hermite elements' badly scaled rotations (||K|| ||M^-1|| / w_1^2 ~ 1e10),
   ! so the test takes the a posteriori one: for the M-orthonormal phi_k and the residual
   ! r = K phi_k - w_k^2 M phi_k an eigenvalue lies within ||r||_(M^-1) of w_k^2 (the
   ! symmetric-definite residual bound), r's own rounding (n eps (|K| + w_k^2 |M|) |phi_k|
   ! componentwise) added. ----
   gram = energy_gram(prepared, orbit%map%omega)
   omega_guess = orbit%map%omega
   noise = 8*epsilon(1.0_dp)*steps*cancellation(gram, orbit%x)
   residual_bound = scene%periodic%tolerance + 2*noise
   weight = sqrt(1 + omega_guess**2/omega_k**2)
   inverse_mass = identity_of(n)
   call solve_dense(mass, inverse_mass)
   coupling = residual_norm(k)
   reference_error = coupling/lambda(k)/2*period_ref
   bound = weight*residual_bound/(omega_k*cos(pi/steps)**2) + reference_error
   error = abs(period - period_ref)
   write (*, '(a,es23.16,a,es10.3,a,es10.3,a,es10.3,a)') 'period ', period, ' s: error ', error, ' s, bound ', bound, &
      ' s (reference ', reference_error, ' s)'
   call t%check_close('the period against 2 P tan(pi/P)/w_k (s)', period, period_ref, bound, scale=1.0_dp)
   call t%check_true('the bound is a round-off bound (< 1e-9 relative)', bound < 1e-9_dp*period_ref)

   ! ---- the shape: U along phi_k, V = 0. Another mode j's component of the fixed point
   ! is its residual over |e^(i phi_j) - 1| = |2 sin(phi_j/2)|, so relative to the orbit
   ! at most c (rho + 2 noise) ||x||/min_j |2 sin(phi_j/2)| in the (w_j q_j, p_j)
   ! coordinates; in the M-norm of U (q_j = that over w_j) and relative to q_k, times
   ! c w_k/w_1 (||x|| <= c w_k |q_k|); twice that for V (the phase condition makes V's
   ! mode-k part the others' through the tip's row); phi_k's own error, the residual
   ! bound ||r||_(M^-1) above over the gap to the nearest eigenvalue (Davis-Kahan) ----
   u = orbit%x(1:n)
   v = orbit%x(n + 1:2*n)
   smallest_gap = huge(1.0_dp)
   nearest = huge(1.0_dp)
   do j = 1, n
      if (j == k) cycle
      smallest_gap = min(smallest_gap, abs(2*sin(steps*atan(sqrt(lambda(j))*dt/2))))
      nearest = min(nearest, abs(lambda(j) - lambda(k)))
   end do
   scale = sqrt(dot_product(u, matmul(mass, u)))
   along = dot_product(modes(:, k), matmul(mass, u))   ! (dsygv's modes are M-orthonormal)
   other = u - along*modes(:, k)
   error = sqrt(dot_product(other, matmul(mass, other)))/scale
   bound = 2*weight**2*sqrt(lambda(k)/lambda(1))*residual_bound/smallest_gap + &
           coupling/nearest
   write (*, '(a,es10.3,a,es10.3,a,es10.3)') 'shape: U off mode k ', error, ', bound ', bound, &
      '; smallest |2 sin(phi_j/2)| ', smallest_gap
   call t%check_close('U along mode k (M-norm, relative)', error, 0.0_dp, bound, scale=1.0_dp)
   error = sqrt(dot_product(v, matmul(mass, v)))/(omega_k*scale)
   call t%check_close('V = 0 at the start (relative to w_k ||U||, M-norm)', error, 0.0_dp, 2*bound, scale=1.0_dp)
   write (*, '(a,es10.3)') 'shape: V relative ', error

   ! ---- the multipliers: the map fixes mode k's plane, so two multipliers are 1; the
   ! linearised monodromy carries the P steps' round-off (8 eps P rho per unit column, as
   ! the noise above), 4 times that for the eigenvalue's sensitivity ----
   call t%check_true('as many multipliers as unknowns of the map (2 J)', size(orbit%multipliers, 2) == 2*n)
   bound = 4*(8*epsilon(1.0_dp)*steps*cancellation(gram, orbit%x) + epsilon(1.0_dp)*sqrt(2.0_dp*n))
   call check_unit_pair()
   call t%finish('test_autonomous_linear')

contains

   !> The identity of size m.
   function identity_of(m) result(out)
      integer, intent(in) :: m
      real(dp) :: out(m, m)
      integer :: i
      out = 0
      do i = 1, m
         out(i, i) = 1
      end do
   end function identity_of

   !> ||r||_(M^-1) + ||rounding of r||_(M^-1), r = K phi_j - w_j^2 M phi_j.
   real(dp) function residual_norm(j)
      integer, intent(in) :: j
      real(dp) :: r(n, 1), rounding(n, 1)
      r(:, 1) = matmul(stiffness, modes(:, j)) - lambda(j)*matmul(mass, modes(:, j))
      rounding(:, 1) = n*epsilon(1.0_dp)*(matmul(abs(stiffness), abs(modes(:, j))) + &
                                          lambda(j)*matmul(abs(mass), abs(modes(:, j))))
      residual_norm = sqrt(dot_product(r(:, 1), matmul(inverse_mass, r(:, 1)))) + &
                      sqrt(dot_product(rounding(:, 1), matmul(inverse_mass, rounding(:, 1))))
   end function residual_norm

   !> The two multipliers nearest 1 are 1 within the bound.
   subroutine check_unit_pair()
      real(dp) :: distance(size(orbit%multipliers, 2))
      integer :: first, second
      distance = hypot(orbit%multipliers(1, :) - 1, orbit%multipliers(2, :))
      first = minloc(distance, dim=1)
      distance(first) = huge(1.0_dp)
      second = minloc(distance, dim=1)
      distance(first) = hypot(orbit%multipliers(1, first) - 1, orbit%multipliers(2, first))
      write (*, '(a,2es10.3,a,es10.3)') 'multipliers at 1: distances ', distance(first), distance(second), &
         ', bound ', bound
      call t%check_close('a Floquet multiplier at 1 (mode k''s plane)', distance(first), 0.0_dp, bound, scale=1.0_dp)
      call t%check_close('a second at 1', distance(second), 0.0_dp, bound, scale=1.0_dp)
   end subroutine check_unit_pair
end program test_autonomous_linear
