!> Initial displacement and velocity of a dynamics run (docs/input.md `&initial`).
!!
!! 'mode' data are the closed-form cantilever mode shapes (theory §7), scaled so that the
!! tip value is the given amplitude, and interpolated on the mesh (Hermite: nodal values
!! and slopes; B-splines: the spline through the nodal values with the tip slope).
!! 'uniform' velocity is a rigid translation at `amplitude` everywhere but next to the
!! clamp, ramping monotonically from 0 there: Hermite, v = amplitude at every node with zero
!! rotation rates (the ramp is the first element); B-splines, every coefficient equal to
!! the amplitude, v = amplitude (1 - B_1 - B_2) by the partition of unity (the ramp spans
!! the first two elements, v(h) = 3/4 amplitude). Interpolating the nodal values instead,
!! as for mode data, overshoots: the spline through 0 (value and slope) at the clamp and
!! the amplitude at every node reaches 1.137 times the amplitude at x = 1.38 h, for every N
!! (a cubic spline's response to the clamp's jump, decaying by 2 - sqrt(3) per element).
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
         if (model%basis == 'bspline') then
            v = scene%velocity_amplitude   ! B-spline coefficients: bounded by them, no overshoot
         else
            v = interpolate_field(model, [(scene%velocity_amplitude, i=1, model%elements)], &
                                  [(0.0_dp, i=1, model%elements)])
         end if
      case default
         v = 0
      end select
   end function initial_velocity
end module vibrobeam_initial_state
