!> The text files of a continued branch (docs/output.md, "Text files"): STEM_branch.dat,
!! one row per branch point, and STEM_bifurcations.dat, one row per bifurcation located
!! (and STEM_branch_2.dat, STEM_bifurcations_2.dat of the branch of twice the period,
!! /periodic/branch_2, when the result holds one),
!! each column named in a header line as in the sweep files ('# 2: amplitude (m)'), read
!! from its dataset of /periodic/branch (`vibrobeam_sweep_text`'s table columns).
module vibrobeam_branch_text
   use vibrobeam_kinds, only: dp
   use vibrobeam_text_derivation, only: derivation, text_sink
   use vibrobeam_sweep_text, only: table_column, column_lines, read_table
   implicit none
   private
   public :: branch_files

contains

   !> STEM_branch.dat and STEM_bifurcations.dat of the branch in the open result, and
   !! STEM_branch_2.dat and STEM_bifurcations_2.dat of the switched branch when it holds one.
   subroutine branch_files(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call branch_tables(run, '/periodic/branch', '', stat, errmsg)
      if (stat == 0) call multiplier_table(run, '/periodic/branch', '', stat, errmsg)
      if (stat == 0 .and. run%file%exists('/periodic/branch_2/parameter')) then
         call branch_tables(run, '/periodic/branch_2', '_2', stat, errmsg)
         if (stat == 0) call multiplier_table(run, '/periodic/branch_2', '_2', stat, errmsg)
      end if
   end subroutine branch_files

   !> STEM_branch_multipliers<tail>.dat: every Floquet multiplier of every point of the
   !! branch in `group` (its floquet_multipliers), a block of rows per point (parameter,
   !! real and imaginary part, modulus, the point's index) with a blank line between
   !! blocks, for the multipliers in the complex plane (scripts/plot_branch.gp). A result
   !! written before the branch kept its multipliers has none: no file.
   subroutine multiplier_table(run, group, tail, stat, errmsg)
      type(derivation), intent(inout) :: run
      character(len=*), intent(in) :: group, tail
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: parameter(:), multipliers(:)
      character(len=:), allocatable :: name
      integer :: k, j, count
      stat = 0
      errmsg = ''
      if (.not. run%file%exists(group//'/floquet_multipliers')) return
      call run%file%read_reals(group//'/parameter', parameter, stat, errmsg)
      if (stat == 0) call run%file%read_reals(group//'/floquet_multipliers', multipliers, stat, errmsg)
      if (stat == 0) call run%file%attr_string(group, 'parameter', name, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'branch_multipliers'//tail, 'the Floquet multipliers of each point of the '// &
                         'branch, largest modulus first, a block of rows per point: the parameter, the real and '// &
                         'imaginary parts, the modulus, the point''s index', stat, errmsg)
      if (stat == 0) call column_lines(run, sink, [table_column('parameter', group//'/parameter', note=name), &
                                                   table_column('real', group//'/floquet_multipliers'), &
                                                   table_column('imaginary', group//'/floquet_multipliers'), &
                                                   table_column('modulus', group//'/floquet_multipliers'), &
                                                   table_column('point', '')], stat, errmsg)
      if (stat /= 0) return
      count = 0
      if (size(parameter) > 0) count = size(multipliers)/(2*size(parameter))
      do k = 1, size(parameter)
         do j = 1, count
            associate (re => multipliers(2*((k - 1)*count + j) - 1), im => multipliers(2*((k - 1)*count + j)))
               call sink%put_row('wide', [parameter(k), re, im, hypot(re, im), real(k, dp)], stat, errmsg, 1)
            end associate
            if (stat /= 0) exit
         end do
         if (stat == 0 .and. k < size(parameter)) call sink%put_line('', stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
   end subroutine multiplier_table

   !> STEM_branch<tail>.dat and STEM_bifurcations<tail>.dat of the branch in `group`.
   subroutine branch_tables(run, group, tail, stat, errmsg)
      type(derivation), intent(inout) :: run
      character(len=*), intent(in) :: group, tail
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(table_column) :: bifurcations(5)
      type(table_column), allocatable :: points(:)
      character(len=:), allocatable :: parameter, gap, found
      integer :: integers
      found = group//'/bifurcations'
      call run%file%attr_string(group, 'parameter', parameter, stat, errmsg)
      if (stat /= 0) return
      points = [table_column('parameter', group//'/parameter', note=parameter), &
                table_column('amplitude', group//'/amplitude'), table_column('period', group//'/period'), &
                table_column('largest_multiplier', group//'/largest_multiplier')]
      points = [points, table_column('stable', group//'/stable'), &
                table_column('newton_iterations', group//'/newton_iterations')]
      ! the smallest clearance when the scene has obstacles: last, so that the columns before
      ! it keep their places (the two integer columns then written as reals)
      gap = ''
      integers = 2
      if (run%file%exists(group//'/minimum_gap')) then
         points = [points, table_column('minimum_gap', group//'/minimum_gap')]
         gap = ', the smallest clearance of the contact points to their obstacles over the orbit (m)'
         integers = 0
      end if
      call write_table('branch'//tail, 'one row per point of the continued branch, in its order: the parameter, the '// &
                       'largest |u| of the tip over the orbit, the period, the largest |mu|, 1 stable '// &
                       '(every |mu| < 1; on a backbone <= 1 + stable_margin) or 0, the corrector''s Newton '// &
                       'iterations'//gap, points, group//'/parameter', &
                       integers, stat, errmsg)
      if (stat /= 0) return
      bifurcations = [table_column('parameter', found//'/parameter', note=parameter), &
                      table_column('amplitude', found//'/amplitude'), &
                      table_column('kind', found//'/kind', note='1 fold, 2 period-doubling, 3 neimark-sacker, 4 grazing, '// &
                                   '5 branch-point'), &
                      table_column('index', found//'/index'), table_column('located', found//'/located')]
      call write_table('bifurcations'//tail, 'one row per bifurcation located on the branch: its parameter, '// &
                       'amplitude and kind, the branch point before it, 1 when the test function''s zero was located (0: '// &
                       'the linear estimate between the two points)', bifurcations, found//'/kind', 3, stat, errmsg)
   contains
      !> '<stem>_<suffix>.dat' of `columns`, as many rows as the dataset `rows_of` has;
      !! the last `integers` columns written as integers.
      subroutine write_table(suffix, what, columns, rows_of, integers, stat, errmsg)
         character(len=*), intent(in) :: suffix, what, rows_of
         type(table_column), intent(in) :: columns(:)
         integer, intent(in) :: integers
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
         type(text_sink) :: sink
         real(dp), allocatable :: values(:), table(:, :)
         integer :: k
         call run%file%read_reals(rows_of, values, stat, errmsg)
         if (stat /= 0) return
         call run%open_sink(sink, suffix, what, stat, errmsg)
         if (stat /= 0) return
         call column_lines(run, sink, columns, stat, errmsg)
         if (stat == 0 .and. size(values) > 0) call read_table(run, columns, 1, size(values), table, stat, errmsg)
         do k = 1, size(values)
            if (stat /= 0) exit
            call sink%put_row('wide', table(:, k), stat, errmsg, integers)
         end do
         call run%close_sink(sink, stat, errmsg)
      end subroutine write_table
   end subroutine branch_tables
end module vibrobeam_branch_text
