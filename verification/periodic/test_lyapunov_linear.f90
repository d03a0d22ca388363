!> The largest Lyapunov exponent of a linear damped scene (no contact) against the
!! scheme's own closed form (issue 20, item 3; docs/statistics.md, "Period, Lyapunov
!! exponent and the 0-1 test").
!!
!! Without contact the velocity scheme is the linear recurrence x' = A x + load terms
!! (test_periodic_linear), and the tangent map of every step is A: the exponent is
!! log|lambda_1|/dt, lambda_1 the eigenvalue of A of largest modulus (dense, LAPACK
!! dgeevx, from the stepped system's M, K and C, and with &flow its force at V^n from the
!! dense modes and Connors' formula: no stepper), and the Floquet multipliers
!! of the periodic analysis are lambda_k^P, so log|lambda_1|/dt = max Re(log mu)/T.
!!
!! The run: the dynamics run's stepper, recorder and loop over the scene (&output
!! lyapunov = .true.), its statistics' 'poincare/lyapunov_exponent'. Bound: once the
!! perturbation w has aligned with the eigenvector pair of lambda_1 = |lambda_1| e^{i phi}
!! (real and imaginary parts x_r, x_i), w_n = |lambda_1|^n (a_n x_r + b_n x_i), and its
!! energy norm is |lambda_1|^n |(a_n, b_n)| times a factor between the singular values
!! s_min and s_max of [x_r x_i] in that norm, (a_n, b_n) being rotated, not scaled. The
!! exponent, the telescoped sum of log ||w|| over the retained periods' duration T', is
!! therefore within log(s_max/s_min)/T' of log|lambda_1|/dt, plus the share of the other
!! eigenvectors left at the start of the retained periods, at most
!! sqrt(2 J) (|lambda_2|/|lambda_1|)^(steps of the periods left out) relative (checked
!! to be below 1e-8 and added), plus the round-off of the sums (negligible).
!! Usage: test_lyapunov_linear SCENE.nml (a dynamics scene with &output lyapunov whose
!! obstacles, if any, are never reached).
program test_lyapunov_linear
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_status, only: outcome_ok
   use vibrobeam_scene, only: scene_type, step_count, forcing_of
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_stepper_factory, only: release_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_run_loop, only: advance
   use vibrobeam_statistics, only: statistics_result
   use vibrobeam_statistics_layout, only: group_poincare
   use vibrobeam_periodic_reference, only: amplification_matrix, eigenvalues_with_conditions, energy_gram, &
      fluid_elastic_damping
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: stepper
   type(dynamics_recorder) :: recorder
   type(statistics_result) :: outcome
   character(len=512) :: path, errmsg, failure
   character(len=:), allocatable :: warning, kind
   real(dp), allocatable :: mass(:, :), stiffness(:, :), damping(:, :), a(:, :), wr(:), wi(:), rconde(:), &
                            vectors(:, :), gram(:, :), pair(:, :)
   real(dp) :: omega, phase, period, reference, lambda, per_period, retained, left_out, remnant, bound, small(2), &
               pair_gram(2, 2), trace, determinant, largest, second
   integer(int64) :: last
   integer :: n, m, j, lead, stat, status

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call t%check_true('the scene asks for the Lyapunov exponent', scene%output%lyapunov)
   kind = forcing_of(scene, omega, phase)
   period = 2*pi/omega

   ! ---- the reference: the largest eigenvalue of the amplification matrix ----
   n = prepared%system%model%unknowns
   m = 2*n
   allocate (mass(n, n), stiffness(n, n), damping(n, n), wr(m), wi(m), rconde(m), vectors(m, m))
   mass = band_to_dense(prepared%system%model%mass)
   stiffness = band_to_dense(prepared%system%model%stiffness)
   damping = scene%beam%rayleigh_mass*mass + scene%beam%rayleigh_stiffness*stiffness
   if (scene%flow%velocity > 0) then
      ! the fluid-elastic force at V^n (the flow over the whole span of the full model,
      ! as the reference takes it: test_periodic_linear)
      if (prepared%reduced .or. scene%flow%x_from > 0) error stop 'test_lyapunov_linear: &flow over the whole span only'
      a = amplification_matrix(mass, stiffness, damping, scene%time%dt, scene%time%theta, &
                               fluid_elastic_damping(mass, stiffness, scene%flow%velocity, scene%flow%density, &
                                                     scene%flow%connors_constant, scene%beam%rho_s(), scene%flow%modes))
   else
      a = amplification_matrix(mass, stiffness, damping, scene%time%dt, scene%time%theta)
   end if
   call eigenvalues_with_conditions(a, wr, wi, rconde, vectors)
   lead = maxloc(hypot(wr, wi), dim=1)
   if (wi(lead) < 0) lead = lead - 1   ! the first column of a complex pair
   largest = hypot(wr(lead), wi(lead))
   second = 0
   do j = 1, m
      if (j == lead .or. (abs(wi(lead)) > 0 .and. j == lead + 1)) cycle
      second = max(second, hypot(wr(j), wi(j)))
   end do
   reference = log(largest)/scene%time%dt
   write (*, '(a,es22.14,a,f10.7,a,f10.7)') 'log|lambda_1|/dt = ', reference, ' 1/s; |lambda_1| = ', largest, &
      ', |lambda_2| = ', second

   ! ---- the run ----
   last = step_count(scene)
   call new_stepper(scene, prepared, stepper, stat, errmsg)
   if (stat /= 0) error stop 'new_stepper'
   call recorder%init(scene, stepper, prepared, last, write_rows=.false.)
   call recorder%start_statistics(stepper, warning)
   call advance(stepper, recorder, prepared%model, last, status, failure, stat, errmsg)
   call t%check_true('the run ends well', stat == 0 .and. status == outcome_ok, trim(failure)//trim(errmsg))
   call t%check_true('no impulse in the run (a linear scene)', recorder%impacts == 0)
   outcome = recorder%window_statistics(stepper)
   lambda = outcome%values(at('lyapunov_exponent'))
   per_period = outcome%values(at('lyapunov_exponent_per_period'))
   retained = outcome%values(at('lyapunov_periods'))
   left_out = outcome%poincare_total - retained
   call release_stepper(stepper)

   ! ---- the bound ----
   gram = energy_gram(prepared, omega)
   if (abs(wi(lead)) > 0) then
      pair = vectors(:, lead:lead + 1)
   else
      pair = reshape([vectors(:, lead), vectors(:, lead)], [m, 2])
   end if
   pair_gram = matmul(transpose(pair), matmul(gram, pair))
   trace = pair_gram(1, 1) + pair_gram(2, 2)
   determinant = pair_gram(1, 1)*pair_gram(2, 2) - pair_gram(1, 2)**2
   small = [0.5_dp*trace + sqrt(max(0.0_dp, 0.25_dp*trace**2 - determinant)), &
            0.5_dp*trace - sqrt(max(0.0_dp, 0.25_dp*trace**2 - determinant))]   ! s_max^2, s_min^2
   if (abs(wi(lead)) <= 0) small(2) = small(1)
   remnant = sqrt(real(m, dp))*(second/largest)**(left_out*period/scene%time%dt)
   call t%check_true('the periods left out align the perturbation (remnant < 1e-8)', remnant < 1e-8_dp)
   bound = (0.5_dp*log(small(1)/small(2)) + remnant + 1e-12_dp*retained)/(retained*period)
   write (*, '(a,es22.14,a,es10.3,a,es10.3,a,f7.0,a,f7.0,a)') 'Lyapunov exponent ', lambda, ' 1/s: error ', &
      lambda - reference, ', bound ', bound, ' (', retained, ' periods retained, ', left_out, ' left out)'
   call t%check_close('Lyapunov exponent against log|lambda_1|/dt (1/s)', lambda, reference, bound, scale=1.0_dp)
   call t%check_close('per forcing period: the exponent times T', per_period, lambda*period, &
                      4*epsilon(1.0_dp), scale=abs(lambda*period))
   call t%check_true('the bound is tight enough to tell the damping (< 1 % of the exponent)', bound < 1e-2_dp*abs(reference))
   call t%finish('test_lyapunov_linear')

contains

   integer function at(name)
      character(len=*), intent(in) :: name
      at = outcome%layout%entries(outcome%layout%find(group_poincare, name))%offset + 1
   end function at
end program test_lyapunov_linear
