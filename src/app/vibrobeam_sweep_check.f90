!> The checks of a sweep before it runs, and what `vibrobeam --check` prints for it
!! (docs/sweeps.md, "Checking a sweep").
!!
!! `check_sweep_files`, for a run and for --check alike: the files a sweep writes or
!! removes (its point files 'STEM_pointNNNN.h5', those of an earlier set that it removes,
!! its partial directory, its text files) must not be the input file nor the file
!! &initial from_file continues, and a point file's name must not be a directory; the
!! start state of &initial from_file must fit the first point's scene; the partial
!! directory must not hold a sweep of another input; and what the sweep writes (its file,
!! its journals and, with keep_runs, every point's result over the point's own windows)
!! must fit the size limit and the free space. Failures are invalid input (exit status 2).
!!
!! `write_sweep_check`: the points in the order they run, with their line, direction,
!! start and windows; the cost (steps in all, and a CPU-time estimate from timing steps
!! of the first point, `step_cost`); the result size (`estimate_sweep_size`); what runs
!! in parallel; what a run finds in the partial directory; and the resolution advice for
!! the statistics. Written line by line, so the time is linear in the number of points.
module vibrobeam_sweep_check
   use vibrobeam_status, only: stat_invalid_input
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_filesystem, only: file_exists
   use vibrobeam_namelist_tokens, only: abbreviated
   use vibrobeam_resolution_advice, only: resolution_advice_text, advice_time_step
   use vibrobeam_output_target, only: max_result_bytes, real_path, resolve_directory, split_path, join, bytes_text, &
      free_bytes
   use vibrobeam_result_estimate, only: sweep_size, estimate_sweep_size, step_cost
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, sweep_points, point_scene, point_windows, &
      task_count, max_settle_windows
   use vibrobeam_sweep_runner, only: point_file_name
   use vibrobeam_sweep_partial, only: partial_directory
   use vibrobeam_sweep, only: inspect_partial
   implicit none
   private
   public :: write_sweep_check, check_sweep_files, resolution_advice

contains

   !> The checks of the files of a resolved sweep (module documentation); `input_file` as
   !! given on the command line, `contact_points` those of the first point. `resume`: what
   !! a run finds in the partial directory ('' when there is none). stat = stat_invalid_input on a failure.
   subroutine check_sweep_files(scene, settings, input_file, contact_points, resume, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      character(len=*), intent(in) :: input_file
      integer, intent(in) :: contact_points
      character(len=:), allocatable, intent(out) :: resume
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(sweep_point), allocatable :: points(:)
      integer :: done
      resume = ''
      allocate (points, source=sweep_points(settings))
      call check_names(scene, settings, input_file, size(points), stat, errmsg)
      if (stat /= 0) return
      call inspect_partial(scene, settings, done, resume, stat, errmsg)
      if (stat /= 0) then
         stat = stat_invalid_input
         return
      end if
      call check_size(scene, settings, points, contact_points, stat, errmsg)
   end subroutine check_sweep_files

   !> The input file and &initial from_file against every name the sweep writes or removes.
   subroutine check_names(scene, settings, input_file, n, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      character(len=*), intent(in) :: input_file
      integer, intent(in) :: n
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: directory, name, resolved, existing, stem, shown
      integer :: k
      stat = 0
      errmsg = ''
      shown = '&output file = '''//abbreviated(trim(scene%output%file), 60)//''''
      call split_path(trim(scene%output%file), directory, name)
      call resolve_directory(directory, resolved, existing, stat, errmsg)
      if (stat /= 0) then
         errmsg = shown//': '//trim(errmsg)
         stat = stat_invalid_input
         return
      end if
      stem = name
      if (len(stem) > 3) then
         if (stem(len(stem) - 2:) == '.h5') stem = stem(1:len(stem) - 3)
      end if
      call against(input_file, 'the input file')
      if (stat == 0 .and. len_trim(scene%initial%from_file) > 0) call against(trim(scene%initial%from_file), '&initial from_file')
      if (stat /= 0 .or. .not. settings%keep_runs) return
      do k = 1, n
         if (.not. file_exists(point_file_name(trim(scene%output%file), k)//'/')) cycle
         stat = stat_invalid_input
         errmsg = '&sweep keep_runs = .true.: the result file of point '//integer_text(k)//', '''// &
                  abbreviated(point_file_name(trim(scene%output%file), k), 80)//''', is a directory: remove it or give '// &
                  '&output file another name'
         return
      end do
   contains
      !> `path` (the file named by `what`) is none of the sweep's files.
      subroutine against(path, what)
         character(len=*), intent(in) :: path, what
         character(len=:), allocatable :: full, base, partial
         integer :: k
         full = real_path(path)
         if (len(full) == 0) return
         base = full(index(full, '/', back=.true.) + 1:)
         ! a point file: written with keep_runs, removed when an earlier set's
         if (full == join(resolved, base) .and. len(base) > len(stem) + 9) then
            if (base(1:len(stem) + 6) == stem//'_point') then
               k = point_number(base)
               if (k > 0) then
                  stat = stat_invalid_input
                  if (settings%keep_runs .and. k <= n) then
                     errmsg = '&sweep keep_runs = .true. would write the result of point '//integer_text(k)// &
                              ' over '//what//' '''//abbreviated(path, 60)//''''
                     if (path /= base) errmsg = trim(errmsg)//' ('''//base//''')'
                     errmsg = trim(errmsg)//': give &output file another name'
                  else
                     errmsg = shown//': publishing the sweep removes the point files '''//stem// &
                              '_pointNNNN.h5'' beside it that are not part of its set (those of an earlier '// &
                              'sweep), and '//what//' '''//abbreviated(path, 60)//''' is one: give &output file '// &
                              'another name or move the file'
                  end if
                  return
               end if
            end if
         end if
         ! inside the partial directory, which the sweep removes once complete
         partial = join(resolved, name)//'.partial/'
         if (len(full) > len(partial)) then
            if (full(1:len(partial)) == partial) then
               stat = stat_invalid_input
               errmsg = shown//': '//what//' '''//abbreviated(path, 60)//''' is inside the sweep''s partial '// &
                        'directory '''//partial_directory(trim(scene%output%file))//''', which the sweep removes when '// &
                        'it is complete: move the file'
               return
            end if
         end if
         ! the sweep's text files (the input file is checked by check_output_target)
         if (scene%output%text .and. what /= 'the input file') then
            if (full == join(resolved, stem//'_sweep.dat') .or. full == join(resolved, stem//'_poincare.dat')) then
               stat = stat_invalid_input
               errmsg = shown//' would write the text file '''//base//''', which is '//what//': give &output '// &
                        'file another name'
            end if
         end if
      end subroutine against

      !> k when `base` is exactly point_file_name's name of point k (at least 4 digits), else 0.
      integer function point_number(base)
         character(len=*), intent(in) :: base
         character(len=:), allocatable :: digits
         integer :: ios
         point_number = 0
         digits = base(len(stem) + 7:len(base) - 3)
         if (base(len(base) - 2:) /= '.h5' .or. len(digits) < 4 .or. len(digits) > 9) return
         if (verify(digits, '0123456789') /= 0) return
         read (digits, *, iostat=ios) point_number
         if (ios /= 0) point_number = 0
         if (point_number < 1) return
         if (point_file_name(stem//'.h5', point_number) /= base) point_number = 0
      end function point_number
   end subroutine check_names

   !> What the sweep writes against the size limit and the free space: its file and its
   !! journals (both exist when it is published), its text files, and with keep_runs the
   !! result of every point over the point's own windows (with steady_tolerance > 0, the
   !! longest transient it may need): `estimate_sweep_size`'s peak.
   subroutine check_size(scene, settings, points, contact_points, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer, intent(in) :: contact_points
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(sweep_size) :: estimate
      character(len=:), allocatable :: directory, name, resolved, existing
      real(dp) :: free
      stat = 0
      errmsg = ''
      estimate = estimate_sweep_size(scene, settings, points, contact_points)
      call split_path(trim(scene%output%file), directory, name)
      call resolve_directory(directory, resolved, existing, stat, errmsg)
      if (stat /= 0) then
         stat = 0
         errmsg = ''
         return
      end if
      if (estimate%peak_bytes > max_result_bytes) then
         stat = stat_invalid_input
         errmsg = size_message()//', more than the limit of '//bytes_text(max_result_bytes)//size_advice()
      else if (free_bytes(existing, free)) then
         if (estimate%peak_bytes > free) then
            stat = stat_invalid_input
            errmsg = size_message()//', more than the '//bytes_text(free)//' free on the file system of '''// &
                     abbreviated(existing, 60)//''''//size_advice()
         end if
      end if
   contains
      function size_message() result(text)
         character(len=:), allocatable :: text
         text = '&sweep: '//integer_text(size(points))//' points would write about '//bytes_text(estimate%peak_bytes)// &
                ' (the sweep file and its journals '//bytes_text(estimate%sweep_bytes + estimate%journal_bytes)
         if (scene%output%text) text = text//', its text files '//bytes_text(estimate%text_bytes)
         if (settings%keep_runs) text = text//', the points'' result files of keep_runs '//bytes_text(estimate%point_bytes)
         text = text//')'
      end function size_message
      function size_advice() result(text)
         character(len=:), allocatable :: text
         if (settings%keep_runs) then
            text = ': set keep_runs = .false., raise &output every and field_every, or shorten the windows'
         else
            text = ': sweep fewer points, or make room'
         end if
      end function size_advice
   end subroutine check_size

   !> The --check report of a resolved sweep to `unit`; `threads` and `ranks` as the run
   !! would use; `resume` what a run finds in the partial directory ('' when nothing);
   !! `contact_points` those of the first point.
   subroutine write_sweep_check(unit, scene, settings, threads, ranks, resume, contact_points)
      integer, intent(in) :: unit
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      integer, intent(in) :: threads, ranks
      character(len=*), intent(in) :: resume
      integer, intent(in) :: contact_points
      type(sweep_point), allocatable :: points(:)
      integer(int64) :: total_steps, least_steps
      character(len=:), allocatable :: line
      allocate (points, source=sweep_points(settings))
      line = 'sweep of '//trim(settings%axis(1)%parameter)
      if (len_trim(settings%axis(2)%parameter) > 0) line = line//' x '//trim(settings%axis(2)%parameter)// &
                                                           ' ('//integer_text(size(settings%axis(2)%values))//' lines)'
      write (unit, '(a)') line//', mode '''//trim(settings%mode)//''': '//integer_text(size(points))//' points in '// &
         integer_text(task_count(points))//' tasks'
      call write_point_table(unit, scene, settings, points, total_steps, least_steps)
      if (scene%analysis%kind == 'periodic') then
         write (unit, '(a)') 'each point: the periodic analysis of its scene (above), exactly as a single run of '// &
            'that scene; its cost is that run''s (not estimated here); its result is its point file'
      else if (settings%steady_tolerance > 0) then
         write (unit, '(a)') 'steady state: after settle, windows of measure until the RMS tip displacement and the '// &
            'impact rate of two consecutive windows agree within '//real_text(settings%steady_tolerance)// &
            ', at most '//integer_text(max_settle_windows)//' windows'
      end if
      if (scene%analysis%kind /= 'periodic') &
         call write_cost(unit, scene, settings, points, total_steps, least_steps, threads, ranks)
      call write_result_size(unit, scene, settings, points, contact_points)
      call write_parallel(unit, settings, points, threads, ranks)
      if (settings%keep_runs) write (unit, '(a)') 'keep_runs: every point''s result is also written, as '// &
         'STEM_pointNNNN.h5 beside '//trim(scene%output%file)//', published with it as one set'
      if (len(resume) > 0) then
         write (unit, '(a)') resume
      else
         write (unit, '(a)') 'partial directory: none; a run streams its points into '''// &
            partial_directory(trim(scene%output%file))//''' (rerunning this input after a kill goes on from there)'
      end if
      ! (the advice is about the statistics of time marching)
      if (scene%analysis%kind /= 'periodic') write (unit, '(a)', advance='no') resolution_advice(scene, settings)
   end subroutine write_sweep_check

   !> The points in the order they run, one line each: line, direction, start, values
   !! and windows; `total_steps` the steps of them all and `least_steps` the fewest (with
   !! steady_tolerance > 0, at most `max_settle_windows` windows a point, at least two:
   !! the first comparison).
   subroutine write_point_table(unit, scene, settings, points, total_steps, least_steps)
      integer, intent(in) :: unit
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer(int64), intent(out) :: total_steps, least_steps
      type(scene_type) :: local
      integer(int64) :: settle_steps, measure_steps
      integer :: k, stat
      character(len=256) :: errmsg
      character(len=32) :: direction, start
      character(len=:), allocatable :: line, settle_text, measure_text
      integer(int64) :: settle_shown, measure_shown   ! bits of the windows whose text is made
      line = '  point  line  direction  start      '//pad(settings%axis(1)%parameter, 22)
      if (len_trim(settings%axis(2)%parameter) > 0) line = line//pad(settings%axis(2)%parameter, 22)
      if (scene%analysis%kind /= 'periodic') line = line//'  settle (s)    measure (s)'
      write (unit, '(a)') trim(line)
      total_steps = 0
      least_steps = 0
      settle_shown = transfer(-1.0_dp, 1_int64)
      measure_shown = settle_shown
      do k = 1, size(points)
         local = point_scene(scene, settings, points(k))
         settle_steps = 0
         measure_steps = 0
         if (local%analysis%kind /= 'periodic') &
            call point_windows(settings, local, settle_steps, measure_steps, stat, errmsg)
         total_steps = total_steps + settle_steps + measure_steps
         least_steps = least_steps + settle_steps + measure_steps
         if (settings%steady_tolerance > 0) then
            ! at most max_settle_windows windows; at least two, the first comparison
            total_steps = total_steps + (max_settle_windows - 1)*measure_steps
            least_steps = least_steps + measure_steps
         end if
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
         line = '  '//pad(integer_text(k), 7)//pad(integer_text(points(k)%line), 6)//pad(direction, 11)// &
                pad(start, 11)//pad(real_text(points(k)%value(1)), 22)
         if (len_trim(settings%axis(2)%parameter) > 0) line = line//pad(real_text(points(k)%value(2)), 22)
         ! (windows in seconds are the same at every point: their text is made once)
         if (transfer(settle_steps*local%time%dt, 1_int64) /= settle_shown) then
            settle_shown = transfer(settle_steps*local%time%dt, 1_int64)
            settle_text = pad(real_text(settle_steps*local%time%dt), 14)
         end if
         if (transfer(measure_steps*local%time%dt, 1_int64) /= measure_shown) then
            measure_shown = transfer(measure_steps*local%time%dt, 1_int64)
            measure_text = real_text(measure_steps*local%time%dt)
         end if
         if (local%analysis%kind == 'periodic') then
            write (unit, '(a)') trim(line)
         else
            write (unit, '(a)') line//settle_text//measure_text
         end if
      end do
   end subroutine write_point_table

   !> The cost: the steps in all (at most `total_steps`, at least `least_steps` with
   !! steady_tolerance > 0) and the CPU time they take on one core and on the workers that
   !! will run, from `step_cost` of the first point (docs/sweeps.md, "Checking a sweep").
   subroutine write_cost(unit, scene, settings, points, total_steps, least_steps, threads, ranks)
      integer, intent(in) :: unit
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer(int64), intent(in) :: total_steps, least_steps
      integer, intent(in) :: threads, ranks
      character(len=:), allocatable :: line
      real(dp) :: seconds_per_step
      integer :: workers
      seconds_per_step = step_cost(point_scene(scene, settings, points(1)))
      workers = max(1, min(task_count(points), threads*ranks))
      line = 'cost: '//real_text(real(total_steps, dp))//' steps in all'
      if (settings%steady_tolerance > 0) line = line//' at most (at least '//real_text(real(least_steps, dp))// &
                                                ', every point settled at its first comparison)'
      if (seconds_per_step > 0) then
         line = line//', about '//seconds(total_steps*seconds_per_step)//' s of CPU on one core ('// &
                seconds(seconds_per_step*1e6_dp)//' us a step of point 1), about '// &
                seconds(total_steps*seconds_per_step/workers)//' s on '//integer_text(workers)//' workers'
         if (settings%steady_tolerance > 0) line = line//' at most (at least '// &
                                                   seconds(least_steps*seconds_per_step/workers)//' s)'
      end if
      write (unit, '(a)') line
   end subroutine write_cost

   !> The result size (`estimate_sweep_size`): the sweep file, its text files and the
   !! points' result files of keep_runs; apart, the journals that exist while it runs.
   subroutine write_result_size(unit, scene, settings, points, contact_points)
      integer, intent(in) :: unit
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer, intent(in) :: contact_points   !! of the first point
      type(sweep_size) :: estimate
      character(len=:), allocatable :: line
      estimate = estimate_sweep_size(scene, settings, points, contact_points)
      line = 'estimated result size: '//real_text(real(nint(estimate%total_bytes, int64), dp))// &
             ' bytes (the sweep file '//bytes_text(estimate%sweep_bytes)
      if (scene%output%text) line = line//', its text files '//bytes_text(estimate%text_bytes)
      if (settings%keep_runs) line = line//', the points'' result files '//bytes_text(estimate%point_bytes)
      write (unit, '(a)') line//'); while it runs, its journals take about '//bytes_text(estimate%journal_bytes)// &
         ' more'
   end subroutine write_result_size

   !> What runs in parallel: the tasks, on `threads` threads x `ranks` processes.
   subroutine write_parallel(unit, settings, points, threads, ranks)
      integer, intent(in) :: unit
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer, intent(in) :: threads, ranks
      character(len=:), allocatable :: line
      line = 'parallel: '//integer_text(task_count(points))//' independent tasks ('
      if (settings%mode == 'independent') then
         line = line//'one per point'
      else
         line = line//'one per line; the points of a continuation branch run in sequence'
      end if
      write (unit, '(a)') line//') on '//integer_text(threads)//' threads x '//integer_text(ranks)//' processes'
   end subroutine write_parallel

   !> `word` left-aligned in `width` characters (at least one blank after it).
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
