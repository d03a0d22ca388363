!> From a validated scene to everything a run needs (scene -> discrete model in the data
!! flow of CONTRIBUTING.md, "Architecture"): the beam model, its contact points and loads,
!! the discrete system a stepper steps (the full model or its reduced one), the stepper's
!! settings and the state the run starts from (the initial data, the checkpoint of
!! &initial from_file, or a state a sweep hands on). Used by the program and by the
!! verification drivers, so both run the same set-up; the stepper itself comes from the
!! factory (`new_stepper`).
module vibrobeam_problem
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure, stat_numerical_failure
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type, step_count, is_unset, structure_of, steps_in_time
   use vibrobeam_scene_structure, only: off_node_warnings
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_band, only: symmetric_band
   use vibrobeam_planes, only: direction_shares, spread_planes
   use vibrobeam_contact_set, only: contact_set, contact_value
   use vibrobeam_obstacles, only: build_contact_points, build_circle_points
   use vibrobeam_circle_set, only: circle_set
   use vibrobeam_loads, only: load_set, build_loads, add_forces, add_flow, add_flow_z
   use vibrobeam_initial_state, only: mode_field, initial_velocity, read_velocity_profile
   use vibrobeam_table_file, only: linear_table
   use vibrobeam_static, only: solve_static
   use vibrobeam_discrete_system, only: discrete_system
   use vibrobeam_time_stepper, only: time_stepper, stepper_settings, dynamic_state
   use vibrobeam_stepper_factory, only: new_time_stepper, state_from_record
   use vibrobeam_state_record, only: state_record
   use vibrobeam_checkpoint, only: read_checkpoint
   use vibrobeam_restart_check, only: check_compatible
   use vibrobeam_compliant_law, only: rule_code
   use vibrobeam_reduction, only: reduced_basis, build_reduction, reduce_model, reduce_contacts, reduce_loads, &
                                  reduce_state, default_reduction_frequency
   use vibrobeam_modal_damping, only: build_modal_damping
   implicit none
   private
   public :: run_problem, build_problem, new_stepper, stepper_settings_of, problem_stepper_settings, reduction_cutoff

   !> A run's problem: what it is about (the model, contacts and loads of the mesh), what a
   !! stepper steps (`system`, in the run's coordinates) and from where (`start`); how it
   !! is stepped is the scene's (`stepper_settings_of`).
   type :: run_problem
      type(beam_model) :: model        !! the beam on its mesh
      type(contact_set) :: contacts    !! the contact points on the mesh
      type(load_set) :: loads          !! the loads on the mesh
      real(dp), allocatable :: u0(:)   !! initial displacement unknowns of the mesh (dynamics, periodic; y then z)
      real(dp), allocatable :: v0(:)   !! initial velocity unknowns of the mesh (dynamics, periodic; y then z)
      !> bending planes: 1, or 2 (u0, v0 and the system's state hold y then z) with the z
      !! plane's stiffness when it has its own (else unallocated)
      integer :: planes = 1
      type(symmetric_band), allocatable :: stiffness_z
      type(circle_set) :: circles      !! the points of circular holes (two planes)
      !> what the stepper steps: model, contacts and loads of the mesh, or with &mesh
      !! reduction = 'craig-bampton' (dynamics, periodic) those of the reduced model, whose
      !! coordinates `reduction` maps back to the mesh (the recorder does)
      type(discrete_system) :: system
      logical :: reduced = .false.
      type(reduced_basis) :: reduction
      !> where the run starts, in the system's coordinates: the initial data, the
      !! checkpoint's state, or the state a sweep's point before hands on (`extra` then too)
      type(dynamic_state) :: start
      logical :: resuming = .false.    !! continues the checkpoint of &initial from_file
      type(state_record) :: resume     !! that checkpoint
      real(dp) :: resume_time = 0      !! its time (s)
      !> damping per mode in the system's coordinates (`vibrobeam_modal_damping`; Y = M Phi,
      !! projected T^T Y on a reduced model, and c): unallocated without
      real(dp), allocatable :: modal_forces(:,:), modal_rates(:)
      !> a beam of two planes whose z plane has a stiffness of its own: its damping per mode
      real(dp), allocatable :: modal_forces_z(:,:), modal_rates_z(:)
   end type run_problem

contains

   !> Build model, contact points, loads and initial state of `scene` (already validated).
   !! stat = `stat_failure` with a message naming the input when the scene is
   !! inconsistent (obstacles that contradict each other, an initial displacement outside
   !! the obstacles, a checkpoint of &initial from_file that does not match);
   !! `stat_invalid_input` when a table of &forces or &initial velocity_profile cannot be
   !! read or does not fit;
   !! `stat_numerical_failure` when the static solve of `&initial displacement = 'static'`
   !! fails; `warnings` collects one line per warning.
   subroutine build_problem(scene, prepared, warnings, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(out) :: prepared
      character(len=:), allocatable, intent(inout) :: warnings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(linear_table) :: profile   ! &initial velocity_profile
      call build_model(scene%mesh%basis, scene%mesh%elements, scene%beam%length, scene%beam%rho_s(), scene%beam%ei(), &
                       prepared%model, stat, errmsg, structure=structure_of(scene))
      if (stat /= 0) return
      warnings = warnings//off_node_warnings(scene, prepared%model)
      ! a beam of two planes: every obstacle is a point in the cross-section (a circle, or a
      ! level's flat point), none a planar contact point
      if (scene%beam%plane_count() == 2) then
         call build_contact_points(scene%obstacles(1:0), prepared%model, prepared%contacts, warnings, stat, errmsg)
         if (stat == 0) call build_circle_points(scene%obstacles, prepared%model, prepared%circles, warnings, stat, &
                                                 errmsg)
      else
         call build_contact_points(scene%obstacles, prepared%model, prepared%contacts, warnings, stat, errmsg)
      end if
      if (stat /= 0) return
      call build_loads(scene%load, prepared%model, scene%beam%rho_s(), prepared%loads)
      call add_forces(prepared%loads, scene%forces, prepared%model, scene%beam%rho_s(), scene%time%dt, stat, errmsg)
      if (stat /= 0) return
      if (steps_in_time(scene)) then   ! (a periodic analysis's period map steps it too)
         call add_flow(prepared%loads, scene%flow, prepared%model, scene%beam%rayleigh_mass, &
                       scene%beam%rayleigh_stiffness, stat, errmsg)
         if (stat /= 0) return
      end if
      if (steps_in_time(scene) .and. len_trim(scene%initial%from_file) > 0) then
         call resume_from_file(scene, prepared, warnings, stat, errmsg)
         if (stat == 0) call full_system(prepared)
         if (stat == 0) call modal_damping_of(scene, prepared, stat, errmsg)
         if (stat == 0) call flow_damping(prepared, warnings)
         return
      end if
      call initial_displacement(scene, prepared, stat, errmsg)
      if (stat /= 0) return
      if (scene%initial%velocity == 'profile') then
         call read_velocity_profile(scene%initial, scene%beam%length, profile, stat, errmsg)
         if (stat /= 0) return
         prepared%v0 = initial_velocity(scene%initial, prepared%model, profile)
      else
         prepared%v0 = initial_velocity(scene%initial, prepared%model)
      end if
      ! a failed interpolation of the initial fields returns NaN (vibrobeam_lapack)
      if (.not. all(ieee_is_finite(prepared%u0)) .or. .not. all(ieee_is_finite(prepared%v0))) then
         stat = stat_numerical_failure
         errmsg = '&initial: the initial displacement or velocity is not finite (interpolation on the mesh failed)'
         return
      end if
      if (steps_in_time(scene) .and. scene%mesh%reduction == 'craig-bampton') then
         call reduce_scene(scene, prepared, stat, errmsg)
      else
         if (scene%beam%plane_count() == 2) call two_planes(scene, prepared, stat, errmsg)
         if (stat /= 0) return
         call full_system(prepared)
      end if
      if (stat == 0) call modal_damping_of(scene, prepared, stat, errmsg)
      if (stat == 0) call flow_damping(prepared, warnings)
   end subroutine build_problem

   !> The fluid-elastic force's modes take the damping per mode (their structural damping
   !! ratios and critical velocities: `take_modal_rates`), then the warning when a mode is
   !! unstable and nothing bounds the motion.
   subroutine flow_damping(prepared, warnings)
      type(run_problem), intent(inout) :: prepared
      character(len=:), allocatable, intent(inout) :: warnings
      real(dp), allocatable :: none(:)
      if (.not. prepared%loads%flow%active) return
      allocate (none(0))
      if (allocated(prepared%modal_rates)) then
         if (allocated(prepared%modal_rates_z)) then
            call prepared%loads%flow%take_modal_rates(prepared%modal_rates, prepared%modal_rates_z)
         else
            call prepared%loads%flow%take_modal_rates(prepared%modal_rates, none)
         end if
      end if
      warnings = warnings//prepared%loads%flow%unbounded_warning(prepared%contacts%count > 0 .or. &
                                                                  prepared%circles%count > 0)
   end subroutine flow_damping

   !> A beam of two bending planes (docs/method.md, "Two bending planes"): the initial
   !! fields, computed in y, turned by &initial displacement_direction and direction (the
   !! velocity's) into 2J unknowns (y then z), then `plane_model`.
   subroutine two_planes(scene, prepared, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(inout) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      prepared%u0 = [prepared%u0, spread(0.0_dp, 1, size(prepared%u0))]
      prepared%v0 = [prepared%v0, spread(0.0_dp, 1, size(prepared%v0))]
      call spread_planes(shares_of(scene%initial%displacement_direction), prepared%u0)
      call spread_planes(shares_of(scene%initial%direction), prepared%v0)
      call plane_model(scene, prepared, '&initial: the initial displacement', .true., stat, errmsg)
   contains
      !> (cos, sin) of a direction of &initial, (1, 0) when it is not given.
      pure function shares_of(degrees) result(shares)
         real(dp), intent(in) :: degrees
         real(dp) :: shares(2)
         shares = [1.0_dp, 0.0_dp]
         if (.not. is_unset(degrees)) shares = direction_shares(degrees)
      end function shares_of
   end subroutine two_planes

   !> The model of a beam of two planes around its start state u0 (2J unknowns: initial
   !! data or a checkpoint): with `check`, the start inside every hole and on the allowed
   !! side of every level (theory §1, to the activation's 1e-12 L; `start` names the state
   !! in the message; a checkpoint may be inside a compliant wall, whose spring then
   !! pushes), and the z plane's stiffness, the model of the same scene with E inertia_z,
   !! when it has one of its own (`beam_settings%own_z_stiffness`). The system's planes and
   !! K_z are set by `full_system`.
   subroutine plane_model(scene, prepared, start, check, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(inout) :: prepared
      character(len=*), intent(in) :: start
      logical, intent(in) :: check
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(beam_model) :: model_z
      integer :: k
      stat = 0
      errmsg = ''
      prepared%planes = 2
      do k = 1, prepared%circles%count
         if (.not. check .or. (prepared%resuming .and. prepared%circles%compliant)) exit
         associate (circles => prepared%circles)
            if (circles%penetration(k, prepared%u0) > 1e-12_dp*scene%beam%length) then
               stat = stat_failure
               errmsg = start//' at x = '//real_text(circles%x(k))//' m, ('// &
                        real_text(prepared%u0(circles%dof(k)))//', '// &
                        real_text(prepared%u0(size(prepared%u0)/2 + circles%dof(k)))//') m, is outside '// &
                        trim(merge('the level ', 'the circle', circles%flat(k)))//' of &obstacles '// &
                        integer_text(circles%obstacle(k))
               return
            end if
         end associate
      end do
      if (.not. scene%beam%own_z_stiffness()) return
      call build_z_model(scene, model_z, stat, errmsg)
      if (stat /= 0) return
      allocate (prepared%stiffness_z, source=model_z%stiffness)
      ! the fluid-elastic force on the z plane's own modes
      if (prepared%loads%flow%active) then
         call add_flow_z(prepared%loads, scene%flow, model_z, scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, &
                         stat, errmsg)
         if (stat /= 0) errmsg = 'the z plane (&beam inertia_z): '//trim(errmsg)
      end if
   end subroutine plane_model

   !> The z plane's model of a beam of two planes with a stiffness of its own: the scene's
   !! model with E inertia_z.
   subroutine build_z_model(scene, model_z, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(out) :: model_z
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call build_model(scene%mesh%basis, scene%mesh%elements, scene%beam%length, scene%beam%rho_s(), &
                       scene%beam%ei_z(), model_z, stat, errmsg, structure=structure_of(scene))
   end subroutine build_z_model

   !> The damping per mode of a dynamics scene (&beam modal_damping, modal_damping_ratios):
   !! on the mesh's modes, every mode below the default cut-off of the reduced model
   !! (`default_reduction_frequency`: resolved by dt to 1 % and 10 times past the forcing)
   !! with modal_damping; on a reduced model, T^T Y (C_r = T^T C T). A beam of two planes
   !! takes them in each plane (the stepper's `add_modal_damping`), the z plane's on the
   !! modes of its own stiffness when it has one (`beam_settings%own_z_stiffness`).
   subroutine modal_damping_of(scene, prepared, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(inout) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(beam_model) :: model_z
      real(dp) :: every, forcing(3)
      logical :: loaded(3)
      stat = 0
      errmsg = ''
      if (.not. steps_in_time(scene) .or. .not. scene%beam%modal()) return
      every = 0
      if (.not. is_unset(scene%beam%modal_damping)) every = scene%beam%modal_damping
      forcing = [scene%load%distributed_frequency, scene%load%point_frequency, scene%load%base_frequency]
      loaded = [abs(scene%load%distributed) > 0, abs(scene%load%point_force) > 0, abs(scene%load%base_amplitude) > 0]
      call build_modal_damping(prepared%model, every, scene%beam%modal_damping_ratios, &
                               default_reduction_frequency(scene%time%dt, pack(forcing, loaded)), &
                               scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, scene%time%dt, &
                               prepared%modal_forces, prepared%modal_rates, stat, errmsg)
      if (stat /= 0) return
      if (prepared%planes == 2 .and. scene%beam%own_z_stiffness()) then
         call build_z_model(scene, model_z, stat, errmsg)
         if (stat == 0) call build_modal_damping(model_z, every, scene%beam%modal_damping_ratios, &
                                                 default_reduction_frequency(scene%time%dt, pack(forcing, loaded)), &
                                                 scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, &
                                                 scene%time%dt, prepared%modal_forces_z, prepared%modal_rates_z, &
                                                 stat, errmsg)
         if (stat /= 0) then
            errmsg = 'the z plane (&beam inertia_z): '//trim(errmsg)
            return
         end if
      end if
      if (prepared%reduced) prepared%modal_forces = matmul(transpose(prepared%reduction%transform), prepared%modal_forces)
   end subroutine modal_damping_of

   !> The system of the mesh itself, starting from the initial fields.
   subroutine full_system(prepared)
      type(run_problem), intent(inout) :: prepared
      prepared%system = discrete_system(prepared%model, prepared%contacts, prepared%loads)
      prepared%system%planes = prepared%planes
      prepared%system%circles = prepared%circles
      if (allocated(prepared%stiffness_z)) allocate (prepared%system%stiffness_z, source=prepared%stiffness_z)
      prepared%start%u = prepared%u0
      prepared%start%v = prepared%v0
   end subroutine full_system

   !> How the problem of `scene` is stepped: `stepper_settings_of` and the damping per
   !! mode `prepared` holds (&beam modal_damping): what every stepper of a run, and of a
   !! periodic analysis's period map, is made with.
   function problem_stepper_settings(scene, prepared) result(settings)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(stepper_settings) :: settings
      settings = stepper_settings_of(scene)
      if (allocated(prepared%modal_rates)) then
         settings%modal_forces = prepared%modal_forces
         settings%modal_rates = prepared%modal_rates
      end if
      if (allocated(prepared%modal_rates_z)) then
         settings%modal_forces_z = prepared%modal_forces_z
         settings%modal_rates_z = prepared%modal_rates_z
      end if
   end function problem_stepper_settings

   !> How the scene is stepped: &time, &impact, the Rayleigh damping of &beam, &solver
   !! (without the damping per mode the problem holds: `problem_stepper_settings`).
   pure function stepper_settings_of(scene) result(settings)
      type(scene_type), intent(in) :: scene
      type(stepper_settings) :: settings
      settings%scheme = scene%time%scheme
      settings%dt = scene%time%dt
      settings%theta = scene%time%theta
      settings%gamma = scene%time%gamma
      settings%restitution = scene%impact%restitution
      settings%separating_restitution = 1
      if (scene%impact%separating_points == 'restitution') settings%separating_restitution = scene%impact%restitution
      settings%rayleigh_mass = scene%beam%rayleigh_mass
      settings%rayleigh_stiffness = scene%beam%rayleigh_stiffness
      settings%compliant_rule = rule_code(trim(scene%time%compliant_rule))
      settings%contact = scene%solver
   end function stepper_settings_of

   !> The stepper of the scene's scheme and settings (`stepper_settings_of`) for the
   !! problem, at its start (at the checkpoint it continues, when it resumes one): the
   !! factory's, `new_time_stepper`.
   subroutine new_stepper(scene, prepared, stepper, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      class(time_stepper), allocatable, intent(out) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(stepper_settings) :: settings
      settings = problem_stepper_settings(scene, prepared)
      if (prepared%resuming) then
         call new_time_stepper(prepared%system, settings, prepared%start, stepper, stat, errmsg, prepared%resume)
      else
         call new_time_stepper(prepared%system, settings, prepared%start, stepper, stat, errmsg)
      end if
   end subroutine new_stepper

   !> The cut-off of the fixed-interface modes (rad/s): &mesh reduction_frequency, or its
   !! default from the forcing frequencies of the scene's &load and of its loads of
   !! &forces built in `loads` (a random signal's highest frequency), and dt
   !! (`default_reduction_frequency`).
   pure function reduction_cutoff(scene, loads) result(cutoff)
      type(scene_type), intent(in) :: scene
      type(load_set), intent(in) :: loads
      real(dp) :: cutoff
      real(dp) :: forcing(3)
      logical :: loaded(3)
      if (.not. is_unset(scene%mesh%reduction_frequency)) then
         cutoff = scene%mesh%reduction_frequency
         return
      end if
      forcing = [scene%load%distributed_frequency, scene%load%point_frequency, scene%load%base_frequency]
      loaded = [abs(scene%load%distributed) > 0, abs(scene%load%point_force) > 0, abs(scene%load%base_amplitude) > 0]
      cutoff = default_reduction_frequency(scene%time%dt, [pack(forcing, loaded), loads%forces%frequencies()])
   end function reduction_cutoff

   !> The Craig-Bampton reduced model of a prepared scene (`vibrobeam_reduction`).
   subroutine reduce_scene(scene, prepared, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(inout) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      if (scene%mesh%reduction_modes > prepared%model%unknowns - prepared%contacts%count) then
         stat = stat_failure
         write (errmsg, '(a,i0,a,i0,a,i0,a,i0,a)') '&mesh reduction_modes = ', scene%mesh%reduction_modes, &
            ' is more than the J - m = ', prepared%model%unknowns - prepared%contacts%count, &
            ' fixed-interface modes of the mesh (J = ', prepared%model%unknowns, ' unknowns, m = ', &
            prepared%contacts%count, ' contact points)'
         return
      end if
      call build_reduction(prepared%model, prepared%contacts, reduction_cutoff(scene, prepared%loads), &
                           scene%mesh%reduction_modes, prepared%reduction, stat, errmsg)
      if (stat /= 0) then
         errmsg = '&mesh reduction = ''craig-bampton'': '//trim(errmsg)
         stat = stat_numerical_failure
         return
      end if
      if (prepared%reduction%boundary + prepared%reduction%modes == 0) then
         stat = stat_failure
         errmsg = '&mesh reduction = ''craig-bampton'' keeps nothing: no contact point and no mode below '// &
                  'reduction_frequency = '//real_text(reduction_cutoff(scene, prepared%loads))// &
                  ' rad/s; raise it or give reduction_modes'
         return
      end if
      call reduce_model(prepared%model, prepared%reduction, prepared%system%model)
      call reduce_contacts(prepared%contacts, prepared%system%contacts)
      call reduce_loads(prepared%loads, prepared%reduction, prepared%system%loads)
      prepared%start%u = reduce_state(prepared%model, prepared%contacts, prepared%reduction, prepared%u0)
      prepared%start%v = reduce_state(prepared%model, prepared%contacts, prepared%reduction, prepared%v0)
      prepared%reduced = .true.
   end subroutine reduce_scene

   !> The initial state of a run that continues the checkpoint of &initial from_file
   !! (docs/output.md, "Checkpoint and restart"): the file must match the scene in its
   !! model, time scheme, contact points and compliant stops; its checkpoint must match its
   !! checksum (one without a checksum, of vibrobeam 0.2.0, is continued with a warning);
   !! t_end must lie after the checkpoint; when the obstacle bounds changed, the state must
   !! satisfy the new ones.
   subroutine resume_from_file(scene, prepared, warnings, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(inout) :: prepared
      character(len=:), allocatable, intent(inout) :: warnings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(dynamic_state) :: resumed
      logical :: same_bounds, verified
      real(dp) :: value
      character(len=:), allocatable :: file
      integer :: c
      file = trim(scene%initial%from_file)
      associate (contacts => prepared%contacts)
         call check_compatible(file, scene, contacts%x, contacts%lower, contacts%upper, same_bounds, stat, errmsg, &
                               stops=.true., hole_x=prepared%circles%x)
         if (stat /= 0) return
         call read_checkpoint(file, prepared%resume, prepared%resume_time, stat, errmsg, verified)
         if (stat /= 0) then
            errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
            return
         end if
         if (.not. verified) warnings = warnings//'&initial from_file = '''//file//''': its checkpoint carries '// &
            'no checksum (written by vibrobeam 0.2.0): it is continued without a check that it is undamaged'// &
            new_line('a')
         call state_from_record(scene%time%scheme, prepared%resume, scene%beam%plane_count()*prepared%model%unknowns, &
                                resumed, stat, errmsg)
         if (stat /= 0) then
            errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
            return
         end if
         ! (a periodic analysis starts from the checkpoint's state and ignores t_end)
         if (scene%analysis%kind == 'dynamics' .and. step_count(scene) <= resumed%step) then
            stat = stat_failure
            errmsg = '&time t_end = '//real_text(scene%time%t_end)//' s is not after the checkpoint of '''//file// &
                     ''' at t = '//real_text(resumed%step*scene%time%dt)//' s (t_end is the end time of the continued run)'
            return
         end if
         ! the stepper starts from U and V and takes the rest back from the checkpoint
         prepared%u0 = resumed%u
         prepared%v0 = resumed%v
         prepared%resuming = .true.
         ! a beam of two planes: its walls may have moved (as rigid levels may); the state
         ! is checked against them when they did (the velocity scheme lets it lie a
         ! step's travel beyond an unchanged wall)
         if (scene%beam%plane_count() == 2) then
            call plane_model(scene, prepared, '&initial from_file = '''//file//''': the beam', .not. same_bounds, stat, &
                             errmsg)
            if (stat /= 0) return
         end if
         do c = 1, contacts%count
            if (same_bounds) exit
            value = contact_value(contacts, c, prepared%u0)
            if (value + 1e-12_dp*(abs(value) + prepared%model%length) < contacts%lower(c) .or. &
                value - 1e-12_dp*(abs(value) + prepared%model%length) > contacts%upper(c)) then
               stat = stat_failure
               errmsg = '&initial from_file = '''//file//''': the beam is at u = '//real_text(value)//' m at x = '// &
                        real_text(contacts%x(c))//' m, outside the changed obstacles there ['// &
                        real_text(contacts%lower(c))//', '//real_text(contacts%upper(c))//'] m'
               return
            end if
         end do
      end associate
   end subroutine resume_from_file

   !> The initial displacement of a dynamics run (zero, a mode, or the static equilibrium
   !! under the loads at t = 0); it must satisfy every obstacle (theory §1: u0 in K).
   subroutine initial_displacement(scene, prepared, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(inout) :: prepared
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: reaction(:)
      real(dp) :: value
      integer :: c, iterations
      stat = 0
      errmsg = ''
      allocate (prepared%u0(prepared%model%unknowns), source=0.0_dp)
      if (.not. steps_in_time(scene)) return
      associate (model => prepared%model, contacts => prepared%contacts)
         select case (scene%initial%displacement)
         case ('mode')
            prepared%u0 = mode_field(model, scene%initial%displacement_mode, scene%initial%displacement_amplitude)
         case ('static')
            allocate (reaction(contacts%count))
            call solve_static(model, contacts, prepared%loads%at(0.0_dp), prepared%u0, reaction, iterations, stat, &
                              errmsg, scene%solver%contact_max_iterations, tolerance=scene%solver%static_tolerance)
            if (stat /= 0) then
               errmsg = '&initial displacement = ''static'': '//trim(errmsg)
               stat = stat_numerical_failure
               return
            end if
         end select
         do c = 1, contacts%count
            value = contact_value(contacts, c, prepared%u0)
            ! a static equilibrium sits on its obstacles up to round-off, relative to the
            ! beam's length (a floor at level 0 has no scale of its own)
            if (value + 1e-12_dp*(abs(value) + model%length) < contacts%lower(c) .or. &
                value - 1e-12_dp*(abs(value) + model%length) > contacts%upper(c)) then
               write (errmsg, '(a,g0.6,a,g0.6,a,g0.6,a,g0.6,a)') '&initial displacement_amplitude = ', &
                  scene%initial%displacement_amplitude, ' puts the beam at u = ', value, ' m at x = ', contacts%x(c), &
                  ' m, outside the obstacles there [', contacts%lower(c), ', '
               write (errmsg, '(a,g0.6,a)') trim(errmsg), contacts%upper(c), '] m'
               stat = stat_failure
               return
            end if
         end do
      end associate
   end subroutine initial_displacement

end module vibrobeam_problem
