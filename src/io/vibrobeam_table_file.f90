!> Two-column tables read from text files (docs/input.md, "Tables"): a measured load
!! record (t, value), a spectrum (f, S). One pair of numbers per line, separated by
!! blanks, a tab or a comma; blank lines and lines whose first non-blank character is '#'
!! or '!' are comments. The first column must increase strictly from line to line, every
!! number must be finite, and at least two pairs are needed. A table holds what its file
!! holds: memory is the user's choice, not the run's length.
!!
!! A table is a piecewise-linear function of its first column (`linear_table%at`), 0
!! outside its range or, with `hold_ends`, its first and last values there.
module vibrobeam_table_file
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: integer_text, real_text
   implicit none
   private
   public :: linear_table, read_table, outside_beam

   integer, parameter :: line_length = 1024   !! longest line of a table

   !> A piecewise-linear function given by its points (x_k, y_k), x increasing.
   type :: linear_table
      real(dp), allocatable :: x(:), y(:)
      !> outside [x_1, x_n]: y_1 before and y_n after (else 0)
      logical :: hold_ends = .false.
   contains
      procedure :: at => table_at
      procedure :: lookup => table_lookup
   end type linear_table

contains

   !> Read the pairs of `path` into `table` (x: first column, y: second). stat =
   !! stat_failure with a message naming the file and line when the file cannot be read,
   !! a line does not hold two finite numbers, the first column does not increase, or
   !! fewer than two pairs are given; the table is then empty.
   subroutine read_table(path, table, stat, errmsg)
      character(len=*), intent(in) :: path
      type(linear_table), intent(out) :: table
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=line_length) :: line
      real(dp), allocatable :: grown(:, :), pairs(:, :)
      real(dp) :: pair(2)
      integer :: unit, ios, count, number, k
      character(len=256) :: iomsg
      stat = 0
      errmsg = ''
      allocate (table%x(0), table%y(0), pairs(2, 1024))
      open (newunit=unit, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
      if (ios /= 0) then
         call fail('cannot be opened ('//trim(iomsg)//')')
         return
      end if
      count = 0
      number = 0
      do
         read (unit, '(a)', iostat=ios, iomsg=iomsg) line
         if (is_iostat_end(ios)) exit
         number = number + 1
         if (ios /= 0) then
            call fail('line '//integer_text(number)//' cannot be read ('//trim(iomsg)//')')
            exit
         end if
         line = adjustl(line)
         if (len_trim(line) == 0 .or. line(1:1) == '#' .or. line(1:1) == '!') cycle
         do k = 1, len_trim(line)
            if (line(k:k) == ',' .or. line(k:k) == achar(9)) line(k:k) = ' '
         end do
         ! a '/' ends a list-directed read early and leaves the rest as it was: NaN is refused below
         pair = ieee_value(pair, ieee_quiet_nan)
         read (line, *, iostat=ios) pair
         if (ios /= 0) then
            call fail('line '//integer_text(number)//' does not hold two numbers: '''//trim(line(1:80))//'''')
            exit
         end if
         if (.not. all(ieee_is_finite(pair))) then
            call fail('line '//integer_text(number)//' holds a number that is not finite')
            exit
         end if
         if (count > 0) then
            if (pair(1) <= pairs(1, count)) then
               call fail('line '//integer_text(number)//': the first column ('//real_text(pair(1))// &
                         ') does not increase (the line before has '//real_text(pairs(1, count))//')')
               exit
            end if
         end if
         if (count == size(pairs, 2)) then
            allocate (grown(2, 2*count))
            grown(:, 1:count) = pairs(:, 1:count)
            call move_alloc(grown, pairs)
         end if
         count = count + 1
         pairs(:, count) = pair
      end do
      close (unit)
      if (stat /= 0) return
      if (count < 2) then
         call fail('holds '//integer_text(count)//' pair(s) of numbers; at least 2 are needed')
         return
      end if
      table%x = pairs(1, 1:count)
      table%y = pairs(2, 1:count)
   contains
      subroutine fail(message)
         character(len=*), intent(in) :: message
         if (stat /= 0) return
         stat = stat_failure
         errmsg = 'the table '''//trim(path)//''' '//message
      end subroutine fail
   end subroutine read_table

   !> '' when every x of a table of positions lies on a beam of `length` (m), [0, length];
   !! else the sentence that says which does not and what is allowed (for the message of
   !! the variable that named the table).
   function outside_beam(table, length) result(message)
      type(linear_table), intent(in) :: table
      real(dp), intent(in) :: length
      character(len=:), allocatable :: message
      integer :: n
      message = ''
      n = size(table%x)
      if (n == 0) return
      ! the beam's ends as the input gives them: an x typed as the length itself is on it
      if (table%x(1) < 0 .or. table%x(n) > length) &
         message = ' holds x = '//real_text(merge(table%x(1), table%x(n), table%x(1) < 0))//' m, outside the beam: '// &
                   'x in [0, '//real_text(length)//'] m (&beam length) is allowed'
   end function outside_beam

   !> The table's value at x (module documentation), the interval found by bisection.
   pure real(dp) function table_at(self, x) result(value)
      class(linear_table), intent(in) :: self
      real(dp), intent(in) :: x
      integer :: hint
      hint = 0
      call self%lookup(x, value, hint)
   end function table_at

   !> `at`, for increasing x at O(1) cost: `hint` is the interval of the last call (0 at
   !! first), tried first with the next one before a bisection, and updated.
   pure subroutine table_lookup(self, x, value, hint)
      class(linear_table), intent(in) :: self
      real(dp), intent(in) :: x
      real(dp), intent(out) :: value
      integer, intent(inout) :: hint
      integer :: n, k, lo, hi
      n = size(self%x)
      if (x < self%x(1) .or. x > self%x(n)) then
         value = 0
         if (self%hold_ends) value = merge(self%y(1), self%y(n), x < self%x(1))
         return
      end if
      k = hint
      if (k < 1 .or. k > n - 1) k = 1
      if (x < self%x(k)) then
         k = 0
      else if (x > self%x(k + 1)) then
         k = k + 1
         if (k > n - 1) then
            k = 0
         else if (x > self%x(k + 1)) then
            k = 0
         end if
      end if
      if (k == 0) then   ! bisection: x(lo) <= x <= x(hi)
         lo = 1
         hi = n
         do while (hi - lo > 1)
            k = (lo + hi)/2
            if (self%x(k) <= x) then
               lo = k
            else
               hi = k
            end if
         end do
         k = lo
      end if
      hint = k
      value = self%y(k) + (self%y(k + 1) - self%y(k))*(x - self%x(k))/(self%x(k + 1) - self%x(k))
   end subroutine table_lookup
end module vibrobeam_table_file
