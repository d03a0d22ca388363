!> Numbers as text for messages, listings and attributes.
module vibrobeam_text
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use vibrobeam_kinds, only: dp, int64
   implicit none
   private
   public :: real_text, integer_text, significant_text, short_text, fixed_text

contains

   !> Decimal text of an integer, without blanks.
   pure function integer_text(value) result(text)
      integer, intent(in) :: value
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      write (buffer, '(i0)') value
      text = trim(buffer)
   end function integer_text

   !> A real number as short text that reads back to the same value (for messages and the
   !! resolved-scene listing): 1.5, 0, 32, 2.1e11, 1.6666666666666667e-9.
   function real_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=40) :: buffer
      integer :: digits, e, exponent, low, high
      if (ieee_is_nan(value)) then
         text = 'NaN'
         return
      else if (abs(value) >= huge(1.0_dp)) then
         text = merge('-inf', ' inf', value < 0)
         text = trim(adjustl(text))
         return
      end if
      ! the fewest digits that read back exactly, by bisection: with more digits the text
      ! only comes closer to the value, so the digits that read back form a range [d, 17]
      low = 0
      high = 17
      do while (low < high)
         digits = (low + high)/2
         if (reads_back(digits)) then
            high = digits
         else
            low = digits + 1
         end if
      end do
      call write_digits(low)
      buffer = adjustl(buffer)
      if (buffer(1:1) == '.') buffer = '0'//buffer(1:len(buffer) - 1)
      if (buffer(1:2) == '-.') buffer = '-0'//buffer(2:len(buffer) - 1)
      e = scan(buffer, 'Ee')
      if (e == 0) e = len_trim(buffer) + 1
      text = buffer(1:e - 1)
      if (index(text, '.') > 0) then
         do while (text(len(text):len(text)) == '0')
            text = text(1:len(text) - 1)
         end do
         if (text(len(text):len(text)) == '.') text = text(1:len(text) - 1)
      end if
      if (e <= len_trim(buffer)) then
         read (buffer(e + 1:), *) exponent
         write (buffer, '(i0)') exponent
         text = text//'e'//trim(buffer)
      end if
   contains
      !> `value` with `digits` digits after the point into `buffer`.
      subroutine write_digits(digits)
         integer, intent(in) :: digits
         character(len=40) :: format
         if (abs(value) < tiny(value) .or. (abs(value) >= 1e-3_dp .and. abs(value) < 1e6_dp)) then
            write (format, '(a,i0,a)') '(f0.', digits, ')'
         else
            write (format, '(a,i0,a)') '(es30.', digits, 'e3)'
         end if
         write (buffer, format) value
      end subroutine write_digits

      !> `value` written with `digits` digits reads back to the same bits.
      logical function reads_back(digits)
         integer, intent(in) :: digits
         real(dp) :: back
         integer :: ios
         call write_digits(digits)
         read (buffer, *, iostat=ios) back
         reads_back = ios == 0 .and. transfer(back, 1_int64) == transfer(value, 1_int64)   ! bitwise
      end function reads_back
   end function real_text

   !> `value` rounded to `digits` significant digits, without blanks or trailing zeros, for
   !! what a person reads (--check, the modes a run found): 210.347, 0.0213, 1.23457e7
   !! with 6 digits. Plain decimals from 1e-3 to 1e6, an exponent outside; '0' for zero.
   function significant_text(value, digits) result(text)
      real(dp), intent(in) :: value
      integer, intent(in) :: digits
      character(len=:), allocatable :: text
      character(len=48) :: buffer
      integer :: e, exponent, decimals
      if (abs(value) >= 1e-3_dp .and. abs(value) < 1e6_dp) then
         decimals = max(0, digits - 1 - floor(log10(abs(value))))
         write (buffer, '(f0.'//integer_text(decimals)//')') value
         text = trim(adjustl(buffer))
         if (index(text, '.') > 0) then
            do while (text(len(text):) == '0')
               text = text(1:len(text) - 1)
            end do
            if (text(len(text):) == '.') text = text(1:len(text) - 1)
         end if
         text = with_leading_zero(text)
      else if (abs(value) > 0) then
         write (buffer, '(es30.'//integer_text(max(digits - 1, 0))//'e3)') value
         buffer = adjustl(buffer)
         e = index(buffer, 'E')
         read (buffer(e + 1:), *) exponent
         text = trim(buffer(1:e - 1))
         if (index(text, '.') > 0) then
            do while (text(len(text):) == '0')
               text = text(1:len(text) - 1)
            end do
            if (text(len(text):) == '.') text = text(1:len(text) - 1)
         end if
         text = text//'e'//integer_text(exponent)
      else
         text = '0'
      end if
   end function significant_text

   !> `value` with `decimals` digits after the point and a digit before it, for what a
   !! person reads (seconds of a run, a multiplier's modulus): 0.63, 12.40, -0.05 with 2
   !! (Fortran's `f0.d` writes .63).
   function fixed_text(value, decimals) result(text)
      real(dp), intent(in) :: value
      integer, intent(in) :: decimals
      character(len=:), allocatable :: text
      character(len=48) :: buffer
      write (buffer, '(f0.'//integer_text(max(decimals, 0))//')') value
      text = with_leading_zero(trim(adjustl(buffer)))
   end function fixed_text

   !> `text` of a decimal number with the 0 before its point that `f0.d` leaves out.
   pure function with_leading_zero(text) result(fixed)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: fixed
      fixed = text
      if (len(fixed) == 0) return
      if (fixed(1:1) == '.') fixed = '0'//fixed
      if (len(fixed) >= 2) then
         if (fixed(1:2) == '-.') fixed = '-0'//fixed(2:)
      end if
   end function with_leading_zero

   !> `value` with 6 significant digits (`significant_text`): 210.347, 0.0213, 1.23457e7.
   function short_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      text = significant_text(value, 6)
   end function short_text
end module vibrobeam_text
