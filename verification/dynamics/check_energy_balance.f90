!> Verification driver (issue 3, "energy balance"): for the result file of a run, the
!! discrete balance total - work + dissipated (docs/method.md "Energies": E^n - W^n plus
!! what impacts, damping and the theta-method took) must stay constant to round-off.
!!   usage: check_energy_balance FILE INPUT.nml
!! The balance is recomputed here from /energy/kinetic, elastic, work and dissipated (not
!! read from /energy/balance), and /run status must be 'ok'. The round-off allowance at
!! each output time is derived, not chosen: the scene of INPUT.nml is run again step by
!! step with the bounds of `vibrobeam_roundoff_bounds` (the evaluation error of the two
!! energies compared, from their conditioning |x|^T|A||x|, and the accumulated bound of
!! every step), so it holds on any conforming BLAS/LAPACK. The largest drift/bound ratio
!! is printed.
program check_energy_balance
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_attr_string
   use vibrobeam_roundoff_bounds, only: balance_bounds_at
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   character(len=512) :: file, input, errmsg
   character(len=:), allocatable :: status
   real(dp), allocatable :: time(:), kinetic(:), elastic(:), work(:), dissipated(:), balance(:), bounds(:)
   real(dp) :: scale, drift, ratio, bound_at_worst
   integer :: stat, j
   call get_command_argument(1, file)
   call get_command_argument(2, input)
   call read_real_1d(trim(file), '/time', time, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/kinetic', kinetic, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/elastic', elastic, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/work', work, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/dissipated', dissipated, stat, errmsg)
   if (stat == 0) call read_attr_string(trim(file), '/run', 'status', status, stat, errmsg)
   call t%check_true('read the energies', stat == 0, errmsg)
   if (stat /= 0) call t%finish('check_energy_balance')
   call t%check_true('/run status is ok', status == 'ok', 'status = '//status)
   bounds = balance_bounds_at(trim(input), time)
   allocate (balance, source=kinetic + elastic - work + dissipated)
   scale = max(maxval(abs(kinetic + elastic)), maxval(abs(work)), maxval(abs(dissipated)))
   drift = maxval(abs(balance - balance(1)))/scale
   ratio = 0
   bound_at_worst = 0
   do j = 2, size(balance)
      if (abs(balance(j) - balance(1))/bounds(j) > ratio) then
         ratio = abs(balance(j) - balance(1))/bounds(j)
         bound_at_worst = bounds(j)
      end if
   end do
   write (output_unit, '(a,i0,a,es10.3,a,es10.3,a,es10.3)') 'output times ', size(balance), &
      ', energy scale ', scale, ' J, work of loads up to ', maxval(abs(work)), ' J, max |balance drift|/scale ', drift
   write (output_unit, '(a,es10.3,a,es10.3,a)') 'largest drift/bound ', ratio, ' (the bound is ', &
      bound_at_worst/scale, ' of the scale there)'
   call t%check_close('|E - W + D - its initial value| / its round-off bound, largest over the outputs', ratio, &
                      0.0_dp, 1.0_dp, 1.0_dp)
   call t%finish('check_energy_balance')
end program check_energy_balance
