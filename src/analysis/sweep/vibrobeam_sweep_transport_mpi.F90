!> Where the tasks of a sweep run and what the ranks agree on, in the MPI build
!! (-DVIBROBEAM_MPI=ON; docs/sweeps.md, "Parallel runs"): `mpirun -n P vibrobeam sweep.nml`
!! deals the tasks round-robin to the P ranks, and each rank runs its own on its threads,
!! writing each finished point into its own journal in the sweep's partial directory
!! (`vibrobeam_sweep_journal`); rank 0 makes the sweep file from the journals. The ranks
!! only agree on a few numbers here: whether one of them failed (and why), whether one was
!! interrupted, and when all are done. Only the main thread of a process calls MPI
!! (MPI_THREAD_FUNNELED). The same interface without MPI is
!! src/analysis/sweep/vibrobeam_sweep_transport.f90.
module vibrobeam_sweep_transport
   use vibrobeam_status, only: stat_failure
   use mpi_f08
   implicit none
   private
   public :: transport_start, transport_stop, transport_rank, transport_ranks, owns_task
   public :: transport_barrier, transport_max, share_failure

contains

   !> MPI is initialized and not yet finalized.
   logical function running()
      logical :: initialized, finalized
      integer :: error
      call MPI_Initialized(initialized, error)
      call MPI_Finalized(finalized, error)
      running = initialized .and. .not. finalized
   end function running

   !> MPI_Init_thread with MPI_THREAD_FUNNELED (OpenMP threads never call MPI).
   subroutine transport_start(stat, errmsg)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: provided, error
      logical :: initialized
      stat = 0
      errmsg = ''
      call MPI_Initialized(initialized, error)
      if (initialized) return
      call MPI_Init_thread(MPI_THREAD_FUNNELED, provided, error)
      if (error /= MPI_SUCCESS .or. provided < MPI_THREAD_FUNNELED) then
         stat = stat_failure
         errmsg = 'MPI could not start with MPI_THREAD_FUNNELED'
      end if
   end subroutine transport_start

   subroutine transport_stop()
      integer :: error
      if (running()) call MPI_Finalize(error)
   end subroutine transport_stop

   integer function transport_rank()
      integer :: error
      transport_rank = 0
      if (running()) call MPI_Comm_rank(MPI_COMM_WORLD, transport_rank, error)
   end function transport_rank

   integer function transport_ranks()
      integer :: error
      transport_ranks = 1
      if (running()) call MPI_Comm_size(MPI_COMM_WORLD, transport_ranks, error)
   end function transport_ranks

   !> True when this rank runs task `task` (1-based): tasks go round-robin over the ranks.
   pure logical function owns_task(task, rank, ranks)
      integer, intent(in) :: task, rank, ranks
      owns_task = mod(task - 1, ranks) == rank
   end function owns_task

   !> Wait until every rank is here.
   subroutine transport_barrier()
      integer :: error
      if (running()) call MPI_Barrier(MPI_COMM_WORLD, error)
   end subroutine transport_barrier

   !> The largest `value` over the ranks (every rank gets it).
   integer function transport_max(value)
      integer, intent(in) :: value
      integer :: error
      transport_max = value
      if (running()) call MPI_Allreduce(value, transport_max, 1, MPI_INTEGER, MPI_MAX, MPI_COMM_WORLD, error)
   end function transport_max

   !> Every rank gets the stat /= 0 and errmsg of the lowest rank that has one (stat = 0
   !! everywhere when none has).
   subroutine share_failure(stat, errmsg)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: first, error, candidate
      if (.not. running()) return
      candidate = huge(1)
      if (stat /= 0) candidate = transport_rank()
      call MPI_Allreduce(candidate, first, 1, MPI_INTEGER, MPI_MIN, MPI_COMM_WORLD, error)
      if (first == huge(1)) return
      call MPI_Bcast(stat, 1, MPI_INTEGER, first, MPI_COMM_WORLD, error)
      call MPI_Bcast(errmsg, len(errmsg), MPI_CHARACTER, first, MPI_COMM_WORLD, error)
   end subroutine share_failure
end module vibrobeam_sweep_transport
