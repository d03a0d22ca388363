!> /sweep/poincare of a sweep file (docs/output.md, "Sweep file"): the kept Poincare
!! samples of every point, read from the chunks of the journals a chunk at a time
!! (`vibrobeam_sweep_journal`), so memory does not grow with the samples.
module vibrobeam_sweep_poincare_file
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_table
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point
   use vibrobeam_sweep_partial, only: sweep_partial
   implicit none
   private
   public :: write_poincare

   !> The Poincare chunks of one journal, grouped by point: order(first(k) : first(k+1) - 1)
   !! are the columns of `table` (point, first row, rows) of point k's chunks, in order.
   type :: journal_chunks
      logical :: loaded = .false.
      real(dp), allocatable :: table(:, :)
      integer, allocatable :: first(:), order(:)
   end type journal_chunks

contains

   !> The kept Poincare samples of every point, one row per sample, in the order of the
   !! points (`observations` points observed): from the chunks of the journal that holds
   !! the point as done, its r_poincare_first first rows skipped (earlier windows), then
   !! r_kept rows, read a chunk at a time.
   subroutine write_poincare(h5, settings, points, partial, owner, kept, poincare_first, observations, stat, errmsg)
      type(h5_writer), intent(inout) :: h5
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      type(sweep_partial), intent(inout) :: partial
      integer, intent(in) :: owner(:)
      integer, intent(in) :: kept(:)                      !! (points) Poincare samples kept
      integer(int64), intent(in) :: poincare_first(:)    !! (points) its rows in the journal's chunks to skip
      integer, intent(in) :: observations
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(h5_table) :: point, direction, first_value, second_value, time, u, v
      type(journal_chunks), allocatable :: journals(:)
      real(dp), allocatable :: rows(:, :)
      integer(int64) :: row, total, skip, first_row
      integer :: k, c, count, left
      logical :: second_axis
      second_axis = len_trim(settings%axis(2)%parameter) > 0
      total = sum(int(kept, int64))
      allocate (journals(max(1, maxval([0, owner]))))
      call point%create(h5, '/sweep/poincare/point', 1, total, stat, errmsg, integers=.true., vector=.true.)
      if (stat == 0) call direction%create(h5, '/sweep/poincare/direction', 1, total, stat, errmsg, &
                                           integers=.true., vector=.true.)
      if (stat == 0) call first_value%create(h5, '/sweep/poincare/parameter', 1, total, stat, errmsg, &
                                             unit=trim(settings%axis(1)%unit), vector=.true.)
      if (stat == 0 .and. second_axis) &
         call second_value%create(h5, '/sweep/poincare/parameter2', 1, total, stat, errmsg, &
                                  unit=trim(settings%axis(2)%unit), vector=.true.)
      if (stat == 0) call time%create(h5, '/sweep/poincare/time', 1, total, stat, errmsg, unit='s', vector=.true.)
      if (stat == 0) call u%create(h5, '/sweep/poincare/displacement', observations, total, stat, errmsg, unit='m')
      if (stat == 0) call v%create(h5, '/sweep/poincare/velocity', observations, total, stat, errmsg, unit='m/s')
      row = 1
      points_loop: do k = 1, size(points)
         if (stat /= 0 .or. kept(k) == 0) cycle
         associate (chunks => journals(owner(k)))
            if (.not. chunks%loaded) call load_chunks(chunks, owner(k))
            if (stat /= 0) exit points_loop
            skip = poincare_first(k)
            left = kept(k)
            do c = chunks%first(k), chunks%first(k + 1) - 1
               if (left == 0) exit
               associate (chunk => chunks%table(:, chunks%order(c)))
                  if (skip >= nint(chunk(3), int64)) then
                     skip = skip - nint(chunk(3), int64)
                     cycle
                  end if
                  first_row = nint(chunk(2), int64) + skip
                  count = int(min(int(left, int64), nint(chunk(3), int64) - skip))
                  skip = 0
               end associate
               if (allocated(rows)) deallocate (rows)
               allocate (rows(1 + 2*observations, count))
               call partial%read_poincare(owner(k), first_row, rows, stat, errmsg)
               if (stat == 0) call write_samples(k, count)
               if (stat /= 0) exit points_loop
               left = left - count
            end do
         end associate
      end do points_loop
      call point%close()
      call direction%close()
      call first_value%close()
      call second_value%close()
      call time%close()
      call u%close()
      call v%close()
   contains
      !> The chunk table of journal j, its chunks grouped by point (in their order).
      subroutine load_chunks(chunks, j)
         type(journal_chunks), intent(inout) :: chunks
         integer, intent(in) :: j
         integer :: c, p
         integer :: next(size(points))
         call partial%read_chunks(j, chunks%table, stat, errmsg)
         if (stat /= 0) return
         allocate (chunks%first(size(points) + 1), source=0)
         allocate (chunks%order(size(chunks%table, 2)), source=0)
         do c = 1, size(chunks%table, 2)
            p = nint(chunks%table(1, c))
            if (p >= 1 .and. p <= size(points)) chunks%first(p + 1) = chunks%first(p + 1) + 1
         end do
         chunks%first(1) = 1
         do p = 1, size(points)
            chunks%first(p + 1) = chunks%first(p) + chunks%first(p + 1)
         end do
         next = chunks%first(1:size(points))
         do c = 1, size(chunks%table, 2)
            p = nint(chunks%table(1, c))
            if (p < 1 .or. p > size(points)) cycle
            chunks%order(next(p)) = c
            next(p) = next(p) + 1
         end do
         chunks%loaded = .true.
      end subroutine load_chunks

      !> rows(:, 1:count) of point k at `row`.
      subroutine write_samples(k, count)
         integer, intent(in) :: k, count
         call point%write_rows(row, spread(spread(real(k, dp), 1, 1), 2, count), stat, errmsg)
         if (stat == 0) call direction%write_rows(row, spread(spread(real(points(k)%direction, dp), 1, 1), 2, count), &
                                                  stat, errmsg)
         if (stat == 0) call first_value%write_rows(row, spread(spread(points(k)%value(1), 1, 1), 2, count), stat, &
                                                    errmsg)
         if (stat == 0 .and. second_axis) &
            call second_value%write_rows(row, spread(spread(points(k)%value(2), 1, 1), 2, count), stat, errmsg)
         if (stat == 0) call time%write_rows(row, rows(1:1, :), stat, errmsg)
         if (stat == 0) call u%write_rows(row, rows(2:1 + observations, :), stat, errmsg)
         if (stat == 0) call v%write_rows(row, rows(2 + observations:, :), stat, errmsg)
         row = row + count
      end subroutine write_samples
   end subroutine write_poincare
end module vibrobeam_sweep_poincare_file
