!> Where the tasks of a sweep run and what the processes running them agree on (docs/sweeps.md,
!! "Parallel runs"). This is the build without MPI: one process (rank 0 of 1) runs every
!! task. With -DVIBROBEAM_MPI=ON the same module comes from
!! src/analysis/sweep/vibrobeam_sweep_transport_mpi.F90, which spreads the tasks over the
!! ranks of `mpirun`. The results themselves travel through the sweep's journals
!! (`vibrobeam_sweep_journal`), not through the transport.
module vibrobeam_sweep_transport
   implicit none
   private
   public :: transport_start, transport_stop, transport_rank, transport_ranks, owns_task
   public :: transport_barrier, transport_max, share_failure

contains

   !> Start the transport (MPI_Init in an MPI build).
   subroutine transport_start(stat, errmsg)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
   end subroutine transport_start

   !> End it (MPI_Finalize in an MPI build).
   subroutine transport_stop()
   end subroutine transport_stop

   integer function transport_rank()
      transport_rank = 0
   end function transport_rank

   integer function transport_ranks()
      transport_ranks = 1
   end function transport_ranks

   !> True when this rank runs task `task` (1-based): tasks go round-robin over the ranks.
   pure logical function owns_task(task, rank, ranks)
      integer, intent(in) :: task, rank, ranks
      owns_task = mod(task - 1, ranks) == rank
   end function owns_task

   !> Wait until every rank is here (nothing to wait for with one process).
   subroutine transport_barrier()
   end subroutine transport_barrier

   !> The largest `value` over the ranks (every rank gets it).
   integer function transport_max(value)
      integer, intent(in) :: value
      transport_max = value
   end function transport_max

   !> Every rank gets the stat /= 0 and errmsg of the lowest rank that has one (stat = 0
   !! everywhere when none has).
   subroutine share_failure(stat, errmsg)
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      ! one process: its own failure is the only one
      if (stat /= 0) errmsg = trim(errmsg)
   end subroutine share_failure
end module vibrobeam_sweep_transport
