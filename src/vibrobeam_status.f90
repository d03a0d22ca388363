!> Exit codes of the vibrobeam executable (INTERFACE.md, "Command line").
!!
!! Library procedures return a `stat` and an `errmsg`; only the main program turns them
!! into one of these codes.
module vibrobeam_status
   implicit none
   private
   public :: exit_ok, exit_other_error, exit_invalid_input, exit_numerical_failure, exit_interrupted
   public :: message_length

   integer, parameter :: exit_ok = 0                !! success
   integer, parameter :: exit_other_error = 1       !! I/O error (earlier results untouched), anything else
   integer, parameter :: exit_invalid_input = 2     !! invalid input, nothing written
   integer, parameter :: exit_numerical_failure = 3 !! NaN/Inf or contact solver failure
   integer, parameter :: exit_interrupted = 4       !! SIGINT/SIGTERM: result published, marked 'interrupted'
   integer, parameter :: message_length = 512       !! length of `errmsg` buffers
end module vibrobeam_status
