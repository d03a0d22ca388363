!> The points of a parameter sweep (&sweep, docs/sweeps.md): the order of the points and
!! which point each one starts from, and each point's scene and windows.
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
module vibrobeam_sweep_points
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text, only: real_text
   use vibrobeam_sorting, only: sorted
   use vibrobeam_scene, only: scene_type, max_obstacles, forcing_of, keyword_length
   use vibrobeam_scene_values, only: set_real_input
   use vibrobeam_sweep_axis, only: sweep_axis
   implicit none
   private
   public :: sweep_settings, sweep_point, sweep_points, point_scene, point_windows, point_label
   public :: max_settle_windows, max_sweep_points, task_count

   !> Most points of a sweep (values x values2, and twice that for 'up-down').
   integer, parameter :: max_sweep_points = 100000
   !> With steady_tolerance > 0: most windows measured after the transient before a point
   !! is reported as not settled (the transient is then settle + (max - 1) windows).
   integer, parameter :: max_settle_windows = 20

   !> A sweep as given in &sweep (`vibrobeam_scene_read`), its axes resolved by
   !! `resolve_sweep` (`vibrobeam_sweep_settings`).
   type :: sweep_settings
      logical :: present = .false.          !! the input has a &sweep group
      type(sweep_axis) :: axis(2)           !! axis(2)%parameter == '': one parameter
      character(len=keyword_length) :: mode = 'independent'
      real(dp) :: settle = 0, measure = 0, settle_periods = 0, measure_periods = 0
      real(dp) :: steady_tolerance = 0
      logical :: keep_runs = .false.
      !> 'latest': the last `kept_samples` Poincare samples of each point's window go into
      !! the sweep file; 'all': every one, streamed into the journal while the point runs
      character(len=keyword_length) :: poincare_samples = 'latest'
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

   !> The transient and the measurement window of a point's scene, in steps. stat = stat_failure
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
         stat = stat_failure
         errmsg = '&sweep settle_periods/measure_periods need a harmonic load (a non-zero amplitude and '// &
                  'frequency): this point has none; give the windows in seconds (settle, measure)'
         return
      end if
      settle = settings%settle
      if (settings%settle_periods > 0) settle = settings%settle_periods*period
      measure = settings%measure
      if (settings%measure_periods > 0) measure = settings%measure_periods*period
      if (settle/scene%time%dt > 1e15_dp .or. measure/scene%time%dt > 1e15_dp) then
         stat = stat_failure
         errmsg = '&sweep: a window of '//real_text(max(settle, measure))//' s makes more than 1e15 steps of dt = '// &
                  real_text(scene%time%dt)//' s'
         return
      end if
      settle_steps = nint(settle/scene%time%dt, int64)
      measure_steps = nint(measure/scene%time%dt, int64)
      if (measure_steps < 1) then
         stat = stat_failure
         errmsg = '&sweep: the measurement window of '//real_text(measure)//' s is shorter than a time step (dt = '// &
                  real_text(scene%time%dt)//' s)'
      end if
   end subroutine point_windows
end module vibrobeam_sweep_points
