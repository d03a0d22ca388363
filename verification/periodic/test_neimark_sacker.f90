!> A Neimark-Sacker point located on a continued branch against an independent reference
!! (issue 20, acceptance "Bifurcations"; docs/method.md, "Continuation of periodic orbits",
!! "A Neimark-Sacker point: the tube in cross-flow"). The scene: a tube forced off
!! resonance, its tip between compliant stops the forced orbit never reaches, continued in
!! the flow velocity U of &flow (`continue_branch`). Without contact each step is the
!! linear recurrence of the velocity scheme with the fluid-elastic force taken at V^n,
!! F_f = -E(U) V^n (docs/theory.md §10), so the orbit's multipliers are lambda_k^P, lambda_k
!! the eigenvalues of the one-step amplification matrix A(U) (`amplification_matrix` with
!! E(U) from the dense modes and Connors' formula, `fluid_elastic_damping`: no stepper, no
!! period map). The pair of mode 1 leaves the unit circle where the spectral radius of
!! A(U) reaches 1: the reference U_NS, by bisection on U. Checked:
!! - one bifurcation on the branch, a Neimark-Sacker point (kind 3), located, at U_NS
!!   within the tolerance derived beside the check;
!! - the points before it stable, those after it unstable, none touching the stops, and
!!   each point's largest |mu| equal to the reference's rho(A(U))^P to its round-off bound;
!! - U_NS against the closed form of the scheme's damping map: mode n's 2 x 2 recurrence
!!   has det = |lambda|^2 = 1 exactly where c_n + e_n = (1 - 2 theta) dt omega_n^2 (c_n = a +
!!   b omega_n^2 its Rayleigh rate, e_n = -2 zeta_f,n omega_n the flow's), that is zeta_f,1
!!   = zeta_1 + (theta - 1/2) omega_1 dt: Connors' velocity of the mesh's mode 1 when theta
!!   = 1/2. It prints the continuous beam's Connors velocity (the exact cantilever
!!   frequency) and its difference from U_NS (the discretization's).
!! Usage: test_neimark_sacker SCENE.nml [DAMPING_FACTOR]: the factor (default 1) scales the
!! reference's Rayleigh damping; 1.001 must make the test fail (a ctest with WILL_FAIL).
program test_neimark_sacker
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_lapack, only: dsygv
   use vibrobeam_periodic_settings, only: period_step
   use vibrobeam_periodic_reference, only: amplification_matrix, eigenvalues_with_conditions, fluid_elastic_damping, &
      energy_gram, cancellation, continue_test_branch
   use vibrobeam_continuation, only: continuation_branch
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   integer, parameter :: neimark_sacker = 3     !! the kind of a Neimark-Sacker bifurcation
   !> locate's stopping rules (vibrobeam_continuation): the bracket below 1e-4 of the
   !! step, the test function (|mu|^2 - 1) within 1e-10 of 0, lambda moving by less than
   !! 1e-9 (relative) between two trials
   real(dp), parameter :: locate_bracket = 1e-4_dp, locate_tolerance = 1e-10_dp, locate_lambda = 1e-9_dp
   !> the first root of 1 + cos(b) cosh(b) = 0 (the clamped-free beam's mode 1)
   real(dp), parameter :: beta_1 = 1.8751040687119611_dp
   real(dp), parameter :: pi = acos(-1.0_dp)
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(continuation_branch) :: branch
   character(len=512) :: path, argument
   real(dp), allocatable :: mass(:, :), stiffness(:, :), damping(:, :), gram(:, :)
   real(dp) :: factor, dt, theta, omega1, zeta1, u_ns, u_closed, u_continuous, f_exact, omega_exact, slope, h
   real(dp) :: multiplier_error, reference_error, tolerance, bracket_width, u_located, error, bound, worst, zeta_needed
   integer :: n, found, k, index, steps, status

   call get_command_argument(1, path)
   factor = 1
   if (command_argument_count() >= 2) then
      call get_command_argument(2, argument)
      read (argument, *, iostat=status) factor
      if (status /= 0) error stop 'test_neimark_sacker: DAMPING_FACTOR is not a number'
   end if
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   n = prepared%system%model%unknowns
   mass = band_to_dense(prepared%system%model%mass)
   stiffness = band_to_dense(prepared%system%model%stiffness)
   damping = factor*(scene%beam%rayleigh_mass*mass + scene%beam%rayleigh_stiffness*stiffness)
   steps = scene%periodic%steps_per_period*scene%periodic%period_multiple
   dt = period_step(scene%load%point_frequency, scene%periodic%steps_per_period)
   theta = scene%time%theta
   gram = energy_gram(prepared, scene%load%point_frequency)

   ! ---- the reference: rho(A(U)) = 1, by bisection on U ----
   call t%check_true('the reference is stable at the start', radius(scene%periodic%parameter_min) < 1)
   call t%check_true('the reference is unstable at parameter_max', radius(scene%periodic%parameter_max) > 1)
   u_ns = bisection(scene%periodic%parameter_min, scene%periodic%parameter_max)
   h = 1e-6_dp*u_ns
   slope = (radius(u_ns + h)**(2*steps) - radius(u_ns - h)**(2*steps))/(2*h)
   multiplier_error = multiplier_bound(u_ns)
   write (*, '(a,f0.10,a,es10.3,a,es10.3)') 'reference U_NS (rho(A) = 1) ', u_ns, ' m/s; d|mu|^2/dU ', slope, &
      ' s/m; multiplier round-off bound ', multiplier_error

   ! ---- the closed form of the scheme's damping map, and the continuous beam ----
   call mode_one(omega1)
   zeta1 = factor*(scene%beam%rayleigh_mass/(2*omega1) + scene%beam%rayleigh_stiffness*omega1/2)
   zeta_needed = zeta1 + (theta - 0.5_dp)*omega1*dt
   u_closed = connors(omega1, zeta_needed)
   error = abs(u_closed - u_ns)
   write (*, '(a,f0.10,a,es10.3,a)') 'closed form (Connors at the mesh''s mode 1, zeta + (theta - 1/2) omega dt) ', &
      u_closed, ' m/s, difference ', error, ' m/s'
   ! the same number two ways; they differ by the bisection's round-off: dgeevx's |lambda|
   ! errs by 4 eps ||A||_F/s (s its reciprocal condition number), which moves the zero of
   ! |lambda| - 1 by that over d|lambda|/dU = (d|mu|^2/dU)/(2P) at |lambda| = 1; the
   ! closed form's own (dsygv's omega_1, a few eps relative) and the bisection's width
   ! (1e-14 relative) are covered by 10 eps U beside it
   reference_error = 2*steps*eigenvalue_bound(u_ns)/abs(slope) + 10*epsilon(1.0_dp)*u_closed
   write (*, '(a,es10.3,a)') 'the reference''s own round-off bound ', reference_error, ' m/s'
   call t%check_close('reference by bisection against the closed form (m/s)', u_ns, u_closed, reference_error, &
                      scale=1.0_dp)
   f_exact = beta_1**2/(2*pi*scene%beam%length**2)*sqrt(scene%beam%ei()/scene%beam%rho_s())
   omega_exact = 2*pi*f_exact
   u_continuous = connors(omega_exact, factor*(scene%beam%rayleigh_mass/(2*omega_exact) + &
                                               scene%beam%rayleigh_stiffness*omega_exact/2))
   write (*, '(a,f0.10,a,f0.8,a,es10.3,a,es10.3,a)') 'continuous Connors velocity ', u_continuous, ' m/s (f1 = ', &
      f_exact, ' Hz); the discrete scheme''s U_NS differs by ', u_ns - u_continuous, ' m/s (', &
      (u_ns - u_continuous)/u_continuous, ' relative)'

   ! ---- the branch ----
   call continue_test_branch(t, 'test_neimark_sacker', scene, prepared, branch)
   found = count(branch%bifurcations%kind == neimark_sacker)
   call t%check_true('one Neimark-Sacker point on the branch', found == 1)
   call t%check_true('nothing else on the branch', size(branch%bifurcations) == found)
   if (found /= 1) call t%finish('test_neimark_sacker')
   k = findloc(branch%bifurcations%kind, neimark_sacker, dim=1)
   call t%check_true('the Neimark-Sacker point was located (regula falsi converged)', branch%bifurcations(k)%located)
   u_located = branch%bifurcations(k)%parameter
   index = branch%bifurcations(k)%index
   call t%check_true('no point of the branch reaches the stops', all(branch%points%minimum_gap > 0))
   call t%check_true('the points before it are stable', all(largest(1, index) < 1))
   call t%check_true('the points after it are unstable', all(largest(index + 1, size(branch%points)) > 1))

   ! each point's largest multiplier against the reference's rho(A(U))^P
   worst = 0
   do k = 1, size(branch%points)
      associate (p => branch%points(k))
         error = abs(hypot(p%multipliers(1, 1), p%multipliers(2, 1)) - radius(p%parameter)**steps)
         bound = multiplier_bound(p%parameter)
         worst = max(worst, error/bound)
         call t%check_close('largest |mu| of a branch point against rho(A(U))^P', error, 0.0_dp, bound, scale=1.0_dp)
      end associate
   end do
   write (*, '(a,i0,a,es10.3)') 'largest |mu| of the ', size(branch%points), ' points: largest error / bound ', worst

   ! Tolerance of the located point: (1) the test function |mu|^2 - 1 of each trial errs by
   ! 2 |mu| d|mu| <= 2.1 multiplier_error near |mu| = 1, which moves its zero by that over
   ! |d|mu|^2/dU|; (2) locate stops with the test function within locate_tolerance of 0 at
   ! a bracket's end (the linear estimate then within about twice that over the slope), or
   ! the bracket below locate_bracket of the step (the zero and the estimate both inside
   ! it: at most that share of the U between the two branch points), or with U moving by
   ! less than locate_lambda (relative) between two trials; (3) the reference's own
   ! round-off (above). The sum of the bounds.
   bracket_width = abs(branch%points(index + 1)%parameter - branch%points(index)%parameter)
   tolerance = (2.1_dp*multiplier_error + 2*locate_tolerance)/abs(slope) + locate_bracket*bracket_width + &
               locate_lambda*u_ns + reference_error
   write (*, '(a,f0.10,a,f0.10,a,es10.3,a,es10.3,a)') 'located Neimark-Sacker point ', u_located, ' m/s, reference ', &
      u_ns, ' m/s: difference ', u_located - u_ns, ' m/s (tolerance ', tolerance, ')'
   call t%check_close('located Neimark-Sacker point against the reference (m/s)', u_located, u_ns, tolerance, &
                      scale=1.0_dp)
   call t%finish('test_neimark_sacker')

contains

   !> The spectral radius of the one-step matrix A(U), the flow at velocity u.
   real(dp) function radius(u)
      real(dp), intent(in) :: u
      real(dp) :: a(2*n, 2*n), wr(2*n), wi(2*n), rconde(2*n), vectors(2*n, 2*n)
      a = amplification(u)
      call eigenvalues_with_conditions(a, wr, wi, rconde, vectors)
      radius = maxval(hypot(wr, wi))
   end function radius

   !> The one-step matrix A(U) of the velocity scheme with the flow at velocity u (the
   !! reference's Rayleigh damping, the flow's force at V^n).
   function amplification(u) result(a)
      real(dp), intent(in) :: u
      real(dp) :: a(2*n, 2*n)
      a = amplification_matrix(mass, stiffness, damping, dt, theta, &
                               fluid_elastic_damping(mass, stiffness, u, scene%flow%density, &
                                                     scene%flow%connors_constant, scene%beam%rho_s(), scene%flow%modes))
   end function amplification

   !> U in [lo, hi] where rho(A(U)) = 1 (rho < 1 at lo, > 1 at hi), to 1e-14 relative.
   real(dp) function bisection(lo, hi)
      real(dp), intent(in) :: lo, hi
      real(dp) :: a, b
      a = lo
      b = hi
      do while (b - a > 1e-14_dp*b)
         bisection = (a + b)/2
         if (radius(bisection) < 1) then
            a = bisection
         else
            b = bisection
         end if
      end do
      bisection = (a + b)/2
   end function bisection

   !> The round-off bound of the largest multiplier of the monodromy by the linearised
   !! steps at velocity u, as test_periodic_linear derives it (a factor 4 beside the
   !! first-order terms): dgeevx's backward error on A times P |lambda|^(P-1), dgeev's on the
   !! monodromy, and P steps' componentwise round-off of the eigenvector (8 eps rho(x_k)),
   !! over the eigenvalue's reciprocal condition number.
   real(dp) function multiplier_bound(u)
      real(dp), intent(in) :: u
      real(dp) :: a(2*n, 2*n), wr(2*n), wi(2*n), rconde(2*n), vectors(2*n, 2*n), power, rho_k
      integer :: j, first
      a = amplification(u)
      call eigenvalues_with_conditions(a, wr, wi, rconde, vectors)
      j = maxloc(hypot(wr, wi), dim=1)
      first = j
      if (wi(j) < 0) first = j - 1
      rho_k = max(cancellation(gram, vectors(:, first)), cancellation(gram, vectors(:, first + 1)))
      power = hypot(wr(j), wi(j))**(steps - 1)
      multiplier_bound = 4*(epsilon(1.0_dp)*steps*sqrt(sum(a**2))*power + epsilon(1.0_dp)*sqrt(real(2*n, dp)) + &
                            8*epsilon(1.0_dp)*steps*power*rho_k)/rconde(j)
   end function multiplier_bound

   !> dgeevx's error bound on the largest-modulus eigenvalue of A(u): 4 eps ||A||_F/s,
   !! s its reciprocal condition number (a factor 4 beside the first-order bound).
   real(dp) function eigenvalue_bound(u)
      real(dp), intent(in) :: u
      real(dp) :: a(2*n, 2*n), wr(2*n), wi(2*n), rconde(2*n), vectors(2*n, 2*n)
      integer :: j
      a = amplification(u)
      call eigenvalues_with_conditions(a, wr, wi, rconde, vectors)
      j = maxloc(hypot(wr, wi), dim=1)
      eigenvalue_bound = 4*epsilon(1.0_dp)*sqrt(sum(a**2))/rconde(j)
   end function eigenvalue_bound

   !> The largest |mu| of the branch points first..last.
   function largest(first, last) result(moduli)
      integer, intent(in) :: first, last
      real(dp) :: moduli(max(0, last - first + 1))
      integer :: i
      do i = first, last
         moduli(i - first + 1) = hypot(branch%points(i)%multipliers(1, 1), branch%points(i)%multipliers(2, 1))
      end do
   end function largest

   !> omega_1 of the dense M, K (LAPACK dsygv).
   subroutine mode_one(omega)
      real(dp), intent(out) :: omega
      real(dp) :: a(n, n), b(n, n), w(n), query(1)
      real(dp), allocatable :: space(:)
      integer :: info
      a = stiffness
      b = mass
      call dsygv(1, 'N', 'L', n, a, n, b, n, w, query, -1, info)
      allocate (space(int(query(1))))
      call dsygv(1, 'N', 'L', n, a, n, b, n, w, space, size(space), info)
      if (info /= 0) error stop 'dsygv failed'
      omega = sqrt(w(1))
   end subroutine mode_one

   !> Connors' velocity K f sqrt(2 pi zeta m/rho) of a mode of frequency omega (rad/s) and
   !! damping ratio zeta, over the whole span.
   real(dp) function connors(omega, zeta)
      real(dp), intent(in) :: omega, zeta
      connors = scene%flow%connors_constant*omega/(2*pi)*sqrt(2*pi*zeta*scene%beam%rho_s()/scene%flow%density)
   end function connors
end program test_neimark_sacker
