!> A dynamics run from start to result files (&analysis kind = 'dynamics'): the time loop
!! around the scheme's stepper, output sampling, progress reports and failure handling.
!!
!! The run takes n = nint(t_end/dt) steps (t_end is rounded to a whole number of steps;
!! a warning says so when that changes it by more than 1e-9 dt). On a numerical failure
!! (contact solver without convergence, non-finite state) the histories up to the last
!! good step are written, complete, with /run status = 'failed'.
module vibrobeam_dynamics
   use, intrinsic :: iso_c_binding, only: c_int
   use vibrobeam_kinds, only: dp, int64, error_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_setup, only: prepared_scene, start_time_stepper
   use vibrobeam_stepper, only: time_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_results, only: result_files
   implicit none
   private
   public :: run_dynamics, run_outcome

   !> What a run reports back to the program.
   type :: run_outcome
      logical :: failed = .false.        !! numerical failure (results written, marked failed)
      integer :: steps = 0
      integer :: impacts = 0
      real(dp) :: wall_seconds = 0
      real(dp) :: max_penetration = 0
      character(len=512) :: failure = ''
   end type run_outcome

   interface
      function c_isatty(fd) result(flag) bind(C, name='isatty')
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: flag
      end function c_isatty
   end interface

contains

   !> Run the scene and write its results. stat /= 0 (with errmsg) only for failures that
   !! prevented writing results (I/O); a numerical failure is reported in `outcome`.
   subroutine run_dynamics(scene, prepared, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      class(time_stepper), allocatable :: stepper
      type(dynamics_recorder) :: recorder
      type(result_files) :: files
      integer :: steps, n, step_stat
      integer(int64) :: start, now, rate, last_report
      logical :: report
      character(len=512) :: step_message
      call system_clock(start, rate)
      steps = max(1, nint(scene%t_end/scene%dt))
      if (abs(steps*scene%dt - scene%t_end) > 1e-9_dp*scene%dt) write (error_unit, '(a,es14.7,a)') &
         'vibrobeam: warning: t_end is not a whole number of steps; the run ends at ', steps*scene%dt, ' s'
      call start_time_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) return
      call recorder%init(stepper, prepared%model)
      call recorder%sample(stepper, prepared%model)
      report = scene%progress .or. c_isatty(2_c_int) == 1
      last_report = start
      do n = 1, steps
         call stepper%step(step_stat, step_message)
         if (step_stat /= 0) then
            outcome%failed = .true.
            write (outcome%failure, '(a,i0,a,es14.7,a)') 'step ', n, ' (t = ', stepper%t + stepper%dt, &
               ' s): '//trim(step_message)
            exit
         end if
         call recorder%after_step(stepper)
         if (mod(n, scene%every) == 0 .or. n == steps) call recorder%sample(stepper, prepared%model)
         if (report) then
            call system_clock(now)
            if (now - last_report >= rate) then
               call progress_line(n, steps, stepper%t, real(now - start, dp)/rate)
               last_report = now
            end if
         end if
      end do
      ! a failed run still ends with a sample of the last good state
      if (outcome%failed .and. recorder%last_output_time < stepper%t) call recorder%sample(stepper, prepared%model)
      if (report) write (error_unit, '(a)') ''
      outcome%steps = stepper%steps
      outcome%impacts = recorder%impacts%rows
      outcome%max_penetration = recorder%max_penetration
      call files%open(scene, prepared%model, stat, errmsg)
      if (stat == 0) call recorder%write(files, prepared%model, stepper, stat, errmsg)
      call system_clock(now)
      outcome%wall_seconds = real(now - start, dp)/rate
      if (stat == 0) call files%commit(trim(merge('failed', 'ok    ', outcome%failed)), stepper%steps, &
                                       outcome%wall_seconds, recorder%iterations_total, recorder%iterations_max, &
                                       stat, errmsg)
      if (stat /= 0) call files%discard()
   end subroutine run_dynamics

   subroutine progress_line(n, steps, t, elapsed)
      integer, intent(in) :: n, steps
      real(dp), intent(in) :: t, elapsed
      real(dp) :: left
      left = elapsed*(steps - n)/max(n, 1)
      write (error_unit, '(a,f6.2,a,es11.4,a,f9.1,a,f9.1,a)', advance='no') achar(13)//'vibrobeam: ', &
         100.0_dp*n/steps, ' %  t = ', t, ' s  wall ', elapsed, ' s  left ~', left, ' s'
      flush (error_unit)
   end subroutine progress_line
end module vibrobeam_dynamics
