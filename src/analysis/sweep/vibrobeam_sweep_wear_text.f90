!> STEM_wear.dat of a sweep of a beam of two planes with obstacles (docs/output.md, "Text
!! files"): the wear at each point of the obstacles against the swept parameter, one block
!! per point (gnuplot's `index`: blocks are parted by two blank lines), one row per sweep
!! point: its number, the parameters, its status, then the value and standard error of
!! each quantity of /sweep/statistics/wear (docs/statistics.md, "Wear at the supports").
!! A comment line opens each block: the point's x and its obstacle. Read a block of
!! `sweep_block` sweep points at a time, as the other text files of a sweep.
module vibrobeam_sweep_wear_text
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_text_derivation, only: derivation, text_sink
   use vibrobeam_statistics_layout, only: wear_names
   use vibrobeam_sweep_text, only: table_column, column_lines, read_table, axis_label, sweep_block
   implicit none
   private
   public :: sweep_wear_file

contains

   !> STEM_wear.dat of the sweep file open in `run`, when it has /sweep/statistics/wear.
   subroutine sweep_wear_file(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      type(table_column), allocatable :: columns(:)
      real(dp), allocatable :: x(:), obstacle(:), table(:, :)
      character(len=:), allocatable :: first_name, first_label, second_name, second_label
      integer(int64) :: points
      integer :: w, q, first, count, k
      stat = 0
      errmsg = ''
      if (.not. run%file%exists('/sweep/statistics/wear/x')) return
      call run%rows_of('/sweep/parameter', points, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/sweep/statistics/wear/x', x, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/sweep/statistics/wear/obstacle', obstacle, stat, errmsg)
      if (stat == 0) call axis_label(run, '/sweep/parameter', first_name, first_label, stat, errmsg)
      second_name = 'none'
      second_label = 'none'
      if (stat == 0 .and. run%file%exists('/sweep/parameter2')) &
         call axis_label(run, '/sweep/parameter2', second_name, second_label, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'wear', 'one block per point of the obstacles (gnuplot index 0, 1, ...), one row per '// &
                         'sweep point: point  parameter: '//first_label//'  parameter2: '//second_label// &
                         '  status (0 ok)  then value and standard error of the wear work rate (W)  mean normal '// &
                         'force (N)  RMS normal force (N)  contact fraction  sliding fraction  impact rate (1/s)'// &
                         '  (with a wear_coefficient) wear volume rate (m^3/s); docs/statistics.md, "Wear at the '// &
                         'supports"', stat, errmsg)
      if (stat /= 0) return
      blocks: do w = 1, size(x)
         allocate (columns(0))
         columns = [table_column('point', ''), table_column('parameter', '/sweep/parameter', note=first_name), &
                    table_column('parameter2', '', note=second_name), table_column('status', '/sweep/status')]
         if (run%file%exists('/sweep/parameter2')) columns(3)%path = '/sweep/parameter2'
         do q = 1, size(wear_names)
            if (.not. run%file%exists('/sweep/statistics/wear/'//trim(wear_names(q)))) cycle
            columns = [columns, table_column(trim(wear_names(q)), '/sweep/statistics/wear/'//trim(wear_names(q)), &
                                             size(x), w), &
                       table_column(trim(wear_names(q))//'_error', '/sweep/statistics/wear/'//trim(wear_names(q))// &
                                    '_error', size(x), w)]
         end do
         if (w > 1) call sink%put_line('', stat, errmsg)
         if (stat == 0 .and. w > 1) call sink%put_line('', stat, errmsg)
         if (stat == 0) call sink%put_line('# point '//integer_text(w)//' of the obstacles: x = '//real_text(x(w))// &
                                           ' m, obstacle '//integer_text(nint(obstacle(w))), stat, errmsg)
         if (stat == 0 .and. w == 1) call column_lines(run, sink, columns, stat, errmsg)
         do first = 1, int(points), sweep_block
            if (stat /= 0) exit blocks
            count = min(sweep_block, int(points) - first + 1)
            call read_table(run, columns, first, count, table, stat, errmsg)
            if (stat /= 0) exit blocks
            table(1, :) = [(real(k, dp), k = first, first + count - 1)]
            do k = 1, count
               call sink%put_row('wide', table(:, k), stat, errmsg)
               if (stat /= 0) exit blocks
            end do
         end do
         deallocate (columns)
      end do blocks
      call run%close_sink(sink, stat, errmsg)
   end subroutine sweep_wear_file
end module vibrobeam_sweep_wear_text
