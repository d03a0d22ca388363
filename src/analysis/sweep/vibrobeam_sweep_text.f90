!> The text files of a sweep file (docs/output.md, "Text files"): STEM_sweep.dat, one row
!! per point, a blank line between the lines of a map, and STEM_poincare.dat, one row per
!! kept Poincare sample. Each column is read from its dataset of the sweep file (a table
!! of sources, `table_column`), a block of `sweep_block` points (samples) at a time, so
!! memory does not grow with the sweep. After the two header lines of every text file,
!! one line per column names it, '# 13: impact_rate (1/s)', its unit the dataset's, so a
!! reader or a plot script finds a column by its name.
module vibrobeam_sweep_text
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_text_derivation, only: derivation, text_sink
   use vibrobeam_statistics_layout, only: periodic_names
   implicit none
   private
   public :: sweep_files, table_column, column_lines, read_table, axis_label, sweep_block

   !> Points (samples) read at a time.
   integer, parameter :: sweep_block = 4096

   !> A column of a text file: its name, and where it comes from: value `which` of each
   !! row of the dataset `path`, of `width` values a row (1 for a 1-d dataset); no path or
   !! `which` = 0: zeros. `note`: what its header line adds after the unit (the name of a
   !! swept input).
   type :: table_column
      character(len=40) :: name = ''
      character(len=64) :: path = ''
      integer :: width = 1, which = 1
      character(len=80) :: note = ''
   end type table_column

   !> The pairs of statistics (value, standard error) of the beam and the energy, in
   !! the order of STEM_sweep.dat.
   character(len=*), parameter :: pairs(9) = [character(len=40) :: 'beam/impact_rate', 'beam/episode_rate', &
      'beam/episode_impulse_mean', 'beam/episode_impulse_max', 'beam/contact_force', 'energy/power_input', &
      'energy/power_impacts', 'energy/power_damping', 'energy/power_dissipated']
   !> Force statistics of the compliant stops, at the contact point with the largest
   !! force_peak summed over the points (the most loaded spring; zeros without one).
   character(len=*), parameter :: force_names(7) = [character(len=28) :: 'force_peak', 'force_mean', &
      'force_contact_mean', 'force_contact_rms', 'force_contact_fraction', 'force_episode_duration_mean', &
      'force_episode_duration_max']
   !> The Poincare sequence's diagnostics (docs/statistics.md, "Period, Lyapunov exponent and
   !! the 0-1 test"), after the force statistics: each a column, the Lyapunov exponents with
   !! their standard errors.
   character(len=*), parameter :: diagnostic_names(9) = [character(len=36) :: 'period', 'period_mismatch', &
      'zero_one_k', 'zero_one_lags', 'lyapunov_exponent', 'lyapunov_exponent_error', 'lyapunov_exponent_per_period', &
      'lyapunov_exponent_per_period_error', 'lyapunov_periods']

contains

   !> STEM_sweep.dat and STEM_poincare.dat of the sweep file open in `run`.
   subroutine sweep_files(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: contact_x(:), point_x(:)
      integer(int64), allocatable :: dims(:)
      integer(int64) :: points, samples
      real(dp) :: loaded_x
      integer :: loaded, observation, peaks, width
      character(len=:), allocatable :: first_label, second_label, first_name, second_name
      type(table_column), allocatable :: columns(:)
      logical :: second_axis
      call run%rows_of('/sweep/parameter', points, stat, errmsg)
      second_axis = run%file%exists('/sweep/parameter2')
      if (stat == 0 .and. run%file%exists('/sweep/statistics/periodic')) then
         call orbit_file(run, int(points), second_axis, stat, errmsg)
         return
      end if
      if (stat == 0) call run%file%read_reals('/sweep/statistics/points/x', point_x, stat, errmsg)
      if (stat == 0) observation = size(point_x)
      ! a beam of two planes: (rows, 1 + points, 2), a row of y, z at each point in turn
      if (stat == 0) call run%file%shape('/sweep/statistics/points/displacement_rms', dims, stat, errmsg)
      if (stat == 0) width = observation*merge(2, 1, size(dims) == 3)
      if (stat == 0) call run%file%shape('/sweep/statistics/spectrum/peak_frequency', dims, stat, errmsg)
      if (stat == 0) peaks = int(product(dims(1:size(dims) - 1)))   ! (peaks, points), two planes (2, peaks, points)
      if (stat == 0) call run%file%read_reals('/sweep/statistics/contacts/x', contact_x, stat, errmsg)
      if (stat /= 0) return
      call most_loaded(run, int(points), size(contact_x), loaded, stat, errmsg)
      if (stat /= 0) return
      loaded_x = 0
      if (loaded > 0) loaded_x = contact_x(loaded)
      call axis_label(run, '/sweep/parameter', first_name, first_label, stat, errmsg)
      second_name = 'none'
      second_label = 'none'
      if (stat == 0 .and. second_axis) call axis_label(run, '/sweep/parameter2', second_name, second_label, stat, errmsg)
      if (stat /= 0) return
      columns = point_columns(second_axis, width, peaks, size(contact_x), loaded)
      if (width > observation) columns = [columns, z_columns(width)]
      columns(4)%note = first_name
      columns(5)%note = second_name
      call point_file(run, int(points), columns, first_label, second_label, loaded_x, width > observation, stat, errmsg)
      if (stat /= 0) return
      call run%rows_of('/sweep/poincare/time', samples, stat, errmsg)
      if (stat /= 0) return
      columns = poincare_columns(second_axis, observation)
      columns(1)%note = first_name
      columns(2)%note = second_name
      call poincare_file(run, int(samples), columns, first_label, second_label, stat, errmsg)
      if (stat == 0 .and. run%file%exists('/sweep/ensemble/realisations')) call ensemble_file(run, width, stat, errmsg)
   end subroutine sweep_files

   !> STEM_ensemble.dat of an ensemble (a sweep over forces.realisation; docs/output.md):
   !! one row per group of /sweep/ensemble, the other axis' value, the branch, the
   !! realisations, then the mean and the half-width of the 95 % interval of the
   !! statistics of STEM_sweep.dat's first columns (tip RMS displacement and velocity,
   !! largest tip displacement (in y for a beam of two planes), the beam's and the energy's),
   !! every column named. `observation`: values a row of the points' statistics.
   subroutine ensemble_file(run, observation, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(in) :: observation
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      type(table_column) :: columns(3 + 2*(3 + size(pairs)))
      real(dp), allocatable :: table(:, :)
      character(len=:), allocatable :: name, label, statistic
      integer(int64) :: groups
      integer :: j, k
      character(len=*), parameter :: tip(3) = [character(len=24) :: 'displacement_rms', 'velocity_rms', &
                                               'displacement_max']
      call run%rows_of('/sweep/ensemble/realisations', groups, stat, errmsg)
      if (stat /= 0) return
      name = 'none'
      label = 'none (a 1-D ensemble: one group)'
      columns(1) = table_column('parameter', '')
      if (run%file%exists('/sweep/ensemble/parameter')) then
         call axis_label(run, '/sweep/ensemble/parameter', name, label, stat, errmsg)
         if (stat /= 0) return
         columns(1)%path = '/sweep/ensemble/parameter'
         columns(1)%note = name
      end if
      columns(2) = table_column('direction', '/sweep/ensemble/direction')
      columns(3) = table_column('realisations', '/sweep/ensemble/realisations')
      do j = 1, size(tip)
         columns(2 + 2*j) = table_column('tip_'//trim(tip(j)), '/sweep/ensemble/points/'//trim(tip(j)), observation, 1)
         columns(3 + 2*j) = table_column('tip_'//trim(tip(j))//'_half_width', &
                                         '/sweep/ensemble/points/'//trim(tip(j))//'_half_width', observation, 1)
      end do
      do j = 1, size(pairs)
         statistic = trim(pairs(j)(index(pairs(j), '/') + 1:))
         columns(2 + 2*(size(tip) + j)) = table_column(statistic, '/sweep/ensemble/'//trim(pairs(j)))
         columns(3 + 2*(size(tip) + j)) = table_column(statistic//'_half_width', &
                                                       '/sweep/ensemble/'//trim(pairs(j))//'_half_width')
      end do
      call run%open_sink(sink, 'ensemble', 'one row per value of the other axis ('//label//') and branch: its '// &
                         'value, direction, realisations R, then the mean over the R realisations of each '// &
                         'statistic and the half-width t(0.975, R - 1) s/sqrt(R) of its 95 % interval '// &
                         '(docs/statistics.md, "Ensembles of realisations"); 0: R < 2', stat, errmsg)
      if (stat /= 0) return
      call column_lines(run, sink, columns, stat, errmsg)
      if (stat == 0) call read_table(run, columns, 1, int(groups), table, stat, errmsg)
      do k = 1, int(groups)
         if (stat /= 0) exit
         call sink%put_row('wide', table(:, k), stat, errmsg)
      end do
      call run%close_sink(sink, stat, errmsg)
   end subroutine ensemble_file

   !> The contact point whose force_peak summed over the `points` (in their order) is
   !! largest; 0 when every sum is 0 or there is no contact point.
   subroutine most_loaded(run, points, contacts, loaded, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(in) :: points, contacts
      integer, intent(out) :: loaded
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: sums(:), rows(:, :)
      real(dp) :: largest_sum
      integer :: first, count, k, j
      loaded = 0
      stat = 0
      errmsg = ''
      if (contacts == 0) return
      allocate (sums(contacts), source=0.0_dp)
      do first = 1, points, sweep_block
         count = min(sweep_block, points - first + 1)
         if (allocated(rows)) deallocate (rows)
         allocate (rows(contacts, count))
         call block_rows(run, '/sweep/statistics/contacts/force_peak', first, rows, stat, errmsg)
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
   end subroutine most_loaded

   !> The columns of STEM_sweep.dat (docs/output.md): `observation` values a row in the
   !! points' statistics (the tip first: 'tip_' names), `peaks` dominant frequencies (the
   !! first: 'peak_frequency_1'), the force statistics of contact point `loaded` of
   !! `contacts` ('stop_' names; 0: none, zeros).
   pure function point_columns(second_axis, observation, peaks, contacts, loaded) result(columns)
      logical, intent(in) :: second_axis
      integer, intent(in) :: observation, peaks, contacts, loaded
      type(table_column) :: columns(12 + 2*size(pairs) + 1 + 2*size(force_names) + size(diagnostic_names))
      character(len=:), allocatable :: statistic
      integer :: j
      columns(1) = table_column('point', '')   ! the point's number
      columns(2) = table_column('line', '/sweep/line')
      columns(3) = table_column('direction', '/sweep/direction')
      columns(4) = table_column('parameter', '/sweep/parameter')
      columns(5) = table_column('parameter2', '')
      if (second_axis) columns(5)%path = '/sweep/parameter2'
      columns(6) = table_column('status', '/sweep/status')
      columns(7) = table_column('settled', '/sweep/settled')
      columns(8) = table_column('transient', '/sweep/transient')
      ! the tip is the first observation point of each row
      columns(9) = table_column('tip_displacement_rms', '/sweep/statistics/points/displacement_rms', observation, 1)
      columns(10) = table_column('tip_displacement_rms_error', '/sweep/statistics/points/displacement_rms_error', &
                                 observation, 1)
      columns(11) = table_column('tip_displacement_max', '/sweep/statistics/points/displacement_max', observation, 1)
      columns(12) = table_column('tip_displacement_max_error', '/sweep/statistics/points/displacement_max_error', &
                                 observation, 1)
      do j = 1, size(pairs)
         statistic = trim(pairs(j)(index(pairs(j), '/') + 1:))
         columns(11 + 2*j) = table_column(statistic, '/sweep/statistics/'//trim(pairs(j)))
         columns(12 + 2*j) = table_column(statistic//'_error', '/sweep/statistics/'//trim(pairs(j))//'_error')
      end do
      columns(13 + 2*size(pairs)) = table_column('peak_frequency_1', '/sweep/statistics/spectrum/peak_frequency', &
                                                 peaks, 1)
      do j = 1, size(force_names)
         columns(12 + 2*size(pairs) + 2*j) = table_column('stop_'//trim(force_names(j)), &
                                                          '/sweep/statistics/contacts/'//trim(force_names(j)), &
                                                          contacts, loaded)
         columns(13 + 2*size(pairs) + 2*j) = table_column('stop_'//trim(force_names(j))//'_error', &
                                                          '/sweep/statistics/contacts/'//trim(force_names(j))// &
                                                          '_error', contacts, loaded)
      end do
      do j = 1, size(diagnostic_names)
         columns(13 + 2*size(pairs) + 2*size(force_names) + j) = &
            table_column(trim(diagnostic_names(j)), '/sweep/statistics/poincare/'//trim(diagnostic_names(j)))
      end do
   end function point_columns

   !> The columns after STEM_sweep.dat's planar ones for a beam of two planes, whose points'
   !! statistics hold `width` values a row (y, z at each point): the tip's RMS and largest
   !! displacement in z, each with its standard error.
   pure function z_columns(width) result(columns)
      integer, intent(in) :: width
      type(table_column) :: columns(4)
      character(len=*), parameter :: names(2) = [character(len=16) :: 'displacement_rms', 'displacement_max']
      integer :: j
      do j = 1, 2
         columns(2*j - 1) = table_column('tip_'//trim(names(j))//'_z', '/sweep/statistics/points/'//trim(names(j)), &
                                         width, 2)
         columns(2*j) = table_column('tip_'//trim(names(j))//'_z_error', &
                                     '/sweep/statistics/points/'//trim(names(j))//'_error', width, 2)
      end do
   end function z_columns

   !> The columns of STEM_poincare.dat (the tip first of `observation`).
   pure function poincare_columns(second_axis, observation) result(columns)
      logical, intent(in) :: second_axis
      integer, intent(in) :: observation
      type(table_column) :: columns(7)
      columns(1) = table_column('parameter', '/sweep/poincare/parameter')
      columns(2) = table_column('parameter2', '')
      if (second_axis) columns(2)%path = '/sweep/poincare/parameter2'
      columns(3) = table_column('direction', '/sweep/poincare/direction')
      columns(4) = table_column('point', '/sweep/poincare/point')
      columns(5) = table_column('time', '/sweep/poincare/time')
      columns(6) = table_column('tip_displacement', '/sweep/poincare/displacement', observation, 1)
      columns(7) = table_column('tip_velocity', '/sweep/poincare/velocity', observation, 1)
   end function poincare_columns

   !> STEM_sweep.dat: one row per point, a blank line where the line changes; `z_plane`:
   !! the columns end with `z_columns`.
   subroutine point_file(run, points, columns, first_label, second_label, loaded_x, z_plane, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(in) :: points
      type(table_column), intent(in) :: columns(:)
      character(len=*), intent(in) :: first_label, second_label
      real(dp), intent(in) :: loaded_x
      logical, intent(in) :: z_plane
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: z_note
      z_note = ''
      if (z_plane) z_note = '; then (a beam of two planes) value and standard error of the RMS tip displacement '// &
                            'in z (m) and of the largest (m); the tip columns before are the y plane''s'
      call row_file(run, points, columns, 'point  line  direction (+1 up, -1 down, 0 independent)  parameter: '// &
                    first_label//'  parameter2: '//second_label//'  status (0 ok)  settled (1, 0, -1 not '// &
                    'asked)  transient (s)  then value and '// &
                    'standard error of: RMS tip displacement (m)  largest tip displacement (m)  impact rate (1/s)'// &
                    '  episode rate (1/s)  mean impulse per episode (N s)  largest impulse per episode (N s)  '// &
                    'contact force (N)  power of the loads (W)  power dissipated at the stops (W)  by damping (W)'// &
                    '  in all (W); then the first dominant frequency (Hz); then value and standard error of '// &
                    'the compliant stops'' force at x = '//real_text(loaded_x)//' m (0: no spring; docs/statistics.md): '// &
                    'peak (N)  mean (N)  mean in contact (N)'// &
                    '  RMS in contact (N)  contact fraction (1)  mean episode duration (s)  longest episode (s); '// &
                    'then the Poincare samples'' period (0: none, -1: not determined) and mismatch, the 0-1 '// &
                    'test''s K and lags, the Lyapunov exponent (1/s) and per forcing period with their errors, '// &
                    'and its periods'//z_note, stat, errmsg)
   end subroutine point_file

   !> STEM_sweep.dat of a sweep of periodic analyses (docs/output.md, "Text files"): per
   !! point its number, line, direction, parameters, status, then /sweep/statistics/periodic
   !! (`periodic_names`) and its wall time; each point's orbit or branch is in its point file.
   subroutine orbit_file(run, points, second_axis, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(in) :: points
      logical, intent(in) :: second_axis
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(table_column) :: columns(6 + size(periodic_names) + 1)
      character(len=:), allocatable :: first_label, second_label, first_name, second_name
      integer :: j
      call axis_label(run, '/sweep/parameter', first_name, first_label, stat, errmsg)
      second_name = 'none'
      second_label = 'none'
      if (stat == 0 .and. second_axis) call axis_label(run, '/sweep/parameter2', second_name, second_label, stat, errmsg)
      if (stat /= 0) return
      columns(1) = table_column('point', '')
      columns(2) = table_column('line', '/sweep/line')
      columns(3) = table_column('direction', '/sweep/direction')
      columns(4) = table_column('parameter', '/sweep/parameter', note=first_name)
      columns(5) = table_column('parameter2', '', note=second_name)
      if (second_axis) columns(5)%path = '/sweep/parameter2'
      columns(6) = table_column('status', '/sweep/status')
      do j = 1, size(periodic_names)
         columns(6 + j) = table_column(trim(periodic_names(j)), '/sweep/statistics/periodic/'//trim(periodic_names(j)))
      end do
      columns(size(columns)) = table_column('wall_seconds', '/sweep/wall_seconds')
      call row_file(run, points, columns, 'point  line  direction (+1 up, -1 down, 0 independent)  parameter: '// &
                    first_label//'  parameter2: '//second_label//'  status (0 ok)  then of the point''s orbit (of its '// &
                    'branch''s first orbit): period (s)  largest Floquet multiplier modulus  Newton iterations; its '// &
                    'branch''s points and bifurcations (0: no continuation); the time steps it took; its wall time '// &
                    '(s). The orbit or branch itself is in the point''s file (STEM_point<k>.h5)', stat, errmsg)
   end subroutine orbit_file

   !> STEM_sweep.dat with the given header: one row per point, a blank line where the line changes.
   subroutine row_file(run, points, columns, header, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(in) :: points
      type(table_column), intent(in) :: columns(:)
      character(len=*), intent(in) :: header
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: table(:, :)   ! (column, point) of a block
      real(dp) :: previous_line
      integer :: first, count, k
      call run%open_sink(sink, 'sweep', header, stat, errmsg)
      if (stat /= 0) return
      call column_lines(run, sink, columns, stat, errmsg)
      if (stat /= 0) then
         call run%close_sink(sink, stat, errmsg)
         return
      end if
      previous_line = 0
      blocks: do first = 1, points, sweep_block
         count = min(sweep_block, points - first + 1)
         call read_table(run, columns, first, count, table, stat, errmsg)
         if (stat /= 0) exit blocks
         table(1, :) = [(real(k, dp), k = first, first + count - 1)]
         do k = 1, count
            if (first + k > 2 .and. nint(table(2, k)) /= nint(previous_line)) call sink%put_line('', stat, errmsg)
            if (stat == 0) call sink%put_row('wide', table(:, k), stat, errmsg)
            if (stat /= 0) exit blocks
            previous_line = table(2, k)
         end do
      end do blocks
      call run%close_sink(sink, stat, errmsg)
   end subroutine row_file

   !> STEM_poincare.dat: one row per kept Poincare sample.
   subroutine poincare_file(run, samples, columns, first_label, second_label, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(in) :: samples
      type(table_column), intent(in) :: columns(:)
      character(len=*), intent(in) :: first_label, second_label
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: table(:, :)   ! (column, sample) of a block
      integer :: first, count, k
      call run%open_sink(sink, 'poincare', 'parameter: '//first_label//'  parameter2: '//second_label// &
                         '  direction  point  time in the point''s run (s)  '// &
                         'tip displacement (m)  tip velocity (m/s), at phase 0 of the forcing', stat, errmsg)
      if (stat /= 0) return
      call column_lines(run, sink, columns, stat, errmsg)
      if (stat /= 0) then
         call run%close_sink(sink, stat, errmsg)
         return
      end if
      blocks: do first = 1, samples, sweep_block
         count = min(sweep_block, samples - first + 1)
         call read_table(run, columns, first, count, table, stat, errmsg)
         if (stat /= 0) exit blocks
         do k = 1, count
            call sink%put_row('wide', table(:, k), stat, errmsg)
            if (stat /= 0) exit blocks
         end do
      end do blocks
      call run%close_sink(sink, stat, errmsg)
   end subroutine poincare_file

   !> The rows first .. first + count - 1 of every column (zeros for a column without a
   !! source): table(column, row).
   subroutine read_table(run, columns, first, count, table, stat, errmsg)
      type(derivation), intent(inout) :: run
      type(table_column), intent(in) :: columns(:)
      integer, intent(in) :: first, count
      real(dp), allocatable, intent(out) :: table(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: rows(:, :)
      integer :: j
      stat = 0
      errmsg = ''
      allocate (table(size(columns), count), source=0.0_dp)
      do j = 1, size(columns)
         if (len_trim(columns(j)%path) == 0 .or. columns(j)%which == 0) cycle
         allocate (rows(columns(j)%width, count))
         call block_rows(run, trim(columns(j)%path), first, rows, stat, errmsg)
         if (stat /= 0) return
         table(j, :) = rows(columns(j)%which, :)
         deallocate (rows)
      end do
   end subroutine read_table

   !> Rows first .. first + size(rows, 2) - 1 of the dataset `path` of size(rows, 1)
   !! values a row (1 for a 1-d dataset).
   subroutine block_rows(run, path, first, rows, stat, errmsg)
      type(derivation), intent(inout) :: run
      character(len=*), intent(in) :: path
      integer, intent(in) :: first
      real(dp), intent(out), contiguous :: rows(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      rows = 0
      call run%file%read_rows(path, int(first, int64), rows, stat, errmsg)
   end subroutine block_rows

   !> One header line per column: '# 13: impact_rate (1/s)', the unit that of its dataset
   !! ('1' when it has none, or the column no dataset), then the column's note if any.
   subroutine column_lines(run, sink, columns, stat, errmsg)
      type(derivation), intent(inout) :: run
      type(text_sink), intent(inout) :: sink
      type(table_column), intent(in) :: columns(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: unit, line
      integer :: j
      stat = 0
      errmsg = ''
      do j = 1, size(columns)
         unit = ''
         if (len_trim(columns(j)%path) > 0) then
            if (run%file%has_attr(trim(columns(j)%path), 'unit')) &
               call run%file%attr_string(trim(columns(j)%path), 'unit', unit, stat, errmsg)
            if (stat /= 0) return
         end if
         if (len(unit) == 0) unit = '1'
         line = '# '//integer_text(j)//': '//trim(columns(j)%name)//' ('//unit//')'
         if (len_trim(columns(j)%note) > 0) line = line//' '//trim(columns(j)%note)
         call sink%put_line(line, stat, errmsg)
         if (stat /= 0) return
      end do
   end subroutine column_lines

   !> The name attribute of an axis, and its label 'load.base_frequency (rad/s)' (with
   !! the unit attribute).
   subroutine axis_label(run, path, name, label, stat, errmsg)
      type(derivation), intent(inout) :: run
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: name, label
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: unit
      name = ''
      label = ''
      call run%file%attr_string(path, 'name', name, stat, errmsg)
      if (stat == 0) call run%file%attr_string(path, 'unit', unit, stat, errmsg)
      if (stat /= 0) return
      if (len(unit) == 0) unit = '1'
      label = name//' ('//unit//')'
   end subroutine axis_label
end module vibrobeam_sweep_text
