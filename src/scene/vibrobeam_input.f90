!> Reading a scene from a namelist file (docs/input.md).
!!
!! The file is first scanned whole against the table of every variable
!! (`vibrobeam_namelist_scan` with `scene_variables`): anything outside a known group, an
!! unterminated or repeated group, a value too long, out of an array, not finite, or of a
!! magnitude that would overflow or underflow in conversion is refused there, with the
!! line, group and variable. Each assignment the scanner accepted is then read by Fortran
!! namelist input from its own canonical record (an internal file), so a failure of the
!! run-time library still names the assignment. Which variables were given comes from the
!! scanner's tokens, never from comparing a value with a marker.
module vibrobeam_input
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_scene, only: scene_type, max_obstacles, max_points, scene_variables, path_length, &
      keyword_length, unknowns_of
   use vibrobeam_namelist_tokens, only: lowercase
   use vibrobeam_namelist_values, only: namelist_variable, range_text, variable_index, real_range_problem, &
      integer_range_problem
   use vibrobeam_namelist_scan, only: scanned_file, scan_namelist_file
   use vibrobeam_scene, only: max_sweep_values, parameter_length
   use vibrobeam_sweep_settings, only: sweep_settings
   use vibrobeam_ignored_values, only: ignored_values
   implicit none
   private
   public :: read_scene, namelist_groups_text

   !> Natural modes computed when `&analysis modes` is not given (fewer when J is smaller).
   integer, parameter :: default_modes = 6

contains

   !> Read `filename` into `scene` (defaults for everything not given). stat = 0 on
   !! success, 1 with a message naming the line, group and variable otherwise. Validation
   !! of the values against each other is `validate_scene`'s job. `warnings` (optional)
   !! receives one line per given value the analysis ignores.
   subroutine read_scene(filename, scene, stat, errmsg, warnings, sweep)
      character(len=*), intent(in) :: filename
      type(scene_type), intent(out) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable, intent(inout), optional :: warnings
      !> the &sweep group as written (`resolve_sweep` checks it against the scene);
      !! sweep%present is false without one
      type(sweep_settings), intent(out), optional :: sweep
      type(scanned_file) :: scanned
      allocate (scene%obstacles(0), scene%points(0))
      call scan_namelist_file(filename, scene_variables(), scanned, stat, errmsg)
      if (stat /= 0) return
      call read_beam(scanned, scene, stat, errmsg)
      if (stat == 0) call read_mesh(scanned, scene, stat, errmsg)
      if (stat == 0) call read_analysis(scanned, scene, stat, errmsg)
      if (stat == 0) call read_obstacles(scanned, scene, stat, errmsg)
      if (stat == 0) call read_impact(scanned, scene, stat, errmsg)
      if (stat == 0) call read_time(scanned, scene, stat, errmsg)
      if (stat == 0) call read_initial(scanned, scene, stat, errmsg)
      if (stat == 0) call read_load(scanned, scene, stat, errmsg)
      if (stat == 0) call read_solver(scanned, scene, stat, errmsg)
      if (stat == 0) call read_output(scanned, scene, stat, errmsg)
      if (stat /= 0) return
      if (present(sweep)) then
         call read_sweep(scanned, sweep, stat, errmsg)
         if (stat /= 0) return
         if (sweep%present .and. present(warnings)) then
            if (scanned%is_given('time', 't_end')) warnings = warnings//'&time t_end is ignored by a sweep: '// &
               'each point runs for its settle and measure windows'//new_line('a')
            if (scanned%is_given('output', 'measure_from')) warnings = warnings//'&output measure_from is '// &
               'ignored by a sweep: each point measures after its settle window'//new_line('a')
         end if
      else if (scanned%group_given('sweep')) then
         stat = 1
         errmsg = '&sweep: this program reads a single run''s scene (a sweep is run by vibrobeam itself)'
         return
      end if
      ! the default number of modes applies only to kind = 'modes', and never beyond J
      if (scene%kind == 'modes' .and. .not. scanned%is_given('analysis', 'modes') .and. scene%elements >= 1) &
         scene%modes = min(default_modes, unknowns_of(scene))
      if (present(warnings)) call ignored_values(scanned, scene, swept_inputs(), warnings)

   contains
      !> The inputs the &sweep varies, 'group.variable' without an element index.
      function swept_inputs() result(names)
         character(len=parameter_length), allocatable :: names(:)
         integer :: a, open
         allocate (names(0))
         if (.not. present(sweep)) return
         do a = 1, 2
            names = [character(len=parameter_length) :: names, lowercase(sweep%axis(a)%parameter)]
            open = index(names(size(names)), '(')
            if (open > 0) names(size(names)) = names(size(names))(1:open - 1)
         end do
      end function swept_inputs
   end subroutine read_scene

   !> '&beam &mesh ... &output': every group a file may hold.
   function namelist_groups_text() result(text)
      character(len=:), allocatable :: text
      type(namelist_variable), allocatable :: table(:)
      integer :: k
      allocate (table, source=scene_variables())
      text = ''
      do k = 1, size(table)
         if (index(text//' ', '&'//trim(table(k)%group)//' ') > 0) cycle
         if (len(text) > 0) text = text//' '
         text = text//'&'//trim(table(k)%group)
      end do
   end function namelist_groups_text

   !> After a namelist read of one canonical record: false on success; otherwise true,
   !! with a message naming the assignment (the scanner accepted it, so this is a
   !! disagreement with the run-time library, reported rather than trusted).
   logical function read_failed(ios, iomsg, label, stat, errmsg)
      integer, intent(in) :: ios
      character(len=*), intent(in) :: iomsg, label
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      read_failed = ios /= 0
      stat = merge(1, 0, read_failed)
      errmsg = ''
      if (read_failed) errmsg = label//': the Fortran run-time library cannot read this value ('// &
                                trim(iomsg)//'); write it as a plain number, quoted string or .true./.false.'
   end function read_failed

   subroutine read_beam(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: length, k2, youngs_modulus, density, area, inertia, rayleigh_mass, rayleigh_stiffness
      namelist /beam/ length, k2, youngs_modulus, density, area, inertia, rayleigh_mass, rayleigh_stiffness
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      length = scene%length; k2 = scene%k2
      youngs_modulus = scene%youngs_modulus; density = scene%density
      area = scene%area; inertia = scene%inertia
      rayleigh_mass = scene%rayleigh_mass; rayleigh_stiffness = scene%rayleigh_stiffness
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'beam')) cycle
         record = scanned%record(k)
         read (record, nml=beam, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%length = length; scene%k2 = k2
      scene%youngs_modulus = youngs_modulus; scene%density = density
      scene%area = area; scene%inertia = inertia
      scene%rayleigh_mass = rayleigh_mass; scene%rayleigh_stiffness = rayleigh_stiffness
   end subroutine read_beam

   subroutine read_mesh(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: elements, reduction_modes
      character(len=keyword_length) :: basis, reduction
      real(dp) :: reduction_frequency
      namelist /mesh/ elements, basis, reduction, reduction_frequency, reduction_modes
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      elements = scene%elements
      basis = scene%basis
      reduction = scene%reduction
      reduction_frequency = scene%reduction_frequency
      reduction_modes = scene%reduction_modes
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'mesh')) cycle
         record = scanned%record(k)
         read (record, nml=mesh, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%elements = elements
      scene%basis = lowercase(basis)
      scene%reduction = lowercase(reduction)
      scene%reduction_frequency = reduction_frequency
      scene%reduction_modes = reduction_modes
   end subroutine read_mesh

   subroutine read_analysis(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=keyword_length) :: kind
      integer :: modes
      namelist /analysis/ kind, modes
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      kind = scene%kind
      modes = scene%modes
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'analysis')) cycle
         record = scanned%record(k)
         read (record, nml=analysis, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%kind = lowercase(kind)
      scene%modes = modes
   end subroutine read_analysis

   !> &obstacles: which elements were given comes from the scanner. An obstacle takes its
   !! defaults (x_from = L, x_to = x_from, level_to = level_from) for what is not given;
   !! side and level_from are required; nothing may be given beyond `count`.
   subroutine read_obstacles(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: count
      character(len=keyword_length) :: side(max_obstacles)
      real(dp), dimension(max_obstacles) :: x_from, x_to, level_from, level_to, stiffness, exponent, damping
      namelist /obstacles/ count, side, x_from, x_to, level_from, level_to, stiffness, exponent, damping
      character(len=:), allocatable :: record
      type(namelist_variable), allocatable :: table(:)
      integer :: ios, i, k
      character(len=256) :: iomsg
      character(len=:), allocatable :: number
      count = 0
      side = ''
      x_from = 0; x_to = 0; level_from = 0; level_to = 0
      stiffness = 0; exponent = 1; damping = 0
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'obstacles')) cycle
         record = scanned%record(k)
         read (record, nml=obstacles, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      stat = 1
      if (count < 0 .or. count > max_obstacles) then
         table = scene_variables()
         errmsg = '&obstacles count = '//integer_text(count)//' is outside '// &
                  range_text(table(variable_index(table, 'obstacles', 'count')))
         return
      end if
      do i = count + 1, max_obstacles
         if (given(i)) then
            errmsg = '&obstacles: obstacle '//integer_text(i)//' is described but count = '//integer_text(count)// &
                     '; raise count or remove it'
            return
         end if
      end do
      deallocate (scene%obstacles)
      allocate (scene%obstacles(count))
      do i = 1, count
         number = integer_text(i)
         if (.not. scanned%is_given('obstacles', 'side', i)) then
            errmsg = '&obstacles side('//number//') is missing: give ''below'' or ''above'''
            return
         end if
         if (.not. scanned%is_given('obstacles', 'level_from', i)) then
            errmsg = '&obstacles level_from('//number//') is missing: give the height (m) of the obstacle surface'
            return
         end if
         scene%obstacles(i)%side = lowercase(side(i))
         scene%obstacles(i)%x_from = merge(x_from(i), scene%length, scanned%is_given('obstacles', 'x_from', i))
         scene%obstacles(i)%x_to = merge(x_to(i), scene%obstacles(i)%x_from, scanned%is_given('obstacles', 'x_to', i))
         scene%obstacles(i)%level_from = level_from(i)
         scene%obstacles(i)%level_to = merge(level_to(i), level_from(i), scanned%is_given('obstacles', 'level_to', i))
         scene%obstacles(i)%stiffness = stiffness(i)
         scene%obstacles(i)%exponent = exponent(i)
         scene%obstacles(i)%damping = damping(i)
      end do
      stat = 0
   contains
      logical function given(i)
         integer, intent(in) :: i
         given = scanned%is_given('obstacles', 'side', i) .or. scanned%is_given('obstacles', 'x_from', i) .or. &
                 scanned%is_given('obstacles', 'x_to', i) .or. scanned%is_given('obstacles', 'level_from', i) .or. &
                 scanned%is_given('obstacles', 'level_to', i) .or. scanned%is_given('obstacles', 'stiffness', i) .or. &
                 scanned%is_given('obstacles', 'exponent', i) .or. scanned%is_given('obstacles', 'damping', i)
      end function given
   end subroutine read_obstacles

   subroutine read_impact(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: restitution
      character(len=keyword_length) :: separating_points
      namelist /impact/ restitution, separating_points
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      restitution = scene%restitution
      separating_points = scene%separating_points
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'impact')) cycle
         record = scanned%record(k)
         read (record, nml=impact, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%restitution = restitution
      scene%separating_points = lowercase(separating_points)
   end subroutine read_impact

   subroutine read_time(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: t_end, dt, theta, gamma
      character(len=keyword_length) :: scheme, compliant_rule
      namelist /time/ t_end, dt, scheme, theta, gamma, compliant_rule
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      t_end = scene%t_end; dt = scene%dt; scheme = scene%scheme
      theta = scene%theta; gamma = scene%gamma; compliant_rule = scene%compliant_rule
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'time')) cycle
         record = scanned%record(k)
         read (record, nml=time, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%t_end = t_end; scene%dt = dt; scene%scheme = lowercase(scheme)
      scene%theta = theta; scene%gamma = gamma; scene%compliant_rule = lowercase(compliant_rule)
   end subroutine read_time

   subroutine read_initial(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=keyword_length) :: displacement, velocity
      integer :: displacement_mode, velocity_mode
      real(dp) :: displacement_amplitude, velocity_amplitude
      character(len=path_length) :: from_file
      namelist /initial/ displacement, displacement_mode, displacement_amplitude, &
         velocity, velocity_mode, velocity_amplitude, from_file
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      displacement = scene%displacement; displacement_mode = scene%displacement_mode
      displacement_amplitude = scene%displacement_amplitude
      velocity = scene%velocity; velocity_mode = scene%velocity_mode
      velocity_amplitude = scene%velocity_amplitude
      from_file = scene%from_file
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'initial')) cycle
         record = scanned%record(k)
         read (record, nml=initial, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%displacement = lowercase(displacement); scene%displacement_mode = displacement_mode
      scene%displacement_amplitude = displacement_amplitude
      scene%velocity = lowercase(velocity); scene%velocity_mode = velocity_mode
      scene%velocity_amplitude = velocity_amplitude
      scene%from_file = from_file
   end subroutine read_initial

   subroutine read_load(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: distributed, distributed_frequency, distributed_phase
      real(dp) :: point_force, point_position, point_frequency, base_amplitude, base_frequency, base_acceleration
      namelist /load/ distributed, distributed_frequency, distributed_phase, point_force, &
         point_position, point_frequency, base_amplitude, base_frequency, base_acceleration
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      distributed = scene%distributed; distributed_frequency = scene%distributed_frequency
      distributed_phase = scene%distributed_phase; point_force = scene%point_force
      point_position = scene%length; point_frequency = scene%point_frequency   ! default: the tip
      base_amplitude = scene%base_amplitude; base_frequency = scene%base_frequency
      base_acceleration = scene%base_acceleration
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'load')) cycle
         record = scanned%record(k)
         read (record, nml=load, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%distributed = distributed; scene%distributed_frequency = distributed_frequency
      scene%distributed_phase = distributed_phase; scene%point_force = point_force
      scene%point_position = point_position; scene%point_frequency = point_frequency
      scene%base_amplitude = base_amplitude; scene%base_frequency = base_frequency
      scene%base_acceleration = base_acceleration
   end subroutine read_load

   subroutine read_solver(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=keyword_length) :: contact_solver, contact_method
      integer :: contact_max_iterations
      namelist /solver/ contact_solver, contact_method, contact_max_iterations
      character(len=:), allocatable :: record
      integer :: ios, k
      character(len=256) :: iomsg
      contact_solver = scene%contact_solver
      contact_method = scene%contact_method
      contact_max_iterations = scene%contact_max_iterations
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'solver')) cycle
         record = scanned%record(k)
         read (record, nml=solver, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%contact_solver = lowercase(contact_solver)
      scene%contact_method = lowercase(contact_method)
      scene%contact_max_iterations = contact_max_iterations
   end subroutine read_solver

   !> &output; `points` are the leading elements given (points(1), points(2), ...).
   subroutine read_output(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=path_length) :: file
      integer :: every, field_every
      logical :: text, progress
      real(dp) :: points(max_points), measure_from, checkpoint_seconds, episode_gap
      character(len=keyword_length) :: poincare_load
      namelist /output/ file, every, text, progress, field_every, points, measure_from, checkpoint_seconds, &
         episode_gap, poincare_load
      character(len=:), allocatable :: record
      integer :: ios, k, count_points
      character(len=256) :: iomsg
      file = scene%file; every = scene%every; text = scene%text; progress = scene%progress
      field_every = scene%field_every; measure_from = scene%measure_from
      checkpoint_seconds = scene%checkpoint_seconds; episode_gap = scene%episode_gap
      poincare_load = scene%poincare_load
      points = 0
      stat = 0
      errmsg = ''
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'output')) cycle
         record = scanned%record(k)
         read (record, nml=output, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      scene%file = file; scene%every = every; scene%text = text; scene%progress = progress
      scene%field_every = field_every; scene%measure_from = measure_from
      scene%checkpoint_seconds = checkpoint_seconds; scene%episode_gap = episode_gap
      scene%poincare_load = lowercase(poincare_load)
      count_points = 0
      do while (count_points < max_points)
         if (.not. scanned%is_given('output', 'points', count_points + 1)) exit
         count_points = count_points + 1
      end do
      do k = count_points + 1, max_points
         if (scanned%is_given('output', 'points', k)) then
            stat = 1
            errmsg = '&output points('//integer_text(k)//') is given but points('//integer_text(count_points + 1)// &
                     ') is not: list the observation points from points(1) on, without gaps'
            return
         end if
      end do
      scene%points = points(1:count_points)
   end subroutine read_output
   !> &sweep as written, and which inputs whose default follows another were given
   !! (docs/sweeps.md, "The parameter").
   subroutine read_sweep(scanned, settings, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(sweep_settings), intent(out) :: settings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=parameter_length) :: parameter, parameter2
      real(dp) :: values(max_sweep_values), values2(max_sweep_values), from, to, from2, to2
      real(dp) :: settle, measure, settle_periods, measure_periods, steady_tolerance
      integer :: count, count2
      character(len=keyword_length) :: spacing, spacing2, mode
      logical :: keep_runs
      namelist /sweep/ parameter, values, from, to, count, spacing, mode, parameter2, values2, from2, to2, count2, &
         spacing2, settle, measure, settle_periods, measure_periods, steady_tolerance, keep_runs
      character(len=:), allocatable :: record
      type(namelist_variable), allocatable :: table(:)
      integer :: ios, k, i
      character(len=256) :: iomsg
      stat = 0
      errmsg = ''
      settings%present = scanned%group_given('sweep')
      if (.not. settings%present) return
      parameter = ''; parameter2 = ''
      values = 0; values2 = 0; from = 0; to = 0; from2 = 0; to2 = 0; count = 0; count2 = 0
      spacing = settings%axis(1)%spacing; spacing2 = settings%axis(2)%spacing; mode = settings%mode
      settle = 0; measure = 0; settle_periods = 0; measure_periods = 0; steady_tolerance = 0
      keep_runs = .false.
      do k = 1, size(scanned%items)
         if (.not. scanned%in_group(k, 'sweep')) cycle
         record = scanned%record(k)
         read (record, nml=sweep, iostat=ios, iomsg=iomsg)
         if (read_failed(ios, iomsg, scanned%label(k), stat, errmsg)) return
      end do
      ! the windows and counts given, against their hard ranges (the values of the
      ! parameter are checked against the parameter's range by resolve_sweep)
      table = scene_variables()
      call check_real('settle', settle)
      call check_real('measure', measure)
      call check_real('settle_periods', settle_periods)
      call check_real('measure_periods', measure_periods)
      call check_real('steady_tolerance', steady_tolerance)
      call check_integer('count', count)
      call check_integer('count2', count2)
      if (stat /= 0) return
      settings%axis(1)%parameter = parameter
      settings%axis(2)%parameter = parameter2
      call axis_values(1, values, from, to, count, spacing, '')
      if (stat == 0) call axis_values(2, values2, from2, to2, count2, spacing2, '2')
      if (stat /= 0) return
      settings%mode = lowercase(mode)
      settings%settle = settle
      settings%measure = measure
      settings%settle_periods = settle_periods
      settings%measure_periods = measure_periods
      settings%steady_tolerance = steady_tolerance
      settings%keep_runs = keep_runs
      settings%point_position_given = scanned%is_given('load', 'point_position')
      do i = 1, max_obstacles
         settings%x_from_given(i) = scanned%is_given('obstacles', 'x_from', i)
         settings%x_to_given(i) = scanned%is_given('obstacles', 'x_to', i)
         settings%level_to_given(i) = scanned%is_given('obstacles', 'level_to', i)
      end do
   contains
      !> A real of &sweep, when given, against its row of `scene_variables`.
      subroutine check_real(name, value)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: value
         character(len=:), allocatable :: problem
         if (stat /= 0 .or. .not. scanned%is_given('sweep', name)) return
         problem = real_range_problem(table(variable_index(table, 'sweep', name)), value)
         if (len(problem) == 0) return
         stat = 1
         errmsg = '&sweep '//name//' = '//real_text(value)//' '//problem
      end subroutine check_real

      !> An integer of &sweep, when given, against its row of `scene_variables`.
      subroutine check_integer(name, value)
         character(len=*), intent(in) :: name
         integer, intent(in) :: value
         character(len=:), allocatable :: problem
         if (stat /= 0 .or. .not. scanned%is_given('sweep', name)) return
         problem = integer_range_problem(table(variable_index(table, 'sweep', name)), value)
         if (len(problem) == 0) return
         stat = 1
         errmsg = '&sweep '//name//' = '//integer_text(value)//' '//problem
      end subroutine check_integer

      !> The leading elements given of values (without gaps), or the range.
      subroutine axis_values(a, list, first, last, number, kind, suffix)
         integer, intent(in) :: a, number
         real(dp), intent(in) :: list(:), first, last
         character(len=*), intent(in) :: kind, suffix
         integer :: given, j
         given = 0
         do while (given < max_sweep_values)
            if (.not. scanned%is_given('sweep', 'values'//suffix, given + 1)) exit
            given = given + 1
         end do
         do j = given + 1, max_sweep_values
            if (scanned%is_given('sweep', 'values'//suffix, j)) then
               stat = 1
               errmsg = '&sweep values'//suffix//'('//integer_text(j)//') is given but values'//suffix//'('// &
                        integer_text(given + 1)//') is not: list the values from values'//suffix//'(1) on, without gaps'
               return
            end if
         end do
         if (given > 0) settings%axis(a)%given_values = list(1:given)
         settings%axis(a)%range_given = scanned%is_given('sweep', 'from'//suffix) .or. &
                                        scanned%is_given('sweep', 'to'//suffix) .or. &
                                        scanned%is_given('sweep', 'count'//suffix)
         if (settings%axis(a)%range_given .and. .not. (scanned%is_given('sweep', 'from'//suffix) .and. &
                                                       scanned%is_given('sweep', 'to'//suffix))) then
            stat = 1
            errmsg = '&sweep: a range needs from'//suffix//' and to'//suffix//' (and count'//suffix//')'
            return
         end if
         settings%axis(a)%from = first
         settings%axis(a)%to = last
         settings%axis(a)%count = number
         settings%axis(a)%spacing = lowercase(kind)
      end subroutine axis_values
   end subroutine read_sweep
end module vibrobeam_input
