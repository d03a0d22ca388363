!> Bit-for-bit comparisons of sweep results (docs/sweeps.md). The references are other
!! runs of the same program, so no tolerance: equal bit patterns.
!!
!! usage: compare_sweep point SWEEP.h5 K RUN.h5
!!    point K of the sweep file equals the single run RUN.h5 (the same scene with the
!!    parameter set, t_end = settle + measure, measure_from = settle): every statistic and
!!    standard error of /sweep/statistics row K equals /statistics of the run, and the
!!    Poincare samples the sweep kept for K are the last ones of the run's.
!! usage: compare_sweep same A.h5 B.h5
!!    two sweep files hold the same results: every dataset of /sweep (the wall-clock
!!    times /sweep/wall_seconds excepted) is equal, e.g. with 1 and 2 threads or ranks.
program compare_sweep
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_real_2d, read_real_3d, read_int_1d, read_attr_int, &
      h5_path_exists
   use vibrobeam_statistics_layout, only: statistics_layout, group_wear
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   type(statistics_layout) :: layout
   character(len=4096) :: mode, first, second, argument
   character(len=512) :: errmsg
   integer :: stat, k, e, point, compared

   call get_command_argument(1, mode)
   call get_command_argument(2, first)
   call layout_of(trim(first))
   select case (trim(mode))
   case ('point')
      call get_command_argument(3, argument)
      read (argument, *) point
      call get_command_argument(4, second)
      call compare_point()
   case ('same')
      call get_command_argument(3, second)
      call compare_files()
   case default
      call t%check_true('usage: compare_sweep point SWEEP.h5 K RUN.h5 | same A.h5 B.h5', .false.)
   end select
   call t%finish('compare_sweep '//trim(mode))

contains

   !> The layout of the sweep file's statistics (a beam of two planes: its obstacles'
   !! points, /sweep/statistics/wear/x, and what the file holds of the wear volume rate and
   !! the power of friction; its points' statistics in y and z: a 3-d dataset).
   subroutine layout_of(file)
      character(len=*), intent(in) :: file
      real(dp), allocatable :: x(:), c(:), w(:), cube(:, :, :)
      integer :: obstacles, planes
      allocate (w(0))
      call read_real_1d(file, '/sweep/statistics/points/x', x, stat, errmsg)
      if (stat == 0) call read_real_1d(file, '/sweep/statistics/contacts/x', c, stat, errmsg)
      if (stat == 0) call read_attr_int(file, '/', 'obstacles.count', obstacles, stat, errmsg)
      if (stat == 0 .and. h5_path_exists(file, '/sweep/statistics/wear/x')) &
         call read_real_1d(file, '/sweep/statistics/wear/x', w, stat, errmsg)
      call t%check_true('read the layout of '//file, stat == 0, errmsg)
      if (stat /= 0) call t%finish('compare_sweep')
      call read_real_3d(file, '/sweep/statistics/points/displacement_mean', cube, stat, errmsg)
      planes = merge(2, 1, stat == 0)
      call layout%init(size(x), size(c), obstacles, size(w), &
                       h5_path_exists(file, '/sweep/statistics/wear/wear_volume_rate'), &
                       h5_path_exists(file, '/sweep/statistics/energy/power_friction'), planes)
   end subroutine layout_of

   !> Row `point` of a /sweep/statistics dataset (1-d, 2-d, or 3-d: y, z of each value).
   function sweep_row(file, path, e) result(row)
      character(len=*), intent(in) :: file, path
      integer, intent(in) :: e
      real(dp), allocatable :: row(:), column(:), table(:, :), cube(:, :, :)
      allocate (row(0))
      if (layout%entries(e)%layers > 1) then
         call read_real_3d(file, path, cube, stat, errmsg)
         if (stat == 0) row = reshape(cube(:, :, point), [size(cube(:, :, point))])
      else if (layout%one_value(e)) then
         call read_real_1d(file, path, column, stat, errmsg)
         if (stat == 0) row = column(point:point)
      else
         call read_real_2d(file, path, table, stat, errmsg)
         if (stat == 0) row = table(:, point)
      end if
      call t%check_true('read '//path, stat == 0, errmsg)
   end function sweep_row

   !> The values of the run's statistic `path` (a beam of two planes: `layers` = 2, y, z of
   !! each point side by side, as a sweep row).
   function run_values(path, layers) result(values)
      character(len=*), intent(in) :: path
      integer, intent(in) :: layers
      real(dp), allocatable :: values(:), table(:, :)
      allocate (values(0))
      if (layers > 1) then
         call read_real_2d(trim(second), path, table, stat, errmsg)
         if (stat == 0) values = reshape(table, [size(table)])
      else
         call read_real_1d(trim(second), path, values, stat, errmsg)
      end if
   end function run_values

   subroutine compare_point()
      real(dp), allocatable :: a(:), b(:), time(:), run_time(:), u(:, :), run_u(:, :)
      integer, allocatable :: owners(:)
      integer :: rows, j
      do e = 1, size(layout%entries)
         do k = 0, 1
            if (k == 1 .and. .not. layout%entries(e)%has_error) cycle
            a = sweep_row(trim(first), '/sweep/statistics/'//layout%path(e, k == 1), e)
            b = run_values('/statistics/'//layout%path(e, k == 1), layout%entries(e)%layers)
            call t%check_true('read run '//layout%path(e, k == 1), stat == 0, errmsg)
            if (stat == 0) call t%check_true(layout%path(e, k == 1)//' of point '//integer_text(point)// &
                                             ' equals the single run', same_bits(a, b), 'differs')
         end do
      end do
      ! a beam of two planes: the run's /wear holds the same numbers as its /statistics/wear
      do e = 1, size(layout%entries)
         if (layout%entries(e)%group /= group_wear) cycle
         do k = 0, 1
            call read_real_1d(trim(second), '/statistics/'//layout%path(e, k == 1), a, stat, errmsg)
            if (stat == 0) call read_real_1d(trim(second), '/'//layout%path(e, k == 1), b, stat, errmsg)
            call t%check_true('read run /'//layout%path(e, k == 1), stat == 0, errmsg)
            if (stat == 0) call t%check_true('/'//layout%path(e, k == 1)//' of the run equals its /statistics/'// &
                                             layout%path(e, k == 1), same_bits(a, b), 'differs')
         end do
      end do
      ! the kept Poincare samples: the last ones of the run
      call read_int_1d(trim(first), '/sweep/poincare/point', owners, stat, errmsg)
      if (stat == 0) call read_real_1d(trim(first), '/sweep/poincare/time', time, stat, errmsg)
      if (stat == 0) call read_real_2d(trim(first), '/sweep/poincare/displacement', u, stat, errmsg)
      if (stat == 0) call read_real_1d(trim(second), '/statistics/poincare/time', run_time, stat, errmsg)
      if (stat == 0) call read_real_2d(trim(second), '/statistics/poincare/displacement', run_u, stat, errmsg)
      call t%check_true('read the Poincare samples', stat == 0, errmsg)
      if (stat /= 0) return
      rows = count(owners == point)
      call t%check_true('Poincare samples of point '//integer_text(point), rows > 0 .and. rows <= size(run_time), &
                        integer_text(rows)//' kept, '//integer_text(size(run_time))//' in the run')
      if (rows == 0 .or. rows > size(run_time)) return
      j = findloc(owners, point, dim=1)
      call t%check_true('Poincare times of point '//integer_text(point)//' equal the run''s last', &
                        same_bits(time(j:j + rows - 1), run_time(size(run_time) - rows + 1:)))
      call t%check_true('Poincare displacements of point '//integer_text(point)//' equal the run''s last', &
                        same_bits(reshape(u(:, j:j + rows - 1), [size(u, 1)*rows]), &
                                  reshape(run_u(:, size(run_time) - rows + 1:), [size(u, 1)*rows])))
   end subroutine compare_point

   subroutine compare_files()
      character(len=*), parameter :: reals(*) = [character(len=40) :: '/sweep/parameter', '/sweep/transient', &
         '/sweep/window', '/sweep/statistics/points/x', '/sweep/statistics/contacts/x', &
         '/sweep/statistics/spectrum/bin_width', '/sweep/poincare/parameter', '/sweep/poincare/time']
      character(len=*), parameter :: integers(*) = [character(len=40) :: '/sweep/direction', '/sweep/line', &
         '/sweep/task', '/sweep/status', '/sweep/start_point', '/sweep/settled', '/sweep/batches', &
         '/sweep/batch_steps', '/sweep/poincare_samples', '/sweep/poincare/point', '/sweep/poincare/direction']
      character(len=*), parameter :: matrices(*) = [character(len=40) :: '/sweep/poincare/displacement', &
         '/sweep/poincare/velocity']
      real(dp), allocatable :: a(:), b(:), x(:, :), y(:, :), xs(:, :, :), ys(:, :, :)
      integer, allocatable :: i(:), j(:)
      compared = 0
      do k = 1, size(reals)
         call read_real_1d(trim(first), trim(reals(k)), a, stat, errmsg)
         if (stat == 0) call read_real_1d(trim(second), trim(reals(k)), b, stat, errmsg)
         call equal(trim(reals(k)), same_bits(a, b))
      end do
      do k = 1, size(integers)
         call read_int_1d(trim(first), trim(integers(k)), i, stat, errmsg)
         if (stat == 0) call read_int_1d(trim(second), trim(integers(k)), j, stat, errmsg)
         call equal(trim(integers(k)), size(i) == size(j) .and. all(i == j))
      end do
      do k = 1, size(matrices)
         call read_real_2d(trim(first), trim(matrices(k)), x, stat, errmsg)
         if (stat == 0) call read_real_2d(trim(second), trim(matrices(k)), y, stat, errmsg)
         call equal(trim(matrices(k)), same_bits(reshape(x, [size(x)]), reshape(y, [size(y)])))
      end do
      do e = 1, size(layout%entries)
         do k = 0, 1
            if (k == 1 .and. .not. layout%entries(e)%has_error) cycle
            associate (path => '/sweep/statistics/'//layout%path(e, k == 1))
               if (layout%entries(e)%layers > 1) then
                  call read_real_3d(trim(first), path, xs, stat, errmsg)
                  if (stat == 0) call read_real_3d(trim(second), path, ys, stat, errmsg)
                  call equal(path, same_bits(reshape(xs, [size(xs)]), reshape(ys, [size(ys)])))
               else if (layout%one_value(e)) then
                  call read_real_1d(trim(first), path, a, stat, errmsg)
                  if (stat == 0) call read_real_1d(trim(second), path, b, stat, errmsg)
                  call equal(path, same_bits(a, b))
               else
                  call read_real_2d(trim(first), path, x, stat, errmsg)
                  if (stat == 0) call read_real_2d(trim(second), path, y, stat, errmsg)
                  call equal(path, same_bits(reshape(x, [size(x)]), reshape(y, [size(y)])))
               end if
            end associate
         end do
      end do
      call t%check_true('every dataset compared', compared > 10)
   end subroutine compare_files

   !> A dataset read from both files (stat) is the same in both.
   subroutine equal(path, same)
      character(len=*), intent(in) :: path
      logical, intent(in) :: same
      call t%check_true('read '//path//' of both files', stat == 0, errmsg)
      if (stat == 0) call t%check_true(path//' is the same in both files', same, 'differs')
      compared = compared + 1
   end subroutine equal

   !> Equal bit patterns.
   pure logical function same_bits(x, y)
      real(dp), intent(in) :: x(:), y(:)
      same_bits = size(x) == size(y)
      if (same_bits) same_bits = all(transfer(x, 1_int64, size(x)) == transfer(y, 1_int64, size(y)))
   end function same_bits
end program compare_sweep
