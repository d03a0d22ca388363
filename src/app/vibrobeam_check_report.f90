!> What `vibrobeam --check` tells about a valid scene before it is run, and the warnings
!! every run prints first (docs/input.md, "What --check prints" and "Warnings").
!!
!! - the first natural frequencies of the beam on its supports: the continuum closed form
!!   (theory §7) or computed (`scene_frequencies`), which ignore the obstacles; the first
!!   flexible mode stands for "mode 1" below when rigid-body motions come first;
!! - the highest frequency of the discrete model (`vibrobeam_highest_frequency`);
!! - omega dt for mode 1 and for the highest mode, steps per period of mode 1, and how many
!!   modes get at least `steps_per_period_wanted` steps per period;
!! - the penetration scale dt |v| of the velocity-based scheme (theory §3: a contact point
!!   is activated from its predicted position, so it may enter an obstacle by about one
!!   step of its approach velocity), with the velocity scale used and where it comes from;
!! - the estimated size of the results (`vibrobeam_result_estimate`; a sweep prints its
!!   own, `vibrobeam_sweep_check`);
!! - for each compliant stop, its contact time scale T_c = pi sqrt(m_eff/(k + k_b)) against
!!   dt (docs/theory.md section 8, "Resolution"): k_b = 3EI/x^3 is the beam's static
!!   stiffness at the stop's position x (a clamped-free beam loaded at x; with a tension
!!   T, plus a string's T L/(x (L - x))), k the stop's
!!   stiffness (a longitudinal one's total, at its middle), m_eff = k_b/omega_1^2 the mass
!!   that makes the beam at x a one-degree-of-freedom oscillator of mode 1's frequency.
!!
!! Warnings (not errors): a time step with fewer than `steps_per_period_wanted` steps per
!! period of mode 1, a compliant stop with fewer than `steps_per_contact_wanted` steps per
!! contact time scale, and physical data of implausible magnitude (a Young's modulus typed
!! in GPa or MPa, a density in g/cm^3, a section in mm^2 or cm^2, an inertia in mm^4 or
!! cm^4 beside an area in m^2).
module vibrobeam_check_report
   !$ use omp_lib, only: omp_get_max_threads
   use vibrobeam_kinds, only: dp, pi, int64
   use vibrobeam_text, only: real_text, integer_text, g => short_text
   use vibrobeam_scene, only: scene_type, is_unset, held_conditions, steps_in_time, forcing_period_steps
   use vibrobeam_scene_structure, only: scene_frequencies
   use vibrobeam_model, only: beam_model
   use vibrobeam_initial_state, only: read_velocity_profile
   use vibrobeam_table_file, only: linear_table
   use vibrobeam_boundary, only: boundary_conditions
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_result_estimate, only: result_size, estimate_result_size
   use vibrobeam_continuation_axis, only: branch_points
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
      real(dp) :: omega(listed_modes) = 0     !! natural frequencies (rad/s), `scene_frequencies`
      integer :: first = 1                    !! the first flexible mode (omega > 0) among them; 0: none
      logical :: closed_form = .true.         !! omega is the continuum's closed form (else computed)
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

   !> The numbers of `check_report` for a validated scene and its model; `contact_points`
   !! (when known) sizes the compliant stops' force in the result size.
   subroutine make_check_report(scene, model, report, stat, errmsg, contact_points)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      type(check_report), intent(out) :: report
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: contact_points
      call scene_frequencies(scene, report%omega, report%first, report%closed_form)
      report%unknowns = model%unknowns
      call highest_frequency(model, report%omega_max, stat, errmsg)
      if (stat /= 0) return
      report%size = estimate_result_size(scene, contact_points)
      report%stepped = steps_in_time(scene)
      if (.not. report%stepped) return
      if (report%first > 0) report%omega1_dt = report%omega(report%first)*scene%time%dt
      report%omega_max_dt = report%omega_max*scene%time%dt
      if (report%first > 0) report%steps_per_period = 2*pi/report%omega1_dt
      report%resolved_modes = resolved_modes(scene, report)
      call velocity_scale(scene, report%velocity, report%velocity_source)
      report%penetration = scene%time%dt*report%velocity
   end subroutine make_check_report

   !> The report as lines of text (the program prints them). A dynamics run ends with its
   !! estimated result size and, with obstacles and a statistics window, the resolution
   !! advice for its statistics (`vibrobeam_resolution_advice`); with `sweep` (default
   !! false) neither: a sweep prints its own (`vibrobeam_sweep_check`).
   function check_report_text(scene, report, sweep) result(text)
      type(scene_type), intent(in) :: scene
      type(check_report), intent(in) :: report
      logical, intent(in), optional :: sweep
      character(len=:), allocatable :: text
      integer :: n
      real(dp) :: time_scale, beam_stiffness, mass
      logical :: single_run
      type(boundary_conditions) :: supports
      character(len=:), allocatable :: what
      supports = scene%beam%supports()
      what = 'the '//supports%name()//' beam'
      if (allocated(scene%supports)) then
         if (size(scene%supports) > 0) what = what//' on '//integer_text(size(scene%supports))//' intermediate support'// &
                                              trim(merge('s', ' ', size(scene%supports) > 1))
      end if
      if (allocated(scene%masses)) then
         if (size(scene%masses) > 0) what = what//' with '//integer_text(size(scene%masses))//' point mass'// &
                                            trim(merge('es', '  ', size(scene%masses) > 1))
      end if
      if (scene%beam%sectioned()) what = what//' of '//integer_text(size(scene%beam%sections))//' sections'
      if (abs(scene%beam%tension()) > 0) what = what//' under the axial force T = '//g(scene%beam%tension())//' N'
      if (report%closed_form) then
         text = 'natural frequencies of '//what//' (continuum closed form; the obstacles are ignored):'//new_line('a')
      else
         text = 'natural frequencies of '//what//' (computed with 64 Hermite elements; the obstacles are ignored):'// &
                new_line('a')
      end if
      do n = 1, listed_modes
         if (.not. report%omega(n) > 0) then
            text = text//'  mode '//integer_text(n)//': omega = 0, a rigid-body motion'//new_line('a')
            cycle
         end if
         text = text//'  mode '//integer_text(n)//': omega = '//g(report%omega(n))//' rad/s, f = '// &
                g(report%omega(n)/(2*pi))//' Hz'
         if (report%stepped) text = text//', omega*dt = '//g(report%omega(n)*scene%time%dt)//', '// &
                                    g(2*pi/(report%omega(n)*scene%time%dt))//' steps per period'
         text = text//new_line('a')
      end do
      text = text//'highest frequency of the discrete model ('//integer_text(report%unknowns)// &
             ' unknowns): omega_max = '//g(report%omega_max)//' rad/s, f_max = '//g(report%omega_max/(2*pi))//' Hz'
      if (report%stepped) text = text//', omega_max*dt = '//g(report%omega_max_dt)
      text = text//new_line('a')
      single_run = .true.
      if (present(sweep)) single_run = .not. sweep
      if (.not. report%stepped) then
         text = text//size_line()
         return
      end if
      if (report%first > 0) text = text//'steps per period of mode '//integer_text(report%first)//': '// &
                                   g(report%steps_per_period)//'; '// &
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
         if (single_run) text = text//size_line()
         return
      end if
      if (.not. single_run) return
      text = text//size_line()
      if (scene%output%measure_from < scene%time%t_end) text = text//resolution_advice_text(scene, 'this run')
   contains
      !> 'estimated result size: ...' of a single run (docs/input.md, "What --check prints").
      function size_line() result(line)
         character(len=:), allocatable :: line
         line = 'estimated result size: '//g(report%size%total_bytes)//' bytes (HDF5 '//g(report%size%hdf5_bytes)// &
                ', text '//g(report%size%text_bytes)//')'
         if (scene%analysis%kind == 'periodic') then
            if (len_trim(scene%periodic%parameter) > 0) then
               line = line//': a branch of at most '//integer_text(branch_points(scene))//' points'
               if (scene%periodic%switch_branch) line = line//' (the switched branch''s points on top, not counted)'
            else
               line = line//': one orbit and its multipliers'
            end if
         end if
         if (scene%analysis%kind == 'dynamics') &
            line = line//': '//real_text(report%size%steps)//' steps, '//g(report%size%outputs)//' output times of '// &
                   g(report%size%values_per_output)//' values and '//g(report%size%snapshots)// &
                   ' field snapshots of '//integer_text(scene%mesh%elements + 1)// &
                   ' nodes, spectra, checkpoint; up to 4096 impacts and episodes'
         line = line//new_line('a')
      end function size_line
   end function check_report_text

   !> What a periodic analysis steps (docs/method.md, "Periodic orbits by shooting"): the
   !! forcing period, its steps, the orbit's steps and how its monodromy is taken; of an
   !! autonomous orbit the period's guess, its steps and the phase and amplitude conditions.
   function periodic_text(scene) result(text)
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable :: text
      integer(int64) :: steps
      integer :: threads
      threads = 1
      !$ threads = omp_get_max_threads()
      steps = forcing_period_steps(scene)
      if (scene%periodic%autonomous) then
         text = 'autonomous periodic orbit (free vibration, the period an unknown; docs/method.md, "Autonomous '// &
                'periodic orbits"): the guess T = '//g(scene%periodic%period)//' s in '//g(real(steps, dp))// &
                ' steps of dt = T/'//g(real(steps, dp))//' = '//g(scene%time%dt)//' s at the guess (dt moves with '// &
                'T); each Gauss-Newton iteration steps the orbit with its monodromy ('''// &
                trim(scene%periodic%monodromy)//''') and once more for dPhi/dT, after a transient of '// &
                integer_text(scene%periodic%transient_periods)//' period(s); the orbit starts where the tip''s '// &
                'velocity is 0, its tip displacement '
         if (is_unset(scene%periodic%tip_amplitude)) then
            text = text//'the start''s own'//new_line('a')
         else
            text = text//g(scene%periodic%tip_amplitude)//' m'//new_line('a')
         end if
         if (len_trim(scene%periodic%parameter) > 0) &
            text = text//'backbone (docs/method.md, "The backbone"): the orbit continued in its tip amplitude, '// &
                   'first step '//g(scene%periodic%step)//' m, at most '//integer_text(branch_points(scene))// &
                   ' points; each point Gauss-Newton at its amplitude from the secant through the last two'// &
                   new_line('a')
         return
      end if
      text = 'periodic orbit: forcing period T = '//g(steps*scene%time%dt)//' s = '//g(real(steps, dp))// &
             ' steps of dt = '//g(scene%time%dt)//' s; the orbit spans '// &
             integer_text(scene%periodic%period_multiple)//' period(s), '// &
             g(real(steps*scene%periodic%period_multiple, dp))//' steps, stepped once per Newton iteration with '// &
             'its monodromy ('''//trim(scene%periodic%monodromy)//'''), after a transient of '// &
             integer_text(scene%periodic%transient_periods)//' period(s)'//new_line('a')
      if (len_trim(scene%periodic%parameter) > 0) &
         text = text//'continuation in '//trim(scene%periodic%parameter)//': first step '// &
                g(scene%periodic%step)//', at most '//integer_text(scene%periodic%max_points)// &
                ' points; each corrector iteration steps the orbit with its monodromy and once more for '// &
                'dPhi/dlambda, at '//g(real(steps, dp))//' steps per forcing period at every value'//new_line('a')
      if (scene%periodic%monodromy /= 'linearised') &
         text = text//'a monodromy by differences (''differences'', or ''auto'' with compliant stops) runs its '// &
                'columns on '//integer_text(threads)//' thread(s) (OMP_NUM_THREADS), the same result on any number'// &
                new_line('a')
   end function periodic_text

   !> Contact time scale of compliant obstacle i of the scene (s; module comment), with the
   !! beam's stiffness k_b at it (N/m) and the effective mass m_eff (kg; per unit rho S when
   !! the beam is given by k2). 0 for a rigid obstacle or one at the clamp.
   subroutine contact_time_scale(scene, i, time_scale, beam_stiffness, effective_mass)
      type(scene_type), intent(in) :: scene
      integer, intent(in) :: i
      real(dp), intent(out) :: time_scale, beam_stiffness, effective_mass
      real(dp) :: x, k, omega1, omega(listed_modes)
      integer :: first
      time_scale = 0
      beam_stiffness = 0
      effective_mass = 0
      associate (o => scene%obstacles(i))
         if (o%stiffness <= 0) return
         x = 0.5_dp*(o%x_from + o%x_to)
         if (x <= 0) return
         k = o%stiffness
         if (o%x_to - o%x_from > 1e-9_dp*scene%beam%length/scene%mesh%elements) k = k*(o%x_to - o%x_from)
         ! ei() is k2 = EI/(rho S) when the beam is given by k2: then per unit rho S, like k;
         ! a tension adds a string's stiffness T L/(x (L - x)) between held ends
         beam_stiffness = 3*scene%beam%ei()/x**3
         if (scene%beam%tension() > 0 .and. x < scene%beam%length) beam_stiffness = beam_stiffness + &
            scene%beam%tension()*scene%beam%length/(x*(scene%beam%length - x))
         call scene_frequencies(scene, omega, first)
         if (first == 0) return
         omega1 = omega(first)
         effective_mass = beam_stiffness/omega1**2
         time_scale = pi*sqrt(effective_mass/(k + beam_stiffness))
      end associate
   end subroutine contact_time_scale

   !> Warnings for a valid scene, one line each (without the 'vibrobeam: warning: '
   !! prefix the program adds): an unresolved mode 1, implausible physical data.
   function scene_warnings(scene) result(text)
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable :: text
      real(dp) :: omega1, steps, ratio, time_scale, beam_stiffness, mass, omega(listed_modes)
      integer :: i, first
      text = ''
      if (steps_in_time(scene)) then
         call scene_frequencies(scene, omega, first)
         if (first > 0) then
            omega1 = omega(first)
            steps = 2*pi/(omega1*scene%time%dt)
            if (steps < steps_per_period_wanted) &
               call add('&time dt = '//real_text(scene%time%dt)//' s gives '//g(steps)//' steps per period of mode '// &
                        integer_text(first)//' (omega_'//integer_text(first)//' = '//g(omega1)// &
                        ' rad/s, continuum): fewer than '//g(steps_per_period_wanted)// &
                        ', so no natural mode is resolved; dt <= '//g(2*pi/(omega1*steps_per_period_wanted))// &
                        ' s resolves mode '//integer_text(first))
         end if
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
      real(dp) :: candidate, deflection, ei, length, a, omega(100)
      integer :: first, stat
      type(linear_table) :: profile
      character(len=256) :: errmsg
      velocity = 0
      source = 'nothing moves (zero initial data, no loads): no penetration expected'
      select case (scene%initial%velocity)
      case ('mode', 'uniform')
         call consider(abs(scene%initial%velocity_amplitude), 'the initial velocity (&initial velocity_amplitude)')
      case ('rotation')
         call consider(abs(scene%initial%velocity_amplitude)*scene%beam%length, 'the initial velocity at x = L '// &
                       '(&initial velocity_amplitude x length)')
      case ('profile')
         call read_velocity_profile(scene%initial, scene%beam%length, profile, stat, errmsg)
         if (stat == 0) call consider(maxval(abs(profile%y)), 'the initial velocity (largest of &initial '// &
                                      'velocity_profile)')
      end select
      call scene_frequencies(scene, omega(1:max(listed_modes, scene%initial%displacement_mode)), first)
      if (scene%initial%displacement == 'mode') &
         call consider(abs(scene%initial%displacement_amplitude)*omega(scene%initial%displacement_mode), &
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
      ! a tension T stiffens it like a string in parallel: q L^2/(8 T) at midspan, F a (L - a)/(T L) under F
      if (scene%beam%tension() > 0 .and. deflection > 0) &
         deflection = 1/(1/deflection + 1/((abs(scene%load%distributed)*length**2/8 + &
                                            abs(scene%load%point_force)*max(a*(length - a)/length, length/4))/ &
                                           scene%beam%tension()))
      if (first > 0) call consider(deflection*omega(first), &
                    'a free oscillation in mode '//integer_text(first)//' with the static tip deflection under the loads ('// &
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

   !> Modes with at least steps_per_period_wanted steps per period, up to J (the rigid-body
   !! motions count as resolved). Beyond the listed modes the roots b_n = L (omega_n^2/k2)^(1/4)
   !! of every pair of end supports are spaced by pi to within exp(-b_n) (theory §7; for
   !! the clamped-free beam b_n = (2n - 1) pi/2), which gives the count without evaluating
   !! cosh of large arguments; for other structures the spacing is the continuum's
   !! asymptote, so the count is an estimate (with an axial force, b_n = beta_n L of
   !! `wave_root`, the pinned-pinned beam's n pi).
   integer function resolved_modes(scene, report)
      type(scene_type), intent(in) :: scene
      type(check_report), intent(in) :: report
      real(dp) :: omega_limit, count, b_limit, b_last
      integer :: n, unknowns
      type(boundary_conditions) :: supports
      supports = scene%beam%supports()
      omega_limit = 2*pi/(steps_per_period_wanted*scene%time%dt)
      unknowns = scene%mesh%unknowns(held_conditions(scene))
      resolved_modes = 0
      do n = 1, min(listed_modes, unknowns)
         if (report%omega(n) > omega_limit) return
         resolved_modes = n
      end do
      if (resolved_modes < listed_modes) return
      b_limit = wave_root(scene, omega_limit)
      if (supports%is_clamped_free() .and. report%closed_form) then
         ! omega_n = ((2n - 1) pi/2)^2 sqrt(k2)/L^2 <= omega_limit
         count = ((2/pi)*b_limit + 1)/2
      else
         b_last = wave_root(scene, report%omega(listed_modes))
         count = listed_modes + (b_limit - b_last)/pi
      end if
      resolved_modes = int(min(real(unknowns, dp), max(real(listed_modes, dp), aint(count))))
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

   !> b = beta L of a frequency omega (rad/s) on the scene's beam, beta the root of
   !! k2 beta^4 + (T/rho S) beta^2 = omega^2 (theory §1, "Axial force"; b = sqrt(omega L^2/
   !! sqrt(k2)) without tension), beta^2 in the form 2 omega^2/(c^2 + sqrt(c^4 + 4 k2
   !! omega^2)), c^2 = T/rho S, which loses no digits as k2 -> 0 (a string).
   pure real(dp) function wave_root(scene, omega)
      type(scene_type), intent(in) :: scene
      real(dp), intent(in) :: omega
      real(dp) :: k2, c2
      k2 = scene%beam%ei()/scene%beam%rho_s()
      c2 = scene%beam%tension()/scene%beam%rho_s()
      if (abs(c2) > 0) then
         wave_root = sqrt(2*omega**2/(c2 + sqrt(c2**2 + 4*k2*omega**2)))*scene%beam%length
      else
         wave_root = sqrt(omega*scene%beam%length**2/sqrt(k2))
      end if
   end function wave_root
end module vibrobeam_check_report
