!> Benchmark of the band kernel and of the natural modes (KERNEL_REPORT.md beside this
!! file; studies/benchmark/benchmark_kernel.sh runs every part under both BLAS libraries).
!!
!!   benchmark_kernel kernel                      wall-clock table, J = 40 ... 1e5
!!   benchmark_kernel count WORKLOAD J CALLS      CALLS calls of one workload, for
!!                                                callgrind and memcheck (lapack | kernel |
!!                                                fused | step)
!!   benchmark_kernel modes METHOD BASIS N COUNT  one compute_modes (lanczos | dense), timed
!!   benchmark_kernel crossover                   dense against Lanczos for J and count
!!   benchmark_kernel planes                      the two-plane layouts against a planar step
!!
!! Workloads, on the Hermite model of N = J/2 elements (k2 = 1, L = 1 m), W = M + (theta
!! dt)^2 K with theta = 1/2, dt = 1e-4 s, and a fixed vector x:
!! - lapack: y = K x by BLAS dsbmv, then y <- W^-1 y by LAPACK dpbtrs (W factored by
!!   dpbtrf): the "LAPACK floor" of a step of the velocity scheme (theory §3);
!! - kernel: the same through band_matvec and band_solve (the kd = 3 kernels);
!! - fused: y = W^-1 (b - K x) by band_residual_solve, the product inside the solve's
!!   forward loop (one more subtraction than the two above);
!! - step: one step of the velocity stepper in free flight (mode-1 velocity, tip 0.1 m/s,
!!   a stop 1 m below the tip that is never reached), set up as the main program does;
!! - the solve and the product alone, each way;
!! - stacked: the 'lapack' workload for two bending planes stored as a J x 2 array
!!   (docs/method.md, "Two bending planes and tube-support contact"): dsbmv on each plane,
!!   then one dpbtrs with two right-hand sides, the factor shared;
!! - interleaved: the same with (y_j, z_j) side by side, one band of order 2J and
!!   half-width 7 (dsbmv and dpbtrs with kd = 7), the layout the design rejects;
!! - stacked fused: the 'fused' workload on each of the two stacked planes (the kd = 3
!!   kernel the velocity stepper uses, which has no counterpart of half-width 7).
!! Timing: each workload runs in batches of at least `min_batch_seconds` (sized once), the
!! batches of all workloads in turn, `repetitions` times; medians of the time per call, the
!! spread (max - min)/median and the smallest CPU/wall ratio say how noisy a row was.
!! Ratios are medians of the paired per-repetition ratios.
program benchmark_kernel
   use vibrobeam_kinds, only: dp, int64, output_unit, error_unit
   use vibrobeam_sorting, only: median
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_combination, band_factor, band_solve, &
                             band_matvec, band_residual_solve
   use vibrobeam_lapack, only: dpbtrf, dpbtrs, dsbmv
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_scene, only: scene_type, obstacle_type
   use vibrobeam_schema_visitor, only: unset
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_problem, only: run_problem, build_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   implicit none

   integer, parameter :: sizes(*) = [40, 200, 400, 2000, 10000, 100000]   !! J
   integer, parameter :: repetitions = 7
   real(dp), parameter :: min_batch_seconds = 0.05_dp
   real(dp), parameter :: time_step = 1e-4_dp, theta = 0.5_dp
   integer, parameter :: workload_lapack = 1, workload_kernel = 2, workload_fused = 3, workload_step = 4, &
                         workload_dpbtrs = 5, workload_solve = 6, workload_dsbmv = 7, workload_matvec = 8, &
                         workload_stacked = 9, workload_interleaved = 10, workload_stacked_fused = 11, &
                         workload_step_two = 12, workload_step_two_own = 13, workload_pressed = 14, &
                         workload_pressed_level = 15, workload_pressed_circle = 16
   character(len=*), parameter :: workload_names(16) = [character(len=14) :: 'dpbtrs+dsbmv', 'solve+matvec', &
                                                        'fused', 'step', 'dpbtrs', 'solve (kd=3)', 'dsbmv', &
                                                        'matvec (kd=3)', 'stacked', 'interleaved', 'stacked fused', &
                                                        'step 2 planes', 'step 2, own Kz', 'pressed', &
                                                        'pressed 2, lvl', 'pressed 2 hole']

   !> Everything a workload works on.
   type :: bench_case
      type(beam_model) :: model
      type(symmetric_band) :: iteration_matrix          !! W
      type(band_cholesky) :: kernel_factor              !! band_factor(W)
      real(dp), allocatable :: lapack_factor(:,:)       !! dpbtrf(W)
      real(dp), allocatable :: x(:), y(:), b(:)
      !> two planes: stacked (J x 2) and interleaved (2J; its K and the dpbtrf factor of
      !! its W, half-width 7, lower storage)
      real(dp), allocatable :: x2(:,:), y2(:,:), xi(:), yi(:), stiffness_i(:,:), factor_i(:,:)
      class(time_stepper), allocatable :: stepper
      !> the free flight of two planes (&beam planes = 2, velocity at 45 degrees: both
      !! planes move), sharing W, and with a z stiffness of its own (inertia_z = 2 inertia)
      class(time_stepper), allocatable :: stepper_two, stepper_two_own
      !> in contact at every step: the tip pressed by a constant force onto a stop at its rest
      !! position, planar, two planes on a level, two planes on a circle's wall
      class(time_stepper), allocatable :: pressed, pressed_level, pressed_circle
   end type bench_case

   character(len=32) :: command
   call get_command_argument(1, command)
   select case (command)
   case ('kernel')
      call kernel_table()
   case ('count')
      call count_calls()
   case ('modes')
      call time_modes()
   case ('crossover')
      call crossover_table()
   case ('planes')
      call planes_table()
   case default
      write (error_unit, '(a)') 'usage: benchmark_kernel kernel | count WORKLOAD J CALLS | '// &
         'modes METHOD BASIS N COUNT | crossover | planes'
      error stop 2
   end select

contains

   subroutine fail(what, stat, errmsg)
      character(len=*), intent(in) :: what, errmsg
      integer, intent(in) :: stat
      write (error_unit, '(a,i0,a)') 'benchmark_kernel: '//what//' failed (stat ', stat, '): '//trim(errmsg)
      error stop 1
   end subroutine fail

   integer function integer_argument(position) result(value)
      integer, intent(in) :: position
      character(len=64) :: text
      integer :: ios
      call get_command_argument(position, text)
      read (text, *, iostat=ios) value
      if (ios /= 0) call fail('reading argument '//trim(text), ios, 'not an integer')
   end function integer_argument

   !> The case of J unknowns (Hermite, N = J/2).
   subroutine set_up(unknowns, case)
      integer, intent(in) :: unknowns
      type(bench_case), intent(out) :: case
      type(scene_type) :: scene
      type(run_problem) :: prepared
      character(len=:), allocatable :: warnings
      character(len=512) :: errmsg
      integer :: stat, i
      scene%mesh%elements = unknowns/2
      scene%load%point_position = scene%beam%length   ! the reader's default (no point force here)
      scene%time%dt = time_step
      scene%time%theta = theta
      scene%obstacles = [obstacle_type(side='below', x_from=1.0_dp, x_to=1.0_dp, level_from=-1.0_dp, &
                                       level_to=-1.0_dp)]
      scene%initial%velocity = 'mode'
      scene%initial%velocity_mode = 1
      scene%initial%velocity_amplitude = 0.1_dp
      call validate_scene(scene, stat, errmsg)
      if (stat /= 0) call fail('validate_scene', stat, errmsg)
      warnings = ''
      call build_problem(scene, prepared, warnings, stat, errmsg)
      if (stat /= 0) call fail('prepare_scene', stat, errmsg)
      call new_stepper(scene, prepared, case%stepper, stat, errmsg)
      if (stat /= 0) call fail('start_time_stepper', stat, errmsg)
      case%model = prepared%model
      ! two planes, no obstacle (not taken yet with planes = 2); the beam by its four data
      ! with k2 = EI/(rho S) = 1, as above
      scene%obstacles = [obstacle_type ::]
      scene%beam%youngs_modulus = 1
      scene%beam%density = 1
      scene%beam%area = 1
      scene%beam%inertia = 1
      scene%beam%planes = 2
      scene%initial%direction = 45
      call two_plane_stepper(scene, case%stepper_two)
      scene%beam%inertia_z = 2
      call two_plane_stepper(scene, case%stepper_two_own)
      ! in contact: a stop at the tip's rest position, the tip pressed onto it by 1 N
      scene%beam%inertia_z = unset
      scene%initial%velocity = 'zero'
      scene%initial%direction = unset
      scene%load%point_force = -1
      scene%obstacles = [obstacle_type(side='below', x_from=1.0_dp, x_to=1.0_dp, level_from=0.0_dp, level_to=0.0_dp)]
      call two_plane_stepper(scene, case%pressed_level)
      scene%obstacles = [obstacle_type(shape='circle', x_from=1.0_dp, x_to=1.0_dp, radius=1.0_dp, center_y=1.0_dp)]
      call two_plane_stepper(scene, case%pressed_circle)
      scene%obstacles = [obstacle_type(side='below', x_from=1.0_dp, x_to=1.0_dp, level_from=0.0_dp, level_to=0.0_dp)]
      scene%beam%planes = 1
      call two_plane_stepper(scene, case%pressed)
      case%iteration_matrix = band_combination(1.0_dp, case%model%mass, (theta*time_step)**2, case%model%stiffness)
      call band_factor(case%iteration_matrix, case%kernel_factor, stat, errmsg)
      if (stat /= 0) call fail('band_factor', stat, errmsg)
      case%lapack_factor = case%iteration_matrix%lower
      call dpbtrf('L', unknowns, 3, case%lapack_factor, 4, stat)
      if (stat /= 0) call fail('dpbtrf', stat, '')
      case%x = [(sin(0.01_dp*i), i=1, unknowns)]
      case%b = [(cos(0.02_dp*i), i=1, unknowns)]
      allocate (case%y(unknowns))
      case%x2 = reshape([case%x, case%b], [unknowns, 2])
      allocate (case%y2(unknowns, 2), case%yi(2*unknowns))
      case%xi = reshape(transpose(case%x2), [2*unknowns])
      case%stiffness_i = interleaved(case%model%stiffness%lower)
      case%factor_i = interleaved(case%iteration_matrix%lower)
      call dpbtrf('L', 2*unknowns, 7, case%factor_i, 8, stat)
      if (stat /= 0) call fail('dpbtrf (interleaved)', stat, '')
   end subroutine set_up

   !> The velocity stepper of a scene of two planes (validated and built as the program does).
   subroutine two_plane_stepper(scene, stepper)
      type(scene_type), intent(in) :: scene
      class(time_stepper), allocatable, intent(out) :: stepper
      type(run_problem) :: prepared
      character(len=:), allocatable :: warnings
      character(len=512) :: errmsg
      integer :: stat
      call validate_scene(scene, stat, errmsg)
      if (stat /= 0) call fail('validate_scene (two planes)', stat, errmsg)
      warnings = ''
      call build_problem(scene, prepared, warnings, stat, errmsg)
      if (stat /= 0) call fail('prepare_scene (two planes)', stat, errmsg)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) call fail('start_time_stepper (two planes)', stat, errmsg)
   end subroutine two_plane_stepper

   !> The band (lower storage, half-width 3) of one plane as the band of two planes
   !! interleaved, (y_j, z_j) side by side with the same matrix in both: entry (i, k) goes
   !! to (2i-1, 2k-1) and (2i, 2k), half-width 7.
   pure function interleaved(lower) result(both)
      real(dp), intent(in) :: lower(:,:)   !! (4, J)
      real(dp) :: both(8, 2*size(lower, 2))
      integer :: d
      both = 0
      do d = 0, 3
         both(2*d + 1, 1::2) = lower(d + 1, :)
         both(2*d + 1, 2::2) = lower(d + 1, :)
      end do
   end function interleaved

   !> `calls` calls of one workload.
   subroutine run(case, workload, calls)
      type(bench_case), intent(inout) :: case
      integer, intent(in) :: workload
      integer(int64), intent(in) :: calls
      integer(int64) :: c
      integer :: n, info, stat
      character(len=256) :: errmsg
      n = case%model%unknowns
      do c = 1, calls
         select case (workload)
         case (workload_lapack)
            call dsbmv('L', n, 3, 1.0_dp, case%model%stiffness%lower, 4, case%x, 1, 0.0_dp, case%y, 1)
            call dpbtrs('L', n, 3, 1, case%lapack_factor, 4, case%y, n, info)
         case (workload_kernel)
            call band_matvec(case%model%stiffness, case%x, case%y)
            call band_solve(case%kernel_factor, case%y)
         case (workload_fused)
            call band_residual_solve(case%kernel_factor, case%model%stiffness, case%x, case%b, case%y)
         case (workload_step)
            call case%stepper%step(stat, errmsg)
            if (stat /= 0) call fail('step', stat, errmsg)
            if (case%stepper%report%active_count /= 0) call fail('free flight', 1, 'a contact point became active')
         case (workload_dpbtrs)
            case%y = case%x
            call dpbtrs('L', n, 3, 1, case%lapack_factor, 4, case%y, n, info)
         case (workload_solve)
            case%y = case%x
            call band_solve(case%kernel_factor, case%y)
         case (workload_dsbmv)
            call dsbmv('L', n, 3, 1.0_dp, case%model%stiffness%lower, 4, case%x, 1, 0.0_dp, case%y, 1)
         case (workload_matvec)
            call band_matvec(case%model%stiffness, case%x, case%y)
         case (workload_stacked)
            call dsbmv('L', n, 3, 1.0_dp, case%model%stiffness%lower, 4, case%x2(:, 1), 1, 0.0_dp, case%y2(:, 1), 1)
            call dsbmv('L', n, 3, 1.0_dp, case%model%stiffness%lower, 4, case%x2(:, 2), 1, 0.0_dp, case%y2(:, 2), 1)
            call dpbtrs('L', n, 3, 2, case%lapack_factor, 4, case%y2, n, info)
         case (workload_interleaved)
            call dsbmv('L', 2*n, 7, 1.0_dp, case%stiffness_i, 8, case%xi, 1, 0.0_dp, case%yi, 1)
            call dpbtrs('L', 2*n, 7, 1, case%factor_i, 8, case%yi, 2*n, info)
         case (workload_step_two)
            call case%stepper_two%step(stat, errmsg)
            if (stat /= 0) call fail('step (two planes)', stat, errmsg)
         case (workload_step_two_own)
            call case%stepper_two_own%step(stat, errmsg)
            if (stat /= 0) call fail('step (two planes, own K_z)', stat, errmsg)
         case (workload_pressed)
            call pressed_step(case%pressed)
         case (workload_pressed_level)
            call pressed_step(case%pressed_level)
         case (workload_pressed_circle)
            call pressed_step(case%pressed_circle)
         case (workload_stacked_fused)
            call band_residual_solve(case%kernel_factor, case%model%stiffness, case%x2(:, 1), case%b, case%y2(:, 1))
            call band_residual_solve(case%kernel_factor, case%model%stiffness, case%x2(:, 2), case%b, case%y2(:, 2))
         end select
      end do
   end subroutine run

   !> One step of a stepper pressed onto its stop (which must hold the tip in every step).
   subroutine pressed_step(stepper)
      class(time_stepper), intent(inout) :: stepper
      integer :: stat
      character(len=256) :: errmsg
      call stepper%step(stat, errmsg)
      if (stat /= 0) call fail('step (pressed)', stat, errmsg)
      if (stepper%report%active_count + stepper%report%circle_count /= 1) &
         call fail('pressed', 1, 'the tip is not held in every step')
   end subroutine pressed_step

   !> Wall and CPU seconds of `calls` calls.
   subroutine timed(case, workload, calls, wall, cpu)
      type(bench_case), intent(inout) :: case
      integer, intent(in) :: workload
      integer(int64), intent(in) :: calls
      real(dp), intent(out) :: wall, cpu
      integer(int64) :: start, finish, rate
      real(dp) :: cpu_start, cpu_finish
      call cpu_time(cpu_start)
      call system_clock(start, rate)
      call run(case, workload, calls)
      call system_clock(finish)
      call cpu_time(cpu_finish)
      wall = real(finish - start, dp)/rate
      cpu = cpu_finish - cpu_start
   end subroutine timed


   !> Each workload's batch sized once to at least `min_batch_seconds`, then the batches of
   !! all workloads in turn, `repetitions` times: the time per call of each (s) and the
   !! smallest CPU/wall ratio of a batch.
   subroutine batches(case, workloads, per_call, cpu_fraction)
      type(bench_case), intent(inout) :: case
      integer, intent(in) :: workloads(:)
      real(dp), intent(out) :: per_call(:,:)   !! (repetitions, workloads)
      real(dp), intent(out) :: cpu_fraction
      integer(int64) :: calls(size(workloads))
      real(dp) :: wall, cpu
      integer :: w, k
      do w = 1, size(workloads)
         calls(w) = 1
         do
            call timed(case, workloads(w), calls(w), wall, cpu)
            if (wall >= min_batch_seconds) exit
            calls(w) = 2*calls(w)
         end do
      end do
      cpu_fraction = 1
      do k = 1, repetitions
         do w = 1, size(workloads)
            call timed(case, workloads(w), calls(w), wall, cpu)
            per_call(k, w) = wall/calls(w)
            cpu_fraction = min(cpu_fraction, cpu/wall)
         end do
      end do
   end subroutine batches

   !> The wall-clock table: per J, each workload's median time per call, its spread, the
   !! ratios kernel/LAPACK and step/LAPACK.
   subroutine kernel_table()
      integer, parameter :: workloads(*) = [workload_lapack, workload_kernel, workload_fused, workload_step, &
                                            workload_dpbtrs, workload_solve, workload_dsbmv, workload_matvec]
      type(bench_case) :: case
      real(dp) :: per_call(repetitions, size(workloads)), cpu_fraction
      integer :: s, w
      write (output_unit, '(a)') '# time per call (microseconds): median of 7 interleaved batches of >= 0.05 s; '// &
         'spread = (max - min)/median'
      write (output_unit, '(a)') '# ratios to dpbtrs+dsbmv of solve+matvec, fused and step: medians of the paired '// &
         'ratios; cpu/wall = smallest CPU/wall ratio of a batch'
      write (output_unit, '(a8,8a24,3a14,a10)') 'J', (trim(workload_names(w))//' (spread)', w=1, size(workloads)), &
         'ratio kernel', 'ratio fused', 'ratio step', 'cpu/wall'
      do s = 1, size(sizes)
         call set_up(sizes(s), case)
         call batches(case, workloads, per_call, cpu_fraction)
         write (output_unit, '(i8,8(f14.3,a2,f5.2,a3),3f14.3,f10.2)') sizes(s), &
            (1e6_dp*median(per_call(:, w)), ' (', (maxval(per_call(:, w)) - minval(per_call(:, w)))/ &
             median(per_call(:, w)), ') ', w=1, size(workloads)), &
            (median(per_call(:, w)/per_call(:, 1)), w=2, 4), cpu_fraction
         flush (output_unit)
      end do
   end subroutine kernel_table

   !> The two-plane table (docs/method.md, "Two bending planes and tube-support contact"):
   !! per J, the medians of the planar LAPACK floor (dpbtrs+dsbmv), of its stacked and
   !! interleaved two-plane versions, of the planar fused kd = 3 kernel and its stacked
   !! version, of a planar free-flight step and of the velocity stepper's two-plane
   !! free-flight steps (sharing W, and with K_z of its own) (microseconds); then, as
   !! medians of the paired per-repetition ratios (all measured in one run):
   !! stacked/planar and interleaved/planar with LAPACK, stacked/planar with the fused
   !! kernel, the estimated cost of a two-plane step relative to the planar step had the
   !! layout been interleaved, (step - fused + interleaved)/step (LAPACK at half-width 7,
   !! there being no kd = 7 kernel), the measured two-plane steps over the planar step
   !! (issue 21's bound: 2.5), in free flight and in contact (the tip pressed onto a stop
   !! in every step: two planes on a level and in a circle's wall, against the planar beam
   !! on the same level).
   subroutine planes_table()
      integer, parameter :: workloads(*) = [workload_lapack, workload_stacked, workload_interleaved, &
                                            workload_fused, workload_stacked_fused, workload_step, &
                                            workload_step_two, workload_step_two_own, workload_pressed, &
                                            workload_pressed_level, workload_pressed_circle]
      type(bench_case) :: case
      real(dp) :: per_call(repetitions, size(workloads)), cpu_fraction
      integer :: s, w
      write (output_unit, '(a)') '# time per call (microseconds): median of 7 interleaved batches of >= 0.05 s; '// &
         'ratios: medians of the paired ratios'
      write (output_unit, '(a8,11a15,8a15,a10)') 'J', (trim(workload_names(workloads(w))), w=1, size(workloads)), &
         'stacked/floor', 'interl./floor', 'st.fused/fused', 'step interl.', '2 planes/step', 'own Kz/step', &
         'pressed lvl/1', 'pressed hole/1', 'cpu/wall'
      do s = 1, size(sizes)
         call set_up(sizes(s), case)
         call batches(case, workloads, per_call, cpu_fraction)
         associate (floor => per_call(:, 1), stacked => per_call(:, 2), interleaved => per_call(:, 3), &
                    fused => per_call(:, 4), stacked_fused => per_call(:, 5), step => per_call(:, 6), &
                    step_two => per_call(:, 7), step_own => per_call(:, 8), pressed => per_call(:, 9), &
                    pressed_level => per_call(:, 10), pressed_circle => per_call(:, 11))
            write (output_unit, '(i8,11f15.3,8f15.3,f10.2)') sizes(s), (1e6_dp*median(per_call(:, w)), w=1, 11), &
               median(stacked/floor), median(interleaved/floor), median(stacked_fused/fused), &
               median((step - fused + interleaved)/step), median(step_two/step), median(step_own/step), &
               median(pressed_level/pressed), median(pressed_circle/pressed), cpu_fraction
         end associate
         flush (output_unit)
      end do
   end subroutine planes_table

   !> benchmark_kernel count WORKLOAD J CALLS
   subroutine count_calls()
      type(bench_case) :: case
      character(len=16) :: name
      integer :: workload
      call get_command_argument(2, name)
      select case (name)
      case ('lapack')
         workload = workload_lapack
      case ('kernel')
         workload = workload_kernel
      case ('fused')
         workload = workload_fused
      case ('step')
         workload = workload_step
      case default
         call fail('count: workload '''//trim(name)//'''', 2, 'expected lapack | kernel | fused | step')
      end select
      call set_up(integer_argument(3), case)
      call run(case, workload, int(integer_argument(4), int64))
   end subroutine count_calls

   !> benchmark_kernel modes METHOD BASIS N COUNT: one compute_modes, wall seconds printed.
   subroutine time_modes()
      type(beam_model) :: model
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      character(len=16) :: method, basis
      integer(int64) :: start, finish, rate
      integer :: stat
      character(len=512) :: errmsg
      call get_command_argument(2, method)
      call get_command_argument(3, basis)
      call build_model(trim(basis), integer_argument(4), 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      if (stat /= 0) call fail('build_model', stat, errmsg)
      call system_clock(start, rate)
      call compute_modes(model, integer_argument(5), omega, shapes, vectors, stat, errmsg, trim(method))
      call system_clock(finish)
      if (stat /= 0) call fail('compute_modes', stat, errmsg)
      write (output_unit, '(a,f10.4,a,es22.15)') 'compute_modes seconds ', real(finish - start, dp)/rate, &
         ' omega_1 ', omega(1)
   end subroutine time_modes

   !> Smallest of 3 wall times of compute_modes, dense and Lanczos, for J = 8 ... 1024
   !! (Hermite) and 1, 6, J/8, J/4, J/2 modes.
   subroutine crossover_table()
      integer, parameter :: elements(*) = [4, 8, 16, 32, 64, 128, 256, 512]
      type(beam_model) :: model
      integer :: e, c, counts(5), stat
      real(dp) :: dense(5), lanczos(5)
      character(len=256) :: errmsg
      write (output_unit, '(a)') '# compute_modes wall seconds (smallest of 3), Hermite, J = 2N; '// &
         '"-" where Lanczos does not apply (count = J)'
      write (output_unit, '(a6,a8,5a10,5a10)') 'J', 'path', 'count', '', '', '', '', 'seconds', '', '', '', ''
      do e = 1, size(elements)
         call build_model('hermite', elements(e), 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
         counts = [1, 6, max(1, model%unknowns/8), max(1, model%unknowns/4), max(1, model%unknowns/2)]
         do c = 1, size(counts)
            dense(c) = fastest(model, counts(c), 'dense')
            lanczos(c) = -1
            if (counts(c) < model%unknowns) lanczos(c) = fastest(model, counts(c), 'lanczos')
         end do
         write (output_unit, '(i6,a8,5i10,5es10.2)') model%unknowns, 'dense', counts, dense
         write (output_unit, '(i6,a8,5i10,5es10.2)') model%unknowns, 'lanczos', counts, lanczos
      end do
   end subroutine crossover_table

   real(dp) function fastest(model, count, method)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: count
      character(len=*), intent(in) :: method
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      integer(int64) :: start, finish, rate, calls, c
      integer :: attempt, stat
      character(len=256) :: errmsg
      ! batches of at least 0.02 s for the small cases
      calls = 1
      do
         call system_clock(start, rate)
         do c = 1, calls
            call compute_modes(model, count, omega, shapes, vectors, stat, errmsg, method)
            if (stat /= 0) call fail('compute_modes '//method, stat, errmsg)
         end do
         call system_clock(finish)
         if (real(finish - start, dp)/rate >= 0.02_dp) exit
         calls = 2*calls
      end do
      fastest = real(finish - start, dp)/rate/calls
      do attempt = 1, 2
         call system_clock(start, rate)
         do c = 1, calls
            call compute_modes(model, count, omega, shapes, vectors, stat, errmsg, method)
         end do
         call system_clock(finish)
         fastest = min(fastest, real(finish - start, dp)/rate/calls)
      end do
   end function fastest
end program benchmark_kernel
