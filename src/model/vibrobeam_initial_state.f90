!> Initial displacement and velocity of a dynamics run (docs/input.md `&initial`).
!!
!! 'mode' data of the uniform clamped-free beam are the closed-form cantilever mode shapes
!! (theory §7), scaled so that the tip value is the given amplitude, and interpolated on the
!! mesh (Hermite: nodal values and slopes; B-splines: the spline through the nodal values
!! with the tip slope). Every other structure (docs/input.md, "&beam" supports) takes the
!! mode of the discrete model itself (`compute_modes`), scaled like the modes of
!! &analysis kind = 'modes': the amplitude at a free end, else at its largest nodal value.
!! 'uniform' velocity is a rigid translation at `amplitude` everywhere but next to the
!! clamp (or another end whose deflection a support holds), ramping monotonically from 0
!! there: Hermite, v = amplitude at every node with zero rotation rates (the ramp is the
!! first element); B-splines, every coefficient equal to
!! the amplitude, v = amplitude (1 - B_1 - B_2) by the partition of unity (the ramp spans
!! the first two elements, v(h) = 3/4 amplitude). Interpolating the nodal values instead,
!! as for mode data, overshoots: the spline through 0 (value and slope) at the clamp and
!! the amplitude at every node reaches 1.137 times the amplitude at x = 1.38 h, for every N
!! (a cubic spline's response to the clamp's jump, decaying by 2 - sqrt(3) per element).
module vibrobeam_initial_state
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use vibrobeam_kinds, only: dp
   use vibrobeam_model, only: beam_model, interpolate_field, flexibility_applies
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, &
      keyword_length, path_length
   implicit none
   private
   public :: mode_field, initial_velocity, initial_settings, visit_initial

   !> &initial as the input gives it (docs/input.md, "&initial").
   type :: initial_settings
      character(len=keyword_length) :: displacement = 'zero'
      integer :: displacement_mode = 1
      real(dp) :: displacement_amplitude = 0
      character(len=keyword_length) :: velocity = 'zero'
      integer :: velocity_mode = 1
      real(dp) :: velocity_amplitude = 0
      character(len=path_length) :: from_file = ''   !! continue from this results file ('' = no)
   end type initial_settings

contains

   !> Every variable of &initial, once (docs/input.md, "&initial").
   subroutine visit_initial(initial, visitor)
      type(initial_settings), intent(inout) :: initial
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(keyword_row('initial', 'displacement', 'zero|mode|static', keyword_length, &
                                        'initial displacement: zero, a natural mode, or the static equilibrium'), &
                            initial%displacement)
      call visitor%variable(integer_row('initial', 'displacement_mode', 1, 100, &
                                        'which natural mode the initial displacement is'), initial%displacement_mode)
      call visitor%variable(real_row('initial', 'displacement_amplitude', 'm', -1e6_dp, 1e6_dp, &
                                     'tip value of the initial mode shape'), initial%displacement_amplitude)
      call visitor%variable(keyword_row('initial', 'velocity', 'zero|mode|uniform', keyword_length, &
                                        'initial velocity: zero, a natural mode, or uniform'), initial%velocity)
      call visitor%variable(integer_row('initial', 'velocity_mode', 1, 100, &
                                        'which natural mode the initial velocity is'), initial%velocity_mode)
      call visitor%variable(real_row('initial', 'velocity_amplitude', 'm/s', -1e8_dp, 1e8_dp, &
                                     'tip velocity of the mode, or the uniform velocity'), initial%velocity_amplitude)
      call visitor%variable(text_row('initial', 'from_file', path_length, &
                                     'continue from the final state or last checkpoint of this results file'), &
                            initial%from_file)
   end subroutine visit_initial

   !> Unknowns of amplitude * (mode `mode`, 1 at the tip) on the mesh: the closed form of
   !! the uniform clamped-free beam, else the discrete mode (module documentation). NaN
   !! when that mode cannot be computed (the caller reports a field that is not finite).
   function mode_field(model, mode, amplitude) result(u)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: mode
      real(dp), intent(in) :: amplitude
      real(dp) :: u(model%unknowns)
      real(dp) :: value(model%elements), slope(model%elements)
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      integer :: i, stat
      character(len=256) :: errmsg
      if (.not. (model%boundary%has_mode_shapes() .and. flexibility_applies(model) .and. &
                 model%structure%masses() == 0)) then
         u = ieee_value(1.0_dp, ieee_quiet_nan)
         if (mode > model%unknowns) return
         call compute_modes(model, mode, omega, shapes, vectors, stat, errmsg)
         if (stat == 0) u = amplitude*vectors(:, mode)
         return
      end if
      do i = 1, model%elements
         value(i) = model%boundary%mode_shape(mode, model%x(i + 1), model%length, 0)
         slope(i) = model%boundary%mode_shape(mode, model%x(i + 1), model%length, 1)
      end do
      u = amplitude*interpolate_field(model, value, slope)
   end function mode_field

   !> Initial velocity unknowns from `&initial velocity`.
   function initial_velocity(initial, model) result(v)
      type(initial_settings), intent(in) :: initial
      type(beam_model), intent(in) :: model
      real(dp) :: v(model%unknowns)
      integer :: i
      select case (initial%velocity)
      case ('mode')
         v = mode_field(model, initial%velocity_mode, initial%velocity_amplitude)
      case ('uniform')
         if (.not. model%hermite) then
            v = initial%velocity_amplitude   ! B-spline coefficients: bounded by them, no overshoot
         else
            v = interpolate_field(model, [(initial%velocity_amplitude, i=1, model%elements)], &
                                  [(0.0_dp, i=1, model%elements)])
            ! a left end free to move moves too (only a held end ramps the velocity)
            if (model%unknown_of(1) > 0) v(model%unknown_of(1)) = initial%velocity_amplitude
         end if
      case default
         v = 0
      end select
   end function initial_velocity
end module vibrobeam_initial_state
