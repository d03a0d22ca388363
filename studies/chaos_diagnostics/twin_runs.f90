!> Why two runs started 1e-9 m apart do not separate where the 0-1 test says chaos (issue
!! 20, item 3; studies/chaos_diagnostics/REPORT.md, docs/method.md "Chaos diagnostics: why
!! twin runs do not separate").
!!
!! A scene is marched SETTLE forcing periods (onto its attractor); there a twin is made, the
!! same state with the tip's displacement moved by delta, and both are marched MEASURE more
!! periods, step by step with the stepper of a dynamics run. Printed, per delta:
!! - the tip separation |u_A - u_B| after 1, 10, 100 periods and at the end, its largest
!!   over the run, and the first period where it exceeds `apart` (a tenth of the gap: the
!!   twins are on different trajectories), or 'never';
!! - the steps in which the twins' steps took different pieces of the map (the held
!!   contact points differ: one had an impulse, or its springs a force, where the other
!!   had none), and whether the twins end identical bit for bit;
!! and once, for the reference run over the same periods, the largest Lyapunov exponent of
!! the discrete map by its tangent (`linearise_step`, renormalised every period; 1/s and
!! per period).
!! usage: twin_runs SCENE.nml DT SETTLE MEASURE DELTA [DELTA ...]   (DT 0: the scene's)
program twin_runs
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_scene, only: scene_type, forcing_of
   use vibrobeam_problem, only: run_problem, new_stepper, stepper_settings_of
   use vibrobeam_time_stepper, only: time_stepper, dynamic_state, energy_norm
   use vibrobeam_stepper_factory, only: new_time_stepper, release_stepper, linearise_step
   use vibrobeam_model, only: node_row
   use vibrobeam_state_record, only: state_record
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene, same_bits
   implicit none
   type(scene_type) :: scene
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: reference
   type(dynamic_state) :: settled
   type(state_record) :: record
   character(len=512) :: path, argument, errmsg
   character(len=:), allocatable :: load
   real(dp) :: omega, phase, period, dt, delta, growth, norm, apart
   real(dp), allocatable :: du(:, :), dv(:, :)
   integer(int64) :: settle, measure, steps_per_period, n, total, renormalised
   integer :: stat, k, dofs(4)
   real(dp) :: weights(4)

   call get_command_argument(1, path)
   call get_command_argument(2, argument)
   read (argument, *) dt
   call get_command_argument(3, argument)
   read (argument, *) settle
   call get_command_argument(4, argument)
   read (argument, *) measure
   scene = read_test_scene(trim(path))
   if (dt > 0) scene%time%dt = dt
   call prepare_test_scene(scene, prepared)
   load = forcing_of(scene, omega, phase)
   period = 2*pi/omega
   steps_per_period = nint(period/scene%time%dt, int64)
   call node_row(prepared%model, prepared%model%elements, dofs, weights)
   apart = 0.1_dp*minval(abs(scene%obstacles%level_from))
   write (*, '(a,a,a,es10.3,a,i0,a,i0,a,i0,a)') 'scene ', trim(path), ', dt = ', scene%time%dt, ' s (', &
      steps_per_period, ' steps a forcing period), ', settle, ' periods to settle, ', measure, ' measured'

   ! ---- the reference: settle, then the tangent's exponent over the measured periods ----
   call new_stepper(scene, prepared, reference, stat, errmsg)
   if (stat /= 0) error stop 'new_stepper'
   do n = 1, settle*steps_per_period
      call reference%step(stat, errmsg)
      if (stat /= 0) error stop 'the settling failed'
   end do
   settled = reference%state()
   call reference%save_state(record)   ! the twins start from it (its step number and loads)
   total = measure*steps_per_period
   allocate (du(size(reference%u), 1), dv(size(reference%u), 1), source=0.0_dp)
   dv(:, 1) = 1
   dv(:, 1) = dv(:, 1)/energy_norm(reference%mass, reference%stiffness, omega, du(:, 1), dv(:, 1))
   growth = 0
   renormalised = 0
   do n = 1, total
      call reference%step(stat, errmsg)
      if (stat /= 0) error stop 'the reference run failed'
      call linearise_step(reference, du, dv, stat, errmsg)
      if (stat /= 0) then
         write (*, '(a)') 'the tangent stopped: '//trim(errmsg)
         exit
      end if
      if (mod(n, steps_per_period) == 0) then
         norm = energy_norm(reference%mass, reference%stiffness, omega, du(:, 1), dv(:, 1))
         ! the first tenth of the periods aligns the perturbation: left out
         if (n > total/10) then
            growth = growth + log(norm)
            renormalised = renormalised + 1
         end if
         du = du/norm
         dv = dv/norm
      end if
   end do
   if (renormalised > 0) write (*, '(a,es11.4,a,es11.4,a,i0,a)') 'tangent exponent ', &
      growth/(renormalised*period), ' 1/s (', growth/renormalised, ' per forcing period, ', renormalised, ' periods)'
   call release_stepper(reference)

   ! ---- the twins ----
   write (*, '(a)') '     delta (m)   sep@1 (m)  sep@10 (m) sep@100 (m)  sep@end (m)  max sep (m)  apart at  '// &
      'piece steps  identical'
   do k = 5, command_argument_count()
      call get_command_argument(k, argument)
      read (argument, *) delta
      call twins(delta)
   end do

contains

   !> The tip's displacement of `stepper`.
   real(dp) function tip(stepper)
      class(time_stepper), intent(in) :: stepper
      integer :: i
      tip = 0
      do i = 1, 4
         if (dofs(i) /= 0) tip = tip + weights(i)*stepper%u(dofs(i))
      end do
   end function tip

   !> The contact points `stepper`'s last step held (a rigid impulse) or pushed (a spring's
   !! force), as a set: the piece of the map the step took.
   function held(stepper) result(points)
      class(time_stepper), intent(in) :: stepper
      logical :: points(stepper%contacts%count)
      integer :: j
      points = abs(stepper%report%contact_force) > 0
      do j = 1, stepper%report%active_count
         if (abs(stepper%report%impulse(j)) > 0) points(stepper%report%active(j)) = .true.
      end do
   end function held

   !> The twins from the settled state, the second's tip moved by delta.
   subroutine twins(delta)
      real(dp), intent(in) :: delta
      class(time_stepper), allocatable :: a, b
      type(dynamic_state) :: moved
      real(dp) :: separation, largest, at(3)
      integer(int64) :: pieces, first_apart, m
      integer :: i
      moved = settled
      do i = 1, 4
         if (dofs(i) /= 0) moved%u(dofs(i)) = moved%u(dofs(i)) + delta*weights(i)/sum(weights**2)
      end do
      call new_time_stepper(prepared%system, stepper_settings_of(scene), settled, a, stat, errmsg, resume=record)
      if (stat == 0) call new_time_stepper(prepared%system, stepper_settings_of(scene), settled, b, stat, errmsg, &
                                           resume=record)
      if (stat /= 0) error stop 'the twins'' steppers'
      b%u = moved%u
      pieces = 0
      largest = abs(tip(a) - tip(b))
      first_apart = -1
      at = 0
      do m = 1, total
         call a%step(stat, errmsg)
         if (stat == 0) call b%step(stat, errmsg)
         if (stat /= 0) error stop 'a twin failed'
         if (any(held(a) .neqv. held(b))) pieces = pieces + 1
         separation = abs(tip(a) - tip(b))
         largest = max(largest, separation)
         if (first_apart < 0 .and. separation > apart) first_apart = (m - 1)/steps_per_period + 1
         if (m == steps_per_period) at(1) = separation
         if (m == 10*steps_per_period) at(2) = separation
         if (m == 100*steps_per_period) at(3) = separation
      end do
      if (first_apart > 0) then
         write (*, '(6es12.3,i10,i13,l11)') delta, at, separation, largest, first_apart, pieces, &
            all(same_bits(a%u, b%u)) .and. all(same_bits(a%v, b%v))
      else
         write (*, '(6es12.3,a10,i13,l11)') delta, at, separation, largest, 'never', pieces, &
            all(same_bits(a%u, b%u)) .and. all(same_bits(a%v, b%v))
      end if
      call release_stepper(a)
      call release_stepper(b)
   end subroutine twins
end program twin_runs
