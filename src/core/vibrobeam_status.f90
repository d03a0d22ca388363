!> Exit statuses of the vibrobeam executable and the status codes (`stat`) that library
!! procedures return, one table of named constants (docs/output.md, "Exit status" and
!! "Status codes of the library").
!!
!! Library procedures return a `stat` and an `errmsg` (empty when stat = stat_ok, else one
!! sentence saying what failed); only the main program turns them into one of the exit
!! statuses. Compare a `stat` with these names, never with a bare number.
module vibrobeam_status
   implicit none
   private
   public :: exit_ok, exit_other_error, exit_invalid_input, exit_numerical_failure, exit_interrupted
   public :: stat_ok, stat_failure, stat_linear_solver_failure, stat_residual_check_failed
   public :: stat_invalid_argument, stat_no_convergence, stat_not_finite, stat_numerical_failure, stat_invalid_input
   public :: message_length, set_failure
   public :: outcome_ok, outcome_failed, outcome_interrupted, outcome_not_run, outcome_name, outcome_exit_status

   ! exit statuses of the executable (public: scripts and batch systems rely on them)
   integer, parameter :: exit_ok = 0                !! success
   integer, parameter :: exit_other_error = 1       !! I/O error (earlier results untouched), anything else
   integer, parameter :: exit_invalid_input = 2     !! invalid input, nothing written
   integer, parameter :: exit_numerical_failure = 3 !! NaN/Inf or contact solver failure
   integer, parameter :: exit_interrupted = 4       !! SIGINT/SIGTERM: result published, marked 'interrupted'

   ! status codes of library procedures
   integer, parameter :: stat_ok = 0                    !! success
   !> the request cannot be carried out: invalid input or data, an I/O error, a library
   !! (HDF5, FFTW, ARPACK) refusing; errmsg says which
   integer, parameter :: stat_failure = 1
   !> a factorization or a linear solve failed (a matrix not numerically positive
   !! definite or singular, LAPACK info /= 0)
   integer, parameter :: stat_linear_solver_failure = 2
   !> a solution was found but does not satisfy its equations to the required accuracy
   integer, parameter :: stat_residual_check_failed = 3
   !> a procedure was called with arguments outside its contract (sizes, limits, NaN)
   integer, parameter :: stat_invalid_argument = 4
   !> an iterative method did not converge within its iteration limit
   integer, parameter :: stat_no_convergence = 5
   !> the computed state is no longer finite (NaN or Inf)
   integer, parameter :: stat_not_finite = 6
   !> a computation needed to prepare the run failed (the static equilibrium of
   !! `&initial displacement = 'static'`); the main program exits with exit_numerical_failure
   integer, parameter :: stat_numerical_failure = 7
   !> the input, or a file it names (a checkpoint to continue, a partial sweep), cannot be
   !! used as given; the main program exits with exit_invalid_input
   integer, parameter :: stat_invalid_input = 8

   integer, parameter :: message_length = 512       !! length of `errmsg` buffers

   ! How a run, or a point of a sweep, ended: one enumeration for the /run status of a
   ! result file (its name, `outcome_name`), the status codes of a sweep's points
   ! (/sweep/status holds the numbers) and the exit status (`outcome_exit_status`)
   integer, parameter :: outcome_ok = 0           !! ran to its end
   integer, parameter :: outcome_failed = 1       !! stopped by a numerical failure
   integer, parameter :: outcome_interrupted = 2  !! stopped by SIGINT, SIGTERM or SIGUSR1
   integer, parameter :: outcome_not_run = 3      !! a sweep's point that was never run

contains

   !> The name of an outcome as /run status and the messages write it.
   pure function outcome_name(outcome) result(name)
      integer, intent(in) :: outcome
      character(len=:), allocatable :: name
      select case (outcome)
      case (outcome_ok)
         name = 'ok'
      case (outcome_failed)
         name = 'failed'
      case (outcome_interrupted)
         name = 'interrupted'
      case default
         name = 'not run'
      end select
   end function outcome_name

   !> The exit status of a run that ended so (a sweep: of its worst point).
   pure integer function outcome_exit_status(outcome)
      integer, intent(in) :: outcome
      select case (outcome)
      case (outcome_ok)
         outcome_exit_status = exit_ok
      case (outcome_failed)
         outcome_exit_status = exit_numerical_failure
      case default
         outcome_exit_status = exit_interrupted
      end select
   end function outcome_exit_status

   !> stat = `code` (one of the names above) and errmsg = `message`: a library procedure's
   !! failure, in one statement (the contact solvers').
   pure subroutine set_failure(code, message, stat, errmsg)
      integer, intent(in) :: code
      character(len=*), intent(in) :: message
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      stat = code
      errmsg = message
   end subroutine set_failure
end module vibrobeam_status
