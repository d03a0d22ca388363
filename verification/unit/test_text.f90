!> The numbers a person reads (vibrobeam_text): fixed_text writes the 0 before the point
!! that Fortran's f0.d leaves out, keeps the requested decimals and the sign; and every
!! text, read back by a list-directed read, gives the value to the rounding of its last
!! decimal (half a unit of it, plus the binary-to-decimal rounding of the read, 2 eps).
program test_text
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: fixed_text, significant_text
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: values(8) = [0.63_dp, 0.05_dp, -0.047_dp, 12.4_dp, 0.0_dp, 1234.5678_dp, 0.9501851_dp, &
                                       -3.0_dp]
   integer, parameter :: decimals(8) = [2, 2, 2, 2, 2, 1, 6, 0]
   character(len=:), allocatable :: text
   real(dp) :: back
   integer :: k, point

   do k = 1, size(values)
      text = fixed_text(values(k), decimals(k))
      call t%check_true('fixed_text('//significant_text(values(k), 8)//') = '//text//' starts with a digit or -digit', &
                        verify(text(1:1), '-0123456789') == 0 .and. (text(1:1) /= '-' .or. &
                                                                    verify(text(2:2), '0123456789') == 0))
      point = index(text, '.')
      if (decimals(k) > 0) then
         call t%check_true(text//' has '//significant_text(real(decimals(k), dp), 3)//' decimals', &
                           point > 0 .and. len(text) - point == decimals(k))
      end if
      read (text, *) back
      call t%check_true(text//' reads back to the value within half its last decimal', &
                        abs(back - values(k)) <= 0.5_dp*10.0_dp**(-decimals(k)) + 2*epsilon(1.0_dp)*abs(values(k)))
   end do
   call t%check_true('fixed_text(0.63, 2) is 0.63', fixed_text(0.63_dp, 2) == '0.63')
   call t%check_true('fixed_text(-0.05, 2) is -0.05', fixed_text(-0.05_dp, 2) == '-0.05')
   call t%finish('test_text')
end program test_text
