!> Self-convergence study of the velocity-based stepper (theory §3) on the two-stop
!! looseness scene (inputs/looseness_tip_stops.nml): a steel cantilever whose tip rattles
!! between rigid stops at +-1 mm. Results and discussion: studies/convergence/REPORT.md.
!!
!! There is no closed form, so every run is compared with a finer run of the same scene
!! (self-convergence) over a window [0, T] that holds about five impact events. Errors of
!! a run (dt, N) against a finer run (dt_f, N_f):
!! - tip: max over the run's steps t_n in [0, T] of |u_h(L, t_n) - u_f(L, t_n)|; every dt
!!   is dt_f times a power of 2, so the finer grid contains every t_n;
!! - field: the time-RMS of the displacement error at 11 equally spaced points
!!   x_p = p L/10, p = 0..10 (evaluated with `point_row`, so the meshes need not match):
!!   ( 1/T int_0^T 1/11 sum_p (u_h - u_f)(x_p, t)^2 dt )^(1/2), trapezoidal rule on the t_n;
!! - energy: |E_h(T) - E_f(T)|, E = 1/2 V^T M V + 1/2 U^T K U.
!!
!! Studies, in the order of the output:
!! 1. survey: the scene as given (its dt, N, t_end) and its impact events, to place T;
!! 2. joint refinement (the acceptance item): level k has dt = dt0/2^k and
!!    N = nint(N0 2^(k/2)); level 4 = (dt0/16, 4 N0) is the reference, levels 0..3 are
!!    compared with it (level 3 is one level coarser than the reference);
!! 3. dt alone at N = 32, reference dt0/256 (4 times finer than the finest row);
!! 4. N alone at dt = dt0/64, reference N = 256 (4 times finer than the finest row);
!! 5. the tip error of the joint levels over shorter windows [0, T_j];
!! 6. successive differences along the joint path (level k against level k + 1, no fixed
!!    reference) far beyond level 4, for the scene and for two variants: theta = 0.55
!!    (numerical damping of the unresolved modes) and e = 1 (no dissipation at impacts).
!!
!! An impact event: the impulses on one side of one contact point whose successive
!! impulses are at most `event_gap` apart (the rebounds of one contact episode, every step
!! or every other step, count once).
!!
!! usage: self_convergence [--check] SCENE.nml OUTPUT_DIRECTORY
!! Writes OUTPUT_DIRECTORY/self_convergence.txt (the tables, also printed) and
!! OUTPUT_DIRECTORY/self_convergence.dat (gnuplot blocks, each named by the start of its
!! first comment line). Exit status 0; 2 on a usage, input or numerical failure; with --check, 1 when an
!! error of the joint refinement does not decrease from one level to the next.
program self_convergence
   use vibrobeam_kinds, only: dp, int64, error_unit, output_unit
   use vibrobeam_text, only: integer_text
   use vibrobeam_status, only: message_length
   use vibrobeam_scene, only: scene_type
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_scene_read, only: read_scene
   use vibrobeam_convergence_runs, only: event_gap, run_history, run_errors, simulate, compare, tip_error, &
                               field_size, move_alloc_history, fail, sci, fixed, padded, rate, coarsest_dt, &
                               level_dt => joint_dt, level_elements => joint_elements
   implicit none

   real(dp), parameter :: window_end = 0.025_dp      !! T (s): free flight after the 4th event
   integer, parameter :: joint_levels = 4            !! levels 0..4; level 4 is the reference
   integer, parameter :: time_study_elements = 32    !! N of the dt-alone study
   integer, parameter :: time_study_levels = 6       !! rows dt0 .. dt0/2^6, reference dt0/2^8
   integer, parameter :: space_study_elements(4) = [8, 16, 32, 64]   !! reference 4*64
   real(dp), parameter :: space_study_dt = coarsest_dt/64            !! dt of the N-alone study (s)
   integer, parameter :: cauchy_levels = 9           !! successive differences up to level 9
   integer, parameter :: variant_levels = 8          !! ... and up to level 8 for the variants
   real(dp), parameter :: free_flight_end = 2e-3_dp  !! before the first impact (t* = 2.06e-3 s)
   real(dp), parameter :: first_contact_end = 2.5e-3_dp   !! 0.4 ms into the first contact episode
   !> window ends of study 5 (s): free flight, inside the first contact episode, then
   !! after each of the four events
   real(dp), parameter :: window_ends(6) = [free_flight_end, first_contact_end, 4e-3_dp, 8e-3_dp, 1.6e-2_dp, &
                                            window_end]


   type(scene_type) :: base
   character(len=:), allocatable :: scene_file, output_directory
   character(len=message_length) :: errmsg
   logical :: check, accepted
   integer :: stat, text_unit, data_unit, k
   integer(int64) :: clock_start, clock_now, clock_rate
   type(run_history) :: survey, joint(0:joint_levels), time_runs(0:time_study_levels), time_reference
   type(run_history) :: space_runs(size(space_study_elements)), space_reference
   type(run_errors) :: joint_errors(0:joint_levels - 1), time_errors(0:time_study_levels)
   type(run_errors) :: space_errors(size(space_study_elements))
   real(dp) :: joint_dt(0:cauchy_levels), time_dt(0:time_study_levels), space_h(size(space_study_elements))
   integer :: joint_elements(0:cauchy_levels)

   call system_clock(clock_start, clock_rate)
   call parse_arguments(scene_file, output_directory, check)
   call read_scene(scene_file, base, stat, errmsg)
   if (stat == 0) call validate_scene(base, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   open (newunit=text_unit, file=output_directory//'/self_convergence.txt', status='replace', action='write', &
         iostat=stat, iomsg=errmsg)
   if (stat /= 0) call fail(errmsg)
   open (newunit=data_unit, file=output_directory//'/self_convergence.dat', status='replace', action='write', &
         iostat=stat, iomsg=errmsg)
   if (stat /= 0) call fail(errmsg)
   write (data_unit, '(a)') '# self_convergence.dat, written by studies/convergence/self_convergence.f90 '// &
      'for '//scene_file, '# one block per study; gnuplot selects one by the start of its first comment '// &
      'line: index ''name''', '', ''

   call emit('Self-convergence of the velocity-based stepper (theory §3) on '//scene_file)
   call emit('(studies/convergence/self_convergence.f90; discussion in studies/convergence/REPORT.md)')
   call emit('')

   ! the joint path: dt halves, N grows by sqrt(2), from (dt0, N0)
   do k = 0, cauchy_levels
      joint_dt(k) = level_dt(k)
      joint_elements(k) = level_elements(k)
   end do

   ! 1. survey of the scene as given
   call simulate(base, base%time%dt, base%mesh%elements, base%time%t_end, survey)
   call write_survey()

   ! 2. joint refinement against level joint_levels = (dt0/16, 4 N0)
   do k = 0, joint_levels
      call simulate(base, joint_dt(k), joint_elements(k), window_end, joint(k))
   end do
   do k = 0, joint_levels - 1
      joint_errors(k) = compare(joint(k), joint(joint_levels), window_end)
   end do
   call write_table('2. Joint refinement (acceptance item): dt = dt0/2^k, N = nint(N0 2^(k/2)), k = 0..3, '// &
                    'against k = 4', joint(0:joint_levels - 1), joint(joint_levels), joint_errors, &
                    joint_dt(0:joint_levels - 1), 'dt (ratio 2; the h ratio is sqrt 2)')
   call emit('   (level 3 is one level coarser than the reference: its error also estimates the reference''s own)')
   call write_data_block('joint refinement', joint(0:joint_levels - 1), joint(joint_levels), joint_errors)

   ! 3. dt alone
   do k = 0, time_study_levels
      time_dt(k) = coarsest_dt/2**k
      call simulate(base, time_dt(k), time_study_elements, window_end, time_runs(k))
   end do
   call simulate(base, coarsest_dt/2**(time_study_levels + 2), time_study_elements, window_end, time_reference)
   do k = 0, time_study_levels
      time_errors(k) = compare(time_runs(k), time_reference, window_end)
   end do
   call write_table('3. Refinement in dt alone (N fixed)', time_runs, time_reference, time_errors, time_dt, 'dt')
   call write_data_block('dt alone', time_runs, time_reference, time_errors)

   ! 4. N alone
   do k = 1, size(space_study_elements)
      call simulate(base, space_study_dt, space_study_elements(k), window_end, space_runs(k))
      space_h(k) = base%beam%length/space_study_elements(k)
   end do
   call simulate(base, space_study_dt, 4*space_study_elements(size(space_study_elements)), window_end, &
                 space_reference)
   do k = 1, size(space_study_elements)
      space_errors(k) = compare(space_runs(k), space_reference, window_end)
   end do
   call write_table('4. Refinement in N alone (dt fixed)', space_runs, space_reference, space_errors, space_h, 'h')
   call write_data_block('N alone', space_runs, space_reference, space_errors)

   ! 5. where the convergence is lost
   call write_window_table()

   ! 6. successive differences along the joint path, far beyond the reference
   call successive_differences(base%time%theta, base%impact%restitution, cauchy_levels, 'scene as given')
   call successive_differences(0.55_dp, base%impact%restitution, variant_levels, 'numerical damping of the unresolved modes')
   call successive_differences(base%time%theta, 1.0_dp, variant_levels, 'no dissipation at impacts')

   accepted = decreasing(joint_errors)
   call emit('')
   call emit('Acceptance item (every error of study 2 decreases from one level to the next): '// &
             trim(merge('met    ', 'not met', accepted)))
   call system_clock(clock_now)
   call emit('total wall time '//fixed(real(clock_now - clock_start, dp)/clock_rate, 1)//' s')
   close (text_unit)
   close (data_unit)
   if (check .and. .not. accepted) then
      write (error_unit, '(a)') 'self_convergence: the errors of the joint refinement do not all decrease'
      stop 1, quiet=.true.
   end if

contains

   subroutine parse_arguments(file, directory, check_flag)
      character(len=:), allocatable, intent(out) :: file       !! scene namelist
      character(len=:), allocatable, intent(out) :: directory  !! where the tables go
      logical, intent(out) :: check_flag                       !! --check given
      character(len=4096) :: argument
      integer :: first, length
      check_flag = .false.
      first = 1
      call get_command_argument(1, argument, length)
      if (trim(argument) == '--check') then
         check_flag = .true.
         first = 2
      end if
      if (command_argument_count() /= first + 1) &
         call fail('usage: self_convergence [--check] SCENE.nml OUTPUT_DIRECTORY')
      call get_command_argument(first, argument, length)
      file = argument(1:length)
      call get_command_argument(first + 1, argument, length)
      directory = argument(1:length)
   end subroutine parse_arguments

   !> Write one line to the text file and to stdout.
   subroutine emit(line)
      character(len=*), intent(in) :: line
      write (text_unit, '(a)') line
      write (output_unit, '(a)') line
   end subroutine emit

   !> Rate of row k against row k - 1 as text, '-' for the first row.
   function rate_text(errors, sizes, k) result(text)
      real(dp), intent(in) :: errors(:), sizes(:)
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      if (k == 1) then
         text = '     -'
      else
         text = fixed(rate(errors(k - 1), errors(k), sizes(k - 1), sizes(k)), 2, 6)
      end if
   end function rate_text

   !> A refinement table: one row per run, errors against `reference`, rates against
   !! `sizes` (dt or h) between successive rows.
   subroutine write_table(title, runs, reference, errors, sizes, size_name)
      character(len=*), intent(in) :: title
      type(run_history), intent(in) :: runs(:), reference
      type(run_errors), intent(in) :: errors(:)
      real(dp), intent(in) :: sizes(:)
      character(len=*), intent(in) :: size_name   !! what `sizes` are, for the caption
      real(dp) :: tip_errors(size(errors)), field_errors(size(errors)), energy_errors(size(errors))
      integer :: k
      tip_errors = errors%tip
      field_errors = errors%field
      energy_errors = errors%energy
      call emit('')
      call emit(title)
      call emit('reference: dt = '//sci(reference%dt)//' s, N = '//integer_text(reference%elements)//': '// &
                integer_text(reference%events)//' impact events, E(T) = '// &
                sci(reference%energy(nint(window_end/reference%dt)))//' J, max |u_tip| = '// &
                sci(maxval(abs(reference%tip)))//' m, time-RMS field = '//sci(field_size(reference, window_end))//' m')
      call emit('     dt (s)     N  events impulses max pen (m)   tip max (m)  rate  field L2 (m)  rate'// &
                '   energy (J)  rate  wall (s)')
      do k = 1, size(runs)
         call emit(sci(runs(k)%dt)//' '//padded(runs(k)%elements, 5)//' '//padded(runs(k)%events, 7)//' '// &
                   padded(runs(k)%impulse_steps, 8)//'   '//sci(runs(k)%max_penetration)//'    '// &
                   sci(tip_errors(k))//rate_text(tip_errors, sizes, k)//'    '//sci(field_errors(k))// &
                   rate_text(field_errors, sizes, k)//'    '//sci(energy_errors(k))// &
                   rate_text(energy_errors, sizes, k)//'  '//fixed(runs(k)%wall_seconds, 2, 8))
      end do
      call emit('   (rates against '//size_name//' between successive rows; "impulses": steps with an impulse)')
   end subroutine write_table

   !> One gnuplot block (two blank lines after it): dt, N, h, errors, and the errors
   !! relative to the size of the reference's own solution.
   subroutine write_data_block(title, runs, reference, errors)
      character(len=*), intent(in) :: title
      type(run_history), intent(in) :: runs(:), reference
      type(run_errors), intent(in) :: errors(:)
      real(dp) :: tip_scale, field_scale, energy_scale
      integer :: k, last
      last = nint(window_end/reference%dt)
      tip_scale = maxval(abs(reference%tip(0:last)))
      field_scale = field_size(reference, window_end)
      energy_scale = reference%energy(last)
      write (data_unit, '(a)') '# '//title//'; reference dt = '//sci(reference%dt)//' s, N = '// &
         integer_text(reference%elements)//'; window [0, '//sci(window_end)//'] s'
      write (data_unit, '(a)') '# dt (s)  N  h (m)  tip max error (m)  field L2 error (m)  energy error (J)  '// &
         'tip/max|u_tip,ref|  field/|u_ref|_L2  energy/E_ref(T)'
      do k = 1, size(runs)
         write (data_unit, '(es14.6,i6,*(es14.6))') runs(k)%dt, runs(k)%elements, base%beam%length/runs(k)%elements, &
            errors(k)%tip, errors(k)%field, errors(k)%energy, errors(k)%tip/tip_scale, &
            errors(k)%field/field_scale, errors(k)%energy/energy_scale
      end do
      write (data_unit, '(a)') '', ''
   end subroutine write_data_block

   !> The impact events of the survey run, and how many fall in the window.
   subroutine write_survey()
      integer :: k
      call emit('1. Impact events of the scene as given (dt = '//sci(survey%dt)//' s, N = '// &
                integer_text(survey%elements)//', t_end = '//sci(survey%steps*survey%dt)//' s): '// &
                integer_text(survey%events)//' events, '//integer_text(survey%impulse_steps)// &
                ' steps with an impulse')
      call emit('   an event: impulses on one side of one contact point at most '//sci(event_gap)// &
                ' s apart (its rebounds count once)')
      call emit('  event  side    first impulse (s)  last impulse (s)  steps with an impulse')
      do k = 1, survey%events
         call emit(padded(k, 7)//'  '//merge('below', 'above', survey%event_side(k) > 0)//'   '// &
                   sci(survey%event_first(k))//'          '//sci(survey%event_last(k))//'        '// &
                   padded(survey%event_impulses(k), 6))
      end do
      call emit('window [0, T], T = '//sci(window_end)//' s: '// &
                integer_text(count(survey%event_first <= window_end))//' events, the last one ends at '// &
                sci(maxval(survey%event_last, mask=survey%event_last <= window_end))//' s, the next one starts at '// &
                sci(minval(survey%event_first, mask=survey%event_first > window_end))//' s')
   end subroutine write_survey

   !> Tip error of each joint level against the reference over [0, T_j].
   subroutine write_window_table()
      integer :: j, level
      character(len=:), allocatable :: line
      call emit('')
      call emit('5. Tip max error (m) of the joint levels against the reference (level 4) over [0, T_j]')
      line = '  level    dt (s)   N'
      do j = 1, size(window_ends)
         line = line//'  T_j = '//sci(window_ends(j))
      end do
      call emit(line)
      do level = 0, joint_levels - 1
         line = padded(level, 7)//'  '//sci(joint(level)%dt)//' '//padded(joint(level)%elements, 3)
         do j = 1, size(window_ends)
            line = line//'        '//sci(tip_error(joint(level), joint(joint_levels), window_ends(j)))
         end do
         call emit(line)
      end do
      line = '  rate, level 0 to 2  '
      do j = 1, size(window_ends)
         line = line//'      '//fixed(rate(tip_error(joint(0), joint(joint_levels), window_ends(j)), &
                                          tip_error(joint(2), joint(joint_levels), window_ends(j)), &
                                          joint(0)%dt, joint(2)%dt), 2, 11)
      end do
      call emit(line)
      call emit('   (T_j: before the first impact, 0.4 ms into the first contact episode, then after events 1, 2, 3, 4)')
      write (data_unit, '(a)') '# window ends: tip max error over [0, T_j] of joint levels 0..3 against level 4'
      write (data_unit, '(a)') '# T_j (s)  level 0  level 1  level 2  level 3 (m)'
      do j = 1, size(window_ends)
         write (data_unit, '(*(es14.6))') window_ends(j), &
            (tip_error(joint(level), joint(joint_levels), window_ends(j)), level=0, joint_levels - 1)
      end do
      write (data_unit, '(a)') '', ''
   end subroutine write_window_table

   !> Along the joint path with theta and e replaced, the difference between each level
   !! and the next one, up to level `levels`: if the runs converge at order p in dt, the
   !! differences shrink by 2^p per level too.
   subroutine successive_differences(theta, restitution, levels, label)
      real(dp), intent(in) :: theta, restitution
      integer, intent(in) :: levels
      character(len=*), intent(in) :: label   !! what the variant is, for the titles
      type(scene_type) :: variant
      type(run_history) :: previous, current
      type(run_errors) :: whole
      real(dp), dimension(0:levels - 1) :: free, first, tip, field, energy
      integer :: level, events(0:levels - 1), impulses(0:levels - 1)
      character(len=:), allocatable :: title
      variant = base
      variant%time%theta = theta
      variant%impact%restitution = restitution
      title = 'successive differences, theta = '//fixed(theta, 2)//', e = '//fixed(restitution, 2)//' ('//label//')'
      call simulate(variant, joint_dt(0), joint_elements(0), window_end, previous)
      do level = 0, levels - 1
         call simulate(variant, joint_dt(level + 1), joint_elements(level + 1), window_end, current)
         free(level) = tip_error(previous, current, free_flight_end)
         first(level) = tip_error(previous, current, first_contact_end)
         whole = compare(previous, current, window_end)
         tip(level) = whole%tip
         field(level) = whole%field
         energy(level) = whole%energy
         events(level) = previous%events
         impulses(level) = previous%impulse_steps
         call move_alloc_history(current, previous)
      end do
      call emit('')
      call emit('6. Level k against level k + 1 along the joint path: '//title)
      call emit('   tip max difference over [0, '//sci(free_flight_end)//'] s (free flight), [0, '// &
                sci(first_contact_end)//'] s (into the first contact episode) and [0, T]')
      call emit('  k     dt (s)     N  events impulses  tip free   rate  tip first  rate   tip [0,T]  rate'// &
                '  field L2   rate   energy    rate')
      do level = 0, levels - 1
         call emit(padded(level, 3)//'  '//sci(joint_dt(level))//' '//padded(joint_elements(level), 5)//' '// &
                   padded(events(level), 7)//' '//padded(impulses(level), 8)//'  '// &
                   sci(free(level))//rate_text(free, joint_dt(0:levels - 1), level + 1)//'  '// &
                   sci(first(level))//rate_text(first, joint_dt(0:levels - 1), level + 1)//'  '// &
                   sci(tip(level))//rate_text(tip, joint_dt(0:levels - 1), level + 1)//'  '// &
                   sci(field(level))//rate_text(field, joint_dt(0:levels - 1), level + 1)//'  '// &
                   sci(energy(level))//rate_text(energy, joint_dt(0:levels - 1), level + 1))
      end do
      call emit('   (differences in m, energy in J; rates against dt between successive rows)')
      write (data_unit, '(a)') '# '//title
      write (data_unit, '(a)') '# k  dt (s)  N  tip [0, free flight] (m)  tip [0, first contact] (m)  '// &
         'tip [0, T] (m)  field L2 [0, T] (m)  energy at T (J)'
      do level = 0, levels - 1
         write (data_unit, '(i3,es14.6,i6,*(es14.6))') level, joint_dt(level), joint_elements(level), free(level), &
            first(level), tip(level), field(level), energy(level)
      end do
      write (data_unit, '(a)') '', ''
   end subroutine successive_differences

   !> True when tip, field and energy errors all decrease strictly from row to row.
   pure logical function decreasing(errors)
      type(run_errors), intent(in) :: errors(:)
      integer :: k
      decreasing = .true.
      do k = 2, size(errors)
         decreasing = decreasing .and. errors(k)%tip < errors(k - 1)%tip .and. &
                      errors(k)%field < errors(k - 1)%field .and. errors(k)%energy < errors(k - 1)%energy
      end do
   end function decreasing


end program self_convergence
