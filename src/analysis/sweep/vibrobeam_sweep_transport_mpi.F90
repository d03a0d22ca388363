!> Where the tasks of a sweep run and how their results reach rank 0, in the MPI build
!! (-DVIBROBEAM_MPI=ON; docs/sweeps.md, "Parallel runs"): `mpirun -n P vibrobeam sweep.nml`
!! deals the tasks round-robin to the P ranks, each rank runs its own on its threads, and
!! the ranks send the results of their points to rank 0, which writes the sweep file. Only
!! the main thread of a process calls MPI (MPI_THREAD_FUNNELED). The same interface
!! without MPI is src/analysis/sweep/vibrobeam_sweep_transport.f90.
!!
!! A point's result travels as one message of doubles (every integer in it is exactly
!! representable) and one of characters (its message), so rank 0 holds the same bits as
!! the rank that computed it.
module vibrobeam_sweep_transport
   use mpi_f08
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_sweep_runner, only: point_result
   implicit none
   private
   public :: transport_start, transport_stop, transport_rank, transport_ranks, gather_results, owns_task

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
         stat = 1
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

   !> The results of the points whose task another rank ran are sent to rank 0, point by
   !! point in increasing order (so blocking sends and receives always match).
   subroutine gather_results(task_of, results, stat, errmsg)
      integer, intent(in) :: task_of(:)
      type(point_result), intent(inout) :: results(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: packed(:)
      integer :: rank, ranks, k, owner, length(1), error
      stat = 0
      errmsg = ''
      ranks = transport_ranks()
      if (ranks == 1) return
      rank = transport_rank()
      do k = 1, size(results)
         owner = mod(task_of(k) - 1, ranks)
         if (owner == 0) cycle
         if (rank == owner) then
            packed = pack_result(results(k))
            length(1) = size(packed)
            call MPI_Send(length, 1, MPI_INTEGER, 0, k, MPI_COMM_WORLD, error)
            call MPI_Send(packed, size(packed), MPI_DOUBLE_PRECISION, 0, k, MPI_COMM_WORLD, error)
            call MPI_Send(results(k)%message, len(results(k)%message), MPI_CHARACTER, 0, k, MPI_COMM_WORLD, error)
         else if (rank == 0) then
            call MPI_Recv(length, 1, MPI_INTEGER, owner, k, MPI_COMM_WORLD, MPI_STATUS_IGNORE, error)
            allocate (packed(length(1)))
            call MPI_Recv(packed, length(1), MPI_DOUBLE_PRECISION, owner, k, MPI_COMM_WORLD, MPI_STATUS_IGNORE, error)
            call MPI_Recv(results(k)%message, len(results(k)%message), MPI_CHARACTER, owner, k, MPI_COMM_WORLD, &
                          MPI_STATUS_IGNORE, error)
            call unpack_result(packed, results(k))
            deallocate (packed)
         end if
         if (error /= MPI_SUCCESS) then
            stat = 1
            errmsg = 'MPI could not gather the result of a sweep point'
            return
         end if
      end do
   end subroutine gather_results

   !> A point's result as doubles: its scalars, then values and errors of its statistics,
   !! then its kept Poincare samples.
   function pack_result(result) result(packed)
      type(point_result), intent(in) :: result
      real(dp), allocatable :: packed(:)
      integer :: values, kept, rows
      associate (s => result%statistics)
         values = 0
         if (allocated(s%values)) values = size(s%values)
         kept = 0
         rows = 0
         if (allocated(s%poincare_time)) kept = size(s%poincare_time)
         if (allocated(s%poincare_values)) rows = size(s%poincare_values, 1)
         packed = [real(result%status, dp), real(result%settled, dp), real(result%start_point, dp), &
                   real(result%settle_steps, dp), real(result%measure_steps, dp), result%dt, result%wall_seconds, &
                   merge(1.0_dp, 0.0_dp, s%present), real(s%first_step, dp), real(s%steps, dp), &
                   real(s%block_steps, dp), real(s%batches, dp), s%window_start, s%window_end, s%bin_width, &
                   real(s%poincare_total, dp), real(values, dp), real(kept, dp), real(rows, dp)]
         if (values > 0) packed = [packed, s%values, s%errors]
         if (kept > 0) packed = [packed, s%poincare_time, reshape(s%poincare_values, [rows*kept])]
      end associate
   end function pack_result

   subroutine unpack_result(packed, result)
      real(dp), intent(in) :: packed(:)
      type(point_result), intent(inout) :: result
      integer :: values, kept, rows, at
      result%status = nint(packed(1))
      result%settled = nint(packed(2))
      result%start_point = nint(packed(3))
      result%settle_steps = nint(packed(4), int64)
      result%measure_steps = nint(packed(5), int64)
      result%dt = packed(6)
      result%wall_seconds = packed(7)
      associate (s => result%statistics)
         s%present = packed(8) > 0
         s%first_step = nint(packed(9), int64)
         s%steps = nint(packed(10), int64)
         s%block_steps = nint(packed(11), int64)
         s%batches = nint(packed(12))
         s%window_start = packed(13)
         s%window_end = packed(14)
         s%bin_width = packed(15)
         s%poincare_total = nint(packed(16), int64)
         values = nint(packed(17))
         kept = nint(packed(18))
         rows = nint(packed(19))
         at = 19
         if (values > 0) then
            s%values = packed(at + 1:at + values)
            s%errors = packed(at + values + 1:at + 2*values)
            at = at + 2*values
         end if
         s%poincare_time = packed(at + 1:at + kept)
         s%poincare_values = reshape(packed(at + kept + 1:at + kept + rows*kept), [rows, kept])
      end associate
   end subroutine unpack_result
end module vibrobeam_sweep_transport
