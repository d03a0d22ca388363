!> Initial displacement and velocity of a dynamics run (docs/input.md `&initial`).
!!
!! 'mode' data of the uniform clamped-free beam are the closed-form cantilever mode shapes
!! (theory §7), scaled so that the tip value is the given amplitude, and interpolated on the
!! mesh (`interpolate_field`: Hermite, nodal values and slopes; B-splines, the spline
!! through the nodal values with the free ends' slopes). Every other structure
!! (docs/input.md, "&beam" supports) takes the mode of the discrete model itself
!! (`compute_modes`), scaled like the modes of &analysis kind = 'modes': the amplitude at a
!! free end, else at its largest nodal value.
!! 'uniform' velocity is a rigid translation at `amplitude` everywhere but next to the
!! clamp (or another end whose deflection a support holds), ramping monotonically from 0
!! there: Hermite, v = amplitude at every node with zero rotation rates (the ramp is the
!! first element); B-splines, every coefficient equal to
!! the amplitude, v = amplitude (1 - B_1 - B_2) by the partition of unity (the ramp spans
!! the first two elements, v(h) = 3/4 amplitude). Interpolating the nodal values instead,
!! as for mode data, overshoots: the spline through 0 (value and slope) at the clamp and
!! the amplitude at every node reaches 1.137 times the amplitude at x = 1.38 h, for every N
!! (a cubic spline's response to the clamp's jump, decaying by 2 - sqrt(3) per element).
!! 'rotation' is the rigid rotation about the left end, v(x) = omega x, and 'profile' the
!! piecewise-linear v(x) of a table of (x, v) pairs (theory §1, "Initial data"); both are
!! interpolated like mode data (values at the nodes, slopes where the basis needs them),
!! so a linear v(x) that the supports allow is exact in both bases.
module vibrobeam_initial_state
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_failure, stat_invalid_input
   use vibrobeam_table_file, only: linear_table, read_table, outside_beam
   use vibrobeam_model, only: beam_model, interpolate_field, flexibility_applies
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, unset, &
      keyword_length, path_length
   implicit none
   private
   public :: mode_field, initial_velocity, initial_settings, visit_initial, check_initial, read_velocity_profile

   !> &initial as the input gives it (docs/input.md, "&initial").
   type :: initial_settings
      character(len=keyword_length) :: displacement = 'zero'
      integer :: displacement_mode = 1
      real(dp) :: displacement_amplitude = 0
      character(len=keyword_length) :: velocity = 'zero'
      integer :: velocity_mode = 1
      real(dp) :: velocity_amplitude = 0   !! m/s ('mode', 'uniform') or rad/s ('rotation')
      character(len=path_length) :: velocity_profile = ''   !! 'profile': file of (x, v) pairs
      character(len=path_length) :: from_file = ''   !! continue from this results file ('' = no)
      !> with &beam planes = 2: the directions of the initial velocity (`direction`) and of
      !! the initial displacement, degrees from y towards z (unset: 0, along y; listed only
      !! when given)
      real(dp) :: direction = unset, displacement_direction = unset
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
      call visitor%variable(keyword_row('initial', 'velocity', 'zero|mode|uniform|rotation|profile', keyword_length, &
                                        'initial velocity: zero, a natural mode, uniform, a rigid rotation about '// &
                                        'the left end, or a profile v(x) from a file'), initial%velocity)
      call visitor%variable(integer_row('initial', 'velocity_mode', 1, 100, &
                                        'which natural mode the initial velocity is'), initial%velocity_mode)
      call visitor%variable(real_row('initial', 'velocity_amplitude', 'm/s', -1e8_dp, 1e8_dp, &
                                     'tip velocity of the mode, the uniform velocity, or the angular velocity '// &
                                     '(rad/s) of the rotation'), initial%velocity_amplitude)
      call visitor%variable(text_row('initial', 'velocity_profile', path_length, &
                                     'profile: file of (x, v) pairs (m, m/s), linear in between'), &
                            initial%velocity_profile)
      call visitor%variable(text_row('initial', 'from_file', path_length, &
                                     'continue from the final state or last checkpoint of this results file'), &
                            initial%from_file)
      call visitor%variable(real_row('initial', 'direction', 'deg', -360.0_dp, 360.0_dp, &
                                     'with &beam planes = 2: direction of the initial velocity, from y towards z '// &
                                     '(default 0)', optional=.true.), initial%direction)
      call visitor%variable(real_row('initial', 'displacement_direction', 'deg', -360.0_dp, 360.0_dp, &
                                     'with &beam planes = 2: direction of the initial displacement, from y towards '// &
                                     'z (default 0)', optional=.true.), initial%displacement_direction)
   end subroutine visit_initial

   !> Unknowns of amplitude * (mode `mode`, 1 at the tip) on the mesh: the closed form of
   !! the uniform clamped-free beam, else the discrete mode (module documentation). NaN
   !! when that mode cannot be computed (the caller reports a field that is not finite).
   function mode_field(model, mode, amplitude) result(u)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: mode
      real(dp), intent(in) :: amplitude
      real(dp) :: u(model%unknowns)
      real(dp) :: value(model%elements + 1), slope(model%elements + 1)
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
      do i = 1, model%elements + 1
         value(i) = model%boundary%mode_shape(mode, model%x(i), model%length, 0)
         slope(i) = model%boundary%mode_shape(mode, model%x(i), model%length, 1)
      end do
      u = amplitude*interpolate_field(model, value, slope)
   end function mode_field

   !> The rules of &initial (docs/input.md, "&initial"): velocity = 'profile' needs its
   !! file. stat = stat_failure with a message naming the variable otherwise.
   subroutine check_initial(initial, stat, errmsg)
      type(initial_settings), intent(in) :: initial
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (initial%velocity == 'profile' .and. len_trim(initial%velocity_profile) == 0) then
         stat = stat_failure
         errmsg = '&initial velocity_profile is missing: velocity = ''profile'' needs the file of (x, v) pairs '// &
                  '(m, m/s) of the initial velocity'
      end if
   end subroutine check_initial

   !> The table of &initial velocity_profile on a beam of `length` (m): read, every x in
   !! [0, length]. stat = stat_invalid_input with a message naming the variable, the file and
   !! its line, or the x outside the beam and what is allowed.
   subroutine read_velocity_profile(initial, length, profile, stat, errmsg)
      type(initial_settings), intent(in) :: initial
      real(dp), intent(in) :: length
      type(linear_table), intent(out) :: profile
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: shown
      shown = '&initial velocity_profile = '''//trim(initial%velocity_profile)//''''
      call read_table(trim(initial%velocity_profile), profile, stat, errmsg)
      if (stat /= 0) then
         stat = stat_invalid_input
         errmsg = shown//': '//trim(errmsg)
         return
      end if
      if (len(outside_beam(profile, length)) > 0) then
         stat = stat_invalid_input
         errmsg = shown//outside_beam(profile, length)
         return
      end if
      profile%hold_ends = .true.   ! beyond its first and last x: their velocities
   end subroutine read_velocity_profile

   !> Initial velocity unknowns from `&initial velocity`; 'profile' needs its table
   !! (`read_velocity_profile`).
   function initial_velocity(initial, model, profile) result(v)
      type(initial_settings), intent(in) :: initial
      type(beam_model), intent(in) :: model
      type(linear_table), intent(in), optional :: profile
      real(dp) :: v(model%unknowns)
      real(dp) :: value(model%elements + 1), slope(model%elements + 1)
      integer :: i
      select case (initial%velocity)
      case ('mode')
         v = mode_field(model, initial%velocity_mode, initial%velocity_amplitude)
      case ('uniform')
         if (.not. model%hermite) then
            v = initial%velocity_amplitude   ! B-spline coefficients: bounded by them, no overshoot
         else
            ! a left end free to move moves too (only a held end ramps the velocity)
            v = interpolate_field(model, [(initial%velocity_amplitude, i=0, model%elements)], &
                                  [(0.0_dp, i=0, model%elements)])
         end if
      case ('rotation')   ! v = omega x, v_x = omega: exact in both bases where the left end allows it
         v = interpolate_field(model, initial%velocity_amplitude*model%x, &
                               [(initial%velocity_amplitude, i=0, model%elements)])
      case ('profile')
         v = ieee_value(1.0_dp, ieee_quiet_nan)   ! without its table (the caller reports a field not finite)
         if (.not. present(profile)) return
         do i = 1, model%elements + 1
            value(i) = profile%at(model%x(i))
            slope(i) = profile_slope(profile, model%x(i))
         end do
         v = interpolate_field(model, value, slope)
      case default
         v = 0
      end select
   end function initial_velocity

   !> The slope of a piecewise-linear table at x: its segment's; at one of its points the
   !! mean of the segments that meet there (one at its ends); 0 outside it (ends held).
   pure real(dp) function profile_slope(profile, x) result(slope)
      type(linear_table), intent(in) :: profile
      real(dp), intent(in) :: x
      integer :: k, meeting
      slope = 0
      meeting = 0
      do k = 1, size(profile%x) - 1
         if (x < profile%x(k) .or. x > profile%x(k + 1)) cycle
         slope = slope + (profile%y(k + 1) - profile%y(k))/(profile%x(k + 1) - profile%x(k))
         meeting = meeting + 1
      end do
      if (meeting > 0) slope = slope/meeting
   end function profile_slope
end module vibrobeam_initial_state
