!> Every real input of a scene by its name (docs/sweeps.md, "The parameter"): what a sweep
!! sets at each of its points. Both walk the scene's declarations (`visit_scene` with a
!! `schema_accessor`), so every real scalar, and every element of a real array, of every
!! group can be swept (verification/unit/test_scene_values.f90 sets each one). Setting a
!! frequency sets its twin in Hz with it, and setting a twin its frequency
!! (`vibrobeam_frequency_twins`): a sweep over `load.base_frequency_hz` runs each point at
!! base_frequency = 2 pi times the value.
module vibrobeam_scene_values
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type, visit_scene
   use vibrobeam_schema_operations, only: schema_accessor
   use vibrobeam_frequency_twins, only: pair_accessor, pair_for
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
      type(schema_accessor) :: accessor
      copy = scene
      accessor = schema_accessor(group=group, name=name, index=index, set=.false.)
      call visit_scene(copy, accessor)
      value = accessor%value
      found = accessor%found
   end subroutine real_input

   !> Set 'group.name' (element `index`) to `value`, and its twin with it (a frequency's in
   !! Hz, a twin's frequency in rad/s); `found` as for `real_input`.
   subroutine set_real_input(scene, group, name, index, value, found)
      type(scene_type), intent(inout) :: scene
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: index
      real(dp), intent(in) :: value
      logical, intent(out) :: found
      type(pair_accessor) :: accessor
      accessor = pair_for(group, name, index, .true., value)
      call visit_scene(scene, accessor)
      found = accessor%named%found
   end subroutine set_real_input
end module vibrobeam_scene_values
