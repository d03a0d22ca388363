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
!! lower_obstacle, upper_obstacle; /sweep/statistics/spectrum/bin_width (points, Hz) and
!! bin_width_rad_s (points, rad/s);
!! /sweep/poincare/point, parameter, parameter2, direction, time (samples) and
!! displacement, velocity (samples, observation points): the latest Poincare samples of
!! each point (at most `kept_samples`). Attributes of /sweep: mode, points, lines, tasks,
!! the windows as given, steady_tolerance, keep_runs, threads, ranks, messages (one line
!! per point with a message). A sweep of periodic analyses (&analysis kind = 'periodic')
!! has neither the datasets of time marching (settled, batches, batch_steps,
!! poincare_samples, transient, window, the spectrum's bin width, /sweep/poincare, the
!! points' and contact points' positions) nor their statistics, but
!! /sweep/statistics/periodic/<name> (points) of `periodic_names`.
module vibrobeam_sweep_file
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_status, only: outcome_interrupted, outcome_name, stat_failure
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_model, only: beam_model
   use vibrobeam_result_files, only: result_files, run_summary
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_table
   use vibrobeam_statistics_layout, only: statistics_layout, group_beam, group_energy
   use vibrobeam_statistics_output, only: statistics_points
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, task_count
   use vibrobeam_sweep_runner, only: status_ok, status_failed, status_interrupted, status_not_run, status_names
   use vibrobeam_sweep_journal, only: record_length, record_head, r_status, r_settled, r_start_point, &
      r_settle_steps, r_measure_steps, r_dt, r_wall, r_batches, r_block_steps, r_bin_width, r_poincare_total, &
      r_kept, r_poincare_first, r_message_length, r_point_file
   use vibrobeam_sweep_partial, only: sweep_partial
   use vibrobeam_sweep_point_files, only: point_files
   use vibrobeam_sweep_ensemble, only: sweep_ensemble, ensemble_confidence
   use vibrobeam_sweep_poincare_file, only: write_poincare
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

   !> The per-point datasets (index t_*) and the statistics' values and errors (index
   !! of the layout's entries), written a block of points at a time.
   integer, parameter :: t_parameter = 1, t_parameter2 = 2, t_direction = 3, t_line = 4, t_task = 5, &
                         t_status = 6, t_start_point = 7, t_settled = 8, t_batches = 9, t_batch_steps = 10, &
                         t_poincare_samples = 11, t_transient = 12, t_window = 13, t_wall = 14, t_bin_width = 15, &
                         t_bin_width_rad_s = 16
   type :: point_tables
      type(h5_table) :: per_point(16)
      type(h5_table), allocatable :: values(:), errors(:)
      logical :: second_axis = .false.
      logical :: dynamics = .true.   !! the points ran in time (not periodic analyses): their windows, batches
   end type point_tables

   !> What the journals say of each point beyond its rows.
   type :: point_outcomes
      integer, allocatable :: kept(:)                  !! (points) Poincare samples kept
      integer(int64), allocatable :: poincare_first(:) !! (points) its rows in the journal's chunks to skip
      logical, allocatable :: has_file(:)              !! (points) its result file is in the set
      type(sweep_counts) :: counts
      character(len=:), allocatable :: messages        !! one line per point with a message
   end type point_outcomes

contains

   !> Write and publish the sweep file `scene%output%file` from the journals of `partial`
   !! (`owner`: the journal of each point, 0 for none). `status` is the /run status ('ok' or
   !! 'interrupted'); `threads` and `ranks` what ran it; `keep_partial`: the partial
   !! directory stays after publication (the sweep is not complete). stat /= 0: nothing is
   !! published.
   subroutine write_sweep_file(scene, model, settings, points, partial, owner, layout, point_x, contact_x, &
                               lower_obstacle, upper_obstacle, wear_x, wear_obstacle, status, wall_seconds, threads, &
                               ranks, keep_partial, meter, counts, text_skipped, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      type(sweep_partial), intent(inout) :: partial
      integer, intent(in) :: owner(:)
      type(statistics_layout), intent(in) :: layout
      real(dp), intent(in) :: point_x(:), contact_x(:), wall_seconds
      integer, intent(in) :: lower_obstacle(:), upper_obstacle(:), threads, ranks
      real(dp), intent(in), optional :: wear_x(:)      !! a beam of two planes' obstacles' points (m)
      integer, intent(in), optional :: wear_obstacle(:)   !! and their obstacles
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
      type(point_tables) :: tables
      type(point_outcomes) :: outcomes
      type(sweep_ensemble) :: ensemble
      text_skipped = .false.
      call files%open(scene, model, stat, errmsg, unbuffered=.true.)
      if (stat /= 0) then
         call files%discard()
         return
      end if
      write_all: block
         call create_point_tables(files%h5, settings, size(points), .not. layout%periodic, tables, stat, errmsg)
         if (stat == 0 .and. .not. layout%periodic) &
            call statistics_points(files%h5, '/sweep/statistics', point_x, contact_x, lower_obstacle, upper_obstacle, &
                                   wear_x, wear_obstacle, stat, errmsg)
         if (stat == 0) call create_statistics_tables(files%h5, layout, size(points), tables, stat, errmsg)
         if (stat /= 0) exit write_all
         call ensemble%init(settings, points, layout%size)
         call write_points(tables, settings, points, partial, owner, layout, status, trim(scene%output%file), meter, &
                           outcomes, ensemble, stat, errmsg)
         if (stat == 0 .and. ensemble%axis > 0) call write_ensemble(files%h5, settings, layout, ensemble, stat, errmsg)
         if (stat /= 0) exit write_all
         if (.not. layout%periodic) &
            call write_poincare(files%h5, settings, points, partial, owner, outcomes%kept, outcomes%poincare_first, &
                                size(point_x), stat, errmsg)
         if (stat /= 0) exit write_all
         call write_attributes(files%h5, settings, points, threads, ranks, outcomes%messages, stat, errmsg)
         if (stat /= 0) exit write_all
         counts = outcomes%counts
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
         set%has_file = outcomes%has_file
         call files%publish(meter, status /= outcome_interrupted, text_skipped, stat, errmsg, also=set)
         if (stat == 0) return
         if (set%missing > 0) errmsg = trim(errmsg)//why_in_set(partial, owner(set%missing), set%missing, layout%size)
      end block write_all
      call files%discard()
      if (stat == 0) stat = stat_failure
   end subroutine write_sweep_file

   !> For a point k whose file is missing at publication: what put it in the set, its
   !! journal's record ('; the journal ... holds point 5 (ok) with its file written').
   function why_in_set(partial, journal, k, layout_size) result(text)
      type(sweep_partial), intent(inout) :: partial
      integer, intent(in) :: journal, k, layout_size
      character(len=:), allocatable :: text
      real(dp) :: row(record_length(layout_size), 1)
      character(len=256) :: message
      integer :: read_stat
      text = ''
      call partial%read_records(journal, k, row, read_stat, message)
      if (read_stat /= 0) return
      text = '; the journal '//partial%journal_label(journal)//' holds point '//integer_text(k)//' ('// &
             outcome_name(nint(row(r_status, 1)))//') with its file written'
   end function why_in_set

   !> The datasets of the points and their parameters (`points` rows), empty (written a
   !! block of points at a time by `write_points`); those of time marching (settled,
   !! batches, batch_steps, poincare_samples, transient, window) only when `dynamics`.
   subroutine create_point_tables(h5, settings, points, dynamics, tables, stat, errmsg)
      type(h5_writer), intent(inout) :: h5
      type(sweep_settings), intent(in) :: settings
      integer, intent(in) :: points
      logical, intent(in) :: dynamics
      type(point_tables), intent(out) :: tables
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: rows
      rows = points
      tables%second_axis = len_trim(settings%axis(2)%parameter) > 0
      tables%dynamics = dynamics
      call real_table(t_parameter, '/sweep/parameter', trim(settings%axis(1)%unit))
      if (stat == 0) call h5%attr_string('/sweep/parameter', 'name', trim(settings%axis(1)%parameter), stat, errmsg)
      if (stat == 0 .and. tables%second_axis) then
         call real_table(t_parameter2, '/sweep/parameter2', trim(settings%axis(2)%unit))
         if (stat == 0) call h5%attr_string('/sweep/parameter2', 'name', trim(settings%axis(2)%parameter), stat, errmsg)
      end if
      if (stat == 0) call integer_table(t_direction, '/sweep/direction')
      if (stat == 0) call integer_table(t_line, '/sweep/line')
      if (stat == 0) call integer_table(t_task, '/sweep/task')
      if (stat == 0) call integer_table(t_status, '/sweep/status')
      if (stat == 0) call h5%attr_string('/sweep/status', 'meaning', status_names, stat, errmsg)
      if (stat == 0) call integer_table(t_start_point, '/sweep/start_point')
      if (stat == 0) call real_table(t_wall, '/sweep/wall_seconds', 's')
      if (.not. dynamics) return
      if (stat == 0) call integer_table(t_settled, '/sweep/settled')
      if (stat == 0) call integer_table(t_batches, '/sweep/batches')
      if (stat == 0) call integer_table(t_batch_steps, '/sweep/batch_steps')
      if (stat == 0) call integer_table(t_poincare_samples, '/sweep/poincare_samples')
      if (stat == 0) call real_table(t_transient, '/sweep/transient', 's')
      if (stat == 0) call real_table(t_window, '/sweep/window', 's')
   contains
      subroutine real_table(t, path, unit)
         integer, intent(in) :: t
         character(len=*), intent(in) :: path, unit
         call tables%per_point(t)%create(h5, path, 1, rows, stat, errmsg, unit=unit, vector=.true.)
      end subroutine real_table

      subroutine integer_table(t, path)
         integer, intent(in) :: t
         character(len=*), intent(in) :: path
         call tables%per_point(t)%create(h5, path, 1, rows, stat, errmsg, integers=.true., vector=.true.)
      end subroutine integer_table
   end subroutine create_point_tables

   !> The datasets of the statistics of every point, empty: the spectrum's bin width (in Hz
   !! and in rad/s) and each entry of `layout` (value and, where it has one, standard error).
   subroutine create_statistics_tables(h5, layout, points, tables, stat, errmsg)
      type(h5_writer), intent(inout) :: h5
      type(statistics_layout), intent(in) :: layout
      integer, intent(in) :: points
      type(point_tables), intent(inout) :: tables
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: rows
      integer :: e
      rows = points
      stat = 0
      errmsg = ''
      if (tables%dynamics) then
         call tables%per_point(t_bin_width)%create(h5, '/sweep/statistics/spectrum/bin_width', 1, rows, stat, errmsg, &
                                                   unit='Hz', vector=.true.)
         if (stat == 0) call tables%per_point(t_bin_width_rad_s)%create(h5, &
                                                                        '/sweep/statistics/spectrum/bin_width_rad_s', &
                                                                        1, rows, stat, errmsg, unit='rad/s', vector=.true.)
         if (stat /= 0) return
      end if
      allocate (tables%values(size(layout%entries)), tables%errors(size(layout%entries)))
      do e = 1, size(layout%entries)
         associate (entry => layout%entries(e))
            call tables%values(e)%create(h5, '/sweep/statistics/'//layout%path(e, .false.), entry%length, rows, &
                                         stat, errmsg, unit=trim(entry%unit), vector=layout%one_value(e), &
                                         layers=entry%layers)
            if (stat == 0 .and. entry%has_error) &
               call tables%errors(e)%create(h5, '/sweep/statistics/'//layout%path(e, .true.), entry%length, rows, &
                                            stat, errmsg, unit=trim(entry%unit), vector=layout%one_value(e), &
                                            layers=entry%layers)
         end associate
         if (stat /= 0) return
      end do
   end subroutine create_statistics_tables

   !> The rows of every point, a block of `block_points` at a time, from the journals;
   !! what each point left (`outcomes`: its Poincare samples, its file, the counts and
   !! messages). Closes the tables.
   subroutine write_points(tables, settings, points, partial, owner, layout, status, file, meter, outcomes, ensemble, &
                           stat, errmsg)
      type(point_tables), intent(inout) :: tables
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      type(sweep_partial), intent(inout) :: partial
      integer, intent(in) :: owner(:)
      type(statistics_layout), intent(in) :: layout
      integer, intent(in) :: status
      character(len=*), intent(in) :: file
      type(progress_meter), intent(inout) :: meter
      type(point_outcomes), intent(out) :: outcomes
      type(sweep_ensemble), intent(inout) :: ensemble   !! fed the points that finished, when an ensemble
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: record(:, :)
      integer :: n, first, count, k, e
      n = size(points)
      allocate (outcomes%kept(n), source=0)
      allocate (outcomes%poincare_first(n), source=0_int64)
      allocate (outcomes%has_file(n), source=.false.)
      outcomes%messages = ''
      stat = 0
      errmsg = ''
      allocate (record(record_length(layout%size), block_points))
      do first = 1, n, block_points
         count = min(block_points, n - first + 1)
         call read_records(partial, owner, first, record(:, 1:count), stat, errmsg)
         if (stat == 0) call write_block(tables, settings, points(first:first + count - 1), owner(first:first + count - 1), &
                                         layout, first, record(:, 1:count), stat, errmsg)
         if (stat == 0) call tally_block(partial, owner, status, first, record(:, 1:count), outcomes, stat, errmsg)
         if (stat /= 0) return
         if (ensemble%axis > 0) then
            do k = 1, count
               if (nint(record(r_status, k)) == status_ok) &
                  call ensemble%add(first + k - 1, record(record_head + 1:record_head + layout%size, k))
            end do
         end if
         if (meter%due()) call meter%report('writing '//file//': '//integer_text(first + count - 1)// &
                                            ' of '//integer_text(n)//' points')
      end do
      do k = 1, size(tables%per_point)
         call tables%per_point(k)%close()
      end do
      do e = 1, size(layout%entries)
         call tables%values(e)%close()
         call tables%errors(e)%close()
      end do
   end subroutine write_points

   !> /sweep/ensemble (docs/output.md, "Sweep file"): for each group of an ensemble, the
   !! other axis' value, its branch, its realisations R, and for every statistic of the
   !! layout the mean over the realisations and the half-width of its 95 % interval, in
   !! the shapes of /sweep/statistics with groups in place of points.
   subroutine write_ensemble(h5, settings, layout, ensemble, stat, errmsg)
      type(h5_writer), intent(inout) :: h5
      type(sweep_settings), intent(in) :: settings
      type(statistics_layout), intent(in) :: layout
      type(sweep_ensemble), intent(in) :: ensemble
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: half(:, :)
      integer :: g, e, other_axis
      allocate (half(layout%size, ensemble%groups))
      do g = 1, ensemble%groups
         half(:, g) = ensemble%half_width(g)
      end do
      other_axis = 3 - ensemble%axis
      stat = 0
      errmsg = ''
      ! a 1-D ensemble has no other axis: one group (per branch)
      if (len_trim(settings%axis(other_axis)%parameter) > 0) then
         call h5%write_real_1d('/sweep/ensemble/parameter', ensemble%other, trim(settings%axis(other_axis)%unit), &
                               stat, errmsg)
         if (stat == 0) call h5%attr_string('/sweep/ensemble/parameter', 'name', &
                                            trim(settings%axis(other_axis)%parameter), stat, errmsg)
      end if
      if (stat == 0) call h5%write_int_1d('/sweep/ensemble/direction', ensemble%direction, stat=stat, errmsg=errmsg)
      if (stat == 0) call h5%write_int_1d('/sweep/ensemble/realisations', ensemble%count, stat=stat, errmsg=errmsg)
      if (stat == 0) call h5%attr_real('/sweep/ensemble', 'confidence', ensemble_confidence, stat, errmsg)
      if (stat == 0) call h5%attr_int('/sweep/ensemble', 'groups', ensemble%groups, stat, errmsg)
      do e = 1, size(layout%entries)
         if (stat /= 0) return
         associate (entry => layout%entries(e), first => layout%entries(e)%offset + 1, &
                    last => layout%entries(e)%offset + layout%entries(e)%length)
            if (entry%group == group_beam .or. entry%group == group_energy) then
               call h5%write_real_1d('/sweep/ensemble/'//layout%path(e, .false.), ensemble%mean(first, :), &
                                     trim(entry%unit), stat, errmsg)
               if (stat == 0) call h5%write_real_1d('/sweep/ensemble/'//layout%path(e, .false.)//'_half_width', &
                                                    half(first, :), trim(entry%unit), stat, errmsg)
            else
               call h5%write_real_2d('/sweep/ensemble/'//layout%path(e, .false.), ensemble%mean(first:last, :), &
                                     trim(entry%unit), stat, errmsg, entry%layers)
               if (stat == 0) call h5%write_real_2d('/sweep/ensemble/'//layout%path(e, .false.)//'_half_width', &
                                                    half(first:last, :), trim(entry%unit), stat, errmsg, entry%layers)
            end if
         end associate
      end do
   end subroutine write_ensemble

   !> The journal records of the points first .. first + size(record, 2) - 1 (a point
   !! without a journal: not run), reading runs of consecutive points of one journal at
   !! once.
   subroutine read_records(partial, owner, first, record, stat, errmsg)
      type(sweep_partial), intent(inout) :: partial
      integer, intent(in) :: owner(:), first
      real(dp), intent(out) :: record(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: count, k, run_start
      stat = 0
      errmsg = ''
      count = size(record, 2)
      record = 0
      record(r_status, :) = status_not_run
      run_start = first
      do k = first, first + count
         if (k < first + count) then
            if (owner(k) == owner(run_start)) cycle
         end if
         if (owner(run_start) /= 0) then
            call partial%read_records(owner(run_start), run_start, record(:, run_start - first + 1:k - first), stat, &
                                      errmsg)
            if (stat /= 0) return
         end if
         run_start = k
      end do
   end subroutine read_records

   !> The rows first .. of every per-point dataset, from the points and their records.
   subroutine write_block(tables, settings, points, owner, layout, first, record, stat, errmsg)
      type(point_tables), intent(inout) :: tables
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)    !! the block's points
      integer, intent(in) :: owner(:)               !! the block's journals
      type(statistics_layout), intent(in) :: layout
      integer, intent(in) :: first
      real(dp), intent(inout) :: record(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: e, first_value, last_value
      stat = 0
      errmsg = ''
      call put(t_parameter, points%value(1))
      if (len_trim(settings%axis(2)%parameter) > 0) call put(t_parameter2, points%value(2))
      call put(t_direction, real(points%direction, dp))
      call put(t_line, real(points%line, dp))
      call put(t_task, real(points%task, dp))
      call put(t_status, record(r_status, :))
      call put(t_start_point, record(r_start_point, :))
      call put(t_wall, record(r_wall, :))
      if (tables%dynamics) call put_dynamics()
      do e = 1, size(layout%entries)
         if (stat /= 0) return
         first_value = record_head + layout%entries(e)%offset + 1
         last_value = record_head + layout%entries(e)%offset + layout%entries(e)%length
         call tables%values(e)%write_rows(int(first, int64), record(first_value:last_value, :), stat, errmsg)
         if (stat == 0 .and. layout%entries(e)%has_error) &
            call tables%errors(e)%write_rows(int(first, int64), record(first_value + layout%size:last_value + &
                                                                        layout%size, :), stat, errmsg)
      end do
   contains
      !> The datasets of time marching (`create_point_tables`).
      subroutine put_dynamics()
         where (owner == 0) record(r_settled, :) = -1
         call put(t_settled, record(r_settled, :))
         call put(t_batches, record(r_batches, :))
         where (owner == 0) record(r_block_steps, :) = 1
         call put(t_batch_steps, record(r_block_steps, :))
         call put(t_poincare_samples, record(r_poincare_total, :))
         call put(t_transient, record(r_settle_steps, :)*record(r_dt, :))
         call put(t_window, record(r_measure_steps, :)*record(r_dt, :))
         call put(t_bin_width, record(r_bin_width, :))
         call put(t_bin_width_rad_s, 2*pi*record(r_bin_width, :))
      end subroutine put_dynamics

      !> Rows first .. of the per-point dataset t.
      subroutine put(t, data)
         integer, intent(in) :: t
         real(dp), intent(in) :: data(:)
         if (stat == 0) call tables%per_point(t)%write_rows(int(first, int64), reshape(data, [1, size(data)]), stat, &
                                                            errmsg)
      end subroutine put
   end subroutine write_block

   !> What the points first .. of the block left: their kept Poincare samples, whether
   !! their result file is in the set, their messages and the counts by status.
   subroutine tally_block(partial, owner, status, first, record, outcomes, stat, errmsg)
      type(sweep_partial), intent(inout) :: partial
      integer, intent(in) :: owner(:), first
      integer, intent(in) :: status
      real(dp), intent(in) :: record(:, :)
      type(point_outcomes), intent(inout) :: outcomes
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=512) :: message
      integer :: j, k
      stat = 0
      errmsg = ''
      do j = 1, size(record, 2)
         k = first + j - 1
         outcomes%kept(k) = nint(record(r_kept, j))
         outcomes%poincare_first(k) = nint(record(r_poincare_first, j), int64)
         outcomes%has_file(k) = owner(k) /= 0 .and. record(r_point_file, j) > 0
         message = ''
         if (owner(k) == 0) then
            message = 'not run'
            if (status == outcome_interrupted) message = 'not run: the sweep was interrupted'
         else if (record(r_message_length, j) > 0) then
            call partial%read_message(owner(k), k, message, stat, errmsg)
            if (stat /= 0) return
         end if
         associate (counts => outcomes%counts)
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
         end associate
         if (len_trim(message) > 0) outcomes%messages = outcomes%messages//'point '//integer_text(k)//': '// &
                                                        trim(message)//new_line('a')
      end do
   end subroutine tally_block

   !> The attributes of /sweep (module documentation).
   subroutine write_attributes(h5, settings, points, threads, ranks, messages, stat, errmsg)
      type(h5_writer), intent(inout) :: h5
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer, intent(in) :: threads, ranks
      character(len=*), intent(in) :: messages
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call h5%attr_string('/sweep', 'mode', trim(settings%mode), stat, errmsg)
      if (stat == 0) call h5%attr_int('/sweep', 'points', size(points), stat, errmsg)
      if (stat == 0) call h5%attr_int('/sweep', 'lines', max(1, size(settings%axis(2)%values)), stat, errmsg)
      if (stat == 0) call h5%attr_int('/sweep', 'tasks', task_count(points), stat, errmsg)
      if (stat == 0) call h5%attr_real('/sweep', 'settle', settings%settle, stat, errmsg)
      if (stat == 0) call h5%attr_real('/sweep', 'measure', settings%measure, stat, errmsg)
      if (stat == 0) call h5%attr_real('/sweep', 'settle_periods', settings%settle_periods, stat, errmsg)
      if (stat == 0) call h5%attr_real('/sweep', 'measure_periods', settings%measure_periods, stat, errmsg)
      if (stat == 0) call h5%attr_real('/sweep', 'steady_tolerance', settings%steady_tolerance, stat, errmsg)
      if (stat == 0) call h5%attr_int('/sweep', 'keep_runs', merge(1, 0, settings%keep_runs), stat, errmsg)
      if (stat == 0) call h5%attr_int('/sweep', 'threads', threads, stat, errmsg)
      if (stat == 0) call h5%attr_int('/sweep', 'ranks', ranks, stat, errmsg)
      if (stat == 0) call h5%attr_string('/sweep', 'messages', messages, stat, errmsg)
   end subroutine write_attributes
end module vibrobeam_sweep_file
