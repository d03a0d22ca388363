!> Every real input of a scene by its name (docs/sweeps.md, "The parameter"): what a sweep
!! sets at each of its points. `real_input` and `set_real_input` cover every real variable
!! of `scene_variables` (verification/unit/test_scene_values.f90 checks that against the
!! table), so any real scalar, or element of a real array, can be swept.
module vibrobeam_scene_values
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   implicit none
   private
   public :: real_input, set_real_input

contains

   !> The value of 'group.name' (element `index` of an array; 1 for a scalar) into
   !! `value`; `found` is false when the scene has no such real input (or element).
   subroutine real_input(scene, group, name, index, value, found)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: index
      real(dp), intent(out) :: value
      logical, intent(out) :: found
      type(scene_type) :: copy
      copy = scene
      call access(copy, group, name, index, value, .false., found)
   end subroutine real_input

   !> Set 'group.name' (element `index`) to `value`; `found` as for `real_input`.
   subroutine set_real_input(scene, group, name, index, value, found)
      type(scene_type), intent(inout) :: scene
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: index
      real(dp), intent(in) :: value
      logical, intent(out) :: found
      real(dp) :: new_value
      new_value = value
      call access(scene, group, name, index, new_value, .true., found)
   end subroutine set_real_input

   !> Read (set = .false.) or write (set = .true.) one real input.
   subroutine access(scene, group, name, index, value, set, found)
      type(scene_type), intent(inout) :: scene
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: index
      real(dp), intent(inout) :: value
      logical, intent(in) :: set
      logical, intent(out) :: found
      found = .true.
      select case (trim(group)//'.'//trim(name))
      case ('beam.length'); call take(scene%length)
      case ('beam.k2'); call take(scene%k2)
      case ('beam.youngs_modulus'); call take(scene%youngs_modulus)
      case ('beam.density'); call take(scene%density)
      case ('beam.area'); call take(scene%area)
      case ('beam.inertia'); call take(scene%inertia)
      case ('beam.rayleigh_mass'); call take(scene%rayleigh_mass)
      case ('beam.rayleigh_stiffness'); call take(scene%rayleigh_stiffness)
      case ('impact.restitution'); call take(scene%restitution)
      case ('time.t_end'); call take(scene%t_end)
      case ('time.dt'); call take(scene%dt)
      case ('time.theta'); call take(scene%theta)
      case ('time.gamma'); call take(scene%gamma)
      case ('initial.displacement_amplitude'); call take(scene%displacement_amplitude)
      case ('initial.velocity_amplitude'); call take(scene%velocity_amplitude)
      case ('load.distributed'); call take(scene%distributed)
      case ('load.distributed_frequency'); call take(scene%distributed_frequency)
      case ('load.distributed_phase'); call take(scene%distributed_phase)
      case ('load.point_force'); call take(scene%point_force)
      case ('load.point_position'); call take(scene%point_position)
      case ('load.point_frequency'); call take(scene%point_frequency)
      case ('load.base_amplitude'); call take(scene%base_amplitude)
      case ('load.base_frequency'); call take(scene%base_frequency)
      case ('load.base_acceleration'); call take(scene%base_acceleration)
      case ('output.measure_from'); call take(scene%measure_from)
      case ('output.checkpoint_seconds'); call take(scene%checkpoint_seconds)
      case ('output.episode_gap'); call take(scene%episode_gap)
      case ('output.points')
         found = allocated(scene%points)
         if (found) found = index >= 1 .and. index <= size(scene%points)
         if (found) call take(scene%points(index))
      case ('obstacles.x_from', 'obstacles.x_to', 'obstacles.level_from', 'obstacles.level_to')
         found = allocated(scene%obstacles)
         if (found) found = index >= 1 .and. index <= size(scene%obstacles)
         if (.not. found) return
         select case (trim(name))
         case ('x_from'); call take(scene%obstacles(index)%x_from)
         case ('x_to'); call take(scene%obstacles(index)%x_to)
         case ('level_from'); call take(scene%obstacles(index)%level_from)
         case default; call take(scene%obstacles(index)%level_to)
         end select
      case default
         found = .false.
      end select
   contains
      subroutine take(field)
         real(dp), intent(inout) :: field
         if (set) then
            field = value
         else
            value = field
         end if
      end subroutine take
   end subroutine access
end module vibrobeam_scene_values
