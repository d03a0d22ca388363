!> Work-precision study (issue 4): error against CPU time for every combination of
!! {Hermite, B-spline} x {velocity (theory §3), position (theory §4)} x {theta = 1/2, 1}
!! over a sweep of N and dt, on two scenes (studies/work_precision/REPORT.md):
!!
!! - `free`: free vibration of the normalized cantilever (k2 = 1, L = 1, no obstacle)
!!   released with a mode-1 velocity (tip 1) and a mode-2 displacement (tip 0.05), over
!!   t in [0, 8] (4.5 periods of mode 1). Error: max over the sample times t_k = k/32 of
!!   |u_h(L, t_k) - u(L, t_k)| / max_k |u(L, t_k)|, u the closed form of theory §7,
!!   u(L, t) = v1 sin(omega_1 t)/omega_1 + a2 cos(omega_2 t) (mode shapes of tip value 1).
!! - `impacts`: inputs/looseness_tip_stops.nml over t in [0, 10 ms] (two contact episodes).
!!   Error: max over the sample times t_k = k 20 us of |u_h(L, t_k) - u_ref(L, t_k)| /
!!   max_k |u_ref(L, t_k)|, u_ref a fine run (Hermite, velocity, theta = 1/2, N = 1024,
!!   dt = 2e-5/1024 s). Its convergence is checked against coarser runs of the same
!!   family (N = 512, 256, 128 with dt N fixed) and against fine runs of every other
!!   combination (N = 512, and N = 1024 for two of them).
!!
!! Cost: CPU time (`cpu_time`) of the stepping loop only (set-up and the factorization
!! of the iteration matrix are excluded), median of 3 repetitions when a run takes less
!! than 0.1 s; a run shorter than 10 ms is repeated in batches of at least 10 ms so that
!! the clock's granularity and call overheads do not dominate. Wall time (`system_clock`)
!! is read around the same loops: CPU/wall well below 1 means the process waited for a
!! processor (the machine is shared).
!!
!! usage: work_precision free    SCENE.nml OUTPUT_DIR [--check]   (verification/dynamics/free_flight.nml)
!!        work_precision impacts SCENE.nml OUTPUT_DIR [--check]   (inputs/looseness_tip_stops.nml)
!! Every field of the free scene that the study relies on is set in code; the file only
!! supplies the defaults. Writes OUTPUT_DIR/work_precision_{free,impacts}.{txt,dat}.
!!
!! `--check` (the ctest entries, label `long`) exits non-zero when a property that
!! REPORT.md relies on fails: (a) at N = 64 the Hermite velocity theta = 1/2 error falls at
!! order 2 in dt (fitted between dt = 2^-7 and 2^-10, in [1.8, 2.2]), velocity theta = 1 at
!! order 1 (2^-12..2^-16, [0.8, 1.2]) and position theta = 1 at order 2 (2^-8..2^-11,
!! [1.8, 2.2]); velocity theta = 1/2 keeps the energy to 1e-9; every theta = 1/2
!! combination reaches 1e-5. (b) the reference differs from its next-coarser level by
!! less than 1 % of the tip amplitude.
program work_precision
   use vibrobeam_kinds, only: dp, int64, output_unit, error_unit
   use vibrobeam_scene, only: scene_type, unset
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_test_support, only: read_test_scene
   use vibrobeam_problem, only: run_problem, build_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_model, only: point_row
   use vibrobeam_cantilever_exact, only: cantilever_frequency, cantilever_mode_shape
   implicit none

   !> One discretization family: basis, time scheme and theta.
   type :: combination
      character(len=16) :: basis = 'hermite'    !! 'hermite' | 'bspline'
      character(len=16) :: scheme = 'velocity'  !! 'velocity' | 'position'
      real(dp) :: theta = 0.5_dp
   end type combination

   !> What one run produced: the tip at the sample times and its diagnostics.
   type :: run_output
      real(dp), allocatable :: tip(:)        !! u_h(L, t_k), k = 1..samples (m)
      real(dp) :: initial_energy = 0         !! E right after the start (J; per unit mass with k2)
      real(dp) :: final_energy = 0           !! E at t_end (J)
      integer :: impacts = 0                 !! impacts as the recorder counts them
      integer :: impulse_steps = 0           !! steps with a non-zero impulse
      integer :: bounces = 0                 !! bursts of impulses separated by > bounce_gap
      integer :: episodes = 0                !! bursts separated by > episode_gap
      real(dp) :: cpu_seconds = 0            !! stepping loop, CPU time (s)
      real(dp) :: wall_seconds = 0           !! stepping loop, wall time (s)
      integer :: repetitions = 1             !! runs behind the median
   end type run_output

   !> One row of a study table.
   type :: run_row
      type(combination) :: family
      integer :: elements = 0, unknowns = 0, steps = 0
      real(dp) :: dt = 0
      type(run_output) :: output
      real(dp) :: error = 0           !! relative tip error (see the study)
      real(dp) :: error_absolute = 0  !! the same before normalization (m)
      real(dp) :: energy_error = 0    !! see the study
      logical :: pareto = .false.
   end type run_row

   real(dp), parameter :: bounce_gap = 20e-6_dp    !! s of flight that separate two bounces
   real(dp), parameter :: episode_gap = 0.5e-3_dp  !! s of flight that separate two contact episodes
   real(dp), parameter :: repeat_below = 0.1_dp    !! s: shorter runs are timed 3 times
   real(dp), parameter :: batch_at_least = 0.01_dp !! s: shorter runs are timed in batches

   type(combination), parameter :: families(8) = [ &
      combination('hermite', 'velocity', 0.5_dp), combination('hermite', 'velocity', 1.0_dp), &
      combination('hermite', 'position', 0.5_dp), combination('hermite', 'position', 1.0_dp), &
      combination('bspline', 'velocity', 0.5_dp), combination('bspline', 'velocity', 1.0_dp), &
      combination('bspline', 'position', 0.5_dp), combination('bspline', 'position', 1.0_dp)]

   character(len=512) :: study, scene_path, output_dir, option
   integer(int64) :: clock_start, clock_end, clock_rate
   logical :: check = .false.   ! --check given
   integer :: failures = 0      ! failed checks

   option = ''
   if (command_argument_count() == 4) call get_command_argument(4, option)
   if (command_argument_count() < 3 .or. command_argument_count() > 4 .or. &
       (command_argument_count() == 4 .and. option /= '--check')) then
      write (error_unit, '(a)') 'usage: work_precision free|impacts SCENE.nml OUTPUT_DIR [--check]'
      error stop 2
   end if
   check = option == '--check'
   call get_command_argument(1, study)
   call get_command_argument(2, scene_path)
   call get_command_argument(3, output_dir)
   call system_clock(clock_start, clock_rate)
   select case (study)
   case ('free')
      call free_vibration_study(trim(scene_path), trim(output_dir))
   case ('impacts')
      call impacts_study(trim(scene_path), trim(output_dir))
   case default
      write (error_unit, '(a)') 'work_precision: unknown study '''//trim(study)//''' (free or impacts)'
      error stop 2
   end select
   call system_clock(clock_end)
   write (output_unit, '(a,a,a,f8.1,a)') 'work_precision ', trim(study), ': total wall time ', &
      real(clock_end - clock_start, dp)/real(clock_rate, dp), ' s'
   if (check) then
      if (failures > 0) then
         write (error_unit, '(a,i0,a)') 'work_precision: ', failures, ' check(s) failed'
         error stop 1
      end if
      write (output_unit, '(a)') 'work_precision: every check passed'
   end if

contains

   !> Study (a): free vibration against the closed form.
   subroutine free_vibration_study(path, directory)
      character(len=*), intent(in) :: path       !! namelist giving the defaults
      character(len=*), intent(in) :: directory  !! where the table and the .dat go
      integer, parameter :: element_counts(5) = [4, 8, 16, 32, 64]
      integer, parameter :: finest_power = 16      ! dt = 2^-5 ... 2^-16
      real(dp), parameter :: sample_interval = 1.0_dp/32, t_end = 8.0_dp
      real(dp), parameter :: velocity_amplitude = 1.0_dp, displacement_amplitude = 0.05_dp
      type(scene_type) :: scene
      type(run_row), allocatable :: rows(:)
      real(dp), allocatable :: exact_tip(:)
      real(dp) :: omega1, omega2, t
      integer :: samples, k, f, i, j, done, unit
      integer(int64) :: study_start, study_end, rate
      call system_clock(study_start, rate)
      scene = read_test_scene(path)
      ! the normalized beam of theory §7, whatever the file says
      scene%beam%length = 1
      scene%beam%k2 = 1
      scene%beam%youngs_modulus = unset
      scene%beam%density = unset
      scene%beam%area = unset
      scene%beam%inertia = unset
      scene%beam%rayleigh_mass = 0
      scene%beam%rayleigh_stiffness = 0
      scene%analysis%kind = 'dynamics'
      if (allocated(scene%obstacles)) deallocate (scene%obstacles)
      allocate (scene%obstacles(0))
      scene%load%distributed = 0
      scene%load%point_force = 0
      scene%load%base_amplitude = 0
      scene%initial%displacement = 'mode'
      scene%initial%displacement_mode = 2
      scene%initial%displacement_amplitude = displacement_amplitude
      scene%initial%velocity = 'mode'
      scene%initial%velocity_mode = 1
      scene%initial%velocity_amplitude = velocity_amplitude
      scene%time%t_end = t_end
      omega1 = cantilever_frequency(1, scene%beam%length, scene%beam%k2)
      omega2 = cantilever_frequency(2, scene%beam%length, scene%beam%k2)
      samples = nint(t_end/sample_interval)
      allocate (exact_tip(samples))
      do k = 1, samples
         t = k*sample_interval
         ! theory §7: each mode evolves on its own; the shapes have tip value 1
         exact_tip(k) = cantilever_mode_shape(1, scene%beam%length, scene%beam%length, 0)*velocity_amplitude* &
                        sin(omega1*t)/omega1 + &
                        cantilever_mode_shape(2, scene%beam%length, scene%beam%length, 0)*displacement_amplitude*cos(omega2*t)
      end do

      allocate (rows(size(families)*size(element_counts)*(finest_power - 4)))
      done = 0
      do f = 1, size(families)
         do i = 1, size(element_counts)
            do j = 5, finest_power
               done = done + 1
               rows(done)%family = families(f)
               rows(done)%elements = element_counts(i)
               rows(done)%dt = 2.0_dp**(-j)
               call run_and_time(scene, rows(done), sample_interval)
               rows(done)%error_absolute = maxval(abs(rows(done)%output%tip - exact_tip))
               rows(done)%error = rows(done)%error_absolute/maxval(abs(exact_tip))
               rows(done)%energy_error = abs(rows(done)%output%final_energy/rows(done)%output%initial_energy - 1)
            end do
            write (output_unit, '(a,1x,a,1x,a,f4.1,a,i3,a,es9.2,a)') 'free:', trim(families(f)%basis), &
               trim(families(f)%scheme), families(f)%theta, ', N =', element_counts(i), ' done, finest error ', &
               rows(done)%error, ''
         end do
      end do
      call mark_pareto(rows)
      call system_clock(study_end)

      open (newunit=unit, file=directory//'/work_precision_free.txt', status='replace', action='write')
      write (unit, '(a)') '# Work-precision study (a): free vibration against the closed form (theory §7)'
      write (unit, '(a)') '# program studies/work_precision/work_precision.f90, run by studies/work_precision/work_precision.sh'
      write (unit, '(a)') '# beam: L = 1, k2 = 1, clamped-free, no obstacle, no load, no damping'
      write (unit, '(a,f5.2,a,f5.2,a)') '# initial data: mode-1 velocity (tip ', velocity_amplitude, &
         ') + mode-2 displacement (tip ', displacement_amplitude, '), closed-form shapes interpolated on the mesh'
      write (unit, '(a,es23.16,a,es23.16)') '# omega_1 = ', omega1, ', omega_2 = ', omega2
      write (unit, '(a,f5.1,a,f8.5,a,i0,a,es10.3)') '# t_end = ', t_end, ', samples every ', sample_interval, &
         ' (', samples, '), max |u_exact(L, t_k)| = ', maxval(abs(exact_tip))
      write (unit, '(a)') '# error  = max_k |u_h(L,t_k) - u_exact(L,t_k)| / max_k |u_exact(L,t_k)|'
      write (unit, '(a)') '# energy = |E(t_end)/E(0) - 1| with the energy the stepper reports (the position scheme:'
      write (unit, '(a)') '#          its conserved half-step energy, at t = 0 too: E_{-1/2} from U^0 and U^{-1})'
      call write_cost_legend(unit)
      write (unit, '(a,f8.1,a)') '# study wall time ', real(study_end - study_start, dp)/real(rate, dp), ' s'
      call write_table(unit, rows(1:done), 'energy drift')
      call write_pareto_summary(unit, rows(1:done))
      close (unit)
      open (newunit=unit, file=directory//'/work_precision_free.dat', status='replace', action='write')
      call write_plot_data(unit, rows(1:done), 'free vibration')
      close (unit)
      if (.not. check) return
      call check_order(rows(1:done), families(1), 64, 7, 10, 1.8_dp, 2.2_dp)
      call check_order(rows(1:done), families(2), 64, 12, 16, 0.8_dp, 1.2_dp)
      call check_order(rows(1:done), families(4), 64, 8, 11, 1.8_dp, 2.2_dp)
      call expect('energy drift of hermite and bspline velocity theta = 0.5 below 1e-9', &
                  maxval(rows(1:done)%energy_error, mask=rows(1:done)%family%scheme == 'velocity' .and. &
                         rows(1:done)%family%theta < 0.75_dp), 0.0_dp, 1e-9_dp)
      do f = 1, size(families)
         if (families(f)%theta > 0.75_dp) cycle
         call expect('smallest error of '//family_label(families(f))//' at most 1e-5', &
                     minval(rows(1:done)%error, mask=[(same_family(rows(i)%family, families(f)), i=1, done)]), &
                     0.0_dp, 1e-5_dp)
      end do
   end subroutine free_vibration_study

   !> Fitted order in dt of the error of `family` at N = `elements` between dt = 2^-coarse
   !! and 2^-fine, expected in [low, high].
   subroutine check_order(rows, family, elements, coarse, fine, low, high)
      type(run_row), intent(in) :: rows(:)
      type(combination), intent(in) :: family
      integer, intent(in) :: elements, coarse, fine
      real(dp), intent(in) :: low, high
      real(dp) :: error_coarse, error_fine
      integer :: i
      error_coarse = -1
      error_fine = -1
      do i = 1, size(rows)
         if (.not. same_family(rows(i)%family, family) .or. rows(i)%elements /= elements) cycle
         if (abs(rows(i)%dt - 2.0_dp**(-coarse)) < 1e-3_dp*rows(i)%dt) error_coarse = rows(i)%error
         if (abs(rows(i)%dt - 2.0_dp**(-fine)) < 1e-3_dp*rows(i)%dt) error_fine = rows(i)%error
      end do
      call expect('order in dt of '//family_label(family), log(error_coarse/error_fine)/((fine - coarse)*log(2.0_dp)), &
                  low, high)
   end subroutine check_order

   !> Record a check: `value` must lie in [low, high].
   subroutine expect(name, value, low, high)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value, low, high
      if (value >= low .and. value <= high) then
         write (output_unit, '(a,es11.4,a,es10.3,a,es10.3,a)') 'check passed: '//name//' = ', value, ' in [', low, &
            ', ', high, ']'
      else
         failures = failures + 1
         write (error_unit, '(a,es11.4,a,es10.3,a,es10.3,a)') 'check FAILED: '//name//' = ', value, ', expected in [', &
            low, ', ', high, ']'
      end if
   end subroutine expect

   !> Study (b): the two-stop looseness scene against a converged fine run.
   subroutine impacts_study(path, directory)
      character(len=*), intent(in) :: path       !! inputs/looseness_tip_stops.nml
      character(len=*), intent(in) :: directory  !! where the table and the .dat go
      integer, parameter :: element_counts(4) = [8, 16, 32, 64]
      integer, parameter :: dt_levels = 7             ! dt = 2e-5/2^j, j = 0..6
      real(dp), parameter :: sample_interval = 2e-5_dp, window = 0.01_dp
      ! the reference family and its levels: dt N = sample_interval (dt proportional to h)
      integer, parameter :: reference_elements = 1024
      integer, parameter :: check_elements(3) = [512, 256, 128]
      integer, parameter :: fine_elements = 512       ! fine run of every combination
      ! and N = 1024 for the two theta = 1/2 combinations that stay farthest from it at 512
      integer, parameter :: finest_families(2) = [5, 3], finest_elements = 1024
      type(scene_type) :: scene
      type(run_row), allocatable :: rows(:), checks(:)
      type(run_row) :: reference
      real(dp) :: tip_scale, energy_scale, uncertainty, spread
      integer :: done, f, i, j, unit, c
      integer(int64) :: study_start, study_end, rate
      call system_clock(study_start, rate)
      scene = read_test_scene(path)
      scene%time%t_end = window

      ! the reference: finest settings, 16 x below the sweep's finest dt, N = 1024
      reference%family = combination('hermite', 'velocity', 0.5_dp)
      reference%elements = reference_elements
      reference%dt = sample_interval/reference_elements
      call run_and_time(scene, reference, sample_interval, once=.true.)
      tip_scale = maxval(abs(reference%output%tip))
      energy_scale = reference%output%initial_energy
      write (output_unit, '(a,es10.3,a,f7.1,a)') 'impacts: reference done, max |u_tip| = ', tip_scale, &
         ' m, ', reference%output%cpu_seconds, ' s CPU'

      ! its convergence: coarser levels of the same family, then fine runs of every combination
      allocate (checks(size(check_elements) + size(families) - 1 + size(finest_families)))
      c = 0
      do i = 1, size(check_elements)
         c = c + 1
         checks(c)%family = reference%family
         checks(c)%elements = check_elements(i)
         checks(c)%dt = sample_interval/check_elements(i)
      end do
      do f = 2, size(families)
         c = c + 1
         checks(c)%family = families(f)
         checks(c)%elements = fine_elements
         checks(c)%dt = sample_interval/fine_elements
      end do
      do f = 1, size(finest_families)
         c = c + 1
         checks(c)%family = families(finest_families(f))
         checks(c)%elements = finest_elements
         checks(c)%dt = sample_interval/finest_elements
      end do
      do c = 1, size(checks)
         call run_and_time(scene, checks(c), sample_interval, once=.true.)
         call compare(checks(c), reference, tip_scale, energy_scale)
         write (output_unit, '(a,1x,a,1x,a,f4.1,a,i5,a,es10.3)') 'impacts: check', trim(checks(c)%family%basis), &
            trim(checks(c)%family%scheme), checks(c)%family%theta, ', N =', checks(c)%elements, &
            ': difference ', checks(c)%error
      end do
      uncertainty = checks(1)%error                               ! next-coarser level
      spread = maxval(checks(size(check_elements) + 1:size(check_elements) + size(families) - 1)%error)   ! others, N = 512

      allocate (rows(size(families)*size(element_counts)*dt_levels))
      done = 0
      do f = 1, size(families)
         do i = 1, size(element_counts)
            do j = 0, dt_levels - 1
               done = done + 1
               rows(done)%family = families(f)
               rows(done)%elements = element_counts(i)
               rows(done)%dt = sample_interval/2**j
               call run_and_time(scene, rows(done), sample_interval)
               call compare(rows(done), reference, tip_scale, energy_scale)
            end do
         end do
         write (output_unit, '(a,1x,a,1x,a,f4.1,a)') 'impacts:', trim(families(f)%basis), &
            trim(families(f)%scheme), families(f)%theta, ' done'
      end do
      call mark_pareto(rows)
      call system_clock(study_end)

      open (newunit=unit, file=directory//'/work_precision_impacts.txt', status='replace', action='write')
      write (unit, '(a)') '# Work-precision study (b): two-stop looseness scene against a converged fine run'
      write (unit, '(a)') '# program studies/work_precision/work_precision.f90, run by studies/work_precision/work_precision.sh'
      write (unit, '(a)') '# scene '//path//' (steel, L = 0.5 m, tip stops at -1/+1 mm, e = 0.8, '// &
         'mode-1 release 0.5 m/s) over [0, 10 ms]'
      write (unit, '(a,es10.3,a,i0,a,es12.5,a)') '# samples every ', sample_interval, ' s (', &
         size(reference%output%tip), '), max |u_ref(L, t_k)| = ', tip_scale, ' m'
      write (unit, '(a)') '# error  = max_k |u_h(L,t_k) - u_ref(L,t_k)| / max_k |u_ref(L,t_k)| (the column "abs" in m)'
      write (unit, '(a)') '# energy = |E_h(t_end) - E_ref(t_end)| / E_ref(0) (position scheme: its half-step energy)'
      write (unit, '(a,es12.5,a,es12.5,a)') '# E_ref(0) = ', energy_scale, ' J, E_ref(t_end) = ', &
         reference%output%final_energy, ' J'
      write (unit, '(a)') '# impacts: the recorder''s count (an approaching point receiving an impulse after a step'
      write (unit, '(a)') '#          without one); impulse steps: steps with a non-zero impulse'
      call write_cost_legend(unit)
      write (unit, '(a,f8.1,a)') '# study wall time ', real(study_end - study_start, dp)/real(rate, dp), ' s'
      write (unit, '(a)') ''
      write (unit, '(a)') '## Reference and its convergence'
      write (unit, '(a)') '# reference: hermite velocity theta 0.5, N = 1024, dt = 2e-5/1024 s (16 x below the '// &
         'sweep''s finest dt); the levels of its family keep dt N = 2e-5 s (dt proportional to h)'
      write (unit, &
         '(a)') '# bounces: bursts of tip impulses separated by more than 20 us of flight; episodes: by more than 0.5 ms'
      write (unit, '(a)') '#  basis    scheme    theta     N     J       dt (s)   steps   cpu (s)   '// &
         'difference  abs (m)    rms (m)     energy   impacts impulse-steps bounces episodes E(t_end) (J)'
      call write_check_row(unit, reference, 0.0_dp)
      do c = 1, size(checks)
         call write_check_row(unit, checks(c), rms_difference(checks(c), reference))
      end do
      write (unit, '(a,es10.3,a,es10.3,a)') '# uncertainty of the reference (its next-coarser level, N = 512): ', &
         uncertainty, ' relative; largest difference of another combination at N = 512: ', spread, ' relative'
      write (unit, '(a)') ''
      write (unit, '(a)') '## Sweep'
      call write_table(unit, rows(1:done), 'energy error', with_counts=.true.)
      call write_pareto_summary(unit, rows(1:done))
      call write_path_summary(unit, rows(1:done), reference, checks, sample_interval)
      close (unit)
      open (newunit=unit, file=directory//'/work_precision_impacts.dat', status='replace', action='write')
      call write_plot_data(unit, rows(1:done), 'looseness, [0, 10 ms]')
      write (unit, '(a)') '# reference levels: uncertainty (next-coarser level) and spread (other combinations, N = 512)'
      write (unit, '(2es12.4)') uncertainty, spread
      close (unit)
      if (check) call expect('reference against its next-coarser level (relative to max |u_tip|)', uncertainty, &
                             0.0_dp, 1e-2_dp)
   end subroutine impacts_study

   !> Run `row`'s settings on `scene`, keep the tip at every multiple of `sample_interval`
   !! and the stepping loop's CPU time: the median of 3 repetitions below `repeat_below`,
   !! each a batch of runs lasting at least `batch_at_least`. `once` skips the repetitions.
   subroutine run_and_time(scene, row, sample_interval, once)
      type(scene_type), intent(in) :: scene
      type(run_row), intent(inout) :: row
      real(dp), intent(in) :: sample_interval   !! s, a whole number of steps
      logical, intent(in), optional :: once
      type(scene_type) :: configured
      type(run_problem) :: prepared
      type(run_output) :: again
      character(len=:), allocatable :: warnings
      character(len=512) :: errmsg
      real(dp) :: cpu(3), wall(3)
      integer :: stat, batch, repetition, b
      configured = scene
      configured%mesh%basis = row%family%basis
      configured%time%scheme = row%family%scheme
      configured%time%theta = row%family%theta
      configured%mesh%elements = row%elements
      configured%time%dt = row%dt
      ! &analysis modes only matters for kind = 'modes' but must not exceed the unknowns
      configured%analysis%modes = 1
      call validate_scene(configured, stat, errmsg)
      if (stat == 0) then
         warnings = ''
         call build_problem(configured, prepared, warnings, stat, errmsg)
      end if
      if (stat /= 0) then
         write (error_unit, '(a)') 'work_precision: '//trim(errmsg)
         error stop 1
      end if
      row%unknowns = prepared%model%unknowns
      row%steps = nint(configured%time%t_end/configured%time%dt)
      call simulate(configured, prepared, sample_interval, row%output)
      if (present(once)) then
         if (once) return
      end if
      if (row%output%cpu_seconds >= repeat_below) return
      batch = max(1, ceiling(batch_at_least/max(row%output%cpu_seconds, 1e-7_dp)))
      do repetition = 1, 3
         cpu(repetition) = 0
         wall(repetition) = 0
         do b = 1, batch
            call simulate(configured, prepared, sample_interval, again)
            cpu(repetition) = cpu(repetition) + again%cpu_seconds
            wall(repetition) = wall(repetition) + again%wall_seconds
         end do
      end do
      row%output%cpu_seconds = median3(cpu)/batch
      row%output%wall_seconds = median3(wall)/batch
      row%output%repetitions = 3*batch
   end subroutine run_and_time

   !> One run from t = 0 to t_end: the tip at the sample times, energies, impact counts
   !! and the time spent in the stepping loop.
   subroutine simulate(scene, prepared, sample_interval, output)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: sample_interval
      type(run_output), intent(out) :: output
      class(time_stepper), allocatable :: stepper
      character(len=512) :: errmsg
      integer :: stat, n, steps, every, dofs(4), a, k, c
      real(dp) :: weights(4), cpu_start, cpu_end, last_impulse
      integer(int64) :: wall_start, wall_end, rate
      logical, allocatable :: in_contact(:), now(:)
      logical :: impulse
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'work_precision: '//trim(errmsg)
         error stop 1
      end if
      call point_row(prepared%model, scene%beam%length, dofs, weights)
      steps = nint(scene%time%t_end/scene%time%dt)
      every = nint(sample_interval/scene%time%dt)
      allocate (output%tip(steps/every), in_contact(prepared%contacts%count), now(prepared%contacts%count))
      in_contact = .false.
      last_impulse = -huge(1.0_dp)
      output%initial_energy = stepper%kinetic_energy() + stepper%elastic_energy()
      call system_clock(wall_start, rate)
      call cpu_time(cpu_start)
      do n = 1, steps
         call stepper%step(stat, errmsg)
         if (stat /= 0) then
            write (error_unit, '(a,1x,a,1x,a,i0,a,es10.3,a)') 'work_precision: step failed (', trim(scene%mesh%basis), &
               trim(scene%time%scheme), scene%mesh%elements, ', dt = ', scene%time%dt, '): '//trim(errmsg)
            error stop 1
         end if
         if (mod(n, every) == 0) then
            output%tip(n/every) = 0
            do a = 1, 4
               if (dofs(a) > 0) output%tip(n/every) = output%tip(n/every) + weights(a)*stepper%u(dofs(a))
            end do
         end if
         if (prepared%contacts%count == 0) cycle
         ! impact bookkeeping as the recorder does it (docs/method.md, "Impacts")
         now = .false.
         impulse = .false.
         do k = 1, stepper%report%active_count
            if (abs(stepper%report%impulse(k)) <= 0) cycle
            c = stepper%report%active(k)
            now(c) = .true.
            impulse = .true.
            if (.not. in_contact(c) .and. stepper%report%approaching(k)) output%impacts = output%impacts + 1
         end do
         in_contact = now
         if (impulse) then
            output%impulse_steps = output%impulse_steps + 1
            if (stepper%report%impulse_time - last_impulse > bounce_gap) output%bounces = output%bounces + 1
            if (stepper%report%impulse_time - last_impulse > episode_gap) output%episodes = output%episodes + 1
            last_impulse = stepper%report%impulse_time
         end if
      end do
      call cpu_time(cpu_end)
      call system_clock(wall_end)
      output%cpu_seconds = cpu_end - cpu_start
      output%wall_seconds = real(wall_end - wall_start, dp)/real(rate, dp)
      output%final_energy = stepper%kinetic_energy() + stepper%elastic_energy()
   end subroutine simulate

   !> Errors of `row` against the reference run (same sample times).
   subroutine compare(row, reference, tip_scale, energy_scale)
      type(run_row), intent(inout) :: row
      type(run_row), intent(in) :: reference
      real(dp), intent(in) :: tip_scale     !! max |u_ref(L, t_k)| (m)
      real(dp), intent(in) :: energy_scale  !! E_ref(0) (J)
      row%error_absolute = maxval(abs(row%output%tip - reference%output%tip))
      row%error = row%error_absolute/tip_scale
      row%energy_error = abs(row%output%final_energy - reference%output%final_energy)/energy_scale
   end subroutine compare

   !> Per combination, the relative errors along the reference's path dt N = `product`
   !! (N = 8..64 from the sweep, then the check runs of the same combination, N = 128..1024;
   !! for the reference family, N = 1024 is the reference itself).
   subroutine write_path_summary(unit, rows, reference, checks, product)
      integer, intent(in) :: unit
      type(run_row), intent(in) :: rows(:), checks(:)
      type(run_row), intent(in) :: reference
      real(dp), intent(in) :: product   !! dt N (s)
      integer, parameter :: check_levels(4) = [128, 256, 512, 1024]
      integer :: f, i, e, c
      logical :: written
      write (unit, '(a)') ''
      write (unit, '(a,es9.2,a)') '## Along the reference''s path dt N = ', product, &
         ' s: relative error for N = 8, 16, 32, 64 (sweep), 128 ... 1024 (checks; "-" not run)'
      write (unit, '(a28,8a11)') '# combination', 'N = 8', '16', '32', '64', '128', '256', '512', '1024'
      do f = 1, size(families)
         write (unit, '(a28)', advance='no') family_label(families(f))
         do i = 1, size(rows)
            if (same_family(rows(i)%family, families(f)) .and. &
                abs(rows(i)%dt*rows(i)%elements - product) < 1e-6_dp*product) &
               write (unit, '(es11.3)', advance='no') rows(i)%error
         end do
         do e = 1, size(check_levels)
            written = .false.
            do c = 1, size(checks)
               if (same_family(checks(c)%family, families(f)) .and. checks(c)%elements == check_levels(e)) then
                  write (unit, '(es11.3)', advance='no') checks(c)%error
                  written = .true.
               end if
            end do
            if (.not. written .and. same_family(reference%family, families(f)) .and. &
                check_levels(e) == reference%elements) then
               write (unit, '(a11)', advance='no') 'reference'
            else if (.not. written) then
               write (unit, '(a11)', advance='no') '-'
            end if
         end do
         write (unit, '(a)') ''
      end do
   end subroutine write_path_summary

   !> Root mean square over the sample times of the tip difference (m).
   pure function rms_difference(row, reference) result(rms)
      type(run_row), intent(in) :: row, reference
      real(dp) :: rms
      rms = sqrt(sum((row%output%tip - reference%output%tip)**2)/size(row%output%tip))
   end function rms_difference

   !> Flag, within each combination, the runs that no cheaper run of it beats in error.
   subroutine mark_pareto(rows)
      type(run_row), intent(inout) :: rows(:)
      integer :: i, j
      do i = 1, size(rows)
         rows(i)%pareto = .true.
         do j = 1, size(rows)
            if (j == i .or. .not. same_family(rows(i)%family, rows(j)%family)) cycle
            if (rows(j)%output%cpu_seconds <= rows(i)%output%cpu_seconds .and. rows(j)%error < rows(i)%error) then
               rows(i)%pareto = .false.
               exit
            end if
         end do
      end do
   end subroutine mark_pareto

   pure logical function same_family(a, b)
      type(combination), intent(in) :: a, b
      same_family = a%basis == b%basis .and. a%scheme == b%scheme .and. abs(a%theta - b%theta) < 1e-12_dp
   end function same_family

   !> Label like 'hermite/velocity/theta=0.5'.
   pure function family_label(family) result(label)
      type(combination), intent(in) :: family
      character(len=:), allocatable :: label
      character(len=8) :: theta
      write (theta, '(f3.1)') family%theta
      label = trim(family%basis)//'/'//trim(family%scheme)//'/theta='//trim(theta)
   end function family_label

   !> Median of three numbers.
   pure real(dp) function median3(x)
      real(dp), intent(in) :: x(3)
      median3 = max(min(x(1), x(2)), min(max(x(1), x(2)), x(3)))
   end function median3

   subroutine write_cost_legend(unit)
      integer, intent(in) :: unit
      write (unit, '(a)') '# cpu: CPU time of the stepping loop (s), set-up and factorization excluded; median of'
      write (unit, '(a)') '#      3 repetitions when below 0.1 s, each a batch of >= 10 ms ("reps" = runs timed);'
      write (unit, '(a)') '#      cpu/wall: CPU over wall time of the same loops (< 1: the process waited for a core)'
   end subroutine write_cost_legend

   !> The whole sweep, one row per run; '*' marks the Pareto front of its combination.
   subroutine write_table(unit, rows, energy_name, with_counts)
      integer, intent(in) :: unit
      type(run_row), intent(in) :: rows(:)
      character(len=*), intent(in) :: energy_name
      logical, intent(in), optional :: with_counts
      logical :: counts
      integer :: i
      counts = .false.
      if (present(with_counts)) counts = with_counts
      if (counts) then
         write (unit, '(a)') '#  basis    scheme    theta     N     J       dt (s)    steps   cpu (s)  reps cpu/wall'// &
            '     error     abs (m)  '//energy_name//'  impacts impulse-steps pareto'
      else
         write (unit, '(a)') '#  basis    scheme    theta     N     J       dt        steps   cpu (s)  reps cpu/wall'// &
            '     error     abs (m)  '//energy_name//'  pareto'
      end if
      do i = 1, size(rows)
         associate (r => rows(i))
            if (counts) then
               write (unit, '(2x,a8,1x,a9,f5.1,i6,i6,es13.4,i9,es10.3,i6,f8.2,3es11.3,i8,i14,a7)') r%family%basis, &
                  r%family%scheme, r%family%theta, r%elements, r%unknowns, r%dt, r%steps, r%output%cpu_seconds, &
                  r%output%repetitions, cpu_over_wall(r%output), r%error, r%error_absolute, r%energy_error, &
                  r%output%impacts, r%output%impulse_steps, merge('      *', '       ', r%pareto)
            else
               write (unit, '(2x,a8,1x,a9,f5.1,i6,i6,es13.4,i9,es10.3,i6,f8.2,3es11.3,a7)') r%family%basis, &
                  r%family%scheme, r%family%theta, r%elements, r%unknowns, r%dt, r%steps, r%output%cpu_seconds, &
                  r%output%repetitions, cpu_over_wall(r%output), r%error, r%error_absolute, r%energy_error, &
                  merge('      *', '       ', r%pareto)
            end if
         end associate
      end do
   end subroutine write_table

   pure real(dp) function cpu_over_wall(output)
      type(run_output), intent(in) :: output
      cpu_over_wall = output%cpu_seconds/max(output%wall_seconds, tiny(1.0_dp))
   end function cpu_over_wall

   !> Per combination: its Pareto front in order of cost, and the cheapest run reaching
   !! each of a few error levels.
   subroutine write_pareto_summary(unit, rows)
      integer, intent(in) :: unit
      type(run_row), intent(in) :: rows(:)
      real(dp), parameter :: levels(6) = [1e-1_dp, 1e-2_dp, 1e-3_dp, 1e-4_dp, 1e-5_dp, 1e-6_dp]
      integer :: f, i, l, best
      integer, allocatable :: order(:)
      write (unit, '(a)') ''
      write (unit, '(a)') '## Pareto fronts (cheapest first): N, dt, CPU s, error'
      do f = 1, size(families)
         order = sorted_front(rows, families(f))
         write (unit, '(a)') '# '//family_label(families(f))
         do i = 1, size(order)
            associate (r => rows(order(i)))
               write (unit, '(4x,i5,es12.4,es11.3,es11.3)') r%elements, r%dt, r%output%cpu_seconds, r%error
            end associate
         end do
      end do
      write (unit, '(a)') ''
      write (unit, '(a)') '## Cheapest run of each combination with error <= level: CPU s (N, dt); "-" none in the sweep'
      write (unit, '(a28,6(5x,a,es7.0,2x))') '# combination', ('<=', levels(l), l=1, size(levels))
      do f = 1, size(families)
         write (unit, '(a28)', advance='no') family_label(families(f))
         do l = 1, size(levels)
            best = 0
            do i = 1, size(rows)
               if (.not. same_family(rows(i)%family, families(f)) .or. rows(i)%error > levels(l)) cycle
               if (best == 0) then
                  best = i
               else if (rows(i)%output%cpu_seconds < rows(best)%output%cpu_seconds) then
                  best = i
               end if
            end do
            if (best == 0) then
               write (unit, '(a18)', advance='no') '-'
            else
               write (unit, '(es9.2,a,i3,a,es7.1,a)', advance='no') rows(best)%output%cpu_seconds, ' (', &
                  rows(best)%elements, ',', rows(best)%dt, ')'
            end if
         end do
         write (unit, '(a)') ''
      end do
   end subroutine write_pareto_summary

   !> Indices of the Pareto runs of `family`, by increasing CPU time.
   function sorted_front(rows, family) result(order)
      type(run_row), intent(in) :: rows(:)
      type(combination), intent(in) :: family
      integer, allocatable :: order(:)
      integer :: i, j, swap
      order = pack([(i, i=1, size(rows))], [(rows(i)%pareto .and. same_family(rows(i)%family, family), i=1, size(rows))])
      do i = 2, size(order)      ! insertion sort: a handful of entries
         j = i
         do while (j > 1)
            if (rows(order(j - 1))%output%cpu_seconds <= rows(order(j))%output%cpu_seconds) exit
            swap = order(j)
            order(j) = order(j - 1)
            order(j - 1) = swap
            j = j - 1
         end do
      end do
   end function sorted_front

   !> gnuplot blocks: index f-1 every run of combination f, index 7+f its Pareto front.
   subroutine write_plot_data(unit, rows, title)
      integer, intent(in) :: unit
      type(run_row), intent(in) :: rows(:)
      character(len=*), intent(in) :: title
      integer :: f, i
      integer, allocatable :: order(:)
      write (unit, '(a)') '# work-precision, '//title//': columns N J dt steps cpu_s error energy'
      do f = 1, size(families)
         write (unit, '(a)') '# all runs '//family_label(families(f))
         do i = 1, size(rows)
            if (same_family(rows(i)%family, families(f))) call write_point(unit, rows(i))
         end do
         write (unit, '(/)')
      end do
      do f = 1, size(families)
         write (unit, '(a)') '# pareto '//family_label(families(f))
         order = sorted_front(rows, families(f))
         do i = 1, size(order)
            call write_point(unit, rows(order(i)))
         end do
         write (unit, '(/)')
      end do
   end subroutine write_plot_data

   !> One point of the plot data: N J dt steps cpu error energy.
   subroutine write_point(unit, row)
      integer, intent(in) :: unit
      type(run_row), intent(in) :: row
      write (unit, '(i6,i6,es13.5,i9,3es13.5)') row%elements, row%unknowns, row%dt, row%steps, &
         row%output%cpu_seconds, row%error, row%energy_error
   end subroutine write_point

   !> One line of the reference table.
   subroutine write_check_row(unit, row, rms)
      integer, intent(in) :: unit
      type(run_row), intent(in) :: row
      real(dp), intent(in) :: rms   !! root mean square tip difference (m)
      write (unit, '(2x,a8,1x,a9,f5.1,i6,i6,es13.4,i9,f9.2,4es11.3,i8,i14,i8,i9,es13.5)') row%family%basis, &
         row%family%scheme, row%family%theta, row%elements, row%unknowns, row%dt, row%steps, row%output%cpu_seconds, &
         row%error, row%error_absolute, rms, row%energy_error, row%output%impacts, row%output%impulse_steps, &
         row%output%bounces, row%output%episodes, row%output%final_energy
   end subroutine write_check_row
end program work_precision
