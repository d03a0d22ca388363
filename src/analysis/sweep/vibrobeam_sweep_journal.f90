!> The journal of a sweep (docs/sweeps.md, "Resuming a sweep"): every finished point goes
!! into an HDF5 file of the sweep's partial directory as soon as it is done, so that a
!! sweep keeps no point in memory and loses none when it is killed. Each process that
!! runs points (one per MPI rank) writes its own journal; the sweep file is made from the
!! journals at the end (`vibrobeam_sweep_file`), and a rerun of the same input reads them
!! to skip the points they hold (`vibrobeam_sweep_partial`).
!!
!! Layout of a journal (`points` = the sweep's points, `tasks` its tasks):
!! /journal/record (points, record_head + 2 L): one row per point, written when it ends
!! (`pack_record`: its status, windows, counts, then the L values and L standard errors of
!! its statistics); /journal/message (points, message_words): its message, four
!! characters per integer; /journal/done (points): 0 not written, 1 done (ok), 2 done
!! (failed), 3 interrupted (written, to be run again); /journal/poincare (rows,
!! 1 + 2 observation points): Poincare samples, time then u then v, written in chunks:
!! /journal/poincare_chunks (chunks, 3) gives for each chunk its point, first row (from 0)
!! and rows, the chunks of a point in time order. With &sweep poincare_samples = 'latest'
!! a point writes one chunk when it ends (its kept samples); with 'all' it writes its
!! samples while it runs, a chunk of at most `chunk_rows` at a time (and the rest when it
!! ends; `vibrobeam_sweep_runner`), so that no point holds them in memory; its record then says how many of its
!! first rows to skip (those of earlier windows of steady_tolerance) and how many follow
!! (r_poincare_first, r_kept); with
!! continuation, /journal/state (2 tasks, 2 + 3 unknowns): two slots per task, each the
!! final state of a point of the task (the point, whether U^{n-1} is there, U, V, U^{n-1}).
!! Attributes of /journal: `fingerprint` (`vibrobeam_sweep_partial`), `generation` (1 for
!! the first run of the sweep, one more for each resumption), `points`, `layout`.
!!
!! Order of the writes, so that a kill at any moment leaves a journal whose points marked
!! done are complete: the file is written without a sieve buffer (raw data reach the file
!! in the order written), in SWMR mode, with every dataset's storage allocated when it is
!! created; a point's record, message, samples and state are written, and only after a
!! flush of the file (which writes the extents of the samples) are the done flags of the
!! points written since the last flush set. Flushes come every `commit_seconds` of wall
!! time (and at the end), so a kill loses at most that much work (and the points running). A point's state goes
!! into the slot of its task that does not hold the state of the task's last point marked
!! done, so that state survives until a newer one is marked.
module vibrobeam_sweep_journal
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_series, h5_table
   use vibrobeam_sweep_runner, only: point_result, status_ok, status_failed
   use vibrobeam_time_stepper, only: dynamic_state
   implicit none
   private
   public :: sweep_journal, journal_name, pack_record, message_words, record_length
   public :: record_head, r_status, r_settled, r_start_point, r_settle_steps, r_measure_steps, r_dt, r_wall, &
      r_present, r_first_step, r_steps, r_block_steps, r_batches, r_window_start, r_window_end, r_bin_width, &
      r_poincare_total, r_values, r_kept, r_poincare_first, r_message_length, r_point_file
   public :: done_none, done_ok, done_failed, done_interrupted

   !> Positions in a record (`pack_record`).
   integer, parameter :: r_status = 1, r_settled = 2, r_start_point = 3, r_settle_steps = 4, r_measure_steps = 5, &
                         r_dt = 6, r_wall = 7, r_present = 8, r_first_step = 9, r_steps = 10, r_block_steps = 11, &
                         r_batches = 12, r_window_start = 13, r_window_end = 14, r_bin_width = 15, &
                         r_poincare_total = 16, r_values = 17, r_kept = 18, r_poincare_first = 19, &
                         r_message_length = 20, r_point_file = 21, record_head = 21
   !> Integers holding a point's message (four characters each).
   integer, parameter :: message_words = 128
   !> Values of /journal/done.
   integer, parameter :: done_none = 0, done_ok = 1, done_failed = 2, done_interrupted = 3
   !> Wall time between two commits of a journal (s): the work a kill may lose.
   real(dp), parameter :: commit_seconds = 1

   !> One process's journal, open for writing.
   type :: sweep_journal
      type(h5_writer) :: h5
      type(h5_table) :: records, messages, done, states
      type(h5_series) :: poincare, chunks
      integer :: layout_size = 0, observations = 0, state_length = 0
      logical :: continuation = .false.
      integer(int64) :: poincare_rows = 0
      !> points written since the last flush, and their done flags
      integer, allocatable :: pending(:), pending_flag(:)
      integer :: pending_count = 0
      !> (tasks) slot holding the state of the task's last point marked done (0: none
      !! here); slot written since
      integer, allocatable :: marked_slot(:), written_slot(:)
      integer(int64) :: last_flush = 0
   contains
      procedure :: create => journal_create
      procedure :: write_point => journal_write_point
      procedure :: write_samples => journal_write_samples
      procedure :: commit => journal_commit
      procedure :: close => journal_close
   end type sweep_journal

contains

   !> The name a journal is created under in the partial directory `directory` (the
   !! writer adds '.<pid>-<token>.tmp', so each process's journal has a name of its own).
   pure function journal_name(directory) result(name)
      character(len=*), intent(in) :: directory
      character(len=:), allocatable :: name
      name = directory//'/journal.h5'
   end function journal_name

   !> Doubles of a record for statistics of `layout_size` values.
   pure integer function record_length(layout_size)
      integer, intent(in) :: layout_size
      record_length = record_head + 2*layout_size
   end function record_length

   !> Create a journal in `directory` for `points` points in `tasks` tasks (module
   !! documentation); `state_length` = 2 + 3 unknowns with continuation, 0 without.
   subroutine journal_create(self, directory, fingerprint, generation, points, tasks, layout_size, observations, &
                             state_length, stat, errmsg)
      class(sweep_journal), intent(inout) :: self
      character(len=*), intent(in) :: directory, fingerprint
      integer, intent(in) :: generation, points, tasks, layout_size, observations, state_length
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: rows
      self%layout_size = layout_size
      self%observations = observations
      self%state_length = state_length
      self%continuation = state_length > 0
      self%poincare_rows = 0
      self%pending_count = 0
      allocate (self%pending(64), self%pending_flag(64))
      rows = points
      call self%h5%create(journal_name(directory), stat, errmsg, unbuffered=.true.)
      if (stat /= 0) return
      call self%records%create(self%h5, '/journal/record', record_length(layout_size), rows, stat, errmsg, early=.true.)
      if (stat == 0) call self%messages%create(self%h5, '/journal/message', message_words, rows, stat, errmsg, &
                                               integers=.true., early=.true.)
      if (stat == 0) call self%done%create(self%h5, '/journal/done', 1, rows, stat, errmsg, integers=.true., &
                                           vector=.true., early=.true.)
      if (stat == 0) call self%poincare%create(self%h5, '/journal/poincare', 1 + 2*observations, '', stat, errmsg, &
                                               matrix=.true.)
      if (stat == 0) call self%chunks%create(self%h5, '/journal/poincare_chunks', 3, '', stat, errmsg)
      if (stat == 0 .and. self%continuation) then
         call self%states%create(self%h5, '/journal/state', state_length, 2*int(tasks, int64), stat, errmsg, &
                                 early=.true.)
         allocate (self%marked_slot(tasks), self%written_slot(tasks), source=0)
      end if
      if (stat == 0) call self%h5%attr_string('/journal', 'fingerprint', fingerprint, stat, errmsg)
      if (stat == 0) call self%h5%attr_int('/journal', 'generation', generation, stat, errmsg)
      if (stat == 0) call self%h5%attr_int('/journal', 'points', points, stat, errmsg)
      if (stat == 0) call self%h5%attr_int('/journal', 'layout', layout_size, stat, errmsg)
      if (stat == 0) call self%h5%start_swmr(stat, errmsg)
      if (stat == 0) call self%h5%flush(stat, errmsg)
      call system_clock(self%last_flush)
   end subroutine journal_create

   !> Write point k of task `task` (its result, and with continuation its final state when
   !! it succeeded); `point_file`: its keep_runs file is in the partial directory. Commits
   !! (flush, then the done flags) when `commit_seconds` have passed since the last one.
   subroutine journal_write_point(self, k, task, result, final, point_file, stat, errmsg)
      class(sweep_journal), intent(inout) :: self
      integer, intent(in) :: k, task
      type(point_result), intent(in) :: result
      type(dynamic_state), intent(in) :: final
      logical, intent(in) :: point_file
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: record(record_length(self%layout_size))
      real(dp), allocatable :: rows(:, :)
      integer :: kept, slot
      integer(int64) :: now, rate
      kept = 0
      if (allocated(result%statistics%poincare_time)) kept = size(result%statistics%poincare_time)
      record = pack_record(result, self%layout_size, point_file)
      call self%records%write_rows(int(k, int64), reshape(record, [size(record), 1]), stat, errmsg)
      if (stat == 0) call self%messages%write_rows(int(k, int64), reshape(message_values(result%message), &
                                                                          [message_words, 1]), stat, errmsg)
      if (stat == 0 .and. kept > 0 .and. result%samples_written == 0) then
         ! the kept samples (poincare_samples = 'latest'), one chunk
         allocate (rows(1 + 2*self%observations, kept))
         rows(1, :) = result%statistics%poincare_time
         rows(2:, :) = result%statistics%poincare_values(1:2*self%observations, :)
         call self%write_samples(k, rows, stat, errmsg)
      end if
      if (stat == 0 .and. self%continuation .and. result%status == status_ok .and. allocated(final%u)) then
         slot = 1
         if (self%marked_slot(task) == 1) slot = 2
         call self%states%write_rows(2*int(task - 1, int64) + slot, reshape(state_values(k, final), &
                                                                            [self%state_length, 1]), stat, errmsg)
         self%written_slot(task) = slot
      end if
      if (stat /= 0) return
      if (self%pending_count == size(self%pending)) then
         self%pending = [self%pending, self%pending]
         self%pending_flag = [self%pending_flag, self%pending_flag]
      end if
      self%pending_count = self%pending_count + 1
      self%pending(self%pending_count) = k
      select case (result%status)
      case (status_ok)
         self%pending_flag(self%pending_count) = done_ok
      case (status_failed)
         self%pending_flag(self%pending_count) = done_failed
      case default
         self%pending_flag(self%pending_count) = done_interrupted
      end select
      call system_clock(now, rate)
      if (now - self%last_flush >= commit_seconds*rate) call self%commit(stat, errmsg)
   end subroutine journal_write_point

   !> Poincare samples of point k (time, then u, then v at each observation point; a column
   !! each), after those it wrote before: one chunk.
   subroutine journal_write_samples(self, k, rows, stat, errmsg)
      class(sweep_journal), intent(inout) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: rows(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: j
      stat = 0
      errmsg = ''
      if (size(rows, 2) == 0) return
      do j = 1, size(rows, 2)
         if (stat == 0) call self%poincare%append(rows(:, j), stat, errmsg)
      end do
      if (stat == 0) call self%chunks%append([real(k, dp), real(self%poincare_rows, dp), real(size(rows, 2), dp)], &
                                             stat, errmsg)
      self%poincare_rows = self%poincare_rows + size(rows, 2)
   end subroutine journal_write_samples

   !> Flush the journal, then set the done flags of the points written since the last
   !! commit (module documentation).
   subroutine journal_commit(self, stat, errmsg)
      class(sweep_journal), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: j
      call self%poincare%write(stat, errmsg)
      if (stat == 0) call self%chunks%write(stat, errmsg)
      if (stat == 0) call self%h5%flush(stat, errmsg)
      do j = 1, self%pending_count
         if (stat /= 0) exit
         call self%done%write_rows(int(self%pending(j), int64), reshape([real(self%pending_flag(j), dp)], [1, 1]), &
                                   stat, errmsg)
      end do
      if (stat /= 0) return
      self%pending_count = 0
      if (self%continuation) then
         where (self%written_slot > 0) self%marked_slot = self%written_slot
         self%written_slot = 0
      end if
      call system_clock(self%last_flush)
   end subroutine journal_commit

   !> Commit and close the journal (it keeps its name: the sweep file is made from it).
   subroutine journal_close(self, stat, errmsg)
      class(sweep_journal), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%commit(stat, errmsg)
      call self%records%close()
      call self%messages%close()
      call self%done%close()
      call self%states%close()
      call self%poincare%close()
      call self%chunks%close()
      if (stat == 0) call self%h5%finish(stat, errmsg)
   end subroutine journal_close

   !> A point's result as doubles (every integer in it is exactly representable):
   !! record_head numbers at the positions r_*, then the values and the standard errors
   !! of its statistics (zeros when it has none). Its Poincare samples in the journal's
   !! chunks: r_poincare_first rows to skip (written before its reported window), then
   !! r_kept rows.
   function pack_record(result, layout_size, point_file) result(record)
      type(point_result), intent(in) :: result
      integer, intent(in) :: layout_size
      logical, intent(in) :: point_file
      real(dp) :: record(record_length(layout_size))
      integer :: kept
      record = 0
      kept = 0
      associate (s => result%statistics)
         if (allocated(s%poincare_time)) kept = size(s%poincare_time)
         if (result%samples_written > 0) kept = int(min(s%poincare_total, result%samples_written))
         record(r_status) = result%status
         record(r_settled) = result%settled
         record(r_start_point) = result%start_point
         record(r_settle_steps) = real(result%settle_steps, dp)
         record(r_measure_steps) = real(result%measure_steps, dp)
         record(r_dt) = result%dt
         record(r_wall) = result%wall_seconds
         record(r_present) = merge(1, 0, s%present)
         record(r_first_step) = real(s%first_step, dp)
         record(r_steps) = real(s%steps, dp)
         record(r_block_steps) = real(s%block_steps, dp)
         record(r_batches) = s%batches
         record(r_window_start) = s%window_start
         record(r_window_end) = s%window_end
         record(r_bin_width) = s%bin_width
         record(r_poincare_total) = real(s%poincare_total, dp)
         record(r_kept) = kept
         record(r_poincare_first) = real(max(0_int64, result%samples_written - kept), dp)
         record(r_message_length) = len_trim(result%message)
         record(r_point_file) = merge(1, 0, point_file)
         if (allocated(s%values)) then
            if (size(s%values) == layout_size) then
               record(r_values) = layout_size
               record(record_head + 1:record_head + layout_size) = s%values
               record(record_head + layout_size + 1:) = s%errors
            end if
         end if
      end associate
   end function pack_record

   !> A message as message_words integers (as doubles), four characters each.
   function message_values(message) result(values)
      character(len=*), intent(in) :: message
      real(dp) :: values(message_words)
      character(len=4*message_words) :: padded
      integer :: j
      padded = message
      do j = 1, message_words
         values(j) = transfer(padded(4*j - 3:4*j), 0)
      end do
   end function message_values

   !> A state slot: the point, 1 when the scheme's extra (U^{n-1}) follows, U, V, extra (zeros without it).
   function state_values(k, state) result(values)
      integer, intent(in) :: k
      type(dynamic_state), intent(in) :: state
      real(dp), allocatable :: values(:)
      integer :: n
      n = size(state%u)
      allocate (values(2 + 3*n), source=0.0_dp)
      values(1) = k
      values(3:2 + n) = state%u
      values(3 + n:2 + 2*n) = state%v
      if (allocated(state%extra)) then
         values(2) = 1
         values(3 + 2*n:) = state%extra
      end if
   end function state_values
end module vibrobeam_sweep_journal
