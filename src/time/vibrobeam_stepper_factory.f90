!> The one place that names the time schemes (docs/input.md, &time scheme): which exist
!! (`scheme_names`, the choices of the input), the stepper of a scheme at the start of a
!! run (`new_time_stepper`), the state a scheme's checkpoint holds (`state_from_record`),
!! and freeing a stepper (`release_stepper`). A new scheme is a module of time/ and a case
!! in each `select case` here.
module vibrobeam_stepper_factory
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_invalid_argument
   use vibrobeam_state_record, only: state_record
   use vibrobeam_discrete_system, only: discrete_system
   use vibrobeam_time_stepper, only: time_stepper, stepper_settings, dynamic_state, checkpoint_state
   use vibrobeam_velocity_stepper, only: velocity_stepper
   use vibrobeam_position_stepper, only: position_stepper, position_state_of_record
   implicit none
   private
   public :: scheme_names, new_time_stepper, state_from_record, release_stepper, can_linearise, linearise_step

   !> The schemes, as `&time scheme` names them: the velocity-based scheme (theory §3) and
   !! the position-based Paoli-Schatzman scheme (theory §4).
   character(len=*), parameter :: scheme_list = 'velocity|position'

contains

   !> 'velocity|position': the allowed values of &time scheme.
   pure function scheme_names() result(names)
      character(len=:), allocatable :: names
      names = scheme_list
   end function scheme_names

   !> The stepper of settings%scheme for `system`, set up at `start`; with `resume`, the
   !! checkpoint it continues (everything the stepper saved, `save_state`) taken back.
   subroutine new_time_stepper(system, settings, start, stepper, stat, errmsg, resume)
      type(discrete_system), intent(in) :: system
      type(stepper_settings), intent(in) :: settings
      type(dynamic_state), intent(in) :: start
      class(time_stepper), allocatable, intent(out) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(state_record), intent(in), optional :: resume
      select case (settings%scheme)
      case ('velocity')
         allocate (velocity_stepper :: stepper)
      case ('position')
         allocate (position_stepper :: stepper)
      case default
         stat = stat_invalid_argument
         errmsg = 'no time scheme '''//trim(settings%scheme)//''' (the schemes: '//scheme_list//')'
         return
      end select
      call stepper%init(system, settings, start, stat, errmsg)
      if (stat == 0 .and. present(resume)) call stepper%restore_state(resume, stat, errmsg)
   end subroutine new_time_stepper

   !> The state (step, U, V of `unknowns` values, and the scheme's extra) that a checkpoint
   !! of `scheme` holds: where a continued run or a sweep starts.
   subroutine state_from_record(scheme, record, unknowns, state, stat, errmsg)
      character(len=*), intent(in) :: scheme
      type(state_record), intent(in) :: record
      integer, intent(in) :: unknowns
      type(dynamic_state), intent(out) :: state
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      select case (scheme)
      case ('position')
         call position_state_of_record(record, unknowns, state, stat, errmsg)
      case default
         call checkpoint_state(record, unknowns, state, stat, errmsg)
      end select
   end subroutine state_from_record

   !> Whether the period map takes the monodromy from `linearise_step` for `stepper`
   !! (docs/method.md, "Periodic orbits by shooting"): the velocity scheme with rigid stops
   !! only. `linearise_step` also linearises compliant stops (the Lyapunov exponent's
   !! tangent), but the periodic analysis keeps its finite differences there.
   logical function can_linearise(stepper)
      class(time_stepper), intent(in) :: stepper
      select type (stepper)
      type is (velocity_stepper)
         can_linearise = stepper%contacts%springs%count == 0
      class default
         can_linearise = .false.
      end select
   end function can_linearise

   !> Apply the derivative of the last step of `stepper` to the columns of (du, dv) (the
   !! scheme's `tangent`); stat_invalid_argument for a scheme that has none.
   subroutine linearise_step(stepper, du, dv, stat, errmsg)
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(inout) :: du(:, :), dv(:, :)   !! (unknowns, columns)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      select type (stepper)
      type is (velocity_stepper)
         call stepper%tangent(du, dv, stat, errmsg)
      class default
         stat = stat_invalid_argument
         write (errmsg, '(a,i0,a)') 'this time scheme does not linearise its steps (', size(du, 2), &
            ' perturbations asked for)'
      end select
   end subroutine linearise_step

   !> Free a stepper and all it holds. gfortran 12 frees only the first of the band-matrix
   !! components of one type when a polymorphic stepper is deallocated (two blocks were lost
   !! per stepper, once per sweep point: valgrind, issue 23): the others are freed first.
   subroutine release_stepper(stepper)
      class(time_stepper), allocatable, intent(inout) :: stepper
      if (.not. allocated(stepper)) return
      if (allocated(stepper%stiffness%lower)) deallocate (stepper%stiffness%lower)
      if (allocated(stepper%iteration_matrix%lower)) deallocate (stepper%iteration_matrix%lower)
      deallocate (stepper)
   end subroutine release_stepper
end module vibrobeam_stepper_factory
