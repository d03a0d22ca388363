!> The numbers and warnings of `vibrobeam --check` (vibrobeam_check_report) against
!! closed forms computed here:
!! - omega_n = (beta_n L)^2 sqrt(EI/(rho S))/L^2 with the roots beta_n L of
!!   1 + cos b cosh b = 0 written here to 21 digits (mpmath findroot at 30 digits; the
!!   first 12 are those of Blevins, Formulas for natural frequency and mode shape, table
!!   8-1), to 16 eps (a handful of roundings in each evaluation);
!! - omega dt, steps per period 2 pi/(omega_1 dt), the number of modes with at least 20
!!   steps per period counted from roots found here by bisection of cos b cosh b + 1;
!! - the velocity scale and its source for each kind of excitation (initial velocity, a
!!   mode shape, base excitation, uniform load and point force through their static tip
!!   deflections q L^4/(8 EI), F a^2 (3L - a)/(6 EI)), and dt |v|;
!! - each warning appears for data typed in the wrong unit, and none for a plausible
!!   steel beam, a 1:100 flat strip, a thin tube (r/t = 100) or a resolved time step;
!! - a pinned-pinned stiff string under an axial force (issue 18, item 5: the steel
!!   section with I = 1e-12 m^4, T = 2e6 N, T L^2/EI = 2400): no closed form is claimed,
!!   and the five frequencies computed on 64 Hermite elements agree with omega_n^2 =
!!   (n pi/L)^4 EI/(rho S) + (n pi/L)^2 T/(rho S) to (n pi/64)^4/100 (the elements' error
!!   bound, test_support_modes.f90); the modes with 20 steps per period beyond the listed
!!   ones (dt = 1e-6 s) are counted from the tensioned roots b_n = beta_n L = n pi: the
!!   closed form's count, 44 (a count from k2 alone, as without tension, gives 102).
program test_check_report
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_scene, only: scene_type
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_check_report, only: check_report, make_check_report, scene_warnings, velocity_scale, &
      steps_per_period_wanted
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   ! beta_n L for n = 1..5
   real(dp), parameter :: roots(5) = [1.87510406871196116645_dp, 4.69409113297417457644_dp, &
                                      7.85475743823761256486_dp, 10.9955407348754669907_dp, &
                                      14.1371683910464705809_dp]
   real(dp), parameter :: length = 0.5_dp, youngs = 210e9_dp, density = 7850, area = 2e-4_dp, &
                          inertia = 1.6666666666666667e-9_dp
   type(scene_type) :: scene
   type(check_report) :: report
   real(dp) :: k2, omega(5), velocity, deflection
   character(len=:), allocatable :: source, warnings
   integer :: n, stat
   character(len=256) :: errmsg

   k2 = youngs*inertia/(density*area)
   omega = roots**2*sqrt(k2)/length**2
   scene = steel()
   scene%time%dt = 1e-5_dp
   call report_of(scene)
   do n = 1, 5
      call t%check_close('omega_n against the closed form', report%omega(n), omega(n), 16*epsilon(1.0_dp))
   end do
   call t%check_close('omega_1 dt', report%omega1_dt, omega(1)*scene%time%dt, 8*epsilon(1.0_dp))
   call t%check_close('steps per period of mode 1', report%steps_per_period, 2*pi/(omega(1)*scene%time%dt), &
                      8*epsilon(1.0_dp))
   call t%check_close('omega_max dt', report%omega_max_dt, report%omega_max*scene%time%dt, 8*epsilon(1.0_dp))
   call t%check_true('resolved modes, dt = 1e-5', report%resolved_modes == resolved_count(scene%time%dt), &
                     'counted '//text(real(resolved_count(scene%time%dt), dp)))
   scene%time%dt = 2*pi/(steps_per_period_wanted*omega(3))*(1 + 1e-9_dp)   ! mode 3 just misses 20 steps
   call report_of(scene)
   call t%check_true('resolved modes: 2 when mode 3 just misses', report%resolved_modes == 2)
   scene%time%dt = 1e-7_dp   ! beyond the listed modes: the asymptotic count (J = 128 > 73 modes)
   scene%mesh%elements = 64
   call report_of(scene)
   call t%check_true('resolved modes, dt = 1e-7', report%resolved_modes == resolved_count(scene%time%dt), &
                     'counted '//text(real(resolved_count(scene%time%dt), dp))//', reported '// &
                     text(real(report%resolved_modes, dp)))

   ! velocity scales and their sources
   scene = steel()
   scene%initial%velocity = 'uniform'
   scene%initial%velocity_amplitude = -0.3_dp
   call velocity_scale(scene, velocity, source)
   call t%check_close('velocity: initial velocity', velocity, 0.3_dp, 0.0_dp)
   call t%check_true('source: initial velocity', index(source, 'initial velocity') > 0, source)
   scene = steel()
   scene%initial%displacement = 'mode'
   scene%initial%displacement_mode = 2
   scene%initial%displacement_amplitude = 1e-3_dp
   call velocity_scale(scene, velocity, source)
   call t%check_close('velocity: mode 2 oscillation', velocity, 1e-3_dp*omega(2), 16*epsilon(1.0_dp))
   call t%check_true('source: initial displacement', index(source, 'omega_2') > 0, source)
   scene = steel()
   scene%load%base_amplitude = 2e-3_dp
   scene%load%base_frequency = 150
   call velocity_scale(scene, velocity, source)
   call t%check_close('velocity: base excitation', velocity, 0.3_dp, 4*epsilon(1.0_dp))
   call t%check_true('source: base excitation', index(source, 'base excitation') > 0, source)
   scene = steel()
   scene%load%distributed = -100
   call velocity_scale(scene, velocity, source)
   deflection = 100*length**4/(8*youngs*inertia)
   call t%check_close('velocity: uniform load', velocity, deflection*omega(1), 8*epsilon(1.0_dp))
   call t%check_true('source: static deflection', index(source, 'static tip deflection') > 0, source)
   scene = steel()
   scene%load%point_force = 20
   scene%load%point_position = 0.3_dp
   call velocity_scale(scene, velocity, source)
   deflection = 20*0.3_dp**2*(3*length - 0.3_dp)/(6*youngs*inertia)
   call t%check_close('velocity: point force', velocity, deflection*omega(1), 8*epsilon(1.0_dp))
   scene = steel()
   call velocity_scale(scene, velocity, source)
   call t%check_close('velocity: nothing moves', velocity, 0.0_dp, 0.0_dp, 1.0_dp)
   scene = steel()
   scene%initial%velocity = 'mode'
   scene%initial%velocity_amplitude = 0.5_dp
   scene%load%base_amplitude = 1e-3_dp
   scene%load%base_frequency = 100   ! 0.1 m/s: the initial velocity is the larger
   scene%time%dt = 2e-5_dp
   call report_of(scene)
   call t%check_close('penetration scale dt |v|', report%penetration, 2e-5_dp*0.5_dp, 4*epsilon(1.0_dp))

   ! warnings on the data (static scenes: no time step to warn about)
   call expect_warning('plausible steel beam', steel(), '')
   scene = steel()
   scene%beam%youngs_modulus = 210
   call expect_warning('E typed in GPa', scene, 'youngs_modulus')
   scene = steel()
   scene%beam%density = 7.85_dp
   call expect_warning('density typed in g/cm^3', scene, 'density')
   scene = steel()
   scene%beam%area = 200
   scene%beam%inertia = 200**2/12.0_dp
   call expect_warning('area typed in mm^2', scene, 'area')
   scene = steel()
   scene%beam%inertia = inertia*1e12_dp
   call expect_warning('inertia typed in mm^4', scene, 'inertia')
   scene = steel()
   scene%beam%area = 1e-3_dp*0.1_dp                       ! a 100 mm x 1 mm strip, bent flatwise
   scene%beam%inertia = 0.1_dp*1e-3_dp**3/12
   call expect_warning('1:100 strip', scene, '')
   scene = steel()
   scene%beam%area = 2*pi*0.05_dp*0.5e-3_dp               ! a tube r = 50 mm, t = 0.5 mm
   scene%beam%inertia = pi*0.05_dp**3*0.5e-3_dp
   call expect_warning('thin tube r/t = 100', scene, '')
   scene = steel()
   scene%time%dt = 2*pi/(omega(1)*10)                     ! 10 steps per period of mode 1
   call expect_warning('10 steps per period', scene, 'steps per period of mode 1')
   scene%time%dt = 2*pi/(omega(1)*25)
   call expect_warning('25 steps per period', scene, '')

   ! an axial force: frequencies computed, the resolved count from the tensioned roots
   call tensioned_beam()
   call t%finish('test_check_report')

contains

   !> The steel cantilever of the README (valid as it stands).
   function steel() result(scene)
      type(scene_type) :: scene
      allocate (scene%obstacles(0), scene%output%points(0))
      scene%beam%length = length
      scene%beam%youngs_modulus = youngs
      scene%beam%density = density
      scene%beam%area = area
      scene%beam%inertia = inertia
      scene%mesh%elements = 8
      scene%load%point_position = length
      scene%time%t_end = 0.1_dp
      scene%time%dt = 1e-5_dp
      scene%output%file = 'unused.h5'
   end function steel

   subroutine report_of(scene)
      type(scene_type), intent(in) :: scene
      type(beam_model) :: model
      call validate_scene(scene, stat, errmsg)
      call t%check_true('scene valid', stat == 0, trim(errmsg))
      call build_model(scene%mesh%basis, scene%mesh%elements, scene%beam%length, scene%beam%density*scene%beam%area, &
                       scene%beam%youngs_modulus*scene%beam%inertia, model, stat, errmsg)
      call make_check_report(scene, model, report, stat, errmsg)
      call t%check_true('report made', stat == 0, trim(errmsg))
   end subroutine report_of

   !> The stiff string pinned at both ends (module documentation).
   subroutine tensioned_beam()
      real(dp), parameter :: tension = 2e6_dp, step = 1e-6_dp, thin = 1e-12_dp
      real(dp) :: exact(5), limit, wave
      integer :: count
      scene = steel()
      scene%beam%inertia = thin
      scene%beam%left_end = 'pinned'
      scene%beam%right_end = 'pinned'
      scene%beam%axial_force = tension
      scene%mesh%elements = 64
      scene%time%dt = step
      call report_of(scene)
      call t%check_true('tensioned beam: no closed form claimed', .not. report%closed_form)
      do n = 1, 5
         wave = n*pi/length
         exact(n) = sqrt((wave**4*youngs*thin + wave**2*tension)/(density*area))
         call t%check_close('tensioned beam: omega_'//achar(48 + n)//' (64 Hermite elements)', report%omega(n), &
                            exact(n), (n*pi/64)**4/100)
      end do
      limit = 2*pi/(steps_per_period_wanted*step)
      count = 0
      do
         wave = (count + 1)*pi/length
         if (sqrt((wave**4*youngs*thin + wave**2*tension)/(density*area)) > limit) exit
         count = count + 1
      end do
      call t%check_true('tensioned beam: resolved modes, dt = 1e-6 s', report%resolved_modes == count, &
                        'counted '//text(real(count, dp))//', reported '//text(real(report%resolved_modes, dp)))
   end subroutine tensioned_beam

   !> The warnings of `scene` name `expected` (one warning), or are empty ('').
   subroutine expect_warning(name, given, expected)
      character(len=*), intent(in) :: name, expected
      type(scene_type), intent(in) :: given
      type(scene_type) :: scene
      scene = given
      if (index(name, 'steps per period') == 0) scene%analysis%kind = 'static'
      call validate_scene(scene, stat, errmsg)
      call t%check_true(name//': scene valid', stat == 0, trim(errmsg))
      warnings = scene_warnings(scene)
      if (len(expected) == 0) then
         call t%check_true(name//': no warning', len(warnings) == 0, warnings)
      else
         call t%check_true(name//': one warning naming '//expected, index(warnings, expected) > 0 .and. &
                           count_lines(warnings) == 1, warnings)
      end if
   end subroutine expect_warning

   integer function count_lines(text)
      character(len=*), intent(in) :: text
      integer :: i
      count_lines = 0
      do i = 1, len(text)
         if (text(i:i) == new_line('a')) count_lines = count_lines + 1
      end do
   end function count_lines

   !> Modes with at least 20 steps per period, from roots found by bisection here.
   integer function resolved_count(step)
      real(dp), intent(in) :: step
      real(dp) :: root
      resolved_count = 0
      do
         root = bisected_root(resolved_count + 1)
         if (2*pi/(root**2*sqrt(k2)/length**2*step) < steps_per_period_wanted) exit
         resolved_count = resolved_count + 1
      end do
   end function resolved_count

   !> n-th root of cos(b) cosh(b) + 1 = 0, in ((n - 1) pi, n pi) by bisection of
   !! cos(b) + 1/cosh(b) (same sign change, no overflow).
   real(dp) function bisected_root(n)
      integer, intent(in) :: n
      real(dp) :: low, high, middle
      integer :: i
      low = (n - 1)*pi + 1e-9_dp
      high = n*pi - 1e-9_dp
      do i = 1, 200
         middle = (low + high)/2
         if ((cos(middle) + 1/cosh(middle) > 0) .eqv. (cos(low) + 1/cosh(low) > 0)) then
            low = middle
         else
            high = middle
         end if
      end do
      bisected_root = (low + high)/2
   end function bisected_root

   function text(value) result(string)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: string
      character(len=32) :: buffer
      write (buffer, '(g0)') value
      string = trim(buffer)
   end function text
end program test_check_report
