!> The refinement study of studies/string_obstacle (REPORT.md): vibrobeam's velocity
!! scheme on a plucked string against a point obstacle, N and dt refined together (dt =
!! h/(2c)), against the exact solution by characteristics (docs/theory.md §7, "A string
!! against a point obstacle"). Arguments: [t_end [largest N [courant [restitution
!! [level/d [smallest N]]]]]] (defaults 20 s, 640, 2, 1, -0.3, 20); prints the exact
!! contact intervals, then one line per run (N doubled from the smallest to the largest).
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
   real(dp) :: t_end, courant, restitution, level
   real(dp), allocatable :: starts(:), ends(:)
   integer :: largest, smallest, elements, b, stat, k
   character(len=512) :: errmsg
   if (command_argument_count() >= 1) then
      call get_command_argument(1, argument)
      if (argument == 'sensitivity') then
         call sensitivity()
         stop
      end if
   end if
   t_end = real_argument(1, 20.0_dp)
   largest = nint(real_argument(2, 640.0_dp))
   courant = real_argument(3, 2.0_dp)
   restitution = real_argument(4, 1.0_dp)
   level = real_argument(5, -0.3_dp)
   smallest = nint(real_argument(6, 20.0_dp))
   ref = plucked(0.0_dp, level, t_end)
   write (*, '(a,f6.1,a,i0,a,f4.1,a,f4.2)') '# t_end = ', t_end, ' s, landings of the exact solution: ', landings(), &
      ', dt = h/(courant c), courant = ', courant, &
      ', e = ', restitution
   call ref%contact_intervals(starts, ends)
   write (*, '(a)', advance='no') '# exact contact intervals (s):'
   write (*, '(*(a,f7.4,a,f7.4,a))') (' [', starts(k), ',', ends(k), ']', k=1, size(starts))
   call ref%contact_intervals(starts, ends, pressed=.true.)
   write (*, '(a)', advance='no') '# of them, where the obstacle pushes (R > 0):'
   write (*, '(*(a,f7.4,a,f7.4,a))') (' [', starts(k), ',', ends(k), ']', k=1, size(starts))
   write (*, '(a)') '# basis N steps rms largest point away impulse impulse_end energy_drift energy_bound '// &
      'impulse_steps contact_times'
   do b = 1, 2
      elements = smallest
      do while (elements <= largest)
         call run_string_obstacle(ref, trim(bases(b)), elements, courant, t_end, 0.25_dp, 0.75_dp, height, errors, &
                                  stat, errmsg, restitution)
         if (stat /= 0) then
            write (*, '(a)') 'error: '//trim(errmsg)
            error stop 1
         end if
         write (*, '(a8,i6,i8,8es11.3,i8,es11.3)') bases(b), elements, errors%steps, errors%rms, errors%largest, errors%point, &
            errors%away, errors%impulse, errors%impulse_end, errors%energy_drift, errors%energy_bound, errors%impulse_steps, &
            errors%contact_times
         flush (6)
         elements = 2*elements
      end do
   end do
contains
   !> Command argument k as a number, or `default` when it is not given.
   real(dp) function real_argument(k, default)
      integer, intent(in) :: k
      real(dp), intent(in) :: default
      real_argument = default
      if (command_argument_count() >= k) then
         call get_command_argument(k, argument)
         read (argument, *) real_argument
      end if
   end function real_argument

   !> The exact plucked string of the study, its height d (1 + delta), the obstacle at
   !! level_in_d d, built to t_end.
   function plucked(delta, level_in_d, t_end) result(exact)
      real(dp), intent(in) :: delta, level_in_d, t_end
      type(string_reference) :: exact
      exact = new_string_reference(1.0_dp, 1.0_dp, 0.25_dp, level_in_d*height, [0.0_dp, 0.6_dp, 1.0_dp], &
                                   [0.0_dp, height*(1 + delta), 0.0_dp], [0.0_dp, 0.0_dp])
      call exact%build(t_end)
   end function plucked

   !> RMS over 201 points of the difference of two exact solutions, the largest over
   !! 2000 times in each window, divided by delta d.
   subroutine sensitivity()
      real(dp), parameter :: windows(6) = [1.2_dp, 3.0_dp, 6.0_dp, 10.0_dp, 14.0_dp, 20.0_dp]
      type(string_reference) :: base, moved
      real(dp) :: delta, time, difference, worst(size(windows))
      integer :: m, n, i
      base = plucked(0.0_dp, -0.3_dp, 20.0_dp)
      write (*, '(a)') '# delta, then the RMS difference/(delta d), largest over 1.2, 3, 6, 10, 14, 20 s'
      do m = 2, 5
         delta = 10.0_dp**(-m)
         moved = plucked(delta, -0.3_dp, 20.0_dp)
         worst = 0
         do n = 1, 2000
            time = 20.0_dp*n/2000
            difference = sqrt(sum([((moved%displacement(i/200.0_dp, time) - base%displacement(i/200.0_dp, time))**2, &
                                    i=0, 200)])/201)/(delta*height)
            where (time <= windows) worst = max(worst, difference)
         end do
         write (*, '(es8.1,6es10.2)') delta, worst
      end do
   end subroutine sensitivity

   !> The number of contact intervals of the exact solution.
   integer function landings()
      real(dp), allocatable :: first(:), last(:)
      call ref%contact_intervals(first, last)
      landings = size(first)
   end function landings
end program string_obstacle_study
