!> Agreement of a periodic orbit with impacts, found by shooting, with the state a long
!! time-marching run settles to (issue 20, "Agreement with time marching"; docs/method.md,
!! "Periodic orbits by shooting").
!!
!! The orbit: `find_periodic_orbit` on the scene (converged, stable: every Floquet
!! multiplier inside the unit circle). The marching: the stepper of a dynamics run
!! (`new_stepper`, the one run loop `advance`) from the scene's initial state over
!! `periods` forcing periods, its state x_j kept at every whole forcing period j.
!!
!! Checked:
!! - the same period: the marched states repeat after k = period_multiple forcing periods
!!   (||x_{N+k} - x_N|| at the noise of the map) and, for k > 1, not after fewer
!!   (||x_{N+i} - x_N|| > 1e-3 ||x_N|| for 1 <= i < k);
!! - the same orbit: ||x_N - x*|| <= ||(I - M)^-1|| (r_N + tolerance + 2 noise) relative
!!   (energy norm), x* the orbit's state, x_N the marched state of the last periods at
!!   its phase (Newton may find an orbit of k periods at any of its k phases), r_N the
!!   marched states' own residual ||x_{N+k} - x_N||, M the orbit's monodromy: on one affine piece of the
!!   discrete map two states whose residuals are r_N and the tolerance lie that far
!!   apart at most; noise = 8 eps P rho (the round-off of one evaluation, see
!!   test_periodic_linear);
!! - the tip over the orbit's period equals the marched tip over its last k periods to
!!   the same bound times the tip's dual norm (as in test_periodic_linear);
!! - the monodromy by the linearised steps (through the held contact points, Newton's law
!!   per point) equals central differences of the map at the orbit to their round-off.
!! It prints the periods the marching needed to come within the tolerance of the orbit
!! (the transient the orbit replaces). Usage: test_periodic_marching SCENE.nml PERIODS.
program test_periodic_marching
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_status, only: outcome_ok
   use vibrobeam_scene, only: scene_type, forcing_period_steps
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_stepper_factory, only: release_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_run_loop, only: advance
   use vibrobeam_periodic_analysis, only: find_periodic_orbit, periodic_orbit
   use vibrobeam_period_map, only: map_image, jacobian_none
   use vibrobeam_periodic_reference, only: energy_gram, energy_norm, cancellation, fixed_point_condition, solve_dense
   use vibrobeam_model, only: node_row
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(periodic_orbit) :: orbit
   type(map_image) :: plus, minus
   class(time_stepper), allocatable :: stepper
   type(dynamics_recorder) :: recorder
   character(len=512) :: path, argument, errmsg, failure
   real(dp), allocatable :: gram(:, :), states(:, :), tip(:), tip_row(:), b(:, :)
   real(dp) :: omega, noise, condition, residual, error, bound, scale, distance, dual, worst, fraction, step_size
   real(dp), allocatable :: shifted(:), column(:)
   integer(int64) :: period_steps, n, first_tip
   integer :: stat, status, periods, k, j, unknowns, settled, dofs(4), i
   real(dp) :: weights(4)

   call get_command_argument(1, path)
   call get_command_argument(2, argument)
   read (argument, *) periods
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   k = scene%periodic%period_multiple
   period_steps = forcing_period_steps(scene)
   unknowns = prepared%system%model%unknowns

   ! ---- the orbit by shooting ----
   call find_periodic_orbit(scene, prepared, orbit, stat, errmsg)
   call t%check_true('find_periodic_orbit runs', stat == 0, trim(errmsg))
   if (stat /= 0) call t%finish('test_periodic_marching')
   call t%check_true('Newton''s method converged', orbit%converged, trim(orbit%failure))
   call t%check_true('the orbit is stable (every multiplier inside the unit circle)', &
                     hypot(orbit%multipliers(1, 1), orbit%multipliers(2, 1)) < 1)
   write (*, '(a,i0,a,es10.3,a,f9.6,a,i0,a)') 'orbit: ', orbit%iterations, ' Newton iterations, residual ', &
      orbit%residuals(size(orbit%residuals)), ', largest multiplier modulus ', &
      hypot(orbit%multipliers(1, 1), orbit%multipliers(2, 1)), ', ', orbit%map%steps_taken, ' steps in all'

   ! ---- time marching: the dynamics run's stepper and loop, a state per forcing period ----
   call new_stepper(scene, prepared, stepper, stat, errmsg)
   if (stat /= 0) error stop 'new_stepper'
   call recorder%init(scene, stepper, prepared, periods*period_steps, write_rows=.false.)
   allocate (states(2*unknowns, 0:periods), tip(0:periods*period_steps))
   states(:, 0) = [stepper%u, stepper%v]
   call recorder%observe(stepper)
   tip(0) = recorder%events%observed(1, 1)
   do n = 1, periods*period_steps
      call advance(stepper, recorder, prepared%model, n, status, failure, stat, errmsg)
      if (stat /= 0 .or. status /= outcome_ok) error stop 'time marching failed'
      call recorder%observe(stepper)
      tip(n) = recorder%events%observed(1, 1)
      if (mod(n, period_steps) == 0) states(:, n/period_steps) = [stepper%u, stepper%v]
   end do
   call release_stepper(stepper)

   ! ---- comparison at the orbit's phase: Newton finds a fixed point of the k-period map,
   ! at whichever of the orbit's k phases its start was nearest; the marched state of the
   ! last k + 1 periods nearest to it is at that phase ----
   omega = 2*pi/(period_steps*scene%time%dt)
   gram = energy_gram(prepared, omega)
   noise = 8*epsilon(1.0_dp)*real(orbit%map%steps, dp)*cancellation(gram, orbit%x)
   condition = fixed_point_condition(gram, orbit%image%jacobian)
   scale = energy_norm(gram, orbit%x)
   j = periods - k
   do i = periods - 2*k + 1, periods - k
      if (energy_norm(gram, states(:, i) - orbit%x) < energy_norm(gram, states(:, j) - orbit%x)) j = i
   end do
   residual = energy_norm(gram, states(:, j + k) - states(:, j))/scale
   call t%check_close('marched states repeat after k forcing periods (relative residual)', residual, 0.0_dp, &
                      max(scene%periodic%tolerance, 2*noise), scale=1.0_dp)
   do i = 1, k - 1
      distance = energy_norm(gram, states(:, j + i) - states(:, j))/scale
      call t%check_true('marched states do not repeat after fewer than k forcing periods', distance > 1e-3_dp)
   end do
   error = energy_norm(gram, states(:, j) - orbit%x)/scale
   bound = condition*(residual + scene%periodic%tolerance + 2*noise)
   write (*, '(a,i0,a,es10.3,a,es10.3,a,es10.3,a,es10.3,a)') 'marched state after ', j, ' periods against the orbit: ', &
      error, ' (bound ', bound, '; ||(I - M)^-1|| = ', condition, ', noise ', noise, ')'
   call t%check_close('marched state against the orbit (energy norm, relative)', error, 0.0_dp, bound, scale=1.0_dp)
   call t%check_true('the bound is tight enough to tell orbits apart (< 1e-6)', bound < 1e-6_dp)

   ! the tip over the last k periods against the orbit's tip
   call node_row(prepared%model, prepared%model%elements, dofs, weights)
   allocate (tip_row(unknowns), source=0.0_dp)
   do i = 1, 4
      if (dofs(i) /= 0) tip_row(dofs(i)) = tip_row(dofs(i)) + weights(i)
   end do
   b = reshape(tip_row, [unknowns, 1])
   call solve_dense(gram(1:unknowns, 1:unknowns), b)
   dual = sqrt(dot_product(tip_row, b(:, 1)))
   first_tip = j*period_steps
   error = maxval(abs(tip(first_tip:first_tip + orbit%map%steps) - orbit%image%tip(1, :)))
   bound = 2*bound*scale*dual
   write (*, '(a,es10.3,a,es10.3,a,es10.3,a)') 'tip over the last period against the orbit''s: ', error, ' m (bound ', &
      bound, ' m, peak ', maxval(abs(orbit%image%tip(1, :))), ' m)'
   call t%check_close('tip over the period against the marched tip (m)', error, 0.0_dp, bound, scale=1.0_dp)

   ! the linearised monodromy through the impacts against central differences of the map
   ! at the orbit, taken here from runs of the plain map (an independent derivative). On
   ! one affine piece a difference quotient is exact but for the round-off of its two
   ! runs: with a perturbation of `fraction` ||x|| in the energy norm, column j errs by
   ! 2 noise/fraction per unit of perturbation (a factor 2 beside it). fraction = 1e-4
   ! moves the tip by about 1e-4 of its amplitude, 7e-8 m here, far less than a step's
   ! travel |v| dt (2e-6 m at the impacts), so the perturbed runs stay on the orbit's
   ! pieces; a column that left them (an impact moved to another step) would be off by
   ! O(1), and a wrong linearisation of the held points by its own size (1 % off in
   ! the restitution term of `tangent` moves a column by 2e-5: caught, tried).
   ! With compliant stops the orbit's monodromy is itself by differences ('auto'): there is
   ! no linearisation to check, and forward differences are not exact to this bound.
   worst = 0
   fraction = 1e-4_dp
   if (orbit%monodromy /= 'linearised') write (*, '(3a)') 'monodromy by ', trim(orbit%monodromy), &
      ': no linearised steps to check against central differences'
   if (orbit%monodromy == 'linearised') then
      do i = 1, 2*unknowns
         step_size = fraction*scale/sqrt(gram(i, i))
         shifted = orbit%x
         shifted(i) = shifted(i) + step_size
         call orbit%map%evaluate(scene, prepared, shifted, jacobian_none, plus, stat, errmsg)
         shifted(i) = orbit%x(i) - step_size
         call orbit%map%evaluate(scene, prepared, shifted, jacobian_none, minus, stat, errmsg)
         if (stat /= 0 .or. plus%status /= outcome_ok .or. minus%status /= outcome_ok) error stop 'map evaluation failed'
         column = (plus%state - minus%state)/(2*step_size)
         worst = max(worst, energy_norm(gram, column - orbit%image%jacobian(:, i))/sqrt(gram(i, i)))
      end do
      bound = 4*noise/fraction
      write (*, '(a,es10.3,a,es10.3,a)') 'monodromy, linearised against central differences: largest column error ', &
         worst, ' (bound ', bound, ')'
      call t%check_close('linearised monodromy against differences (energy norm per unit perturbation)', worst, 0.0_dp, &
                         bound, scale=1.0_dp)
   end if

   ! the transient the orbit replaces: periods until the marched state is within the
   ! tolerance of the orbit at its phase
   settled = -1
   do i = 0, periods
      if (modulo(i - j, k) /= 0) cycle
      if (energy_norm(gram, states(:, i) - orbit%x) <= scene%periodic%tolerance*scale) then
         settled = i
         exit
      end if
   end do
   write (*, '(a,i0,a,i0,a,i0,a)') 'time marching came within the tolerance of the orbit after ', settled, &
      ' forcing periods (', settled*period_steps, ' steps; the shooting took ', orbit%map%steps_taken, ')'
   call t%check_true('time marching reaches the orbit within the periods run', settled >= 0)
   call t%finish('test_periodic_marching')
end program test_periodic_marching
