!> Unit test of the BLAS thread policy (`vibrobeam_blas_threads`, docs/method.md "BLAS
!! threads"), and a record of which BLAS the test suite runs on (printed first: the CI
!! runs the suite once per library).
!!   usage: test_blas_threads EXPECTED [warning]
!! EXPECTED is the number of threads the library must report after `limit_blas_threads`
!! under the environment ctest gives (VIBROBEAM_BLAS_THREADS unset: 1; '3': 3); a library
!! without a known thread control reports 0 and passes (it is single-threaded). With
!! 'warning', the variable holds a bad value: a warning naming it must come back.
program test_blas_threads
   use vibrobeam_kinds, only: output_unit
   use vibrobeam_blas_threads, only: limit_blas_threads, blas_threads, blas_library_description, &
                                     blas_thread_variable
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   character(len=:), allocatable :: warning
   character(len=32) :: argument
   integer :: expected
   write (output_unit, '(a)') 'BLAS before the policy: '//blas_library_description()
   call get_command_argument(1, argument)
   read (argument, *) expected
   call limit_blas_threads(warning)
   write (output_unit, '(a)') 'BLAS after the policy:  '//blas_library_description()
   if (blas_threads() == 0) then
      write (output_unit, '(a)') 'no known thread control: nothing to check'
   else
      call t%check_true('threads reported after the policy', blas_threads() == expected)
   end if
   call get_command_argument(2, argument)
   if (argument == 'warning') then
      call t%check_true('a bad '//blas_thread_variable//' gives a warning naming it', &
                        index(warning, blas_thread_variable) > 0, 'warning: '''//warning//'''')
      if (len(warning) > 0) write (output_unit, '(a)') 'warning: '//warning
   else
      call t%check_true('no warning', len(warning) == 0, warning)
   end if
   call t%finish('test_blas_threads')
end program test_blas_threads
