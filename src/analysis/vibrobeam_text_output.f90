!> The gnuplot-ready .dat files of a result, derived from its HDF5 file (docs/output.md,
!! "Text files"): after a run with `&output text = .true.`, and by `vibrobeam --text
!! FILE.h5` at any time later. The HDF5 file is read a block of rows at a time, so a
!! long run's text files need no more memory than a short run's.
!!
!! Names follow the HDF5 file: results/run.h5 gives results/run_tip.dat, ...
!! (`text_file_name`). Each file is written under its own temporary name
!! (`unique_temporary_name`), every write checked, closed and synced; the caller renames
!! the set (`vibrobeam_result_files: publish_files`). Line 1 of each file names the run
!! ('# vibrobeam run <run_id> (<file>.h5)', the /run run_id attribute), line 2 its
!! columns and units.
module vibrobeam_text_output
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_filesystem, only: text_file, open_text_for_atomic_write, write_text_line, write_text_row, &
      finish_text_file, discard_text_file
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   implicit none
   private
   public :: derived_file, derive_text_files, discard_derived, text_file_name, text_suffixes, path_length

   integer, parameter :: path_length = 1024

   !> Every suffix a result's .dat files can have.
   character(len=*), parameter :: text_suffixes(18) = [character(len=16) :: 'modes', 'shapes', 'static', &
      'reactions', 'tip', 'energy', 'impacts', 'episodes', 'points', 'field', 'spectrum', 'obstacles', 'contact', &
      'force', 'sweep', 'poincare', 'orbit', 'multipliers']

   !> Most values read from the HDF5 file at once (8 MiB).
   integer, parameter :: block_values = 2**20

   !> A derived file, complete under its temporary name.
   type :: derived_file
      character(len=path_length) :: temporary = ''
      character(len=path_length) :: final = ''
   end type derived_file

   !> One .dat file being written.
   type :: text_sink
      type(text_file) :: file
      character(len=:), allocatable :: temporary, final
   end type text_sink

contains

   !> '<stem>_<suffix>.dat' for a result file 'stem.h5'.
   pure function text_file_name(h5_name, suffix) result(name)
      character(len=*), intent(in) :: h5_name, suffix
      character(len=:), allocatable :: name
      integer :: n
      n = len_trim(h5_name)
      if (n > 3) then
         if (h5_name(n - 2:n) == '.h5') n = n - 3
      end if
      name = h5_name(1:n)//'_'//suffix//'.dat'
   end function text_file_name

   !> Delete the temporary files of `files`.
   subroutine discard_derived(files)
      type(derived_file), intent(in) :: files(:)
      integer :: k
      type(text_file) :: closed
      do k = 1, size(files)
         call discard_text_file(closed, trim(files(k)%temporary))
      end do
   end subroutine discard_derived

   !> Derive every .dat file of the HDF5 file `source` (the temporary file of a run, or a
   !! published file), named after `final_h5`. On return `files` lists them, complete and
   !! synced under temporary names. With `stop_on_signal`, SIGINT/SIGTERM stops the
   !! derivation (a run already stopped by a signal passes .false.: its result gets its
   !! text files, and a second signal ends the process): `interrupted` is set, nothing is
   !! left and `files` is empty. On failure nothing is left either.
   subroutine derive_text_files(source, final_h5, meter, stop_on_signal, files, interrupted, stat, errmsg)
      character(len=*), intent(in) :: source, final_h5
      type(progress_meter), intent(inout) :: meter
      logical, intent(in) :: stop_on_signal
      type(derived_file), allocatable, intent(out) :: files(:)
      logical, intent(out) :: interrupted
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(h5_reader) :: file
      character(len=:), allocatable :: run_id, header
      integer :: slash

      allocate (files(0))
      interrupted = .false.
      call file%open(source, stat, errmsg)
      if (stat /= 0) return
      call file%attr_string('/run', 'run_id', run_id, stat, errmsg)
      if (stat /= 0) then
         call file%close()
         return
      end if
      slash = index(final_h5, '/', back=.true.)
      header = '# vibrobeam run '//run_id//' ('//final_h5(slash + 1:)//')'
      derive: block
         if (file%exists('/modes/frequency')) then
            call modes_files()
            if (stat /= 0 .or. interrupted) exit derive
         end if
         if (file%exists('/static/displacement')) then
            call static_files()
            if (stat /= 0 .or. interrupted) exit derive
         end if
         if (file%exists('/periodic/orbit/time')) then
            call periodic_files()
            if (stat /= 0 .or. interrupted) exit derive
         end if
         if (file%exists('/time')) call dynamics_files()
         if (stat /= 0 .or. interrupted) exit derive
         if (file%exists('/sweep/parameter')) call sweep_files()
      end block derive
      call file%close()
      if (stat /= 0 .or. interrupted) then
         call discard_derived(files)
         deallocate (files)
         allocate (files(0))
      end if

   contains

      !> Open '<stem>_<suffix>.dat' with its two header lines.
      subroutine open_sink(sink, suffix, columns)
         type(text_sink), intent(out) :: sink
         character(len=*), intent(in) :: suffix, columns
         sink%final = text_file_name(final_h5, suffix)
         call open_text_for_atomic_write(sink%final, sink%file, sink%temporary, stat, errmsg)
         if (stat /= 0) return
         call put_line(sink, header)
         call put_line(sink, '# '//columns)
         if (meter%due()) call meter%report('deriving '//sink%final)
      end subroutine open_sink

      !> Write one line, checked.
      subroutine put_line(sink, line)
         type(text_sink), intent(inout) :: sink
         character(len=*), intent(in) :: line
         if (stat /= 0) return
         call write_text_line(sink%file, line, sink%temporary, stat, errmsg)
      end subroutine put_line

      !> Write one row of numbers (`layout`: 'wide' es24.15-like, 'narrow' es16.7-like;
      !! the last `integers` values as integers), checked.
      subroutine put_row(sink, layout, values, integers)
         type(text_sink), intent(inout) :: sink
         character(len=*), intent(in) :: layout
         real(dp), intent(in) :: values(:)
         integer, intent(in), optional :: integers
         integer :: tail
         if (stat /= 0) return
         tail = 0
         if (present(integers)) tail = integers
         if (layout == 'narrow') then
            call write_text_row(sink%file, values, 16, 7, tail, sink%temporary, stat, errmsg)
         else
            call write_text_row(sink%file, values, 24, 15, tail, sink%temporary, stat, errmsg)
         end if
      end subroutine put_row

      !> Close and sync `sink` and add it to `files`; on failure delete it.
      subroutine close_sink(sink)
         type(text_sink), intent(inout) :: sink
         type(derived_file) :: done
         if (stat == 0) call finish_text_file(sink%file, sink%temporary, stat, errmsg)
         if (stat /= 0) then
            call discard_text_file(sink%file, sink%temporary)
            return
         end if
         done%temporary = sink%temporary
         done%final = sink%final
         files = [files, done]
      end subroutine close_sink

      !> Rows of the datasets `paths` (each 1-d of `rows` values, or 2-d of
      !! widths(k) columns) side by side, `form` per row, a block of rows at a time;
      !! `field` writes the gnuplot blocks of the displacement field instead.
      subroutine stream_rows(sink, paths, widths, rows, form, integers)
         type(text_sink), intent(inout) :: sink
         character(len=*), intent(in) :: paths(:)
         integer, intent(in) :: widths(:)
         integer(int64), intent(in) :: rows
         character(len=*), intent(in) :: form      !! layout of `put_row`
         integer, intent(in), optional :: integers
         real(dp), allocatable :: block(:, :), part(:, :)
         integer(int64) :: first
         integer :: count, k, column, i
         count = int(max(1_int64, min(rows, int(block_values/max(1, sum(widths)), int64))))
         allocate (block(sum(widths), count))
         first = 1
         do while (first <= rows .and. stat == 0)
            count = int(min(int(size(block, 2), int64), rows - first + 1))
            column = 1
            do k = 1, size(paths)
               allocate (part(widths(k), count))
               call file%read_rows(trim(paths(k)), first, part, stat, errmsg)
               if (stat /= 0) return
               block(column:column + widths(k) - 1, 1:count) = part
               column = column + widths(k)
               deallocate (part)
            end do
            do i = 1, count
               call put_row(sink, form, block(:, i), integers)
            end do
            first = first + count
            if (stop_on_signal .and. interrupt_requested()) then
               interrupted = .true.
               return
            end if
            if (meter%due()) call meter%report('deriving '//sink%final//': '// &
                                               integer_text(int(100*(first - 1)/max(rows, 1_int64)))//' %')
         end do
      end subroutine stream_rows

      !> Rows of the 1-d dataset `path` (0 when it is missing).
      integer(int64) function rows_of(path)
         character(len=*), intent(in) :: path
         integer(int64), allocatable :: dims(:)
         rows_of = 0
         if (stat /= 0 .or. .not. file%exists(path)) return
         call file%shape(path, dims, stat, errmsg)
         if (stat == 0 .and. size(dims) > 0) rows_of = dims(size(dims))
      end function rows_of

      subroutine modes_files()
         type(text_sink) :: sink
         real(dp), allocatable :: omega(:), x(:), shapes(:)
         character(len=64) :: line
         integer :: k, i, nodes
         call file%read_reals('/modes/frequency', omega, stat, errmsg)
         if (stat == 0) call file%read_reals('/mesh/x', x, stat, errmsg)
         if (stat == 0) call file%read_reals('/modes/shape', shapes, stat, errmsg)
         if (stat /= 0) return
         call open_sink(sink, 'modes', 'mode  omega (rad/s)  frequency (Hz)')
         do k = 1, size(omega)
            write (line, '(i6, 2es24.15)') k, omega(k), omega(k)/(2*pi)
            call put_line(sink, trim(line))
         end do
         call close_sink(sink)
         if (stat /= 0) return
         call open_sink(sink, 'shapes', 'x (m)  then the shape of mode 1, 2, ... (tip value 1)')
         nodes = size(x)
         do i = 1, nodes
            call put_row(sink, 'wide', [x(i), (shapes(i + (k - 1)*nodes), k=1, size(omega))])
         end do
         call close_sink(sink)
      end subroutine modes_files

      !> A periodic orbit: its tip over one period, and its Floquet multipliers.
      subroutine periodic_files()
         type(text_sink) :: sink
         real(dp), allocatable :: time(:), u(:), v(:), multipliers(:)
         integer :: i
         call file%read_reals('/periodic/orbit/time', time, stat, errmsg)
         if (stat == 0) call file%read_reals('/periodic/orbit/tip_displacement', u, stat, errmsg)
         if (stat == 0) call file%read_reals('/periodic/orbit/tip_velocity', v, stat, errmsg)
         if (stat /= 0) return
         call open_sink(sink, 'orbit', 't (s)  tip u (m)  tip v (m/s): one period of the orbit')
         do i = 1, size(time)
            call put_row(sink, 'wide', [time(i), u(i), v(i)])
         end do
         call close_sink(sink)
         if (stat /= 0 .or. .not. file%exists('/periodic/floquet_multipliers')) return
         call file%read_reals('/periodic/floquet_multipliers', multipliers, stat, errmsg)
         if (stat /= 0) return
         call open_sink(sink, 'multipliers', 'real  imaginary  modulus: the Floquet multipliers, largest modulus first')
         do i = 1, size(multipliers)/2
            call put_row(sink, 'wide', [multipliers(2*i - 1), multipliers(2*i), hypot(multipliers(2*i - 1), &
                                                                                  multipliers(2*i))])
         end do
         call close_sink(sink)
      end subroutine periodic_files

      subroutine static_files()
         type(text_sink) :: sink
         real(dp), allocatable :: x(:), u(:), contact_x(:), reaction(:)
         integer :: i
         call file%read_reals('/mesh/x', x, stat, errmsg)
         if (stat == 0) call file%read_reals('/static/displacement', u, stat, errmsg)
         if (stat == 0) call file%read_reals('/static/contact_x', contact_x, stat, errmsg)
         if (stat == 0) call file%read_reals('/static/reaction', reaction, stat, errmsg)
         if (stat /= 0) return
         call open_sink(sink, 'static', 'x (m)  u (m)')
         do i = 1, size(x)
            call put_row(sink, 'wide', [x(i), u(i)])
         end do
         call close_sink(sink)
         if (stat /= 0) return
         call open_sink(sink, 'reactions', 'x (m)  reaction (N, positive upwards)')
         do i = 1, size(contact_x)
            call put_row(sink, 'wide', [contact_x(i), reaction(i)])
         end do
         call close_sink(sink)
      end subroutine static_files

      subroutine dynamics_files()
         type(text_sink) :: sink
         integer(int64) :: outputs, impacts, episodes, snapshots, bins
         real(dp), allocatable :: x(:), lower(:), upper(:), fraction(:), times(:, :), field(:, :)
         integer :: points, nodes, i, k
         integer(int64) :: first, count
         outputs = rows_of('/time')
         impacts = rows_of('/impacts/time')
         episodes = rows_of('/episodes/x')
         snapshots = rows_of('/field/time')
         bins = rows_of('/spectrum/frequency')
         if (stat /= 0) return
         call open_sink(sink, 'tip', 't (s)  u_tip (m)  v_tip (m/s)  mean tip contact force over the output '// &
                        'interval = tip impulse/interval (N)  tip impulse over the interval (N s)')
         call stream_rows(sink, [character(len=40) :: '/time', '/tip/displacement', '/tip/velocity', '/tip/reaction', &
                                 '/tip/impulse'], [1, 1, 1, 1, 1], outputs, 'wide')
         call close_sink(sink)
         if (stat /= 0 .or. interrupted) return
         call open_sink(sink, 'energy', 't (s)  kinetic  elastic  work of loads  dissipated (impacts + damping + '// &
                        'numerical)  dissipated by impacts  by damping  total = kinetic + elastic  balance = total - '// &
                        'work + dissipated (J)  penetration (m)  dissipated by the theta-method (J)')
         call stream_rows(sink, [character(len=40) :: '/time', '/energy/kinetic', '/energy/elastic', '/energy/work', &
                                 '/energy/dissipated', '/energy/dissipated_impacts', '/energy/dissipated_damping', &
                                 '/energy/total', '/energy/balance', '/contact/penetration', &
                                 '/energy/dissipated_numerical'], [(1, k=1, 11)], outputs, 'wide')
         call close_sink(sink)
         if (stat /= 0 .or. interrupted) return
         call open_sink(sink, 'impacts', 't (s)  x (m)  impulse (N s)  velocity before (m/s)  velocity after (m/s)')
         call stream_rows(sink, [character(len=40) :: '/impacts/time', '/impacts/x', '/impacts/impulse', &
                                 '/impacts/velocity_before', '/impacts/velocity_after'], [1, 1, 1, 1, 1], impacts, &
                          'wide')
         call close_sink(sink)
         if (stat /= 0 .or. interrupted) return
         call open_sink(sink, 'episodes', 'x (m)  start (s)  end (s)  total impulse (N s)  largest approach '// &
                        'speed (m/s)  impacts  open at the end of the run (1)')
         call stream_rows(sink, [character(len=40) :: '/episodes/x', '/episodes/start', '/episodes/end', &
                                 '/episodes/impulse', '/episodes/approach_speed', '/episodes/impacts', &
                                 '/episodes/open_at_end'], [(1, k=1, 7)], episodes, 'wide', integers=2)
         call close_sink(sink)
         if (stat /= 0 .or. interrupted) return
         if (file%exists('/points/x')) then
            call file%read_reals('/points/x', x, stat, errmsg)
            if (stat /= 0) return
            points = size(x)
            call open_sink(sink, 'points', 't (s)  then u (m) at each observation point x = '// &
                           points_text(x)//' m, then v (m/s) at each')
            call stream_rows(sink, [character(len=40) :: '/time', '/points/displacement', '/points/velocity'], &
                             [1, points, points], outputs, 'wide')
            call close_sink(sink)
            if (stat /= 0 .or. interrupted) return
         end if
         if (file%exists('/contact/force')) then
            ! compliant stops: the force at each contact point (docs/output.md)
            call file%read_reals('/contact/x', x, stat, errmsg)
            if (stat /= 0) return
            points = size(x)
            call open_sink(sink, 'force', 't (s)  then the compliant stops'' force (N) at each contact point x = '// &
                           points_text(x)//' m')
            call stream_rows(sink, [character(len=40) :: '/time', '/contact/force'], [1, points], outputs, 'wide')
            call close_sink(sink)
            if (stat /= 0 .or. interrupted) return
         end if
         ! the field: one gnuplot block per snapshot, x t u
         call file%read_reals('/mesh/x', x, stat, errmsg)
         if (stat /= 0) return
         nodes = size(x)
         call open_sink(sink, 'field', 'x (m)  t (s)  u (m); one block per snapshot (gnuplot splot/pm3d)')
         count = max(1_int64, int(block_values/nodes, int64))
         first = 1
         do while (first <= snapshots .and. stat == 0)
            count = min(count, snapshots - first + 1)
            allocate (times(1, count), field(nodes, count))
            call file%read_rows('/field/time', first, times, stat, errmsg)
            if (stat == 0) call file%read_rows('/field/displacement', first, field, stat, errmsg)
            if (stat /= 0) return
            do k = 1, int(count)
               do i = 1, nodes
                  call put_row(sink, 'narrow', [x(i), times(1, k), field(i, k)])
               end do
               call put_line(sink, '')
            end do
            deallocate (times, field)
            first = first + count
            if (stop_on_signal .and. interrupt_requested()) then
               interrupted = .true.
               return
            end if
         end do
         call close_sink(sink)
         if (stat /= 0 .or. interrupted) return
         call open_sink(sink, 'spectrum', 'frequency (Hz)  amplitude of the tip displacement (m): single-sided, '// &
                        'mean removed, Hann window, Welch average over segments of 2^16 samples when longer')
         call stream_rows(sink, [character(len=40) :: '/spectrum/frequency', '/spectrum/tip_amplitude'], [1, 1], &
                          bins, 'wide')
         call close_sink(sink)
         if (stat /= 0 .or. interrupted) return
         call file%read_reals('/contact/x', x, stat, errmsg)
         if (stat == 0) call file%read_reals('/contact/lower', lower, stat, errmsg)
         if (stat == 0) call file%read_reals('/contact/upper', upper, stat, errmsg)
         if (stat == 0) call file%read_reals('/contact/fraction', fraction, stat, errmsg)
         if (stat /= 0) return
         call open_sink(sink, 'obstacles', 'x (m)  lower bound g1 (m)  upper bound g2 (m) at each contact point '// &
                        '(+-1e30: no obstacle on that side)')
         do k = 1, size(x)
            call put_row(sink, 'wide', [x(k), max(-1e30_dp, lower(k)), min(1e30_dp, upper(k))])
         end do
         call close_sink(sink)
         if (stat /= 0) return
         call open_sink(sink, 'contact', 'x (m)  fraction of the run in contact (1)')
         do k = 1, size(x)
            call put_row(sink, 'wide', [x(k), fraction(k)])
         end do
         call close_sink(sink)
      end subroutine dynamics_files

      !> A sweep file (docs/output.md, "Sweep file"): STEM_sweep.dat, one row per point,
      !! and STEM_poincare.dat, one row per kept Poincare sample; read a block of
      !! `sweep_block` points (samples) at a time, so memory does not grow with the sweep.
      subroutine sweep_files()
         character(len=*), parameter :: pairs(9) = [character(len=40) :: 'beam/impact_rate', 'beam/episode_rate', &
            'beam/episode_impulse_mean', 'beam/episode_impulse_max', 'beam/contact_force', 'energy/power_input', &
            'energy/power_impacts', 'energy/power_damping', 'energy/power_dissipated']
         !> Force statistics of the compliant stops, at the contact point with the largest
         !! force_peak summed over the points (the most loaded spring; zeros without one).
         character(len=*), parameter :: force_names(7) = [character(len=28) :: 'force_peak', 'force_mean', &
            'force_contact_mean', 'force_contact_rms', 'force_contact_fraction', 'force_episode_duration_mean', &
            'force_episode_duration_max']
         integer, parameter :: sweep_block = 4096
         real(dp), allocatable :: contact_x(:), sums(:), column(:), rows(:, :), table(:, :)
         integer(int64), allocatable :: dims(:)
         ! (table(column, point): the block's columns of STEM_sweep.dat or STEM_poincare.dat)
         real(dp) :: largest_sum, loaded_x, previous_line
         integer :: contacts, loaded, n, k, j, first, count, observation, samples, peaks
         type(text_sink) :: sink
         character(len=:), allocatable :: first_label, second_label
         logical :: second_axis
         n = int(rows_of('/sweep/parameter'))
         second_axis = file%exists('/sweep/parameter2')
         if (stat == 0) call file%read_reals('/sweep/statistics/points/x', column, stat, errmsg)
         if (stat == 0) observation = size(column)
         if (stat == 0) call file%shape('/sweep/statistics/spectrum/peak_frequency', dims, stat, errmsg)
         if (stat == 0) peaks = int(dims(1))   ! (peaks, points)
         if (stat == 0) call file%read_reals('/sweep/statistics/contacts/x', contact_x, stat, errmsg)
         if (stat /= 0) return
         contacts = size(contact_x)
         ! the most loaded contact point: force_peak summed over the points in their order
         loaded = 0
         if (contacts > 0) then
            allocate (sums(contacts), source=0.0_dp)
            do first = 1, n, sweep_block
               count = min(sweep_block, n - first + 1)
               if (allocated(rows)) deallocate (rows)
               allocate (rows(contacts, count))
               call block_rows('/sweep/statistics/contacts/force_peak', first, rows)
               if (stat /= 0) return
               do k = 1, count
                  sums = sums + rows(:, k)
               end do
            end do
            largest_sum = 0
            do j = 1, contacts
               if (sums(j) <= largest_sum) cycle
               largest_sum = sums(j)
               loaded = j
            end do
         end if
         loaded_x = 0
         if (loaded > 0) loaded_x = contact_x(loaded)
         call axis_label('/sweep/parameter', first_label)
         second_label = 'none'
         if (second_axis) call axis_label('/sweep/parameter2', second_label)
         if (stat /= 0) return
         call open_sink(sink, 'sweep', 'point  line  direction (+1 up, -1 down, 0 independent)  parameter: '// &
                        first_label//'  parameter2: '//second_label//'  status (0 ok)  settled (1, 0, -1 not '// &
                        'asked)  transient (s)  then value and '// &
                        'standard error of: RMS tip displacement (m)  largest tip displacement (m)  impact rate (1/s)'// &
                        '  episode rate (1/s)  mean impulse per episode (N s)  largest impulse per episode (N s)  '// &
                        'contact force (N)  power of the loads (W)  power dissipated at the stops (W)  by damping (W)'// &
                        '  in all (W); then the first dominant frequency (Hz); then value and standard error of '// &
                        'the compliant stops'' force at x = '//real_text(loaded_x)//' m (0: no spring; docs/statistics.md): '// &
                        'peak (N)  mean (N)  mean in contact (N)'// &
                        '  RMS in contact (N)  contact fraction (1)  mean episode duration (s)  longest episode (s)')
         ! the columns of a block of points: table(column, point)
         previous_line = 0
         do first = 1, n, sweep_block
            count = min(sweep_block, n - first + 1)
            if (allocated(table)) deallocate (table)
            allocate (table(12 + 2*size(pairs) + 1 + 2*size(force_names), count), source=0.0_dp)
            table(1, :) = [(real(k, dp), k = first, first + count - 1)]
            call block_column('/sweep/line', 1, 1, first, table(2, :))
            call block_column('/sweep/direction', 1, 1, first, table(3, :))
            call block_column('/sweep/parameter', 1, 1, first, table(4, :))
            if (second_axis) call block_column('/sweep/parameter2', 1, 1, first, table(5, :))
            call block_column('/sweep/status', 1, 1, first, table(6, :))
            call block_column('/sweep/settled', 1, 1, first, table(7, :))
            call block_column('/sweep/transient', 1, 1, first, table(8, :))
            ! the tip is the first observation point of each row
            call block_column('/sweep/statistics/points/displacement_rms', observation, 1, first, table(9, :))
            call block_column('/sweep/statistics/points/displacement_rms_error', observation, 1, first, &
                              table(10, :))
            call block_column('/sweep/statistics/points/displacement_max', observation, 1, first, table(11, :))
            call block_column('/sweep/statistics/points/displacement_max_error', observation, 1, first, &
                              table(12, :))
            do j = 1, size(pairs)
               call block_column('/sweep/statistics/'//trim(pairs(j)), 1, 1, first, table(11 + 2*j, :))
               call block_column('/sweep/statistics/'//trim(pairs(j))//'_error', 1, 1, first, table(12 + 2*j, :))
            end do
            call block_column('/sweep/statistics/spectrum/peak_frequency', peaks, 1, first, &
                              table(13 + 2*size(pairs), :))
            do j = 1, size(force_names)
               if (loaded == 0) exit
               call block_column('/sweep/statistics/contacts/'//trim(force_names(j)), contacts, loaded, first, &
                                 table(12 + 2*size(pairs) + 2*j, :))
               call block_column('/sweep/statistics/contacts/'//trim(force_names(j))//'_error', contacts, loaded, &
                                 first, table(13 + 2*size(pairs) + 2*j, :))
            end do
            if (stat /= 0) return
            do k = 1, count
               if (first + k > 2 .and. nint(table(2, k)) /= nint(previous_line)) call put_line(sink, '')
               previous_line = table(2, k)
               call put_row(sink, 'wide', table(:, k))
            end do
         end do
         call close_sink(sink)
         if (stat /= 0) return
         samples = int(rows_of('/sweep/poincare/time'))
         if (stat /= 0) return
         call open_sink(sink, 'poincare', 'parameter: '//first_label//'  parameter2: '//second_label// &
                        '  direction  point  time in the point''s run (s)  '// &
                        'tip displacement (m)  tip velocity (m/s), at phase 0 of the forcing')
         do first = 1, samples, sweep_block
            count = min(sweep_block, samples - first + 1)
            if (allocated(table)) deallocate (table)
            allocate (table(7, count), source=0.0_dp)
            call block_column('/sweep/poincare/parameter', 1, 1, first, table(1, :))
            if (second_axis) call block_column('/sweep/poincare/parameter2', 1, 1, first, table(2, :))
            call block_column('/sweep/poincare/direction', 1, 1, first, table(3, :))
            call block_column('/sweep/poincare/point', 1, 1, first, table(4, :))
            call block_column('/sweep/poincare/time', 1, 1, first, table(5, :))
            call block_column('/sweep/poincare/displacement', observation, 1, first, table(6, :))
            call block_column('/sweep/poincare/velocity', observation, 1, first, table(7, :))
            if (stat /= 0) return
            do k = 1, count
               call put_row(sink, 'wide', table(:, k))
            end do
         end do
         call close_sink(sink)
      end subroutine sweep_files

      !> Rows first .. first + size(rows, 2) - 1 of the dataset `path` of size(rows, 1)
      !! values a row (1 for a 1-d dataset).
      subroutine block_rows(path, first, rows)
         character(len=*), intent(in) :: path
         integer, intent(in) :: first
         real(dp), intent(out), contiguous :: rows(:, :)
         rows = 0
         if (stat == 0) call file%read_rows(path, int(first, int64), rows, stat, errmsg)
      end subroutine block_rows

      !> Value `which` of the rows first .. of the dataset `path` of `columns` values a row
      !! (1-d: columns = which = 1), into `column`.
      subroutine block_column(path, columns, which, first, column)
         character(len=*), intent(in) :: path
         integer, intent(in) :: columns, which, first
         real(dp), intent(inout) :: column(:)
         real(dp) :: rows(columns, size(column))
         call block_rows(path, first, rows)
         if (stat == 0) column = rows(which, :)
      end subroutine block_column

      !> 'load.base_frequency (rad/s)': the name and unit attributes of an axis.
      subroutine axis_label(path, label)
         character(len=*), intent(in) :: path
         character(len=:), allocatable, intent(out) :: label
         character(len=:), allocatable :: name, unit
         label = ''
         call file%attr_string(path, 'name', name, stat, errmsg)
         if (stat == 0) call file%attr_string(path, 'unit', unit, stat, errmsg)
         if (stat /= 0) return
         if (len(unit) == 0) unit = '1'
         label = name//' ('//unit//')'
      end subroutine axis_label

   end subroutine derive_text_files

   !> '0.1, 0.25' for the observation points' x.
   function points_text(x) result(text)
      real(dp), intent(in) :: x(:)
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      integer :: k
      text = ''
      do k = 1, size(x)
         write (buffer, '(g0.6)') x(k)
         text = text//trim(adjustl(buffer))
         if (k < size(x)) text = text//', '
      end do
   end function points_text
end module vibrobeam_text_output
