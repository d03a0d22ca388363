!> Every stable point of a continued branch is the state time marching settles to (issue
!! 20, acceptance "Agreement with time marching"; docs/method.md, "Continuation of
!! periodic orbits"). The branch: `continue_branch` on a scene with compliant stops whose
!! response curve folds (continuation_fold.nml). At each stable point (every multiplier
!! inside the unit circle) the dynamics run's stepper and loop (`new_stepper`, `advance`)
!! march the scene at that point's forcing frequency (dt = T/P, P kept) from the point's
!! state moved by 1e-3 of itself, over `periods` forcing periods; its state x_N at the
!! last whole period must equal the point's x* to
!!    ||x_N - x*|| <= ||(I - M)^-1|| (r_N + c^2 tolerance + 2 noise)   (relative, energy norm)
!! with r_N = ||x_{N+1} - x_N|| the marched states' own residual (to first order, a
!! state whose period map moves it by r lies ||(I - M)^-1|| r from the fixed point), M
!! the monodromy at x* (forward differences of the map, as the continuation takes it),
!! tolerance the corrector's (relative in the start's energy norm: c = max(Omega/Omega0,
!! Omega0/Omega) converts it, as in test_continuation_linear) and noise = 8 eps P rho(x*)
!! the round-off of one orbit (test_periodic_linear). Usage: test_continuation_marching
!! SCENE.nml PERIODS.
program test_continuation_marching
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: outcome_ok
   use vibrobeam_scene, only: scene_type, forcing_period_steps
   use vibrobeam_problem, only: run_problem, stepper_settings_of
   use vibrobeam_time_stepper, only: time_stepper, dynamic_state
   use vibrobeam_stepper_factory, only: new_time_stepper, release_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_run_loop, only: advance
   use vibrobeam_periodic_settings, only: period_step
   use vibrobeam_period_map, only: period_map, map_image, jacobian_differences
   use vibrobeam_continuation, only: continuation_branch, continue_branch
   use vibrobeam_periodic_reference, only: energy_gram, energy_norm, cancellation, fixed_point_condition
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, local
   type(run_problem) :: prepared, at_point
   type(continuation_branch) :: branch
   type(period_map) :: map
   type(map_image) :: image
   type(dynamic_state) :: start
   character(len=512) :: path, argument, errmsg, failure
   real(dp), allocatable :: gram(:, :), last(:), before(:)
   real(dp) :: omega, omega0, noise, condition, residual, error, bound, scale, worst, c
   integer(int64) :: period_steps
   integer :: stat, status, periods, k, unknowns, stable

   call get_command_argument(1, path)
   call get_command_argument(2, argument)
   read (argument, *) periods
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call continue_branch(scene, prepared, branch, stat, errmsg)
   call t%check_true('continue_branch runs', stat == 0, trim(errmsg))
   if (stat /= 0) call t%finish('test_continuation_marching')
   call t%check_true('the branch reached its end without failure', len_trim(branch%failure) == 0, trim(branch%failure))
   period_steps = forcing_period_steps(scene)
   unknowns = prepared%system%model%unknowns
   omega0 = scene%load%point_frequency
   worst = 0
   stable = 0
   do k = 1, size(branch%points)
      associate (point => branch%points(k))
         if (.not. hypot(point%multipliers(1, 1), point%multipliers(2, 1)) < 1) cycle
         stable = stable + 1
         omega = point%parameter
         local = scene
         local%load%point_frequency = omega
         local%time%dt = period_step(omega, int(period_steps))
         call prepare_test_scene(local, at_point)
         ! the monodromy at the point, by differences (the continuation's own way)
         map%steps = period_steps*scene%periodic%period_multiple
         map%unknowns = unknowns
         map%omega = omega
         call map%evaluate(local, at_point, point%x, jacobian_differences, image, stat, errmsg)
         if (stat /= 0 .or. image%status /= outcome_ok) error stop 'the monodromy at a branch point'
         gram = energy_gram(at_point, omega)
         condition = fixed_point_condition(gram, image%jacobian)
         noise = 8*epsilon(1.0_dp)*real(map%steps, dp)*cancellation(gram, point%x)
         ! time marching from the point's state moved by 1e-3 of itself
         start%u = 1.001_dp*point%x(1:unknowns)
         start%v = 1.001_dp*point%x(unknowns + 1:)
         call march(local, at_point, start, map%steps, before, last)
         scale = energy_norm(gram, point%x)
         residual = energy_norm(gram, last - before)/scale
         c = max(omega/omega0, omega0/omega)
         error = energy_norm(gram, before - point%x)/scale
         bound = condition*(residual + c**2*scene%periodic%tolerance + 2*noise)
         worst = max(worst, error/bound)
         write (*, '(a,i3,a,f9.4,a,f8.5,a,es10.3,a,es10.3,a,es10.3)') 'point ', k, ': Omega ', omega, &
            ' rad/s, largest |mu| ', hypot(point%multipliers(1, 1), point%multipliers(2, 1)), &
            ', marched state against it ', error, ' (bound ', bound, ', residual ', residual
         call t%check_close('the marched state against the stable branch point (energy norm, relative)', error, &
                            0.0_dp, bound, scale=1.0_dp)
      end associate
   end do
   write (*, '(i0,a,i0,a,es10.3)') stable, ' stable points of ', size(branch%points), ': largest error / bound ', worst
   call t%check_true('the branch has stable points on both sides of its folds (more than 10)', stable > 10)
   call t%finish('test_continuation_marching')

contains

   !> March `scene` from `start` over periods + 1 orbits of `steps` steps: the states after
   !! `periods` orbits (`before`) and after one more (`last`).
   subroutine march(scene, prepared, start, steps, before, last)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(dynamic_state), intent(in) :: start
      integer(int64), intent(in) :: steps
      real(dp), allocatable, intent(out) :: before(:), last(:)
      class(time_stepper), allocatable :: stepper
      type(dynamics_recorder) :: recorder
      integer(int64) :: n
      call new_time_stepper(prepared%system, stepper_settings_of(scene), start, stepper, stat, errmsg)
      if (stat /= 0) error stop 'new_time_stepper'
      call recorder%init(scene, stepper, prepared, (periods + 1)*steps, write_rows=.false.)
      do n = 1, (periods + 1)*steps
         call advance(stepper, recorder, prepared%model, n, status, failure, stat, errmsg)
         if (stat /= 0 .or. status /= outcome_ok) error stop 'time marching failed'
         if (n == periods*steps) before = [stepper%u, stepper%v]
      end do
      last = [stepper%u, stepper%v]
      call release_stepper(stepper)
   end subroutine march
end program test_continuation_marching
