!> Verification driver: reads /modes/frequency and /modes/shape from a vibrobeam result
!! file and compares them with the closed-form cantilever (theory §7) for the beam given on
!! the command line:  check_modes_file FILE L E RHO AREA INERTIA FREQUENCY_TOLERANCE SHAPE_TOLERANCE
!! Frequencies are compared in Hz (the roots beta_n L quoted to 20 digits,
!! scripts/cantilever_roots.py); shapes at the nodes (tip value 1) with the closed form.
program check_modes_file
   use vibrobeam_kinds, only: dp, output_unit, pi
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_real_2d
   use vibrobeam_cantilever_exact, only: cantilever_mode_shape
   use vibrobeam_test_support, only: test_counter
   implicit none
   real(dp), parameter :: beta_l(6) = [1.8751040687119611664_dp, 4.6940911329741745764_dp, 7.8547574382376125649_dp, &
                                       10.995540734875466991_dp, 14.137168391046470581_dp, 17.278759532088236334_dp]
   type(test_counter) :: t
   character(len=512) :: file, argument
   real(dp) :: length, young, density, area, inertia, tolerance, shape_tolerance, exact_hz, shape_error
   real(dp), allocatable :: omega(:), x(:), shapes(:,:)
   integer :: stat, n, i
   character(len=300) :: errmsg
   character(len=40) :: label
   call get_command_argument(1, file)
   call real_argument(2, length)
   call real_argument(3, young)
   call real_argument(4, density)
   call real_argument(5, area)
   call real_argument(6, inertia)
   call real_argument(7, tolerance)
   call real_argument(8, shape_tolerance)
   call read_real_1d(trim(file), '/modes/frequency', omega, stat, errmsg)
   call t%check_true('read /modes/frequency', stat == 0, errmsg)
   call read_real_1d(trim(file), '/mesh/x', x, stat, errmsg)
   call t%check_true('read /mesh/x', stat == 0, errmsg)
   call read_real_2d(trim(file), '/modes/shape', shapes, stat, errmsg)
   call t%check_true('read /modes/shape', stat == 0, errmsg)
   if (t%failed > 0) call t%finish('check_modes_file')
   write (output_unit, '(a)') ' mode   vibrobeam (Hz)    closed form (Hz)   relative error'
   do n = 1, min(size(omega), size(beta_l))
      exact_hz = beta_l(n)**2*sqrt(young*inertia/(density*area))/length**2/(2*pi)
      write (output_unit, '(i5, 2f18.6, es14.2)') n, omega(n)/(2*pi), exact_hz, abs(omega(n)/(2*pi) - exact_hz)/exact_hz
      write (label, '(a,i0,a)') 'frequency of mode ', n, ' (Hz)'
      call t%check_close(trim(label), omega(n)/(2*pi), exact_hz, tolerance)
      shape_error = 0
      do i = 1, size(x)
         shape_error = max(shape_error, abs(shapes(i, n) - cantilever_mode_shape(n, x(i), length, 0)))
      end do
      write (label, '(a,i0)') 'max nodal error of mode shape ', n
      call t%check_close(trim(label), shape_error, 0.0_dp, 1.0_dp, shape_tolerance)
   end do
   call t%finish('check_modes_file')
contains
   subroutine real_argument(position, value)
      integer, intent(in) :: position
      real(dp), intent(out) :: value
      call get_command_argument(position, argument)
      read (argument, *) value
   end subroutine real_argument
end program check_modes_file
