!> SDNL32 as published (verification/published/SOURCES.md section 6b):
!!   check_sdnl32 RESULT.h5 STIFFNESS
!! The tip displacement at t = 1, 2, ... 12 ms must agree with the VPCS reference table of
!! code_aster's V5.02.032 for the spring STIFFNESS (18000 or 45000 N/m) to 0.7 % of the
!! table's peak |u| at every time: the issue's criterion, which an independent
!! Euler-Bernoulli model met. Independent of vibrobeam: the numbers come from the table.
!! The resolved Euler-Bernoulli beam stays within 0.66 % (case 1, at 3 ms, where the
!! table is 0.65 % of its peak from code_aster's own Timoshenko run too) and 0.36 % (case
!! 2); the Timoshenko beam's shear and rotary inertia move it by less than 0.2 %
!! (studies/sdnl32/REPORT.md). The check fails on a coarse mesh (N = 5: 0.82 % in case 2)
!! and against the other case's table.
program check_sdnl32
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_hdf5_file_reads, only: read_real_1d
   use vibrobeam_test_support, only: test_counter
   implicit none
   !> VPCS tip displacements u_y(L, t) at t = 1..12 ms (m), springs of 18 000 and 45 000 N/m
   real(dp), parameter :: reference(12, 2) = reshape(1e-3_dp*[ &
      -2.66_dp, -4.33_dp, -4.92_dp, -4.78_dp, -3.82_dp, -2.87_dp, -2.71_dp, -3.09_dp, -3.41_dp, -3.36_dp, -2.64_dp, -0.742_dp, &
      -2.25_dp, -2.66_dp, -1.96_dp, -1.15_dp, -0.124_dp, -0.364_dp, -2.01_dp, -2.74_dp, -1.89_dp, -0.352_dp, 1.70_dp, &
      4.99_dp], [12, 2])
   real(dp), parameter :: criterion = 0.007_dp   !! of the table's peak |u|
   type(test_counter) :: t
   character(len=512) :: file, errmsg, text
   real(dp), allocatable :: time(:), u(:)
   real(dp) :: stiffness, peak, worst
   integer :: stat, i, k, case
   character(len=64) :: label
   call get_command_argument(1, file)
   call get_command_argument(2, text)
   read (text, *, iostat=stat) stiffness
   if (stat /= 0) stiffness = 0
   case = 0
   if (abs(stiffness - 18000) < 1) case = 1
   if (abs(stiffness - 45000) < 1) case = 2
   call t%check_true('the spring is 18000 or 45000 N/m', case > 0, 'usage: check_sdnl32 RESULT.h5 18000|45000')
   if (t%failed > 0) call t%finish('check_sdnl32')
   call read_real_1d(trim(file), '/time', time, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/tip/displacement', u, stat, errmsg)
   call t%check_true('read the histories', stat == 0, errmsg)
   if (t%failed > 0) call t%finish('check_sdnl32')
   peak = maxval(abs(reference(:, case)))
   worst = 0
   do k = 1, 12
      i = minloc(abs(time - k*1e-3_dp), 1)
      write (label, '(a,i0,a)') 'output at ', k, ' ms'
      call t%check_true(trim(label), abs(time(i) - k*1e-3_dp) < 1e-9_dp)
      write (output_unit, '(a,i2,a,f9.5,a,f8.4,a,f7.3,a)') 't = ', k, ' ms: u_tip = ', 1e3_dp*u(i), ' mm, VPCS ', &
         1e3_dp*reference(k, case), ' mm, difference ', 100*(u(i) - reference(k, case))/peak, ' % of the peak'
      worst = max(worst, abs(u(i) - reference(k, case))/peak)
      write (label, '(a,i0,a)') 'SDNL32 tip displacement at ', k, ' ms'
      call t%check_close(trim(label), u(i), reference(k, case), criterion, peak)   ! criterion x peak
   end do
   write (output_unit, '(a,f6.3,a)') 'largest difference: ', 100*worst, ' % of the peak (criterion 0.7 %)'
   call t%finish('check_sdnl32')
end program check_sdnl32
