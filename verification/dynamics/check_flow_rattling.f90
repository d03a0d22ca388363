!> Fluid-elastic rattling stays bounded (flow_rattling.nml): every point of the sweep
!! succeeded, settled (/sweep/settled = 1: two consecutive windows agreed within
!! steady_tolerance) and kept its tip within twice the gap of its supports (the springs'
!! penetration is a fraction of the gap at these forces).
!! usage: check_flow_rattling SWEEP.h5 GAP
program check_flow_rattling
   use vibrobeam_kinds, only: dp, output_unit, error_unit
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_real_2d, read_int_1d
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   character(len=4096) :: path, argument
   character(len=512) :: errmsg
   real(dp) :: gap
   real(dp), allocatable :: velocity(:), largest(:, :), smallest(:, :), rate(:)
   integer, allocatable :: status(:), settled(:)
   integer :: stat, k
   call get_command_argument(1, path)
   call get_command_argument(2, argument)
   read (argument, *) gap
   call read_real_1d(trim(path), '/sweep/parameter', velocity, stat, errmsg)
   if (stat == 0) call read_int_1d(trim(path), '/sweep/status', status, stat, errmsg)
   if (stat == 0) call read_int_1d(trim(path), '/sweep/settled', settled, stat, errmsg)
   if (stat == 0) call read_real_2d(trim(path), '/sweep/statistics/points/displacement_max', largest, stat, errmsg)
   if (stat == 0) call read_real_2d(trim(path), '/sweep/statistics/points/displacement_min', smallest, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(path), '/sweep/statistics/beam/episode_rate', rate, stat, errmsg)
   if (stat /= 0) then
      write (error_unit, '(a)') 'FAIL reading '//trim(path)//': '//trim(errmsg)
      error stop 1
   end if
   do k = 1, size(velocity)
      write (output_unit, '(a,f6.3,a,i0,a,i0,a,es10.3,a,es10.3,a,f7.1,a)') 'U = ', velocity(k), ' m/s: status ', &
         status(k), ', settled ', settled(k), ', tip in [', smallest(1, k), ', ', largest(1, k), '] m, ', rate(k), &
         ' contact episodes per second'
      call t%check_true('the point succeeded', status(k) == 0)
      call t%check_true('the rattling settled', settled(k) == 1)
      call t%check_true('the tip stays within twice the gap', max(largest(1, k), -smallest(1, k)) <= 2*gap)
      call t%check_true('the tube rattles', rate(k) > 10)
   end do
   call t%finish('check_flow_rattling')
end program check_flow_rattling
