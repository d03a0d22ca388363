!> Where the tasks of a sweep run and how their results reach the process that writes the
!! sweep file (docs/sweeps.md, "Parallel runs"). This is the build without MPI: one
!! process (rank 0 of 1) runs every task. With -DVIBROBEAM_MPI=ON the same module comes
!! from src/analysis/sweep/vibrobeam_sweep_transport_mpi.F90, which spreads the tasks over the ranks of
!! `mpirun` and gathers the results on rank 0.
module vibrobeam_sweep_transport
   use vibrobeam_sweep_runner, only: point_result
   implicit none
   private
   public :: transport_start, transport_stop, transport_rank, transport_ranks, gather_results, owns_task

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

   !> Make every rank's `results` those of rank 0's view: the entries of the points whose
   !! task another rank ran are sent to rank 0 (nothing to do with one process).
   subroutine gather_results(task_of, results, stat, errmsg)
      integer, intent(in) :: task_of(:)
      type(point_result), intent(inout) :: results(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.false.) print *, size(task_of), size(results)
   end subroutine gather_results
end module vibrobeam_sweep_transport
