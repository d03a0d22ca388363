!> A sweep from start to published sweep file (docs/sweeps.md): the points of
!! `vibrobeam_sweep_settings` run as independent tasks (`vibrobeam_sweep_runner`) on the
!! threads of each process (OpenMP; OMP_NUM_THREADS or every core) and, in an MPI build,
!! over the ranks. Each point goes into the process's journal in the sweep's partial
!! directory as it ends (`vibrobeam_sweep_journal`), so nothing accumulates in memory and a
!! killed sweep loses at most the last seconds of work; a rerun of the same input skips
!! the points the journals hold as done (`vibrobeam_sweep_partial`). At the end rank 0
!! makes the sweep file from the journals and publishes it with its point files as one set
!! (`vibrobeam_sweep_file`); a complete sweep then removes its partial directory.
!!
!! The answers do not depend on the number of threads or ranks, nor on how often the sweep
!! was stopped and resumed: each point's computation depends only on its task's earlier
!! points (or on the state a journal kept of them, bit for bit), never on how tasks are
!! shared out, and the program asks the BLAS for one thread (`limit_blas_threads`).
module vibrobeam_sweep
   !$ use omp_lib, only: omp_get_max_threads
   use vibrobeam_kinds, only: dp, error_unit
   use vibrobeam_status, only: outcome_ok, outcome_interrupted, outcome_name, stat_failure, stat_invalid_input
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, build_problem
   use vibrobeam_recorder, only: statistics_options
   use vibrobeam_checkpoint, only: read_checkpoint
   use vibrobeam_restart_check, only: check_compatible
   use vibrobeam_state_record, only: state_record
   use vibrobeam_statistics_layout, only: statistics_layout
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, sweep_points, point_scene, task_count
   use vibrobeam_sweep_runner, only: point_result, task_start, point_sink, run_task
   use vibrobeam_time_stepper, only: dynamic_state
   use vibrobeam_stepper_factory, only: state_from_record
   use vibrobeam_sweep_journal, only: sweep_journal, done_ok, done_failed
   use vibrobeam_sweep_partial, only: sweep_partial, sweep_fingerprint
   use vibrobeam_sweep_file, only: write_sweep_file, sweep_counts
   use vibrobeam_sweep_transport, only: transport_rank, transport_ranks, owns_task, transport_barrier, &
      transport_max, share_failure
   implicit none
   private
   public :: run_sweep, sweep_outcome, sweep_threads, sweep_start_state, inspect_partial

   !> What a sweep reports back to the program.
   type :: sweep_outcome
      integer :: status = outcome_ok           !! outcome_ok | outcome_interrupted (/run status)
      integer :: points = 0, failed = 0, interrupted = 0, not_run = 0
      integer :: resumed = 0                   !! points a partial directory held as done at the start
      logical :: text_skipped = .false.
      real(dp) :: wall_seconds = 0
      integer :: threads = 1, ranks = 1
      character(len=2048) :: failures = ''     !! the first failed points and their reasons
   end type sweep_outcome

   !> The journal as the runner's `point_sink`: points written one thread at a time
   !! (HDF5 is not thread-safe), the progress reported: the points of this process's
   !! tasks done (`done`, those done before included) of `total`; under mpirun, rank 0
   !! reports its own share of the `points` of the sweep.
   type, extends(point_sink) :: journal_sink
      type(sweep_journal) :: journal
      type(progress_meter) :: meter
      logical :: failed = .false.
      integer :: done = 0, total = 0, rank = 0, ranks = 1, points = 0
   contains
      procedure :: take => sink_take
      procedure :: take_samples => sink_take_samples
      procedure :: halted => sink_halted
   end type journal_sink

contains

   !> Threads each process runs tasks on: OMP_NUM_THREADS, or every core (1 without OpenMP).
   integer function sweep_threads()
      sweep_threads = 1
      !$ sweep_threads = omp_get_max_threads()
   end function sweep_threads

   !> Run every point not yet done and publish the sweep file `scene%output%file` (on rank 0).
   !! stat /= 0 (with errmsg, the same on every rank): 2 when the start state of &initial
   !! from_file cannot be read or the partial directory holds a sweep of another input
   !! (invalid input, nothing written); 1 when the sweep's files cannot be written or
   !! another process runs this sweep (the points done so far stay in the partial
   !! directory, and what was at `scene%output%file` is untouched).
   subroutine run_sweep(scene, settings, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(sweep_point), allocatable :: points(:)
      type(dynamic_state) :: base
      type(run_problem) :: first
      type(statistics_layout) :: layout
      type(scene_type) :: first_scene
      type(sweep_partial) :: partial
      type(journal_sink) :: sink
      type(sweep_counts) :: counts
      character(len=16) :: fingerprint
      character(len=len(errmsg)) :: task_message
      integer, allocatable :: first_of(:), owner(:), flag(:)
      integer :: task, tasks, rank, ranks, n, task_stat, generation, state_length
      logical :: complete, interrupted
      call sink%meter%init(scene%output%progress)
      rank = transport_rank()
      ranks = transport_ranks()
      sink%rank = rank
      if (rank /= 0) sink%meter%enabled = .false.
      outcome%threads = sweep_threads()
      outcome%ranks = ranks
      allocate (points, source=sweep_points(settings))
      n = size(points)
      outcome%points = n
      tasks = task_count(points)
      first_of = task_first_points(points)
      call sweep_start_state(scene, settings, first_scene, first, base, stat, errmsg)
      if (stat /= 0) return
      if (first_scene%analysis%kind == 'periodic') then
         call layout%init_periodic()
      else
         call layout%init(1 + size(first_scene%output%points), first%contacts%count, size(first_scene%obstacles), &
                          first%circles%count, statistics_options(first_scene, 'wear_volume'), &
                          statistics_options(first_scene, 'friction'), first_scene%beam%plane_count())
      end if
      fingerprint = sweep_fingerprint(scene, settings, base)
      ! the partial directory: rank 0 makes and locks it, then every rank reads it
      if (rank == 0) then
         call partial%open(trim(scene%output%file), fingerprint, stat, errmsg)
         if (stat == 0 .and. len(partial%notes) > 0) &
            write (error_unit, '(a)', advance='no') 'vibrobeam: warning: '//partial%notes
      end if
      call share_failure(stat, errmsg)
      if (stat /= 0) return
      if (rank /= 0) call partial%inspect(trim(scene%output%file), fingerprint, stat, errmsg, locked_here=.true.)
      if (stat == 0) call partial%index(n, owner, flag, stat, errmsg)
      call share_failure(stat, errmsg)
      if (stat /= 0) then
         call partial%close()
         return
      end if
      outcome%resumed = count(flag == done_ok .or. flag == done_failed)
      generation = transport_max(partial%generation) + 1
      call transport_barrier()   ! every rank has read the journals before new ones appear
      state_length = 0
      if (settings%mode /= 'independent') state_length = 2 + 3*first%model%unknowns*first_scene%beam%plane_count()
      call sink%journal%create(partial%directory, fingerprint, generation, n, tasks, layout%size, &
                               1 + size(first_scene%output%points), state_length, stat, errmsg)
      if (stat /= 0) call sink%journal%h5%discard()
      call share_failure(stat, errmsg)
      if (stat /= 0) then
         call partial%close()
         return
      end if
      sink%ranks = ranks
      sink%points = n
      do task = 1, tasks
         if (.not. owns_task(task, rank, ranks)) cycle
         sink%total = sink%total + first_of(task + 1) - first_of(task)
         sink%done = sink%done + count(flag(first_of(task):first_of(task + 1) - 1) == done_ok .or. &
                                       flag(first_of(task):first_of(task + 1) - 1) == done_failed)
      end do
      !$omp parallel do schedule(dynamic, 1) default(shared) private(task, task_stat, task_message)
      do task = 1, tasks
         if (.not. owns_task(task, rank, ranks) .or. sink%failed) cycle
         task_stat = 0
         task_message = ''
         block
            type(task_start) :: start
            !$omp critical (vibrobeam_hdf5)
            call resume_point(task, start, task_stat, task_message)
            !$omp end critical (vibrobeam_hdf5)
            if (task_stat == 0) call run_task(scene, settings, points, task, first_of(task), first_of(task + 1) - 1, &
                                              base, start, partial%directory, sink, task_stat, task_message)
         end block
         if (task_stat /= 0) then
            !$omp critical (vibrobeam_sweep_failure)
            if (stat == 0) then
               stat = task_stat
               errmsg = task_message
            end if
            sink%failed = .true.
            !$omp end critical (vibrobeam_sweep_failure)
         end if
      end do
      !$omp end parallel do
      call sink%meter%end_line()
      if (rank /= 0) call partial%close()   ! (rank 0 reads the journals again to publish)
      call sink%journal%close(task_stat, task_message)
      if (stat == 0 .and. task_stat /= 0) then
         stat = task_stat
         errmsg = task_message
      end if
      call share_failure(stat, errmsg)
      if (stat /= 0) then
         call partial%close()
         errmsg = trim(errmsg)//'; the points done are kept in '''//partial%directory//''': run the same input '// &
                  'again to go on from them'
         stat = stat_failure
         return
      end if
      interrupted = transport_max(merge(1, 0, interrupt_requested())) > 0
      outcome%wall_seconds = sink%meter%elapsed()
      call transport_barrier()   ! every journal is closed
      if (rank == 0) call publish()
      call share_failure(stat, errmsg)
      if (transport_max(merge(1, 0, outcome%status == outcome_interrupted)) > 0) outcome%status = outcome_interrupted
      outcome%failed = transport_max(counts%failed)
      outcome%interrupted = transport_max(counts%interrupted)
      outcome%not_run = transport_max(counts%not_run)
      outcome%failures = counts%failures
   contains
      !> Where task `task` starts (docs/sweeps.md, "Resuming a sweep"): its points before
      !! the first one the journals do not hold as done are skipped. A continuation task
      !! goes on from the last point done that succeeded and whose final state a journal
      !! kept (a point marked done after it whose state is lost is run again: a kill while
      !! the done flags were set), skipping the failed points done after it.
      subroutine resume_point(task, start, stat, errmsg)
         integer, intent(in) :: task
         type(task_start), intent(out) :: start
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
         integer :: k, q
         stat = 0
         errmsg = ''
         start%first_to_run = first_of(task)
         start%last_good_point = 0
         if (settings%mode == 'independent') then
            ! one point per task
            do k = first_of(task), first_of(task + 1) - 1
               if (flag(k) == done_ok .or. flag(k) == done_failed) start%first_to_run = k + 1
            end do
            return
         end if
         q = 0
         do k = first_of(task + 1) - 1, first_of(task), -1
            if (flag(k) /= done_ok) cycle
            call partial%read_state(owner(k), task, k, first%model%unknowns, start%state, stat, errmsg)
            if (stat /= 0) return
            if (allocated(start%state%u)) then
               q = k
               exit
            end if
         end do
         if (q == 0) then
            ! no state kept: from the start of the task, skipping the points done before
            ! any that succeeded (they failed from the scene's initial state)
            do k = first_of(task), first_of(task + 1) - 1
               if (flag(k) /= done_failed) exit
               start%first_to_run = k + 1
            end do
            return
         end if
         start%last_good_point = q
         start%first_to_run = q + 1
         do k = q + 1, first_of(task + 1) - 1
            if (flag(k) /= done_failed) exit
            start%first_to_run = k + 1
         end do
      end subroutine resume_point

      !> Rank 0: the sweep file from every journal, published with its point files; the
      !! partial directory removed when the sweep is complete.
      subroutine publish()
         character(len=512) :: message
         integer :: ignored
         call partial%reload(fingerprint, stat, errmsg)   ! with this run's journals
         if (stat == 0) call partial%index(n, owner, flag, stat, errmsg)
         if (stat /= 0) then
            call partial%close()
            stat = stat_failure
            return
         end if
         complete = all(flag == done_ok .or. flag == done_failed)
         ! a signal after the last point: the sweep is complete (the program still exits 4)
         if (interrupted .and. .not. complete) outcome%status = outcome_interrupted
         call write_sweep_file(scene, first%model, settings, points, partial, owner, layout, &
                               [first_scene%beam%length, first_scene%output%points], first%contacts%x, &
                               first%contacts%lower_obstacle, first%contacts%upper_obstacle, first%circles%x, &
                               first%circles%obstacle, outcome%status, &
                               outcome%wall_seconds, outcome%threads, ranks, .not. complete, sink%meter, counts, &
                               outcome%text_skipped, stat, errmsg)
         call sink%meter%end_line()
         if (stat /= 0) then
            call partial%close()
            errmsg = trim(errmsg)//'; the points done are kept in '''//partial%directory//''''
            return
         end if
         if (complete) then
            call partial%remove(ignored, message)
         else
            call partial%close()
         end if
      end subroutine publish
   end subroutine run_sweep

   !> The first point of every task, and one past the last point (size tasks + 1): the
   !! points are in the order of their tasks.
   function task_first_points(points) result(first_of)
      type(sweep_point), intent(in) :: points(:)
      integer, allocatable :: first_of(:)
      integer :: k
      allocate (first_of(task_count(points) + 1))
      first_of(size(first_of)) = size(points) + 1
      do k = size(points), 1, -1
         first_of(points(k)%task) = k
      end do
   end function task_first_points

   !> The first point's scene prepared (its model and contact points are the sweep file's)
   !! and the start state of &initial from_file: U, V (and U^{n-1}) of its checkpoint, at
   !! t = 0, checked against that scene. stat = stat_invalid_input when the first point
   !! cannot be prepared or the file cannot be continued; its own numerical failures are
   !! the point's (it is marked failed when it runs).
   subroutine sweep_start_state(scene, settings, first_scene, first, base, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(scene_type), intent(out) :: first_scene
      type(run_problem), intent(out) :: first
      type(dynamic_state), intent(out) :: base
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(state_record) :: record
      character(len=:), allocatable :: warnings, file
      real(dp) :: time
      logical :: same_bounds
      first_scene = point_scene(scene, settings, first_point(settings))
      warnings = ''
      call build_problem(first_scene, first, warnings, stat, errmsg)
      if (stat /= 0) then
         ! the points' own failures are reported per point; this one's contact points are needed
         if (.not. allocated(first%contacts%x)) then
            errmsg = '&sweep point 1: '//trim(errmsg)
            stat = stat_invalid_input
            return
         end if
         stat = 0
      end if
      if (len_trim(scene%initial%from_file) == 0) return
      file = trim(scene%initial%from_file)
      call check_compatible(file, first_scene, first%contacts%x, first%contacts%lower, first%contacts%upper, &
                            same_bounds, stat, errmsg, hole_x=first%circles%x)
      if (stat == 0) call read_checkpoint(file, record, time, stat, errmsg)
      if (stat /= 0) then
         if (index(errmsg, '&initial from_file') == 0) errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
         stat = stat_invalid_input
         return
      end if
      ! the scheme is the file's (check_compatible): its state, at t = 0
      call state_from_record(first_scene%time%scheme, record, first_scene%beam%plane_count()*first%model%unknowns, &
                             base, stat, errmsg)
      if (stat /= 0) then
         errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
         stat = stat_invalid_input
         if (allocated(base%u)) deallocate (base%u)
         return
      end if
      base%step = 0
   end subroutine sweep_start_state

   !> The first point of the sweep (its scene is the sweep file's model).
   function first_point(settings) result(point)
      type(sweep_settings), intent(in) :: settings
      type(sweep_point) :: point
      type(sweep_point), allocatable :: points(:)
      allocate (points, source=sweep_points(settings))
      point = points(1)
   end function first_point

   !> What a run of this sweep would find in its partial directory (`vibrobeam --check`):
   !! a sentence saying so ('' when there is none), the points it holds as done. stat = stat_invalid_input
   !! when it holds a sweep of another input (the run refuses it). When a sweep is running
   !! into it, the points its journals hold as done are those that sweep has committed so
   !! far (docs/sweeps.md, "Checking a sweep"); the sentence leaves the count out when
   !! they cannot be read at that moment.
   subroutine inspect_partial(scene, settings, done, text, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      integer, intent(out) :: done
      character(len=:), allocatable, intent(out) :: text
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(scene_type) :: first_scene
      type(run_problem) :: first
      type(dynamic_state) :: base
      type(sweep_partial) :: partial
      integer, allocatable :: owner(:), flag(:)
      integer :: n
      done = 0
      text = ''
      call sweep_start_state(scene, settings, first_scene, first, base, stat, errmsg)
      if (stat /= 0) return
      call partial%inspect(trim(scene%output%file), sweep_fingerprint(scene, settings, base), stat, errmsg)
      if (stat /= 0 .and. .not. partial%busy) return
      if (.not. partial%existed) return
      n = size(settings%axis(1)%values)*max(1, size(settings%axis(2)%values))*merge(2, 1, settings%mode == 'up-down')
      if (stat == 0) call partial%index(n, owner, flag, stat, errmsg)
      call partial%close()
      if (stat == 0) done = count(flag == done_ok .or. flag == done_failed)
      if (partial%busy) then
         text = 'a sweep is running into '''//trim(scene%output%file)//''' now (it holds '''//partial%directory//'/lock'''
         if (stat == 0) text = text//'; its journals hold '//integer_text(done)//' of '//integer_text(n)// &
                               ' points of this sweep, done'
         text = text//'): a run started now would stop at once with status 1'
         stat = 0
         errmsg = ''
      else if (stat /= 0) then
         stat = stat_failure
         return
      else
         text = 'resume: '''//partial%directory//''' holds '//integer_text(done)//' of '//integer_text(n)// &
                ' points of this sweep, done; a run goes on from them ('//integer_text(n - done)//' points to run)'
      end if
      if (len(partial%notes) > 0) text = text//new_line('a')//partial%notes
   end subroutine inspect_partial

   !> Write point k into the journal (one thread at a time) and report progress.
   subroutine sink_take(self, k, task, result, final, point_file, stat, errmsg)
      class(journal_sink), intent(inout) :: self
      integer, intent(in) :: k, task
      type(point_result), intent(in) :: result
      type(dynamic_state), intent(in) :: final
      logical, intent(in) :: point_file
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: share
      stat = 0
      errmsg = ''
      !$omp critical (vibrobeam_hdf5)
      call self%journal%write_point(k, task, result, final, point_file, stat, errmsg)
      self%done = self%done + 1
      if (self%meter%due()) then
         share = ''
         if (self%ranks > 1) share = ' on rank '//integer_text(self%rank)//' ('//integer_text(self%points)//' on '// &
                                     integer_text(self%ranks)//' ranks)'
         call self%meter%report('sweep: '//integer_text(self%done)//' of '//integer_text(self%total)//' points'// &
                                share//', wall '//real_text(nint(self%meter%elapsed()*10)/10.0_dp)//' s')
      end if
      !$omp end critical (vibrobeam_hdf5)
   end subroutine sink_take

   !> Poincare samples of point k into the journal, one thread at a time.
   subroutine sink_take_samples(self, k, rows, stat, errmsg)
      class(journal_sink), intent(inout) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: rows(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      !$omp critical (vibrobeam_hdf5)
      call self%journal%write_samples(k, rows, stat, errmsg)
      !$omp end critical (vibrobeam_hdf5)
   end subroutine sink_take_samples

   logical function sink_halted(self)
      class(journal_sink), intent(in) :: self
      sink_halted = self%failed
   end function sink_halted
end module vibrobeam_sweep
