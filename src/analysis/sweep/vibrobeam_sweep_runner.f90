!> Running the points of a sweep (docs/sweeps.md): each task (one point in 'independent'
!! mode, one line of points otherwise) runs its points in order, each from the scene's
!! initial state or from the final state of the point before it; tasks are independent
!! and run in parallel, on the threads of this process (OpenMP) and, in an MPI build, over
!! the ranks (`vibrobeam_sweep_transport`).
!!
!! A point: its scene (`point_scene`) is prepared like a single run's; it starts from the
!! scene's initial state or from the state (U, V and, for the position scheme, U^{n-1}) a
!! point before it ended in, at t = 0; it runs its transient, then its measurement window
!! (with steady_tolerance > 0, window after window until two consecutive ones agree), and
!! its statistics are those of a single run with the same scene and window
!! (`run_statistics`). Without keep_runs nothing is written: the recorder only decides
!! impacts and episodes and feeds the statistics. With keep_runs the point's full result
!! is written by `run_dynamics` (the same loop as a single run) into the sweep's partial
!! directory (`kept_point_file`), published with the sweep file at the end.
!!
!! Each point's result goes to a `point_sink` as soon as the point ends (the sweep's
!! journal), so nothing accumulates here. With &sweep poincare_samples = 'all' its
!! Poincare samples go there while it runs, `chunk_rows` at a time (`sample_stream`; with
!! keep_runs, read back from its point file in such chunks). A point that fails (contact solver, non-finite
!! state, a start its scene refuses) is marked failed with the reason; the next point of
!! its task starts from the last point that succeeded (the scene's initial state if none
!! did). After SIGINT/SIGTERM the point in progress stops (status 'interrupted', its
!! statistics so far) and the points not started are not run. A point of &analysis kind =
!! 'periodic' is its scene's periodic analysis (`run_periodic_point`), its result always
!! a point file. A point file that cannot be
!! written is an I/O error: the task stops with stat /= 0 (the sweep fails, exit status 1).
module vibrobeam_sweep_runner
   use vibrobeam_status, only: stat_failure, outcome_failed, outcome_interrupted
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, build_problem, new_stepper
   use vibrobeam_stepper_factory, only: release_stepper
   use vibrobeam_time_stepper, only: time_stepper, dynamic_state
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_dynamics, only: run_dynamics
   use vibrobeam_result_files, only: run_outcome
   use vibrobeam_periodic_run, only: run_periodic_kind
   use vibrobeam_state_record, only: state_record
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_statistics, only: statistics_result
   use vibrobeam_statistics_layout, only: group_points, group_beam
   use vibrobeam_signals, only: interrupt_requested
   use vibrobeam_run_loop, only: advance, run_hooks
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_filesystem, only: file_exists
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, point_scene, point_windows, max_settle_windows
   ! (the point's result and names, re-exported: the sweep's other modules take them from here)
   use vibrobeam_sweep_point_result, only: point_result, point_file_name, kept_point_file, point_digits, status_ok, &
      status_failed, status_interrupted, status_not_run, status_names, chunk_rows
   implicit none
   private
   public :: point_result, task_start, point_sink, run_task, point_file_name, kept_point_file, point_digits
   public :: status_ok, status_failed, status_interrupted, status_not_run, status_names, chunk_rows

   !> Where a task starts: its first point to run (the points before it are done), the
   !! last point before it that succeeded (0: none) and that point's final state.
   type :: task_start
      integer :: first_to_run = 0
      integer :: last_good_point = 0
      type(dynamic_state) :: state
   end type task_start

   !> What takes each point's result as it ends (the sweep's journal). `take` may be
   !! called from several threads; `halted` is true once the sweep must stop (an I/O
   !! error in another task).
   type, abstract :: point_sink
   contains
      procedure(take_point), deferred :: take
      procedure(take_point_samples), deferred :: take_samples
      procedure(sink_halted), deferred :: halted
   end type point_sink

   abstract interface
      !> Point k of task `task` ended with `result`; `final` its final state (when it
      !! succeeded); `point_file`: its keep_runs file was written.
      subroutine take_point(self, k, task, result, final, point_file, stat, errmsg)
         import :: point_sink, point_result, dynamic_state
         class(point_sink), intent(inout) :: self
         integer, intent(in) :: k, task
         type(point_result), intent(in) :: result
         type(dynamic_state), intent(in) :: final
         logical, intent(in) :: point_file
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine take_point
      !> Poincare samples of point k (a column each: time, u then v at each observation
      !! point), after those it handed before; may be called from several threads.
      subroutine take_point_samples(self, k, rows, stat, errmsg)
         import :: point_sink, dp
         class(point_sink), intent(inout) :: self
         integer, intent(in) :: k
         real(dp), intent(in) :: rows(:, :)
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine take_point_samples
      logical function sink_halted(self)
         import :: point_sink
         class(point_sink), intent(in) :: self
      end function sink_halted
   end interface

   !> What a point does after each step with poincare_samples = 'all': the Poincare
   !! samples that fell in the step into `rows`, handed to the sink as a chunk when full.
   type, extends(run_hooks) :: sample_stream
      class(point_sink), pointer :: sink => null()
      integer :: point = 0, count = 0
      integer(int64) :: written = 0
      real(dp), allocatable :: rows(:, :)   !! (1 + 2 observation points, chunk_rows)
   contains
      procedure :: after_step => stream_samples
      procedure :: flush => flush_samples
   end type sample_stream

contains

   !> Run the points first .. last of task `task` (points(first:last), in order) from
   !! `start` and hand each result to `sink`. `base` is the start state of &initial
   !! from_file (given = .false. without one); `directory` the partial directory, where
   !! keep_runs files go. stat /= 0: an I/O error (a point file or the sink), the task
   !! stopped.
   subroutine run_task(scene, settings, points, task, first, last, base, start, directory, sink, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer, intent(in) :: task, first, last
      type(dynamic_state), intent(in) :: base
      type(task_start), intent(in) :: start
      character(len=*), intent(in) :: directory
      class(point_sink), intent(inout), target :: sink
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(dynamic_state) :: last_good, final
      integer :: k, last_good_point
      logical :: written
      stat = 0
      errmsg = ''
      if (start%first_to_run < first .or. start%first_to_run > last) return
      last_good_point = start%last_good_point
      if (last_good_point > 0) last_good = start%state
      do k = start%first_to_run, last
         if (interrupt_requested() .or. sink%halted()) exit
         one_point: block
            type(point_result) :: result   ! a new one for each point
            if (points(k)%start_point == 0 .or. last_good_point == 0) then
               call run_point(scene, settings, k, points(k), base, 0, directory, sink, result, final, written, stat, &
                              errmsg)
            else
               call run_point(scene, settings, k, points(k), last_good, last_good_point, directory, sink, result, final, &
                              written, stat, errmsg)
            end if
            if (stat /= 0) return
            call sink%take(k, task, result, final, written, stat, errmsg)
            if (stat /= 0) return
            if (result%status == status_ok) then
               call move_state(final, last_good)
               last_good_point = k
            end if
         end block one_point
      end do
   end subroutine run_task

   subroutine move_state(from, to)
      type(dynamic_state), intent(inout) :: from, to
      to%step = from%step
      if (allocated(to%u)) deallocate (to%u)
      if (allocated(to%v)) deallocate (to%v)
      if (allocated(to%extra)) deallocate (to%extra)
      if (allocated(from%u)) call move_alloc(from%u, to%u)
      if (allocated(from%v)) call move_alloc(from%v, to%v)
      if (allocated(from%extra)) call move_alloc(from%extra, to%extra)
   end subroutine move_state

   !> One point (module documentation): its result, and its final state in `final`;
   !! `written`: its keep_runs file is in `directory`. io_stat /= 0 (with io_message): the
   !! point file could not be written.
   subroutine run_point(scene, settings, k, point, start, start_point, directory, sink, result, final, written, &
                        io_stat, io_message)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      integer, intent(in) :: k, start_point
      type(sweep_point), intent(in) :: point
      type(dynamic_state), intent(in) :: start
      character(len=*), intent(in) :: directory
      class(point_sink), intent(inout), target :: sink
      type(point_result), intent(inout) :: result
      type(dynamic_state), intent(out) :: final
      logical, intent(out) :: written
      integer, intent(out) :: io_stat
      character(len=*), intent(out) :: io_message
      type(scene_type) :: local
      type(run_problem) :: prepared
      character(len=:), allocatable :: warnings
      character(len=512) :: errmsg
      integer(int64) :: clock_start, clock_end, rate, transient
      integer :: stat, windows
      type(sample_stream), allocatable :: stream
      written = .false.
      io_stat = 0
      io_message = ''
      call system_clock(clock_start, rate)
      local = point_scene(scene, settings, point)
      local%output%progress = .false.
      result%dt = local%time%dt
      result%start_point = start_point
      if (local%analysis%kind == 'periodic') then
         call run_periodic_point()
         call system_clock(clock_end)
         result%wall_seconds = real(clock_end - clock_start, dp)/rate
         return
      end if
      call point_windows(settings, local, result%settle_steps, result%measure_steps, stat, errmsg)
      warnings = ''
      if (stat == 0) call build_problem(local, prepared, warnings, stat, errmsg)
      if (stat /= 0) then
         call failed('the point''s initial state: '//trim(errmsg))
         return
      end if
      if (allocated(start%u)) call take_start()
      transient = result%settle_steps
      if (settings%poincare_samples == 'all' .and. .not. settings%keep_runs) then
         ! the samples of a point without a file go to the sink while it runs
         allocate (stream)
         stream%sink => sink
         stream%point = k
         allocate (stream%rows(1 + 2*(1 + size(local%output%points)), chunk_rows))
      end if
      if (settings%steady_tolerance > 0) then
         call measure_until_steady()
         if (stat /= 0 .or. result%status /= status_ok) then
            call hand_on_samples()
            return
         end if
      end if
      if (settings%keep_runs) then
         call run_with_file()
      else if (settings%steady_tolerance <= 0) then
         call run_without_file()
      end if
      call hand_on_samples()
      call system_clock(clock_end)
      result%wall_seconds = real(clock_end - clock_start, dp)/rate
   contains
      subroutine failed(message)
         character(len=*), intent(in) :: message
         result%status = status_failed
         result%message = message
      end subroutine failed

      !> Start from `start` unless its displacement violates this point's obstacles (an
      !! obstacle moved by the sweep): then from the scene's initial state, as noted.
      subroutine take_start()
         real(dp) :: value, tolerance
         logical :: outside
         integer :: c
         tolerance = 1e-12_dp*prepared%model%length
         outside = .false.
         do c = 1, prepared%contacts%count
            value = contact_value(prepared%contacts, c, start%u)
            outside = outside .or. value + tolerance < prepared%contacts%lower(c) .or. &
                      value - tolerance > prepared%contacts%upper(c)
         end do
         do c = 1, prepared%circles%count   ! a beam of two planes: the walls of its holes and levels
            outside = outside .or. prepared%circles%penetration(c, start%u) > tolerance
         end do
         if (outside) then
            result%start_point = 0
            result%message = 'started from the scene''s initial state: the state of point '// &
                             integer_text(start_point)//' violates this point''s obstacles'
            return
         end if
         ! the stepper starts there (the scheme's extra with it: the scheme is the sweep's)
         prepared%start%u = start%u
         prepared%start%v = start%v
         if (allocated(start%extra)) prepared%start%extra = start%extra
      end subroutine take_start

      !> Step `stepper` (already at `first` or before it) to `last` without writing
      !! anything (the one run loop, `advance`); a failure or an interruption marks the
      !! point.
      subroutine step_to(stepper, recorder, last)
         class(time_stepper), intent(inout) :: stepper
         type(dynamics_recorder), intent(inout) :: recorder
         integer(int64), intent(in) :: last
         integer :: status
         character(len=512) :: failure
         if (allocated(stream)) then
            call advance(stepper, recorder, prepared%model, last, status, failure, stat, errmsg, stream)
         else
            call advance(stepper, recorder, prepared%model, last, status, failure, stat, errmsg)
         end if
         if (stat /= 0) then
            call failed(errmsg)
            return
         end if
         select case (status)
         case (outcome_failed)
            call failed('numerical failure at '//trim(failure))
         case (outcome_interrupted)
            result%status = status_interrupted
            result%message = 'interrupted at t = '//real_text(stepper%steps*local%time%dt)//' s'
         end select
      end subroutine step_to

      !> A stepper at the point's start and a recorder that writes nothing, for at most
      !! `last` steps, its statistics window open; result%status ok, or failed.
      subroutine start_without_file(stepper, recorder, last)
         class(time_stepper), allocatable, intent(out) :: stepper
         type(dynamics_recorder), intent(out) :: recorder
         integer(int64), intent(in) :: last
         character(len=:), allocatable :: ignored
         call new_stepper(local, prepared, stepper, stat, errmsg)
         if (stat /= 0) then
            call failed(errmsg)
            return
         end if
         call recorder%init(local, stepper, prepared, last, write_rows=.false.)
         call recorder%start_statistics(stepper, ignored)
         result%status = status_ok
      end subroutine start_without_file

      !> Without keep_runs and steady-state detection: settle, measure, statistics.
      subroutine run_without_file()
         class(time_stepper), allocatable :: stepper
         type(dynamics_recorder) :: recorder
         call start_without_file(stepper, recorder, transient + result%measure_steps)
         if (result%status /= status_ok) then
            call release_stepper(stepper)
            return
         end if
         call step_to(stepper, recorder, transient + result%measure_steps)
         result%statistics = recorder%window_statistics(stepper)
         call keep_final(stepper)
         call release_stepper(stepper)
      end subroutine run_without_file

      !> steady_tolerance > 0: after the transient, windows of measure_steps until the RMS
      !! tip displacement and the impact rate of two consecutive windows agree within the
      !! tolerance, at most max_settle_windows windows. Sets the transient and the result
      !! (without keep_runs: the statistics of the last window).
      subroutine measure_until_steady()
         class(time_stepper), allocatable :: stepper
         type(dynamics_recorder) :: recorder
         type(statistics_result) :: previous, current
         call start_without_file(stepper, recorder, result%settle_steps + max_settle_windows*result%measure_steps)
         if (result%status /= status_ok) then
            call release_stepper(stepper)
            return
         end if
         result%settled = 0
         do windows = 1, max_settle_windows
            transient = result%settle_steps + (windows - 1)*result%measure_steps
            if (windows > 1) call recorder%restart_statistics(stepper, transient)
            call recorder%restart_wear(transient)
            call step_to(stepper, recorder, transient + result%measure_steps)
            current = recorder%window_statistics(stepper)
            if (result%status /= status_ok) exit
            if (windows > 1) then
               if (agree(previous, current, settings%steady_tolerance)) then
                  result%settled = 1
                  exit
               end if
            end if
            previous = current
         end do
         windows = min(windows, max_settle_windows)
         result%settle_steps = transient
         result%statistics = current
         if (result%status == status_ok .and. .not. settings%keep_runs) call keep_final(stepper)
         call release_stepper(stepper)
      end subroutine measure_until_steady

      !> keep_runs: the point's full result through `run_dynamics`, into `kept_point_file`.
      subroutine run_with_file()
         type(run_outcome) :: outcome
         type(dynamic_state) :: last_state
         local%output%file = kept_point_file(directory, k)
         local%output%text = .false.
         local%output%measure_from = transient*local%time%dt
         local%time%t_end = (transient + result%measure_steps)*local%time%dt
         call run_dynamics(local, prepared, outcome, stat, errmsg, quiet=.true., statistics=result%statistics, &
                           final_state=last_state)
         if (stat /= 0) then
            ! an I/O error, not a property of the point: the sweep stops (exit status 1)
            io_stat = stat_failure
            io_message = '&sweep keep_runs: the result of point '//integer_text(k)//' ('''// &
                         point_file_name(scene%output%file, k)//''') cannot be written: '//trim(errmsg)
            result%status = status_not_run
            return
         end if
         ! run_dynamics renamed the file onto its name; the journal must never name a file
         ! that is not there (a sweep once found one missing when it published its set):
         ! said now, the failure tells when the file went
         if (.not. file_exists(trim(local%output%file))) then
            io_stat = stat_failure
            io_message = '&sweep keep_runs: the result of point '//integer_text(k)//' ('''//trim(local%output%file)// &
                         ''') is not there right after it was published'
            result%status = status_not_run
            return
         end if
         written = .true.
         if (settings%poincare_samples == 'all') then
            call samples_of_file(trim(local%output%file))
            if (io_stat /= 0) return
         end if
         call take_outcome(outcome%status, 'numerical failure at '//trim(outcome%failure))
         if (result%status /= status_ok) return
         call move_state(last_state, final)
      end subroutine run_with_file

      !> The point's status from the run outcome of its file's analysis (`failure`: the
      !! reason, when it failed).
      subroutine take_outcome(status, failure)
         integer, intent(in) :: status
         character(len=*), intent(in) :: failure
         select case (status)
         case (outcome_failed)
            call failed(failure)
         case (outcome_interrupted)
            result%status = status_interrupted
            result%message = 'interrupted'
         case default
            result%status = status_ok
         end select
      end subroutine take_outcome

      !> &analysis kind = 'periodic': the point's orbit or branch, as a single run of its
      !! scene finds it (`run_periodic_kind`, from the scene's own start), published into
      !! `kept_point_file`; its summary in the layout of `init_periodic`. A point whose
      !! analysis cannot run or be written is marked failed with the reason (the sweep goes
      !! on); one that does not converge keeps its file (its last iterate, marked failed).
      subroutine run_periodic_point()
         type(run_outcome) :: outcome
         warnings = ''
         call build_problem(local, prepared, warnings, stat, errmsg)
         if (stat /= 0) then
            call failed('the point''s problem: '//trim(errmsg))
            return
         end if
         local%output%file = kept_point_file(directory, k)
         local%output%text = .false.
         call run_periodic_kind(local, prepared, outcome, stat, errmsg)
         if (stat /= 0) then
            call failed(trim(errmsg))
            return
         end if
         written = file_exists(trim(local%output%file))
         call take_outcome(outcome%status, trim(outcome%failure))
         call result%statistics%layout%init_periodic()
         result%statistics%present = .true.
         result%statistics%values = [outcome%period, outcome%largest_multiplier, real(outcome%newton_iterations, dp), &
                                     real(outcome%branch_points, dp), real(outcome%bifurcations, dp), &
                                     real(outcome%steps, dp)]
         allocate (result%statistics%errors(size(result%statistics%values)), source=0.0_dp)
      end subroutine run_periodic_point

      !> The samples the stream still holds go to the sink; how many it handed on.
      subroutine hand_on_samples()
         if (.not. allocated(stream)) return
         call stream%flush(stat, errmsg)
         if (stat /= 0) then
            io_stat = stat
            io_message = errmsg
            result%status = status_not_run
         end if
         result%samples_written = stream%written
      end subroutine hand_on_samples

      !> keep_runs with poincare_samples = 'all': the samples of the point file's
      !! /statistics/poincare, read back and handed to the sink chunk_rows at a time.
      subroutine samples_of_file(file)
         character(len=*), intent(in) :: file
         type(h5_reader) :: reader
         integer(int64), allocatable :: dims(:)
         integer(int64) :: first, total
         integer :: count, observations
         real(dp), allocatable :: rows(:, :)
         observations = 1 + size(local%output%points)
         total = 0
         !$omp critical (vibrobeam_hdf5)
         call reader%open(file, io_stat, io_message)
         if (io_stat == 0) then
            if (reader%exists('/statistics/poincare/time')) call reader%shape('/statistics/poincare/time', dims, io_stat, &
                                                                              io_message)
            if (allocated(dims)) total = dims(1)
         end if
         !$omp end critical (vibrobeam_hdf5)
         do first = 1, total, chunk_rows
            if (io_stat /= 0) exit
            count = int(min(int(chunk_rows, int64), total - first + 1))
            allocate (rows(1 + 2*observations, count))
            !$omp critical (vibrobeam_hdf5)
            call reader%read_rows('/statistics/poincare/time', first, rows(1:1, :), io_stat, io_message)
            if (io_stat == 0) call reader%read_rows('/statistics/poincare/displacement', first, &
                                                    rows(2:1 + observations, :), io_stat, io_message)
            if (io_stat == 0) call reader%read_rows('/statistics/poincare/velocity', first, rows(2 + observations:, :), &
                                                    io_stat, io_message)
            !$omp end critical (vibrobeam_hdf5)
            if (io_stat == 0) call sink%take_samples(k, rows, io_stat, io_message)
            if (io_stat == 0) result%samples_written = result%samples_written + count
            deallocate (rows)
         end do
         !$omp critical (vibrobeam_hdf5)
         call reader%close()
         !$omp end critical (vibrobeam_hdf5)
         if (io_stat /= 0) then
            io_message = '&sweep poincare_samples = ''all'': the samples of point '//integer_text(k)//' ('''//file// &
                         '''): '//trim(io_message)
            result%status = status_not_run
         end if
      end subroutine samples_of_file

      !> The state the point ends in, which the next point of a continuation starts from.
      subroutine keep_final(stepper)
         class(time_stepper), intent(in) :: stepper
         if (result%status /= status_ok) return
         final = stepper%state()
      end subroutine keep_final
   end subroutine run_point

   !> After a step of a point with poincare_samples = 'all': its Poincare samples into
   !! the buffer, handed to the sink when the buffer is full.
   subroutine stream_samples(self, stepper, recorder, step, stat, errmsg)
      class(sample_stream), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(dynamics_recorder), intent(inout) :: recorder
      integer(int64), intent(in) :: step
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: j
      stat = 0
      errmsg = ''
      ! the samples the recorder holds are those of the step the stepper just took
      if (stepper%steps /= step) return
      associate (statistics => recorder%statistics)
         do j = 1, statistics%poincare_found
            if (self%count == size(self%rows, 2)) call self%flush(stat, errmsg)
            if (stat /= 0) return
            self%count = self%count + 1
            self%rows(1, self%count) = statistics%sample_times(j)
            self%rows(2:, self%count) = statistics%sample_values(:, j)
         end do
      end associate
   end subroutine stream_samples

   !> The samples held so far to the sink, as one chunk.
   subroutine flush_samples(self, stat, errmsg)
      class(sample_stream), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (self%count == 0) return
      call self%sink%take_samples(self%point, self%rows(:, 1:self%count), stat, errmsg)
      if (stat /= 0) return
      self%written = self%written + self%count
      self%count = 0
   end subroutine flush_samples

   !> The RMS tip displacement and the impact rate of the beam agree within `tolerance`
   !! (relative to the larger; two zeros agree).
   logical function agree(a, b, tolerance)
      type(statistics_result), intent(in) :: a, b
      real(dp), intent(in) :: tolerance
      integer :: rms, rate
      rms = a%layout%entries(a%layout%find(group_points, 'displacement_rms'))%offset + 1
      rate = a%layout%entries(a%layout%find(group_beam, 'impact_rate'))%offset + 1
      agree = close(a%values(rms), b%values(rms)) .and. close(a%values(rate), b%values(rate))
   contains
      logical function close(x, y)
         real(dp), intent(in) :: x, y
         close = abs(x - y) <= tolerance*max(abs(x), abs(y))
      end function close
   end function agree
end module vibrobeam_sweep_runner
