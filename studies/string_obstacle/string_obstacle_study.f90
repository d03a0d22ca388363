!> The refinement study of studies/string_obstacle (REPORT.md): vibrobeam's velocity
!! scheme on a plucked string against a point obstacle, N and dt refined together (dt =
!! h/(2c)), against the exact solution by characteristics (docs/theory.md §7, "A string
!! against a point obstacle"). Arguments: [t_end [largest N [courant [restitution]]]]
!! (defaults 20 s, 640, 2, 1); prints the exact contact intervals, then one line per run.
program string_obstacle_study
   use vibrobeam_kinds, only: dp
   use vibrobeam_string_obstacle_reference, only: string_reference, new_string_reference
   use vibrobeam_string_obstacle_runs, only: string_run_errors, run_string_obstacle
   implicit none
   real(dp), parameter :: height = 0.01_dp
   type(string_reference) :: ref
   type(string_run_errors) :: errors
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   character(len=32) :: argument
   real(dp) :: t_end, courant, restitution
   integer :: largest, elements, b, stat, k
   character(len=512) :: errmsg
   t_end = 20
   largest = 640
   courant = 2
   restitution = 1
   if (command_argument_count() >= 1) then
      call get_command_argument(1, argument)
      read (argument, *) t_end
   end if
   if (command_argument_count() >= 2) then
      call get_command_argument(2, argument)
      read (argument, *) largest
   end if
   if (command_argument_count() >= 3) then
      call get_command_argument(3, argument)
      read (argument, *) courant
   end if
   if (command_argument_count() >= 4) then
      call get_command_argument(4, argument)
      read (argument, *) restitution
   end if
   ref = new_string_reference(1.0_dp, 1.0_dp, 0.25_dp, -0.3_dp*height, [0.0_dp, 0.6_dp, 1.0_dp], &
                              [0.0_dp, height, 0.0_dp], [0.0_dp, 0.0_dp])
   call ref%build(t_end)
   write (*, '(a,f6.1,a,i0,a,f4.1,a,f4.2)') '# t_end = ', t_end, ' s, landings of the exact solution: ', landings(), &
      ', dt = h/(courant c), courant = ', courant, &
      ', e = ', restitution
   write (*, '(a)', advance='no') '# exact contact intervals (s):'
   do k = 2, ref%points
      if (ref%w(k) <= ref%level .and. ref%w(k - 1) > ref%level) write (*, '(a,f7.4)', advance='no') ' [', ref%t(k)
      if (ref%w(k) > ref%level .and. ref%w(k - 1) <= ref%level) write (*, '(a,f7.4,a)', advance='no') ',', ref%t(k - 1), ']'
   end do
   write (*, *)
   write (*, '(a)') '# basis N steps rms largest point away impulse impulse_end energy_drift energy_bound impulse_steps'
   do b = 1, 2
      elements = 20
      do while (elements <= largest)
         call run_string_obstacle(ref, trim(bases(b)), elements, courant, t_end, 0.25_dp, 0.75_dp, height, errors, &
                                  stat, errmsg, restitution)
         if (stat /= 0) then
            write (*, '(a)') 'error: '//trim(errmsg)
            error stop 1
         end if
         write (*, '(a8,i6,i8,8es11.3,i8)') bases(b), elements, errors%steps, errors%rms, errors%largest, errors%point, &
            errors%away, errors%impulse, errors%impulse_end, errors%energy_drift, errors%energy_bound, errors%impulse_steps
         flush (6)
         elements = 2*elements
      end do
   end do
contains
   integer function landings()
      landings = 0
      do k = 2, ref%points
         if (ref%w(k) <= ref%level .and. ref%w(k - 1) > ref%level) landings = landings + 1
      end do
   end function landings
end program string_obstacle_study
