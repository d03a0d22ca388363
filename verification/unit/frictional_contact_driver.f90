!> Solves the 2-D frictional contact problems of a text file with
!! `solve_frictional_contact`, for the comparison with Siconos
!! (check_frictional_siconos.py, test unit.frictional_contact_siconos).
!!
!! usage: frictional_contact_driver PROBLEMS RESULTS
!!
!! PROBLEMS: the number of problems, then per problem a line with m, a line with mu(1:m),
!! a line with q(1:2m) and 2m lines with the rows of D (list-directed; contact i at
!! entries 2i - 1 (normal) and 2i (tangent)).
!! RESULTS: per problem a line "stat pivots" and a line with r(1:2m) (es25.17, so that the
!! decimal text gives back the binary value). Exit status 1 when a file cannot be read
!! or written (the message on stderr); a solver failure is reported in its stat.
program frictional_contact_driver
   use vibrobeam_kinds, only: dp, error_unit
   use vibrobeam_frictional_contact, only: solve_frictional_contact, frictional_contact_solution
   use vibrobeam_test_support, only: use_program_blas_threads
   implicit none
   character(len=4096) :: problems_path, results_path
   character(len=512) :: errmsg, io_message
   real(dp), allocatable :: d(:, :), q(:), mu(:)
   type(frictional_contact_solution) :: solution
   integer :: problems_unit, results_unit, problem_count, problem, m, i, stat, io_status

   if (command_argument_count() /= 2) then
      write (error_unit, '(a)') 'usage: frictional_contact_driver PROBLEMS RESULTS'
      error stop 1
   end if
   call use_program_blas_threads()
   call get_command_argument(1, problems_path)
   call get_command_argument(2, results_path)
   open (newunit=problems_unit, file=trim(problems_path), status='old', action='read', iostat=io_status, &
         iomsg=io_message)
   if (io_status /= 0) call io_failure('cannot open '//trim(problems_path)//': '//trim(io_message))
   open (newunit=results_unit, file=trim(results_path), status='replace', action='write', iostat=io_status, &
         iomsg=io_message)
   if (io_status /= 0) call io_failure('cannot open '//trim(results_path)//': '//trim(io_message))
   read (problems_unit, *, iostat=io_status, iomsg=io_message) problem_count
   if (io_status /= 0) call io_failure('problem count: '//trim(io_message))
   do problem = 1, problem_count
      read (problems_unit, *, iostat=io_status, iomsg=io_message) m
      if (io_status /= 0 .or. m < 0) call io_failure('size of a problem: '//trim(io_message))
      allocate (d(2*m, 2*m), q(2*m), mu(m))
      read (problems_unit, *, iostat=io_status, iomsg=io_message) mu
      if (io_status == 0) read (problems_unit, *, iostat=io_status, iomsg=io_message) q
      do i = 1, 2*m
         if (io_status == 0) read (problems_unit, *, iostat=io_status, iomsg=io_message) d(i, :)
      end do
      if (io_status /= 0) call io_failure('data of a problem: '//trim(io_message))
      call solve_frictional_contact(d, q, mu, solution, stat, errmsg)
      if (stat /= 0) write (error_unit, '(a, i0, a)') 'problem ', problem, ': '//trim(errmsg)
      write (results_unit, '(i0, 1x, i0)') stat, solution%pivots
      write (results_unit, '(*(es25.17))') solution%impulse
      deallocate (d, q, mu)
   end do
   close (results_unit)
   close (problems_unit)

contains

   !> Report a file error and exit with status 1.
   subroutine io_failure(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'frictional_contact_driver: '//message
      error stop 1
   end subroutine io_failure

end program frictional_contact_driver
