!> Shared checks of the vibrobeam test programs: each check prints one line on failure
!! naming the quantity, its value, the reference and the tolerance; `finish` prints
!! 'NAME: N passed, M failed' and exits non-zero when anything failed, and the largest
!! ratio |value - reference| / allowed difference over the `check_close` calls (how much
!! room each tolerance leaves; the CI prints it for every library it runs on).
module vibrobeam_test_support
   use vibrobeam_kinds, only: dp, int64, error_unit, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_scene_read, only: read_scene
   use vibrobeam_problem, only: run_problem, build_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_blas_threads, only: limit_blas_threads
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_entry, band_factor, band_solve
   use vibrobeam_lapack, only: dpbcon, dpbtrf, dpotrf, dpotrs, dgetrf
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_band_kernel, only: kernel_bandwidth
   use vibrobeam_contact_set, only: contact_set, contact_value, no_bound
   use vibrobeam_lcp, only: solve_lcp
   use vibrobeam_obstacles, only: obstacle_type
   use vibrobeam_schema_visitor, only: unset
   implicit none
   private
   public :: test_counter, read_test_scene, prepare_test_scene, use_program_blas_threads, fitted_order, band_abs_times
   public :: band_condition, abs_factor_times
   public :: dense_lcp_reference, same_bits
   public :: wave_row, lu_determinant, static_deflection, scanned_roots, real_function
   public :: start_test_stepper, advance_test_stepper, angular_momentum, start_planar_twins, hole_levels, start_friction_case
   public :: advance_planar_twins

   type, public :: test_counter
      integer :: passed = 0
      integer :: failed = 0
      real(dp) :: worst_ratio = 0                !! largest |value - reference| / allowed difference
      character(len=120) :: worst_check = ''     !! the check where it occurred
   contains
      procedure :: check_close     !! |value - reference| <= tolerance * max(|reference|, scale)
      procedure :: check_true
      procedure :: finish
   end type test_counter

   abstract interface
      !> A real function of one real (a frequency determinant as a function of b = beta L).
      real(dp) function real_function(x)
         import :: dp
         real(dp), intent(in) :: x
      end function real_function
   end interface

contains

   subroutine check_close(self, name, value, reference, tolerance, scale)
      class(test_counter), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value, reference, tolerance
      real(dp), intent(in), optional :: scale   !! floor of the relative scale (default tiny)
      real(dp) :: size
      size = abs(reference)
      if (present(scale)) size = max(size, scale)
      if (tolerance*size > 0) then
         if (report_every_check()) write (output_unit, '(a,es10.3,a)') 'ratio ', &
            abs(value - reference)/(tolerance*size), ' '//name
         if (abs(value - reference)/(tolerance*size) >= self%worst_ratio) then
            self%worst_ratio = abs(value - reference)/(tolerance*size)
            self%worst_check = name
         end if
      end if
      if (abs(value - reference) <= tolerance*size) then
         self%passed = self%passed + 1
      else
         self%failed = self%failed + 1
         write (error_unit, '(a,es23.15,a,es23.15,a,es10.3,a,es10.3)') 'FAIL '//name//': value ', value, &
            ', reference ', reference, ', relative difference ', abs(value - reference)/max(size, tiny(size)), &
            ', tolerance ', tolerance
      end if
   end subroutine check_close

   !> VIBROBEAM_CHECK_RATIOS set: print the ratio of every check (for margin studies).
   logical function report_every_check()
      integer :: length
      call get_environment_variable('VIBROBEAM_CHECK_RATIOS', length=length)
      report_every_check = length > 0
   end function report_every_check

   subroutine check_true(self, name, condition, detail)
      class(test_counter), intent(inout) :: self
      character(len=*), intent(in) :: name
      logical, intent(in) :: condition
      character(len=*), intent(in), optional :: detail
      if (condition) then
         self%passed = self%passed + 1
      else
         self%failed = self%failed + 1
         if (present(detail)) then
            write (error_unit, '(a)') 'FAIL '//name//': '//detail
         else
            write (error_unit, '(a)') 'FAIL '//name
         end if
      end if
   end subroutine check_true

   subroutine finish(self, program_name)
      class(test_counter), intent(in) :: self
      character(len=*), intent(in) :: program_name
      if (len_trim(self%worst_check) > 0) write (output_unit, '(a,es10.3,a)') program_name// &
         ': largest |value - reference| / tolerance ', self%worst_ratio, ' ('//trim(self%worst_check)//')'
      write (output_unit, '(a,i0,a,i0,a)') program_name//': ', self%passed, ' passed, ', self%failed, ' failed'
      if (self%failed > 0) error stop 1
   end subroutine finish

   !> Least-squares slope of log(error) against log(1/N) over the points marked `use`: the
   !! observed order of convergence in h = L/N (0 when fewer than 2 points are used).
   pure function fitted_order(elements, error, use) result(slope)
      integer, intent(in) :: elements(:)     !! N of each point
      real(dp), intent(in) :: error(:)       !! error of each point (> 0 where used)
      logical, intent(in) :: use(:)
      real(dp) :: slope
      real(dp) :: x(size(error)), y(size(error))
      integer :: m
      x = log(1.0_dp/elements)
      y = log(max(min(error, 1.0_dp), tiny(1.0_dp)))
      m = count(use)
      slope = 0
      if (m >= 2) slope = (m*sum(x*y, use) - sum(x, use)*sum(y, use))/(m*sum(x*x, use) - sum(x, use)**2)
   end function fitted_order

   !> The scene of a verification namelist file; stops the test if it is not valid.
   function read_test_scene(path) result(scene)
      character(len=*), intent(in) :: path
      type(scene_type) :: scene
      integer :: stat
      character(len=512) :: errmsg
      call read_scene(path, scene, stat, errmsg)
      if (stat == 0) call validate_scene(scene, stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'FAIL reading '//path//': '//trim(errmsg)
         error stop 1
      end if
   end function read_test_scene

   !> prepare_scene, stopping the test on failure; the BLAS thread policy of the program
   !! (`limit_blas_threads`) applies to every driver that steps a scene.
   subroutine prepare_test_scene(scene, prepared)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(out) :: prepared
      character(len=:), allocatable :: warnings
      integer :: stat
      character(len=512) :: errmsg
      call use_program_blas_threads()
      warnings = ''
      call build_problem(scene, prepared, warnings, stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'FAIL preparing the scene: '//trim(errmsg)
         error stop 1
      end if
   end subroutine prepare_test_scene

   !> The program's BLAS thread policy (`limit_blas_threads`: one thread unless
   !! VIBROBEAM_BLAS_THREADS says otherwise), for every test that calls BLAS or LAPACK:
   !! OpenBLAS's own threads on the tests' small matrices spin against each other on a
   !! loaded machine (test_lcp: 11 s instead of 0.6 s alone, 310 s in the fast suite).
   subroutine use_program_blas_threads()
      character(len=:), allocatable :: warning
      call limit_blas_threads(warning)
      if (len(warning) > 0) write (error_unit, '(a)') 'warning: '//warning
   end subroutine use_program_blas_threads

   !> |A| |v| for a symmetric band matrix in lower band storage (the scale of A v's rounding).
   pure function band_abs_times(a, v) result(y)
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: v(:)
      real(dp) :: y(size(v))
      integer :: i, j
      y = 0
      do j = 1, a%n
         y(j) = y(j) + abs(a%lower(1, j))*abs(v(j))
         do i = j + 1, min(a%n, j + a%kd)
            y(i) = y(i) + abs(a%lower(1 + i - j, j))*abs(v(j))
            y(j) = y(j) + abs(a%lower(1 + i - j, j))*abs(v(i))
         end do
      end do
   end function band_abs_times

   !> LAPACK dpbcon's estimate of the 1-norm condition number of the SPD band matrix a.
   !! dpbcon needs LAPACK's Cholesky factor, so a is factored here by dpbtrf (the kd = 3
   !! kernel of `band_factor` stores L D L^T instead).
   function band_condition(a) result(condition)
      type(symmetric_band), intent(in) :: a
      real(dp) :: condition
      real(dp) :: rcond, work(3*a%n), ones(a%n), cholesky(a%kd + 1, a%n)
      integer :: iwork(a%n), info
      ones = 1
      cholesky = a%lower
      call dpbtrf('L', a%n, a%kd, cholesky, a%kd + 1, info)
      if (info /= 0) then
         condition = huge(1.0_dp)
         return
      end if
      call dpbcon('L', a%n, a%kd, cholesky, a%kd + 1, maxval(band_abs_times(a, ones)), rcond, work, iwork, info)
      condition = 1/max(rcond, tiny(1.0_dp))
   end function band_condition

   !> |L| |D| |L^T| |x| for a band factorization as `band_factor` leaves it: for kd = 3 the
   !! kernel's L D L^T (column j holds 1/d_j, then the unit-lower entries below the
   !! diagonal), otherwise dpbtrf's Cholesky factor R (D = I, L = R). Both forms give the
   !! same matrix, since |R| |R^T| = |L| D |L^T| for R = L D^(1/2): the componentwise
   !! backward error bound of the factorization and solve (Higham, Thm 9.3 and 10.3).
   pure function abs_factor_times(chol, x) result(y)
      type(band_cholesky), intent(in) :: chol
      real(dp), intent(in) :: x(:)
      real(dp) :: y(size(x)), z(size(x))
      integer :: i, j
      logical :: ldl
      ldl = chol%kd == kernel_bandwidth
      z = 0   ! D |L^T| |x|: z_j = d_j sum_{i >= j} |L_ij| |x_i|
      do j = 1, chol%n
         if (ldl) then
            z(j) = abs(x(j))
            do i = j + 1, min(chol%n, j + chol%kd)
               z(j) = z(j) + abs(chol%factor(1 + i - j, j)*x(i))
            end do
            z(j) = z(j)/abs(chol%factor(1, j))
         else
            do i = j, min(chol%n, j + chol%kd)
               z(j) = z(j) + abs(chol%factor(1 + i - j, j)*x(i))
            end do
         end if
      end do
      y = 0   ! |L| z
      do j = 1, chol%n
         if (ldl) then
            y(j) = y(j) + z(j)
         else
            y(j) = y(j) + abs(chol%factor(1, j))*z(j)
         end if
         do i = j + 1, min(chol%n, j + chol%kd)
            y(i) = y(i) + abs(chol%factor(1 + i - j, j))*z(j)
         end do
      end do
   end function abs_factor_times

   !> A reference projection for one-sided bounds (s_k = +1: H_k x >= lower_k, -1:
   !! H_k x <= upper_k), independent of the contact solver: the dense LCP of the explicitly
   !! formed Delassus matrix A = S H W^-1 H^T S, q = S (H x_free - bound), solved by
   !! `solve_lcp` (block principal pivoting, tested against enumeration); P = S z,
   !! x = x_free + W^-1 H^T P. W^-1 H^T by dense Cholesky (dpotrf/dpotrs) for J <= 600, by
   !! band solves beyond. With `load` instead of `x_free`, x_free = W^-1 load by the same
   !! factor. stat /= 0 (with errmsg) when solve_lcp fails.
   subroutine dense_lcp_reference(w, contacts, s, x_ref, p_ref, stat, errmsg, x_free, load)
      type(symmetric_band), intent(in) :: w
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: s(:)
      real(dp), intent(out) :: x_ref(:), p_ref(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), intent(in), optional :: x_free(:), load(:)
      real(dp), allocatable :: columns(:, :), dense(:, :), a(:, :), q(:), z(:), wz(:)
      type(band_cholesky) :: factor
      integer :: m, n, c, l, i, j, info, iterations
      m = contacts%count
      n = w%n
      allocate (columns(n, m + 1), a(m, m), q(m), z(m), wz(m))
      columns = 0
      do c = 1, m
         do l = 1, 4
            if (contacts%dofs(l, c) /= 0) columns(contacts%dofs(l, c), c) = contacts%weights(l, c)
         end do
      end do
      if (present(load)) then
         columns(:, m + 1) = load
      else
         columns(:, m + 1) = 0
      end if
      if (n <= 600) then
         allocate (dense(n, n))
         do j = 1, n
            do i = 1, n
               dense(i, j) = band_entry(w, i, j)
            end do
         end do
         call dpotrf('L', n, dense, n, info)
         call dpotrs('L', n, m + 1, dense, n, columns, n, info)
      else
         call band_factor(w, factor, stat, errmsg)
         do c = 1, m + 1
            call band_solve(factor, columns(:, c))
         end do
      end if
      if (present(x_free)) columns(:, m + 1) = x_free
      do l = 1, m
         do c = 1, m
            a(c, l) = s(c)*s(l)*contact_value(contacts, c, columns(:, l))
         end do
         q(l) = s(l)*(contact_value(contacts, l, columns(:, m + 1)) - merge(contacts%lower(l), contacts%upper(l), s(l) > 0))
      end do
      a = 0.5_dp*(a + transpose(a))
      call solve_lcp(a, q, z, wz, iterations, stat, errmsg)
      p_ref = s*z
      x_ref = columns(:, m + 1) + matmul(columns(:, 1:m), p_ref)
   end subroutine dense_lcp_reference

   !> a and b are the same double, bit for bit (a NaN equals itself; +0 and -0 differ).
   elemental logical function same_bits(a, b)
      real(dp), intent(in) :: a, b
      same_bits = transfer(a, 0_int64) == transfer(b, 0_int64)
   end function same_bits

   !> The order-th derivatives (0..3) of cosh(z), sinh(z), cos(z), sin(z) with respect to
   !! z: a row of the frequency determinants of the beam tests, where z = beta x and each
   !! derivative in x carries one more beta (docs/theory.md §7).
   pure function wave_row(z, order) result(row)
      real(dp), intent(in) :: z
      integer, intent(in) :: order
      real(dp) :: row(4)
      select case (order)
      case (0)
         row = [cosh(z), sinh(z), cos(z), sin(z)]
      case (1)
         row = [sinh(z), cosh(z), -sin(z), cos(z)]
      case (2)
         row = [cosh(z), sinh(z), -cos(z), -sin(z)]
      case default
         row = [sinh(z), cosh(z), sin(z), -cos(z)]
      end select
   end function wave_row

   !> The determinant of a square matrix from its LU factors (LAPACK dgetrf): the product
   !! of U's diagonal, its sign turned by each row exchange (0 for a singular one).
   real(dp) function lu_determinant(a) result(determinant)
      real(dp), intent(in) :: a(:,:)
      real(dp) :: lu(size(a, 1), size(a, 2))
      integer :: pivots(size(a, 1)), info, i
      lu = a
      call dgetrf(size(a, 1), size(a, 1), lu, size(a, 1), pivots, info)
      determinant = 1
      do i = 1, size(a, 1)
         determinant = determinant*lu(i, i)
         if (pivots(i) /= i) determinant = -determinant
      end do
   end function lu_determinant

   !> The static deflection at the nodes of a scene of kind 'static' (its whole path:
   !! `build_problem`, `solve_static` under the loads at t = 0), the solver's report and
   !! (optional) the reactions of its contact points.
   subroutine static_deflection(scene, w, report, stat, errmsg, reaction)
      type(scene_type), intent(in) :: scene
      real(dp), allocatable, intent(out) :: w(:)
      type(static_report), intent(out) :: report
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable, intent(out), optional :: reaction(:)
      type(run_problem) :: prepared
      real(dp), allocatable :: u(:), reactions(:)
      integer :: iterations
      call prepare_test_scene(scene, prepared)
      allocate (u(prepared%model%unknowns), reactions(prepared%contacts%count))
      call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u, reactions, iterations, stat, &
                        errmsg, report=report)
      w = nodal_displacement(prepared%model, u)
      if (present(reaction)) call move_alloc(reactions, reaction)
   end subroutine static_deflection

   !> The first `count` roots of f above `from`: the sign changes on a scan of step `step`,
   !! each bisected to 4 eps relative; error stop when fewer lie below `limit`.
   function scanned_roots(f, count, from, step, limit) result(roots)
      procedure(real_function) :: f
      integer, intent(in) :: count
      real(dp), intent(in) :: from, step, limit
      real(dp) :: roots(count)
      real(dp) :: low, high, middle, f_low
      integer :: found
      found = 0
      low = from
      f_low = f(low)
      do while (low < limit)
         high = low + step
         if ((f(high) > 0) .neqv. (f_low > 0)) then
            do while (high - low > 4*epsilon(1.0_dp)*high)
               middle = 0.5_dp*(low + high)
               if ((f(middle) > 0) .eqv. (f_low > 0)) then
                  low = middle
               else
                  high = middle
               end if
            end do
            found = found + 1
            roots(found) = 0.5_dp*(low + high)
            if (found == count) return
         end if
         low = high
         f_low = f(low)
      end do
      error stop 'scanned_roots: fewer roots than asked below the limit'
   end function scanned_roots

   !> The stepper of a prepared scene (`new_stepper`), stopping the test on failure.
   subroutine start_test_stepper(scene, prepared, stepper)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      class(time_stepper), allocatable, intent(out) :: stepper
      integer :: stat
      character(len=512) :: errmsg
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'FAIL starting the stepper: '//trim(errmsg)
         error stop 1
      end if
   end subroutine start_test_stepper

   !> A beam of two planes (`two_planes`) and its planar twins, started: `reference` the same
   !! scene with planes = 1, no directions and the obstacles `planar_obstacles` (levels),
   !! `perturbed` that twin with its initial velocity's amplitude one ulp larger (how far
   !! rounding carries on the trajectory: the derived tolerance of the planar reductions,
   !! test_circle_holes and test_compliant_faces), `stepper` the two-plane scene itself;
   !! j its unknowns per plane.
   subroutine start_planar_twins(two_planes, planar_obstacles, stepper, reference, perturbed, j)
      type(scene_type), intent(in) :: two_planes
      type(obstacle_type), intent(in) :: planar_obstacles(:)
      class(time_stepper), allocatable, intent(out) :: stepper, reference, perturbed
      integer, intent(out) :: j
      type(scene_type) :: planar, nudged
      type(run_problem) :: prepared_planar, prepared_nudged, prepared
      planar = two_planes
      planar%beam%planes = 1
      planar%initial%direction = unset
      planar%initial%displacement_direction = unset
      planar%load%direction = unset
      planar%obstacles = planar_obstacles
      nudged = planar
      nudged%initial%velocity_amplitude = nearest(planar%initial%velocity_amplitude, 1.0_dp)
      call prepare_test_scene(planar, prepared_planar)
      call prepare_test_scene(nudged, prepared_nudged)
      call prepare_test_scene(two_planes, prepared)
      call start_test_stepper(planar, prepared_planar, reference)
      call start_test_stepper(nudged, prepared_nudged, perturbed)
      call start_test_stepper(two_planes, prepared, stepper)
      j = prepared%model%unknowns
   end subroutine start_planar_twins

   !> One step of a beam of two planes and its planar twins (`start_planar_twins`), with the
   !! largest values so far: `deviation` of the two-plane U and V from the twin's times
   !! `shares` (y from shares(1), z from shares(2) times the twin's y), `own` the twin one
   !! ulp faster's from the twin, `scale` the twin's largest |U|, |V|.
   subroutine advance_planar_twins(stepper, reference, perturbed, shares, deviation, own, scale)
      class(time_stepper), intent(inout) :: stepper, reference, perturbed
      real(dp), intent(in) :: shares(2)
      real(dp), intent(inout) :: deviation, own, scale
      integer :: j
      j = size(stepper%u)/2
      call advance_test_stepper(reference)
      call advance_test_stepper(perturbed)
      call advance_test_stepper(stepper)
      deviation = max(deviation, maxval(abs(stepper%u(1:j) - shares(1)*reference%u)), &
                      maxval(abs(stepper%v(1:j) - shares(1)*reference%v)), &
                      maxval(abs(stepper%u(j + 1:) - shares(2)*reference%u)), &
                      maxval(abs(stepper%v(j + 1:) - shares(2)*reference%v)))
      own = max(own, maxval(abs(perturbed%u - reference%u)), maxval(abs(perturbed%v - reference%v)))
      scale = max(scale, maxval(abs(reference%u)), maxval(abs(reference%v)))
   end subroutine advance_planar_twins

   !> The planar twin's obstacles of a hole `o` (a circle or a square of orientation 0):
   !! levels at -R (below) and +R (above) over the same x with the same stiffness.
   function hole_levels(o) result(levels)
      type(obstacle_type), intent(in) :: o
      type(obstacle_type) :: levels(2)
      levels = [obstacle_type(side='below', x_from=o%x_from, x_to=o%x_to, level_from=-o%radius, level_to=-o%radius, &
                              stiffness=o%stiffness), &
                obstacle_type(side='above', x_from=o%x_from, x_to=o%x_to, level_from=o%radius, level_to=o%radius, &
                              stiffness=o%stiffness)]
   end function hole_levels

   !> A tube's tip pressed on a compliant wall (obstacle 1, stiffness k, friction mu) by
   !! `&load point_force` F_n and pulled along it by `&forces` load 1, started just below
   !! (case 1) or above (case 2) the friction angle's closed form: at rest the wall carries
   !! `normal` f = F_n k/(k + k_b) (k_b = `tip_stiffness` 3 E I/L^3, the cantilever's, exact
   !! on Hermite elements), so tan a* = mu f/F_n; `angle` = a* (1 -+ 1e-3), `pull` F_t =
   !! F_n tan(angle), set as the load's amplitude (test_compliant_friction, test_compliant_faces).
   subroutine start_friction_case(scene, case, stepper, tip_stiffness, normal, angle, pull)
      type(scene_type), intent(inout) :: scene
      integer, intent(in) :: case
      class(time_stepper), allocatable, intent(out) :: stepper
      real(dp), intent(out) :: tip_stiffness, normal, angle, pull
      type(run_problem) :: prepared
      associate (b => scene%beam, k => scene%obstacles(1)%stiffness)
         tip_stiffness = 3*b%youngs_modulus*b%inertia/b%length**3
         normal = scene%load%point_force*k/(k + tip_stiffness)
      end associate
      angle = atan(scene%obstacles(1)%friction*normal/scene%load%point_force)*merge(1 - 1e-3_dp, 1 + 1e-3_dp, case == 1)
      pull = scene%load%point_force*tan(angle)
      scene%forces%load(1)%amplitude = pull
      call prepare_test_scene(scene, prepared)
      call start_test_stepper(scene, prepared, stepper)
   end subroutine start_friction_case

   !> One step, stopping the test on failure.
   subroutine advance_test_stepper(stepper)
      class(time_stepper), intent(inout) :: stepper
      integer :: stat
      character(len=512) :: errmsg
      call stepper%step(stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'FAIL stepping: '//trim(errmsg)
         error stop 1
      end if
   end subroutine advance_test_stepper

   !> U_y^T M V_z - U_z^T M V_y of a beam of two planes (its state stacked y then z): the
   !! discrete angular momentum about the beam's axis (docs/theory.md section 11).
   function angular_momentum(stepper) result(moment)
      class(time_stepper), intent(in) :: stepper
      real(dp) :: moment, mv(size(stepper%v))
      integer :: j
      j = size(stepper%u)/2
      call stepper%mass_into(stepper%v, mv)
      moment = dot_product(stepper%u(1:j), mv(j + 1:)) - dot_product(stepper%u(j + 1:), mv(1:j))
   end function angular_momentum
end module vibrobeam_test_support
