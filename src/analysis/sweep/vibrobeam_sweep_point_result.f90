!> What one point of a sweep reached (`point_result`), its status numbers and the names
!! of its keep_runs file (docs/sweeps.md, "The sweep file"); the runner
!! (`vibrobeam_sweep_runner`) fills it and re-exports these names to the sweep's other
!! modules.
module vibrobeam_sweep_point_result
   use vibrobeam_status, only: outcome_ok, outcome_failed, outcome_interrupted, outcome_not_run
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_statistics, only: statistics_result
   implicit none
   private
   public :: point_result, point_file_name, kept_point_file, point_digits
   public :: status_ok, status_failed, status_interrupted, status_not_run, status_names, chunk_rows

   ! a point's status: the run outcome of core/vibrobeam_status (the numbers in /sweep/status)
   integer, parameter :: status_ok = outcome_ok, status_failed = outcome_failed, &
                         status_interrupted = outcome_interrupted, status_not_run = outcome_not_run
   character(len=*), parameter :: status_names = '0 ok, 1 failed, 2 interrupted, 3 not run'
   !> Poincare samples a point holds before it hands them to the sink as one chunk
   !! (poincare_samples = 'all'): memory of 4096 (1 + 2 observation points) reals a thread.
   integer, parameter :: chunk_rows = 4096


   !> What a point reached.
   type :: point_result
      integer :: status = status_not_run
      character(len=512) :: message = ''
      integer :: settled = -1                    !! 1 settled, 0 not settled, -1 not tested (steady_tolerance = 0)
      integer :: start_point = 0                 !! the point whose final state it started from (0: the scene's)
      integer(int64) :: settle_steps = 0         !! transient used (steps)
      integer(int64) :: measure_steps = 0        !! window (steps)
      real(dp) :: dt = 0
      real(dp) :: wall_seconds = 0
      type(statistics_result) :: statistics
      integer(int64) :: samples_written = 0      !! Poincare samples handed to the sink while it ran ('all')
   end type point_result

contains

   !> '0001', '0042', '100000': a point's index with at least 4 digits.
   pure function point_digits(k) result(digits)
      integer, intent(in) :: k
      character(len=:), allocatable :: digits
      character(len=16) :: buffer
      write (buffer, '(i4.4)') k
      digits = trim(adjustl(buffer))
   end function point_digits

   !> The result file of point k with keep_runs: '<stem>_point<k>.h5' beside the sweep
   !! file '<stem>.h5', k with at least 4 digits.
   pure function point_file_name(sweep_file, k) result(name)
      character(len=*), intent(in) :: sweep_file
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      integer :: n
      n = len_trim(sweep_file)
      if (n > 3) then
         if (sweep_file(n - 2:n) == '.h5') n = n - 3
      end if
      name = sweep_file(1:n)//'_point'//point_digits(k)//'.h5'
   end function point_file_name

   !> Where the keep_runs file of point k is written until the sweep is published:
   !! 'point<k>.h5' in the sweep's partial directory `directory`.
   pure function kept_point_file(directory, k) result(name)
      character(len=*), intent(in) :: directory
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      name = directory//'/point'//point_digits(k)//'.h5'
   end function kept_point_file
end module vibrobeam_sweep_point_result
