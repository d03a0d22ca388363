!> The result of a sweep (docs/output.md, "Sweep file"): one HDF5 file, made from the
!! journals of the sweep's partial directory (`vibrobeam_sweep_journal`) a block of points
!! at a time, so that memory does not grow with the number of points, and published with
!! its keep_runs point files as one set (docs/sweeps.md, "The sweep file"): under the
!! directory lock the sweep file, its text files and its point files are renamed onto
!! their names and the point files of an earlier sweep of the same name that the new set
!! does not have are removed.
!!
!! Layout (h5py shapes; `points` = the sweep's points in the order of its tasks):
!! /sweep/parameter (points) and, with a second axis, /sweep/parameter2 (points), each
!! with attributes `name` and `unit`; /sweep/direction (+1 up, -1 down, 0 independent),
!! line, task, status (0 ok, 1 failed, 2 interrupted, 3 not run), start_point, settled
!! (1, 0, -1 not tested), batches, batch_steps, poincare_samples (points, integers);
!! /sweep/transient, window, wall_seconds (points, s); /sweep/statistics/<group>/<name>
!! and <name>_error: (points) for the groups beam and energy, (points, n) for points,
!! contacts, obstacles and spectrum; /sweep/statistics/points/x, contacts/x,
!! lower_obstacle, upper_obstacle; /sweep/statistics/spectrum/bin_width (points);
!! /sweep/poincare/point, parameter, parameter2, direction, time (samples) and
!! displacement, velocity (samples, observation points): the latest Poincare samples of
!! each point (at most `kept_samples`). Attributes of /sweep: mode, points, lines, tasks,
!! the windows as given, steady_tolerance, keep_runs, threads, ranks, messages (one line
!! per point with a message).
module vibrobeam_sweep_file
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_status, only: outcome_interrupted
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_model, only: beam_model
   use vibrobeam_result_files, only: result_files, run_summary, publish_step
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_filesystem, only: directory_of, rename_file, remove_file, file_exists, process_id, temporary_suffix
   use vibrobeam_directory_entries, only: directory_listing, link_file
   use vibrobeam_hdf5_series, only: h5_table
   use vibrobeam_statistics_layout, only: statistics_layout, group_beam, group_energy
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, task_count
   use vibrobeam_sweep_runner, only: status_ok, status_failed, status_interrupted, status_not_run, status_names, &
      point_file_name, kept_point_file
   use vibrobeam_sweep_journal, only: record_length, record_head, r_status, r_settled, r_start_point, &
      r_settle_steps, r_measure_steps, r_dt, r_wall, r_batches, r_block_steps, r_bin_width, r_poincare_total, &
      r_kept, r_poincare_first, r_message_length, r_point_file
   use vibrobeam_sweep_partial, only: sweep_partial
   implicit none
   private
   public :: write_sweep_file, sweep_counts

   !> Points written at a time.
   integer, parameter :: block_points = 1024
   !> Longest list of failed points kept for the program's message.
   integer, parameter :: failures_length = 2048

   !> What the sweep file holds, for the program's message and exit status.
   type :: sweep_counts
      integer :: ok = 0, failed = 0, interrupted = 0, not_run = 0
      character(len=failures_length) :: failures = ''   !! the first failed points and their reasons
   end type sweep_counts

   !> The point files of a sweep's set (`publish_step`): from the partial directory onto
   !! their names beside the sweep file, and the point files of an earlier set removed.
   type, extends(publish_step) :: point_files
      character(len=:), allocatable :: file, directory
      logical, allocatable :: has_file(:)   !! (points) the point's file is in the set
      logical :: keep = .false.             !! the partial directory stays: link, do not move
   contains
      procedure :: prepare => point_files_prepare
      procedure :: commit => point_files_commit
   end type point_files

contains

   !> Write and publish the sweep file `scene%output%file` from the journals of `partial`
   !! (`owner`: the journal of each point, 0 for none). `status` is the /run status ('ok' or
   !! 'interrupted'); `threads` and `ranks` what ran it; `keep_partial`: the partial
   !! directory stays after publication (the sweep is not complete). stat /= 0: nothing is
   !! published.
   subroutine write_sweep_file(scene, model, settings, points, partial, owner, layout, point_x, contact_x, &
                               lower_obstacle, upper_obstacle, status, wall_seconds, threads, ranks, keep_partial, &
                               meter, counts, text_skipped, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      type(sweep_partial), intent(inout) :: partial
      integer, intent(in) :: owner(:)
      type(statistics_layout), intent(in) :: layout
      real(dp), intent(in) :: point_x(:), contact_x(:), wall_seconds
      integer, intent(in) :: lower_obstacle(:), upper_obstacle(:), threads, ranks
      integer, intent(in) :: status   !! the sweep's run outcome (core/vibrobeam_status)
      logical, intent(in) :: keep_partial
      type(progress_meter), intent(inout) :: meter
      type(sweep_counts), intent(out) :: counts
      logical, intent(out) :: text_skipped
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(result_files) :: files
      type(run_summary) :: summary
      type(point_files) :: set
      type(h5_table), allocatable :: per_point(:), values(:), errors(:)
      integer, parameter :: t_parameter = 1, t_parameter2 = 2, t_direction = 3, t_line = 4, t_task = 5, &
                            t_status = 6, t_start_point = 7, t_settled = 8, t_batches = 9, t_batch_steps = 10, &
                            t_poincare_samples = 11, t_transient = 12, t_window = 13, t_wall = 14, t_bin_width = 15, &
                            t_bin_width_rad_s = 16, tables = 16
      integer, allocatable :: kept(:)
      integer(int64), allocatable :: poincare_first(:)
      integer(int64) :: total
      integer :: n, k, e, observations
      logical :: second_axis
      character(len=:), allocatable :: messages
      text_skipped = .false.
      n = size(points)
      observations = size(point_x)
      second_axis = len_trim(settings%axis(2)%parameter) > 0
      allocate (kept(n), source=0)
      allocate (poincare_first(n), source=0_int64)
      allocate (per_point(tables), values(size(layout%entries)), errors(size(layout%entries)))
      allocate (set%has_file(n), source=.false.)
      messages = ''
      call files%open(scene, model, stat, errmsg, unbuffered=.true.)
      if (stat /= 0) then
         call files%discard()
         return
      end if
      write_all: block
         call create_tables()
         if (stat /= 0) exit write_all
         call write_points()
         if (stat /= 0) exit write_all
         call write_poincare()
         if (stat /= 0) exit write_all
         call write_attributes()
         if (stat /= 0) exit write_all
         summary%status = status
         summary%wall_seconds = wall_seconds
         call files%set_run(summary, stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/run', 'points_ok', counts%ok, stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/run', 'points_failed', counts%failed, stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/run', 'points_interrupted', counts%interrupted, stat, errmsg)
         if (stat /= 0) exit write_all
         set%file = trim(scene%output%file)
         set%directory = partial%directory
         set%keep = keep_partial
         call files%publish(meter, status /= outcome_interrupted, text_skipped, stat, errmsg, also=set)
         if (stat == 0) return
      end block write_all
      call files%discard()
      if (stat == 0) stat = 1
   contains
      !> Every per-point dataset, empty (written a block of points at a time).
      subroutine create_tables()
         integer(int64) :: rows
         rows = n
         call real_table(t_parameter, '/sweep/parameter', trim(settings%axis(1)%unit))
         if (stat == 0) call files%h5%attr_string('/sweep/parameter', 'name', trim(settings%axis(1)%parameter), &
                                                  stat, errmsg)
         if (stat == 0 .and. second_axis) then
            call real_table(t_parameter2, '/sweep/parameter2', trim(settings%axis(2)%unit))
            if (stat == 0) call files%h5%attr_string('/sweep/parameter2', 'name', trim(settings%axis(2)%parameter), &
                                                     stat, errmsg)
         end if
         call integer_table(t_direction, '/sweep/direction')
         call integer_table(t_line, '/sweep/line')
         call integer_table(t_task, '/sweep/task')
         call integer_table(t_status, '/sweep/status')
         if (stat == 0) call files%h5%attr_string('/sweep/status', 'meaning', status_names, stat, errmsg)
         call integer_table(t_start_point, '/sweep/start_point')
         call integer_table(t_settled, '/sweep/settled')
         call integer_table(t_batches, '/sweep/batches')
         call integer_table(t_batch_steps, '/sweep/batch_steps')
         call integer_table(t_poincare_samples, '/sweep/poincare_samples')
         call real_table(t_transient, '/sweep/transient', 's')
         call real_table(t_window, '/sweep/window', 's')
         call real_table(t_wall, '/sweep/wall_seconds', 's')
         if (stat == 0) call files%h5%write_real_1d('/sweep/statistics/points/x', point_x, 'm', stat, errmsg)
         if (stat == 0) call files%h5%write_real_1d('/sweep/statistics/contacts/x', contact_x, 'm', stat, errmsg)
         if (stat == 0) call files%h5%write_int_1d('/sweep/statistics/contacts/lower_obstacle', lower_obstacle, &
                                                   stat=stat, errmsg=errmsg)
         if (stat == 0) call files%h5%write_int_1d('/sweep/statistics/contacts/upper_obstacle', upper_obstacle, &
                                                   stat=stat, errmsg=errmsg)
         call real_table(t_bin_width, '/sweep/statistics/spectrum/bin_width', 'Hz')
         call real_table(t_bin_width_rad_s, '/sweep/statistics/spectrum/bin_width_rad_s', 'rad/s')
         do e = 1, size(layout%entries)
            if (stat /= 0) return
            associate (entry => layout%entries(e))
               call values(e)%create(files%h5, '/sweep/statistics/'//layout%path(e, .false.), entry%length, rows, &
                                     stat, errmsg, unit=trim(entry%unit), vector=one_value(e))
               if (stat == 0 .and. entry%has_error) &
                  call errors(e)%create(files%h5, '/sweep/statistics/'//layout%path(e, .true.), entry%length, rows, &
                                        stat, errmsg, unit=trim(entry%unit), vector=one_value(e))
            end associate
         end do
      end subroutine create_tables

      subroutine real_table(t, path, unit)
         integer, intent(in) :: t
         character(len=*), intent(in) :: path, unit
         if (stat == 0) call per_point(t)%create(files%h5, path, 1, int(n, int64), stat, errmsg, unit=unit, &
                                                 vector=.true.)
      end subroutine real_table

      subroutine integer_table(t, path)
         integer, intent(in) :: t
         character(len=*), intent(in) :: path
         if (stat == 0) call per_point(t)%create(files%h5, path, 1, int(n, int64), stat, errmsg, integers=.true., &
                                                 vector=.true.)
      end subroutine integer_table

      !> The statistics of the groups of one value (beam, energy) are 1-d datasets.
      logical function one_value(e)
         integer, intent(in) :: e
         one_value = layout%entries(e)%group == group_beam .or. layout%entries(e)%group == group_energy
      end function one_value

      !> The rows of every point, a block at a time; the counts, messages and point files.
      subroutine write_points()
         real(dp), allocatable :: record(:, :)
         integer :: first, count, j, run_start, first_value, last_value
         character(len=512) :: message
         allocate (record(record_length(layout%size), block_points))
         do first = 1, n, block_points
            count = min(block_points, n - first + 1)
            ! the records of the block, reading runs of consecutive points of one journal at once
            record(:, 1:count) = 0
            record(r_status, 1:count) = status_not_run
            run_start = first
            do k = first, first + count
               if (k < first + count) then
                  if (owner(k) == owner(run_start)) cycle
               end if
               if (owner(run_start) /= 0) then
                  call partial%read_records(owner(run_start), run_start, &
                                            record(:, run_start - first + 1:k - first), stat, errmsg)
                  if (stat /= 0) return
               end if
               run_start = k
            end do
            call put(t_parameter, first, points(first:first + count - 1)%value(1))
            if (second_axis) call put(t_parameter2, first, points(first:first + count - 1)%value(2))
            call put(t_direction, first, real(points(first:first + count - 1)%direction, dp))
            call put(t_line, first, real(points(first:first + count - 1)%line, dp))
            call put(t_task, first, real(points(first:first + count - 1)%task, dp))
            call put(t_status, first, record(r_status, 1:count))
            call put(t_start_point, first, record(r_start_point, 1:count))
            where (owner(first:first + count - 1) == 0) record(r_settled, 1:count) = -1
            call put(t_settled, first, record(r_settled, 1:count))
            call put(t_batches, first, record(r_batches, 1:count))
            where (owner(first:first + count - 1) == 0) record(r_block_steps, 1:count) = 1
            call put(t_batch_steps, first, record(r_block_steps, 1:count))
            call put(t_poincare_samples, first, record(r_poincare_total, 1:count))
            call put(t_transient, first, record(r_settle_steps, 1:count)*record(r_dt, 1:count))
            call put(t_window, first, record(r_measure_steps, 1:count)*record(r_dt, 1:count))
            call put(t_wall, first, record(r_wall, 1:count))
            call put(t_bin_width, first, record(r_bin_width, 1:count))
            call put(t_bin_width_rad_s, first, 2*pi*record(r_bin_width, 1:count))
            do e = 1, size(layout%entries)
               if (stat /= 0) return
               first_value = record_head + layout%entries(e)%offset + 1
               last_value = record_head + layout%entries(e)%offset + layout%entries(e)%length
               call values(e)%write_rows(int(first, int64), record(first_value:last_value, 1:count), stat, errmsg)
               if (stat == 0 .and. layout%entries(e)%has_error) &
                  call errors(e)%write_rows(int(first, int64), record(first_value + layout%size:last_value + &
                                                                      layout%size, 1:count), stat, errmsg)
            end do
            if (stat /= 0) return
            do j = 1, count
               k = first + j - 1
               kept(k) = nint(record(r_kept, j))
               poincare_first(k) = nint(record(r_poincare_first, j), int64)
               set%has_file(k) = owner(k) /= 0 .and. record(r_point_file, j) > 0
               message = ''
               if (owner(k) == 0) then
                  message = 'not run'
                  if (status == outcome_interrupted) message = 'not run: the sweep was interrupted'
               else if (record(r_message_length, j) > 0) then
                  call partial%read_message(owner(k), k, message, stat, errmsg)
                  if (stat /= 0) return
               end if
               select case (nint(record(r_status, j)))
               case (status_ok)
                  counts%ok = counts%ok + 1
               case (status_failed)
                  counts%failed = counts%failed + 1
                  if (len_trim(counts%failures) + len_trim(message) <= failures_length - 40) &
                     counts%failures = trim(counts%failures)//'point '//integer_text(k)//': '//trim(message)// &
                                       new_line('a')
               case (status_interrupted)
                  counts%interrupted = counts%interrupted + 1
               case default
                  counts%not_run = counts%not_run + 1
               end select
               if (len_trim(message) > 0) messages = messages//'point '//integer_text(k)//': '//trim(message)// &
                                                     new_line('a')
            end do
            if (meter%due()) call meter%report('writing '//trim(scene%output%file)//': '//integer_text(first + count - 1)// &
                                               ' of '//integer_text(n)//' points')
         end do
         do k = 1, tables
            call per_point(k)%close()
         end do
         do e = 1, size(layout%entries)
            call values(e)%close()
            call errors(e)%close()
         end do
      end subroutine write_points

      !> Rows first .. of the per-point dataset t.
      subroutine put(t, first, data)
         integer, intent(in) :: t, first
         real(dp), intent(in) :: data(:)
         if (stat == 0) call per_point(t)%write_rows(int(first, int64), reshape(data, [1, size(data)]), stat, errmsg)
      end subroutine put

      !> The kept Poincare samples of every point, one row per sample, in the order of the points.
      subroutine write_poincare()
         type(h5_table) :: point, direction, first_value, second_value, time, u, v
         real(dp), allocatable :: rows(:, :)
         integer(int64) :: row
         total = sum(int(kept, int64))
         call point%create(files%h5, '/sweep/poincare/point', 1, total, stat, errmsg, integers=.true., vector=.true.)
         if (stat == 0) call direction%create(files%h5, '/sweep/poincare/direction', 1, total, stat, errmsg, &
                                              integers=.true., vector=.true.)
         if (stat == 0) call first_value%create(files%h5, '/sweep/poincare/parameter', 1, total, stat, errmsg, &
                                                unit=trim(settings%axis(1)%unit), vector=.true.)
         if (stat == 0 .and. second_axis) &
            call second_value%create(files%h5, '/sweep/poincare/parameter2', 1, total, stat, errmsg, &
                                     unit=trim(settings%axis(2)%unit), vector=.true.)
         if (stat == 0) call time%create(files%h5, '/sweep/poincare/time', 1, total, stat, errmsg, unit='s', &
                                         vector=.true.)
         if (stat == 0) call u%create(files%h5, '/sweep/poincare/displacement', observations, total, stat, errmsg, &
                                      unit='m')
         if (stat == 0) call v%create(files%h5, '/sweep/poincare/velocity', observations, total, stat, errmsg, &
                                      unit='m/s')
         row = 1
         do k = 1, n
            if (stat /= 0 .or. kept(k) == 0) cycle
            if (allocated(rows)) deallocate (rows)
            allocate (rows(1 + 2*observations, kept(k)))
            call partial%read_poincare(owner(k), poincare_first(k), rows, stat, errmsg)
            if (stat == 0) call point%write_rows(row, spread(spread(real(k, dp), 1, 1), 2, kept(k)), stat, errmsg)
            if (stat == 0) call direction%write_rows(row, spread(spread(real(points(k)%direction, dp), 1, 1), 2, &
                                                                 kept(k)), stat, errmsg)
            if (stat == 0) call first_value%write_rows(row, spread(spread(points(k)%value(1), 1, 1), 2, kept(k)), &
                                                       stat, errmsg)
            if (stat == 0 .and. second_axis) &
               call second_value%write_rows(row, spread(spread(points(k)%value(2), 1, 1), 2, kept(k)), stat, errmsg)
            if (stat == 0) call time%write_rows(row, rows(1:1, :), stat, errmsg)
            if (stat == 0) call u%write_rows(row, rows(2:1 + observations, :), stat, errmsg)
            if (stat == 0) call v%write_rows(row, rows(2 + observations:, :), stat, errmsg)
            row = row + kept(k)
         end do
         call point%close()
         call direction%close()
         call first_value%close()
         call second_value%close()
         call time%close()
         call u%close()
         call v%close()
      end subroutine write_poincare

      subroutine write_attributes()
         call files%h5%attr_string('/sweep', 'mode', trim(settings%mode), stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/sweep', 'points', n, stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/sweep', 'lines', max(1, size(settings%axis(2)%values)), stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/sweep', 'tasks', task_count(points), stat, errmsg)
         if (stat == 0) call files%h5%attr_real('/sweep', 'settle', settings%settle, stat, errmsg)
         if (stat == 0) call files%h5%attr_real('/sweep', 'measure', settings%measure, stat, errmsg)
         if (stat == 0) call files%h5%attr_real('/sweep', 'settle_periods', settings%settle_periods, stat, errmsg)
         if (stat == 0) call files%h5%attr_real('/sweep', 'measure_periods', settings%measure_periods, stat, errmsg)
         if (stat == 0) call files%h5%attr_real('/sweep', 'steady_tolerance', settings%steady_tolerance, stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/sweep', 'keep_runs', merge(1, 0, settings%keep_runs), stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/sweep', 'threads', threads, stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/sweep', 'ranks', ranks, stat, errmsg)
         if (stat == 0) call files%h5%attr_string('/sweep', 'messages', messages, stat, errmsg)
      end subroutine write_attributes
   end subroutine write_sweep_file

   !> Under the directory lock, before the sweep file is renamed: every point file must be
   !! in the partial directory and its name free for a file (not a directory), and when the
   !! partial directory stays its point files get a second name beside their final one
   !! (renamed onto it in `commit`).
   subroutine point_files_prepare(self, stat, errmsg)
      class(point_files), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=256) :: message
      integer :: k, j, ignored
      stat = 0
      errmsg = ''
      do k = 1, size(self%has_file)
         if (.not. self%has_file(k)) cycle
         if (file_exists(point_file_name(self%file, k)//'/')) then
            stat = 1
            errmsg = 'cannot publish '''//point_file_name(self%file, k)//''': it is a directory'
         else if (.not. file_exists(kept_point_file(self%directory, k))) then
            stat = 1
            errmsg = 'cannot publish the result of point '//integer_text(k)//': '''// &
                     kept_point_file(self%directory, k)//''' is missing'
         else if (self%keep) then
            call remove_file(linked_name(self%file, k), ignored, message)
            call link_file(kept_point_file(self%directory, k), linked_name(self%file, k), stat, errmsg)
         end if
         if (stat /= 0) then
            ! take back the names given so far: nothing is published
            do j = 1, k - 1
               if (self%has_file(j)) call remove_file(linked_name(self%file, j), ignored, message)
            end do
            return
         end if
      end do
   end subroutine point_files_prepare

   !> The second name point k's file gets beside its final one when the partial directory
   !! stays ('<point file>.<pid>-set.tmp').
   function linked_name(file, k) result(name)
      character(len=*), intent(in) :: file
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      name = point_file_name(file, k)//'.'//integer_text(process_id())//'-set'//temporary_suffix
   end function linked_name

   !> Under the directory lock, after the sweep file was renamed: every point file onto its
   !! name, then the point files of an earlier set that this one does not have removed
   !! ('<stem>_point<k>.h5' for a k without a file here).
   subroutine point_files_commit(self, stat, errmsg)
      class(point_files), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(directory_listing) :: listing
      character(len=:), allocatable :: name, directory, prefix, stem
      character(len=256) :: message
      integer :: k, ignored, slash
      stat = 0
      errmsg = ''
      do k = 1, size(self%has_file)
         if (.not. self%has_file(k)) cycle
         if (self%keep) then
            call rename_file(linked_name(self%file, k), point_file_name(self%file, k), stat, errmsg)
         else
            call rename_file(kept_point_file(self%directory, k), point_file_name(self%file, k), stat, errmsg)
         end if
         if (stat /= 0) then
            errmsg = 'the sweep file is published but not all its point files: '//trim(errmsg)
            return
         end if
      end do
      ! stale members of an earlier set
      directory = directory_of(self%file)
      stem = point_file_name(self%file, 1)
      slash = index(stem, '/', back=.true.)
      prefix = stem(slash + 1:index(stem, '_point', back=.true.) + 5)
      call listing%open(directory, stat, errmsg)
      if (stat /= 0) return
      do while (listing%next(name))
         k = point_index(name, prefix)
         if (k == 0) cycle
         if (k <= size(self%has_file)) then
            if (self%has_file(k)) cycle
         end if
         call remove_file(directory//'/'//name, ignored, message)
      end do
      call listing%close()
   end subroutine point_files_commit

   !> k when `name` is the point file name of point k ('<prefix><k with at least 4
   !! digits>.h5', exactly as `point_file_name` writes it), else 0.
   function point_index(name, prefix) result(k)
      character(len=*), intent(in) :: name, prefix
      integer :: k, digits, ios
      k = 0
      digits = len(name) - len(prefix) - 3
      if (digits < 4 .or. digits > 9) return
      if (name(1:len(prefix)) /= prefix .or. name(len(name) - 2:) /= '.h5') return
      if (verify(name(len(prefix) + 1:len(name) - 3), '0123456789') /= 0) return
      read (name(len(prefix) + 1:len(name) - 3), *, iostat=ios) k
      if (ios /= 0 .or. k < 1) then
         k = 0
         return
      end if
      if (name /= point_file_name(prefix(1:len(prefix) - 6)//'.h5', k)) k = 0
   end function point_index
end module vibrobeam_sweep_file
