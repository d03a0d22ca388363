!> The rules between the input values of a scene (docs/input.md): `validate_scene` checks
!! every value against its hard range and keywords (the rows of `visit_scene`), then the
!! relations between variables that matter for the analysis asked for, group by group.
!! The scene itself, its variables and their listing are `vibrobeam_scene`'s.
module vibrobeam_scene_rules
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_schema_visitor, only: is_unset
   use vibrobeam_schema_operations, only: schema_checker
   use vibrobeam_namelist_tokens, only: lowercase
   use vibrobeam_boundary, only: boundary_conditions
   use vibrobeam_beam_settings, only: check_planes
   use vibrobeam_structure, only: beam_structure
   use vibrobeam_section_settings, only: check_sections, max_sections
   use vibrobeam_buckling, only: check_compression
   use vibrobeam_initial_state, only: check_initial
   use vibrobeam_force_settings, only: check_forces
   use vibrobeam_flow, only: check_flow
   use vibrobeam_periodic_settings, only: forcing_frequency, whole_step_tolerance
   use vibrobeam_scene, only: scene_type, visit_scene, sync_frequency_twins, steps_in_time, forcing_of, &
      structure_of, held_conditions, max_steps, max_obstacles, max_supports, max_masses, max_points
   implicit none
   private
   public :: validate_scene

contains

   !> Check every value against what is allowed: first each against its hard range and
   !! keywords (the rows of `visit_scene`), then the relations that matter for the
   !! analysis asked for, group by group. On the first violation stat = stat_failure and errmsg reads
   !! like '&impact restitution = 1.5 is outside [0, 1]'.
   subroutine validate_scene(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(schema_checker) :: checker
      type(scene_type) :: copy
      stat = 0
      errmsg = ''
      if (allocated(scene%obstacles)) then
         if (size(scene%obstacles) > max_obstacles) &
            call fail(stat, errmsg, '&obstacles count = '//integer_text(size(scene%obstacles))//' is outside [0, '// &
                      integer_text(max_obstacles)//']')
      end if
      if (allocated(scene%supports)) then
         if (size(scene%supports) > max_supports) &
            call fail(stat, errmsg, '&supports count = '//integer_text(size(scene%supports))//' is outside [0, '// &
                      integer_text(max_supports)//']')
      end if
      if (allocated(scene%masses)) then
         if (size(scene%masses) > max_masses) &
            call fail(stat, errmsg, '&masses count = '//integer_text(size(scene%masses))//' is outside [0, '// &
                      integer_text(max_masses)//']')
      end if
      if (allocated(scene%beam%sections)) then
         if (size(scene%beam%sections) > max_sections) &
            call fail(stat, errmsg, '&sections count = '//integer_text(size(scene%beam%sections))//' is outside [0, '// &
                      integer_text(max_sections)//']')
      end if
      if (allocated(scene%output%points)) then
         if (size(scene%output%points) > max_points) &
            call fail(stat, errmsg, '&output points: '//integer_text(size(scene%output%points))// &
                      ' points; at most '//integer_text(max_points))
      end if
      if (stat /= 0) return
      copy = scene
      call sync_frequency_twins(copy)
      call visit_scene(copy, checker)
      if (checker%stat /= 0) then
         call fail(stat, errmsg, trim(checker%errmsg))
         return
      end if
      call model_rules(copy, stat, errmsg)
      call structure_rules(copy, stat, errmsg)
      call obstacle_rules(copy, stat, errmsg)
      call time_rules(copy, stat, errmsg)
      call load_rules(copy, stat, errmsg)
      if (stat == 0) call check_forces(copy%forces, copy%beam%length, copy%time%dt, copy%analysis%kind == 'dynamics', &
                                       stat, errmsg)
      if (stat == 0) call check_flow(copy%flow, copy%beam%length, copy%time%scheme, copy%mesh%unknowns(), &
                                     steps_in_time(copy), stat, errmsg)
      if (stat == 0 .and. steps_in_time(copy) .and. len_trim(copy%initial%from_file) == 0) &
         call check_initial(copy%initial, stat, errmsg)
      call output_rules(copy, stat, errmsg)
      if (copy%analysis%kind == 'periodic') call periodic_rules(copy, stat, errmsg)
      call plane_rules(copy, stat, errmsg)
   end subroutine validate_scene

   !> &beam: the four physical data go together; &mesh: a reduced model cannot continue a
   !! checkpoint, and its cut-off is given one way; &analysis: `modes` is bounded by the
   !! mesh only when modes are computed, and the modes in contact need obstacles.
   subroutine model_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      associate (beam => scene%beam, mesh => scene%mesh, analysis => scene%analysis)
         if (beam%physical() .and. .not. beam%sectioned()) then
            call check_given('youngs_modulus', beam%youngs_modulus)
            call check_given('density', beam%density)
            call check_given('area', beam%area)
            call check_given('inertia', beam%inertia)
         end if
         if (stat == 0) call check_planes(beam, stat, errmsg)
         if (mesh%reduction /= 'none' .and. steps_in_time(scene) .and. len_trim(scene%initial%from_file) > 0) &
            call fail(stat, errmsg, '&mesh reduction = '''//trim(mesh%reduction)//''' cannot continue a checkpoint '// &
                      '(&initial from_file): its state is in reduced coordinates; use reduction = ''none''')
         if (mesh%reduction_modes /= -1 .and. .not. is_unset(mesh%reduction_frequency)) &
            call fail(stat, errmsg, '&mesh reduction_modes = '//integer_text(mesh%reduction_modes)// &
                      ' and reduction_frequency = '//real_text(mesh%reduction_frequency)// &
                      ' rad/s are both given: give one of them')
         if (analysis%kind == 'modes') then
            if (analysis%modes < 1 .or. analysis%modes > mesh%unknowns(held_conditions(scene))) &
               call fail(stat, errmsg, '&analysis modes = '//integer_text(analysis%modes)//' is outside [1, '// &
                         integer_text(mesh%unknowns(held_conditions(scene)))//'], the unknowns J of the mesh')
            if (analysis%contact_modes .and. size(scene%obstacles) == 0) &
               call fail(stat, errmsg, '&analysis contact_modes = .true. needs obstacles: the modes in contact hold '// &
                         'every contact point of &obstacles; give obstacles or contact_modes = .false.')
         end if
      end associate
   contains
      !> One of the four physical data, which go together.
      subroutine check_given(name, value)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: value
         if (is_unset(value)) call fail(stat, errmsg, '&beam '//name//' is missing: youngs_modulus, density, '// &
                                        'area and inertia go together (or give k2 alone)')
      end subroutine check_given
   end subroutine model_rules

   !> The supports (&beam ends and springs, &supports) and point masses (&masses): each
   !! support inside the beam, on a node of its own that is not an end's, a 'spring' one
   !! with a spring; each mass on the beam; statics, an initial static equilibrium and the
   !! reduced model need a beam without rigid-body motion (K U = F); statics of another
   !! structure than the clamped-free beam takes linear compliant stops only.
   subroutine structure_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      type(boundary_conditions) :: supports
      type(beam_structure) :: structure
      integer :: node(size(scene%supports)), i, j
      real(dp) :: h
      character(len=:), allocatable :: item
      supports = scene%beam%supports()
      structure = structure_of(scene)
      h = scene%beam%length/scene%mesh%elements
      do i = 1, size(scene%supports)
         item = '('//integer_text(i)//')'
         associate (p => scene%supports(i))
            call in_range(stat, errmsg, 'supports', 'x'//item, p%x, 0.0_dp, scene%beam%length, &
                          ' m, (0, length): a support at an end is &beam left_end or right_end')
            node(i) = nint(p%x/h)
            if (stat == 0 .and. (node(i) == 0 .or. node(i) == scene%mesh%elements)) &
               call fail(stat, errmsg, '&supports x'//item//' = '//real_text(p%x)//' m is nearest the end node x = '// &
                         real_text(node(i)*h)//' m: a support at an end is &beam left_end or right_end (with '// &
                         'its springs); put it on an interior node or refine the mesh')
            do j = 1, i - 1
               if (node(j) == node(i)) call fail(stat, errmsg, '&supports x'//item//' = '//real_text(p%x)//' m and x('// &
                                                 integer_text(j)//') = '//real_text(scene%supports(j)%x)// &
                                                 ' m act at the same node: give one support per node')
            end do
            if (p%kind == 'spring' .and. .not. (p%stiffness > 0 .or. p%rotational_stiffness > 0)) &
               call fail(stat, errmsg, '&supports kind'//item//' = ''spring'' has no spring: give stiffness'//item// &
                         ' > 0 or rotational_stiffness'//item//' > 0 (N/m, N m/rad)')
         end associate
      end do
      do i = 1, size(scene%masses)
         call in_range(stat, errmsg, 'masses', 'x('//integer_text(i)//')', scene%masses(i)%x, 0.0_dp, &
                       scene%beam%length, ' m, [0, length]')
      end do
      if (scene%beam%sectioned() .and. stat == 0) then
         call check_sections(scene%beam%sections, scene%beam%length, scene%mesh%elements, stat, errmsg)
         if (scene%flow%velocity > 0 .and. steps_in_time(scene)) &
            call fail(stat, errmsg, '&flow velocity = '//real_text(scene%flow%velocity)//' m/s is not available '// &
                      'with &sections: Connors'' fluid-elastic force takes one mass per length, for now')
      end if
      ! an axial compression up to the buckling load (K positive definite on the mesh)
      if (stat == 0) call check_compression(scene%mesh%basis, scene%mesh%elements, scene%beam%length, &
                                            scene%beam%rho_s(), scene%beam%ei(), structure, stat, errmsg)
      associate (analysis => scene%analysis, mesh => scene%mesh)
         ! statics solves K U = F, singular with a rigid-body motion
         if (structure%rigid_motions(scene%beam%length) > 0) then
            if (analysis%kind == 'static') &
               call fail(stat, errmsg, rigid_text()//': &analysis kind = ''static'' needs supports or end springs '// &
                         'that hold it (statics of a beam held by its obstacles alone is not available); give a '// &
                         'support or a spring, or use kind = ''dynamics'' or ''modes''')
            if (analysis%kind == 'dynamics' .and. scene%initial%displacement == 'static') &
               call fail(stat, errmsg, rigid_text()//': &initial displacement = ''static'' needs supports or end '// &
                         'springs that hold it; give a support or a spring, or another initial displacement')
            if (analysis%kind == 'dynamics' .and. mesh%reduction /= 'none') &
               call fail(stat, errmsg, rigid_text()//': &mesh reduction = '''//trim(mesh%reduction)//''' needs the '// &
                         'stiffness K of a beam without rigid-body motion (its constraint modes solve with K); use '// &
                         'reduction = ''none''')
         end if
         if (.not. (supports%is_clamped_free() .and. size(scene%supports) == 0) .and. (analysis%kind == 'static' .or. &
             (analysis%kind == 'dynamics' .and. scene%initial%displacement == 'static'))) then
            do i = 1, size(scene%obstacles)
               if (scene%obstacles(i)%stiffness > 0 .and. abs(scene%obstacles(i)%exponent - 1) > 0) &
                  call fail(stat, errmsg, '&obstacles exponent('//integer_text(i)//') = '// &
                            real_text(scene%obstacles(i)%exponent)//': the static equilibrium of a '// &
                            supports%name()//' beam takes linear compliant stops only (exponent = 1); the '// &
                            'clamped-free beam takes any exponent')
            end do
         end if
      end associate
   contains
      !> The supports and how many rigid-body motions they leave, for a message.
      function rigid_text() result(text)
         character(len=:), allocatable :: text
         integer :: rigid
         rigid = structure%rigid_motions(scene%beam%length)
         text = '&beam left_end = '''//supports%end_name(1)//''' and right_end = '''//supports%end_name(2)//''''
         if (supports%has_springs()) text = text//' with their springs'
         if (size(scene%supports) > 0) text = text//' and the '//integer_text(size(scene%supports))//' &supports'
         text = text//' leave the beam '//integer_text(rigid)//' rigid-body motion'
         if (rigid > 1) text = text//'s'
         text = text//' (u = a + b x, free of strain)'
      end function rigid_text
   end subroutine structure_rules

   !> &obstacles: damping only on a compliant stop; each obstacle on the beam, x_to not
   !! before x_from.
   subroutine obstacle_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=:), allocatable :: item
      integer :: i
      do i = 1, size(scene%obstacles)
         item = '('//integer_text(i)//')'
         associate (o => scene%obstacles(i))
            if (o%stiffness <= 0 .and. o%damping > 0) &
               call fail(stat, errmsg, '&obstacles damping'//item//' = '//real_text(o%damping)// &
                         ' is given for a rigid obstacle (stiffness'//item// &
                         ' = 0): contact damping needs a compliant stop; give stiffness'//item//' > 0 or damping 0')
            call in_range(stat, errmsg, 'obstacles', 'x_from'//item, o%x_from, 0.0_dp, scene%beam%length, &
                          ' m, [0, length]')
            call in_range(stat, errmsg, 'obstacles', 'x_to'//item, o%x_to, o%x_from, scene%beam%length, &
                          ' m, [x_from'//item//', length]')
         end associate
      end do
   end subroutine obstacle_rules

   !> &time, when time is stepped: dt in (0, t_end], at most max_steps steps.
   subroutine time_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      if (scene%analysis%kind /= 'dynamics') return
      associate (time => scene%time)
         call in_range(stat, errmsg, 'time', 'dt', time%dt, 0.0_dp, time%t_end, ' s, (0, t_end]')
         ! t_end/dt <= 1e30 by the hard ranges: finite, compared before any integer conversion
         if (stat == 0 .and. time%t_end/time%dt > real(max_steps, dp)) &
            call fail(stat, errmsg, '&time dt = '//real_text(time%dt)//' with t_end = '//real_text(time%t_end)// &
                      ' makes '//rounded(time%t_end/time%dt)//' steps: at most '//rounded(real(max_steps, dp))// &
                      ' steps; raise dt or lower t_end')
      end associate
   end subroutine time_rules

   !> A large count to 3 digits: '1.00e30'.
   function rounded(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=16) :: buffer
      integer :: e, exponent
      write (buffer, '(es10.2e3)') value
      e = index(buffer, 'E')
      read (buffer(e + 1:), *) exponent
      text = trim(adjustl(buffer(1:e - 1)))//'e'//integer_text(exponent)
   end function rounded

   !> A count as an integer when it is one of default kind, else as `rounded`.
   function count_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      if (value < 1e9_dp) then
         text = integer_text(nint(value))
      else
         text = rounded(value)
      end if
   end function count_text

   !> &analysis kind = 'periodic' (docs/input.md, "&periodic"): one forcing frequency,
   !! the velocity scheme, a whole number of steps per forcing period, a step count
   !! within max_steps (any monodromy: the linearised steps take compliant stops when asked), and a branch
   !! switch only on a continued branch.
   subroutine periodic_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: omega, ratio
      character(len=:), allocatable :: problem
      associate (time => scene%time, periodic => scene%periodic)
         if (periodic%autonomous) then
            call autonomous_rules(scene, stat, errmsg)
            if (stat /= 0) return
         else
            call forcing_frequency(scene%load, omega, problem)
            if (len(problem) > 0) then
               call fail(stat, errmsg, '&analysis kind = ''periodic'' '//problem)
               return
            end if
         end if
         if (time%scheme /= 'velocity') &
            call fail(stat, errmsg, '&time scheme = '''//trim(time%scheme)//''' is not available with &analysis '// &
                      'kind = ''periodic'': the period map steps the velocity scheme only, for now')
         ! what the period map does not take yet (docs/input.md, "&periodic"): the loads of
         ! &forces (their common period is not known); the fluid-elastic force and damping per
         ! mode it steps, and linearises, as a dynamics run does
         if (allocated(scene%forces%load)) then
            if (size(scene%forces%load) > 0) &
               call fail(stat, errmsg, '&forces count = '//integer_text(size(scene%forces%load))//' is not '// &
                         'available with &analysis kind = ''periodic'': the period map takes the harmonic loads of '// &
                         '&load only, for now (give the load in &load)')
         end if
         if (periodic%autonomous) then
            call shared_rules()
            return
         end if
         ! omega dt may underflow (no trap); the quotient is computed only when it is at most max_steps
         if (omega*time%dt < 2*pi/real(max_steps, dp)) then
            call fail(stat, errmsg, '&time dt = '//real_text(time%dt)//' s makes more than '// &
                      rounded(real(max_steps, dp))//' steps per forcing period 2 pi/Omega (Omega = '// &
                      real_text(omega)//' rad/s)')
            return
         end if
         ratio = 2*pi/(omega*time%dt)
         if (nint(ratio, int64) < 1) &
            call fail(stat, errmsg, '&time dt = '//real_text(time%dt)//' s is longer than the forcing period '// &
                      '2 pi/Omega = '//real_text(2*pi/omega)//' s: give &periodic steps_per_period instead')
         if (stat == 0 .and. abs(ratio - nint(ratio, int64)) > whole_step_tolerance*ratio) &
            call fail(stat, errmsg, '&time dt = '//real_text(time%dt)//' s makes '//real_text(ratio)// &
                      ' steps per forcing period 2 pi/Omega = '//real_text(2*pi/omega)//' s: a periodic orbit '// &
                      'needs a whole number (to a relative 1e-9); give &periodic steps_per_period = '// &
                      count_text(anint(ratio))//' (dt = T/steps_per_period) instead of dt, or dt = T/n')
         if (stat == 0 .and. ratio*(real(periodic%transient_periods, dp) + periodic%period_multiple) > &
             real(max_steps, dp)) &
            call fail(stat, errmsg, '&periodic transient_periods = '//integer_text(periodic%transient_periods)// &
                      ' with '//rounded(ratio)//' steps per period makes more than '//rounded(real(max_steps, dp))// &
                      ' steps')
         call shared_rules()
      end associate
   contains
      !> What a forced and an autonomous orbit both need.
      subroutine shared_rules()
         if (scene%periodic%switch_branch .and. len_trim(scene%periodic%parameter) == 0) &
            call fail(stat, errmsg, '&periodic switch_branch = .true. needs a continuation: the branch of twice '// &
                      'the period starts at a period doubling of the continued branch; give &periodic parameter '// &
                      '(and step), or switch_branch = .false. (the default)')
      end subroutine shared_rules
   end subroutine periodic_rules

   !> &periodic autonomous = .true. (docs/input.md, "&periodic"; docs/method.md,
   !! "Autonomous periodic orbits"): no harmonic load, the period's guess and the steps of
   !! one period given, one orbit (no multiple) or its backbone (a continuation in its tip
   !! amplitude alone, no branch switch), and a conservative scene:
   !! a scene that dissipates energy has no free periodic orbit but rest.
   subroutine autonomous_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=*), parameter :: free = ' is not available with &periodic autonomous = .true.: '
      character(len=*), parameter :: decays = 'a scene that dissipates energy has no free periodic orbit (its free '// &
                                              'vibration decays to rest)'
      integer :: k
      associate (load => scene%load, periodic => scene%periodic)
         if (abs(load%point_force) > 0 .and. load%point_frequency > 0) &
            call fail(stat, errmsg, '&load point_frequency = '//real_text(load%point_frequency)//' rad/s (point_force = '// &
                      real_text(load%point_force)//')'//free//'a free vibration has no harmonic load; give the '// &
                      'load''s amplitude 0 (constant loads may stay), or autonomous = .false. (the default)')
         if (abs(load%distributed) > 0 .and. load%distributed_frequency > 0) &
            call fail(stat, errmsg, '&load distributed_frequency = '//real_text(load%distributed_frequency)// &
                      ' rad/s (distributed = '//real_text(load%distributed)//')'//free//'a free vibration has no '// &
                      'harmonic load; give the load''s amplitude 0 (constant loads may stay), or autonomous = .false.')
         if (abs(load%base_load_amplitude()) > 0 .and. load%base_frequency > 0) &
            call fail(stat, errmsg, '&load base_frequency = '//real_text(load%base_frequency)//' rad/s'//free// &
                      'a free vibration has no base excitation; give its amplitude 0, or autonomous = .false.')
         if (is_unset(periodic%period)) &
            call fail(stat, errmsg, '&periodic autonomous = .true. needs &periodic period (s), the guess of the '// &
                      'orbit''s period (> 0)')
         if (periodic%steps_per_period < 1) &
            call fail(stat, errmsg, '&periodic steps_per_period = '//integer_text(periodic%steps_per_period)// &
                      free//'give the steps of one period, at least 1 (dt = period/steps_per_period varies with '// &
                      'the unknown period)')
         if (periodic%period_multiple /= 1) &
            call fail(stat, errmsg, '&periodic period_multiple = '//integer_text(periodic%period_multiple)//free// &
                      'the period is the unknown itself; give 1 (the default)')
         if (len_trim(periodic%parameter) > 0 .and. lowercase(trim(periodic%parameter)) /= 'periodic.tip_amplitude') &
            call fail(stat, errmsg, '&periodic parameter = '''//trim(periodic%parameter)//''''//free// &
                      'an autonomous orbit is continued in its tip amplitude alone (the backbone of its nonlinear '// &
                      'normal mode); give parameter = ''periodic.tip_amplitude'', or '''' (one orbit, the default)')
         if (periodic%switch_branch) &
            call fail(stat, errmsg, '&periodic switch_branch = .true.'//free//'a backbone has no period doubling '// &
                      'to switch at (its multipliers lie on the unit circle; no bifurcation is looked for on it); '// &
                      'give .false. (the default)')
         if (scene%beam%plane_count() /= 1) &
            call fail(stat, errmsg, '&beam planes = '//integer_text(scene%beam%plane_count())//free// &
                      'the phase condition holds the tip''s velocity in y; give 1, for now')
         if (scene%beam%rayleigh_mass > 0 .or. scene%beam%rayleigh_stiffness > 0) &
            call fail(stat, errmsg, '&beam rayleigh_mass = '//real_text(scene%beam%rayleigh_mass)// &
                      ' 1/s and rayleigh_stiffness = '//real_text(scene%beam%rayleigh_stiffness)//' s'//free// &
                      decays//'; give both 0')
         if (scene%beam%modal()) &
            call fail(stat, errmsg, '&beam modal_damping (or modal_damping_ratios)'//free//decays//'; give none')
         if (scene%flow%velocity > 0) &
            call fail(stat, errmsg, '&flow velocity = '//real_text(scene%flow%velocity)//' m/s'//free// &
                      'the fluid-elastic force feeds or takes energy (a self-excited orbit is not a free vibration '// &
                      'of a conservative scene); give 0')
         if (abs(scene%time%theta - 0.5_dp) > 0) &
            call fail(stat, errmsg, '&time theta = '//real_text(scene%time%theta)//free//'theta > 1/2 damps '// &
                      'every mode of the discrete scheme, so '//decays//'; give 0.5')
         do k = 1, size(scene%obstacles)
            if (scene%obstacles(k)%stiffness > 0 .and. scene%obstacles(k)%damping > 0) &
               call fail(stat, errmsg, '&obstacles damping('//integer_text(k)//') = '// &
                         real_text(scene%obstacles(k)%damping)//' s/m'//free//decays//'; give 0')
            if (.not. scene%obstacles(k)%stiffness > 0 .and. scene%impact%restitution < 1) &
               call fail(stat, errmsg, '&impact restitution = '//real_text(scene%impact%restitution)//' with the '// &
                         'rigid &obstacles '//integer_text(k)//free//decays//'; give 1')
         end do
         if (stat == 0 .and. (real(periodic%transient_periods, dp) + 1)*periodic%steps_per_period > &
             real(max_steps, dp)) &
            call fail(stat, errmsg, '&periodic transient_periods = '//integer_text(periodic%transient_periods)// &
                      ' with '//integer_text(periodic%steps_per_period)//' steps per period makes more than '// &
                      rounded(real(max_steps, dp))//' steps')
      end associate
   end subroutine autonomous_rules

   !> &load: the point force on the beam; a base excitation by its acceleration or its
   !! amplitude, not both, and by its acceleration only with a frequency.
   subroutine load_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      associate (load => scene%load)
         if (.not. is_unset(load%point_position)) &
            call in_range(stat, errmsg, 'load', 'point_position', load%point_position, 0.0_dp, scene%beam%length, &
                          ' m, [0, length]')
         if (abs(load%base_acceleration) > 0 .and. abs(load%base_amplitude) > 0) &
            call fail(stat, errmsg, '&load base_acceleration = '//real_text(load%base_acceleration)// &
                      ' and base_amplitude = '//real_text(load%base_amplitude)// &
                      ' are both given: give one of them (a = A Omega^2)')
         if (abs(load%base_acceleration) > 0 .and. load%base_frequency <= 0) &
            call fail(stat, errmsg, '&load base_acceleration = '//real_text(load%base_acceleration)// &
                      ' needs base_frequency > 0 (the support moves as (a/Omega^2) sin(Omega t))')
      end associate
   end subroutine load_rules

   !> &output: a file name, the observation points on the beam, the Poincare load one of
   !! the harmonic loads.
   subroutine output_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: i
      associate (output => scene%output)
         if (len_trim(output%file) == 0) &
            call fail(stat, errmsg, '&output file = '''' is empty: give a file name such as ''results/run.h5''')
         do i = 1, size(output%points)
            call in_range(stat, errmsg, 'output', 'points('//integer_text(i)//')', output%points(i), 0.0_dp, &
                          scene%beam%length, ' m, [0, length]')
         end do
         if (stat == 0 .and. output%poincare_load /= 'auto') then
            if (forcing_of(scene) /= output%poincare_load) &
               call fail(stat, errmsg, '&output poincare_load = '''//trim(output%poincare_load)// &
                         ''' names no harmonic load: give that load a non-zero amplitude and frequency, or write '// &
                         '''auto''')
         end if
         ! the Lyapunov exponent (docs/statistics.md): renormalised once per forcing period,
         ! through the velocity scheme's tangent (its damping, per mode too, and the fluid-elastic force)
         if (output%lyapunov .and. scene%analysis%kind == 'dynamics') then
            if (forcing_of(scene) == 'none') &
               call fail(stat, errmsg, '&output lyapunov = .true. needs a harmonic load (&load base_frequency, '// &
                         'point_frequency or distributed_frequency with its amplitude): the exponent is renormalised '// &
                         'once per forcing period, at the Poincare section')
            if (scene%time%scheme /= 'velocity') &
               call fail(stat, errmsg, '&output lyapunov = .true. is not available with &time scheme = '''// &
                         trim(scene%time%scheme)//''': the tangent map is the velocity scheme''s')
         end if
      end associate
   end subroutine output_rules

   !> &beam planes (docs/input.md, "&beam"): a planar beam takes no direction (like
   !! inertia_z, it would be unused); with planes = 2, what the two-plane model does not
   !! take yet, each refused by name (issue 21 builds them in turn). Built: the velocity
   !! scheme with the loads of &load and &forces and the initial data of &initial, each
   !! turned by its direction, end supports, &supports, &masses, the axial force, Rayleigh
   !! damping, damping per mode and the fluid-elastic force of &flow, holes and levels (rigid or compliant, with friction),
   !! sweeps and continued checkpoints.
   subroutine plane_rules(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=*), parameter :: planar = ' is not available with &beam planes = 2 yet (issue 21: the two-plane '// &
                                              'model runs the velocity scheme with circular and polygonal holes and '// &
                                              'levels, so far); '
      integer :: i
      if (scene%beam%plane_count() == 1) then
         call no_direction('load', 'direction', scene%load%direction)
         call no_direction('load', 'point_direction', scene%load%point_direction)
         call no_direction('initial', 'direction', scene%initial%direction)
         call no_direction('initial', 'displacement_direction', scene%initial%displacement_direction)
         if (allocated(scene%forces%load)) then
            do i = 1, size(scene%forces%load)
               call no_direction('forces', 'direction('//integer_text(i)//')', scene%forces%load(i)%direction)
            end do
         end if
         do i = 1, size(scene%obstacles)
            if (scene%obstacles(i)%hole()) &
               call fail(stat, errmsg, '&obstacles shape('//integer_text(i)//') = '''// &
                         trim(scene%obstacles(i)%shape)//''' needs &beam planes = 2: a hole in the cross-section '// &
                         'holds both deflections; give planes = 2, or shape = ''level''')
            if (.not. is_unset(scene%obstacles(i)%wear_coefficient)) &
               call fail(stat, errmsg, '&obstacles wear_coefficient('//integer_text(i)//') = '// &
                         real_text(scene%obstacles(i)%wear_coefficient)//' m^3/(N m) needs &beam planes = 2: the '// &
                         'wear at the supports is a two-plane output (docs/statistics.md); give planes = 2 or remove it')
            if (.not. is_unset(scene%obstacles(i)%friction)) &
               call fail(stat, errmsg, '&obstacles friction('//integer_text(i)//') = '// &
                         real_text(scene%obstacles(i)%friction)//' needs &beam planes = 2: a planar beam''s contact '// &
                         'has no tangent to slide along (the beam has no axial motion); give planes = 2 or remove it')
         end do
         return
      end if
      do i = 1, size(scene%obstacles)
         associate (o => scene%obstacles(i))
            ! a level: a flat point of the cross-section (its normal +-y), rigid or compliant
            if (.not. o%circle() .and. len_trim(o%profile) > 0) &
               call fail(stat, errmsg, '&obstacles profile('//integer_text(i)//') = '''//trim(o%profile)//''''// &
                         planar//'give level_from and level_to')
            if (o%stiffness > 0 .neqv. scene%obstacles(1)%stiffness > 0) &
               call fail(stat, errmsg, '&obstacles stiffness('//integer_text(i)//') = '//real_text(o%stiffness)// &
                         ' N/m and stiffness(1) = '//real_text(scene%obstacles(1)%stiffness)//' N/m (rigid and '// &
                         'compliant obstacles together)'//planar//'make every obstacle rigid or every one compliant')
         end associate
      end do
      if (size(scene%obstacles) > 0 .and. scene%mesh%basis /= 'hermite') &
         call fail(stat, errmsg, '&mesh basis = '''//trim(scene%mesh%basis)//''' with obstacles'//planar// &
                   'allowed: ''hermite''')
      if (scene%analysis%kind /= 'dynamics') &
         call fail(stat, errmsg, '&analysis kind = '''//trim(scene%analysis%kind)//''''//planar//'allowed: ''dynamics''')
      if (scene%time%scheme /= 'velocity') &
         call fail(stat, errmsg, '&time scheme = '''//trim(scene%time%scheme)//''''//planar//'allowed: ''velocity''')
      if (scene%mesh%reduction /= 'none') &
         call fail(stat, errmsg, '&mesh reduction = '''//trim(scene%mesh%reduction)//''''//planar//'allowed: ''none''')
      if (scene%initial%displacement == 'static') &
         call fail(stat, errmsg, '&initial displacement = ''static'''//planar//'allowed: ''zero'', ''mode''')
      if (scene%output%lyapunov) &
         call fail(stat, errmsg, '&output lyapunov = .true.'//planar//'allowed: .false.')
   contains
      !> A direction given to a planar beam.
      subroutine no_direction(group, name, value)
         character(len=*), intent(in) :: group, name
         real(dp), intent(in) :: value
         if (.not. is_unset(value)) &
            call fail(stat, errmsg, '&'//group//' '//name//' = '//real_text(value)//' deg is given with &beam planes '// &
                      '= 1: a planar beam moves in y only; give planes = 2 or remove '//name)
      end subroutine no_direction
   end subroutine plane_rules

   !> stat = stat_failure and errmsg = message, unless an earlier violation is kept
   !! (stat /= 0).
   subroutine fail(stat, errmsg, message)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=*), intent(in) :: message
      if (stat /= 0) return
      stat = stat_failure
      errmsg = message
   end subroutine fail

   !> A range that depends on other values; `why` names it (' m, [0, length]').
   subroutine in_range(stat, errmsg, group, name, value, low, high, why)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=*), intent(in) :: group, name, why
      real(dp), intent(in) :: value, low, high
      if (stat /= 0) return
      if (value < low .or. value > high) call fail(stat, errmsg, '&'//group//' '//name//' = '//real_text(value)// &
                                                   ' is outside ['//real_text(low)//', '//real_text(high)//']'//why)
   end subroutine in_range
end module vibrobeam_scene_rules
