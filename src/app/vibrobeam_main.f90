!> vibrobeam: dynamics of a clamped-free Euler-Bernoulli beam between rigid obstacles.
!!
!! Command line (docs/output.md, "Exit status"): `vibrobeam INPUT.nml`, `vibrobeam --check INPUT.nml`,
!! `vibrobeam --text RESULT.h5`, `vibrobeam --help`, `vibrobeam --version`. This program
!! is the only place where an error becomes a message on stderr and an exit status
!! (docs/output.md, "Exit status").
program vibrobeam_main
   use, intrinsic :: iso_c_binding, only: c_int
   use vibrobeam_kinds, only: dp, int64, pi, error_unit, output_unit
   use vibrobeam_status, only: exit_ok, exit_other_error, exit_invalid_input, exit_numerical_failure, &
                               exit_interrupted, message_length, stat_numerical_failure, outcome_failed, outcome_interrupted, &
                               outcome_exit_status, stat_invalid_input
   use vibrobeam_version, only: version_string
   use vibrobeam_scene, only: scene_type, format_scene, is_unset
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_scene_read, only: read_scene, namelist_groups_text
   use vibrobeam_output_target, only: check_output_target
   use vibrobeam_check_report, only: check_report, make_check_report, check_report_text, scene_warnings
   use vibrobeam_modal_analysis, only: run_modal, frequencies_text
   use vibrobeam_static_analysis, only: run_equilibrium
   use vibrobeam_periodic_run, only: run_periodic_kind
   use vibrobeam_continuation_axis, only: resolve_continuation, continues
   use vibrobeam_sweep_axis, only: sweep_axis
   use vibrobeam_problem, only: run_problem, build_problem
   use vibrobeam_dynamics, only: run_dynamics
   use vibrobeam_result_files, only: run_outcome, publish_files
   use vibrobeam_text_output, only: derived_file, derive_text_files
   use vibrobeam_text, only: significant_text, integer_text, fixed_text
   use vibrobeam_hdf5_base, only: close_library
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: watch_signals, interrupt_requested, interrupt_name
   use vibrobeam_sweep_settings, only: sweep_settings, resolve_sweep, sweep_points, point_scene
   use vibrobeam_sweep, only: run_sweep, sweep_outcome, sweep_threads
   use vibrobeam_sweep_check, only: write_sweep_check, check_sweep_files
   use vibrobeam_sweep_transport, only: transport_start, transport_stop, transport_rank, transport_ranks, share_failure
   use vibrobeam_blas_threads, only: limit_blas_threads
   implicit none

   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(sweep_settings) :: sweep
   character(len=message_length) :: errmsg
   character(len=:), allocatable :: input_file, warnings, blas_warning, resume
   logical :: check_only, text_only
   integer :: stat

   call transport_start(stat, errmsg)
   if (stat /= 0) call fail(exit_other_error, errmsg)
   call parse_command_line(input_file, check_only, text_only)
   if (text_only) call run_text(input_file)
   warnings = ''
   call read_scene(input_file, scene, stat, errmsg, warnings, sweep)
   if (stat /= 0) call fail(exit_invalid_input, errmsg)
   call validate_scene(scene, stat, errmsg)
   if (stat /= 0) call fail(exit_invalid_input, errmsg)
   if (sweep%present) then
      call resolve_sweep(sweep, scene, stat, errmsg)
      if (stat /= 0) call fail(exit_invalid_input, errmsg)
   end if
   if (continues(scene)) call check_continuation()
   call check_output_target(scene, input_file, stat, errmsg, check_size=.not. sweep%present)
   if (stat /= 0) call fail(exit_invalid_input, errmsg)
   ! one BLAS thread unless VIBROBEAM_BLAS_THREADS says otherwise; a sweep's tasks share the
   ! cores themselves (docs/sweeps.md, "Parallel runs")
   call limit_blas_threads(blas_warning)
   if (len(blas_warning) > 0) warnings = warnings//blas_warning//new_line('a')
   if (sweep%present) then
      ! a sweep prepares each point itself; here the first one, for its warnings
      associate (points => sweep_points(sweep))
         call build_problem(point_scene(scene, sweep, points(1)), prepared, warnings, stat, errmsg)
      end associate
      if (stat /= 0 .and. stat /= stat_numerical_failure) call fail(exit_invalid_input, '&sweep point 1: '//errmsg)
      ! the files it writes, its start state, its partial directory, its size (rank 0 looks:
      ! the others would see its lock as another run's)
      stat = 0
      resume = ''
      if (transport_rank() == 0) call check_sweep_files(scene, sweep, input_file, prepared%contacts%count, resume, &
                                                        stat, errmsg)
      call share_failure(stat, errmsg)
      if (stat /= 0) call fail(exit_invalid_input, errmsg)
   else
      call build_problem(scene, prepared, warnings, stat, errmsg)
      if (stat == stat_numerical_failure) call fail(exit_numerical_failure, errmsg)
      if (stat /= 0) call fail(exit_invalid_input, errmsg)
   end if
   warnings = warnings//scene_warnings(scene)
   if (len(warnings) > 0 .and. transport_rank() == 0) &
      write (error_unit, '(a)', advance='no') prefixed(warnings, 'vibrobeam: warning: ')

   if (check_only) then
      if (transport_rank() == 0) then
         call print_resolved_scene()
         if (sweep%present) call write_sweep_check(output_unit, scene, sweep, sweep_threads(), transport_ranks(), resume, &
                                                 prepared%contacts%count)
      end if
      call finish(exit_ok)
   end if

   ! from here on files are written: a signal finishes the work in progress (docs/output.md)
   call watch_signals(stat, errmsg)
   if (stat /= 0) call fail(exit_other_error, errmsg)
   if (sweep%present) call run_sweep_input()
   ! a single run is rank 0's alone (under mpirun the other ranks have nothing to do)
   if (transport_rank() /= 0) call finish(exit_ok)
   select case (scene%analysis%kind)
   case ('modes')
      call run_modes()
   case ('static')
      call run_static()
   case ('periodic')
      call run_periodic_scene()
   case default
      call run_dynamics_scene()
   end select

contains

   !> Print `message` on stderr as 'vibrobeam: message' and stop with `code`. HDF5 is
   !! closed first (every file is closed or discarded by then), so its exit handler has
   !! nothing left to do; stderr is flushed.
   subroutine fail(code, message)
      integer, intent(in) :: code
      character(len=*), intent(in) :: message
      ! under mpirun every rank reads the same input and fails alike: rank 0 speaks
      if (transport_rank() /= 0) call finish(code)
      write (error_unit, '(a)') 'vibrobeam: '//trim(message)
      select case (code)
      case (exit_invalid_input)
         write (error_unit, '(a)') 'vibrobeam: invalid input, nothing written'
      case (exit_other_error)
         if (.not. text_only) write (error_unit, '(a)') &
            'vibrobeam: nothing published; what was at '''//trim(scene%output%file)//''' is untouched'
      end select
      call finish(code)
   end subroutine fail

   !> Close HDF5, flush stdout and stderr, and end with `code` at once (`vb_exit`:
   !! HDF5's exit handler would retry writing a file that a full disk refuses).
   subroutine finish(code)
      integer, intent(in) :: code
      interface
         subroutine c_exit(status) bind(C, name='vb_exit')
            import :: c_int
            integer(c_int), value :: status
         end subroutine c_exit
      end interface
      call close_library()
      call transport_stop()
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(code, c_int))
   end subroutine finish

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

   subroutine parse_command_line(file, check, text)
      character(len=:), allocatable, intent(out) :: file
      logical, intent(out) :: check, text
      character(len=4096) :: argument
      integer :: count, length
      count = command_argument_count()
      check = .false.
      text = .false.
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
      case ('--text')
         if (count /= 2) call usage_error('--text takes exactly one result file')
         text = .true.
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
      write (error_unit, '(a)') 'usage: vibrobeam INPUT.nml | vibrobeam --check INPUT.nml | vibrobeam --text RESULT.h5 | '// &
         'vibrobeam --help | --version'
      stop exit_other_error, quiet=.true.
   end subroutine usage_error

   subroutine print_help()
      write (output_unit, '(a)') &
         'vibrobeam '//version_string//': an elastic Euler-Bernoulli beam on its supports (clamped-free by', &
         'default), vibrating between rigid obstacles (Newton impact law) or compliant ones.', &
         '', &
         'usage:', &
         '  vibrobeam INPUT.nml            run the scene described by INPUT.nml', &
         '  vibrobeam --check INPUT.nml    validate the input, print the resolved scene, its natural', &
         '                                 frequencies, time-step and result-size checks; run nothing', &
         '  vibrobeam --text RESULT.h5     (re)derive the .dat text files of a result file', &
         '  vibrobeam --help | --version', &
         '', &
         'namelist groups: '//namelist_groups_text(), &
         '(every variable is optional; see docs/input.md for units, defaults and ranges).', &
         '', &
         'exit status: 0 success, 2 invalid input (nothing written), 3 numerical failure', &
         '(results up to the failure published, marked failed), 4 interrupted by SIGINT/SIGTERM/SIGUSR1', &
         '(results up to the interruption published, marked interrupted), 1 I/O or other error', &
         '(nothing published, earlier results untouched).'
   end subroutine print_help

   subroutine print_resolved_scene()
      type(check_report) :: report
      associate (model => prepared%model, contacts => prepared%contacts)
      write (output_unit, '(a)') 'vibrobeam '//version_string//': input '''//input_file//''' is valid', &
         'resolved scene:'
      write (output_unit, '(a)', advance='no') format_scene(scene)
      write (output_unit, '(a,i0,a,i0,a)') 'discrete model: ', model%elements, ' '//trim(model%basis)// &
         ' elements, ', model%unknowns, ' unknowns'
      write (output_unit, '(a,i0)') 'contact points: ', contacts%count
      write (output_unit, '(a)', advance='no') prepared%loads%forces%report()
      write (output_unit, '(a)', advance='no') prepared%loads%flow%report()
      if (prepared%reduced) then
         associate (reduction => prepared%reduction)
            write (output_unit, '(a,i0,a,i0,a,i0,a)') 'reduced model (craig-bampton): ', &
               reduction%boundary + reduction%modes, ' unknowns (', reduction%boundary, &
               ' contact displacement'//plural(reduction%boundary)//', ', reduction%modes, &
               ' fixed-interface mode'//plural(reduction%modes)//')'
            if (reduction%modes > 0) write (output_unit, '(a,es12.5,a,es12.5,a)') '  highest fixed-interface mode kept: ', &
               reduction%omega(reduction%modes), ' rad/s, ', reduction%omega(reduction%modes)/(2*pi), ' Hz'
            if (reduction%cutoff > 0) write (output_unit, '(a,es12.5,a,es12.5,a)') '  cut-off: ', reduction%cutoff, &
               ' rad/s, ', reduction%cutoff/(2*pi), ' Hz'//merge(' (default)', '          ', &
               is_unset(scene%mesh%reduction_frequency))
         end associate
      end if
      call make_check_report(scene, model, report, stat, errmsg, contacts%count)
      if (stat /= 0) call fail(exit_numerical_failure, errmsg)
      write (output_unit, '(a)', advance='no') check_report_text(scene, report, sweep=sweep%present)
      end associate
   end subroutine print_resolved_scene

   !> A modes run: compute, publish, print the frequencies (docs/output.md, "Natural modes").
   subroutine run_modes()
      type(run_outcome) :: outcome
      call run_modal(scene, prepared, outcome, stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      write (output_unit, '(a,i0,a)') 'vibrobeam: ', size(outcome%omega), ' natural modes written to '// &
         trim(scene%output%file)//':'
      write (output_unit, '(a)', advance='no') frequencies_text(outcome%omega)
      call stop_if_interrupted(outcome%text_skipped)
      call finish(exit_ok)
   end subroutine run_modes

   !> A static analysis. A failed solve (no convergence, or an answer that fails its
   !! a-posteriori check) publishes its last iterate marked 'failed' with the reason in
   !! /static, and exits with status 3 (docs/output.md, "Exit status").
   subroutine run_static()
      type(run_outcome) :: outcome
      call run_equilibrium(scene, prepared, outcome, stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      if (outcome%status == outcome_failed) then
         write (error_unit, '(a)') 'vibrobeam: static equilibrium failed: '//trim(outcome%failure)
         write (error_unit, '(a)') 'vibrobeam: the last iterate, not an equilibrium, written to '// &
            trim(scene%output%file)//' (/run status = ''failed'', the reason in /static failure)'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(exit_numerical_failure)
      end if
      write (output_unit, '(a,i0,a,es9.2,a)') 'vibrobeam: static equilibrium with ', outcome%in_contact, &
         ' contact points in contact (displacements to ', outcome%position_bound, ' m) written to '// &
         trim(scene%output%file)
      call stop_if_interrupted(outcome%text_skipped)
      call finish(exit_ok)
   end subroutine run_static

   !> A periodic-orbit analysis (docs/method.md, "Periodic orbits by shooting"). An orbit
   !! that Newton's method does not reach, or a step that fails, publishes the last
   !! iterate marked 'failed' with the reason in /periodic failure and exits with status 3.
   subroutine run_periodic_scene()
      type(run_outcome) :: outcome
      character(len=:), allocatable :: orbit_kind, method
      call run_periodic_kind(scene, prepared, outcome, stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      if (continues(scene)) then
         call report_continuation(outcome)
         return
      end if
      select case (outcome%status)
      case (outcome_failed)
         write (error_unit, '(a)') 'vibrobeam: periodic orbit not found: '//trim(outcome%failure)
         write (error_unit, '(a)') 'vibrobeam: the last iterate, not an orbit, written to '//trim(scene%output%file)// &
            ' (/run status = ''failed'', the reason in /periodic failure)'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(outcome_exit_status(outcome%status))
      case (outcome_interrupted)
         write (error_unit, '(a,i0,a)') 'vibrobeam: interrupted by '//interrupt_name()//' after ', &
            outcome%newton_iterations, ' Newton iterations; the last iterate written to '//trim(scene%output%file)// &
            ' (/run status = ''interrupted'')'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(outcome_exit_status(outcome%status))
      end select
      orbit_kind = 'periodic orbit'
      method = 'Newton'
      if (scene%periodic%autonomous) then
         orbit_kind = 'autonomous periodic orbit'
         method = 'Gauss-Newton'
      end if
      write (output_unit, '(a,es12.5,a,i0,a,es9.2,a)') 'vibrobeam: '//orbit_kind//' of period ', &
         outcome%period, ' s after ', outcome%newton_iterations, ' '//method//' iterations (residual ', outcome%residual, &
         '), largest Floquet multiplier modulus '//fixed_text(outcome%largest_multiplier, 6)//', '// &
         fixed_text(outcome%wall_seconds, 2)//' s; written to '//trim(scene%output%file)
      call stop_if_interrupted(outcome%text_skipped)
      call finish(exit_ok)
   end subroutine run_periodic_scene

   !> The continuation's parameter, step and bounds (`resolve_continuation`): invalid input
   !! stops here, before anything is written.
   subroutine check_continuation()
      type(sweep_axis) :: axis
      real(dp) :: start
      call resolve_continuation(scene, axis, start, stat, errmsg)
      if (stat /= 0) call fail(exit_invalid_input, errmsg)
   end subroutine check_continuation

   !> What a continuation of periodic orbits did (docs/method.md, "Continuation of periodic
   !! orbits"). A branch that ends early (its first orbit not found, the corrector failing
   !! at the smallest step) publishes its points marked 'failed' with the reason in
   !! /periodic failure and exits with status 3.
   subroutine report_continuation(outcome)
      type(run_outcome), intent(in) :: outcome
      select case (outcome%status)
      case (outcome_failed)
         write (error_unit, '(a)') 'vibrobeam: continuation ended early: '//trim(outcome%failure)
         write (error_unit, '(a,i0,a)') 'vibrobeam: the branch''s ', outcome%branch_points, ' points written to '// &
            trim(scene%output%file)//' (/run status = ''failed'', the reason in /periodic failure)'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(outcome_exit_status(outcome%status))
      case (outcome_interrupted)
         write (error_unit, '(a,i0,a)') 'vibrobeam: interrupted by '//interrupt_name()//' after ', &
            outcome%branch_points, ' branch points; they are written to '//trim(scene%output%file)// &
            ' (/run status = ''interrupted'')'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(outcome_exit_status(outcome%status))
      end select
      if (scene%periodic%autonomous) then   ! a backbone: no bifurcation is looked for on it
         write (output_unit, '(a,i0,a)') 'vibrobeam: backbone of ', outcome%branch_points, &
            ' autonomous periodic orbits, '//fixed_text(outcome%wall_seconds, 2)//' s; written to '// &
            trim(scene%output%file)
      else
         write (output_unit, '(a,i0,a,i0,a)') 'vibrobeam: branch of ', outcome%branch_points, &
            ' periodic orbits with ', outcome%bifurcations, ' bifurcations located, '// &
            fixed_text(outcome%wall_seconds, 2)//' s; written to '//trim(scene%output%file)
      end if
      call stop_if_interrupted(outcome%text_skipped)
      call finish(exit_ok)
   end subroutine report_continuation

   subroutine run_dynamics_scene()
      type(run_outcome) :: outcome
      call run_dynamics(scene, prepared, outcome, stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      select case (outcome%status)
      case (outcome_failed)
         write (error_unit, '(a)') 'vibrobeam: numerical failure at '//trim(outcome%failure)
         write (error_unit, '(a)') 'vibrobeam: results up to the failure written to '//trim(scene%output%file)// &
            ' (/run status = ''failed'')'
         call finish(outcome_exit_status(outcome%status))
      case (outcome_interrupted)
         write (error_unit, '(a,i0,a)') 'vibrobeam: interrupted by '//interrupt_name()//' after step ', &
            outcome%steps, '; results up to it written to '//trim(scene%output%file)//' (/run status = ''interrupted'')'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(outcome_exit_status(outcome%status))
      end select
      ! impacts and penetration are the rigid stops'; compliant stops show their peak force
      ! and how long they were in contact (docs/output.md, "What a run prints")
      write (output_unit, '(a,i0,a)', advance='no') 'vibrobeam: ', outcome%steps, ' steps, '
      if (any(scene%obstacles%stiffness <= 0) .or. .not. outcome%compliant) &
         write (output_unit, '(i0,a,es10.3,a)', advance='no') outcome%impacts, ' impacts, largest penetration ', &
         outcome%max_penetration, ' m, '
      if (outcome%compliant) write (output_unit, '(a,es10.3,a,es10.3,a)', advance='no') 'peak contact force ', &
         outcome%peak_force, ' N, in contact ', outcome%contact_time, ' s ('// &
         fixed_text(100*outcome%contact_time/max(outcome%steps*scene%time%dt, tiny(1.0_dp)), 2)//' % of the run), '
      write (output_unit, '(a)') fixed_text(outcome%wall_seconds, 2)//' s; written to '//trim(scene%output%file)// &
         ' (run '//trim(outcome%run_id)//')'
      if (outcome%poincare_samples > 0) call print_diagnostics(outcome)
      call stop_if_interrupted(outcome%text_skipped)
      call finish(exit_ok)
   end subroutine run_dynamics_scene

   !> What the Poincare samples of the statistics window say (docs/output.md, "What a run
   !! prints"): their period, the 0-1 test and, when asked, the Lyapunov exponent.
   subroutine print_diagnostics(outcome)
      type(run_outcome), intent(in) :: outcome
      write (output_unit, '(a,i0,a)', advance='no') 'vibrobeam: ', outcome%poincare_samples, ' Poincare samples: '
      select case (outcome%poincare_period)
      case (1:)
         write (output_unit, '(a,i0)', advance='no') 'period ', outcome%poincare_period
      case (0)
         write (output_unit, '(a,i0)', advance='no') 'no period up to ', min(64_int64, outcome%poincare_samples/3)
      case default
         write (output_unit, '(a)', advance='no') 'period not determined'
      end select
      if (outcome%zero_one_lags > 0) then
         write (output_unit, '(a)', advance='no') ', 0-1 test K = '//significant_text(outcome%zero_one_k, 3)//' ('// &
            integer_text(outcome%zero_one_lags)//' lags)'
      else
         write (output_unit, '(a)', advance='no') ', 0-1 test not determined (fewer than 100 samples)'
      end if
      if (outcome%lyapunov_periods > 0) then
         write (output_unit, '(a)') ', Lyapunov exponent '//significant_text(outcome%lyapunov, 4)//' +- '// &
            significant_text(outcome%lyapunov_error, 2)//' 1/s ('//significant_text(outcome%lyapunov_per_period, 4)// &
            ' per forcing period, over '//integer_text(int(outcome%lyapunov_periods))//' periods)'
      else
         write (output_unit, '(a)') ''
      end if
   end subroutine print_diagnostics

   !> A sweep (docs/sweeps.md): every point not yet done, the sweep file, and the exit
   !! status: 0, 3 when a point failed (the sweep file is published, the failed points
   !! marked), 4 when interrupted (published with the points done; rerun to go on), 1 when
   !! its files cannot be written (nothing published; the points done are kept for a rerun).
   subroutine run_sweep_input()
      type(sweep_outcome) :: outcome
      call run_sweep(scene, sweep, outcome, stat, errmsg)
      if (stat == stat_invalid_input) call fail(exit_invalid_input, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      if (transport_rank() /= 0) then
         if (outcome%status == outcome_interrupted) call finish(exit_interrupted)
         if (outcome%failed > 0) call finish(exit_numerical_failure)
         if (interrupt_requested()) call finish(exit_interrupted)
         call finish(exit_ok)
      end if
      write (output_unit, '(a,i0,a)', advance='no') 'vibrobeam: sweep of ', outcome%points, ' points ('
      if (outcome%resumed > 0) write (output_unit, '(i0,a)', advance='no') outcome%resumed, &
         ' done before, from '//trim(scene%output%file)//'.partial, '
      write (output_unit, '(i0,a,i0,a,i0,a,i0,a)') outcome%failed, ' failed, ', outcome%interrupted, &
         ' interrupted), '//fixed_text(outcome%wall_seconds, 2)//' s on ', outcome%threads, ' threads x ', outcome%ranks, &
         ' processes; written to '//trim(scene%output%file)
      if (outcome%status == outcome_interrupted) then
         write (error_unit, '(a,i0,a)') 'vibrobeam: interrupted by '//signal_name()//'; the points done are in '// &
            trim(scene%output%file)//' (/run status = ''interrupted''), ', outcome%not_run + outcome%interrupted, &
            ' to run: run the same input again to go on (they are kept in '//trim(scene%output%file)//'.partial)'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(exit_interrupted)
      end if
      if (outcome%failed > 0) then
         write (error_unit, '(a)', advance='no') prefixed(trim(outcome%failures), 'vibrobeam: failed: ')
         write (error_unit, '(a,i0,a)') 'vibrobeam: ', outcome%failed, ' points failed (marked in /sweep/status)'
         call stop_if_interrupted(outcome%text_skipped)
         call finish(exit_numerical_failure)
      end if
      call stop_if_interrupted(outcome%text_skipped)
      call finish(exit_ok)
   end subroutine run_sweep_input

   !> After publication: a signal that arrived meanwhile ends the program with status 4
   !! (the published result is complete; the text files are missing when `text_skipped`).
   subroutine stop_if_interrupted(text_skipped)
      logical, intent(in) :: text_skipped
      if (text_skipped) write (error_unit, '(a)') 'vibrobeam: '//interrupt_name()// &
         ' while deriving the text files: published without them; derive them with vibrobeam --text '// &
         trim(scene%output%file)
      if (interrupt_requested()) call finish(exit_interrupted)
   end subroutine stop_if_interrupted

   !> vibrobeam --text RESULT.h5: derive the .dat files of a result file and publish them
   !! beside it (the .dat files of the same stem that it does not produce are removed).
   subroutine run_text(file)
      character(len=*), intent(in) :: file
      type(derived_file), allocatable :: files(:)
      type(progress_meter) :: meter
      logical :: interrupted
      call watch_signals(stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      call meter%init(.false.)
      call derive_text_files(file, file, meter, .true., files, interrupted, stat, errmsg)
      call meter%end_line()
      if (stat /= 0) call fail(exit_other_error, errmsg)
      if (interrupted) then
         write (error_unit, '(a)') 'vibrobeam: interrupted by '//interrupt_name()//'; no text file changed'
         call finish(exit_interrupted)
      end if
      call publish_files('', file, files, stat, errmsg)
      if (stat /= 0) call fail(exit_other_error, errmsg)
      write (output_unit, '(a,i0,a)') 'vibrobeam: ', size(files), ' text files derived from '//file
      call finish(exit_ok)
   end subroutine run_text

   !> The signal that interrupted this process, or (under mpirun) another rank.
   function signal_name() result(name)
      character(len=:), allocatable :: name
      name = interrupt_name()
      if (len(name) == 0) name = 'a signal to another rank'
   end function signal_name

   !> 's' unless `count` is 1, for the messages.
   pure function plural(count) result(suffix)
      integer, intent(in) :: count
      character(len=:), allocatable :: suffix
      suffix = merge('s', ' ', count /= 1)
      suffix = trim(suffix)
   end function plural
end program vibrobeam_main
