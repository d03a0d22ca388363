!> Continuation without contact against the discrete scheme's harmonic steady state
!! (issue 20, item 2; docs/method.md, "Continuation of periodic orbits"). The scene is
!! continued in its forcing frequency (`continue_branch`); at every branch point Omega_k,
!! the reference is the scheme's harmonic steady state at Omega_k with dt = T_k/P
!! (`harmonic_steady_state`: a complex linear system from the dense M, K, no stepper, no
!! period map, as test_periodic_linear), and the point's state must equal it to the
!! round-off bound derived below, and each of its Floquet multipliers lambda_k^P, lambda_k
!! the eigenvalues of the scheme's one-step matrix there (`check_multipliers`). A linear response curve has no fold, period doubling
!! or Neimark-Sacker point: none may be reported, every point is stable, and the branch
!! runs monotonically in Omega across the resonance to the bound.
!! Usage: test_continuation_linear SCENE.nml (kind = 'periodic', &periodic parameter =
!! 'load.point_frequency', parameter_max given, no obstacle reached).
program test_continuation_linear
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_periodic_settings, only: period_step
   use vibrobeam_periodic_reference, only: energy_gram, energy_norm, cancellation, fixed_point_condition, &
      amplification_matrix, harmonic_steady_state, matrix_power, continue_test_branch, check_multipliers
   use vibrobeam_continuation, only: continuation_branch
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, local
   type(run_problem) :: prepared, at_point
   type(continuation_branch) :: branch
   character(len=512) :: path
   real(dp), allocatable :: mass(:, :), stiffness(:, :), damping(:, :), gram(:, :), x_ref(:), a(:, :)
   complex(dp), allocatable :: harmonic(:)
   real(dp) :: omega, omega0, dt, error, bound, noise, worst, norm_ratio, largest_bound, worst_multipliers
   integer :: k, n, info, steps_per_period
   integer(int64) :: steps

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call continue_test_branch(t, 'test_continuation_linear', scene, prepared, branch)
   call t%check_true('more than 10 points', size(branch%points) > 10)
   call t%check_true('no bifurcation on a linear response curve', size(branch%bifurcations) == 0)
   call t%check_true('Omega increases monotonically along the branch (no fold)', &
                     all(branch%points(2:)%parameter > branch%points(:size(branch%points) - 1)%parameter))
   call t%check_true('the branch crosses the first resonance and ends within 4 steps of parameter_max', &
                     branch%points(size(branch%points))%parameter > scene%periodic%parameter_max - &
                     4*scene%periodic%step)
   call t%check_true('every point is stable (|mu| < 1)', &
                     all([(hypot(branch%points(k)%multipliers(1, 1), branch%points(k)%multipliers(2, 1)) < 1, &
                           k=1, size(branch%points))]))

   steps_per_period = scene%periodic%steps_per_period
   omega0 = scene%load%point_frequency
   worst = 0
   worst_multipliers = 0
   largest_bound = 0
   do k = 1, size(branch%points)
      omega = branch%points(k)%parameter
      local = scene
      local%load%point_frequency = omega
      dt = period_step(omega, steps_per_period)
      local%time%dt = dt
      call prepare_test_scene(local, at_point)
      n = at_point%system%model%unknowns
      mass = band_to_dense(at_point%system%model%mass)
      stiffness = band_to_dense(at_point%system%model%stiffness)
      damping = scene%beam%rayleigh_mass*mass + scene%beam%rayleigh_stiffness*stiffness
      call harmonic_steady_state(at_point, mass, stiffness, damping, dt, scene%time%theta, omega, harmonic, info)
      call t%check_true('zgesv solves the harmonic system', info == 0)
      x_ref = real(harmonic)
      gram = energy_gram(at_point, omega)
      a = amplification_matrix(mass, stiffness, damping, dt, scene%time%theta)
      steps = int(steps_per_period, int64)*scene%periodic%period_multiple
      ! Bound (as test_periodic_linear): the corrector stops at a relative residual <=
      ! tolerance, measured in the energy norm at the start's Omega0; in the norm at
      ! Omega the U part's weight K + Omega^2 M differs from K + Omega0^2 M by at most
      ! the factor norm_ratio^2 = max(Omega/Omega0, Omega0/Omega)^2, numerator and
      ! denominator of the relative residual each by norm_ratio at most. With the map's
      ! noise 8 eps P rho(x_ref) the fixed point is within ||(I - M)^-1|| (norm_ratio^2
      ! tolerance + 2 noise) of the exact one, relative.
      norm_ratio = max(omega/omega0, omega0/omega)
      noise = 8*epsilon(1.0_dp)*real(steps, dp)*cancellation(gram, x_ref)
      bound = fixed_point_condition(gram, matrix_power(a, steps))*(norm_ratio**2*scene%periodic%tolerance + 2*noise)
      error = energy_norm(gram, branch%points(k)%x - x_ref)/energy_norm(gram, x_ref)
      worst = max(worst, error/bound)
      largest_bound = max(largest_bound, bound)
      call t%check_close('branch point against the harmonic steady state at its Omega (energy norm, relative)', &
                         error, 0.0_dp, bound, scale=1.0_dp)
      ! every multiplier of the point (/periodic/branch/floquet_multipliers) against
      ! lambda_k^P of the scheme at its Omega and dt
      worst_multipliers = max(worst_multipliers, check_multipliers(t, branch%points(k)%multipliers, a, steps, &
                                                                   branch%monodromy, noise, gram))
   end do
   write (*, '(a,es10.3)') 'Floquet multipliers at every point: largest error / bound ', worst_multipliers
   write (*, '(a,es10.3,a,es10.3)') 'states: largest error / bound ', worst, ', largest bound ', largest_bound
   call t%check_true('the bounds are round-off bounds (< 1e-6)', largest_bound < 1e-6_dp)
   call t%finish('test_continuation_linear')

end program test_continuation_linear
