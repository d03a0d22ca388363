!> SDNL104 as published (verification/published/README.md):
!!   check_sdnl104_compliant RESULT.h5
!! The tip displacement at t = 0.1315 s and the tip velocity at t = 0.1566 s must agree
!! with code_aster's published -1.85334e-6 m and -4.63284e-3 m/s (V5.02.104 section 2.2,
!! 6 digits) and the kinetic energy at 0.16 s with the non-regression value
!! 0.0514081404196 J of astest/sdnl104a.comm, each to 1e-4 relative (the issue's criterion;
!! the document's 6 printed digits and the .comm's own values, which differ from the
!! document by 1.2e-5, both sit inside it). Independent of vibrobeam: the numbers come
!! from code_aster. A rigid stop gives 0.0383 J here, the gradient rule 1.6e-4 off the
!! displacement: the check can fail.
program check_sdnl104_compliant
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_hdf5_file_reads, only: read_real_1d
   use vibrobeam_test_support, only: test_counter
   implicit none
   real(dp), parameter :: dt = 1e-4_dp
   type(test_counter) :: t
   character(len=512) :: file, errmsg
   real(dp), allocatable :: time(:), u(:), v(:), kinetic(:)
   integer :: stat, i, j
   call get_command_argument(1, file)
   call read_real_1d(trim(file), '/time', time, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/tip/displacement', u, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/tip/velocity', v, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/kinetic', kinetic, stat, errmsg)
   call t%check_true('read the histories', stat == 0, errmsg)
   if (t%failed > 0) call t%finish('check_sdnl104_compliant')
   i = minloc(abs(time - 0.1315_dp), 1)
   j = minloc(abs(time - 0.1566_dp), 1)
   call t%check_true('output at 0.1315 s and 0.1566 s', abs(time(i) - 0.1315_dp) < 0.01_dp*dt .and. &
                     abs(time(j) - 0.1566_dp) < 0.01_dp*dt)
   write (output_unit, '(a,es16.8,a,es10.3)') 'u_tip(0.1315 s) = ', u(i), ' m, relative to published ', &
      u(i)/(-1.85334e-6_dp) - 1
   write (output_unit, '(a,es16.8,a,es10.3)') 'v_tip(0.1566 s) = ', v(j), ' m/s, relative to published ', &
      v(j)/(-4.63284e-3_dp) - 1
   write (output_unit, '(a,es20.12,a,es10.3)') 'kinetic energy (0.16 s) = ', kinetic(size(kinetic)), &
      ' J, relative to non-regression ', kinetic(size(kinetic))/0.0514081404196_dp - 1
   call t%check_close('SDNL104 tip displacement at 0.1315 s', u(i), -1.85334e-6_dp, 1e-4_dp)
   call t%check_close('SDNL104 tip velocity at 0.1566 s', v(j), -4.63284e-3_dp, 1e-4_dp)
   call t%check_close('SDNL104 kinetic energy at 0.16 s', kinetic(size(kinetic)), 0.0514081404196_dp, 1e-4_dp)
   call t%finish('check_sdnl104_compliant')
end program check_sdnl104_compliant
