!> Benchmark of the contact projection (issue 10), a study, not a test: it asserts
!! nothing and is not run by ctest; studies/benchmark/benchmark_contact.sh builds it in Release,
!! runs it and writes benchmark_contact.txt beside this file (studies/benchmark/
!! REPORT.md discusses the results).
!!
!! A. The slap (verification/stress/slap_plastic.nml, slap_bouncing.nml: a beam dropped
!!    flat onto a floor under its whole length, e = 0 and 0.5, 500 steps of 1e-4 s) for
!!    N = 500 ... 16000 with the 'newton' method: median wall time per step of the whole
!!    run over `repetitions` runs, the same per band-solve baseline (one `band_solve`
!!    with W's factor plus one `band_matvec` with K, of the same order, timed between
!!    the runs) and their ratio, the old method on the same scene (at most 2000 pivots per
!!    projection), the largest number of linear solves in one step, the
!!    steps that ran the interior-point method, the fall-backs; the exponent p of
!!    t ~ N^p (least squares on log-log) of the time per step and of the ratio.
!! B. Every stress scene of verification/stress at N = 200, 2000 and 8000 with the old
!!    method ('pivoting') and the new one ('newton') in the same run: status (the old one
!!    may fail: the step and the message), wall time, steps with impulses, largest and
!!    total linear solves, the largest one-step energy change beyond the work of the loads
!!    (dE - F.dU, evaluated in the difference form Vbar^T M dV + Ubar^T K dU) and the
!!    largest consistency residual |W (V^{n+1} - V_f) - H^T P| / (|W| |V^{n+1}|), V_f the
!!    free velocity recomputed from the step's impulses.
!! C. Statics: the tip lift-off (liftoff_tip_static.nml) for N = 10^3, 10^4, 10^5 and the
!!    mid-span lift-off (liftoff_static.nml) for N = 10^3, 10^4, with both methods
!!    (pivoting limited to 2000 pivots): the contact projection in the metric K, the statics
!!    of vibrobeam before issue 23 (`band_static_solve`; the program now solves statics in
!!    curvatures, studies/static_cost).
!! D. The regime threshold: the 'newton' method in the 'delassus' and the 'band' regime
!!    on the press and the bouncing slap, N = 4 ... 128 (contact points = N), median time
!!    per step.
!!
!! Usage: benchmark_contact STRESS_DIRECTORY [TABLE_FILE] ['quick' | 'slap' | 'regimes' | 'static']
!! ('slap', 'static', 'regimes': part A, C or D alone)
program benchmark_contact
   use vibrobeam_kinds, only: dp, int64, output_unit, error_unit
   use vibrobeam_sorting, only: median
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_band, only: band_matvec, band_solve
   use vibrobeam_band_statics, only: band_static_solve
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene
   implicit none

   integer, allocatable :: slap_sizes(:), stress_sizes(:), static_sizes(:), regime_sizes(:)
   integer :: repetitions = 3
   character(len=*), parameter :: stress_scenes(*) = [character(len=16) :: 'slap_plastic', 'slap_bouncing', 'press', &
                                                     'liftoff_dynamic', 'chattering', 'profiled_floor']

   !> What one run of a scene did.
   type :: run_record
      logical :: failed = .false.
      integer :: steps_done = 0, steps = 0
      character(len=200) :: failure = ''
      real(dp) :: seconds = 0
      integer :: impulse_steps = 0, largest_solves = 0, total_solves = 0, interior_steps = 0, largest_interior = 0
      integer :: fallbacks = 0, largest_iterations = 0
      real(dp) :: largest_rise = 0, largest_energy = 0, largest_residual = 0
   end type run_record

   character(len=512) :: directory, table_file, mode
   integer :: unit, ios

   call get_command_argument(1, directory)
   call get_command_argument(2, table_file)
   call get_command_argument(3, mode)
   static_sizes = [1000, 10000, 100000]
   if (mode == 'regimes') then   ! part D alone
      regime_sizes = [4, 8, 12, 16, 24, 32, 48, 64, 128]
      repetitions = 5
   else if (mode == 'quick') then   ! a smoke run of every part, a few seconds
      slap_sizes = [250, 500]
      stress_sizes = [100]
      static_sizes = [1000]
      regime_sizes = [8, 16]
      repetitions = 1
   else
      slap_sizes = [500, 1000, 2000, 4000, 8000, 16000]
      stress_sizes = [200, 2000, 8000]
      static_sizes = [1000, 10000, 100000]
      regime_sizes = [4, 8, 12, 16, 24, 32, 48, 64, 128]
   end if
   if (len_trim(directory) == 0) then
      write (error_unit, '(a)') 'usage: benchmark_contact STRESS_DIRECTORY [TABLE_FILE]'
      error stop 1
   end if
   unit = output_unit
   if (len_trim(table_file) > 0) then
      open (newunit=unit, file=trim(table_file), status='replace', action='write', iostat=ios)
      if (ios /= 0) error stop 'benchmark_contact: cannot write the table file'
   end if
   select case (mode)
   case ('regimes')
      call part_regimes(unit)
   case ('static')
      call part_static(unit)
   case ('slap')
      call part_slap(unit)
   case default
      call part_slap(unit)
      call part_stress(unit)
      call part_static(unit)
      call part_regimes(unit)
   end select
   if (unit /= output_unit) close (unit)

contains

   !> The scene `name` of the stress directory with N elements, method and regime set.
   function stress_scene(name, elements, method, regime) result(scene)
      character(len=*), intent(in) :: name, method, regime
      integer, intent(in) :: elements
      type(scene_type) :: scene
      scene = read_test_scene(trim(directory)//'/'//trim(name)//'.nml')
      scene%mesh%elements = elements
      scene%solver%contact_method = method
      scene%solver%contact_solver = regime
      ! the old method's default limit, max(100, 10 m) pivots, lets one failing step run for
      ! hours at N = 16000: 2000 pivots per projection at most
      if (method == 'pivoting') scene%solver%contact_max_iterations = 2000
   end function stress_scene

   !> Run a scene, timing the steps only; with `measure`, also the energy change and the
   !! consistency residual of every step (not timed).
   subroutine run_scene(scene, measure, record)
      type(scene_type), intent(in) :: scene
      logical, intent(in) :: measure
      type(run_record), intent(out) :: record
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      real(dp), allocatable :: u_old(:), v_old(:), f_old(:), f_bar(:), work(:), hp(:), v_f(:)
      real(dp) :: de, norm
      integer(int64) :: start, finish, rate, elapsed
      integer :: n, stat, m, k, a, c
      character(len=512) :: errmsg
      call prepare_test_scene(scene, prepared)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) error stop 'start_time_stepper failed'
      record%steps = nint(scene%time%t_end/scene%time%dt)
      elapsed = 0
      do n = 1, record%steps
         if (measure) then
            u_old = stepper%u
            v_old = stepper%v
            f_old = stepper%loads%at(stepper%t)
         end if
         call system_clock(start, rate)
         call stepper%step(stat, errmsg)
         call system_clock(finish)
         elapsed = elapsed + (finish - start)
         if (stat /= 0) then
            record%failed = .true.
            write (record%failure, '(a,i0,a)') 'step ', n, ': '//trim(errmsg)
            exit
         end if
         record%steps_done = n
         m = stepper%report%active_count
         if (count(abs(stepper%report%impulse(1:m)) > 0) > 0) record%impulse_steps = record%impulse_steps + 1
         record%largest_solves = max(record%largest_solves, stepper%report%linear_solves)
         record%total_solves = record%total_solves + stepper%report%linear_solves
         record%largest_iterations = max(record%largest_iterations, stepper%report%iterations)
         if (stepper%projector%interior_iterations > 0) record%interior_steps = record%interior_steps + 1
         record%largest_interior = max(record%largest_interior, stepper%projector%interior_iterations)
         if (stepper%report%used_fallback) record%fallbacks = record%fallbacks + 1
         if (measure) then
            f_bar = 0.5_dp*(f_old + stepper%loads%at(stepper%t))
            allocate (work(size(u_old)))
            call band_matvec(stepper%mass, stepper%v - v_old, work)
            de = 0.5_dp*dot_product(stepper%v + v_old, work)
            call band_matvec(stepper%stiffness, stepper%u - u_old, work)
            de = de + 0.5_dp*dot_product(stepper%u + u_old, work) - dot_product(f_bar, stepper%u - u_old)
            record%largest_rise = max(record%largest_rise, de)
            record%largest_energy = max(record%largest_energy, stepper%kinetic_energy() + stepper%elastic_energy())
            ! consistency of the projection: W (V^{n+1} - V_f) = H^T P, V_f recomputed as
            ! V^n + W^-1 dt (Fbar - K (U^n + dt/2 V^n)) (theta = 1/2, no damping)
            call band_matvec(stepper%stiffness, u_old + 0.5_dp*stepper%dt*v_old, work)
            v_f = stepper%dt*(stepper%theta*stepper%loads%at(stepper%t) + (1 - stepper%theta)*f_old - work)
            call band_solve(stepper%iteration_factor, v_f)
            v_f = v_old + v_f
            hp = 0*v_f
            do k = 1, m
               c = stepper%report%active(k)
               do a = 1, 4
                  if (stepper%contacts%dofs(a, c) /= 0) hp(stepper%contacts%dofs(a, c)) = &
                     hp(stepper%contacts%dofs(a, c)) + stepper%contacts%weights(a, c)*stepper%report%impulse(k)
               end do
            end do
            call band_matvec(stepper%iteration_matrix, stepper%v - v_f, work)
            norm = maxval(abs(stepper%iteration_matrix%lower))*maxval(abs(stepper%v))*(2*stepper%iteration_matrix%kd + 1)
            record%largest_residual = max(record%largest_residual, maxval(abs(work - hp))/max(norm, tiny(1.0_dp)))
            deallocate (work)
         end if
      end do
      record%seconds = real(elapsed, dp)/rate
   end subroutine run_scene


   !> Least-squares slope of log(y) against log(x).
   real(dp) function slope(x, y)
      real(dp), intent(in) :: x(:), y(:)
      real(dp) :: lx(size(x)), ly(size(y))
      integer :: n
      n = size(x)
      lx = log(x)
      ly = log(y)
      slope = (n*sum(lx*ly) - sum(lx)*sum(ly))/(n*sum(lx*lx) - sum(lx)**2)
   end function slope

   !> Seconds per call of the baseline (one band solve with W's factor and one band
   !! product with K) for the scene's matrices, median of 5 batches of >= 0.05 s.
   real(dp) function baseline_seconds(scene)
      type(scene_type), intent(in) :: scene
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      real(dp), allocatable :: x(:), y(:)
      real(dp) :: batches(5)
      integer(int64) :: calls
      integer :: stat, b
      character(len=512) :: errmsg
      call prepare_test_scene(scene, prepared)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      x = stepper%v + 1
      allocate (y(size(x)))
      calls = 1
      do while (baseline_batch(stepper, x, y, calls) < 0.05_dp)   ! calibration, also the warm-up
         calls = 2*calls
      end do
      do b = 1, size(batches)
         batches(b) = baseline_batch(stepper, x, y, calls)/calls
      end do
      baseline_seconds = median(batches)
   end function baseline_seconds

   !> Seconds taken by `count` calls of the baseline on the stepper's matrices.
   real(dp) function baseline_batch(stepper, x, y, count)
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(inout) :: x(:), y(:)
      integer(int64), intent(in) :: count
      integer(int64) :: start, finish, rate, i
      call system_clock(start, rate)
      do i = 1, count
         call band_solve(stepper%iteration_factor, x)
         call band_matvec(stepper%stiffness, x, y)
         x = y*1e-12_dp + 1
      end do
      call system_clock(finish)
      baseline_batch = real(finish - start, dp)/rate
   end function baseline_batch

   subroutine part_slap(unit)
      integer, intent(in) :: unit
      character(len=*), parameter :: scenes(2) = [character(len=16) :: 'slap_plastic', 'slap_bouncing']
      type(run_record) :: record, old
      real(dp) :: per_step(repetitions), base(repetitions), t_step(size(slap_sizes)), ratio(size(slap_sizes)), &
                  spread
      ! (repetitions is fixed before these are sized)
      integer :: s, i, r, largest(size(slap_sizes))
      write (unit, '(a)') '# A. slap: median wall time per step over the whole run (500 steps), repetitions = 3'
      do s = 1, size(scenes)
         write (unit, '(a)') '# scene '//trim(scenes(s))
         write (unit, '(a)') '#     N      J   t_step_us  t_base_us  step/base  spread  max_solves  total_solves' // &
            '  interior_steps  max_interior  fallbacks  | pivoting: status, t_step_us, max_solves'
         do i = 1, size(slap_sizes)
            do r = 1, repetitions
               call run_scene(stress_scene(scenes(s), slap_sizes(i), 'newton', 'auto'), .false., record)
               per_step(r) = record%seconds/max(record%steps_done, 1)
               base(r) = baseline_seconds(stress_scene(scenes(s), slap_sizes(i), 'newton', 'auto'))
            end do
            t_step(i) = median(per_step)
            ratio(i) = median(per_step/base)
            spread = (maxval(per_step) - minval(per_step))/t_step(i)
            largest(i) = record%largest_solves
            call run_scene(stress_scene(scenes(s), slap_sizes(i), 'pivoting', 'auto'), .false., old)
            write (unit, '(i7,i7,f12.1,f11.2,f11.1,f8.2,i12,i14,i16,i14,i11,a,a,f11.1,i6)') slap_sizes(i), 2*slap_sizes(i), &
               1e6*t_step(i), 1e6*median(base), ratio(i), spread, record%largest_solves, record%total_solves, &
               record%interior_steps, record%largest_interior, record%fallbacks, '  | ', &
               merge('failed ', 'ok     ', old%failed), 1e6*old%seconds/max(old%steps_done, 1), old%largest_solves
            if (old%failed) write (unit, '(a)') '#        pivoting failed at '//trim(old%failure)
            flush (unit)
            write (error_unit, '(a,i0,a)') 'benchmark_contact: slap '//trim(scenes(s))//', N = ', slap_sizes(i), ' done'
         end do
         write (unit, '(a,i0,a,i0,a,f6.3,a,f6.3)') '# fitted exponent of t_step ~ N^p over N = ', slap_sizes(1), &
            ' ... ', slap_sizes(size(slap_sizes)), ': p = ', slope(real(slap_sizes, dp), t_step), &
            '; of step/base: ', slope(real(slap_sizes, dp), ratio)
         write (unit, '(a,20i4)') '# largest linear solves in one step, by N: ', largest
      end do
   end subroutine part_slap

   subroutine part_stress(unit)
      integer, intent(in) :: unit
      type(run_record) :: record
      integer :: s, i, method
      character(len=8), parameter :: methods(2) = [character(len=8) :: 'pivoting', 'newton']
      write (unit, '(a)') '#'
      write (unit, '(a)') '# B. stress scenes, old (pivoting) and new (newton) method side by side, regime auto'
      write (unit, '(a)') '# scene              N  method    status  steps_done  wall_s  impulse_steps  max_solves' // &
         '  total_solves  interior_steps  fallbacks  max(dE-F.dU)/E_max  max_consistency'
      do s = 1, size(stress_scenes)
         do i = 1, size(stress_sizes)
            do method = 1, 2
               call run_scene(stress_scene(stress_scenes(s), stress_sizes(i), methods(method), 'auto'), .true., record)
               write (unit, '(a18,i6,2x,a8,2x,a6,i12,f8.2,i15,i12,i14,i16,i11,es20.2,es17.2)') stress_scenes(s), &
                  stress_sizes(i), methods(method), merge('failed', 'ok    ', record%failed), record%steps_done, &
                  record%seconds, record%impulse_steps, record%largest_solves, record%total_solves, &
                  record%interior_steps, record%fallbacks, record%largest_rise/max(record%largest_energy, tiny(1.0_dp)), &
                  record%largest_residual
               if (record%failed) write (unit, '(a)') '#   '//trim(record%failure)
               flush (unit)
               write (error_unit, '(a,i0,a)') 'benchmark_contact: '//trim(stress_scenes(s))//', N = ', stress_sizes(i), &
                  ', '//trim(methods(method))//' done'
            end do
         end do
      end do
   end subroutine part_stress

   subroutine part_static(unit)
      integer, intent(in) :: unit
      type(scene_type) :: scene
      type(run_problem) :: prepared
      real(dp), allocatable :: u(:), reaction(:)
      integer(int64) :: start, finish, rate
      integer :: i, k, method, stat, iterations
      real(dp) :: lifted, continuum, deflection_error, largest
      character(len=512) :: errmsg
      character(len=8), parameter :: methods(2) = [character(len=8) :: 'pivoting', 'newton']
      character(len=*), parameter :: static_scenes(2) = [character(len=20) :: 'liftoff_tip_static', 'liftoff_static']
      write (unit, '(a)') '#'
      write (unit, '(a)') '# C. static lift-off at the tip and at mid-span, regime band; pivoting limited to 2000 pivots'
      write (unit, '(a)') '#   lifted_length: h x (nodes with w > 0 and R = 0) (+ h at mid-span: both touchdown nodes'// &
         ' are held), against the continuum 2F/|q| (tip), 3F/(2|q|) (mid-span, 2b);'
      write (unit, '(a)') '#   deflection_error: w(L) / ((2/3) F^4/(|q|^3 EI)) - 1 (tip), w(L/2) / (|q| b^4/(72 EI)) - 1,'// &
         ' b = 3F/(4|q|) (mid-span); the exact discrete difference is (h/a)^3/sqrt(3) when a/h is an integer'
      write (unit, '(a)') '#   (9.0e-3, 9.0e-6, 9.0e-9 at N = 1e3, 1e4, 1e5; mid-span ~ (sqrt(3)/2)(h/b)^3:'// &
         ' 7.6e-8, 7.6e-11), verification/stress/test_liftoff_closed_form.f90;'
      write (unit, '(a)') '#   max_R_lifted: largest reaction on a node with w > 0 (|q| h = 1/N)'
      write (unit, '(a)') '# scene                    N  method    status  wall_s  iterations  points_in_contact' // &
         '  sum_of_reactions  lifted_length  continuum  deflection_error  max_R_lifted'
      do k = 1, size(static_scenes)
      do i = 1, size(static_sizes)
         if (k == 2 .and. static_sizes(i) > 10000) cycle   ! ill-conditioned beyond (docs/method.md)
         do method = 1, 2
            scene = read_test_scene(trim(directory)//'/'//trim(static_scenes(k))//'.nml')
            scene%mesh%elements = static_sizes(i)
            call prepare_test_scene(scene, prepared)
            allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count))
            call system_clock(start, rate)
            call band_static_solve(prepared, 'band', methods(method), 2000, u, reaction, iterations, stat, errmsg)
            call system_clock(finish)
            call liftoff_measures(scene, prepared, u, reaction, k == 1, lifted, continuum, deflection_error, largest)
            write (unit, '(a20,i9,2x,a8,2x,a6,f8.2,i12,i19,es18.8,f15.6,f11.6,es18.3,es14.2)') static_scenes(k), &
               static_sizes(i), methods(method), merge('ok    ', 'failed', stat == 0), real(finish - start, dp)/rate, &
               iterations, count(abs(reaction) > 0), sum(reaction), lifted, continuum, deflection_error, largest
            if (stat /= 0) write (unit, '(a)') '#   '//trim(errmsg)
            flush (unit)
            deallocate (u, reaction)
         end do
      end do
      end do
   end subroutine part_static

   !> Lifted length and its continuum value, deflection error against the continuum closed
   !! form, largest reaction on a lifted node (Hermite: w_i = u(2i - 1), contact point i at
   !! node i) of the tip (`tip`) or mid-span lift-off.
   subroutine liftoff_measures(scene, prepared, u, reaction, tip, lifted, continuum, deflection_error, largest)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: u(:), reaction(:)
      logical, intent(in) :: tip
      real(dp), intent(out) :: lifted, continuum, deflection_error, largest
      real(dp) :: q, f, ei, h, b
      integer :: n
      n = scene%mesh%elements
      q = -scene%load%distributed
      f = scene%load%point_force
      ei = prepared%model%ei
      h = prepared%model%length/n
      lifted = h*count(u(1:2*n:2) > 0 .and. .not. abs(reaction) > 0)
      largest = maxval([reaction, 0.0_dp], mask=[u(1:2*n:2) > 0, .true.])
      if (tip) then
         continuum = 2*f/q
         deflection_error = u(2*n - 1)/(2*f**4/(3*q**3*ei)) - 1
      else
         b = 3*f/(4*q)
         lifted = lifted + h
         continuum = 2*b
         deflection_error = u(n - 1)/(q*b**4/(72*ei)) - 1
      end if
   end subroutine liftoff_measures

   subroutine part_regimes(unit)
      integer, intent(in) :: unit
      type(run_record) :: record
      real(dp) :: delassus(repetitions), band(repetitions)
      integer :: i, r, s, solves(2)
      character(len=*), parameter :: scenes(2) = [character(len=16) :: 'press', 'slap_bouncing']
      write (unit, '(a)') '#'
      write (unit, '(a)') '# D. regime threshold, newton method: press (every point lands and stays held) and the'
      write (unit, '(a)') '#    bouncing slap, contact points = N; median time per step over the whole run'
      write (unit, '(a)') '# scene              N  t_delassus_us  t_band_us  delassus/band  max_solves(delassus, band)'
      do s = 1, size(scenes)
         do i = 1, size(regime_sizes)
            do r = 1, repetitions
               call run_scene(stress_scene(scenes(s), regime_sizes(i), 'newton', 'delassus'), .false., record)
               delassus(r) = record%seconds/record%steps_done
               solves(1) = record%largest_solves
               call run_scene(stress_scene(scenes(s), regime_sizes(i), 'newton', 'band'), .false., record)
               band(r) = record%seconds/record%steps_done
               solves(2) = record%largest_solves
            end do
            write (unit, '(a16,i5,f15.2,f11.2,f15.2,2i8)') scenes(s), regime_sizes(i), 1e6*median(delassus), &
               1e6*median(band), median(delassus/band), solves
            flush (unit)
         end do
      end do
   end subroutine part_regimes
end program benchmark_contact
