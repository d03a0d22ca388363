!> What every evaluation of a continuation needs and the evaluations themselves (docs/method.md,
!! "Continuation of periodic orbits"): the context (the base scene, the period maps, the
!! scaled coordinates), the scene and its problem at a value lambda of the parameter (dt =
!! T/P for the forcing there, P kept), Phi(x, lambda), dPhi/dlambda by a forward
!! difference, and the relative residual; `vibrobeam_continuation` predicts, corrects
!! and locates with them.
module vibrobeam_continuation_map
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure, outcome_ok, outcome_failed
   use vibrobeam_text, only: real_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_scene_values, only: set_real_input
   use vibrobeam_sweep_axis, only: sweep_axis
   use vibrobeam_periodic_settings, only: forcing_frequency, period_step
   use vibrobeam_problem, only: run_problem, build_problem
   use vibrobeam_period_map, only: period_map, map_image, jacobian_none, jacobian_linearised, difference_fraction
   implicit none
   private
   public :: continuation_context, omega_at, problem_at, scene_at_parameter, evaluate_at, parameter_derivative, residual

   !> What every evaluation needs: the base scene, the period map, the scaling.
   type :: continuation_context
      type(scene_type) :: scene
      type(sweep_axis) :: axis
      integer(int64) :: period_steps = 0                !! P, steps per forcing period, kept along the branch
      type(period_map) :: map
      !> of k = period_multiple/2 periods when that is whole (steps 0: none): the branch point test
      type(period_map) :: half_map
      !> Phi_k(x) - x of the last point kept: the sign of the branch point test
      real(dp), allocatable :: shift_reference(:)
      type(run_problem) :: reference                   !! the start's problem: the norm of the residual
      !> (2 J + 1) the weights of the scaled coordinates: of each unknown the square root
      !! of its diagonal weight in the energy norm, of lambda 1 over the parameter's scale
      real(dp), allocatable :: weights(:)
      real(dp) :: largest_size = 0                     !! the largest weighted size of a point's x so far
      integer :: jacobian = jacobian_linearised
      real(dp) :: tolerance = 0
   end type continuation_context

contains

   !> The forcing frequency of the scene at lambda (rad/s).
   real(dp) function omega_at(run, lambda)
      type(continuation_context), intent(in) :: run
      real(dp), intent(in) :: lambda
      type(scene_type) :: local
      character(len=:), allocatable :: problem
      logical :: found
      local = run%scene
      call set_real_input(local, run%axis%group, run%axis%name, run%axis%index, lambda, found)
      call forcing_frequency(local%load, omega_at, problem)
   end function omega_at

   !> The scene at lambda, with dt = T/P for the scene's forcing there (P kept), and its
   !! problem. stat /= 0: the harmonic loads no longer share one frequency, or the problem
   !! cannot be built.
   subroutine problem_at(run, lambda, local, prepared, stat, errmsg)
      type(continuation_context), intent(in) :: run
      real(dp), intent(in) :: lambda
      type(scene_type), intent(out) :: local
      type(run_problem), intent(out) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call scene_at_parameter(run%scene, run%axis, run%period_steps, lambda, local, prepared, stat, errmsg)
   end subroutine problem_at

   !> `scene` with its input `axis` at lambda and dt = T/`period_steps` for its forcing
   !! there, in `local`, and its problem (`problem_at`; a branch switch's start).
   subroutine scene_at_parameter(scene, axis, period_steps, lambda, local, prepared, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_axis), intent(in) :: axis
      integer(int64), intent(in) :: period_steps
      real(dp), intent(in) :: lambda
      type(scene_type), intent(out) :: local
      type(run_problem), intent(out) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: problem, warnings
      real(dp) :: omega
      logical :: found
      local = scene
      call set_real_input(local, axis%group, axis%name, axis%index, lambda, found)
      call forcing_frequency(local%load, omega, problem)
      if (len(problem) > 0 .or. .not. omega > 0) then
         stat = stat_failure
         errmsg = 'at '//trim(axis%parameter)//' = '//real_text(lambda)//' the scene '//problem
         return
      end if
      local%time%dt = period_step(omega, int(period_steps))
      warnings = ''
      call build_problem(local, prepared, warnings, stat, errmsg)
   end subroutine scene_at_parameter

   !> Phi(x, lambda) (with the monodromy by `jacobian`) in `image`; a lambda at which the
   !! scene cannot be built is image%status = outcome_failed with the reason.
   subroutine evaluate_at(run, x, lambda, jacobian, image, stat, errmsg)
      type(continuation_context), intent(inout) :: run
      real(dp), intent(in) :: x(:), lambda
      integer, intent(in) :: jacobian
      type(map_image), intent(out) :: image
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(scene_type) :: local
      type(run_problem) :: prepared
      call problem_at(run, lambda, local, prepared, stat, errmsg)
      if (stat /= 0) then
         ! (a corrector that wandered out of the parameter's domain: a failed evaluation)
         image%status = outcome_failed
         image%failure = errmsg
         stat = 0
         errmsg = ''
         return
      end if
      call run%map%evaluate(local, prepared, x, jacobian, image, stat, errmsg)
   end subroutine evaluate_at

   !> dPhi/dlambda at (x, lambda) by a forward difference, h = sqrt(eps) max(|lambda|,
   !! 1/scale_lambda) (the step actually taken after rounding), from `image` = Phi(x,
   !! lambda). `ok` false when the shifted evaluation failed (errmsg says why).
   subroutine parameter_derivative(run, x, lambda, image, derivative, ok, stat, errmsg)
      type(continuation_context), intent(inout) :: run
      real(dp), intent(in) :: x(:), lambda
      type(map_image), intent(in) :: image
      real(dp), allocatable, intent(out) :: derivative(:)
      logical, intent(out) :: ok
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(map_image) :: shifted
      real(dp) :: moved
      moved = lambda + difference_fraction*max(abs(lambda), 1/run%weights(size(run%weights)))
      call evaluate_at(run, x, moved, jacobian_none, shifted, stat, errmsg)
      ok = stat == 0 .and. shifted%status == outcome_ok
      if (stat == 0 .and. .not. ok) errmsg = 'dPhi/dlambda: '//trim(shifted%failure)
      if (.not. ok) return
      derivative = (shifted%state - image%state)/(moved - lambda)
   end subroutine parameter_derivative

   !> ||Phi(x) - x|| relative to max(||x||, ||Phi(x)||), in the start's energy norm.
   real(dp) function residual(run, x, image)
      type(continuation_context), intent(in) :: run
      real(dp), intent(in) :: x(:)
      type(map_image), intent(in) :: image
      real(dp) :: scale
      scale = max(run%map%norm(run%reference, x), run%map%norm(run%reference, image%state))
      residual = run%map%norm(run%reference, image%state - x)
      if (scale > 0) residual = residual/scale
   end function residual
end module vibrobeam_continuation_map
