!> Initial displacement and velocity of a dynamics run (INTERFACE.md `&initial`).
!!
!! 'mode' data are the closed-form cantilever mode shapes (SPEC §6), scaled so that the
!! tip value is the given amplitude, and interpolated on the mesh (Hermite: nodal values
!! and slopes; B-splines: the spline through the nodal values with the tip slope).
!! 'uniform' velocity is v = amplitude at every node with zero slope rate (Hermite: zero
!! rotation rates; B-splines: zero slope rate at the tip), a rigid translation everywhere
!! but next to the clamp.
module vibrobeam_initial_state
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   use vibrobeam_model, only: beam_model, interpolate_field
   use vibrobeam_cantilever_exact, only: cantilever_mode_shape
   implicit none
   private
   public :: mode_field, initial_velocity

contains

   !> Unknowns of amplitude * (closed-form mode `mode`, tip value 1) on the mesh.
   function mode_field(model, mode, amplitude) result(u)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: mode
      real(dp), intent(in) :: amplitude
      real(dp) :: u(model%unknowns)
      real(dp) :: value(model%elements), slope(model%elements)
      integer :: i
      do i = 1, model%elements
         value(i) = cantilever_mode_shape(mode, model%x(i + 1), model%length, 0)
         slope(i) = cantilever_mode_shape(mode, model%x(i + 1), model%length, 1)
      end do
      u = amplitude*interpolate_field(model, value, slope)
   end function mode_field

   !> Initial velocity unknowns from `&initial velocity`.
   function initial_velocity(scene, model) result(v)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      real(dp) :: v(model%unknowns)
      integer :: i
      select case (scene%velocity)
      case ('mode')
         v = mode_field(model, scene%velocity_mode, scene%velocity_amplitude)
      case ('uniform')
         v = interpolate_field(model, [(scene%velocity_amplitude, i=1, model%elements)], &
                               [(0.0_dp, i=1, model%elements)])
      case default
         v = 0
      end select
   end function initial_velocity
end module vibrobeam_initial_state
