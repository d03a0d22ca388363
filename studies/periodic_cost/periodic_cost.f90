!> The cost of one periodic orbit by shooting against the time-marching transient it
!! replaces (studies/periodic_cost/REPORT.md; issue 20, "Cost"). For each scene of kind
!! 'periodic' given on the command line:
!! - shooting: `find_periodic_orbit` from the scene's start (its transient_periods, then
!!   Newton's method to its tolerance), wall time (median of `repeats`), steps stepped,
!!   Newton iterations, the unknowns of the period map;
!! - marching: the dynamics run's stepper and loop (`new_stepper`, `advance`) from the same
!!   start, period after period, until the state at phase 0 repeats after k forcing
!!   periods to the same relative tolerance in the same energy norm (the test Newton's
!!   method stops on), or `max_periods`; wall time (median), periods;
!! and the ratio marching/shooting. One line per scene into TABLE (appended).
!! Usage: periodic_cost TABLE REPEATS MAX_PERIODS SCENE.nml ...
program periodic_cost
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: outcome_ok
   use vibrobeam_scene, only: scene_type, forcing_period_steps
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_stepper_factory, only: release_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_run_loop, only: advance
   use vibrobeam_periodic_analysis, only: find_periodic_orbit, periodic_orbit
   use vibrobeam_sorting, only: median
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene
   implicit none
   character(len=4096) :: table, argument
   integer :: repeats, max_periods, a, unit
   call get_command_argument(1, table)
   call get_command_argument(2, argument)
   read (argument, *) repeats
   call get_command_argument(3, argument)
   read (argument, *) max_periods
   open (newunit=unit, file=trim(table), position='append', action='write')
   write (unit, '(a)') '# scene  unknowns_of_map  newton_iterations  shooting_steps  shooting_s  marching_periods  '// &
      'marching_steps  marching_s  marching/shooting  largest_multiplier'
   do a = 4, command_argument_count()
      call get_command_argument(a, argument)
      call measure(trim(argument))
   end do
   close (unit)

contains

   subroutine measure(path)
      character(len=*), intent(in) :: path
      type(scene_type) :: scene
      type(run_problem) :: prepared
      type(periodic_orbit) :: orbit
      real(dp) :: shooting(repeats), marching(repeats)
      integer :: r, periods, stat, slash
      character(len=512) :: errmsg
      integer(int64) :: start, finish, rate
      scene = read_test_scene(path)
      call prepare_test_scene(scene, prepared)
      do r = 1, repeats
         call system_clock(start, rate)
         call find_periodic_orbit(scene, prepared, orbit, stat, errmsg)
         call system_clock(finish)
         if (stat /= 0 .or. .not. orbit%converged) then
            write (*, '(a)') path//': no orbit: '//trim(errmsg)//trim(orbit%failure)
            return
         end if
         shooting(r) = real(finish - start, dp)/rate
         call system_clock(start, rate)
         call march(scene, prepared, orbit, periods)
         call system_clock(finish)
         marching(r) = real(finish - start, dp)/rate
      end do
      slash = index(path, '/', back=.true.)
      write (unit, '(a,i6,i4,i10,es11.3,i7,i10,es11.3,f9.2,f10.6)') path(slash + 1:)//'  ', &
         2*prepared%system%model%unknowns, orbit%iterations, orbit%map%steps_taken, median(shooting), periods, &
         periods*forcing_period_steps(scene), median(marching), median(marching)/median(shooting), &
         hypot(orbit%multipliers(1, 1), orbit%multipliers(2, 1))
      write (*, '(a,f8.3,a,f8.3,a,i0,a)') path(slash + 1:)//': shooting ', median(shooting), ' s, marching ', &
         median(marching), ' s (', periods, ' periods)'
   end subroutine measure

   !> Periods of time marching from the scene's start until the state at phase 0 repeats
   !! after k periods to the tolerance (orbit%map%norm, relative), at most max_periods.
   subroutine march(scene, prepared, orbit, periods)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(periodic_orbit), intent(in) :: orbit
      integer, intent(out) :: periods
      class(time_stepper), allocatable :: stepper
      type(dynamics_recorder) :: recorder
      real(dp), allocatable :: states(:, :)
      integer(int64) :: period_steps
      integer :: k, status, stat
      character(len=512) :: failure, errmsg
      k = scene%periodic%period_multiple
      period_steps = forcing_period_steps(scene)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      call recorder%init(scene, stepper, prepared, max_periods*period_steps, write_rows=.false.)
      allocate (states(2*prepared%system%model%unknowns, 0:max_periods))
      states(:, 0) = [stepper%u, stepper%v]
      do periods = 1, max_periods
         call advance(stepper, recorder, prepared%model, periods*period_steps, status, failure, stat, errmsg)
         if (stat /= 0 .or. status /= outcome_ok) exit
         states(:, periods) = [stepper%u, stepper%v]
         if (periods < k) cycle
         if (orbit%map%norm(prepared, states(:, periods) - states(:, periods - k)) <= &
             scene%periodic%tolerance*orbit%map%norm(prepared, states(:, periods))) exit
      end do
      periods = min(periods, max_periods)
      call release_stepper(stepper)
   end subroutine march
end program periodic_cost
