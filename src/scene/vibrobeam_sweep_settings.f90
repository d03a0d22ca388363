!> A parameter sweep (&sweep, docs/sweeps.md): what is varied, its values, the order of
!! the points and which point each one starts from, and each point's scene and windows.
!!
!! Points. With one parameter of values v_1..v_n: mode 'independent' runs the values in
!! the order given, each from the scene's initial state; 'up' runs them in increasing
!! order, 'down' in decreasing order, each point from the final state of the one before
!! (the first from the scene's initial state); 'up-down' runs the 'up' branch, then the
!! 'down' branch over the same values, whose first point starts from the up branch's last
!! state. With a second parameter of values w_1..w_m, each w_j is one line: the same
!! points of the first parameter with w_j set (in 'independent' mode every point of every
!! line starts from the scene's initial state). A task is what must run in sequence: one
!! point in 'independent' mode, one line otherwise.
!!
!! Windows of a point: a transient of `settle` seconds (or `settle_periods` periods
!! 2 pi/Omega of the point's forcing frequency, `forcing_of`), then a measurement window of
!! `measure` seconds (or `measure_periods` periods), both rounded to whole steps. A point's
!! scene is the base scene with the parameters set, t_end = (settle + measure) steps,
!! measure_from = settle steps.
module vibrobeam_sweep_settings
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_sorting, only: sorted
   use vibrobeam_scene, only: scene_type, scene_variables, validate_scene, max_obstacles, max_sweep_values, &
      parameter_length, forcing_of, keyword_length
   use vibrobeam_namelist_schema, only: namelist_variable, kind_real, range_text, variable_index, choices_text
   use vibrobeam_namelist_tokens, only: lowercase
   use vibrobeam_scene_values, only: real_input, set_real_input
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_obstacles, only: build_contact_points
   implicit none
   private
   public :: sweep_settings, sweep_axis, sweep_point, resolve_sweep, sweep_points, point_scene, point_windows
   public :: max_settle_windows, max_sweep_points, task_count

   !> Most points of a sweep (values x values2, and twice that for 'up-down').
   integer, parameter :: max_sweep_points = 100000
   !> With steady_tolerance > 0: most windows measured after the transient before a point
   !! is reported as not settled (the transient is then settle + (max - 1) windows).
   integer, parameter :: max_settle_windows = 20

   !> One axis: the parameter as written, what it names, and its values.
   type :: sweep_axis
      character(len=parameter_length) :: parameter = ''   !! 'group.variable' or 'group.variable(i)', lower case
      character(len=16) :: group = ''
      character(len=32) :: name = ''
      integer :: index = 1                  !! array element (1 for a scalar)
      character(len=16) :: unit = ''
      ! as given
      real(dp), allocatable :: given_values(:)
      logical :: range_given = .false.      !! from, to (and count) given
      real(dp) :: from = 0, to = 0
      integer :: count = 0
      character(len=keyword_length) :: spacing = 'linear'
      ! resolved
      real(dp), allocatable :: values(:)    !! in the order given (a range: from .. to)
   end type sweep_axis

   type :: sweep_settings
      logical :: present = .false.          !! the input has a &sweep group
      type(sweep_axis) :: axis(2)           !! axis(2)%parameter == '': one parameter
      character(len=keyword_length) :: mode = 'independent'
      real(dp) :: settle = 0, measure = 0, settle_periods = 0, measure_periods = 0
      real(dp) :: steady_tolerance = 0
      logical :: keep_runs = .false.
      ! inputs whose default follows another input (docs/sweeps.md, "The parameter")
      logical :: point_position_given = .true.
      logical :: x_from_given(max_obstacles) = .true., x_to_given(max_obstacles) = .true., &
                 level_to_given(max_obstacles) = .true.
   end type sweep_settings

   !> One point of the sweep.
   type :: sweep_point
      integer :: line = 1                   !! index of the value of parameter 2 (1 without it)
      integer :: direction = 0              !! +1 up, -1 down, 0 independent
      integer :: start_point = 0            !! the point whose final state it starts from; 0: the scene's
      integer :: task = 0                   !! points of one task run in sequence
      real(dp) :: value(2) = 0              !! parameter values (value(2) = 0 without parameter 2)
   end type sweep_point

contains

   !> Resolve the parameters against the scene's inputs (`scene_variables`), build the
   !! values, and check every point: its scene must be valid, hold as many contact points
   !! as the first, and its windows at least one step. stat = 1 with a message naming
   !! &sweep and the value otherwise.
   subroutine resolve_sweep(settings, scene, stat, errmsg)
      type(sweep_settings), intent(inout) :: settings
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(sweep_point), allocatable :: points(:)
      type(scene_type) :: trial
      type(beam_model) :: model
      type(contact_set) :: contacts
      character(len=:), allocatable :: warnings
      integer(int64) :: settle_steps, measure_steps, total
      integer :: k, a, contact_count
      logical :: same_model, same_contacts
      stat = 0
      errmsg = ''
      if (scene%analysis%kind /= 'dynamics') then
         call fail('&sweep needs &analysis kind = ''dynamics'' (kind = '''//trim(scene%analysis%kind)//''')')
         return
      end if
      call check_keyword('mode', settings%mode)
      call check_keyword('spacing', settings%axis(1)%spacing)
      call check_keyword('spacing2', settings%axis(2)%spacing)
      if (stat /= 0) return
      do a = 1, 2
         if (a == 2 .and. len_trim(settings%axis(2)%parameter) == 0) then
            if (allocated(settings%axis(2)%given_values) .or. settings%axis(2)%range_given) then
               call fail('&sweep values2/from2/to2 are given but parameter2 is not: name the second parameter')
               return
            end if
            allocate (settings%axis(2)%values(0))
            cycle
         end if
         call resolve_axis(settings%axis(a), a)
         if (stat /= 0) return
      end do
      if (len_trim(settings%axis(2)%parameter) > 0 .and. settings%axis(2)%parameter == settings%axis(1)%parameter) then
         call fail('&sweep parameter2 = '''//trim(settings%axis(2)%parameter)//''' is parameter itself: '// &
                   'a map needs two different inputs')
         return
      end if
      if (settings%mode /= 'independent' .and. trim(settings%axis(1)%group)//'.'//trim(settings%axis(1)%name) == 'time.dt') then
         call fail('&sweep parameter = ''time.dt'' with mode = '''//trim(settings%mode)//''': a continuation '// &
                   'carries the state from one time step to another; use mode = ''independent''')
         return
      end if
      if (settings%measure <= 0 .and. settings%measure_periods <= 0) then
         call fail('&sweep: give the measurement window, measure (s) or measure_periods (> 0)')
      else if (settings%measure > 0 .and. settings%measure_periods > 0) then
         call fail('&sweep measure = '//real_text(settings%measure)//' and measure_periods = '// &
                   real_text(settings%measure_periods)//' are both given: give one of them')
      else if (settings%settle > 0 .and. settings%settle_periods > 0) then
         call fail('&sweep settle = '//real_text(settings%settle)//' and settle_periods = '// &
                   real_text(settings%settle_periods)//' are both given: give one of them')
      end if
      if (settings%mode /= 'independent' .and. scene%mesh%reduction /= 'none') then
         ! a continuation point starts from the previous point's state; with a reduced model
         ! that state is in reduced coordinates, whose basis (the cut-off, the modes) may
         ! change with the parameter
         call fail('&sweep mode = '''//trim(settings%mode)//''' carries each point''s state to the next, '// &
                   'which a reduced model (&mesh reduction = '''//trim(scene%mesh%reduction)//''') cannot do: '// &
                   'use mode = ''independent'' or reduction = ''none''')
      end if
      if (stat /= 0) return
      ! (in 64 bits: 65536 x 65536 values make 2^32 points)
      total = int(size(settings%axis(1)%values), int64)*max(1, size(settings%axis(2)%values))
      if (settings%mode == 'up-down') total = 2*total
      if (total > max_sweep_points) then
         warnings = '&sweep: '//integer_text(size(settings%axis(1)%values))//' values'
         if (len_trim(settings%axis(2)%parameter) > 0) &
            warnings = warnings//' x '//integer_text(size(settings%axis(2)%values))//' values2'
         if (settings%mode == 'up-down') warnings = warnings//' x 2 branches'
         call fail(warnings//' make '//real_text(real(total, dp))//' points; at most '// &
                   integer_text(max_sweep_points))
         return
      end if
      allocate (points, source=sweep_points(settings))
      ! the model and the contact points change only with a parameter of &beam, &mesh or
      ! &obstacles: otherwise those of the first point serve every point
      same_model = .not. any(settings%axis%group == 'beam' .or. settings%axis%group == 'mesh')
      same_contacts = same_model .and. .not. any(settings%axis%group == 'obstacles')
      contact_count = -1
      do k = 1, size(points)
         trial = point_scene(scene, settings, points(k))
         call validate_scene(trial, stat, errmsg)
         if (stat == 0) call point_windows(settings, trial, settle_steps, measure_steps, stat, errmsg)
         if (stat == 0 .and. (k == 1 .or. .not. same_model)) &
            call build_model(trial%mesh%basis, trial%mesh%elements, trial%beam%length, trial%beam%rho_s(), trial%beam%ei(), model, &
                             stat, errmsg)
         if (stat == 0 .and. (k == 1 .or. .not. same_contacts)) then
            warnings = ''
            call build_contact_points(trial%obstacles, model, contacts, warnings, stat, errmsg)
         end if
         if (stat == 0 .and. contact_count >= 0 .and. contacts%count /= contact_count) then
            stat = 1
            errmsg = 'the point has '//integer_text(contacts%count)//' contact points and point 1 has '// &
                     integer_text(contact_count)//': a sweep keeps the same contact points (move obstacles '// &
                     'between nodes, not across them)'
         end if
         if (stat /= 0) then
            errmsg = '&sweep point '//integer_text(k)//' ('//point_label(settings, points(k))//'): '//trim(errmsg)
            return
         end if
         contact_count = contacts%count
      end do
   contains
      subroutine fail(message)
         character(len=*), intent(in) :: message
         stat = 1
         errmsg = message
      end subroutine fail

      !> A keyword of &sweep against the choices of its row in `scene_variables`.
      subroutine check_keyword(name, value)
         character(len=*), intent(in) :: name, value
         type(namelist_variable), allocatable :: table(:)
         type(namelist_variable) :: variable
         if (stat /= 0) return
         allocate (table, source=scene_variables())
         variable = table(variable_index(table, 'sweep', name))
         if (index('|'//trim(variable%choices)//'|', '|'//trim(value)//'|') > 0 .and. len_trim(value) > 0) return
         call fail('&sweep '//name//' = '''//trim(value)//''' is not one of '//choices_text(variable))
      end subroutine check_keyword

      !> Name, index and values of axis `a` (1: parameter, 2: parameter2).
      subroutine resolve_axis(axis, a)
         type(sweep_axis), intent(inout) :: axis
         integer, intent(in) :: a
         type(namelist_variable), allocatable :: table(:)
         type(namelist_variable) :: variable
         character(len=:), allocatable :: label, text, suffix
         integer :: open, close, dot, row, k, ios, extent
         real(dp) :: value
         logical :: found
         suffix = merge('  ', '2 ', a == 1)
         label = '&sweep parameter'//trim(suffix)//' = '''//trim(axis%parameter)//''''
         text = lowercase(trim(axis%parameter))
         if (len(text) == 0) then
            call fail('&sweep parameter is missing: name the input to vary, e.g. parameter = ''load.base_frequency''')
            return
         end if
         axis%parameter = text
         dot = index(text, '.')
         open = index(text, '(')
         close = index(text, ')')
         if (dot < 2) then
            call fail(label//' is not of the form ''group.variable'' or ''group.variable(i)''')
            return
         end if
         axis%index = 1
         if (open > 0) then
            if (close /= len(text) .or. close < open + 2) then
               call fail(label//': write the element as ''group.variable(i)''')
               return
            end if
            read (text(open + 1:close - 1), *, iostat=ios) axis%index
            if (ios /= 0 .or. verify(text(open + 1:close - 1), '0123456789') /= 0) then
               call fail(label//': the element '''//text(open + 1:close - 1)//''' is not a whole number')
               return
            end if
            axis%name = text(dot + 1:open - 1)
         else
            axis%name = text(dot + 1:)
         end if
         axis%group = text(1:dot - 1)
         allocate (table, source=scene_variables())
         row = 0
         do k = 1, size(table)
            if (table(k)%group == axis%group .and. table(k)%name == axis%name) row = k
         end do
         if (row == 0 .or. axis%group == 'sweep') then
            call fail(label//' is not an input of vibrobeam (docs/input.md lists them)')
            return
         end if
         variable = table(row)
         axis%unit = variable%unit
         if (variable%kind /= kind_real) then
            call fail(label//' is not a real input: only real values can be swept')
            return
         end if
         select case (trim(axis%group)//'.'//trim(axis%name))
         case ('time.t_end', 'output.measure_from')
            call fail(label//' is set by the sweep itself (settle and measure windows)')
            return
         case ('output.checkpoint_seconds')
            call fail(label//' is wall-clock time, not a property of the scene')
            return
         end select
         extent = variable%extent
         if (extent > 0 .and. open == 0) then
            call fail(label//' is an array: name one element, '''//trim(axis%group)//'.'//trim(axis%name)//'(1)''')
            return
         else if (extent == 0 .and. open > 0) then
            call fail(label//': '//trim(axis%name)//' is not an array')
            return
         end if
         call real_input(scene, axis%group, axis%name, axis%index, value, found)
         if (.not. found) then
            if (axis%group == 'obstacles') then
               call fail(label//': element '//integer_text(axis%index)//' is outside [1, '// &
                         integer_text(size(scene%obstacles))//'], the obstacles of &obstacles count')
            else
               call fail(label//': element '//integer_text(axis%index)//' is outside [1, '// &
                         integer_text(size(scene%output%points))//'], the &output points given')
            end if
            return
         end if
         ! the values
         if (allocated(axis%given_values) .and. axis%range_given) then
            call fail('&sweep values'//trim(suffix)//' and from'//trim(suffix)//'/to'//trim(suffix)// &
                      ' are both given: give the values or a range')
            return
         end if
         if (allocated(axis%given_values)) then
            if (size(axis%given_values) == 0) deallocate (axis%given_values)
         end if
         if (allocated(axis%given_values)) then
            axis%values = axis%given_values
         else if (axis%range_given) then
            if (axis%count < 1) then
               call fail('&sweep count'//trim(suffix)//' is missing: how many values from'//trim(suffix)//' to to'// &
                         trim(suffix)//' (1: from alone)')
               return
            end if
            if (axis%spacing == 'log' .and. (axis%from <= 0 .or. axis%to <= 0)) then
               call fail('&sweep spacing'//trim(suffix)//' = ''log'' with from'//trim(suffix)//' = '// &
                         real_text(axis%from)//' and to'//trim(suffix)//' = '//real_text(axis%to)// &
                         ': both must be > 0')
               return
            end if
            allocate (axis%values(axis%count))
            do k = 1, axis%count
               if (axis%count == 1) then
                  axis%values(k) = axis%from
               else if (k == axis%count) then
                  axis%values(k) = axis%to
               else if (axis%spacing == 'log') then
                  axis%values(k) = axis%from*(axis%to/axis%from)**(real(k - 1, dp)/(axis%count - 1))
               else
                  axis%values(k) = axis%from + (k - 1)*((axis%to - axis%from)/(axis%count - 1))
               end if
            end do
         else
            call fail('&sweep: give values'//trim(suffix)//' or from'//trim(suffix)//', to'//trim(suffix)// &
                      ' and count'//trim(suffix)//' for '//label(8:))
            return
         end if
         ! each value inside the variable's hard range
         do k = 1, size(axis%values)
            value = axis%values(k)
            if (.not. ieee_is_finite(value) .or. value < variable%lowest .or. value > variable%highest .or. &
                (abs(value) > 0 .and. abs(value) < variable%smallest_nonzero)) then
               call fail(label//': value '//integer_text(k)//' = '//real_text(value)//' is outside '// &
                         range_text(variable)//', the range of &'//trim(axis%group)//' '//trim(axis%name))
               return
            end if
         end do
      end subroutine resolve_axis
   end subroutine resolve_sweep

   !> 'load.base_frequency = 150' (and ', obstacles.level_from(2) = 0.001').
   function point_label(settings, point) result(text)
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: point
      character(len=:), allocatable :: text
      text = trim(settings%axis(1)%parameter)//' = '//real_text(point%value(1))
      if (len_trim(settings%axis(2)%parameter) > 0) &
         text = text//', '//trim(settings%axis(2)%parameter)//' = '//real_text(point%value(2))
   end function point_label

   !> Every point of the sweep in the order of its tasks (module documentation).
   function sweep_points(settings) result(points)
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), allocatable :: points(:)
      real(dp), allocatable :: ascending(:)
      integer :: lines, line, k, n, task, filled
      n = size(settings%axis(1)%values)
      lines = max(1, size(settings%axis(2)%values))
      allocate (points(lines*merge(2*n, n, settings%mode == 'up-down')))
      ascending = increasing(settings%axis(1)%values)
      filled = 0
      task = 0
      do line = 1, lines
         select case (settings%mode)
         case ('independent')
            do k = 1, n
               task = task + 1
               call add(settings%axis(1)%values(k), 0, 0)
            end do
         case ('up')
            task = task + 1
            call branch(ascending, 1, 0)
         case ('down')
            task = task + 1
            call branch(ascending(n:1:-1), -1, 0)
         case default   ! 'up-down'
            task = task + 1
            call branch(ascending, 1, 0)
            call branch(ascending(n:1:-1), -1, filled)
         end select
      end do
   contains
      !> A branch over `values` in their order, the first point starting from point `first_start`.
      subroutine branch(values, direction, first_start)
         real(dp), intent(in) :: values(:)
         integer, intent(in) :: direction, first_start
         integer :: j
         do j = 1, size(values)
            if (j == 1) then
               call add(values(j), direction, first_start)
            else
               call add(values(j), direction, filled)
            end if
         end do
      end subroutine branch

      subroutine add(value, direction, start)
         real(dp), intent(in) :: value
         integer, intent(in) :: direction, start
         filled = filled + 1
         points(filled)%line = line
         points(filled)%direction = direction
         points(filled)%start_point = start
         points(filled)%task = task
         points(filled)%value(1) = value
         if (size(settings%axis(2)%values) > 0) points(filled)%value(2) = settings%axis(2)%values(line)
      end subroutine add
   end function sweep_points

   !> `values` in increasing order: as they are or reversed when they are monotone (every
   !! range from, to, count), sorted otherwise (values given one by one, at most
   !! max_sweep_values of them).
   function increasing(values) result(out)
      real(dp), intent(in) :: values(:)
      real(dp), allocatable :: out(:)
      integer :: n
      n = size(values)
      if (all(values(2:) >= values(:n - 1))) then
         out = values
      else if (all(values(2:) <= values(:n - 1))) then
         out = values(n:1:-1)
      else
         allocate (out(n))
         out = sorted(values)
      end if
   end function increasing

   !> Number of tasks of `points`.
   pure integer function task_count(points)
      type(sweep_point), intent(in) :: points(:)
      task_count = 0
      if (size(points) > 0) task_count = maxval(points%task)
   end function task_count


   !> The scene of `point`: the base scene with the parameters set; inputs whose default
   !! follows another one follow it when not given (load.point_position and the
   !! obstacles' x_from follow beam.length, x_to follows x_from, level_to follows
   !! level_from). t_end and measure_from are those of the windows without steady-state
   !! detection; &initial from_file is cleared (a sweep reads it once, docs/sweeps.md).
   function point_scene(scene, settings, point) result(out)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: point
      type(scene_type) :: out
      integer(int64) :: settle_steps, measure_steps
      integer :: a, i, stat
      logical :: found
      character(len=256) :: errmsg
      out = scene
      do a = 1, 2
         if (len_trim(settings%axis(a)%parameter) == 0) cycle
         associate (axis => settings%axis(a))
            call set_real_input(out, axis%group, axis%name, axis%index, point%value(a), found)
         end associate
      end do
      if (.not. (settings%point_position_given .or. swept('load.point_position'))) out%load%point_position = out%beam%length
      do i = 1, size(out%obstacles)
         if (.not. (settings%x_from_given(i) .or. swept('obstacles.x_from', i))) out%obstacles(i)%x_from = out%beam%length
         if (.not. (settings%x_to_given(i) .or. swept('obstacles.x_to', i))) &
            out%obstacles(i)%x_to = out%obstacles(i)%x_from
         if (.not. (settings%level_to_given(i) .or. swept('obstacles.level_to', i))) &
            out%obstacles(i)%level_to = out%obstacles(i)%level_from
      end do
      out%initial%from_file = ''
      call point_windows(settings, out, settle_steps, measure_steps, stat, errmsg)
      if (stat /= 0) return
      out%output%measure_from = settle_steps*out%time%dt
      out%time%t_end = (settle_steps + measure_steps)*out%time%dt
   contains
      !> Input `name` (element `element`) is one of the sweep's parameters.
      logical function swept(name, element)
         character(len=*), intent(in) :: name
         integer, intent(in), optional :: element
         integer :: b
         swept = .false.
         do b = 1, 2
            if (trim(settings%axis(b)%group)//'.'//trim(settings%axis(b)%name) /= name) cycle
            if (present(element)) then
               if (settings%axis(b)%index /= element) cycle
            end if
            swept = .true.
         end do
      end function swept
   end function point_scene

   !> The transient and the measurement window of a point's scene, in steps. stat = 1
   !! when a window in periods has no forcing frequency, or the measurement window is
   !! shorter than a step.
   subroutine point_windows(settings, scene, settle_steps, measure_steps, stat, errmsg)
      type(sweep_settings), intent(in) :: settings
      type(scene_type), intent(in) :: scene
      integer(int64), intent(out) :: settle_steps, measure_steps
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: omega, period, settle, measure
      stat = 0
      errmsg = ''
      settle_steps = 0
      measure_steps = 0
      if (forcing_of(scene, omega) == 'none') omega = 0
      period = 0
      if (omega > 0) period = 2*pi/omega
      if ((settings%settle_periods > 0 .or. settings%measure_periods > 0) .and. omega <= 0) then
         stat = 1
         errmsg = '&sweep settle_periods/measure_periods need a harmonic load (a non-zero amplitude and '// &
                  'frequency): this point has none; give the windows in seconds (settle, measure)'
         return
      end if
      settle = settings%settle
      if (settings%settle_periods > 0) settle = settings%settle_periods*period
      measure = settings%measure
      if (settings%measure_periods > 0) measure = settings%measure_periods*period
      if (settle/scene%time%dt > 1e15_dp .or. measure/scene%time%dt > 1e15_dp) then
         stat = 1
         errmsg = '&sweep: a window of '//real_text(max(settle, measure))//' s makes more than 1e15 steps of dt = '// &
                  real_text(scene%time%dt)//' s'
         return
      end if
      settle_steps = nint(settle/scene%time%dt, int64)
      measure_steps = nint(measure/scene%time%dt, int64)
      if (measure_steps < 1) then
         stat = 1
         errmsg = '&sweep: the measurement window of '//real_text(measure)//' s is shorter than a time step (dt = '// &
                  real_text(scene%time%dt)//' s)'
      end if
   end subroutine point_windows
end module vibrobeam_sweep_settings
