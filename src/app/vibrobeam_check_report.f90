!> What `vibrobeam --check` tells about a valid scene before it is run, and the warnings
!! every run prints first (docs/input.md, "What --check prints" and "Warnings").
!!
!! - the first natural frequencies of the clamped-free beam: the continuum closed form
!!   (theory §7, `vibrobeam_cantilever_exact`), which ignores the obstacles;
!! - the highest frequency of the discrete model (`vibrobeam_highest_frequency`);
!! - omega dt for mode 1 and for the highest mode, steps per period of mode 1, and how many
!!   modes get at least `steps_per_period_wanted` steps per period;
!! - the penetration scale dt |v| of the velocity-based scheme (theory §3: a contact point
!!   is activated from its predicted position, so it may enter an obstacle by about one
!!   step of its approach velocity), with the velocity scale used and where it comes from;
!! - the estimated size of the results (`vibrobeam_output_target`);
!! - for each compliant stop, its contact time scale T_c = pi sqrt(m_eff/(k + k_b)) against
!!   dt (docs/theory.md section 8, "Resolution"): k_b = 3EI/x^3 is the beam's static
!!   stiffness at the stop's position x (a clamped-free beam loaded at x), k the stop's
!!   stiffness (a longitudinal one's total, at its middle), m_eff = k_b/omega_1^2 the mass
!!   that makes the beam at x a one-degree-of-freedom oscillator of mode 1's frequency.
!!
!! Warnings (not errors): a time step with fewer than `steps_per_period_wanted` steps per
!! period of mode 1, a compliant stop with fewer than `steps_per_contact_wanted` steps per
!! contact time scale, and physical data of implausible magnitude (a Young's modulus typed
!! in GPa or MPa, a density in g/cm^3, a section in mm^2 or cm^2, an inertia in mm^4 or
!! cm^4 beside an area in m^2).
module vibrobeam_check_report
   use vibrobeam_kinds, only: dp, pi, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type, is_unset, steps_in_time, forcing_period_steps
   use vibrobeam_model, only: beam_model
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_output_target, only: result_size, estimate_result_size
   use vibrobeam_resolution_advice, only: resolution_advice_text
   implicit none
   private
   public :: check_report, make_check_report, check_report_text, scene_warnings
   public :: steps_per_period_wanted, velocity_scale, steps_per_contact_wanted, contact_time_scale

   !> Fewer steps than this per period of mode 1: the time step does not resolve it (a
   !! theta = 1/2 scheme then errs by about (omega dt)^2/12 = 8e-3 in phase per period).
   real(dp), parameter :: steps_per_period_wanted = 20
   !> Fewer steps than this per contact time scale of a compliant stop: the contact is not
   !! resolved (studies/compliant_resolution/REPORT.md: the first episode's duration and
   !! impulse err by 30 % and 18 % at 10 steps, by 2.9 % and 1.2 % at 20, below 1 % at 40).
   real(dp), parameter :: steps_per_contact_wanted = 20
   !> Continuum frequencies listed.
   integer, parameter :: listed_modes = 5
   !> Plausible magnitudes (warnings below): steel is 2.1e11 Pa, rubber 1e6 Pa; water
   !! 1000 kg/m^3, osmium 22590, aerogels 10; a section of 1 m^2 is a bridge girder, one
   !! of 1e-12 m^2 a 1 um wire; I/S^2 is h/(12 b) for a b x h rectangle, r/(4 pi t) for a
   !! thin tube of radius r and wall t, 1 to 10 for rolled I-sections.
   real(dp), parameter :: youngs_modulus_least = 1e6_dp
   real(dp), parameter :: density_range(2) = [10.0_dp, 1e5_dp]
   real(dp), parameter :: area_range(2) = [1e-12_dp, 1.0_dp]
   real(dp), parameter :: inertia_ratio_range(2) = [1e-5_dp, 1e2_dp]

   !> The numbers --check prints.
   type :: check_report
      real(dp) :: omega(listed_modes) = 0     !! continuum natural frequencies (rad/s)
      integer :: unknowns = 0                 !! J
      real(dp) :: omega_max = 0               !! highest frequency of the discrete model (rad/s)
      logical :: stepped = .false.            !! kind = 'dynamics': the time-step numbers mean something
      real(dp) :: omega1_dt = 0, omega_max_dt = 0
      real(dp) :: steps_per_period = 0        !! of mode 1
      integer :: resolved_modes = 0           !! continuum modes with >= steps_per_period_wanted steps per period
      real(dp) :: velocity = 0                !! velocity scale |v| (m/s)
      character(len=:), allocatable :: velocity_source
      real(dp) :: penetration = 0             !! dt |v| (m)
      type(result_size) :: size
   end type check_report

contains

   !> The numbers of `check_report` for a validated scene and its model.
   subroutine make_check_report(scene, model, report, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      type(check_report), intent(out) :: report
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: n
      do n = 1, listed_modes
         report%omega(n) = scene%beam%boundary%natural_frequency(n, scene%beam%length, k2_of(scene))
      end do
      report%unknowns = model%unknowns
      call highest_frequency(model, report%omega_max, stat, errmsg)
      if (stat /= 0) return
      report%stepped = steps_in_time(scene)
      if (.not. report%stepped) return
      report%omega1_dt = report%omega(1)*scene%time%dt
      report%omega_max_dt = report%omega_max*scene%time%dt
      report%steps_per_period = 2*pi/report%omega1_dt
      report%resolved_modes = resolved_modes(scene)
      call velocity_scale(scene, report%velocity, report%velocity_source)
      report%penetration = scene%time%dt*report%velocity
      if (scene%analysis%kind == 'dynamics') report%size = estimate_result_size(scene)
   end subroutine make_check_report

   !> The report as lines of text (the program prints them). With `advice` (default true),
   !! a dynamics run with obstacles and a statistics window ends with the resolution advice
   !! for its statistics (`vibrobeam_resolution_advice`); a sweep prints its own.
   function check_report_text(scene, report, advice) result(text)
      type(scene_type), intent(in) :: scene
      type(check_report), intent(in) :: report
      logical, intent(in), optional :: advice
      character(len=:), allocatable :: text
      integer :: n
      real(dp) :: time_scale, beam_stiffness, mass
      logical :: with_advice
      text = 'natural frequencies of the '//scene%beam%boundary%name()//' beam (continuum closed form; the '// &
             'obstacles are ignored):'// &
             new_line('a')
      do n = 1, listed_modes
         text = text//'  mode '//integer_text(n)//': omega = '//g(report%omega(n))//' rad/s, f = '// &
                g(report%omega(n)/(2*pi))//' Hz'
         if (report%stepped) text = text//', omega*dt = '//g(report%omega(n)*scene%time%dt)//', '// &
                                    g(2*pi/(report%omega(n)*scene%time%dt))//' steps per period'
         text = text//new_line('a')
      end do
      text = text//'highest frequency of the discrete model ('//integer_text(report%unknowns)// &
             ' unknowns): omega_max = '//g(report%omega_max)//' rad/s'
      if (report%stepped) text = text//', omega_max*dt = '//g(report%omega_max_dt)
      text = text//new_line('a')
      if (.not. report%stepped) return
      text = text//'steps per period of mode 1: '//g(report%steps_per_period)//'; '// &
             resolved_text(report%resolved_modes, report%unknowns)//new_line('a')
      text = text//'penetration scale dt*|v| = '//g(report%penetration)//' m, with |v| = '//g(report%velocity)// &
             ' m/s: '//report%velocity_source//new_line('a')
      do n = 1, size(scene%obstacles)
         call contact_time_scale(scene, n, time_scale, beam_stiffness, mass)
         if (time_scale <= 0) cycle
         text = text//'compliant stop '//integer_text(n)//': beam stiffness there k_b = 3EI/x^3 = '// &
                g(beam_stiffness)//' N/m, effective mass k_b/omega_1^2 = '//g(mass)// &
                ' kg, contact time scale pi sqrt(m_eff/(k + k_b)) = '//g(time_scale)//' s = '// &
                g(time_scale/scene%time%dt)//' steps'
         if (time_scale/scene%time%dt < steps_per_contact_wanted) text = text//' (NOT resolved: fewer than '// &
                                                                   g(steps_per_contact_wanted)//')'
         text = text//new_line('a')
      end do
      if (scene%analysis%kind == 'periodic') then
         text = text//periodic_text(scene)
         return
      end if
      text = text//'estimated result size: '//g(report%size%total_bytes)//' bytes (HDF5 '// &
             g(report%size%hdf5_bytes)//', text '//g(report%size%text_bytes)//'): '//g(report%size%outputs)// &
             ' output times of '//g(report%size%values_per_output)//' values and '//g(report%size%snapshots)// &
             ' field snapshots of '//integer_text(scene%mesh%elements + 1)//' nodes; impacts not counted'//new_line('a')
      with_advice = .true.
      if (present(advice)) with_advice = advice
      if (with_advice .and. scene%output%measure_from < scene%time%t_end) text = text//resolution_advice_text(scene, 'this run')
   end function check_report_text

   !> What a periodic analysis steps (docs/method.md, "Periodic orbits by shooting"): the
   !! forcing period, its steps, the orbit's steps and how its monodromy is taken.
   function periodic_text(scene) result(text)
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable :: text
      integer(int64) :: steps
      steps = forcing_period_steps(scene)
      text = 'periodic orbit: forcing period T = '//g(steps*scene%time%dt)//' s = '//g(real(steps, dp))// &
             ' steps of dt = '//g(scene%time%dt)//' s; the orbit spans '// &
             integer_text(scene%periodic%period_multiple)//' period(s), '// &
             g(real(steps*scene%periodic%period_multiple, dp))//' steps, stepped once per Newton iteration with '// &
             'its monodromy ('''//trim(scene%periodic%monodromy)//'''), after a transient of '// &
             integer_text(scene%periodic%transient_periods)//' period(s)'//new_line('a')
   end function periodic_text

   !> Contact time scale of compliant obstacle i of the scene (s; module comment), with the
   !! beam's stiffness k_b at it (N/m) and the effective mass m_eff (kg; per unit rho S when
   !! the beam is given by k2). 0 for a rigid obstacle or one at the clamp.
   subroutine contact_time_scale(scene, i, time_scale, beam_stiffness, effective_mass)
      type(scene_type), intent(in) :: scene
      integer, intent(in) :: i
      real(dp), intent(out) :: time_scale, beam_stiffness, effective_mass
      real(dp) :: x, k, omega1
      time_scale = 0
      beam_stiffness = 0
      effective_mass = 0
      associate (o => scene%obstacles(i))
         if (o%stiffness <= 0) return
         x = 0.5_dp*(o%x_from + o%x_to)
         if (x <= 0) return
         k = o%stiffness
         if (o%x_to - o%x_from > 1e-9_dp*scene%beam%length/scene%mesh%elements) k = k*(o%x_to - o%x_from)
         ! ei() is k2 = EI/(rho S) when the beam is given by k2: then per unit rho S, like k
         beam_stiffness = 3*scene%beam%ei()/x**3
         omega1 = scene%beam%boundary%natural_frequency(1, scene%beam%length, k2_of(scene))
         effective_mass = beam_stiffness/omega1**2
         time_scale = pi*sqrt(effective_mass/(k + beam_stiffness))
      end associate
   end subroutine contact_time_scale

   !> Warnings for a valid scene, one line each (without the 'vibrobeam: warning: '
   !! prefix the program adds): an unresolved mode 1, implausible physical data.
   function scene_warnings(scene) result(text)
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable :: text
      real(dp) :: omega1, steps, ratio, time_scale, beam_stiffness, mass
      integer :: i
      text = ''
      if (steps_in_time(scene)) then
         omega1 = scene%beam%boundary%natural_frequency(1, scene%beam%length, k2_of(scene))
         steps = 2*pi/(omega1*scene%time%dt)
         if (steps < steps_per_period_wanted) &
            call add('&time dt = '//real_text(scene%time%dt)//' s gives '//g(steps)//' steps per period of mode 1 '// &
                     '(omega_1 = '//g(omega1)//' rad/s, continuum): fewer than '//g(steps_per_period_wanted)// &
                     ', so no natural mode is resolved; dt <= '//g(2*pi/(omega1*steps_per_period_wanted))// &
                     ' s resolves mode 1')
         do i = 1, size(scene%obstacles)
            call contact_time_scale(scene, i, time_scale, beam_stiffness, mass)
            if (time_scale <= 0) cycle
            if (time_scale/scene%time%dt < steps_per_contact_wanted) &
               call add('&obstacles stiffness('//integer_text(i)//') = '//real_text(scene%obstacles(i)%stiffness)// &
                        ': its contact time scale '//g(time_scale)//' s spans '//g(time_scale/scene%time%dt)// &
                        ' steps of dt, fewer than '//g(steps_per_contact_wanted)//', so the contact is not resolved; '// &
                        'dt <= '//g(time_scale/steps_per_contact_wanted)//' s resolves it')
         end do
      end if
      if (is_unset(scene%beam%youngs_modulus)) return
      if (scene%beam%youngs_modulus < youngs_modulus_least) &
         call add('&beam youngs_modulus = '//real_text(scene%beam%youngs_modulus)//' Pa is below '// &
                  g(youngs_modulus_least)//' Pa (rubber): given in GPa or MPa? (steel: 2.1e11 Pa)')
      if (scene%beam%density < density_range(1) .or. scene%beam%density > density_range(2)) &
         call add('&beam density = '//real_text(scene%beam%density)//' kg/m^3 is outside ['//g(density_range(1))// &
                  ', '//g(density_range(2))//'] kg/m^3: given in g/cm^3 or t/m^3? (steel: 7850 kg/m^3)')
      if (scene%beam%area < area_range(1) .or. scene%beam%area > area_range(2)) &
         call add('&beam area = '//real_text(scene%beam%area)//' m^2 is outside ['//g(area_range(1))//', '// &
                  g(area_range(2))//'] m^2: given in mm^2 or cm^2? (1 mm^2 = 1e-6 m^2)')
      ratio = scene%beam%inertia/scene%beam%area**2
      if (ratio < inertia_ratio_range(1) .or. ratio > inertia_ratio_range(2)) &
         call add('&beam inertia = '//real_text(scene%beam%inertia)//' m^4 does not fit area = '//real_text(scene%beam%area)// &
                  ' m^2: inertia/area^2 = '//g(ratio)//' is outside ['//g(inertia_ratio_range(1))//', '// &
                  g(inertia_ratio_range(2))//'] (a rectangle b x h has h/(12 b), a thin tube r/(4 pi t)): '// &
                  'inertia given in mm^4 or cm^4, or area in mm^2 or cm^2?')
   contains
      subroutine add(line)
         character(len=*), intent(in) :: line
         text = text//line//new_line('a')
      end subroutine add
   end function scene_warnings

   !> The velocity scale of a dynamics scene and where it comes from: the largest of the
   !! initial velocity, the velocity of a free oscillation of the initial mode shape
   !! (amplitude x omega_n), the base excitation (amplitude x frequency), and the velocity
   !! of a free oscillation in mode 1 whose amplitude is the static tip deflection under
   !! the loads' amplitudes (q L^4/(8 EI) for a uniform load, F a^2 (3L - a)/(6 EI) for a
   !! point force at a).
   subroutine velocity_scale(scene, velocity, source)
      type(scene_type), intent(in) :: scene
      real(dp), intent(out) :: velocity
      character(len=:), allocatable, intent(out) :: source
      real(dp) :: candidate, deflection, ei, length, a
      velocity = 0
      source = 'nothing moves (zero initial data, no loads): no penetration expected'
      if (scene%initial%velocity /= 'zero') call consider(abs(scene%initial%velocity_amplitude), 'the initial velocity '// &
                                                  '(&initial velocity_amplitude)')
      if (scene%initial%displacement == 'mode') &
         call consider(abs(scene%initial%displacement_amplitude)* &
                       scene%beam%boundary%natural_frequency(scene%initial%displacement_mode, scene%beam%length, &
                                                             k2_of(scene)), &
                       'a free oscillation of the initial displacement (displacement_amplitude x omega_'// &
                       integer_text(scene%initial%displacement_mode)//')')
      if (abs(scene%load%base_acceleration) > 0) then
         call consider(abs(scene%load%base_acceleration)/scene%load%base_frequency, &
                       'the base excitation (&load base_acceleration / base_frequency)')
      else
         call consider(abs(scene%load%base_amplitude)*scene%load%base_frequency, &
                       'the base excitation (&load base_amplitude x base_frequency)')
      end if
      ei = scene%beam%ei()   ! N m^2; k2 when the beam is given by k2 (loads are then per unit mass)
      length = scene%beam%length
      a = scene%load%point_position
      deflection = abs(scene%load%distributed)*length**4/(8*ei) + abs(scene%load%point_force)*a**2*(3*length - a)/(6*ei)
      call consider(deflection*scene%beam%boundary%natural_frequency(1, length, k2_of(scene)), &
                    'a free oscillation in mode 1 with the static tip deflection under the loads ('// &
                    g(deflection)//' m) as amplitude (a resonant load moves faster)')
   contains
      subroutine consider(value, what)
         real(dp), intent(in) :: value
         character(len=*), intent(in) :: what
         candidate = value
         if (candidate > velocity) then
            velocity = candidate
            source = what
         end if
      end subroutine consider
   end subroutine velocity_scale

   !> Continuum modes with at least steps_per_period_wanted steps per period, up to J.
   !! Beyond the listed modes, beta_n L = (2n - 1) pi/2 to within exp(-beta_n L) (the
   !! frequency equation 1 + cos b cosh b = 0), which gives the count in closed form
   !! without evaluating cosh of large arguments.
   integer function resolved_modes(scene)
      type(scene_type), intent(in) :: scene
      real(dp) :: omega_limit, count
      integer :: n
      omega_limit = 2*pi/(steps_per_period_wanted*scene%time%dt)
      resolved_modes = 0
      do n = 1, min(listed_modes, scene%mesh%unknowns())
         if (scene%beam%boundary%natural_frequency(n, scene%beam%length, k2_of(scene)) > omega_limit) return
         resolved_modes = n
      end do
      if (resolved_modes < listed_modes) return
      ! omega_n = ((2n - 1) pi/2)^2 sqrt(k2)/L^2 <= omega_limit
      count = ((2/pi)*sqrt(omega_limit*scene%beam%length**2/sqrt(k2_of(scene))) + 1)/2
      resolved_modes = int(min(real(scene%mesh%unknowns(), dp), max(real(listed_modes, dp), aint(count))))
   end function resolved_modes

   function resolved_text(modes, unknowns) result(text)
      integer, intent(in) :: modes, unknowns
      character(len=:), allocatable :: text
      if (modes == 0) then
         text = 'no mode has '//g(steps_per_period_wanted)//' steps per period'
      else if (modes == 1) then
         text = 'mode 1 has at least '//g(steps_per_period_wanted)//' steps per period'
      else if (modes >= unknowns) then
         text = 'all '//integer_text(unknowns)//' modes of the mesh have at least '//g(steps_per_period_wanted)// &
                ' steps per period (continuum frequencies)'
      else
         text = 'modes 1 to '//integer_text(modes)//' have at least '//g(steps_per_period_wanted)// &
                ' steps per period (continuum frequencies)'
      end if
   end function resolved_text

   !> k2 = EI/(rho S) (m^4/s^2).
   pure real(dp) function k2_of(scene)
      type(scene_type), intent(in) :: scene
      k2_of = scene%beam%ei()/scene%beam%rho_s()
   end function k2_of

   !> A number with 6 significant digits, without blanks: 210.347, 0.0213, 1.23457e7.
   function g(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      integer :: e, exponent, decimals
      if (abs(value) >= 1e-3_dp .and. abs(value) < 1e6_dp) then
         decimals = max(0, 5 - floor(log10(abs(value))))
         write (buffer, '(f0.'//integer_text(decimals)//')') value
         text = trim(adjustl(buffer))
         if (index(text, '.') > 0) then
            do while (text(len(text):) == '0')
               text = text(1:len(text) - 1)
            end do
            if (text(len(text):) == '.') text = text(1:len(text) - 1)
         end if
         if (text(1:1) == '.') text = '0'//text
         if (len(text) >= 2) then
            if (text(1:2) == '-.') text = '-0'//text(2:)
         end if
      else if (abs(value) > 0) then
         write (buffer, '(es16.5e3)') value
         e = index(buffer, 'E')
         read (buffer(e + 1:), *) exponent
         text = trim(adjustl(buffer(1:e - 1)))
         do while (text(len(text):) == '0')
            text = text(1:len(text) - 1)
         end do
         if (text(len(text):) == '.') text = text(1:len(text) - 1)
         text = text//'e'//integer_text(exponent)
      else
         text = '0'
      end if
   end function g
end module vibrobeam_check_report
