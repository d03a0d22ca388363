!> The impacts of rigid obstacles, counted independently of the recorder, against what a
!! run wrote (issue 23 item 3: a rigid wall behind a compliant stop on the same node and
!! side had none of its impacts logged, because the spring's force marked the point as in
!! contact).   usage: check_rigid_impacts RESULT.h5 INPUT.nml
!!
!! Reference: the scene of INPUT.nml is stepped again here (the same library, so the same
!! states and impulses), and the rule of docs/method.md ("Impacts and contact statistics")
!! is applied to the rigid impulses alone, in this program's own code: a contact point
!! logs an impact in a step when it receives a non-zero rigid impulse P, received none in
!! the previous step (at the first step: it did not start on its rigid obstacle, within
!! 1e-12 L, without moving into it), and approached that obstacle at the start of the step
!! (s H V^n <= 0 with s = sign(P): upwards from the obstacle below). Each impact belongs to
!! the rigid obstacle on its side, found here from the scene's obstacle list (the most
!! restrictive punctual rigid obstacle at the point's x), not from the contact set. The
!! springs' forces play no part in it.
!!
!! Checks, all exact (integers, or one rounding): the count (/impacts attribute `count`
!! and the rows of /impacts/time) equals the reference, every row's time and impulse
!! equal the reference's (the same computation: to 4 eps); the statistics impact_rate of
!! each obstacle, of each contact point and of the beam times the window T = N dt equals
!! the reference count (a count divided by T and multiplied back: 4 eps relative). The
!! scene must exercise the case: the wall has impacts, some of them while the spring on
!! its node and side pushes.
program check_rigid_impacts
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_attr_int
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   real(dp), parameter :: eps = epsilon(1.0_dp)
   type(test_counter) :: t
   character(len=4096) :: file, input
   character(len=512) :: errmsg
   character(len=80) :: label
   type(scene_type) :: scene
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: s
   logical, allocatable :: previous(:), touched(:), pushing(:)
   real(dp), allocatable :: times(:), impulses(:), file_times(:), file_impulses(:), rates(:)
   integer, allocatable :: per_obstacle(:), per_point(:)
   integer :: steps, n, k, c, side, obstacle, count, behind_spring, file_count, stat, wall
   real(dp) :: window, value, speed, tolerance

   call get_command_argument(1, file)
   call get_command_argument(2, input)
   scene = read_test_scene(trim(input))
   call prepare_test_scene(scene, prepared)
   call new_stepper(scene, prepared, s, stat, errmsg)
   if (stat /= 0) error stop 'check_rigid_impacts: cannot start the stepper'
   if (scene%output%measure_from > 0) error stop 'check_rigid_impacts: the statistics window must be the whole run'
   steps = nint(scene%time%t_end/scene%time%dt)
   window = steps*scene%time%dt
   allocate (previous(s%contacts%count), touched(s%contacts%count), pushing(s%contacts%count))
   allocate (per_obstacle(size(scene%obstacles)), per_point(s%contacts%count), source=0)
   allocate (times(0), impulses(0))
   ! started in contact: on (or beyond) a rigid obstacle of the point without moving into it
   tolerance = 1e-12_dp*scene%beam%length
   do c = 1, s%contacts%count
      value = contact_value(s%contacts, c, s%u)
      speed = contact_value(s%contacts, c, s%v)
      previous(c) = .false.
      do side = -1, 1, 2
         obstacle = rigid_obstacle(s%contacts%x(c), side)
         if (obstacle == 0) cycle
         if (side*(value - scene%obstacles(obstacle)%level_from) <= tolerance .and. side*speed >= 0) &
            previous(c) = .true.
      end do
   end do
   count = 0
   behind_spring = 0
   do n = 1, steps
      pushing = abs(s%report%contact_force) > 0   ! the springs' force at t_n, before the step
      call s%step(stat, errmsg)
      if (stat /= 0) error stop 'check_rigid_impacts: a step failed'
      touched = .false.
      do k = 1, s%report%active_count
         if (abs(s%report%impulse(k)) <= 0) cycle
         c = s%report%active(k)
         touched(c) = .true.
         side = nint(sign(1.0_dp, s%report%impulse(k)))   ! +1: pushed up by the obstacle below
         if (previous(c) .or. side*s%report%velocity_before(k) > 0) cycle
         count = count + 1
         times = [times, s%report%impulse_time]
         impulses = [impulses, s%report%impulse(k)]
         obstacle = rigid_obstacle(s%contacts%x(c), side)
         if (obstacle == 0) error stop 'check_rigid_impacts: a rigid impulse without a rigid obstacle'
         per_obstacle(obstacle) = per_obstacle(obstacle) + 1
         per_point(c) = per_point(c) + 1
         if (pushing(c)) behind_spring = behind_spring + 1
      end do
      previous = touched
   end do

   ! the scene exercises the case: a rigid wall behind a spring on the same node and side
   wall = 0
   do k = 1, size(scene%obstacles)
      if (scene%obstacles(k)%stiffness > 0) cycle
      if (any(scene%obstacles%stiffness > 0 .and. scene%obstacles%side == scene%obstacles(k)%side .and. &
              abs(scene%obstacles%x_from - scene%obstacles(k)%x_from) <= 1e-9_dp*scene%beam%length)) wall = k
   end do
   write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a)') 'reference: ', count, ' impacts, ', per_obstacle(max(wall, 1)), &
      ' at the wall (obstacle ', wall, '), ', behind_spring, ' of them while the spring on that node pushes'
   call t%check_true('the scene has a rigid wall behind a spring', wall > 0)
   if (wall > 0) call t%check_true('the wall is hit while the spring pushes', per_obstacle(wall) > 0 .and. &
                                   behind_spring > 0)

   ! /impacts
   call read_attr_int(trim(file), '/impacts', 'count', file_count, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/impacts/time', file_times, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/impacts/impulse', file_impulses, stat, errmsg)
   call t%check_true('read /impacts', stat == 0, errmsg)
   if (stat /= 0) call t%finish('check_rigid_impacts')
   write (output_unit, '(a,i0,a,i0,a)') 'the run: ', file_count, ' impacts (', size(file_times), ' rows)'
   call t%check_true('/impacts count = the reference count', file_count == count)
   call t%check_true('rows of /impacts = the reference count', size(file_times) == count)
   if (size(file_times) == count .and. count > 0) then
      call t%check_close('largest |impact time - reference|', maxval(abs(file_times - times)), 0.0_dp, 4*eps, &
                         maxval(abs(times)))
      call t%check_close('largest |impact impulse - reference|', maxval(abs(file_impulses - impulses)), 0.0_dp, &
                         4*eps, maxval(abs(impulses)))
   end if

   ! statistics: impact rates times the window are the counts
   call read_real_1d(trim(file), '/statistics/obstacles/impact_rate', rates, stat, errmsg)
   call t%check_true('read /statistics/obstacles/impact_rate', stat == 0 .and. size(rates) == size(per_obstacle), &
                     errmsg)
   if (stat == 0 .and. size(rates) == size(per_obstacle)) then
      do k = 1, size(per_obstacle)
         write (label, '(a,i0,a)') 'impacts of obstacle ', k, ' (impact_rate T)'
         write (output_unit, '(a,f12.3,a,i0)') trim(label)//': ', rates(k)*window, ', reference ', per_obstacle(k)
         call t%check_close(trim(label), rates(k)*window, real(per_obstacle(k), dp), 4*eps, 1.0_dp)
      end do
   end if
   call read_real_1d(trim(file), '/statistics/contacts/impact_rate', rates, stat, errmsg)
   call t%check_true('read /statistics/contacts/impact_rate', stat == 0 .and. size(rates) == size(per_point), errmsg)
   if (stat == 0 .and. size(rates) == size(per_point)) then
      do c = 1, size(per_point)
         write (label, '(a,i0,a)') 'impacts of contact point ', c, ' (impact_rate T)'
         call t%check_close(trim(label), rates(c)*window, real(per_point(c), dp), 4*eps, 1.0_dp)
      end do
   end if
   call read_real_1d(trim(file), '/statistics/beam/impact_rate', rates, stat, errmsg)
   call t%check_true('read /statistics/beam/impact_rate', stat == 0 .and. size(rates) == 1, errmsg)
   if (stat == 0 .and. size(rates) == 1) &
      call t%check_close('impacts of the beam (impact_rate T)', rates(1)*window, real(count, dp), 4*eps, 1.0_dp)
   call t%finish('check_rigid_impacts')

contains

   !> The rigid punctual obstacle that bounds the point at x from `side` (+1 below, -1
   !! above): the most restrictive one there (the highest below, the lowest above); 0: none.
   integer function rigid_obstacle(x, side) result(found)
      real(dp), intent(in) :: x
      integer, intent(in) :: side
      integer :: j
      found = 0
      do j = 1, size(scene%obstacles)
         associate (o => scene%obstacles(j))
            if (o%stiffness > 0) cycle
            if ((side > 0) .neqv. (o%side == 'below')) cycle
            if (o%x_to > o%x_from) error stop 'check_rigid_impacts: punctual rigid obstacles only'
            if (abs(o%x_from - x) > 1e-9_dp*scene%beam%length) cycle
            if (found == 0) then
               found = j
            else if (side*(o%level_from - scene%obstacles(found)%level_from) > 0) then
               found = j
            end if
         end associate
      end do
   end function rigid_obstacle
end program check_rigid_impacts
