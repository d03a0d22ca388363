!> The one time loop of vibrobeam: a single run (`vibrobeam_dynamics`) and a sweep's
!! point (`vibrobeam_sweep_runner`) both step through `advance`, so a run and a point
!! stop, record and report a failure the same way. Each step: the stepper's step, the
!! recorder's work (impacts, episodes, statistics and, when it writes a result file, the
!! samples due), the interruption test (SIGINT/SIGTERM: the step in progress is finished),
!! and what the caller adds after a step (`run_hooks`: a single run flushes its file,
!! writes checkpoints and reports progress).
module vibrobeam_run_loop
   use vibrobeam_kinds, only: int64
   use vibrobeam_status, only: outcome_ok, outcome_failed, outcome_interrupted
   use vibrobeam_model, only: beam_model
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_signals, only: interrupt_requested
   implicit none
   private
   public :: advance, run_hooks

   !> What a run does after each step beyond recording it.
   type, abstract :: run_hooks
   contains
      procedure(after_step_interface), deferred :: after_step
   end type run_hooks

   abstract interface
      !> After step `step` (recorded). stat /= 0 stops the loop (an I/O error).
      subroutine after_step_interface(self, stepper, recorder, step, stat, errmsg)
         import :: run_hooks, time_stepper, dynamics_recorder, int64
         class(run_hooks), intent(inout) :: self
         class(time_stepper), intent(in) :: stepper
         type(dynamics_recorder), intent(inout) :: recorder
         integer(int64), intent(in) :: step
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine after_step_interface
   end interface

contains

   !> Step from stepper%steps to `last` (global step numbers). `status` says how the loop
   !! ended: 'ok' at `last`; 'failed' at a numerical failure of a step (the stepper's state
   !! is that of the last good step; `failure` reads 'step n (t = ... s): reason');
   !! 'interrupted' after the step during which SIGINT or SIGTERM came. stat /= 0 (errmsg):
   !! the recorder or a hook failed (an I/O error), the loop stopped. `model` is the mesh's
   !! (field samples).
   subroutine advance(stepper, recorder, model, last, status, failure, stat, errmsg, hooks)
      class(time_stepper), intent(inout) :: stepper
      type(dynamics_recorder), intent(inout) :: recorder
      type(beam_model), intent(in) :: model
      integer(int64), intent(in) :: last
      integer, intent(out) :: status
      character(len=*), intent(out) :: failure
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      class(run_hooks), intent(inout), optional :: hooks
      integer(int64) :: n
      integer :: step_stat
      character(len=512) :: step_message
      status = outcome_ok
      failure = ''
      stat = 0
      errmsg = ''
      do n = stepper%steps + 1, last
         call stepper%step(step_stat, step_message)
         if (step_stat /= 0) then
            status = outcome_failed
            write (failure, '(a,i0,a,es14.7,a)') 'step ', n, ' (t = ', n*stepper%dt, ' s): '//trim(step_message)
            return
         end if
         call recorder%record_step(stepper, model, n, stat, errmsg)
         if (stat /= 0) return
         if (interrupt_requested()) then
            status = outcome_interrupted
            return
         end if
         if (present(hooks)) then
            call hooks%after_step(stepper, recorder, n, stat, errmsg)
            if (stat /= 0) return
         end if
      end do
   end subroutine advance
end module vibrobeam_run_loop
