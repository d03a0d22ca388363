!> Reading a scene from a namelist file (docs/input.md).
!!
!! The file is first scanned whole against the table of every variable
!! (`vibrobeam_namelist_scan` with `scene_variables`): anything outside a known group, an
!! unterminated or repeated group, a value too long, out of an array, not finite, or of a
!! magnitude that would overflow or underflow in conversion is refused there, with the
!! line, group and variable. The values the scanner accepted are then set by walking the
!! settings' declarations (`visit_scene` with a `schema_reader`): each value converted by
!! the run-time library's list-directed read, so a failure still names the assignment.
!! Which variables were given comes from the scanner's tokens, never from comparing a
!! value with a marker. What is left here is what relates variables: the defaults that
!! follow another input, the variables an obstacle requires, the observation points
!! listed without gaps, and the warnings for values the analysis ignores.
module vibrobeam_scene_read
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_periodic_settings, only: forcing_frequency, period_step
   use vibrobeam_scene, only: scene_type, max_obstacles, max_points, max_supports, max_masses, max_forces, &
      max_sections, scene_variables, visit_scene, held_conditions, sync_frequency_twins
   use vibrobeam_scene_values, only: real_input, set_real_input
   use vibrobeam_frequency_twins, only: is_twin, frequency_name
   use vibrobeam_obstacles, only: obstacle_type
   use vibrobeam_namelist_schema, only: namelist_variable, real_range_problem
   use vibrobeam_namelist_scan, only: scanned_file, scan_namelist_file
   use vibrobeam_schema_operations, only: schema_reader
   use vibrobeam_sweep_input, only: sweep_input, visit_sweep, max_sweep_values
   use vibrobeam_sweep_settings, only: sweep_settings
   use vibrobeam_ignored_values, only: ignored_values
   use vibrobeam_namelist_tokens, only: lowercase
   use vibrobeam_filesystem, only: directory_of
   use vibrobeam_schema_operations, only: schema_checker
   use vibrobeam_sweep_input, only: parameter_length
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
      type(schema_reader) :: reader
      integer :: count, support_count, mass_count, force_count, section_count
      call scan_namelist_file(filename, scene_variables(), reader%scanned, stat, errmsg)
      if (stat /= 0) return
      ! room for every obstacle, support, mass, section, load and point the file may
      ! describe (the obstacles it does describe: each holds a file name); cut to what it
      ! gives below
      allocate (scene%obstacles(highest_given(reader%scanned, 'obstacles', max_obstacles)), &
                scene%output%points(max_points), scene%supports(max_supports), &
                scene%masses(max_masses), scene%forces%load(max_forces), scene%beam%sections(max_sections))
      scene%obstacles(:)%side = ''
      scene%output%points = 0
      count = 0
      support_count = 0
      mass_count = 0
      force_count = 0
      section_count = 0
      call visit_scene(scene, reader, obstacle_count=count, support_count=support_count, mass_count=mass_count, &
                       force_count=force_count, section_count=section_count)
      if (reader%stat /= 0) then
         stat = reader%stat
         errmsg = reader%errmsg
         return
      end if
      call resolve_obstacles(reader%scanned, count, filename, scene, stat, errmsg)
      if (stat == 0) call resolve_supports(reader%scanned, support_count, scene, stat, errmsg)
      if (stat == 0) call resolve_masses(reader%scanned, mass_count, scene, stat, errmsg)
      if (stat == 0) call resolve_sections(reader%scanned, section_count, scene, stat, errmsg)
      if (stat == 0) call resolve_forces(reader%scanned, force_count, filename, scene, stat, errmsg)
      call beside_input(filename, 'initial', 'velocity_profile', scene%initial%velocity_profile, stat, errmsg)
      if (stat == 0) call resolve_points(reader%scanned, scene, stat, errmsg)
      if (stat == 0) call resolve_frequency_twins(reader%scanned, scene, stat, errmsg)
      if (stat /= 0) return
      if (.not. reader%scanned%is_given('load', 'point_position')) scene%load%point_position = scene%beam%length
      if (scene%analysis%kind == 'periodic') call resolve_periodic_step(scene)
      if (present(sweep)) then
         call read_sweep(reader, sweep, stat, errmsg)
         if (stat /= 0) return
         if (sweep%present .and. present(warnings)) then
            if (reader%scanned%is_given('time', 't_end')) warnings = warnings//'&time t_end is ignored by a sweep: '// &
               'each point runs for its settle and measure windows'//new_line('a')
            if (reader%scanned%is_given('output', 'measure_from')) warnings = warnings//'&output measure_from is '// &
               'ignored by a sweep: each point measures after its settle window'//new_line('a')
         end if
      else if (reader%scanned%group_given('sweep')) then
         stat = stat_failure
         errmsg = '&sweep: this program reads a single run''s scene (a sweep is run by vibrobeam itself)'
         return
      end if
      ! the default number of modes applies only to kind = 'modes', and never beyond J
      if (scene%analysis%kind == 'modes' .and. .not. reader%scanned%is_given('analysis', 'modes') .and. &
          scene%mesh%elements >= 1) scene%analysis%modes = min(default_modes, scene%mesh%unknowns(held_conditions(scene)))
      if (present(warnings)) call ignored_values(reader%scanned, scene, swept_inputs(), warnings)

   contains
      !> The inputs the &sweep varies, and a continuation's &periodic parameter (a branch
      !! may start where that input is 0: &flow velocity), 'group.variable' without an
      !! element index.
      function swept_inputs() result(names)
         character(len=parameter_length), allocatable :: names(:)
         integer :: a
         allocate (names(0))
         if (scene%analysis%kind == 'periodic' .and. len_trim(scene%periodic%parameter) > 0) &
            names = [character(len=parameter_length) :: names, without_element(scene%periodic%parameter)]
         if (.not. present(sweep)) return
         do a = 1, 2
            names = [character(len=parameter_length) :: names, without_element(sweep%axis(a)%parameter)]
         end do
      end function swept_inputs

      !> 'group.variable(i)' in lower case without '(i)'.
      function without_element(parameter) result(name)
         character(len=*), intent(in) :: parameter
         character(len=parameter_length) :: name
         integer :: open
         name = lowercase(parameter)
         open = index(name, '(')
         if (open > 0) name = name(1:open - 1)
      end function without_element
   end subroutine read_scene

   !> &periodic steps_per_period > 0 sets &time dt = T/steps_per_period, T = 2 pi/Omega the
   !! period of the harmonic loads (`forcing_frequency`); with none, or several of
   !! different frequencies, dt stays as given and `validate_scene` says why. An
   !! autonomous orbit's T is &periodic period, the guess of its period.
   subroutine resolve_periodic_step(scene)
      type(scene_type), intent(inout) :: scene
      real(dp) :: omega
      character(len=:), allocatable :: problem
      if (scene%periodic%steps_per_period <= 0) return
      if (scene%periodic%autonomous) then
         ! the period's guess is cut into the steps (a period unset or out of range:
         ! `validate_scene` says so, dt stays)
         if (scene%periodic%period > 0) scene%time%dt = scene%periodic%period/scene%periodic%steps_per_period
         return
      end if
      call forcing_frequency(scene%load, omega, problem)
      if (len(problem) > 0) return
      ! (2 pi/(Omega steps) finite: the hard ranges leave Omega > 0 as small as a normal double)
      if (omega*scene%periodic%steps_per_period <= 2*pi/huge(1.0_dp)) return
      scene%time%dt = period_step(omega, scene%periodic%steps_per_period)
   end subroutine resolve_periodic_step

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

   !> &obstacles after reading: nothing may be described beyond `count`; each obstacle
   !! needs side and level_from (or a profile, whose relative file name is taken from the
   !! input file's directory) and takes the defaults that follow other inputs for what
   !! is not given (x_from = L, x_to = x_from, level_to = level_from).
   subroutine resolve_obstacles(scanned, count, filename, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      integer, intent(in) :: count
      character(len=*), intent(in) :: filename
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(obstacle_type), allocatable :: read(:)
      integer :: i
      character(len=:), allocatable :: number
      call check_count(scanned, 'obstacles', 'obstacle', count, max_obstacles, stat, errmsg)
      if (stat /= 0) return
      stat = stat_failure
      call move_alloc(scene%obstacles, read)
      allocate (scene%obstacles(count))
      do i = 1, count
         number = integer_text(i)
         if (read(i)%hole()) then
            ! a circle or a polygon: its radius and centre (and a polygon's sides), none of a
            ! level's variables
            if (.not. scanned%is_given('obstacles', 'radius', i)) then
               errmsg = '&obstacles radius('//number//') is missing: shape('//number//') = '''// &
                        trim(read(i)%shape)//''' needs the radius (m) of the hole'
               return
            end if
            if (read(i)%shape == 'polygon' .and. .not. scanned%is_given('obstacles', 'sides', i)) then
               errmsg = '&obstacles sides('//number//') is missing: shape('//number//') = ''polygon'' needs its '// &
                        'number of faces (3 to 64)'
               return
            end if
            if (read(i)%shape == 'circle' .and. (scanned%is_given('obstacles', 'sides', i) .or. &
                                                 scanned%is_given('obstacles', 'orientation', i))) then
               errmsg = '&obstacles sides('//number//') or orientation('//number//') is given for shape('//number// &
                        ') = ''circle'': they describe a polygon; remove them or give shape = ''polygon'''
               return
            end if
            if (given_of_level(i) /= '') then
               errmsg = '&obstacles '//given_of_level(i)//'('//number//') is given for shape('//number//') = '''// &
                        trim(read(i)%shape)//''': a hole has radius, center_y and center_z; remove it'
               return
            end if
            scene%obstacles(i) = read(i)
            scene%obstacles(i)%side = 'below'   ! (unused by a hole)
            if (.not. scanned%is_given('obstacles', 'x_from', i)) scene%obstacles(i)%x_from = scene%beam%length
            if (.not. scanned%is_given('obstacles', 'x_to', i)) scene%obstacles(i)%x_to = scene%obstacles(i)%x_from
            cycle
         end if
         if (.not. scanned%is_given('obstacles', 'side', i)) then
            errmsg = '&obstacles side('//number//') is missing: give ''below'' or ''above'''
            return
         end if
         if (.not. (scanned%is_given('obstacles', 'level_from', i) .or. scanned%is_given('obstacles', 'profile', i))) then
            errmsg = '&obstacles level_from('//number//') is missing: give the height (m) of the obstacle surface '// &
                     '(or its profile('//number//'))'
            return
         end if
         if (scanned%is_given('obstacles', 'radius', i) .or. scanned%is_given('obstacles', 'center_y', i) .or. &
             scanned%is_given('obstacles', 'center_z', i) .or. scanned%is_given('obstacles', 'sides', i) .or. &
             scanned%is_given('obstacles', 'orientation', i)) then
            errmsg = '&obstacles radius('//number//'), center_y('//number//'), center_z('//number//'), sides('// &
                     number//') or orientation('//number//') is given for a level obstacle: give shape('//number// &
                     ') = ''circle'' or ''polygon'', or remove them'
            return
         end if
         scene%obstacles(i) = read(i)
         if (.not. scanned%is_given('obstacles', 'x_from', i)) scene%obstacles(i)%x_from = scene%beam%length
         if (.not. scanned%is_given('obstacles', 'x_to', i)) scene%obstacles(i)%x_to = scene%obstacles(i)%x_from
         if (.not. scanned%is_given('obstacles', 'level_to', i)) scene%obstacles(i)%level_to = read(i)%level_from
      end do
      stat = 0
      errmsg = ''
      do i = 1, count
         call beside_input(filename, 'obstacles', 'profile', scene%obstacles(i)%profile, stat, errmsg, i)
      end do
   contains
      !> The first variable of a level obstacle given for obstacle i ('' none).
      function given_of_level(i) result(name)
         integer, intent(in) :: i
         character(len=:), allocatable :: name
         character(len=10), parameter :: names(4) = [character(len=10) :: 'side', 'level_from', 'level_to', &
                                                     'profile']
         integer :: k
         name = ''
         do k = 1, size(names)
            if (scanned%is_given('obstacles', trim(names(k)), i)) then
               name = trim(names(k))
               return
            end if
         end do
      end function given_of_level
   end subroutine resolve_obstacles

   !> The frequencies given in Hz (docs/input.md, "Frequencies in Hz"): a twin and its
   !! frequency are not both given; a twin given (checked against its own range first, so
   !! that a message names what the file says) sets its frequency to 2 pi times it; every
   !! other twin is the frequency over 2 pi. An array's twin (&forces frequency_hz(i)) is
   !! taken element by element.
   subroutine resolve_frequency_twins(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(namelist_variable), allocatable :: table(:)
      character(len=:), allocatable :: group, twin, frequency, problem, item
      real(dp) :: value, given
      logical :: found
      integer :: k, i
      stat = 0
      errmsg = ''
      allocate (table, source=scene_variables())
      do k = 1, size(table)
         if (.not. is_twin(table(k)%name)) cycle
         group = trim(table(k)%group)
         twin = trim(table(k)%name)
         frequency = frequency_name(twin)
         do i = 1, max(table(k)%extent, 1)
            if (table(k)%extent > 0) then
               if (.not. scanned%is_given(group, twin, i)) cycle
               item = '('//integer_text(i)//')'
            else
               if (.not. scanned%is_given(group, twin)) cycle
               item = ''
            end if
            call real_input(scene, group, twin, i, given, found)
            if (.not. found) cycle   ! an element beyond the count, which the count's check refused
            if (given_too(frequency, i)) then
               call real_input(scene, group, frequency, i, value, found)
               stat = stat_failure
               errmsg = '&'//group//' '//frequency//item//' = '//real_text(value)//' rad/s and '//twin//item// &
                        ' = '//real_text(given)//' Hz are both given: give one of them ('//twin//' = '//frequency// &
                        '/(2 pi))'
               return
            end if
            problem = real_range_problem(table(k), given)
            if (len(problem) > 0) then
               stat = stat_failure
               errmsg = '&'//group//' '//twin//item//' = '//real_text(given)//' '//problem
               return
            end if
            call set_real_input(scene, group, twin, i, given, found)   ! and the frequency, 2 pi times it
         end do
      end do
      call sync_frequency_twins(scene)
   contains
      !> The frequency of the twin is given too (element i of an array).
      logical function given_too(name, i)
         character(len=*), intent(in) :: name
         integer, intent(in) :: i
         if (table(k)%extent > 0) then
            given_too = scanned%is_given(group, name, i)
         else
            given_too = scanned%is_given(group, name)
         end if
      end function given_too
   end subroutine resolve_frequency_twins
   !> The count of an array of settings (&obstacles, &supports, &masses, &sections, &forces)
   !! against what the file describes: in [0, most], and no element beyond it given (any
   !! array variable of `group`, as the table of variables declares them; the message
   !! names the first one found).
   subroutine check_count(scanned, group, element, count, most, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      character(len=*), intent(in) :: group, element   !! 'obstacles', 'obstacle'
      integer, intent(in) :: count, most
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(namelist_variable), allocatable :: table(:)
      integer :: i, k
      stat = stat_failure
      if (count < 0 .or. count > most) then
         errmsg = '&'//group//' count = '//integer_text(count)//' is outside [0, '//integer_text(most)//']'
         return
      end if
      allocate (table, source=scene_variables())
      do i = count + 1, most
         do k = 1, size(table)
            if (table(k)%group /= group .or. table(k)%extent == 0) cycle
            if (scanned%is_given(group, trim(table(k)%name), i)) then
               errmsg = '&'//group//': '//element//' '//integer_text(i)//' is described ('//trim(table(k)%name)// &
                        '('//integer_text(i)//')) but count = '//integer_text(count)//'; raise count or remove it'
               return
            end if
         end do
      end do
      stat = 0
      errmsg = ''
   end subroutine check_count

   !> The highest element i <= most of any array variable of `group` the file gives (0:
   !! none), so that reading holds only the elements described.
   integer function highest_given(scanned, group, most) result(highest)
      type(scanned_file), intent(in) :: scanned
      character(len=*), intent(in) :: group
      integer, intent(in) :: most
      type(namelist_variable), allocatable :: table(:)
      integer :: k
      allocate (table, source=scene_variables())
      do highest = most, 1, -1
         do k = 1, size(table)
            if (table(k)%group /= group .or. table(k)%extent == 0) cycle
            if (scanned%is_given(group, trim(table(k)%name), highest)) return
         end do
      end do
      highest = 0
   end function highest_given

   !> The count of an array of settings whose count is an optional row (&supports, &masses,
   !! &sections): `given` is 0 when the file does not give it (count is then unset, -1),
   !! else the count given, checked as `check_count` does (even -1).
   subroutine optional_count(scanned, group, element, count, most, given, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      character(len=*), intent(in) :: group, element
      integer, intent(in) :: count, most
      integer, intent(out) :: given
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      given = 0
      if (scanned%is_given(group, 'count')) given = count
      call check_count(scanned, group, element, given, most, stat, errmsg)
   end subroutine optional_count

   !> &supports after reading: count (0 when not given) and what it allows; each support
   !! needs its x.
   subroutine resolve_supports(scanned, count, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      integer, intent(in) :: count
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i, given
      call optional_count(scanned, 'supports', 'support', count, max_supports, given, stat, errmsg)
      if (stat /= 0) return
      scene%supports = scene%supports(1:given)
      do i = 1, size(scene%supports)
         if (.not. scanned%is_given('supports', 'x', i)) then
            stat = stat_failure
            errmsg = '&supports x('//integer_text(i)//') is missing: give the position (m) of the support'
            return
         end if
      end do
   end subroutine resolve_supports

   !> &masses after reading: count (0 when not given) and what it allows; each mass needs
   !! its x.
   subroutine resolve_masses(scanned, count, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      integer, intent(in) :: count
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i, given
      call optional_count(scanned, 'masses', 'mass', count, max_masses, given, stat, errmsg)
      if (stat /= 0) return
      scene%masses = scene%masses(1:given)
      do i = 1, size(scene%masses)
         if (.not. scanned%is_given('masses', 'x', i)) then
            stat = stat_failure
            errmsg = '&masses x('//integer_text(i)//') is missing: give the position (m) of the mass'
            return
         end if
      end do
   end subroutine resolve_masses

   !> &sections after reading: count (0 when not given) and what it allows; each section
   !! needs its end and its four data; a beam given by &beam k2 alone (per unit mass) takes
   !! none (docs/input.md, "&sections").
   subroutine resolve_sections(scanned, count, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      integer, intent(in) :: count
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: names(5) = [character(len=14) :: 'x_to', 'youngs_modulus', 'density', 'area', &
                                                 'inertia']
      character(len=*), parameter :: meaning(5) = [character(len=31) :: 'the end (m) of the section', &
                                                   'its Young''s modulus (Pa)', 'its density (kg/m^3)', &
                                                   'its cross-section area (m^2)', 'its second moment of area (m^4)']
      integer :: i, k, given
      call optional_count(scanned, 'sections', 'section', count, max_sections, given, stat, errmsg)
      if (stat /= 0) return
      scene%beam%sections = scene%beam%sections(1:given)
      if (given == 0) return
      stat = stat_failure
      if (scanned%is_given('beam', 'k2') .and. .not. (scanned%is_given('beam', 'youngs_modulus') .or. &
          scanned%is_given('beam', 'density') .or. scanned%is_given('beam', 'area') .or. &
          scanned%is_given('beam', 'inertia'))) then
         errmsg = '&sections count = '//integer_text(given)//' is not available for a beam given by &beam k2 alone '// &
                  '(per unit mass): sections give E, rho, S and I each; remove k2, or the sections'
         return
      end if
      do i = 1, given
         do k = 1, size(names)
            if (.not. scanned%is_given('sections', trim(names(k)), i)) then
               errmsg = '&sections '//trim(names(k))//'('//integer_text(i)//') is missing: give '//trim(meaning(k))// &
                        ' (each section gives x_to, youngs_modulus, density, area and inertia)'
               return
            end if
         end do
      end do
      stat = 0
      errmsg = ''
   end subroutine resolve_sections

   !> &forces after reading: nothing may be described beyond `count` (any array variable
   !! of &forces, as the table of variables declares them); the loads are cut to it; a
   !! relative file name of a table is taken from the directory of the input file
   !! `filename` (`beside_input`).
   !! The defaults that follow other inputs are taken when the loads are built.
   subroutine resolve_forces(scanned, count, filename, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      integer, intent(in) :: count
      character(len=*), intent(in) :: filename
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i
      call check_count(scanned, 'forces', 'load', count, max_forces, stat, errmsg)
      if (stat /= 0) return
      scene%forces%load = scene%forces%load(1:count)
      do i = 1, count
         call beside_input(filename, 'forces', 'table', scene%forces%load(i)%table, stat, errmsg, i)
         call beside_input(filename, 'forces', 'psd_table', scene%forces%load(i)%psd_table, stat, errmsg, i)
      end do
   end subroutine resolve_forces

   !> A relative file name `path` of group.name(i) taken from the directory of the input
   !! file `filename` (docs/input.md, "Tables"), so that a scene and its files move
   !! together; an absolute one as it is; nothing when stat is already set. stat =
   !! stat_failure when the result is longer than the variable.
   subroutine beside_input(filename, group, name, path, stat, errmsg, i)
      character(len=*), intent(in) :: filename, group, name
      character(len=*), intent(inout) :: path
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      integer, intent(in), optional :: i   !! the element of an array variable
      character(len=:), allocatable :: directory, shown
      if (stat /= 0 .or. len_trim(path) == 0 .or. path(1:1) == '/') return
      directory = directory_of(filename)
      if (directory == '.') return
      shown = '&'//group//' '//name
      if (present(i)) shown = shown//'('//integer_text(i)//')'
      if (len(directory) + 1 + len_trim(path) > len(path)) then
         errmsg = shown//' = '''//trim(path)//''' taken from the directory of the input file is longer than '// &
                  integer_text(len(path))//' characters'
         stat = stat_failure
         return
      end if
      path = directory//'/'//trim(path)
   end subroutine beside_input

   !> &output points: the leading elements given (points(1), points(2), ...), no gaps.
   subroutine resolve_points(scanned, scene, stat, errmsg)
      type(scanned_file), intent(in) :: scanned
      type(scene_type), intent(inout) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k, count_points
      stat = 0
      errmsg = ''
      count_points = leading_given(scanned, 'output', 'points', max_points)
      do k = count_points + 1, max_points
         if (scanned%is_given('output', 'points', k)) then
            stat = stat_failure
            errmsg = '&output points('//integer_text(k)//') is given but points('//integer_text(count_points + 1)// &
                     ') is not: list the observation points from points(1) on, without gaps'
            return
         end if
      end do
      scene%output%points = scene%output%points(1:count_points)
   end subroutine resolve_points

   !> How many of group.name(1), (2), ... are given before the first that is not.
   integer function leading_given(scanned, group, name, most)
      type(scanned_file), intent(in) :: scanned
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: most
      leading_given = 0
      do while (leading_given < most)
         if (.not. scanned%is_given(group, name, leading_given + 1)) exit
         leading_given = leading_given + 1
      end do
   end function leading_given

   !> &sweep as written, and which inputs whose default follows another were given
   !! (docs/sweeps.md, "The parameter").
   subroutine read_sweep(reader, settings, stat, errmsg)
      type(schema_reader), intent(inout) :: reader
      type(sweep_settings), intent(out) :: settings
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(sweep_input) :: input
      type(schema_checker) :: checker
      integer :: i
      stat = 0
      errmsg = ''
      settings%present = reader%scanned%group_given('sweep')
      if (.not. settings%present) return
      call visit_sweep(input, reader)
      if (reader%stat /= 0) then
         stat = reader%stat
         errmsg = reader%errmsg
         return
      end if
      ! every value of &sweep against its hard range (the values of the parameter are checked
      ! against the parameter's own range by resolve_sweep)
      call visit_sweep(input, checker)
      if (checker%stat /= 0) then
         stat = checker%stat
         errmsg = checker%errmsg
         return
      end if
      settings%axis(1)%parameter = input%parameter
      settings%axis(2)%parameter = input%parameter2
      call axis_values(1, input%values, input%from, input%to, input%count, input%spacing, '')
      if (stat == 0) call axis_values(2, input%values2, input%from2, input%to2, input%count2, input%spacing2, '2')
      if (stat /= 0) return
      settings%mode = input%mode
      settings%settle = input%settle
      settings%measure = input%measure
      settings%settle_periods = input%settle_periods
      settings%measure_periods = input%measure_periods
      settings%steady_tolerance = input%steady_tolerance
      settings%keep_runs = input%keep_runs
      settings%poincare_samples = input%poincare_samples
      settings%point_position_given = reader%scanned%is_given('load', 'point_position')
      do i = 1, max_obstacles
         settings%x_from_given(i) = reader%scanned%is_given('obstacles', 'x_from', i)
         settings%x_to_given(i) = reader%scanned%is_given('obstacles', 'x_to', i)
         settings%level_to_given(i) = reader%scanned%is_given('obstacles', 'level_to', i)
      end do
   contains
      !> The leading elements given of values (without gaps), or the range.
      subroutine axis_values(a, list, first, last, number, kind, suffix)
         integer, intent(in) :: a, number
         real(dp), intent(in) :: list(:), first, last
         character(len=*), intent(in) :: kind, suffix
         integer :: given, j
         given = leading_given(reader%scanned, 'sweep', 'values'//suffix, max_sweep_values)
         do j = given + 1, max_sweep_values
            if (reader%scanned%is_given('sweep', 'values'//suffix, j)) then
               stat = stat_failure
               errmsg = '&sweep values'//suffix//'('//integer_text(j)//') is given but values'//suffix//'('// &
                        integer_text(given + 1)//') is not: list the values from values'//suffix//'(1) on, without gaps'
               return
            end if
         end do
         if (given > 0) settings%axis(a)%given_values = list(1:given)
         settings%axis(a)%range_given = reader%scanned%is_given('sweep', 'from'//suffix) .or. &
                                        reader%scanned%is_given('sweep', 'to'//suffix) .or. &
                                        reader%scanned%is_given('sweep', 'count'//suffix)
         if (settings%axis(a)%range_given .and. .not. (reader%scanned%is_given('sweep', 'from'//suffix) .and. &
                                                       reader%scanned%is_given('sweep', 'to'//suffix))) then
            stat = stat_failure
            errmsg = '&sweep: a range needs from'//suffix//' and to'//suffix//' (and count'//suffix//')'
            return
         end if
         settings%axis(a)%from = first
         settings%axis(a)%to = last
         settings%axis(a)%count = max(number, 0)
         settings%axis(a)%spacing = kind
      end subroutine axis_values
   end subroutine read_sweep
end module vibrobeam_scene_read
