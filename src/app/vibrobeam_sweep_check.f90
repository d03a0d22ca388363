!> What `vibrobeam --check` prints for a sweep (docs/sweeps.md, "Checking a sweep"): the
!! points in the order they run, with their line, direction, start and windows; the cost
!! (steps in all, and a wall-time estimate from timing a few steps of the first point);
!! what runs in parallel; and the resolution advice for the statistics.
module vibrobeam_sweep_check
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_setup, only: prepared_scene, prepare_scene, start_time_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_resolution_advice, only: resolution_advice_text, advice_time_step
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, sweep_points, point_scene, point_windows, &
      task_count, max_settle_windows
   implicit none
   private
   public :: sweep_check_text, resolution_advice

   !> The cost estimate times steps of the first point after `warm_up_steps`, for at least
   !! `timed_seconds` of wall time or `timed_steps` steps.
   integer, parameter :: warm_up_steps = 50, timed_steps = 20000
   real(dp), parameter :: timed_seconds = 0.05_dp

contains

   !> The --check report of a resolved sweep; `threads` and `ranks` as the run would use.
   function sweep_check_text(scene, settings, threads, ranks) result(text)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      integer, intent(in) :: threads, ranks
      character(len=:), allocatable :: text
      type(sweep_point), allocatable :: points(:)
      type(scene_type) :: local
      integer(int64) :: settle_steps, measure_steps, total_steps
      integer :: k, stat, tasks, workers
      real(dp) :: seconds_per_step
      character(len=256) :: errmsg
      character(len=32) :: direction, start
      allocate (points, source=sweep_points(settings))
      tasks = task_count(points)
      text = 'sweep of '//trim(settings%axis(1)%parameter)
      if (len_trim(settings%axis(2)%parameter) > 0) text = text//' x '//trim(settings%axis(2)%parameter)// &
                                                           ' ('//integer_text(size(settings%axis(2)%values))//' lines)'
      text = text//', mode '''//trim(settings%mode)//''': '//integer_text(size(points))//' points in '// &
             integer_text(tasks)//' tasks'//new_line('a')
      text = text//'  point  line  direction  start      '//pad(settings%axis(1)%parameter, 22)
      if (len_trim(settings%axis(2)%parameter) > 0) text = text//pad(settings%axis(2)%parameter, 22)
      text = text//'  settle (s)    measure (s)'//new_line('a')
      total_steps = 0
      do k = 1, size(points)
         local = point_scene(scene, settings, points(k))
         call point_windows(settings, local, settle_steps, measure_steps, stat, errmsg)
         total_steps = total_steps + settle_steps + measure_steps
         if (settings%steady_tolerance > 0) total_steps = total_steps + (max_settle_windows - 1)*measure_steps
         select case (points(k)%direction)
         case (1)
            direction = 'up'
         case (-1)
            direction = 'down'
         case default
            direction = 'independent'
         end select
         start = 'scene'
         if (points(k)%start_point > 0) start = 'point '//integer_text(points(k)%start_point)
         text = text//'  '//pad(integer_text(k), 7)//pad(integer_text(points(k)%line), 6)//pad(direction, 11)// &
                pad(start, 11)//pad(real_text(points(k)%value(1)), 22)
         if (len_trim(settings%axis(2)%parameter) > 0) text = text//pad(real_text(points(k)%value(2)), 22)
         text = text//pad(real_text(settle_steps*local%time%dt), 14)//real_text(measure_steps*local%time%dt)//new_line('a')
      end do
      if (settings%steady_tolerance > 0) then
         text = text//'steady state: after settle, windows of measure until the RMS tip displacement and the '// &
                'impact rate of two consecutive windows agree within '//real_text(settings%steady_tolerance)// &
                ', at most '//integer_text(max_settle_windows)//' windows'//new_line('a')
      end if
      seconds_per_step = time_per_step(scene, settings, points(1))
      workers = max(1, min(tasks, threads*ranks))
      text = text//'cost: '//real_text(real(total_steps, dp))//' steps in all'
      if (settings%steady_tolerance > 0) text = text//' at most'
      if (seconds_per_step > 0) then
         text = text//', about '//seconds(total_steps*seconds_per_step)//' s of one core ('// &
                seconds(seconds_per_step*1e6_dp)//' us a step of point 1), about '// &
                seconds(total_steps*seconds_per_step/workers)//' s on '//integer_text(workers)//' workers'
      end if
      text = text//new_line('a')
      text = text//'parallel: '//integer_text(tasks)//' independent tasks ('
      if (settings%mode == 'independent') then
         text = text//'one per point'
      else
         text = text//'one per line; the points of a continuation branch run in sequence'
      end if
      text = text//') on '//integer_text(threads)//' threads x '//integer_text(ranks)//' processes'//new_line('a')
      if (settings%keep_runs) text = text//'keep_runs: every point''s result is also written, as '// &
                                     'STEM_pointNNNN.h5 beside '//trim(scene%output%file)//new_line('a')
      text = text//resolution_advice(scene, settings)
   contains
      pure function pad(word, width) result(out)
         character(len=*), intent(in) :: word
         integer, intent(in) :: width
         character(len=max(width, len_trim(word) + 1)) :: out
         out = trim(word)
      end function pad

      !> Three significant digits: '0.0451', '8.54e-4', '1.2e5'.
      function seconds(value) result(out)
         real(dp), intent(in) :: value
         character(len=:), allocatable :: out
         character(len=32) :: buffer
         integer :: decimals
         if (value >= 1e-3_dp .and. value < 1e5_dp) then
            decimals = max(0, 2 - floor(log10(value)))
            write (buffer, '(f0.'//integer_text(decimals)//')') value
            out = trim(adjustl(buffer))
            if (out(1:1) == '.') out = '0'//out
         else
            write (buffer, '(es10.2e1)') value
            out = trim(adjustl(buffer))
         end if
      end function seconds
   end function sweep_check_text

   !> Wall time of one step of the point's scheme (s), timed over a few steps; 0 when the
   !! point cannot be prepared.
   function time_per_step(scene, settings, point) result(seconds)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: point
      real(dp) :: seconds
      type(scene_type) :: local
      type(prepared_scene) :: prepared
      class(time_stepper), allocatable :: stepper
      character(len=:), allocatable :: warnings
      character(len=256) :: errmsg
      integer(int64) :: start, finish, rate
      integer :: stat, n
      seconds = 0
      local = point_scene(scene, settings, point)
      warnings = ''
      call prepare_scene(local, prepared, warnings, stat, errmsg)
      if (stat == 0) call start_time_stepper(local, prepared, stepper, stat, errmsg)
      if (stat /= 0) return
      do n = 1, warm_up_steps
         call stepper%step(stat, errmsg)
         if (stat /= 0) return
      end do
      call system_clock(start, rate)
      do n = 1, timed_steps
         call stepper%step(stat, errmsg)
         if (stat /= 0) exit
         call system_clock(finish)
         if (finish - start >= timed_seconds*rate) exit
      end do
      call system_clock(finish)
      seconds = real(finish - start, dp)/rate/max(1, n)
   end function time_per_step

   !> The resolution advice for the statistics of a sweep (`vibrobeam_resolution_advice`),
   !! for its least resolved point: the one whose dt is largest against the dt the advice
   !! asks for (the parameter may be dt or an input that sets the natural frequencies).
   function resolution_advice(scene, settings) result(text)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      character(len=:), allocatable :: text
      type(sweep_point), allocatable :: points(:)
      type(scene_type) :: local
      real(dp) :: ratio, worst, best
      integer :: k, least
      allocate (points, source=sweep_points(settings))
      least = 1
      worst = -1
      best = huge(1.0_dp)
      do k = 1, size(points)
         local = point_scene(scene, settings, points(k))
         ratio = local%time%dt/advice_time_step(local)
         best = min(best, ratio)
         if (ratio > worst) then
            worst = ratio
            least = k
         end if
      end do
      local = point_scene(scene, settings, points(least))
      if (.not. worst > best) then   ! every point has the same dt against its threshold
         text = resolution_advice_text(local, 'every point of the sweep')
      else
         text = resolution_advice_text(local, 'point '//integer_text(least)//' (the least resolved of the sweep)')
      end if
   end function resolution_advice
end module vibrobeam_sweep_check
