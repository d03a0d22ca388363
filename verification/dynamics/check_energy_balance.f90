!> Verification driver (issue 3, "energy balance"): for a result file of a run with
!! theta = 1/2, the discrete balance total - work + dissipated (SPEC §3: E^n - W^n plus what
!! impacts and damping took) must stay constant to TOLERANCE relative to the largest
!! energy involved.   usage: check_energy_balance FILE TOLERANCE
!! The balance is recomputed here from /energy/kinetic, elastic, work and dissipated (not
!! read from /energy/balance), and /run status must be 'ok'.
program check_energy_balance
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_hdf5, only: read_real_1d, read_attr_string
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   character(len=512) :: file, argument, errmsg
   character(len=:), allocatable :: status
   real(dp), allocatable :: kinetic(:), elastic(:), work(:), dissipated(:), balance(:)
   real(dp) :: tolerance, scale, drift
   integer :: stat
   call get_command_argument(1, file)
   call get_command_argument(2, argument)
   read (argument, *) tolerance
   call read_real_1d(trim(file), '/energy/kinetic', kinetic, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/elastic', elastic, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/work', work, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/dissipated', dissipated, stat, errmsg)
   if (stat == 0) call read_attr_string(trim(file), '/run', 'status', status, stat, errmsg)
   call t%check_true('read the energies', stat == 0, errmsg)
   if (stat /= 0) call t%finish('check_energy_balance')
   call t%check_true('/run status is ok', status == 'ok', 'status = '//status)
   allocate (balance, source=kinetic + elastic - work + dissipated)
   scale = max(maxval(abs(kinetic + elastic)), maxval(abs(work)), maxval(abs(dissipated)))
   drift = maxval(abs(balance - balance(1)))/scale
   write (output_unit, '(a,i0,a,es10.3,a,es10.3,a,es10.3)') 'output times ', size(balance), ', energy scale ', &
      scale, ' J, work of loads up to ', maxval(abs(work)), ' J, max |balance drift|/scale ', drift
   call t%check_close('relative drift of E - W + D', drift, 0.0_dp, 1.0_dp, tolerance)
   call t%finish('check_energy_balance')
end program check_energy_balance
