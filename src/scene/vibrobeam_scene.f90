!> The scene: every input value of a run, resolved (defaults filled in) and validated
!! (docs/input.md). The scene is made of the settings of each group, each owned by the
!! package that uses it and declaring its variables once in its `visit` routine
!! (`vibrobeam_schema_visitor`): &beam and &mesh (`vibrobeam_beam_settings`), &obstacles
!! (`vibrobeam_obstacles`), &initial (`vibrobeam_initial_state`), &load
!! (`vibrobeam_loads`), &time and &impact (`vibrobeam_time_settings`), &solver
!! (`vibrobeam_contact_options`), &output (`vibrobeam_output_settings`), and &analysis here.
!! This module walks them all (`visit_scene`): the table of every variable
!! (`scene_variables`, which the file scanner checks a file against) and the listing with
!! units (`scene_entries`, `format_scene`); the check of every value against its range or
!! choices and of the rules between variables is `vibrobeam_scene_rules`' `validate_scene`.
!! Reading a file is `vibrobeam_scene_read`'s job.
!!
!! The hard ranges bound every input so that the quantities the model derives from them
!! stay finite and normal in double precision (docs/input.md, "Hard limits"): with
!! 1e-9 <= L <= 1e6 m, N <= 1e6, 1 <= E <= 1e13 Pa, 1e-2 <= rho <= 1e6 kg/m^3,
!! 1e-20 <= S <= 1e4 m^2, 1e-42 <= I <= 1e8 m^4 (or 1e-30 <= k2 <= 1e30), dt <= 1e12 s,
!! the largest of k2 = EI/(rho S), EI/h^3, theta^2 dt^2 EI/h^3 (the stiffness part of
!! W = M + theta^2 dt^2 K), rho S A Omega^2 and the discrete omega_max^2 stay below
!! 1e110 and the smallest of rho S h^3 above 1e-70 (verification/unit/test_input_limits.f90
!! evaluates them at the corners).
module vibrobeam_scene
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_namelist_schema, only: namelist_variable
   use vibrobeam_schema_visitor, only: schema_visitor, integer_row, keyword_row, logical_row, unset, is_unset, &
      unset_integer, keyword_length, &
      path_length
   use vibrobeam_schema_operations, only: schema_table, schema_checker, schema_lister, scene_entry => schema_entry
   use vibrobeam_frequency_twins, only: twin_sync
   use vibrobeam_beam_settings, only: beam_settings, mesh_settings, visit_beam, visit_mesh
   use vibrobeam_boundary, only: boundary_conditions
   use vibrobeam_structure, only: beam_structure
   use vibrobeam_obstacles, only: obstacle_type, max_obstacles, visit_obstacles
   use vibrobeam_support_settings, only: support_settings, mass_settings, visit_supports, visit_masses, &
      max_supports, max_masses, structure_from
   use vibrobeam_section_settings, only: section_settings, visit_sections, check_sections, max_sections
   use vibrobeam_buckling, only: check_compression
   use vibrobeam_initial_state, only: initial_settings, visit_initial, check_initial
   use vibrobeam_loads, only: load_settings, visit_load
   use vibrobeam_force_settings, only: forces_settings, visit_forces, check_forces, max_forces
   use vibrobeam_flow, only: flow_settings, visit_flow, check_flow
   use vibrobeam_time_settings, only: time_settings, impact_settings, visit_time, visit_impact
   use vibrobeam_contact_options, only: contact_options, visit_solver
   use vibrobeam_output_settings, only: output_settings, visit_output, max_points
   use vibrobeam_sweep_input, only: sweep_input, visit_sweep, max_sweep_values, parameter_length
   use vibrobeam_periodic_settings, only: periodic_settings, visit_periodic, forcing_frequency, whole_step_tolerance
   implicit none
   private
   public :: scene_type, analysis_settings, obstacle_type, scene_entry, max_obstacles, max_points, unset
   public :: visit_scene, scene_entries, format_scene, is_unset
   public :: scene_variables, path_length, keyword_length, max_steps, step_count
   public :: forcing_of, max_sweep_values, parameter_length, sync_frequency_twins, max_forces
   public :: support_settings, mass_settings, max_supports, max_masses, held_conditions, structure_of
   public :: section_settings, max_sections
   public :: steps_in_time, forcing_period_steps

   !> Most time steps of a run: nint(t_end/dt) must fit a 64-bit count with room to spare.
   integer(int64), parameter :: max_steps = 1000000000000000000_int64

   !> &analysis.
   type :: analysis_settings
      character(len=keyword_length) :: kind = 'dynamics'   !! 'modes' | 'static' | 'dynamics' | 'periodic'
      integer :: modes = 6                                 !! natural modes computed (kind = 'modes')
      logical :: contact_modes = .false.                   !! also the modes with every contact point held
   end type analysis_settings

   !> Every input value of a run, after defaults: the settings of each group.
   type :: scene_type
      type(beam_settings) :: beam
      type(mesh_settings) :: mesh
      type(support_settings), allocatable :: supports(:)   !! &supports (docs/input.md)
      type(mass_settings), allocatable :: masses(:)         !! &masses
      type(analysis_settings) :: analysis
      type(periodic_settings) :: periodic     !! &periodic (kind = 'periodic' only)
      type(obstacle_type), allocatable :: obstacles(:)
      type(impact_settings) :: impact
      type(time_settings) :: time
      type(initial_settings) :: initial
      type(load_settings) :: load
      type(forces_settings) :: forces
      type(flow_settings) :: flow
      type(contact_options) :: solver
      type(output_settings) :: output
   end type scene_type

contains

   !> Every variable of the scene, group by group in the order of docs/input.md.
   !! `obstacle_count`, `support_count`, `mass_count`, `section_count`, `force_count` (the
   !! reader's): the counts read, when the scene's arrays hold room for the most a file may
   !! give; otherwise each count is the size of its array (&supports, &masses and
   !! &sections: not listed when 0, so that a scene without them keeps the listing of
   !! earlier versions; the sections are the beam's, `beam_settings%sections`). &periodic
   !! belongs to kind = 'periodic' and is visited only in a scene of that kind (after
   !! &analysis, so a reader has read the kind by then): the results of the other kinds do
   !! not list it, and `scene_variables` takes its rows from a scene of that kind.
   subroutine visit_scene(scene, visitor, obstacle_count, support_count, mass_count, force_count, section_count)
      type(scene_type), intent(inout) :: scene
      class(schema_visitor), intent(inout) :: visitor
      integer, intent(inout), optional :: obstacle_count, support_count, mass_count, force_count, section_count
      integer :: count
      if (.not. allocated(scene%obstacles)) allocate (scene%obstacles(0))
      if (.not. allocated(scene%supports)) allocate (scene%supports(0))
      if (.not. allocated(scene%masses)) allocate (scene%masses(0))
      if (.not. allocated(scene%beam%sections)) allocate (scene%beam%sections(0))
      call visit_beam(scene%beam, visitor)
      call visit_mesh(scene%mesh, visitor)
      if (present(support_count)) then
         call visit_supports(scene%supports, support_count, visitor)
      else
         count = merge(size(scene%supports), unset_integer, size(scene%supports) > 0)
         call visit_supports(scene%supports, count, visitor)
      end if
      if (present(mass_count)) then
         call visit_masses(scene%masses, mass_count, visitor)
      else
         count = merge(size(scene%masses), unset_integer, size(scene%masses) > 0)
         call visit_masses(scene%masses, count, visitor)
      end if
      if (present(section_count)) then
         call visit_sections(scene%beam%sections, section_count, visitor)
      else
         count = merge(size(scene%beam%sections), unset_integer, size(scene%beam%sections) > 0)
         call visit_sections(scene%beam%sections, count, visitor)
      end if
      call visit_analysis(scene%analysis, visitor)
      if (scene%analysis%kind == 'periodic') call visit_periodic(scene%periodic, visitor)
      if (present(obstacle_count)) then
         call visit_obstacles(scene%obstacles, obstacle_count, visitor)
      else
         count = size(scene%obstacles)
         call visit_obstacles(scene%obstacles, count, visitor)
      end if
      call visit_impact(scene%impact, visitor)
      call visit_time(scene%time, visitor)
      call visit_initial(scene%initial, visitor)
      call visit_load(scene%load, visitor)
      if (.not. allocated(scene%forces%load)) allocate (scene%forces%load(0))
      if (present(force_count)) then
         call visit_forces(scene%forces, force_count, visitor)
      else
         count = size(scene%forces%load)
         call visit_forces(scene%forces, count, visitor)
      end if
      call visit_flow(scene%flow, visitor)
      call visit_solver(scene%solver, visitor)
      call visit_output(scene%output, visitor)
   end subroutine visit_scene

   !> Every variable of &analysis, once (docs/input.md, "&analysis").
   subroutine visit_analysis(analysis, visitor)
      type(analysis_settings), intent(inout) :: analysis
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(keyword_row('analysis', 'kind', 'modes|static|dynamics|periodic', keyword_length, &
                                        'natural modes, static equilibrium, time integration, or periodic orbits'), &
                            analysis%kind)
      call visitor%variable(integer_row('analysis', 'modes', 1, 2000000, 'number of natural modes computed'), &
                            analysis%modes)
      call visitor%variable(logical_row('analysis', 'contact_modes', 'also the natural modes with every contact '// &
                                        'point held at its obstacle (kind = ''modes'')', optional=.true.), &
                            analysis%contact_modes)
   end subroutine visit_analysis

   !> Every input variable, the scene's and &sweep's: group, name, kind, extent, longest
   !! string, hard range, allowed keywords, unit and meaning, in the order of the visits.
   !! The file scanner refuses what this table does not allow before any value is
   !! converted; `validate_scene` checks the values against the same rows.
   function scene_variables() result(table)
      type(namelist_variable), allocatable :: table(:)
      type(schema_table) :: collector
      type(scene_type) :: defaults
      type(sweep_input) :: sweep
      defaults%analysis%kind = 'periodic'   ! a scene whose visit includes every group
      call visit_scene(defaults, collector)
      call visit_sweep(sweep, collector)
      call move_alloc(collector%rows, table)
   end function scene_variables

   !> Every frequency's twin in Hz agrees with it (`vibrobeam_frequency_twins`): a twin that
   !! does not (a scene built in code that set a frequency alone) is set to the frequency
   !! over 2 pi. The rad/s variables are the ones the code uses; they are not changed.
   subroutine sync_frequency_twins(scene)
      type(scene_type), intent(inout) :: scene
      type(twin_sync) :: sync
      call visit_scene(scene, sync)
      sync%collecting = .false.
      call visit_scene(scene, sync)
   end subroutine sync_frequency_twins

   !> The harmonic load whose phase times the Poincare samples (docs/statistics.md): the
   !! one &output poincare_load names, or with 'auto' the first harmonic load (non-zero
   !! amplitude and frequency) of base excitation, point force, distributed load; 'none'
   !! when there is none. `omega` (rad/s) and `phase` (rad): the phase of the load is
   !! omega t + phase (base: s(t) ~ sin(Omega_b t); point: cos(Omega_p t); distributed:
   !! cos(Omega t + phi)).
   function forcing_of(scene, omega, phase) result(kind)
      type(scene_type), intent(in) :: scene
      real(dp), intent(out), optional :: omega, phase
      character(len=:), allocatable :: kind
      logical :: harmonic(3)
      character(len=*), parameter :: names(3) = [character(len=11) :: 'base', 'point', 'distributed']
      integer :: k
      associate (load => scene%load)
         harmonic = [abs(load%base_load_amplitude()) > 0 .and. load%base_frequency > 0, &
                     abs(load%point_force) > 0 .and. load%point_frequency > 0, &
                     abs(load%distributed) > 0 .and. load%distributed_frequency > 0]
         kind = 'none'
         do k = 1, 3
            if (.not. harmonic(k)) cycle
            if (scene%output%poincare_load /= 'auto' .and. scene%output%poincare_load /= names(k)) cycle
            kind = trim(names(k))
            exit
         end do
         if (present(omega)) omega = 0
         if (present(phase)) phase = 0
         select case (kind)
         case ('base')
            if (present(omega)) omega = load%base_frequency
         case ('point')
            if (present(omega)) omega = load%point_frequency
         case ('distributed')
            if (present(omega)) omega = load%distributed_frequency
            if (present(phase)) phase = load%distributed_phase
         end select
      end associate
   end function forcing_of

   !> What `build_model` takes of the scene beyond the uniform beam: its end supports and
   !! springs, intermediate supports and point masses (`structure_from`; a scene built in
   !! code may leave the groups unallocated).
   pure function structure_of(scene) result(structure)
      type(scene_type), intent(in) :: scene
      type(beam_structure) :: structure
      type(support_settings), allocatable :: supports(:)
      type(mass_settings), allocatable :: masses(:)
      allocate (supports(0), masses(0))
      if (allocated(scene%supports)) supports = scene%supports
      if (allocated(scene%masses)) masses = scene%masses
      structure = structure_from(scene%beam, supports, masses)
   end function structure_of

   !> The conditions the scene's supports impose on the displacement (ends and &supports;
   !! `beam_structure%held_count`): the mesh has `mesh%unknowns(held_conditions(scene))`
   !! unknowns.
   pure integer function held_conditions(scene)
      type(scene_type), intent(in) :: scene
      type(beam_structure) :: structure
      structure = structure_of(scene)
      held_conditions = structure%held_count()
   end function held_conditions
   !> The analysis steps the scene in time: kind = 'dynamics' or 'periodic' (the initial
   !! state, the reduction, damping and &time are theirs).
   pure logical function steps_in_time(scene)
      type(scene_type), intent(in) :: scene
      steps_in_time = scene%analysis%kind == 'dynamics' .or. scene%analysis%kind == 'periodic'
   end function steps_in_time

   !> Steps of one forcing period 2 pi/Omega of a periodic analysis, nint(2 pi/(Omega dt)),
   !! as a 64-bit count; of an autonomous orbit (no forcing) &periodic steps_per_period.
   !! The scene must be valid (`validate_scene` bounds it by max_steps).
   integer(int64) function forcing_period_steps(scene)
      type(scene_type), intent(in) :: scene
      real(dp) :: omega
      character(len=:), allocatable :: problem
      if (scene%periodic%autonomous) then   ! (no forcing: the steps of one period, as given)
         forcing_period_steps = max(1_int64, int(scene%periodic%steps_per_period, int64))
         return
      end if
      call forcing_frequency(scene%load, omega, problem)
      forcing_period_steps = max(1_int64, nint(2*pi/(omega*scene%time%dt), int64))
   end function forcing_period_steps

   !> Time steps of a dynamics run, nint(t_end/dt) (at least 1), as a 64-bit count; the
   !! scene must be valid (validate_scene bounds t_end/dt by max_steps).
   pure integer(int64) function step_count(scene)
      type(scene_type), intent(in) :: scene
      step_count = max(1_int64, nint(scene%time%t_end/scene%time%dt, int64))
   end function step_count

   !> Every resolved input value as a list of entries (name 'group.variable', value, unit):
   !! the variables of `visit_scene` (an optional one only when given; every frequency in
   !! rad/s and, its twin, in Hz), with the beam's
   !! k2 = EI/(rho S) as derived, and its mass per length and bending stiffness.
   function scene_entries(scene) result(list)
      type(scene_type), intent(in) :: scene
      type(scene_entry), allocatable :: list(:)
      type(schema_lister) :: lister, derived
      type(scene_type) :: copy
      integer :: k, n
      copy = scene
      call sync_frequency_twins(copy)
      call visit_scene(copy, lister)
      call derived%add_real('beam.mass_per_length', scene%beam%rho_s(), 'kg/m')
      call derived%add_real('beam.bending_stiffness', scene%beam%ei(), 'N m^2')
      allocate (list(lister%count + derived%count))
      n = 0
      do k = 1, lister%count
         if (lister%entries(k)%name == 'beam.k2') lister%entries(k)%real_value = scene%beam%ei()/scene%beam%rho_s()
         ! the amplitude of a rotation is its angular velocity (docs/input.md, &initial)
         if (lister%entries(k)%name == 'initial.velocity_amplitude' .and. scene%initial%velocity == 'rotation') &
            lister%entries(k)%unit = 'rad/s'
         if (lister%entries(k)%name == 'beam.rayleigh_mass') then
            list(n + 1:n + derived%count) = derived%entries(1:derived%count)
            n = n + derived%count
         end if
         n = n + 1
         list(n) = lister%entries(k)
      end do
      list = list(1:n)
   end function scene_entries

   !> The resolved scene as text, one 'group.variable = value  ! unit' line per entry.
   function format_scene(scene) result(text)
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable :: text
      type(scene_entry), allocatable :: list(:)
      character(len=:), allocatable :: value
      integer :: i
      allocate (list, source=scene_entries(scene))
      text = ''
      do i = 1, size(list)
         select case (list(i)%kind)
         case ('real')
            value = real_text(list(i)%real_value)
         case ('integer')
            value = integer_text(list(i)%integer_value)
         case ('logical')
            value = merge('.true. ', '.false.', list(i)%logical_value)
         case default
            value = ''''//trim(list(i)%string_value)//''''
         end select
         text = text//'  '//list(i)%name(1:max(32, len_trim(list(i)%name)))//' = '//trim(value)
         if (len_trim(list(i)%unit) > 0) text = text//'   ! '//trim(list(i)%unit)
         text = text//new_line('a')
      end do
   end function format_scene
end module vibrobeam_scene
