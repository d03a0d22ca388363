!> The runs of the self-convergence study (studies/convergence: self_convergence.f90,
!! REPORT.md), shared with its test verification/dynamics/test_first_episode.f90: run the
!! velocity-based stepper on a variant of a scene, keep the histories that the comparisons need (tip, sample points, energy, impact events) and compare a run
!! with a finer one. The error measures are defined in self_convergence.f90's header.
module vibrobeam_convergence_runs
   use vibrobeam_kinds, only: dp, int64, error_unit, output_unit
   use vibrobeam_text, only: integer_text
   use vibrobeam_status, only: message_length
   use vibrobeam_scene, only: scene_type
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_model, only: point_row
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_problem, only: run_problem, build_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   implicit none
   private
   public :: event_gap, sample_points, run_history, run_errors
   public :: simulate, compare, tip_error, field_size, move_alloc_history, fail, sci, fixed, padded
   public :: coarsest_dt, joint_dt, joint_elements, rate

   real(dp), parameter :: event_gap = 5e-4_dp        !! largest gap inside one impact event (s)
   integer, parameter :: sample_points = 11          !! x_p = p L/10, p = 0..10
   real(dp), parameter :: coarsest_dt = 4e-5_dp      !! dt0 (s) of the joint path
   integer, parameter :: coarsest_elements = 16      !! N0 of the joint path

   !> What a run leaves for the comparisons: histories at every time step.
   type :: run_history
      real(dp) :: dt = 0                    !! time step (s)
      integer :: elements = 0               !! N
      integer :: steps = 0                  !! number of steps taken
      real(dp), allocatable :: tip(:)       !! (0:steps) u_h(L, t_n) (m)
      real(dp), allocatable :: field(:,:)   !! (sample_points, 0:steps) u_h(x_p, t_n) (m)
      real(dp), allocatable :: energy(:)    !! (0:steps) E^n (J)
      integer :: impulse_steps = 0          !! steps with a nonzero impulse somewhere
      real(dp) :: max_penetration = 0       !! largest penetration over the run (m)
      real(dp) :: wall_seconds = 0
      integer :: events = 0                 !! impact events (see self_convergence.f90's header)
      real(dp), allocatable :: event_first(:), event_last(:)   !! first, last impulse (s)
      integer, allocatable :: event_side(:)                    !! +1 from below, -1 from above
      integer, allocatable :: event_impulses(:)                !! steps with an impulse
   end type run_history

   !> Errors of one run against a finer one.
   type :: run_errors
      real(dp) :: tip = 0       !! max-in-time tip displacement error (m)
      real(dp) :: field = 0     !! time-RMS of the error at the sample points (m)
      real(dp) :: energy = 0    !! |E_h(T) - E_f(T)| (J)
   end type run_errors

contains

   !> Print `message` as 'PROGRAM: message' on stderr (PROGRAM: the executable's name) and stop with status 2.
   subroutine fail(message)
      character(len=*), intent(in) :: message
      character(len=4096) :: program_path
      integer :: length
      call get_command_argument(0, program_path, length)
      length = min(length, len(program_path))
      write (error_unit, '(a)') program_path(index(program_path(1:length), '/', back=.true.) + 1:length)//': '// &
         trim(message)
      stop 2, quiet=.true.
   end subroutine fail

   !> Run `scene` with time step `dt` and `elements` elements from t = 0 to `t_end` and
   !! keep the histories (tip, sample points, energy) and the impact events.
   subroutine simulate(scene, dt, elements, t_end, run)
      type(scene_type), intent(in) :: scene
      real(dp), intent(in) :: dt           !! time step (s)
      integer, intent(in) :: elements      !! N
      real(dp), intent(in) :: t_end        !! end of the run (s), a whole number of steps
      type(run_history), intent(out) :: run
      type(scene_type) :: variant
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      character(len=:), allocatable :: warnings
      character(len=message_length) :: message
      integer :: point_dofs(4, sample_points), tip_dofs(4), n, p, k, c, side, status
      real(dp) :: point_weights(4, sample_points), tip_weights(4), value
      real(dp), allocatable :: last_impulse(:)
      integer, allocatable :: last_side(:), last_event(:)
      integer(int64) :: start, finish, rate
      call system_clock(start, rate)
      variant = scene
      variant%time%dt = dt
      variant%mesh%elements = elements
      variant%time%t_end = t_end
      call validate_scene(variant, status, message)
      if (status /= 0) call fail(message)
      warnings = ''
      call build_problem(variant, prepared, warnings, status, message)
      if (status /= 0) call fail(message)
      if (len(warnings) > 0) write (error_unit, '(a)', advance='no') warnings
      call new_stepper(variant, prepared, stepper, status, message)
      if (status /= 0) call fail(message)
      run%dt = dt
      run%elements = elements
      run%steps = nint(t_end/dt)
      if (abs(run%steps*dt - t_end) > 1e-9_dp*dt) &
         call fail('t_end = '//sci(t_end)//' s is not a whole number of steps dt = '//sci(dt)//' s')
      allocate (run%tip(0:run%steps), run%field(sample_points, 0:run%steps), run%energy(0:run%steps))
      allocate (run%event_first(0), run%event_last(0), run%event_side(0), run%event_impulses(0))
      do p = 1, sample_points
         call point_row(prepared%model, scene%beam%length*(p - 1)/(sample_points - 1), point_dofs(:, p), &
                        point_weights(:, p))
      end do
      call point_row(prepared%model, scene%beam%length, tip_dofs, tip_weights)
      allocate (last_impulse(stepper%contacts%count), source=-huge(1.0_dp))
      allocate (last_side(stepper%contacts%count), last_event(stepper%contacts%count), source=0)
      call record_state(run, 0, stepper, point_dofs, point_weights, tip_dofs, tip_weights)
      do n = 1, run%steps
         call stepper%step(status, message)
         if (status /= 0) call fail('dt = '//sci(dt)//' s, N = '//integer_text(elements)//': '//trim(message))
         call record_state(run, n, stepper, point_dofs, point_weights, tip_dofs, tip_weights)
         if (any(abs(stepper%report%impulse(1:stepper%report%active_count)) > 0)) run%impulse_steps = run%impulse_steps + 1
         do k = 1, stepper%report%active_count
            if (.not. abs(stepper%report%impulse(k)) > 0) cycle
            c = stepper%report%active(k)
            side = nint(sign(1.0_dp, stepper%report%impulse(k)))   ! s_c P_c >= 0: the sign of P is s_c
            if (side /= last_side(c) .or. stepper%t - last_impulse(c) > event_gap*(1 + 1e-9_dp)) then
               run%events = run%events + 1
               run%event_first = [run%event_first, stepper%t]
               run%event_last = [run%event_last, stepper%t]
               run%event_side = [run%event_side, side]
               run%event_impulses = [run%event_impulses, 0]
               last_event(c) = run%events
               last_side(c) = side
            end if
            run%event_last(last_event(c)) = stepper%t
            run%event_impulses(last_event(c)) = run%event_impulses(last_event(c)) + 1
            last_impulse(c) = stepper%t
         end do
         do c = 1, stepper%contacts%count
            value = contact_value(stepper%contacts, c, stepper%u)
            run%max_penetration = max(run%max_penetration, stepper%contacts%lower(c) - value, &
                                      value - stepper%contacts%upper(c))
         end do
      end do
      call system_clock(finish)
      run%wall_seconds = real(finish - start, dp)/rate
      write (output_unit, '(a)') '  run dt = '//sci(dt)//' s, N = '//integer_text(elements)//', theta = '// &
         fixed(scene%time%theta, 2)//', e = '//fixed(scene%impact%restitution, 2)//', T = '//sci(t_end)//' s: '// &
         integer_text(run%events)//' impact events, '//fixed(run%wall_seconds, 2)//' s'
   end subroutine simulate

   !> Store the state of `stepper` as time step `step` of `run`.
   subroutine record_state(run, step, stepper, point_dofs, point_weights, tip_dofs, tip_weights)
      type(run_history), intent(inout) :: run
      integer, intent(in) :: step
      class(time_stepper), intent(in) :: stepper
      integer, intent(in) :: point_dofs(:,:), tip_dofs(:)          !! rows from `point_row`
      real(dp), intent(in) :: point_weights(:,:), tip_weights(:)
      integer :: p
      do p = 1, sample_points
         run%field(p, step) = row_value(point_dofs(:, p), point_weights(:, p), stepper%u)
      end do
      run%tip(step) = row_value(tip_dofs, tip_weights, stepper%u)
      run%energy(step) = stepper%kinetic_energy() + stepper%elastic_energy()
   end subroutine record_state

   !> sum(weights * u(dofs)) over the dofs that are not clamped (0).
   pure real(dp) function row_value(dofs, weights, u)
      integer, intent(in) :: dofs(:)
      real(dp), intent(in) :: weights(:)
      real(dp), intent(in) :: u(:)
      integer :: a
      row_value = 0
      do a = 1, size(dofs)
         if (dofs(a) /= 0) row_value = row_value + weights(a)*u(dofs(a))
      end do
   end function row_value

   !> Errors of `run` against the finer run `fine` over [0, t_end] (self_convergence.f90's header).
   function compare(run, fine, t_end) result(errors)
      type(run_history), intent(in) :: run, fine
      real(dp), intent(in) :: t_end   !! end of the window (s), a step of both runs
      type(run_errors) :: errors
      integer :: stride, last, n
      real(dp) :: weight, square_sum
      stride = nint(run%dt/fine%dt)
      if (stride < 1 .or. abs(stride*fine%dt - run%dt) > 1e-9_dp*run%dt) &
         call fail('dt = '//sci(run%dt)//' s is not a multiple of the finer dt = '//sci(fine%dt)//' s')
      last = nint(t_end/run%dt)
      if (last > run%steps .or. last*stride > fine%steps) call fail('window beyond the end of a run')
      errors%tip = maxval(abs(run%tip(0:last) - fine%tip(0:last*stride:stride)))
      square_sum = 0
      do n = 0, last
         weight = merge(0.5_dp, 1.0_dp, n == 0 .or. n == last)
         square_sum = square_sum + weight*run%dt*sum((run%field(:, n) - fine%field(:, n*stride))**2)
      end do
      errors%field = sqrt(square_sum/(sample_points*t_end))
      errors%energy = abs(run%energy(last) - fine%energy(last*stride))
   end function compare

   !> Tip error of `run` against `fine` over [0, t_end].
   real(dp) function tip_error(run, fine, t_end)
      type(run_history), intent(in) :: run, fine
      real(dp), intent(in) :: t_end
      type(run_errors) :: errors
      errors = compare(run, fine, t_end)
      tip_error = errors%tip
   end function tip_error

   !> The time-RMS over [0, t_end] of a run's own field at the sample points (m).
   real(dp) function field_size(run, t_end)
      type(run_history), intent(in) :: run
      real(dp), intent(in) :: t_end   !! end of the window (s), a step of the run
      real(dp) :: weight, square_sum
      integer :: n, last
      last = nint(t_end/run%dt)
      square_sum = 0
      do n = 0, last
         weight = merge(0.5_dp, 1.0_dp, n == 0 .or. n == last)
         square_sum = square_sum + weight*run%dt*sum(run%field(:, n)**2)
      end do
      field_size = sqrt(square_sum/(sample_points*t_end))
   end function field_size

   !> Time step of level k of the joint path: dt0/2^k (each level halves dt).
   pure real(dp) function joint_dt(k)
      integer, intent(in) :: k
      joint_dt = coarsest_dt/2**k
   end function joint_dt

   !> Elements of level k of the joint path: nint(N0 2^(k/2)) (h falls by sqrt 2 per level,
   !! so that omega_max dt stays the same at every level).
   pure integer function joint_elements(k)
      integer, intent(in) :: k
      joint_elements = nint(coarsest_elements*2.0_dp**(0.5_dp*k))
   end function joint_elements

   !> Observed order ln(e1/e2)/ln(s1/s2) for errors e at sizes s; 0 when undefined.
   pure real(dp) function rate(e1, e2, s1, s2)
      real(dp), intent(in) :: e1, e2   !! errors at the coarser and the finer size
      real(dp), intent(in) :: s1, s2   !! sizes (dt or h), s1 > s2
      rate = 0
      if (e1 > 0 .and. e2 > 0 .and. s1 > s2) rate = log(e1/e2)/log(s1/s2)
   end function rate

   !> previous <- current (the histories move, nothing is copied).
   subroutine move_alloc_history(current, previous)
      type(run_history), intent(inout) :: current
      type(run_history), intent(inout) :: previous
      previous%dt = current%dt
      previous%elements = current%elements
      previous%steps = current%steps
      previous%impulse_steps = current%impulse_steps
      previous%max_penetration = current%max_penetration
      previous%wall_seconds = current%wall_seconds
      previous%events = current%events
      call move_alloc(current%tip, previous%tip)
      call move_alloc(current%field, previous%field)
      call move_alloc(current%energy, previous%energy)
      call move_alloc(current%event_first, previous%event_first)
      call move_alloc(current%event_last, previous%event_last)
      call move_alloc(current%event_side, previous%event_side)
      call move_alloc(current%event_impulses, previous%event_impulses)
   end subroutine move_alloc_history

   !> `value` as 'd.dddE+xx'.
   function sci(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=16) :: buffer
      write (buffer, '(es10.3)') value
      text = trim(adjustl(buffer))
   end function sci

   !> `value` with `decimals` decimals, right-aligned in `width` characters if given.
   function fixed(value, decimals, width) result(text)
      real(dp), intent(in) :: value
      integer, intent(in) :: decimals
      integer, intent(in), optional :: width
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      character(len=16) :: form
      write (form, '(a,i0,a)') '(f0.', decimals, ')'
      write (buffer, form) value
      text = trim(adjustl(buffer))
      if (text(1:1) == '.') text = '0'//text
      if (len(text) > 1) then
         if (text(1:2) == '-.') text = '-0'//text(2:)
      end if
      if (present(width)) text = repeat(' ', max(0, width - len(text)))//text
   end function fixed

   !> `value` right-aligned in `width` characters.
   function padded(value, width) result(text)
      integer, intent(in) :: value, width
      character(len=:), allocatable :: text
      text = integer_text(value)
      text = repeat(' ', max(0, width - len(text)))//text
   end function padded
end module vibrobeam_convergence_runs
