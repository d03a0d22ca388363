!> What an accumulator of a dynamics run sees (docs/output.md, "Streaming"): the recorder
!! calls each observer after every step and puts each one's state into the checkpoint.
!! Contact episodes (`vibrobeam_episodes`) are one, the statistics over a window
!! (`vibrobeam_statistics`) another, which sees what the episodes decided in the step
!! (`step_events`). An observer that writes datasets creates them with the recorder's
!! (before the file enters SWMR mode, where no object or attribute can be created).
module vibrobeam_step_observer
   use vibrobeam_kinds, only: dp
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_state_record, only: state_record
   implicit none
   private
   public :: step_observer, step_events

   !> What the recorder decided about the last step, beside the stepper's own record.
   type :: step_events
      !> (contact points) entry k of the stepper's active list is a new impact
      !! (docs/method.md, "Impacts and contact statistics")
      logical, allocatable :: impact(:)
      !> (observation points, 2) u and v at the tip (1) and at each &output points x,
      !! after the step (when an observer needs them)
      real(dp), allocatable :: observed(:, :)
      !> (observation points, 2) the same in z for a beam of two planes (0 for a planar one)
      real(dp), allocatable :: observed_z(:, :)
      !> contact episodes that closed in the step: at closed_point(1:closed_count), of total
      !! impulse closed_impulse (N s)
      integer :: closed_count = 0
      integer, allocatable :: closed_point(:)
      real(dp), allocatable :: closed_impulse(:)
      !> (contact points) an episode opened at the point in the step
      logical, allocatable :: opened(:)
   end type step_events

   !> An accumulator of a dynamics run: it sees every step (and what the observers before
   !! it decided in the step, in `events`) and keeps its state in the checkpoint. The
   !! recorder calls its observers in order: the episodes, then the statistics.
   type, abstract :: step_observer
   contains
      procedure(observe_step_interface), deferred :: observe_step
      procedure(save_state_interface), deferred :: save_state
      procedure(restore_state_interface), deferred :: restore_state
   end type step_observer

   abstract interface
      !> After every step: `events` holds what the recorder and the observers before this
      !! one decided about the step; an observer adds its own decisions for those after it.
      subroutine observe_step_interface(self, stepper, events, stat, errmsg)
         import :: step_observer, time_stepper, step_events
         class(step_observer), intent(inout) :: self
         class(time_stepper), intent(in) :: stepper
         type(step_events), intent(inout) :: events
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine observe_step_interface

      !> Put the observer's state into a checkpoint record.
      subroutine save_state_interface(self, record)
         import :: step_observer, state_record
         class(step_observer), intent(in) :: self
         type(state_record), intent(inout) :: record
      end subroutine save_state_interface

      !> Take the observer's state back from a checkpoint record.
      subroutine restore_state_interface(self, record, stat, errmsg)
         import :: step_observer, state_record
         class(step_observer), intent(inout) :: self
         type(state_record), intent(in) :: record
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine restore_state_interface
   end interface
end module vibrobeam_step_observer
