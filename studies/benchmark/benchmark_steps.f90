!> Benchmark of the velocity-based time stepper (theory §3): wall-clock time per step
!! against the number of elements N = 16 .. 1024 (Hermite elements, J = 2N unknowns,
!! k2 = 1, L = 1, dt = 1e-4 s, theta = gamma = 1/2). A study, not a test: it checks
!! nothing against a tolerance and is not run by ctest.
!!
!! Cases, each on a fresh stepper:
!! - (a) tip obstacle: one 'below' punctual obstacle at x = L, level -1 m, which a beam
!!   released in mode 1 with tip velocity 0.1 m/s (tip amplitude about 0.03 m) never
!!   reaches, so every step is a free-flight step (no active contact point; checked);
!! - baseline: one `band_solve` with the factor of the iteration matrix W plus one
!!   `band_matvec` with the stiffness K, of the same order J, timed in turn with (a);
!! - (b) longitudinal obstacle: a 'below' obstacle at level 0 under the whole beam
!!   (x = 0 .. L, so every node 1..N is a contact point), a uniform load q = -1 (per unit
!!   mass) pressing the beam onto it, zero initial velocity, restitution 0. The initial
!!   displacement is exactly the static equilibrium (`solve_static`), as
!!   `&initial displacement = 'static'` gives it: its nodes sit on the obstacle up to
!!   round-off, which the stepper's activation tolerance (1e-12 L) absorbs, so every node
!!   stays active with the same active set in every step (checked: the smallest active
!!   count of the timed steps and the pivots per step are printed beside the number of
!!   contact points). Contact regime 'auto' (Delassus up to `delassus_limit` contact
!!   points, band saddle-point solver above); for N <= 64 both regimes are timed.
!!
!! Timing: `system_clock` with int64 counts (wall clock, nanosecond resolution with
!! gfortran). For each workload a batch of calls is doubled until it lasts at least
!! `min_batch_seconds` (this calibration is also the warm-up); then the batch is timed
!! `repetitions` times and the median time per call is kept. (a) and the baseline are
!! timed in turn within each repetition, and their ratio is the median of the paired
!! ratios, so that a change of load on a shared machine affects both alike. `cpu_time` is
!! read around the same batches; the smallest ratio of CPU to wall time is printed as a
!! sign of interference (well below 1: the process waited for a processor).
!!
!! The exponent p of t ~ N^p is the least-squares slope of log t against log N, over
!! N >= 64 (below, fixed per-step overheads dominate) and over all N.
!!
!! Usage: `benchmark_steps [TABLE_FILE]`; the table goes to standard output and, when a
!! file name is given, to that file as well.
program benchmark_steps
   use vibrobeam_kinds, only: dp, int64, output_unit, error_unit
   use vibrobeam_sorting, only: median
   use vibrobeam_scene, only: scene_type, obstacle_type
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_obstacles, only: build_contact_points
   use vibrobeam_loads, only: load_set, build_loads
   use vibrobeam_initial_state, only: mode_field
   use vibrobeam_static, only: solve_static
   use vibrobeam_velocity_stepper, only: velocity_stepper
   use vibrobeam_time_stepper, only: stepper_settings, dynamic_state
   use vibrobeam_discrete_system, only: discrete_system
   use vibrobeam_problem, only: stepper_settings_of
   use vibrobeam_contact_projector, only: regime_band, delassus_limit
   use vibrobeam_band, only: band_solve, band_matvec
   implicit none

   !> Numbers of elements N of the study.
   integer, parameter :: element_counts(*) = [16, 32, 64, 128, 256, 512, 1024]
   !> Smallest N of the "large N" exponent fit.
   integer, parameter :: fit_from = 64
   !> Largest N for which both regimes of case (b) are timed.
   integer, parameter :: delassus_up_to = 64
   !> Timed batches per measurement; the median is kept.
   integer, parameter :: repetitions = 5
   !> Shortest duration of one timed batch (s).
   real(dp), parameter :: min_batch_seconds = 0.2_dp
   !> Time step (s) and beam data (normalized: rho S = 1, E I = k2 = 1, L = 1 m).
   real(dp), parameter :: time_step = 1.0e-4_dp, beam_length = 1.0_dp
   !> Tip velocity amplitude of the mode-1 initial velocity of case (a) (m/s).
   real(dp), parameter :: tip_velocity = 0.1_dp
   !> Uniform load of case (b) (N/m per unit mass, negative: downwards).
   real(dp), parameter :: pressing_load = -1.0_dp
   !> What `timed_batch` runs: a step of the stepper, or the baseline on its matrices.
   integer, parameter :: workload_step = 1, workload_baseline = 2

   !> One measurement: median time per call and what the calls did.
   type :: measurement
      real(dp) :: seconds = -1               !! median wall time per call (s); < 0: not measured
      real(dp) :: spread = 0                 !! (max - min)/median of the repetitions
      real(dp) :: cpu_fraction = 1           !! smallest CPU/wall ratio of the timed batches
      integer(int64) :: calls = 0            !! calls per timed batch
      integer :: active_min = huge(1)        !! fewest active contact points in a timed step
      integer :: active_max = 0              !! most active contact points in a timed step
      real(dp) :: active_mean = 0            !! mean active contact points per timed step
      real(dp) :: iterations_per_step = 0    !! contact solver pivots per timed step
   end type measurement

   !> What a series of steps did.
   type :: step_tally
      integer(int64) :: steps = 0, iterations = 0, active = 0
      integer :: active_min = huge(1), active_max = 0
   end type step_tally

   !> One line of the table.
   type :: table_row
      integer :: elements = 0, unknowns = 0, contact_points_b = 0
      character(len=8) :: regime_b = ''     !! regime that 'auto' chose in case (b)
      type(measurement) :: tip, baseline
      real(dp) :: ratio = 0                       !! median of the paired ratios t(a)/t(baseline)
      type(measurement) :: longitudinal           !! (b), regime 'auto'
      type(measurement) :: longitudinal_band      !! (b), band regime (= longitudinal where auto chose it)
      type(measurement) :: longitudinal_delassus  !! (b), Delassus regime (N <= delassus_up_to)
   end type table_row

   type(table_row) :: rows(size(element_counts))
   character(len=:), allocatable :: table_file
   integer :: r, table_unit, ios

   call table_file_argument(table_file)
   ! every free-flight case first, on a heap the contact cases have not yet used
   do r = 1, size(element_counts)
      call measure_free_flight(element_counts(r), rows(r))
      write (error_unit, '(a,i0,a)') 'benchmark_steps: case (a), N = ', element_counts(r), ' done'
   end do
   do r = 1, size(element_counts)
      call measure_contact(element_counts(r), rows(r))
      write (error_unit, '(a,i0,a)') 'benchmark_steps: cases (b), N = ', element_counts(r), ' done'
   end do
   call write_report(output_unit)
   if (len(table_file) > 0) then
      open (newunit=table_unit, file=table_file, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         write (error_unit, '(a)') 'benchmark_steps: cannot write '''//table_file//''''
         error stop 1
      end if
      call write_report(table_unit)
      close (table_unit)
   end if

contains

   !> The optional first command-line argument ('' when absent).
   subroutine table_file_argument(file)
      character(len=:), allocatable, intent(out) :: file
      integer :: length
      if (command_argument_count() < 1) then
         file = ''
         return
      end if
      call get_command_argument(1, length=length)
      allocate (character(len=length) :: file)
      call get_command_argument(1, file)
   end subroutine table_file_argument

   !> Stop with a message naming the case (the only failure exit of the program).
   subroutine fail(what, stat, errmsg)
      character(len=*), intent(in) :: what, errmsg
      integer, intent(in) :: stat
      write (error_unit, '(a,i0,a)') 'benchmark_steps: '//what//' failed (stat ', stat, '): '//trim(errmsg)
      error stop 1
   end subroutine fail

   !> Case (a) and the baseline at one mesh size.
   subroutine measure_free_flight(elements, row)
      integer, intent(in) :: elements
      type(table_row), intent(out) :: row
      type(velocity_stepper) :: stepper
      type(measurement) :: pair(2)
      row%elements = elements
      row%unknowns = 2*elements
      call start_tip_case(elements, stepper)
      call measure_interleaved(stepper, [workload_step, workload_baseline], pair, row%ratio)
      row%tip = pair(1)
      row%baseline = pair(2)
      if (row%tip%active_max /= 0) call fail('case (a): a free-flight step had an active contact point', 1, '')
   end subroutine measure_free_flight

   !> Case (b) at one mesh size, in regime 'auto' and (N <= delassus_up_to) in both regimes.
   subroutine measure_contact(elements, row)
      integer, intent(in) :: elements
      type(table_row), intent(inout) :: row
      type(velocity_stepper) :: stepper
      call start_longitudinal_case(elements, 'auto', stepper)
      row%contact_points_b = stepper%contacts%count
      row%longitudinal = measure(stepper, workload_step)
      if (stepper%projector%regime == regime_band) then
         row%regime_b = 'band'
         row%longitudinal_band = row%longitudinal
      else
         row%regime_b = 'delassus'
         row%longitudinal_delassus = row%longitudinal
         call start_longitudinal_case(elements, 'band', stepper)
         row%longitudinal_band = measure(stepper, workload_step)
      end if
      if (elements <= delassus_up_to .and. row%longitudinal_delassus%seconds < 0) then
         call start_longitudinal_case(elements, 'delassus', stepper)
         row%longitudinal_delassus = measure(stepper, workload_step)
      end if
   end subroutine measure_contact

   !> The beam of every case: normalized data, `elements` Hermite elements, no obstacle.
   function base_scene(elements) result(scene)
      integer, intent(in) :: elements
      type(scene_type) :: scene
      scene%beam%length = beam_length
      scene%beam%k2 = 1
      scene%mesh%elements = elements
      scene%mesh%basis = 'hermite'
      scene%time%dt = time_step
      scene%time%t_end = 1
      scene%load%point_position = beam_length   ! the reader's default (no point force here)
      allocate (scene%obstacles(0))
   end function base_scene

   !> Model, contact points and loads of a scene (the chain of the main program).
   subroutine discretize(scene, model, contacts, loads)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(out) :: model
      type(contact_set), intent(out) :: contacts
      type(load_set), intent(out) :: loads
      character(len=512) :: errmsg
      character(len=:), allocatable :: warnings
      integer :: stat
      call validate_scene(scene, stat, errmsg)
      if (stat /= 0) call fail('validate_scene', stat, errmsg)
      call build_model(scene%mesh%basis, scene%mesh%elements, scene%beam%length, scene%beam%rho_s(), scene%beam%ei(), &
         model, stat, errmsg)
      if (stat /= 0) call fail('build_model', stat, errmsg)
      warnings = ''
      call build_contact_points(scene%obstacles, model, contacts, warnings, stat, errmsg)
      if (stat /= 0) call fail('build_contact_points', stat, errmsg)
      if (len(warnings) > 0) write (error_unit, '(a)', advance='no') warnings
      call build_loads(scene%load, model, scene%beam%rho_s(), loads)
   end subroutine discretize

   !> Case (a): free flight in mode 1 above a tip obstacle that is never reached.
   subroutine start_tip_case(elements, stepper)
      integer, intent(in) :: elements
      type(velocity_stepper), intent(out) :: stepper
      type(scene_type) :: scene
      type(beam_model) :: model
      type(contact_set) :: contacts
      type(load_set) :: loads
      real(dp), allocatable :: zero(:)
      character(len=512) :: errmsg
      integer :: stat
      type(stepper_settings) :: settings
      type(dynamic_state) :: start
      scene = base_scene(elements)
      scene%obstacles = [obstacle_type(side='below', x_from=beam_length, x_to=beam_length, &
                                       level_from=-1.0_dp, level_to=-1.0_dp)]
      call discretize(scene, model, contacts, loads)
      if (contacts%count /= 1) call fail('case (a): expected one contact point', contacts%count, '')
      allocate (zero(model%unknowns), source=0.0_dp)
      settings = stepper_settings_of(scene)
      settings%contact%contact_solver = 'auto'
      start = dynamic_state(u=zero, v=mode_field(model, 1, tip_velocity))
      call stepper%init(discrete_system(model, contacts, loads), settings, start, stat, errmsg)
      if (stat /= 0) call fail('case (a): stepper%init', stat, errmsg)
   end subroutine start_tip_case

   !> Case (b): the beam pressed by a uniform load onto an obstacle under its whole length,
   !! starting at rest exactly from its static equilibrium.
   subroutine start_longitudinal_case(elements, regime, stepper)
      integer, intent(in) :: elements
      character(len=*), intent(in) :: regime   !! contact regime: 'auto' | 'delassus' | 'band'
      type(velocity_stepper), intent(out) :: stepper
      type(scene_type) :: scene
      type(beam_model) :: model
      type(contact_set) :: contacts
      type(load_set) :: loads
      real(dp), allocatable :: u0(:), v0(:), reaction(:)
      character(len=512) :: errmsg
      integer :: stat, iterations
      type(stepper_settings) :: settings
      scene = base_scene(elements)
      scene%obstacles = [obstacle_type(side='below', x_from=0.0_dp, x_to=beam_length, &
                                       level_from=0.0_dp, level_to=0.0_dp)]
      scene%load%distributed = pressing_load
      scene%impact%restitution = 0
      scene%solver%contact_solver = regime
      call discretize(scene, model, contacts, loads)
      if (contacts%count /= elements) call fail('case (b): expected a contact point at every node', contacts%count, '')
      allocate (u0(model%unknowns), reaction(contacts%count))
      allocate (v0(model%unknowns), source=0.0_dp)
      call solve_static(model, contacts, loads%at(0.0_dp), u0, reaction, iterations, stat, errmsg)
      if (stat /= 0) call fail('case (b): solve_static', stat, errmsg)
      if (count(reaction > 0) /= contacts%count) &
         call fail('case (b): the static equilibrium does not touch the obstacle at every node', &
                   count(reaction > 0), '')
      settings = stepper_settings_of(scene)
      settings%contact%contact_solver = regime
      call stepper%init(discrete_system(model, contacts, loads), settings, dynamic_state(u=u0, v=v0), stat, errmsg)
      if (stat /= 0) call fail('case (b): stepper%init', stat, errmsg)
   end subroutine start_longitudinal_case

   !> Median time per call of one `workload` (see `measure_interleaved`).
   function measure(stepper, workload) result(timing)
      type(velocity_stepper), intent(inout) :: stepper
      integer, intent(in) :: workload
      type(measurement) :: timing
      type(measurement) :: timings(1)
      call measure_interleaved(stepper, [workload], timings)
      timing = timings(1)
   end function measure

   !> Median time per call of each of `workloads` (a step of `stepper`, or the baseline
   !! on its matrices). For each workload a batch is doubled until it lasts
   !! `min_batch_seconds` (warm-up); then the batches of all workloads are timed in turn,
   !! `repetitions` times, so that a change of load on the machine hits them alike.
   !! `ratio`: median over the repetitions of time(workload 1)/time(workload 2).
   subroutine measure_interleaved(stepper, workloads, timings, ratio)
      type(velocity_stepper), intent(inout) :: stepper
      integer, intent(in) :: workloads(:)
      type(measurement), intent(out) :: timings(:)
      real(dp), intent(out), optional :: ratio
      type(step_tally) :: warm_up, timed(size(workloads))
      real(dp) :: per_call(repetitions, size(workloads)), seconds, cpu_seconds
      real(dp) :: x(size(stepper%u)), y(size(stepper%u))
      integer(int64) :: calls(size(workloads))
      integer :: k, w
      ! the baseline's input: any field of the right size (its values do not matter)
      x = stepper%u + 1
      do w = 1, size(workloads)
         calls(w) = 1
         do
            call timed_batch(stepper, workloads(w), calls(w), x, y, seconds, cpu_seconds, warm_up)
            if (seconds >= min_batch_seconds) exit
            calls(w) = 2*calls(w)
         end do
      end do
      do k = 1, repetitions
         do w = 1, size(workloads)
            call timed_batch(stepper, workloads(w), calls(w), x, y, seconds, cpu_seconds, timed(w))
            per_call(k, w) = seconds/calls(w)
            timings(w)%cpu_fraction = min(timings(w)%cpu_fraction, cpu_seconds/seconds)
         end do
      end do
      do w = 1, size(workloads)
         associate (timing => timings(w), tally => timed(w))
            timing%calls = calls(w)
            timing%seconds = median(per_call(:, w))
            timing%spread = (maxval(per_call(:, w)) - minval(per_call(:, w)))/timing%seconds
            timing%active_min = tally%active_min
            timing%active_max = tally%active_max
            if (tally%steps > 0) then
               timing%iterations_per_step = real(tally%iterations, dp)/tally%steps
               timing%active_mean = real(tally%active, dp)/tally%steps
            end if
         end associate
      end do
      if (present(ratio)) ratio = median(per_call(:, 1)/per_call(:, 2))
   end subroutine measure_interleaved

   !> Run `count` calls of `workload`; their wall and CPU time (s). Steps add what they
   !! did to `tally`; the baseline maps x to y = W^-1 K x, leaving x unchanged.
   subroutine timed_batch(stepper, workload, count, x, y, wall, cpu, tally)
      type(velocity_stepper), intent(inout) :: stepper
      integer, intent(in) :: workload
      integer(int64), intent(in) :: count
      real(dp), intent(in) :: x(:)
      real(dp), intent(inout) :: y(:)
      real(dp), intent(out) :: wall, cpu
      type(step_tally), intent(inout) :: tally
      integer(int64) :: start, finish, rate, i
      real(dp) :: cpu_start, cpu_finish
      character(len=512) :: errmsg
      integer :: stat
      call cpu_time(cpu_start)
      call system_clock(start, rate)
      select case (workload)
      case (workload_step)
         do i = 1, count
            call stepper%step(stat, errmsg)
            if (stat /= 0) call fail('stepper%step', stat, errmsg)
            tally%active_min = min(tally%active_min, stepper%report%active_count)
            tally%active_max = max(tally%active_max, stepper%report%active_count)
            tally%iterations = tally%iterations + stepper%report%iterations
            tally%active = tally%active + stepper%report%active_count
         end do
         tally%steps = tally%steps + count
      case (workload_baseline)
         do i = 1, count
            call band_matvec(stepper%stiffness, x, y)
            call band_solve(stepper%iteration_factor, y)
         end do
      end select
      call system_clock(finish)
      call cpu_time(cpu_finish)
      wall = real(finish - start, dp)/rate
      cpu = cpu_finish - cpu_start
   end subroutine timed_batch


   !> Least-squares slope p of log(t) = p log(N) + c.
   pure function fitted_exponent(elements, seconds) result(p)
      integer, intent(in) :: elements(:)
      real(dp), intent(in) :: seconds(:)
      real(dp) :: p
      real(dp) :: x(size(elements)), y(size(elements))
      x = log(real(elements, dp))
      y = log(seconds)
      x = x - sum(x)/size(x)
      y = y - sum(y)/size(y)
      p = sum(x*y)/sum(x*x)
   end function fitted_exponent

   !> The tables, the exponents and the run's noise indicators on `unit`.
   subroutine write_report(unit)
      integer, intent(in) :: unit
      integer :: i
      logical :: large(size(rows)), small(size(rows))
      write (unit, '(a)') '# vibrobeam benchmark_steps: median wall-clock time per call in microseconds ' // &
         '(system_clock, int64 counts)'
      write (unit, '(a,es8.1,a,i0,a,f4.2,a)') '# Hermite, k2 = 1, L = 1, dt = ', time_step, &
         ' s, theta = gamma = 1/2; median of ', repetitions, ' batches of >= ', min_batch_seconds, ' s each'
      write (unit, '(a)') '# (a) free flight above a tip obstacle never reached; baseline = band_solve(W) + ' // &
         'band_matvec(K), same J'
      write (unit, '(a,i0,a)') '# (b) whole beam pressed onto a longitudinal obstacle, persistent contact, ' // &
         'from the exact static equilibrium; regime auto (Delassus up to ', delassus_limit, ' contact points)'
      write (unit, '(a)') '#'
      write (unit, '(a6,a7,5a12,a10,a16)') 'N', 'J', 't_step_a', 't_baseline', 'a/baseline', 't_step_b', &
         'pivots_b', 'regime_b', 'active_b/points'
      do i = 1, size(rows)
         associate (row => rows(i))
            write (unit, '(i6,i7,2f12.3,f12.2,f12.3,f12.2,a10,i9,a1,i6)') row%elements, row%unknowns, &
               1e6_dp*row%tip%seconds, 1e6_dp*row%baseline%seconds, row%ratio, &
               1e6_dp*row%longitudinal%seconds, row%longitudinal%iterations_per_step, adjustr(row%regime_b), &
               row%longitudinal%active_min, '/', row%contact_points_b
         end associate
      end do
      large = rows%elements >= fit_from
      small = rows%longitudinal_delassus%seconds > 0
      write (unit, '(a)') '#'
      write (unit, '(a,i0,a)') '# (b) in both contact regimes (N <= ', delassus_up_to, &
         ': the regime that auto did not choose is forced)'
      write (unit, '(a6,3a14)') 'N', 't_b_delassus', 't_b_band', 'delassus/band'
      do i = 1, size(rows)
         if (.not. small(i)) cycle
         associate (row => rows(i))
            write (unit, '(i6,2f14.3,f14.2)') row%elements, 1e6_dp*row%longitudinal_delassus%seconds, &
               1e6_dp*row%longitudinal_band%seconds, &
               row%longitudinal_delassus%seconds/row%longitudinal_band%seconds
         end associate
      end do
      write (unit, '(a)') '#'
      write (unit, '(a,i0,a,i0,a)') '# fitted exponent p of t ~ N^p (least squares on log-log): N = ', fit_from, &
         '..', maxval(rows%elements), ', all N'
      call write_fit(unit, '#   (a) tip obstacle, free flight            ', large, rows%tip%seconds)
      call write_fit(unit, '#   (b) persistent contact, band regime      ', large, rows%longitudinal_band%seconds)
      call write_fit(unit, '#   (b) persistent contact, auto regime      ', large, rows%longitudinal%seconds)
      call write_fit(unit, '#   baseline solve + matvec                  ', large, rows%baseline%seconds)
      write (unit, '(a,f6.2,a,f6.2)') '# ratio (a)/baseline (median of the paired ratios of the repetitions): ' // &
         'largest ', maxval(rows%ratio), ', smallest ', minval(rows%ratio)
      write (unit, '(a,i0)') '# most active contact points in a timed step of (a): ', maxval(rows%tip%active_max)
      write (unit, '(a,l1)') '# (b) every node active in every timed step (both regimes): ', &
         all(rows%longitudinal%active_min == rows%contact_points_b) .and. &
         all(rows%longitudinal_band%active_min == rows%contact_points_b) .and. &
         all(pack(rows%longitudinal_delassus%active_min, small) == pack(rows%contact_points_b, small))
      write (unit, '(a,f6.2)') '# (b) most contact pivots per timed step (both regimes): ', &
         maxval([rows%longitudinal%iterations_per_step, rows%longitudinal_band%iterations_per_step, &
                 rows%longitudinal_delassus%iterations_per_step])
      write (unit, '(a)') '#'
      write (unit, '(a,f6.3)') '# noise: largest spread (max - min)/median of the repetitions ', &
         maxval([rows%tip%spread, rows%baseline%spread, rows%longitudinal%spread, rows%longitudinal_band%spread, &
                 rows%longitudinal_delassus%spread])
      write (unit, '(a,f6.3)') '# noise: smallest CPU/wall time ratio of a timed batch ', &
         minval([rows%tip%cpu_fraction, rows%baseline%cpu_fraction, rows%longitudinal%cpu_fraction, &
                 rows%longitudinal_band%cpu_fraction, rows%longitudinal_delassus%cpu_fraction])
   end subroutine write_report

   !> One line of the exponent fits of write_report: `label`, then p of t ~ N^p fitted over
   !! the rows marked `large` (N >= fit_from) and over all rows.
   subroutine write_fit(unit, label, large, seconds)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: label
      logical, intent(in) :: large(:)       !! rows of the large-N fit
      real(dp), intent(in) :: seconds(:)    !! time per step of each row (s)
      write (unit, '(a,2f8.3)') label, fitted_exponent(pack(rows%elements, large), pack(seconds, large)), &
         fitted_exponent(rows%elements, seconds)
   end subroutine write_fit
end program benchmark_steps
