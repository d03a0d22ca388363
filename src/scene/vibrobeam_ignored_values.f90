!> Warnings for values that the file gives and the run does not use (docs/input.md,
!! "Warnings"): a value that is silently ignored leaves its author believing it acted.
!! Which variables were given comes from the scanner (`scanned_file`), never from
!! comparing a value with its default.
!!
!! A value is ignored because of another value of the scene (a mode number beside
!! displacement = 'zero', a frequency beside a zero amplitude, an exponent on a rigid
!! stop); when a sweep varies that other value (`swept`), the value may act at some points
!! and no warning is given.
module vibrobeam_ignored_values
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_scene, only: scene_type, scene_variables, steps_in_time
   use vibrobeam_namelist_scanned, only: scanned_file
   use vibrobeam_namelist_schema, only: namelist_variable, variable_index
   use vibrobeam_scene_values, only: real_input
   use vibrobeam_frequency_twins, only: twin_name
   use vibrobeam_force_settings, only: ignored_forces
   use vibrobeam_flow, only: ignored_flow
   implicit none
   private
   public :: ignored_values

contains

   !> Append to `warnings` one line for each value given that the analysis does not use.
   !! `swept`: the inputs a sweep varies, as 'group.variable' in lower case, without an
   !! element index (none for a single run).
   subroutine ignored_values(scanned, scene, swept, warnings)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: swept(:)
      character(len=:), allocatable, intent(inout) :: warnings
      call analysis_warnings(scanned, scene, warnings)
      if (scene%analysis%kind == 'modes') return
      call obstacle_warnings(scanned, scene, swept, warnings)
      call load_warnings(scanned, scene, swept, warnings)
      call ignored_forces(scanned, scene%forces, scene%analysis%kind == 'static', warnings)
      call ignored_flow(scanned, scene%flow, steps_in_time(scene), any(swept == 'flow.velocity'), warnings)
      if (.not. steps_in_time(scene)) return
      call time_warnings(scanned, scene, swept, warnings)
      call initial_warnings(scanned, scene, warnings)
   end subroutine ignored_values

   !> What the kind of analysis does not use: the modes' count, whole groups, &periodic
   !! outside kind = 'periodic' and t_end (and a dt that steps_per_period sets) inside it,
   !! damping outside the analyses that step in time, histories outside dynamics, the
   !! reduction; and k2 beside the beam's data, the beam's data beside &sections.
   subroutine analysis_warnings(scanned, scene, warnings)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable, intent(inout) :: warnings
      character(len=*), parameter :: unused_by_modes(8) = [character(len=9) :: 'obstacles', 'impact', 'time', &
                                                            'initial', 'load', 'forces', 'flow', 'solver']
      character(len=*), parameter :: unused_by_static(3) = [character(len=9) :: 'impact', 'time', 'initial']
      character(len=*), parameter :: beam_data(4) = [character(len=14) :: 'youngs_modulus', 'density', 'area', &
                                                     'inertia']
      character(len=:), allocatable :: kind_reason, item
      integer :: k
      kind_reason = 'kind = '''//trim(scene%analysis%kind)//''''
      if (scene%analysis%kind /= 'modes' .and. scanned%is_given('analysis', 'modes')) &
         call add(warnings, '&analysis modes = '//integer_text(scene%analysis%modes)//' is ignored: '//kind_reason// &
                  ' computes no natural modes')
      if (scene%analysis%kind /= 'modes' .and. scene%analysis%contact_modes) &
         call add(warnings, '&analysis contact_modes = .true. is ignored: '//kind_reason//' computes no natural modes')
      if (scanned%is_given('beam', 'k2') .and. (scanned%is_given('beam', 'youngs_modulus') .or. &
          scanned%is_given('beam', 'density') .or. scanned%is_given('beam', 'area') .or. &
          scanned%is_given('beam', 'inertia'))) &
         call add(warnings, '&beam k2 is ignored: youngs_modulus, density, area and inertia are given (k2 = EI/(rho S))')
      ! a beam of sections takes its data from them (they cover the whole beam)
      if (scene%beam%sectioned()) then
         do k = 1, size(beam_data)
            if (scanned%is_given('beam', trim(beam_data(k)))) &
               call add(warnings, '&beam '//trim(beam_data(k))//' is ignored: the beam is given by its '// &
                        integer_text(size(scene%beam%sections))//' &sections, which cover it whole')
         end do
      end if
      select case (scene%analysis%kind)
      case ('modes')
         do k = 1, size(unused_by_modes)
            ! the modes in contact hold the contact points of the obstacles
            if (unused_by_modes(k) == 'obstacles' .and. scene%analysis%contact_modes) cycle
            if (scanned%group_given(trim(unused_by_modes(k)))) &
               call add(warnings, '&'//trim(unused_by_modes(k))//' is ignored: kind = ''modes'' computes the modes '// &
                        'of the free cantilever')
         end do
      case ('static')
         do k = 1, size(unused_by_static)
            if (scanned%group_given(trim(unused_by_static(k)))) &
               call add(warnings, '&'//trim(unused_by_static(k))//' is ignored: kind = ''static'' solves for the '// &
                        'equilibrium under the loads at t = 0')
         end do
      end select

      ! &beam damping and &output histories: dynamics only
      if (scene%analysis%kind /= 'periodic' .and. scanned%group_given('periodic')) &
         call add(warnings, '&periodic is ignored: '//kind_reason//' (it belongs to kind = ''periodic'')')
      if (scene%analysis%kind == 'periodic') then
         call given_real(scanned, scene, warnings, 'time', 't_end', scene%time%t_end, kind_reason// &
                         ' steps one orbit at a time (&periodic)')
         ! (the value given is gone: the reader has set dt from steps_per_period)
         if (scene%periodic%steps_per_period > 0 .and. scanned%is_given('time', 'dt')) &
            call add(warnings, '&time dt is ignored: &periodic steps_per_period = '// &
                     integer_text(scene%periodic%steps_per_period)//' sets dt = '//real_text(scene%time%dt)// &
                     ' s, the forcing period over that many steps')
         ! the guess of an autonomous orbit's period and its amplitude: autonomous only
         if (.not. scene%periodic%autonomous) then
            if (scanned%is_given('periodic', 'period')) &
               call add(warnings, '&periodic period is ignored: autonomous = .false. (the period of a forced orbit '// &
                        'is the forcing''s)')
            if (scanned%is_given('periodic', 'tip_amplitude')) &
               call add(warnings, '&periodic tip_amplitude is ignored: autonomous = .false. (it picks an autonomous '// &
                        'orbit of a conservative scene)')
         end if
      end if
      if (.not. steps_in_time(scene)) then
         call given_real(scanned, scene, warnings, 'beam', 'rayleigh_mass', scene%beam%rayleigh_mass, &
                         kind_reason//' has no damping')
         call given_real(scanned, scene, warnings, 'beam', 'rayleigh_stiffness', scene%beam%rayleigh_stiffness, &
                         kind_reason//' has no damping')
         if (scene%beam%modal()) call add(warnings, '&beam modal_damping and modal_damping_ratios are ignored: '// &
                                          kind_reason//' has no damping')
      end if
      if (scene%analysis%kind /= 'dynamics') then
         ! what shapes a dynamics run's histories, statistics and checkpoints
         item = ' is ignored: '//kind_reason//' writes no histories (they belong to kind = ''dynamics'')'
         if (scanned%is_given('output', 'every')) &
            call add(warnings, '&output every = '//integer_text(scene%output%every)//item)
         if (scanned%is_given('output', 'field_every')) &
            call add(warnings, '&output field_every = '//integer_text(scene%output%field_every)//item)
         if (scanned%is_given('output', 'points', 1)) call add(warnings, '&output points'//item)
         call given_real(scanned, scene, warnings, 'output', 'measure_from', scene%output%measure_from, item(14:))
         call given_real(scanned, scene, warnings, 'output', 'checkpoint_seconds', scene%output%checkpoint_seconds, &
                         item(14:))
         call given_real(scanned, scene, warnings, 'output', 'episode_gap', scene%output%episode_gap, item(14:))
         if (scanned%is_given('output', 'poincare_load')) &
            call add(warnings, '&output poincare_load = '''//trim(scene%output%poincare_load)//''''//item)
         if (scene%output%lyapunov) call add(warnings, '&output lyapunov = .true.'//item)
      end if

      ! &mesh: the reduction steps a dynamics run only
      if (scene%mesh%reduction /= 'none' .and. .not. steps_in_time(scene)) then
         call add(warnings, '&mesh reduction = '''//trim(scene%mesh%reduction)//''' is ignored: '//kind_reason// &
                  ' solves the full model (the reduction is for kind = ''dynamics'' and ''periodic'')')
      end if
      if (scene%mesh%reduction == 'none' .or. .not. steps_in_time(scene)) then
         if (scanned%is_given('mesh', 'reduction_modes')) &
            call add(warnings, '&mesh reduction_modes = '//integer_text(scene%mesh%reduction_modes)//' is ignored: '// &
                     reduction_reason())
         call given_real(scanned, scene, warnings, 'mesh', 'reduction_frequency', scene%mesh%reduction_frequency, &
                         reduction_reason())
      end if
   contains
      function reduction_reason() result(text)
         character(len=:), allocatable :: text
         if (.not. steps_in_time(scene)) then
            text = kind_reason//' solves the full model'
         else
            text = 'reduction = ''none'''
         end if
      end function reduction_reason
   end subroutine analysis_warnings

   !> &obstacles: what a rigid or a punctual obstacle does not use.
   subroutine obstacle_warnings(scanned, scene, swept, warnings)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: swept(:)
      character(len=:), allocatable, intent(inout) :: warnings
      character(len=:), allocatable :: item
      integer :: i
      do i = 1, size(scene%obstacles)
         item = '('//integer_text(i)//')'
         associate (o => scene%obstacles(i))
            if (o%stiffness <= 0 .and. scanned%is_given('obstacles', 'exponent', i) .and. &
                .not. any(swept == 'obstacles.stiffness')) &
               call add(warnings, '&obstacles exponent'//item//' = '//real_text(o%exponent)//' is ignored: obstacle '// &
                        integer_text(i)//' is rigid (stiffness'//item//' = 0); the exponent shapes the force of a '// &
                        'compliant stop')
            if (o%x_to <= o%x_from .and. scanned%is_given('obstacles', 'level_to', i) .and. &
                .not. (any(swept == 'obstacles.x_from') .or. any(swept == 'obstacles.x_to'))) &
               call add(warnings, '&obstacles level_to'//item//' = '//real_text(o%level_to)//' m is ignored: obstacle '// &
                        integer_text(i)//' is punctual (x_to = x_from = '//real_text(o%x_from)// &
                        ' m): its level is level_from'//item)
            if (len_trim(o%profile) > 0) then
               if (scanned%is_given('obstacles', 'level_from', i)) &
                  call add(warnings, '&obstacles level_from'//item//' = '//real_text(o%level_from)//' m is ignored: '// &
                           'obstacle '//integer_text(i)//' takes its levels from profile'//item)
               if (scanned%is_given('obstacles', 'level_to', i)) &
                  call add(warnings, '&obstacles level_to'//item//' = '//real_text(o%level_to)//' m is ignored: '// &
                           'obstacle '//integer_text(i)//' takes its levels from profile'//item)
            end if
         end associate
      end do
   end subroutine obstacle_warnings

   !> &load: a frequency, phase or position of a load whose amplitude is zero; and in
   !! statics, what the loads at t = 0 do not use.
   subroutine load_warnings(scanned, scene, swept, warnings)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: swept(:)
      character(len=:), allocatable, intent(inout) :: warnings
      character(len=:), allocatable :: kind_reason
      kind_reason = 'kind = '''//trim(scene%analysis%kind)//''''
      associate (load => scene%load)
         if (abs(load%distributed) <= 0 .and. .not. any(swept == 'load.distributed')) then
            call given_real(scanned, scene, warnings, 'load', 'distributed_frequency', load%distributed_frequency, &
                            'distributed = 0')
            call given_real(scanned, scene, warnings, 'load', 'distributed_phase', load%distributed_phase, &
                            'distributed = 0')
         end if
         if (abs(load%point_force) <= 0 .and. .not. any(swept == 'load.point_force')) then
            call given_real(scanned, scene, warnings, 'load', 'point_frequency', load%point_frequency, &
                            'point_force = 0')
            call given_real(scanned, scene, warnings, 'load', 'point_position', load%point_position, &
                            'point_force = 0')
         end if
         if (abs(load%base_amplitude) <= 0 .and. abs(load%base_acceleration) <= 0 .and. &
             .not. (any(swept == 'load.base_amplitude') .or. any(swept == 'load.base_acceleration'))) &
            call given_real(scanned, scene, warnings, 'load', 'base_frequency', load%base_frequency, &
                            'base_amplitude = 0 and base_acceleration = 0')
         if (scene%analysis%kind /= 'static') return
         ! the loads at t = 0: cos(0) = 1 for the harmonic ones, sin(0) = 0 for the base's
         ! (a frequency beside a zero amplitude has had its warning above)
         if (abs(load%distributed) > 0) call given_real(scanned, scene, warnings, 'load', 'distributed_frequency', &
                                                        load%distributed_frequency, kind_reason//' takes the loads at t = 0')
         if (abs(load%point_force) > 0) call given_real(scanned, scene, warnings, 'load', 'point_frequency', &
                                                        load%point_frequency, kind_reason//' takes the loads at t = 0')
         call given_real(scanned, scene, warnings, 'load', 'base_amplitude', load%base_amplitude, kind_reason// &
                         ' takes the loads at t = 0, where the base excitation''s load (sin 0) is 0')
         call given_real(scanned, scene, warnings, 'load', 'base_acceleration', load%base_acceleration, kind_reason// &
                         ' takes the loads at t = 0, where the base excitation''s load (sin 0) is 0')
         if (abs(load%base_amplitude) > 0 .or. abs(load%base_acceleration) > 0) &
            call given_real(scanned, scene, warnings, 'load', 'base_frequency', load%base_frequency, kind_reason// &
                            ' takes the loads at t = 0, where the base excitation''s load (sin 0) is 0')
      end associate
   end subroutine load_warnings

   !> &time and &impact: what the scheme or the obstacles do not use.
   subroutine time_warnings(scanned, scene, swept, warnings)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: swept(:)
      character(len=:), allocatable, intent(inout) :: warnings
      logical :: any_compliant, any_rigid
      any_compliant = any(scene%obstacles%stiffness > 0) .or. any(swept == 'obstacles.stiffness')
      any_rigid = any(scene%obstacles%stiffness <= 0) .or. any(swept == 'obstacles.stiffness')
      if (scene%time%scheme == 'position') call given_real(scanned, scene, warnings, 'time', 'gamma', scene%time%gamma, &
                                                           'scheme = ''position'' activates contacts by position')
      if (.not. any_compliant .and. scanned%is_given('time', 'compliant_rule')) &
         call add(warnings, '&time compliant_rule = '''//trim(scene%time%compliant_rule)//''' is ignored: no obstacle '// &
                  'is compliant (stiffness > 0)')
      if (.not. any_rigid) then
         call given_real(scanned, scene, warnings, 'impact', 'restitution', scene%impact%restitution, &
                         'no obstacle is rigid (impacts happen at rigid obstacles only)')
         if (scanned%is_given('impact', 'separating_points')) &
            call add(warnings, '&impact separating_points = '''//trim(scene%impact%separating_points)//''' is '// &
                     'ignored: no obstacle is rigid (impacts happen at rigid obstacles only)')
      end if
   end subroutine time_warnings

   !> &initial: the checkpoint's state, or the shape a keyword does not use; and &solver
   !! static_tolerance without a static start.
   subroutine initial_warnings(scanned, scene, warnings)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable, intent(inout) :: warnings
      !> &initial variables that describe the initial state
      character(len=*), parameter :: initial_state(7) = [character(len=22) :: 'displacement', 'displacement_mode', &
                                                          'displacement_amplitude', 'velocity', 'velocity_mode', &
                                                          'velocity_amplitude', 'velocity_profile']
      integer :: k
      associate (initial => scene%initial)
         if (initial%displacement /= 'static' .or. len_trim(initial%from_file) > 0) &
            call given_real(scanned, scene, warnings, 'solver', 'static_tolerance', scene%solver%static_tolerance, &
                            'kind = ''dynamics'' solves a static equilibrium only for &initial displacement = ''static''')
         if (len_trim(initial%from_file) > 0) then
            do k = 1, size(initial_state)
               if (scanned%is_given('initial', trim(initial_state(k)))) &
                  call add(warnings, '&initial '//trim(initial_state(k))//' is ignored: from_file continues the '// &
                           'state of its checkpoint')
            end do
            return
         end if
         if (initial%displacement /= 'mode') then
            if (scanned%is_given('initial', 'displacement_mode')) &
               call add(warnings, '&initial displacement_mode = '//integer_text(initial%displacement_mode)// &
                        ' is ignored: displacement = '''//trim(initial%displacement)//'''')
            call given_real(scanned, scene, warnings, 'initial', 'displacement_amplitude', &
                            initial%displacement_amplitude, &
                            'displacement = '''//trim(initial%displacement)//'''')
         end if
         if (initial%velocity /= 'mode' .and. scanned%is_given('initial', 'velocity_mode')) &
            call add(warnings, '&initial velocity_mode = '//integer_text(initial%velocity_mode)//' is ignored: '// &
                     'velocity = '''//trim(initial%velocity)//'''')
         if (initial%velocity == 'zero' .or. initial%velocity == 'profile') &
            call given_real(scanned, scene, warnings, 'initial', 'velocity_amplitude', initial%velocity_amplitude, &
                            'velocity = '''//trim(initial%velocity)//'''')
         if (initial%velocity /= 'profile' .and. scanned%is_given('initial', 'velocity_profile')) &
            call add(warnings, '&initial velocity_profile = '''//trim(initial%velocity_profile)//''' is ignored: '// &
                     'velocity = '''//trim(initial%velocity)//'''')
      end associate
   end subroutine initial_warnings

   !> Append one warning line.
   subroutine add(warnings, line)
      character(len=:), allocatable, intent(inout) :: warnings
      character(len=*), intent(in) :: line
      warnings = warnings//line//new_line('a')
   end subroutine add

   !> The warning for the real group.name, when given: 'value unit is ignored: reason';
   !! a frequency given in Hz, by its twin (`vibrobeam_frequency_twins`), the same with
   !! the twin's name, value and unit.
   subroutine given_real(scanned, scene, warnings, group, name, value, reason)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable, intent(inout) :: warnings
      character(len=*), intent(in) :: group, name, reason
      real(dp), intent(in) :: value
      type(namelist_variable), allocatable :: table(:)
      type(namelist_variable) :: variable
      character(len=:), allocatable :: unit, given
      real(dp) :: shown
      logical :: found
      given = name
      shown = value
      if (scanned%is_given(group, twin_name(name))) given = twin_name(name)
      if (given /= name) call real_input(scene, group, given, 1, shown, found)
      if (.not. scanned%is_given(group, given)) return
      allocate (table, source=scene_variables())
      variable = table(variable_index(table, group, given))
      unit = trim(variable%unit)
      if (len(unit) > 0) unit = ' '//unit
      call add(warnings, '&'//group//' '//given//' = '//real_text(shown)//unit//' is ignored: '//reason)
   end subroutine given_real
end module vibrobeam_ignored_values
