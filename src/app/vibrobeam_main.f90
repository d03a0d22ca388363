!> vibrobeam: dynamics of a clamped-free Euler-Bernoulli beam between rigid obstacles.
!!
!! Command line (INTERFACE.md): `vibrobeam INPUT.nml`, `vibrobeam --check INPUT.nml`,
!! `vibrobeam --help`, `vibrobeam --version`. This program is the only place where an
!! error becomes a message on stderr and an exit status.
program vibrobeam_main
   use vibrobeam_kinds, only: dp, error_unit, output_unit
   use vibrobeam_status, only: exit_ok, exit_other_error, exit_invalid_input, exit_numerical_failure, &
                               message_length
   use vibrobeam_version, only: version_string
   use vibrobeam_scene, only: scene_type, validate_scene, format_scene
   use vibrobeam_input, only: read_scene
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_static, only: solve_static
   use vibrobeam_setup, only: prepared_scene, prepare_scene
   use vibrobeam_dynamics, only: run_dynamics, run_outcome
   use vibrobeam_results, only: result_files
   implicit none

   type(scene_type) :: scene
   type(prepared_scene) :: prepared
   character(len=message_length) :: errmsg
   character(len=:), allocatable :: input_file, warnings
   logical :: check_only
   integer :: stat

   call parse_command_line(input_file, check_only)
   call read_scene(input_file, scene, stat, errmsg)
   if (stat /= 0) call fail(exit_invalid_input, errmsg)
   call validate_scene(scene, stat, errmsg)
   if (stat /= 0) call fail(exit_invalid_input, errmsg)
   warnings = ''
   call prepare_scene(scene, prepared, warnings, stat, errmsg)
   if (stat /= 0) call fail(exit_invalid_input, errmsg)
   if (len(warnings) > 0) write (error_unit, '(a)', advance='no') prefixed(warnings, 'vibrobeam: warning: ')

   if (check_only) then
      call print_resolved_scene()
      stop exit_ok, quiet=.true.
   end if

   select case (scene%kind)
   case ('modes')
      call run_modes()
   case ('static')
      call run_static()
   case default
      call run_dynamics_scene()
   end select

contains

   !> Print `message` on stderr as 'vibrobeam: message' and stop with `code`.
   subroutine fail(code, message)
      integer, intent(in) :: code
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'vibrobeam: '//trim(message)
      if (code == exit_invalid_input) write (error_unit, '(a)') 'vibrobeam: invalid input, nothing written'
      stop code, quiet=.true.
   end subroutine fail

   !> Every line of `text` with `prefix` in front.
   pure function prefixed(text, prefix) result(out)
      character(len=*), intent(in) :: text, prefix
      character(len=:), allocatable :: out
      integer :: start, finish
      out = ''
      start = 1
      do while (start <= len(text))
         finish = index(text(start:), new_line('a'))
         if (finish == 0) finish = len(text) - start + 2
         out = out//prefix//text(start:start + finish - 2)//new_line('a')
         start = start + finish
      end do
   end function prefixed

   subroutine parse_command_line(file, check)
      character(len=:), allocatable, intent(out) :: file
      logical, intent(out) :: check
      character(len=4096) :: argument
      integer :: count, length
      count = command_argument_count()
      check = .false.
      if (count == 0) call usage_error('no input file given')
      call get_command_argument(1, argument, length)
      select case (trim(argument))
      case ('--help', '-h')
         call print_help()
         stop exit_ok, quiet=.true.
      case ('--version')
         write (output_unit, '(a)') 'vibrobeam '//version_string
         stop exit_ok, quiet=.true.
      case ('--check')
         if (count /= 2) call usage_error('--check takes exactly one input file')
         check = .true.
         call get_command_argument(2, argument, length)
      case default
         if (argument(1:1) == '-') call usage_error('unknown option '''//trim(argument)//'''')
         if (count /= 1) call usage_error('give exactly one input file')
      end select
      if (length > len(argument)) call usage_error('input file name too long')
      file = argument(1:length)
   end subroutine parse_command_line

   subroutine usage_error(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'vibrobeam: '//message
      write (error_unit, '(a)') 'usage: vibrobeam INPUT.nml | vibrobeam --check INPUT.nml | vibrobeam --help | --version'
      stop exit_other_error, quiet=.true.
   end subroutine usage_error

   subroutine print_help()
      write (output_unit, '(a)') &
         'vibrobeam '//version_string//': an elastic Euler-Bernoulli beam, clamped at x = 0 and free at', &
         'x = L, vibrating between rigid obstacles (Newton impact law).', &
         '', &
         'usage:', &
         '  vibrobeam INPUT.nml            run the scene described by INPUT.nml', &
         '  vibrobeam --check INPUT.nml    validate the input, print the resolved scene, run nothing', &
         '  vibrobeam --help | --version', &
         '', &
         'namelist groups: &beam &mesh &analysis &obstacles &impact &time &initial &load &output', &
         '(every variable is optional; see docs/input.md for units, defaults and ranges).', &
         '', &
         'exit status: 0 success, 2 invalid input (nothing written), 3 numerical failure', &
         '(results up to the failure kept, marked failed), 1 anything else.'
   end subroutine print_help

   subroutine print_resolved_scene()
      associate (model => prepared%model, contacts => prepared%contacts)
      write (output_unit, '(a)') 'vibrobeam '//version_string//': input '''//input_file//''' is valid', &
         'resolved scene:'
      write (output_unit, '(a)', advance='no') format_scene(scene)
      write (output_unit, '(a,i0,a,i0,a)') 'discrete model: ', model%elements, ' '//trim(model%basis)// &
         ' elements, ', model%unknowns, ' unknowns'
      write (output_unit, '(a,i0)') 'contact points: ', contacts%count
      end associate
   end subroutine print_resolved_scene

   subroutine run_modes()
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      type(result_files) :: files
      integer(kind=8) :: start, finish, rate
      associate (model => prepared%model)
      call system_clock(start, rate)
      call compute_modes(model, scene%modes, omega, shapes, vectors, stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      call files%open(scene, model, stat, errmsg)
      if (stat == 0) call files%write_modes(model, omega, shapes, stat, errmsg)
      call system_clock(finish)
      if (stat == 0) call files%commit('ok', 0, real(finish - start, dp)/rate, 0, 0, stat, errmsg)
      if (stat /= 0) then
         call files%discard()
         call fail(exit_other_error, errmsg)
      end if
      write (output_unit, '(a,i0,a)') 'vibrobeam: ', size(omega), ' natural modes written to '//trim(scene%file)
      end associate
   end subroutine run_modes

   subroutine run_static()
      real(dp), allocatable :: u(:), reaction(:)
      type(result_files) :: files
      integer(kind=8) :: start, finish, rate
      integer :: iterations
      associate (model => prepared%model, contacts => prepared%contacts, loads => prepared%loads)
      call system_clock(start, rate)
      allocate (u(model%unknowns), reaction(contacts%count))
      call solve_static(model%stiffness, contacts, loads%at(0.0_dp), scene%contact_solver, u, reaction, &
                        iterations, stat, errmsg, trim(scene%contact_method))
      if (stat /= 0) call fail(exit_numerical_failure, errmsg)
      call files%open(scene, model, stat, errmsg)
      if (stat == 0) call files%write_static(model, nodal_displacement(model, u), contacts%x, reaction, stat, errmsg)
      call system_clock(finish)
      if (stat == 0) call files%commit('ok', 0, real(finish - start, dp)/rate, iterations, iterations, stat, errmsg)
      if (stat /= 0) then
         call files%discard()
         call fail(exit_other_error, errmsg)
      end if
      write (output_unit, '(a,i0,a)') 'vibrobeam: static equilibrium with ', count(abs(reaction) > 0), &
         ' contact points in contact written to '//trim(scene%file)
      end associate
   end subroutine run_static

   subroutine run_dynamics_scene()
      type(run_outcome) :: outcome
      call run_dynamics(scene, prepared, outcome, stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      if (outcome%failed) then
         write (error_unit, '(a)') 'vibrobeam: numerical failure at '//trim(outcome%failure)
         write (error_unit, '(a)') 'vibrobeam: results up to the failure written to '//trim(scene%file)// &
            ' (/run status = ''failed'')'
         stop exit_numerical_failure, quiet=.true.
      end if
      write (output_unit, '(a,i0,a,i0,a,es10.3,a,f0.2,a)') 'vibrobeam: ', outcome%steps, ' steps, ', outcome%impacts, &
         ' impacts, largest penetration ', outcome%max_penetration, ' m, ', outcome%wall_seconds, ' s; written to '// &
         trim(scene%file)
   end subroutine run_dynamics_scene
end program vibrobeam_main
