!> A sweep from start to published sweep file (docs/sweeps.md): the points of
!! `vibrobeam_sweep_settings` run as independent tasks (`vibrobeam_sweep_runner`) on the
!! threads of each process (OpenMP; OMP_NUM_THREADS or every core) and, in an MPI build,
!! over the ranks; rank 0 gathers the results and writes the sweep file
!! (`vibrobeam_sweep_file`). The answers do not depend on the number of threads or ranks:
!! each point's computation depends only on its task's earlier points, never on how tasks
!! are shared out, and the program asks the BLAS for one thread (`limit_blas_threads`).
module vibrobeam_sweep
   !$ use omp_lib, only: omp_get_max_threads
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_setup, only: prepared_scene, prepare_scene
   use vibrobeam_checkpoint, only: read_checkpoint
   use vibrobeam_restart_check, only: check_compatible
   use vibrobeam_state_record, only: state_record
   use vibrobeam_statistics_layout, only: statistics_layout
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, sweep_points, point_scene, task_count
   use vibrobeam_sweep_runner, only: point_result, start_state, run_task, status_failed, status_interrupted
   use vibrobeam_sweep_file, only: write_sweep_file
   use vibrobeam_sweep_transport, only: transport_rank, transport_ranks, gather_results, owns_task
   implicit none
   private
   public :: run_sweep, sweep_outcome, sweep_threads

   !> What a sweep reports back to the program.
   type :: sweep_outcome
      character(len=16) :: status = 'ok'       !! 'ok' | 'interrupted' (/run status)
      integer :: points = 0, failed = 0, interrupted = 0
      logical :: text_skipped = .false.
      real(dp) :: wall_seconds = 0
      integer :: threads = 1, ranks = 1
      character(len=2048) :: failures = ''     !! the first failed points and their reasons
   end type sweep_outcome

contains

   !> Threads each process runs tasks on: OMP_NUM_THREADS, or every core (1 without OpenMP).
   integer function sweep_threads()
      sweep_threads = 1
      !$ sweep_threads = omp_get_max_threads()
   end function sweep_threads

   !> Run every point and publish the sweep file `scene%output%file` (on rank 0). stat /= 0 (with
   !! errmsg) when no sweep file could be written or the start state of &initial from_file
   !! cannot be read (then stat = 2: invalid input).
   subroutine run_sweep(scene, settings, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(sweep_point), allocatable :: points(:)
      type(point_result), allocatable :: results(:)
      type(start_state) :: base
      type(prepared_scene) :: first
      type(statistics_layout) :: layout
      type(progress_meter) :: meter
      type(scene_type) :: first_scene
      character(len=:), allocatable :: warnings
      integer :: task, tasks, rank, ranks, done, k
      call meter%init(scene%output%progress)
      rank = transport_rank()
      ranks = transport_ranks()
      if (rank /= 0) meter%enabled = .false.
      outcome%threads = sweep_threads()
      outcome%ranks = ranks
      allocate (points, source=sweep_points(settings))
      outcome%points = size(points)
      tasks = task_count(points)
      allocate (results(size(points)))
      ! the first point's scene: the model of the sweep file, its contact points
      first_scene = point_scene(scene, settings, points(1))
      warnings = ''
      call prepare_scene(first_scene, first, warnings, stat, errmsg)
      if (stat /= 0) then
         ! the points' own failures are reported per point; this one's contact points are needed
         if (.not. allocated(first%contacts%x)) then
            errmsg = '&sweep point 1: '//trim(errmsg)
            stat = 2
            return
         end if
         stat = 0
      end if
      if (len_trim(scene%initial%from_file) > 0) then
         call read_start(trim(scene%initial%from_file))
         if (stat /= 0) return
      end if
      done = 0
      !$omp parallel do schedule(dynamic, 1) default(shared) private(task)
      do task = 1, tasks
         if (.not. owns_task(task, rank, ranks)) cycle
         call run_task(scene, settings, points, task, base, results)
         !$omp critical (vibrobeam_sweep_progress)
         done = done + count(points%task == task)
         if (meter%due()) call meter%report('sweep: '//integer_text(done)//' of '//integer_text(size(points))// &
                                            ' points ('//integer_text(rank)//'), wall '// &
                                            real_text(nint(meter%elapsed()*10)/10.0_dp)//' s')
         !$omp end critical (vibrobeam_sweep_progress)
      end do
      !$omp end parallel do
      call meter%end_line()
      call gather_results(points%task, results, stat, errmsg)
      if (stat /= 0) return
      outcome%wall_seconds = meter%elapsed()
      if (interrupt_requested()) outcome%status = 'interrupted'
      outcome%failed = count(results%status == status_failed)
      outcome%interrupted = count(results%status == status_interrupted)
      do k = 1, size(points)
         if (results(k)%status /= status_failed) cycle
         if (len_trim(outcome%failures) + len_trim(results(k)%message) > len(outcome%failures) - 40) exit
         outcome%failures = trim(outcome%failures)//'point '//integer_text(k)//': '//trim(results(k)%message)// &
                            new_line('a')
      end do
      if (rank /= 0) return
      call layout%init(1 + size(first_scene%output%points), first%contacts%count, size(first_scene%obstacles))
      call write_sweep_file(scene, first%model, settings, points, results, layout, &
                            [first_scene%beam%length, first_scene%output%points], first%contacts%x, &
                               first%contacts%lower_obstacle, &
                            first%contacts%upper_obstacle, outcome%status, outcome%wall_seconds, outcome%threads, &
                            ranks, meter, outcome%text_skipped, stat, errmsg)
      call meter%end_line()
   contains
      !> The start state of &initial from_file: U, V (and U^{n-1}) of its checkpoint, at t = 0.
      subroutine read_start(file)
         character(len=*), intent(in) :: file
         type(state_record) :: record
         real(dp) :: time
         logical :: same_bounds
         call check_compatible(file, first_scene, first%contacts%x, first%contacts%lower, first%contacts%upper, &
                               same_bounds, stat, errmsg)
         if (stat == 0) call read_checkpoint(file, record, time, stat, errmsg)
         if (stat /= 0) then
            if (index(errmsg, '&initial from_file') == 0) errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
            stat = 2
            return
         end if
         allocate (base%u(first%model%unknowns), base%v(first%model%unknowns))
         call record%get_reals('stepper.u', base%u, stat, errmsg)
         if (stat == 0) call record%get_reals('stepper.v', base%v, stat, errmsg)
         if (stat == 0 .and. record%find('stepper.u_previous') > 0) then
            allocate (base%u_previous(first%model%unknowns))
            call record%get_reals('stepper.u_previous', base%u_previous, stat, errmsg)
         end if
         if (stat /= 0) then
            errmsg = '&initial from_file = '''//file//''': '//trim(errmsg)
            stat = 2
            return
         end if
         base%given = .true.
      end subroutine read_start
   end subroutine run_sweep
end module vibrobeam_sweep
