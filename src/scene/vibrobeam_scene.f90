!> The scene: every input value of a run, resolved (defaults filled in) and validated
!! (docs/input.md). Reading the namelist file is `vibrobeam_input`'s job; this
!! module knows what values are allowed (`scene_variables`, the one table of every
!! variable's kind, extent, longest string, hard range and choices, which both the file
!! scanner and `validate_scene` use) and how to list them with their units.
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
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_namelist_values, only: namelist_variable, variable_index, range_text, choices_text, &
      kind_real, kind_integer, kind_logical, kind_string, real_range_problem
   implicit none
   private
   public :: scene_type, obstacle_type, scene_entry, max_obstacles, max_points, unset
   public :: validate_scene, scene_entries, format_scene, rho_s_of, ei_of, is_unset
   public :: scene_variables, path_length, keyword_length, max_steps, step_count, unknowns_of
   public :: forcing_of, base_load_amplitude, max_sweep_values, parameter_length

   integer, parameter :: max_obstacles = 32       !! most obstacles a scene may hold
   integer, parameter :: max_points = 64          !! most observation points (&output points)
   integer, parameter :: max_sweep_values = 1000  !! most explicit values of a sweep axis (&sweep values)
   integer, parameter :: parameter_length = 64    !! longest &sweep parameter name
   real(dp), parameter :: unset = -huge(1.0_dp)   !! marks a real the user did not give
   integer, parameter :: name_length = 64
   integer, parameter :: path_length = 4096       !! longest file name (&output file, &initial from_file)
   integer, parameter :: keyword_length = 16      !! longest keyword ('hermite', 'dynamics', ...)
   !> Most time steps of a run: nint(t_end/dt) must fit a 64-bit count with room to spare.
   integer(int64), parameter :: max_steps = 1000000000000000000_int64

   !> One obstacle of `&obstacles` (docs/input.md).
   type :: obstacle_type
      character(len=keyword_length) :: side = 'below'   !! 'below' (bounds u from below) | 'above'
      real(dp) :: x_from = 0, x_to = 0      !! extent along the beam (m)
      real(dp) :: level_from = 0, level_to = 0   !! surface height at x_from, x_to (m)
      !> 0: rigid (Newton's law, &impact); > 0: compliant stop with force stiffness p^exponent
      !! (N/m for a punctual obstacle, N/m per m of length for a longitudinal one; per unit
      !! rho S when the beam is given by k2), docs/theory.md section 8
      real(dp) :: stiffness = 0
      real(dp) :: exponent = 1                   !! 1 linear, 1.5 Hertz-like
      real(dp) :: damping = 0                    !! Hunt-Crossley alpha (s/m), compliant stops only
   end type obstacle_type

   !> Every input value of a run, after defaults.
   type :: scene_type
      ! &beam
      real(dp) :: length = 1                  !! L (m)
      real(dp) :: k2 = 1                      !! EI/(rho S) (m^4/s^2)
      real(dp) :: youngs_modulus = unset      !! E (Pa)
      real(dp) :: density = unset             !! rho (kg/m^3)
      real(dp) :: area = unset                !! S (m^2)
      real(dp) :: inertia = unset             !! I (m^4)
      real(dp) :: rayleigh_mass = 0           !! a in C = a M + b K (1/s)
      real(dp) :: rayleigh_stiffness = 0      !! b in C = a M + b K (s)
      ! &mesh
      integer :: elements = 32
      character(len=keyword_length) :: basis = 'hermite'
      character(len=keyword_length) :: reduction = 'none'   !! 'none' | 'craig-bampton' (dynamics only)
      real(dp) :: reduction_frequency = unset   !! cut-off of the fixed-interface modes (rad/s); unset: default
      integer :: reduction_modes = -1           !! number of fixed-interface modes; -1: set by the cut-off
      ! &analysis
      character(len=keyword_length) :: kind = 'dynamics'
      integer :: modes = 6
      ! &obstacles
      type(obstacle_type), allocatable :: obstacles(:)
      ! &impact
      real(dp) :: restitution = 1
      character(len=keyword_length) :: separating_points = 'elastic'   !! restitution of active points moving away
      ! &time
      real(dp) :: t_end = 1, dt = 1e-4_dp
      character(len=keyword_length) :: scheme = 'velocity'
      real(dp) :: theta = 0.5_dp, gamma = 0.5_dp
      !> force of a compliant stop over a step: 'gradient' (discrete gradient of its potential,
      !! conserves energy) or 'mean' (theta-weighted mean of the end forces, Newmark's rule)
      character(len=keyword_length) :: compliant_rule = 'gradient'
      ! &initial
      character(len=keyword_length) :: displacement = 'zero'
      integer :: displacement_mode = 1
      real(dp) :: displacement_amplitude = 0
      character(len=keyword_length) :: velocity = 'zero'
      integer :: velocity_mode = 1
      real(dp) :: velocity_amplitude = 0
      character(len=path_length) :: from_file = ''   !! continue from this results file ('' = no)
      ! &load
      real(dp) :: distributed = 0, distributed_frequency = 0, distributed_phase = 0
      real(dp) :: point_force = 0, point_position = unset, point_frequency = 0
      real(dp) :: base_amplitude = 0, base_frequency = 0
      real(dp) :: base_acceleration = 0       !! amplitude of the support's acceleration (m/s^2), instead of base_amplitude
      ! &solver (vibrobeam extension)
      character(len=keyword_length) :: contact_solver = 'auto'
      character(len=keyword_length) :: contact_method = 'newton'   !! 'newton' | 'pivoting'
      integer :: contact_max_iterations = 0
      ! &output
      character(len=path_length) :: file = 'results/vibrobeam.h5'
      integer :: every = 10                   !! histories every `every` steps
      integer :: field_every = 0              !! field snapshots every `field_every` steps (0: = every)
      logical :: text = .true.
      logical :: progress = .false.
      real(dp), allocatable :: points(:)      !! observation points x (m), beside the tip
      real(dp) :: measure_from = 0            !! start of the statistics window (s)
      real(dp) :: checkpoint_seconds = 0      !! > 0: restartable checkpoint this often (wall s)
      real(dp) :: episode_gap = unset         !! impacts closer than this form one episode (s); unset: default
      character(len=keyword_length) :: poincare_load = 'auto'   !! whose phase times the Poincare samples
   end type scene_type

   !> One resolved input value with its unit, for printing and for HDF5 attributes.
   !! Exactly one of the value components is meaningful, as `kind` says.
   type :: scene_entry
      character(len=name_length) :: name = ''     !! 'group.variable', e.g. 'beam.length'
      character(len=8) :: kind = 'real'           !! 'real' | 'integer' | 'string' | 'logical'
      real(dp) :: real_value = 0
      integer :: integer_value = 0
      character(len=path_length) :: string_value = ''
      logical :: logical_value = .false.
      character(len=16) :: unit = ''              !! SI unit, '' when dimensionless
   end type scene_entry

contains

   !> True when `value` is the `unset` marker (a NaN or -Inf is a given value, not unset).
   !! Uses no comparison on a NaN, which traps under -ffpe-trap=invalid. The reader decides
   !! what was given from the file's tokens; the marker serves scenes built in code.
   elemental logical function is_unset(value)
      real(dp), intent(in) :: value
      if (ieee_is_finite(value)) then
         is_unset = value <= unset   ! finite and <= -huge: the marker itself; -Inf is not unset
      else
         is_unset = .false.
      end if
   end function is_unset

   !> True when the beam is given by E, rho, S, I (then k2 = EI/(rho S)).
   pure logical function physical(scene)
      type(scene_type), intent(in) :: scene
      physical = .not. all(is_unset([scene%youngs_modulus, scene%density, scene%area, scene%inertia]))
   end function physical

   !> Mass per unit length rho S (kg/m); 1 when the beam is given by k2.
   pure real(dp) function rho_s_of(scene)
      type(scene_type), intent(in) :: scene
      rho_s_of = 1
      if (physical(scene)) rho_s_of = scene%density*scene%area
   end function rho_s_of

   !> Bending stiffness E I (N m^2); k2 when the beam is given by k2.
   pure real(dp) function ei_of(scene)
      type(scene_type), intent(in) :: scene
      ei_of = scene%k2
      if (physical(scene)) ei_of = scene%youngs_modulus*scene%inertia
   end function ei_of

   !> Every input variable: group, name, kind, extent, longest string, hard range, allowed
   !! keywords, unit. The file scanner refuses what this table does not allow before any
   !! value is converted; `validate_scene` checks the converted values (and scenes built
   !! in code) against the same table, then the relations between variables.
   pure function scene_variables() result(table)
      type(namelist_variable), allocatable :: table(:)
      integer, parameter :: many = huge(1)
      table = [ &
         real_variable('beam', 'length', 1e-9_dp, 1e6_dp, 'm'), &
         real_variable('beam', 'k2', 1e-30_dp, 1e30_dp, 'm^4/s^2'), &
         real_variable('beam', 'youngs_modulus', 1.0_dp, 1e13_dp, 'Pa'), &
         real_variable('beam', 'density', 1e-2_dp, 1e6_dp, 'kg/m^3'), &
         real_variable('beam', 'area', 1e-20_dp, 1e4_dp, 'm^2'), &
         real_variable('beam', 'inertia', 1e-42_dp, 1e8_dp, 'm^4'), &
         real_variable('beam', 'rayleigh_mass', 0.0_dp, 1e12_dp, '1/s'), &
         real_variable('beam', 'rayleigh_stiffness', 0.0_dp, 1e3_dp, 's'), &
         integer_variable('mesh', 'elements', 1, 1000000), &
         keyword_variable('mesh', 'basis', 'hermite|bspline'), &
         keyword_variable('mesh', 'reduction', 'none|craig-bampton'), &
         real_variable('mesh', 'reduction_frequency', 1e-30_dp, 1e30_dp, 'rad/s'), &
         integer_variable('mesh', 'reduction_modes', 0, 100000), &
         keyword_variable('analysis', 'kind', 'modes|static|dynamics'), &
         integer_variable('analysis', 'modes', 1, 2000000), &
         integer_variable('obstacles', 'count', 0, max_obstacles), &
         keyword_variable('obstacles', 'side', 'below|above', max_obstacles), &
         real_variable('obstacles', 'x_from', 0.0_dp, 1e6_dp, 'm', max_obstacles), &
         real_variable('obstacles', 'x_to', 0.0_dp, 1e6_dp, 'm', max_obstacles), &
         real_variable('obstacles', 'level_from', -1e6_dp, 1e6_dp, 'm', max_obstacles), &
         real_variable('obstacles', 'level_to', -1e6_dp, 1e6_dp, 'm', max_obstacles), &
         real_variable('obstacles', 'stiffness', 0.0_dp, 1e30_dp, 'N/m', max_obstacles), &
         real_variable('obstacles', 'exponent', 1.0_dp, 3.0_dp, '', max_obstacles), &
         real_variable('obstacles', 'damping', 0.0_dp, 1e6_dp, 's/m', max_obstacles), &
         real_variable('impact', 'restitution', 0.0_dp, 1.0_dp, ''), &
         keyword_variable('impact', 'separating_points', 'elastic|restitution'), &
         real_variable('time', 't_end', 1e-15_dp, 1e12_dp, 's'), &
         real_variable('time', 'dt', 1e-18_dp, 1e12_dp, 's'), &
         keyword_variable('time', 'scheme', 'velocity|position'), &
         real_variable('time', 'theta', 0.5_dp, 1.0_dp, ''), &
         real_variable('time', 'gamma', 0.0_dp, 1.0_dp, ''), &
         keyword_variable('time', 'compliant_rule', 'gradient|mean'), &
         keyword_variable('initial', 'displacement', 'zero|mode|static'), &
         integer_variable('initial', 'displacement_mode', 1, 100), &
         real_variable('initial', 'displacement_amplitude', -1e6_dp, 1e6_dp, 'm'), &
         keyword_variable('initial', 'velocity', 'zero|mode|uniform'), &
         integer_variable('initial', 'velocity_mode', 1, 100), &
         real_variable('initial', 'velocity_amplitude', -1e8_dp, 1e8_dp, 'm/s'), &
         path_variable('initial', 'from_file'), &
         real_variable('load', 'distributed', -1e15_dp, 1e15_dp, 'N/m'), &
         real_variable('load', 'distributed_frequency', 0.0_dp, 1e15_dp, 'rad/s'), &
         real_variable('load', 'distributed_phase', -1e6_dp, 1e6_dp, 'rad'), &
         real_variable('load', 'point_force', -1e15_dp, 1e15_dp, 'N'), &
         real_variable('load', 'point_position', 0.0_dp, 1e6_dp, 'm'), &
         real_variable('load', 'point_frequency', 0.0_dp, 1e15_dp, 'rad/s'), &
         real_variable('load', 'base_amplitude', -1e6_dp, 1e6_dp, 'm'), &
         real_variable('load', 'base_frequency', 0.0_dp, 1e15_dp, 'rad/s'), &
         real_variable('load', 'base_acceleration', -1e15_dp, 1e15_dp, 'm/s^2'), &
         keyword_variable('solver', 'contact_solver', 'auto|delassus|band'), &
         keyword_variable('solver', 'contact_method', 'newton|pivoting'), &
         integer_variable('solver', 'contact_max_iterations', 0, many), &
         path_variable('output', 'file'), &
         integer_variable('output', 'every', 1, many), &
         logical_variable('output', 'text'), &
         logical_variable('output', 'progress'), &
         integer_variable('output', 'field_every', 0, many), &
         real_variable('output', 'points', 0.0_dp, 1e6_dp, 'm', max_points), &
         real_variable('output', 'measure_from', 0.0_dp, 1e12_dp, 's'), &
         real_variable('output', 'checkpoint_seconds', 0.0_dp, 1e9_dp, 's'), &
         real_variable('output', 'episode_gap', 1e-18_dp, 1e12_dp, 's'), &
         keyword_variable('output', 'poincare_load', 'auto|base|point|distributed'), &
         ! &sweep (docs/sweeps.md): checked against the scene by vibrobeam_sweep_settings
         name_variable('sweep', 'parameter'), &
         real_variable('sweep', 'values', -1e30_dp, 1e30_dp, '', max_sweep_values), &
         real_variable('sweep', 'from', -1e30_dp, 1e30_dp, ''), &
         real_variable('sweep', 'to', -1e30_dp, 1e30_dp, ''), &
         integer_variable('sweep', 'count', 1, 100000), &
         keyword_variable('sweep', 'spacing', 'linear|log'), &
         keyword_variable('sweep', 'mode', 'independent|up|down|up-down'), &
         name_variable('sweep', 'parameter2'), &
         real_variable('sweep', 'values2', -1e30_dp, 1e30_dp, '', max_sweep_values), &
         real_variable('sweep', 'from2', -1e30_dp, 1e30_dp, ''), &
         real_variable('sweep', 'to2', -1e30_dp, 1e30_dp, ''), &
         integer_variable('sweep', 'count2', 1, 100000), &
         keyword_variable('sweep', 'spacing2', 'linear|log'), &
         real_variable('sweep', 'settle', 0.0_dp, 1e12_dp, 's'), &
         real_variable('sweep', 'measure', 0.0_dp, 1e12_dp, 's'), &
         real_variable('sweep', 'settle_periods', 0.0_dp, 1e9_dp, ''), &
         real_variable('sweep', 'measure_periods', 0.0_dp, 1e9_dp, ''), &
         real_variable('sweep', 'steady_tolerance', 0.0_dp, 1.0_dp, ''), &
         logical_variable('sweep', 'keep_runs')]
   contains
      pure function real_variable(group, name, lowest, highest, unit, extent) result(variable)
         character(len=*), intent(in) :: group, name, unit
         real(dp), intent(in) :: lowest, highest
         integer, intent(in), optional :: extent
         type(namelist_variable) :: variable
         variable = namelist_variable(group=group, name=name, kind=kind_real, lowest=lowest, highest=highest, unit=unit)
         if (present(extent)) variable%extent = extent
      end function real_variable
      pure function integer_variable(group, name, lowest, highest) result(variable)
         character(len=*), intent(in) :: group, name
         integer, intent(in) :: lowest, highest
         type(namelist_variable) :: variable
         variable = namelist_variable(group=group, name=name, kind=kind_integer, lowest_integer=lowest, &
                                      highest_integer=highest)
      end function integer_variable
      pure function keyword_variable(group, name, choices, extent) result(variable)
         character(len=*), intent(in) :: group, name, choices
         integer, intent(in), optional :: extent
         type(namelist_variable) :: variable
         variable = namelist_variable(group=group, name=name, kind=kind_string, max_length=keyword_length, &
                                      choices=choices)
         if (present(extent)) variable%extent = extent
      end function keyword_variable
      pure function path_variable(group, name) result(variable)
         character(len=*), intent(in) :: group, name
         type(namelist_variable) :: variable
         variable = namelist_variable(group=group, name=name, kind=kind_string, max_length=path_length)
      end function path_variable
      pure function name_variable(group, name) result(variable)
         character(len=*), intent(in) :: group, name
         type(namelist_variable) :: variable
         variable = namelist_variable(group=group, name=name, kind=kind_string, max_length=parameter_length)
      end function name_variable
      pure function logical_variable(group, name) result(variable)
         character(len=*), intent(in) :: group, name
         type(namelist_variable) :: variable
         variable = namelist_variable(group=group, name=name, kind=kind_logical)
      end function logical_variable
   end function scene_variables

   !> Amplitude of the support's acceleration, A Omega_b^2 or &load base_acceleration
   !! (m/s^2): the base excitation loads the beam with rho S times this, sin(Omega_b t).
   pure real(dp) function base_load_amplitude(scene)
      type(scene_type), intent(in) :: scene
      if (abs(scene%base_acceleration) > 0) then
         base_load_amplitude = scene%base_acceleration
      else
         base_load_amplitude = scene%base_amplitude*scene%base_frequency**2
      end if
   end function base_load_amplitude

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
      harmonic = [abs(base_load_amplitude(scene)) > 0 .and. scene%base_frequency > 0, &
                  abs(scene%point_force) > 0 .and. scene%point_frequency > 0, &
                  abs(scene%distributed) > 0 .and. scene%distributed_frequency > 0]
      kind = 'none'
      do k = 1, 3
         if (.not. harmonic(k)) cycle
         if (scene%poincare_load /= 'auto' .and. scene%poincare_load /= names(k)) cycle
         kind = trim(names(k))
         exit
      end do
      if (present(omega)) omega = 0
      if (present(phase)) phase = 0
      select case (kind)
      case ('base')
         if (present(omega)) omega = scene%base_frequency
      case ('point')
         if (present(omega)) omega = scene%point_frequency
      case ('distributed')
         if (present(omega)) omega = scene%distributed_frequency
         if (present(phase)) phase = scene%distributed_phase
      end select
   end function forcing_of

   !> Unknowns J of the mesh: 2N (Hermite) or N + 1 (B-splines).
   pure integer function unknowns_of(scene)
      type(scene_type), intent(in) :: scene
      unknowns_of = merge(2*scene%elements, scene%elements + 1, scene%basis == 'hermite')
   end function unknowns_of

   !> Time steps of a dynamics run, nint(t_end/dt) (at least 1), as a 64-bit count; the
   !! scene must be valid (validate_scene bounds t_end/dt by max_steps).
   pure integer(int64) function step_count(scene)
      type(scene_type), intent(in) :: scene
      step_count = max(1_int64, nint(scene%t_end/scene%dt, int64))
   end function step_count

   !> Check every value against what is allowed: first each against its hard range and
   !! keywords (`scene_variables`), then the relations that matter for the analysis asked
   !! for. On the first violation stat = 1 and errmsg reads like
   !! '&impact restitution = 1.5 is outside [0, 1]'.
   subroutine validate_scene(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(namelist_variable), allocatable :: table(:)
      integer :: i
      character(len=:), allocatable :: item
      stat = 0
      errmsg = ''
      table = scene_variables()
      ! &beam
      call check_real('beam', 'length', scene%length)
      call check_real('beam', 'k2', scene%k2)
      if (physical(scene)) then
         call check_given('youngs_modulus', scene%youngs_modulus)
         call check_given('density', scene%density)
         call check_given('area', scene%area)
         call check_given('inertia', scene%inertia)
      end if
      call check_real('beam', 'rayleigh_mass', scene%rayleigh_mass)
      call check_real('beam', 'rayleigh_stiffness', scene%rayleigh_stiffness)
      ! &mesh
      call check_integer('mesh', 'elements', scene%elements)
      call check_keyword('mesh', 'basis', scene%basis)
      call check_keyword('mesh', 'reduction', scene%reduction)
      if (.not. is_unset(scene%reduction_frequency)) &
         call check_real('mesh', 'reduction_frequency', scene%reduction_frequency)
      if (scene%reduction_modes /= -1) call check_integer('mesh', 'reduction_modes', scene%reduction_modes)
      if (stat /= 0) return
      if (scene%reduction /= 'none' .and. scene%kind == 'dynamics' .and. len_trim(scene%from_file) > 0) &
         call fail('&mesh reduction = '''//trim(scene%reduction)//''' cannot continue a checkpoint '// &
                   '(&initial from_file): its state is in reduced coordinates; use reduction = ''none''')
      if (scene%reduction_modes /= -1 .and. .not. is_unset(scene%reduction_frequency)) &
         call fail('&mesh reduction_modes = '//integer_text(scene%reduction_modes)//' and reduction_frequency = '// &
                   real_text(scene%reduction_frequency)//' rad/s are both given: give one of them')
      if (stat /= 0) return
      ! &analysis: `modes` is bounded by the mesh only when modes are computed
      call check_keyword('analysis', 'kind', scene%kind)
      call check_integer('analysis', 'modes', scene%modes)
      if (stat /= 0) return
      if (scene%kind == 'modes') call integer_in_range('analysis', 'modes', scene%modes, 1, unknowns_of(scene), &
                                                       ', the unknowns J of the mesh')
      ! &obstacles
      if (size(scene%obstacles) > max_obstacles) &
         call fail('&obstacles count = '//integer_text(size(scene%obstacles))//' is outside [0, '// &
                   integer_text(max_obstacles)//']')
      do i = 1, size(scene%obstacles)
         item = '('//integer_text(i)//')'
         associate (o => scene%obstacles(i))
            call check_keyword('obstacles', 'side', o%side, item)
            call check_real('obstacles', 'x_from', o%x_from, item)
            call check_real('obstacles', 'x_to', o%x_to, item)
            call check_real('obstacles', 'level_from', o%level_from, item)
            call check_real('obstacles', 'level_to', o%level_to, item)
            call check_real('obstacles', 'stiffness', o%stiffness, item)
            call check_real('obstacles', 'exponent', o%exponent, item)
            call check_real('obstacles', 'damping', o%damping, item)
            if (stat /= 0) return
            if (o%stiffness <= 0 .and. o%damping > 0) &
               call fail('&obstacles damping'//item//' = '//real_text(o%damping)// &
                         ' is given for a rigid obstacle (stiffness'//item// &
                         ' = 0): contact damping needs a compliant stop; give stiffness'//item//' > 0 or damping 0')
            if (stat /= 0) return
            call in_range('obstacles', 'x_from'//item, o%x_from, 0.0_dp, scene%length, ' m, [0, length]')
            call in_range('obstacles', 'x_to'//item, o%x_to, o%x_from, scene%length, ' m, [x_from'//item//', length]')
         end associate
      end do
      ! &impact
      call check_real('impact', 'restitution', scene%restitution)
      call check_keyword('impact', 'separating_points', scene%separating_points)
      ! &time: the step count matters only when time is stepped
      call check_real('time', 't_end', scene%t_end)
      call check_real('time', 'dt', scene%dt)
      call check_keyword('time', 'scheme', scene%scheme)
      call check_real('time', 'theta', scene%theta)
      call check_real('time', 'gamma', scene%gamma)
      call check_keyword('time', 'compliant_rule', scene%compliant_rule)
      if (stat /= 0) return
      if (scene%kind == 'dynamics') then
         call in_range('time', 'dt', scene%dt, 0.0_dp, scene%t_end, ' s, (0, t_end]')
         ! t_end/dt <= 1e30 by the hard ranges: finite, compared before any integer conversion
         if (stat == 0 .and. scene%t_end/scene%dt > real(max_steps, dp)) &
            call fail('&time dt = '//real_text(scene%dt)//' with t_end = '//real_text(scene%t_end)//' makes '// &
                      rounded(scene%t_end/scene%dt)//' steps: at most '//rounded(real(max_steps, dp))// &
                      ' steps; raise dt or lower t_end')
      end if
      ! &initial
      call check_keyword('initial', 'displacement', scene%displacement)
      call check_integer('initial', 'displacement_mode', scene%displacement_mode)
      call check_real('initial', 'displacement_amplitude', scene%displacement_amplitude)
      call check_keyword('initial', 'velocity', scene%velocity)
      call check_integer('initial', 'velocity_mode', scene%velocity_mode)
      call check_real('initial', 'velocity_amplitude', scene%velocity_amplitude)
      ! &load
      call check_real('load', 'distributed', scene%distributed)
      call check_real('load', 'distributed_frequency', scene%distributed_frequency)
      call check_real('load', 'distributed_phase', scene%distributed_phase)
      call check_real('load', 'point_force', scene%point_force)
      call check_real('load', 'point_position', scene%point_position)
      if (stat /= 0) return
      call in_range('load', 'point_position', scene%point_position, 0.0_dp, scene%length, ' m, [0, length]')
      call check_real('load', 'point_frequency', scene%point_frequency)
      call check_real('load', 'base_amplitude', scene%base_amplitude)
      call check_real('load', 'base_frequency', scene%base_frequency)
      call check_real('load', 'base_acceleration', scene%base_acceleration)
      if (abs(scene%base_acceleration) > 0 .and. abs(scene%base_amplitude) > 0) &
         call fail('&load base_acceleration = '//real_text(scene%base_acceleration)//' and base_amplitude = '// &
                   real_text(scene%base_amplitude)//' are both given: give one of them (a = A Omega^2)')
      if (abs(scene%base_acceleration) > 0 .and. scene%base_frequency <= 0) &
         call fail('&load base_acceleration = '//real_text(scene%base_acceleration)// &
                   ' needs base_frequency > 0 (the support moves as (a/Omega^2) sin(Omega t))')

      ! &solver
      call check_keyword('solver', 'contact_solver', scene%contact_solver)
      call check_keyword('solver', 'contact_method', scene%contact_method)
      call check_integer('solver', 'contact_max_iterations', scene%contact_max_iterations)
      ! &output
      if (len_trim(scene%file) == 0) call fail('&output file = '''' is empty: give a file name such as ''results/run.h5''')
      call check_integer('output', 'every', scene%every)
      call check_integer('output', 'field_every', scene%field_every)
      if (allocated(scene%points)) then
         if (size(scene%points) > max_points) &
            call fail('&output points: '//integer_text(size(scene%points))//' points; at most '//integer_text(max_points))
         do i = 1, size(scene%points)
            item = '('//integer_text(i)//')'
            call check_real('output', 'points', scene%points(i), item)
            if (stat /= 0) return
            call in_range('output', 'points'//item, scene%points(i), 0.0_dp, scene%length, ' m, [0, length]')
         end do
      end if
      call check_real('output', 'measure_from', scene%measure_from)
      call check_real('output', 'checkpoint_seconds', scene%checkpoint_seconds)
      if (.not. is_unset(scene%episode_gap)) call check_real('output', 'episode_gap', scene%episode_gap)
      call check_keyword('output', 'poincare_load', scene%poincare_load)
      if (stat == 0 .and. scene%poincare_load /= 'auto') then
         if (forcing_of(scene) /= scene%poincare_load) &
            call fail('&output poincare_load = '''//trim(scene%poincare_load)//''' names no harmonic load: give '// &
                      'that load a non-zero amplitude and frequency, or write ''auto''')
      end if

   contains

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

      subroutine fail(message)
         character(len=*), intent(in) :: message
         if (stat /= 0) return   ! keep the first violation
         stat = 1
         errmsg = message
      end subroutine fail

      !> The schema entry of group.name (every name used here is in the table).
      function entry_of(group, name) result(variable)
         character(len=*), intent(in) :: group, name
         type(namelist_variable) :: variable
         variable = table(variable_index(table, group, name))
      end function entry_of

      !> A real against its hard range: finite, inside [lowest, highest], and 0 or at least
      !! `smallest_nonzero` in magnitude. `item` is '(i)' for array elements.
      subroutine check_real(group, name, value, item)
         character(len=*), intent(in) :: group, name
         real(dp), intent(in) :: value
         character(len=*), intent(in), optional :: item
         character(len=:), allocatable :: label, problem
         if (stat /= 0) return
         label = '&'//group//' '//name
         if (present(item)) label = label//item
         problem = real_range_problem(entry_of(group, name), value)
         if (len(problem) > 0) call fail(label//' = '//real_text(value)//' '//problem)
      end subroutine check_real

      subroutine check_integer(group, name, value)
         character(len=*), intent(in) :: group, name
         integer, intent(in) :: value
         type(namelist_variable) :: variable
         variable = entry_of(group, name)
         call integer_in_range(group, name, value, variable%lowest_integer, variable%highest_integer, '')
      end subroutine check_integer

      subroutine check_keyword(group, name, value, item)
         character(len=*), intent(in) :: group, name, value
         character(len=*), intent(in), optional :: item
         type(namelist_variable) :: variable
         character(len=:), allocatable :: label
         if (stat /= 0) return
         variable = entry_of(group, name)
         if (index('|'//trim(variable%choices)//'|', '|'//trim(value)//'|') > 0 .and. len_trim(value) > 0) return
         label = '&'//group//' '//name
         if (present(item)) label = label//item
         call fail(label//' = '''//trim(value)//''' is not one of '//choices_text(variable))
      end subroutine check_keyword

      !> One of the four physical data, which go together.
      subroutine check_given(name, value)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: value
         if (is_unset(value)) then
            call fail('&beam '//name//' is missing: youngs_modulus, density, area and inertia '// &
                      'go together (or give k2 alone)')
         else
            call check_real('beam', name, value)
         end if
      end subroutine check_given

      !> A range that depends on other values; `why` names it (', the unknowns J of the mesh').
      subroutine in_range(group, name, value, low, high, why)
         character(len=*), intent(in) :: group, name, why
         real(dp), intent(in) :: value, low, high
         if (stat /= 0) return
         if (value < low .or. value > high) call fail('&'//group//' '//name//' = '//real_text(value)// &
                                                      ' is outside ['//real_text(low)//', '//real_text(high)//']'//why)
      end subroutine in_range

      subroutine integer_in_range(group, name, value, low, high, why)
         character(len=*), intent(in) :: group, name, why
         integer, intent(in) :: value, low, high
         if (value < low .or. value > high) &
            call fail('&'//group//' '//name//' = '//integer_text(value)//' is outside ['//integer_text(low)// &
                      ', '//integer_text(high)//']'//why)
      end subroutine integer_in_range
   end subroutine validate_scene


   !> Every resolved input value as a list of entries (name 'group.variable', value, unit).
   pure function scene_entries(scene) result(list)
      type(scene_type), intent(in) :: scene
      type(scene_entry), allocatable :: list(:)
      integer :: i
      character(len=8) :: index
      allocate (list(0))
      call add_real('beam.length', scene%length, 'm')
      call add_real('beam.k2', ei_of(scene)/rho_s_of(scene), 'm^4/s^2')
      if (physical(scene)) then
         call add_real('beam.youngs_modulus', scene%youngs_modulus, 'Pa')
         call add_real('beam.density', scene%density, 'kg/m^3')
         call add_real('beam.area', scene%area, 'm^2')
         call add_real('beam.inertia', scene%inertia, 'm^4')
      end if
      call add_real('beam.mass_per_length', rho_s_of(scene), 'kg/m')
      call add_real('beam.bending_stiffness', ei_of(scene), 'N m^2')
      call add_real('beam.rayleigh_mass', scene%rayleigh_mass, '1/s')
      call add_real('beam.rayleigh_stiffness', scene%rayleigh_stiffness, 's')
      call add_integer('mesh.elements', scene%elements)
      call add_string('mesh.basis', scene%basis)
      call add_string('mesh.reduction', scene%reduction)
      if (.not. is_unset(scene%reduction_frequency)) &
         call add_real('mesh.reduction_frequency', scene%reduction_frequency, 'rad/s')
      if (scene%reduction_modes /= -1) call add_integer('mesh.reduction_modes', scene%reduction_modes)
      call add_string('analysis.kind', scene%kind)
      call add_integer('analysis.modes', scene%modes)
      call add_integer('obstacles.count', size(scene%obstacles))
      do i = 1, size(scene%obstacles)
         write (index, '(a,i0,a)') '(', i, ')'
         call add_string('obstacles.side'//trim(index), scene%obstacles(i)%side)
         call add_real('obstacles.x_from'//trim(index), scene%obstacles(i)%x_from, 'm')
         call add_real('obstacles.x_to'//trim(index), scene%obstacles(i)%x_to, 'm')
         call add_real('obstacles.level_from'//trim(index), scene%obstacles(i)%level_from, 'm')
         call add_real('obstacles.level_to'//trim(index), scene%obstacles(i)%level_to, 'm')
         call add_real('obstacles.stiffness'//trim(index), scene%obstacles(i)%stiffness, 'N/m')
         call add_real('obstacles.exponent'//trim(index), scene%obstacles(i)%exponent, '')
         call add_real('obstacles.damping'//trim(index), scene%obstacles(i)%damping, 's/m')
      end do
      call add_real('impact.restitution', scene%restitution, '')
      call add_string('impact.separating_points', scene%separating_points)
      call add_real('time.t_end', scene%t_end, 's')
      call add_real('time.dt', scene%dt, 's')
      call add_string('time.scheme', scene%scheme)
      call add_real('time.theta', scene%theta, '')
      call add_real('time.gamma', scene%gamma, '')
      call add_string('time.compliant_rule', scene%compliant_rule)
      call add_string('initial.displacement', scene%displacement)
      call add_integer('initial.displacement_mode', scene%displacement_mode)
      call add_real('initial.displacement_amplitude', scene%displacement_amplitude, 'm')
      call add_string('initial.velocity', scene%velocity)
      call add_integer('initial.velocity_mode', scene%velocity_mode)
      call add_real('initial.velocity_amplitude', scene%velocity_amplitude, 'm/s')
      call add_string('initial.from_file', scene%from_file)
      call add_real('load.distributed', scene%distributed, 'N/m')
      call add_real('load.distributed_frequency', scene%distributed_frequency, 'rad/s')
      call add_real('load.distributed_phase', scene%distributed_phase, 'rad')
      call add_real('load.point_force', scene%point_force, 'N')
      call add_real('load.point_position', scene%point_position, 'm')
      call add_real('load.point_frequency', scene%point_frequency, 'rad/s')
      call add_real('load.base_amplitude', scene%base_amplitude, 'm')
      call add_real('load.base_frequency', scene%base_frequency, 'rad/s')
      call add_real('load.base_acceleration', scene%base_acceleration, 'm/s^2')
      call add_string('solver.contact_solver', scene%contact_solver)
      call add_string('solver.contact_method', scene%contact_method)
      call add_integer('solver.contact_max_iterations', scene%contact_max_iterations)
      call add_string('output.file', scene%file)
      call add_integer('output.every', scene%every)
      call add_logical('output.text', scene%text)
      call add_logical('output.progress', scene%progress)
      call add_integer('output.field_every', scene%field_every)
      if (allocated(scene%points)) then
         do i = 1, size(scene%points)
            write (index, '(a,i0,a)') '(', i, ')'
            call add_real('output.points'//trim(index), scene%points(i), 'm')
         end do
      end if
      call add_real('output.measure_from', scene%measure_from, 's')
      call add_real('output.checkpoint_seconds', scene%checkpoint_seconds, 's')
      if (.not. is_unset(scene%episode_gap)) call add_real('output.episode_gap', scene%episode_gap, 's')
      call add_string('output.poincare_load', scene%poincare_load)
   contains
      pure subroutine add_real(name, value, unit)
         character(len=*), intent(in) :: name, unit
         real(dp), intent(in) :: value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'real'
         item%real_value = value
         item%unit = unit
         list = [list, item]
      end subroutine add_real
      pure subroutine add_integer(name, value)
         character(len=*), intent(in) :: name
         integer, intent(in) :: value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'integer'
         item%integer_value = value
         list = [list, item]
      end subroutine add_integer
      pure subroutine add_string(name, value)
         character(len=*), intent(in) :: name, value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'string'
         item%string_value = value
         list = [list, item]
      end subroutine add_string
      pure subroutine add_logical(name, value)
         character(len=*), intent(in) :: name
         logical, intent(in) :: value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'logical'
         item%logical_value = value
         list = [list, item]
      end subroutine add_logical
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
