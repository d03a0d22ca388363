!> The result of a sweep (docs/output.md, "Sweep file"): one HDF5 file, written when the
!! points are done and published like a run's result (temporary name, fsync, rename under
!! the directory lock, text files derived from it).
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
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_model, only: beam_model
   use vibrobeam_result_files, only: result_files, run_summary
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_statistics_layout, only: statistics_layout, group_beam, group_energy
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, task_count
   use vibrobeam_sweep_runner, only: point_result, status_ok, status_failed, status_interrupted, status_names
   implicit none
   private
   public :: write_sweep_file

contains

   !> Write and publish the sweep file `scene%output%file`. `status` is the /run status ('ok' or
   !! 'interrupted'); `threads` and `ranks` what ran it. stat /= 0: nothing is published.
   subroutine write_sweep_file(scene, model, settings, points, results, layout, point_x, contact_x, &
                               lower_obstacle, upper_obstacle, status, wall_seconds, threads, ranks, meter, &
                               text_skipped, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      type(point_result), intent(in) :: results(:)
      type(statistics_layout), intent(in) :: layout
      real(dp), intent(in) :: point_x(:), contact_x(:), wall_seconds
      integer, intent(in) :: lower_obstacle(:), upper_obstacle(:), threads, ranks
      character(len=*), intent(in) :: status
      type(progress_meter), intent(inout) :: meter
      logical, intent(out) :: text_skipped
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(result_files) :: files
      type(run_summary) :: summary
      real(dp), allocatable :: values(:, :), errors(:, :)
      integer :: n, k, e, first, last
      character(len=:), allocatable :: messages, path
      text_skipped = .false.
      n = size(points)
      call files%open(scene, model, stat, errmsg)
      if (stat /= 0) then
         call files%discard()
         return
      end if
      write_all: block
         associate (h5 => files%h5)
            call axis_dataset('/sweep/parameter', 1)
            if (stat == 0 .and. len_trim(settings%axis(2)%parameter) > 0) call axis_dataset('/sweep/parameter2', 2)
            if (stat == 0) call h5%write_int_1d('/sweep/direction', points%direction, stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/line', points%line, stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/task', points%task, stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/status', results%status, stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%attr_string('/sweep/status', 'meaning', status_names, stat, errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/start_point', results%start_point, stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/settled', results%settled, stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/batches', [(results(k)%statistics%batches, k = 1, n)], &
                                                stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/batch_steps', &
                                                [(int(results(k)%statistics%block_steps), k = 1, n)], &
                                                stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/poincare_samples', &
                                                [(int(results(k)%statistics%poincare_total), k = 1, n)], &
                                                stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_real_1d('/sweep/transient', results%settle_steps*results%dt, 's', &
                                                 stat, errmsg)
            if (stat == 0) call h5%write_real_1d('/sweep/window', results%measure_steps*results%dt, 's', stat, errmsg)
            if (stat == 0) call h5%write_real_1d('/sweep/wall_seconds', results%wall_seconds, 's', stat, errmsg)
            if (stat /= 0) exit write_all
            ! statistics
            if (stat == 0) call h5%write_real_1d('/sweep/statistics/points/x', point_x, 'm', stat, errmsg)
            if (stat == 0) call h5%write_real_1d('/sweep/statistics/contacts/x', contact_x, 'm', stat, errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/statistics/contacts/lower_obstacle', lower_obstacle, &
                                                stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_int_1d('/sweep/statistics/contacts/upper_obstacle', upper_obstacle, &
                                                stat=stat, errmsg=errmsg)
            if (stat == 0) call h5%write_real_1d('/sweep/statistics/spectrum/bin_width', &
                                                 [(results(k)%statistics%bin_width, k = 1, n)], 'Hz', stat, errmsg)
            if (stat /= 0) exit write_all
            allocate (values(layout%size, n), errors(layout%size, n), source=0.0_dp)
            do k = 1, n
               if (.not. allocated(results(k)%statistics%values)) cycle
               if (size(results(k)%statistics%values) /= layout%size) cycle
               values(:, k) = results(k)%statistics%values
               errors(:, k) = results(k)%statistics%errors
            end do
            do e = 1, size(layout%entries)
               first = layout%entries(e)%offset + 1
               last = layout%entries(e)%offset + layout%entries(e)%length
               call statistic('/sweep/statistics/'//layout%path(e, .false.), values(first:last, :), e)
               if (stat == 0 .and. layout%entries(e)%has_error) &
                  call statistic('/sweep/statistics/'//layout%path(e, .true.), errors(first:last, :), e)
               if (stat /= 0) exit write_all
            end do
            call write_poincare()
            if (stat /= 0) exit write_all
            ! attributes
            call h5%attr_string('/sweep', 'mode', trim(settings%mode), stat, errmsg)
            if (stat == 0) call h5%attr_int('/sweep', 'points', n, stat, errmsg)
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
            messages = ''
            do k = 1, n
               if (len_trim(results(k)%message) > 0) messages = messages//'point '//integer_text(k)//': '// &
                                                                trim(results(k)%message)//new_line('a')
            end do
            if (stat == 0) call h5%attr_string('/sweep', 'messages', messages, stat, errmsg)
            if (stat /= 0) exit write_all
         end associate
         summary%status = status
         summary%wall_seconds = wall_seconds
         call files%set_run(summary, stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/run', 'points_ok', count(results%status == status_ok), stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/run', 'points_failed', count(results%status == status_failed), &
                                               stat, errmsg)
         if (stat == 0) call files%h5%attr_int('/run', 'points_interrupted', &
                                               count(results%status == status_interrupted), stat, errmsg)
         if (stat /= 0) exit write_all
         call files%publish(meter, status /= 'interrupted', text_skipped, stat, errmsg)
         if (stat == 0) return
      end block write_all
      call files%discard()
      if (stat == 0) stat = 1
   contains
      !> Values of axis `a` with its name and unit.
      subroutine axis_dataset(name, a)
         character(len=*), intent(in) :: name
         integer, intent(in) :: a
         call files%h5%write_real_1d(name, points%value(a), trim(settings%axis(a)%unit), stat, errmsg)
         if (stat == 0) call files%h5%attr_string(name, 'name', trim(settings%axis(a)%parameter), stat, errmsg)
      end subroutine axis_dataset

      !> One statistic of every point: 1-d for the groups of one value, (points, n) otherwise.
      subroutine statistic(name, data, e)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: data(:, :)
         integer, intent(in) :: e
         if (layout%entries(e)%group == group_beam .or. layout%entries(e)%group == group_energy) then
            call files%h5%write_real_1d(name, data(1, :), trim(layout%entries(e)%unit), stat, errmsg)
         else
            call files%h5%write_real_2d(name, data, trim(layout%entries(e)%unit), stat, errmsg)
         end if
      end subroutine statistic

      !> The kept Poincare samples of every point, one row per sample.
      subroutine write_poincare()
         integer :: total, j, row, observation
         integer, allocatable :: owner(:), direction(:)
         real(dp), allocatable :: time(:), first_value(:), second_value(:), u(:, :), v(:, :)
         total = 0
         do k = 1, n
            if (allocated(results(k)%statistics%poincare_time)) total = total + size(results(k)%statistics%poincare_time)
         end do
         observation = size(point_x)
         allocate (owner(total), direction(total), time(total), first_value(total), second_value(total), &
                   u(observation, total), v(observation, total))
         row = 0
         do k = 1, n
            if (.not. allocated(results(k)%statistics%poincare_time)) cycle
            do j = 1, size(results(k)%statistics%poincare_time)
               row = row + 1
               owner(row) = k
               direction(row) = points(k)%direction
               first_value(row) = points(k)%value(1)
               second_value(row) = points(k)%value(2)
               time(row) = results(k)%statistics%poincare_time(j)
               u(:, row) = results(k)%statistics%poincare_values(1:observation, j)
               v(:, row) = results(k)%statistics%poincare_values(observation + 1:, j)
            end do
         end do
         path = '/sweep/poincare/'
         call files%h5%write_int_1d(path//'point', owner, stat=stat, errmsg=errmsg)
         if (stat == 0) call files%h5%write_int_1d(path//'direction', direction, stat=stat, errmsg=errmsg)
         if (stat == 0) call files%h5%write_real_1d(path//'parameter', first_value, trim(settings%axis(1)%unit), &
                                                    stat, errmsg)
         if (stat == 0 .and. len_trim(settings%axis(2)%parameter) > 0) &
            call files%h5%write_real_1d(path//'parameter2', second_value, trim(settings%axis(2)%unit), stat, errmsg)
         if (stat == 0) call files%h5%write_real_1d(path//'time', time, 's', stat, errmsg)
         if (stat == 0) call files%h5%write_real_2d(path//'displacement', u, 'm', stat, errmsg)
         if (stat == 0) call files%h5%write_real_2d(path//'velocity', v, 'm/s', stat, errmsg)
      end subroutine write_poincare
   end subroutine write_sweep_file
end module vibrobeam_sweep_file
