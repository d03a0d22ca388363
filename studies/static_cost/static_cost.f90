!> The cost and the accuracy of the static solve against N (studies/static_cost/REPORT.md):
!! the three scenes of verification/statics (the steel strip free, on a tip stop, on a
!! floor), both bases, N = 1e3 ... 1e5, solved by the statics of this version (`solve_static`:
!! double integration and the three-moment equations, docs/method.md "Statics") and by the
!! one it replaces (`band_static_solve`: band Cholesky of K and the contact projection in the
!! metric K, regime 'auto' and method 'newton' as the program ran it, 500 pivots for its
!! fall-back). Per case: median wall time of `repetitions` solves (the scene is prepared once,
!! outside the timing), active-set iterations, the status, and the relative error of the
!! quantity with a closed form (verification/statics/test_static_closed_forms.f90): the tip
!! deflection q L^4/(8 EI), the stop's reaction 3 EI (|q| L^4/(8 EI) - g)/L^3, the floor's total
!! reaction |q| L - 2|q|a/3 plus its discrete term (|q| h^3/2)/(a^2 (2 sqrt 3 + 4h/a)).
!! usage: static_cost STATICS_DIRECTORY TABLE_FILE [repetitions]
program static_cost
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_band_statics, only: band_static_solve
   use vibrobeam_sorting, only: median
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene
   implicit none
   integer, parameter :: sizes(5) = [1000, 3000, 10000, 30000, 100000]
   character(len=*), parameter :: scenes(3) = [character(len=18) :: 'strip_free', 'strip_tip_stop', 'strip_floor']
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   character(len=8), parameter :: methods(2) = [character(len=8) :: 'band', 'moments']
   character(len=512) :: directory, table, argument
   integer :: unit, repetitions, s, b, i, m
   call get_command_argument(1, directory)
   call get_command_argument(2, table)
   repetitions = 3
   if (command_argument_count() >= 3) then
      call get_command_argument(3, argument)
      read (argument, *) repetitions
   end if
   open (newunit=unit, file=trim(table), status='replace', action='write')
   write (unit, '(a)') '# static solve: the band Cholesky of K and the projection in the metric K (band, before issue 23)'
   write (unit, '(a)') '# against the double integration and the three-moment equations (moments, this version);'
   write (unit, '(a,i0,a)') '# wall_s: median of ', repetitions, ' solves; error: relative, of the closed-form quantity'
   write (unit, '(a)') '# scene              basis       N  method   status   wall_s  iterations  in_contact       error'
   do s = 1, size(scenes)
      do b = 1, size(bases)
         do i = 1, size(sizes)
            do m = 1, size(methods)
               call measure(trim(scenes(s)), trim(bases(b)), sizes(i), trim(methods(m)))
            end do
         end do
      end do
   end do
   close (unit)

contains

   subroutine measure(name, basis, elements, method)
      character(len=*), intent(in) :: name, basis, method
      integer, intent(in) :: elements
      type(scene_type) :: scene
      type(run_problem) :: prepared
      type(static_report) :: report
      real(dp), allocatable :: u(:), reaction(:), seconds(:)
      real(dp) :: p, g, length, ei, a, h, value, exact
      integer(int64) :: start, finish, rate
      integer :: r, iterations, stat
      character(len=512) :: errmsg
      scene = read_test_scene(trim(directory)//'/'//name//'.nml')
      scene%mesh%elements = elements
      scene%mesh%basis = basis
      call prepare_test_scene(scene, prepared)
      allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count), seconds(repetitions))
      do r = 1, repetitions
         call system_clock(start, rate)
         if (method == 'band') then
            call band_static_solve(prepared, 'auto', 'newton', 0, u, reaction, iterations, stat, errmsg)
         else
            call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u, reaction, iterations, &
                              stat, errmsg, report=report)
         end if
         call system_clock(finish)
         seconds(r) = real(finish - start, dp)/rate
      end do
      p = -scene%load%distributed
      g = -scene%obstacles(1)%level_from
      length = scene%beam%length
      ei = scene%beam%ei()
      h = length/elements
      select case (name)
      case ('strip_free')
         associate (w => nodal_displacement(prepared%model, u))
            value = w(size(w))
         end associate
         exact = -p*length**4/(8*ei)
      case ('strip_tip_stop')
         value = reaction(1)
         exact = 3*ei*(p*length**4/(8*ei) - g)/length**3
      case default
         a = (72*ei*g/p)**0.25_dp
         value = sum(reaction)
         exact = p*length - 2*p*a/3 + (p*h**3/2)/(a**2*(2*sqrt(3.0_dp) + 4*h/a))
      end select
      write (unit, '(a18,1x,a8,i8,2x,a8,1x,a6,f9.4,i12,i12,es12.3)') name, basis, elements, method, &
         merge('ok    ', 'failed', stat == 0), median(seconds), iterations, count(abs(reaction) > 0), value/exact - 1
      if (stat /= 0) write (unit, '(a)') '#   '//trim(errmsg)
      flush (unit)
   end subroutine measure
end program static_cost
