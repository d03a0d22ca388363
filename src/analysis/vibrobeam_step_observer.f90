!> What an accumulator of a dynamics run sees (docs/output.md, "Streaming"): the recorder
!! calls each observer after every step, at every history output, when buffers are
!! written and at the end, and puts each one's state into the checkpoint. Contact
!! episodes (`vibrobeam_episodes`) are one, the statistics over a window
!! (`vibrobeam_statistics`) another, which sees what the episodes decided in the step.
!!
!! Datasets must be created in `create_datasets` (the file then enters SWMR mode, where
!! no object or attribute can be created; `finish` writes into what exists).
module vibrobeam_step_observer
   use vibrobeam_kinds, only: dp
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_hdf5, only: h5_writer
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
      !> contact episodes that closed in the step: at closed_point(1:closed_count), of total
      !! impulse closed_impulse (N s)
      integer :: closed_count = 0
      integer, allocatable :: closed_point(:)
      real(dp), allocatable :: closed_impulse(:)
      !> (contact points) an episode opened at the point in the step
      logical, allocatable :: opened(:)
   end type step_events

   type, abstract :: step_observer
   contains
      procedure(observe_step_interface), deferred :: observe_step
      procedure :: observe_output
      procedure :: create_datasets
      procedure :: write_buffers
      procedure :: finish
      procedure :: save_state
      procedure :: restore_state
   end type step_observer

   abstract interface
      !> After every step.
      subroutine observe_step_interface(self, stepper, events, stat, errmsg)
         import :: step_observer, time_stepper, step_events
         class(step_observer), intent(inout) :: self
         class(time_stepper), intent(in) :: stepper
         type(step_events), intent(in) :: events
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine observe_step_interface
   end interface

contains

   !> At every history output time (default: nothing).
   subroutine observe_output(self, stepper, stat, errmsg)
      class(step_observer), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.false.) call unused(self, stepper%t)
   end subroutine observe_output

   !> Create the observer's datasets, before the file enters SWMR mode (default: none).
   subroutine create_datasets(self, writer, stat, errmsg)
      class(step_observer), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.false.) call unused(self, real(len(writer%temporary_file()), dp))
   end subroutine create_datasets

   !> Write buffered rows (at a flush; default: nothing).
   subroutine write_buffers(self, stat, errmsg)
      class(step_observer), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.false.) call unused(self, 0.0_dp)
   end subroutine write_buffers

   !> Write the final results at the end of the run into the datasets and attributes made
   !! by `create_datasets` (default: nothing).
   subroutine finish(self, writer, stat, errmsg)
      class(step_observer), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.false.) call unused(self, real(len(writer%temporary_file()), dp))
   end subroutine finish

   !> Put the observer's state into a checkpoint record (default: none).
   subroutine save_state(self, record)
      class(step_observer), intent(in) :: self
      type(state_record), intent(inout) :: record
      if (.false.) call unused(self, real(record%count, dp))
   end subroutine save_state

   !> Take the observer's state back from a checkpoint record (default: none).
   subroutine restore_state(self, record, stat, errmsg)
      class(step_observer), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.false.) call unused(self, real(record%count, dp))
   end subroutine restore_state

   !> Keeps -Wunused-dummy-argument quiet in the empty defaults.
   subroutine unused(self, value)
      class(step_observer), intent(in) :: self
      real(dp), intent(in) :: value
      if (.false.) print *, same_type_as(self, self), value
   end subroutine unused
end module vibrobeam_step_observer
