!> Grazing located on a continued branch against an independent reference (issue 20,
!! item 2; docs/method.md, "Continuation of periodic orbits", "Grazing"). The scene: a
!! damped cantilever with one compliant stop at the distance g above its tip, continued in
!! its forcing frequency towards resonance (`continue_branch`). While the orbit does not
!! touch the stop it is the scheme's harmonic steady state Re(U^ z^n), z = e^{2 pi i/P}
!! at dt = T/P (`harmonic_steady_state`: a complex linear system from the dense M and K,
!! no stepper, no period map), so the grazing frequency Omega_g is where the largest tip
!! excursion over the P sampled steps of a period, max_n Re(u^ z^n), reaches g; it is
!! found here by bisection on the reference alone, and the grazing the continuation
!! locates (kind 4) must equal it within the tolerance derived beside the check. Also:
!! the smallest clearance of every branch point before grazing against the reference's,
!! the sampling effect (the sampled grazing against the envelope |u^| = g, within
!! g (1/cos(pi/P) - 1) of excursion), the convergence in P, and a branch whose orbit
!! never reaches the stop (g five times larger) reports no grazing.
!! Usage: test_continuation_grazing SCENE.nml (kind = 'periodic', &periodic parameter =
!! 'load.point_frequency', one compliant stop 'above' at the tip, reached below
!! parameter_max).
program test_continuation_grazing
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_periodic_settings, only: period_step
   use vibrobeam_periodic_reference, only: energy_gram, cancellation, fixed_point_condition, amplification_matrix, &
      harmonic_steady_state, matrix_power, solve_dense, continue_test_branch
   use vibrobeam_continuation, only: continuation_branch
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   integer, parameter :: grazing = 4            !! the kind of a grazing bifurcation
   !> locate's stopping rules (vibrobeam_continuation): the bracket below 1e-4 of the
   !! step, the test function (here the clearance, m) within 1e-10 of 0, lambda moving by
   !! less than 1e-9 (relative) between two trials
   real(dp), parameter :: locate_bracket = 1e-4_dp, locate_tolerance = 1e-10_dp, locate_lambda = 1e-9_dp
   real(dp), parameter :: pi = acos(-1.0_dp)
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(continuation_branch) :: branch
   character(len=512) :: path
   real(dp) :: level, omega0, omega_g, omega_envelope, omega_located, slope, tolerance, gap_error, bracket_width
   real(dp) :: error, worst, previous, change, previous_change, envelope_bound
   real(dp) :: envelope, sampled
   integer :: k, found, steps_per_period, index, p, steps

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   level = scene%obstacles(1)%level_from
   steps_per_period = scene%periodic%steps_per_period
   omega0 = scene%load%point_frequency

   ! the reference grazing, by bisection between the branch's start and parameter_max
   call t%check_true('the reference orbit is free of the stop at the start', &
                     reference_gap(omega0, steps_per_period, .true.) > 0)
   call t%check_true('the reference orbit reaches the stop before parameter_max', &
                     reference_gap(scene%periodic%parameter_max, steps_per_period, .true.) < 0)
   omega_g = bisection(steps_per_period, .true.)
   omega_envelope = bisection(steps_per_period, .false.)
   slope = gap_slope(omega_g)
   write (*, '(a,f0.9,a,f0.9,a,es10.3,a)') 'reference grazing (P sampled steps) ', omega_g, &
      ' rad/s, envelope |u^| = g at ', omega_envelope, ' rad/s; d(gap)/dOmega ', slope, ' m s/rad'

   call continue_test_branch(t, 'test_continuation_grazing', scene, prepared, branch)
   found = count(branch%bifurcations%kind == grazing)
   call t%check_true('one grazing on the branch', found == 1)
   call t%check_true('nothing else on the branch', size(branch%bifurcations) == found)
   if (found /= 1) call t%finish('test_continuation_grazing')
   k = findloc(branch%bifurcations%kind, grazing, dim=1)
   call t%check_true('the grazing was located (regula falsi converged)', branch%bifurcations(k)%located)
   omega_located = branch%bifurcations(k)%parameter
   index = branch%bifurcations(k)%index

   ! the clearance of the points before grazing: the reference's to the orbit's error bound
   worst = 0
   do k = 1, index
      error = abs(branch%points(k)%minimum_gap - reference_gap(branch%points(k)%parameter, steps_per_period, .true.))
      worst = max(worst, error/orbit_gap_bound(branch%points(k)%parameter))
      call t%check_close('smallest clearance of a point before grazing against the reference', error, 0.0_dp, &
                         orbit_gap_bound(branch%points(k)%parameter), scale=1.0_dp)
   end do
   write (*, '(a,i0,a,es10.3)') 'clearance of the ', index, ' points before grazing: largest error / bound ', worst
   call t%check_true('the points after grazing press into the stop', &
                     all(branch%points(index + 1:)%minimum_gap < 0))

   ! Tolerance of the located grazing. Sampling: the reference takes the same P samples as
   ! the period map (the steps of the orbit), so the sampled minimum's own error
   ! (below) is common to both and does not enter. What does: (1) the orbit's clearance
   ! differs from the reference's by at most gap_error (the fixed-point bound of the
   ! corrector's tolerance, orbit_gap_bound), which moves the zero by gap_error/|dg/dOmega|;
   ! (2) locate stops with the clearance within locate_tolerance of 0 at a bracket's end
   ! (the linear estimate inside the bracket then lies within about twice that over
   ! |dg/dOmega| of the zero), or with the bracket below locate_bracket of the step (the
   ! zero and the estimate both inside it: at most that share of the Omega between the two
   ! branch points), or with Omega moving by less than locate_lambda (relative) between
   ! two trials (regula falsi converging superlinearly: the error below that move). The
   ! sum of the three bounds.
   gap_error = orbit_gap_bound(omega_g)
   bracket_width = abs(branch%points(index + 1)%parameter - branch%points(index)%parameter)
   tolerance = (gap_error + 2*locate_tolerance)/abs(slope) + locate_bracket*bracket_width + locate_lambda*omega_g
   write (*, '(a,f0.9,a,f0.9,a,es10.3,a,es10.3,a)') 'located grazing ', omega_located, ' rad/s, reference ', &
      omega_g, ' rad/s: difference ', abs(omega_located - omega_g), ', tolerance ', tolerance, ' rad/s'
   call t%check_close('located grazing against the reference (|difference|, rad/s)', abs(omega_located - omega_g), &
                      0.0_dp, tolerance, scale=1.0_dp)

   ! The sampling effect: the largest of P samples of |u^| cos(phi + 2 pi n/P) is at least
   ! |u^| cos(pi/P) (the nearest sample within pi/P of the peak's phase), so where it
   ! reaches g the envelope |u^| is at most g/cos(pi/P): the sampled grazing lies above
   ! the envelope's by at most g (1/cos(pi/P) - 1)/|dg/dOmega| (1 % allowed for the
   ! slope's change over that interval), O(dt^2).
   envelope_bound = level*(1/cos(pi/steps_per_period) - 1)/abs(slope)
   write (*, '(a,es10.3,a,es10.3,a)') 'sampled grazing - envelope grazing ', omega_g - omega_envelope, &
      ' rad/s, bound ', envelope_bound, ' rad/s'
   call t%check_true('the sampled grazing lies at or above the envelope''s, within the sampling bound', &
                     omega_g >= omega_envelope .and. omega_g - omega_envelope <= 1.01_dp*envelope_bound)
   ! Convergence in P: the discrete steady state differs from the beam's by O(dt^2)
   ! (theta = 1/2), so the envelope's grazing converges at second order (each halving of
   ! dt divides its change by about 4; checked > 3.5); the sampled grazing follows it
   ! within the sampling bound above, which is O(dt^2) too but oscillates with the phase
   ! of the peak between two samples (no clean ratio).
   previous_change = 0
   previous = 0
   do p = 1, 4
      steps = 100*2**(p - 1)
      envelope = bisection(steps, .false.)
      sampled = bisection(steps, .true.)
      call t%check_true('the sampled grazing within the sampling bound of the envelope''s at every P', &
                        sampled >= envelope .and. sampled - envelope <= &
                        1.01_dp*level*(1/cos(pi/steps) - 1)/abs(gap_slope(envelope)))
      write (*, '(a,i0,a,f0.9,a,f0.9,a)') 'reference grazing at P = ', steps, ': envelope ', envelope, &
         ' rad/s, sampled ', sampled, ' rad/s'
      change = envelope - previous
      if (p > 2) call t%check_true('the envelope''s grazing converges in P at second order (change ratio > 3.5)', &
                                   abs(previous_change) > 3.5_dp*abs(change))
      if (p > 2) write (*, '(a,f0.3)') '  ratio of the changes from P/4 to P/2 and P/2 to P: ', previous_change/change
      previous_change = change
      previous = envelope
   end do

   ! a stop out of reach: no grazing, every clearance positive
   level = 5*level
   scene%obstacles(1)%level_from = level
   call continue_test_branch(t, 'test_continuation_grazing', scene, prepared, branch)
   write (*, '(a,i0,a,es10.3,a)') 'stop out of reach: ', size(branch%points), ' points, smallest clearance ', &
      minval(branch%points%minimum_gap), ' m'
   call t%check_true('no grazing where the orbit never reaches the stop', &
                     count(branch%bifurcations%kind == grazing) == 0)
   call t%check_true('every clearance positive where the orbit never reaches the stop', &
                     all(branch%points%minimum_gap > 0))
   call t%check_true('the reference agrees: the stop is out of reach at the branch''s end', &
                     reference_gap(branch%points(size(branch%points))%parameter, steps_per_period, .true.) > 0)
   call t%finish('test_continuation_grazing')

contains

   !> The problem at Omega with dt = T/steps, its dense M, K and Rayleigh C.
   subroutine reference_problem(omega, steps, at, mass, stiffness, damping)
      real(dp), intent(in) :: omega
      integer, intent(in) :: steps
      type(run_problem), intent(out) :: at
      real(dp), allocatable, intent(out) :: mass(:, :), stiffness(:, :), damping(:, :)
      type(scene_type) :: local
      local = scene
      local%load%point_frequency = omega
      local%time%dt = period_step(omega, steps)
      call prepare_test_scene(local, at)
      mass = band_to_dense(at%system%model%mass)
      stiffness = band_to_dense(at%system%model%stiffness)
      damping = scene%beam%rayleigh_mass*mass + scene%beam%rayleigh_stiffness*stiffness
   end subroutine reference_problem

   !> The reference's clearance g - max_n Re(u^ z^n) over the `steps` samples of a period
   !! (`sampled`), or g - |u^| (the envelope), u^ the harmonic steady state's complex
   !! amplitude at the stop's contact point (its row H_c of the mesh).
   real(dp) function reference_gap(omega, steps, sampled)
      real(dp), intent(in) :: omega
      integer, intent(in) :: steps
      logical, intent(in) :: sampled
      type(run_problem) :: at
      real(dp), allocatable :: mass(:, :), stiffness(:, :), damping(:, :)
      complex(dp), allocatable :: harmonic(:)
      complex(dp) :: amplitude
      integer :: info, n
      call reference_problem(omega, steps, at, mass, stiffness, damping)
      call harmonic_steady_state(at, mass, stiffness, damping, period_step(omega, steps), scene%time%theta, omega, &
                                 harmonic, info)
      if (info /= 0) error stop 'zgesv: the harmonic system is singular'
      amplitude = sum(at%contacts%weights(:, 1)*harmonic(max(1, at%contacts%dofs(:, 1))), &
                      mask=at%contacts%dofs(:, 1) /= 0)
      if (sampled) then
         reference_gap = level - maxval([(real(amplitude*exp(cmplx(0.0_dp, 2*pi*n/steps, dp))), n=0, steps - 1)])
      else
         reference_gap = level - abs(amplitude)
      end if
   end function reference_gap

   !> Omega in [the start, parameter_max] where reference_gap vanishes, by bisection to
   !! the last bit (60 halvings of a bracket of tens of rad/s).
   real(dp) function bisection(steps, sampled)
      integer, intent(in) :: steps
      logical, intent(in) :: sampled
      real(dp) :: low, high
      integer :: i
      low = omega0
      high = scene%periodic%parameter_max
      do i = 1, 60
         bisection = (low + high)/2
         if (reference_gap(bisection, steps, sampled) > 0) then
            low = bisection
         else
            high = bisection
         end if
      end do
      bisection = (low + high)/2
   end function bisection

   !> d(reference_gap)/dOmega by a central difference (h = 1e-3 rad/s: a relative error
   !! of order (h/width of the resonance)^2, far below the tolerance it enters).
   real(dp) function gap_slope(omega)
      real(dp), intent(in) :: omega
      real(dp), parameter :: h = 1e-3_dp
      gap_slope = (reference_gap(omega + h, steps_per_period, .true.) - &
                   reference_gap(omega - h, steps_per_period, .true.))/(2*h)
   end function gap_slope

   !> How far the continued orbit's clearance may lie from the reference's at Omega (m):
   !! as test_continuation_linear, the state within ||(I - M)^-1|| (c^2 tolerance + 2
   !! noise) of the exact fixed point, relative, in the energy norm at Omega (c the ratio
   !! of the norms at Omega and the start's Omega0, noise 8 eps k P rho(x)); the contact
   !! point's displacement h . U within sqrt(h^T (K + Omega^2 M)^-1 h) times that norm
   !! (Cauchy-Schwarz in the energy norm's U part).
   real(dp) function orbit_gap_bound(omega)
      real(dp), intent(in) :: omega
      type(run_problem) :: at
      real(dp), allocatable :: mass(:, :), stiffness(:, :), damping(:, :), gram(:, :), x(:), row(:, :), weighted(:, :)
      complex(dp), allocatable :: harmonic(:)
      real(dp) :: dt, ratio, noise, relative
      integer(int64) :: steps
      integer :: info, n, a
      dt = period_step(omega, steps_per_period)
      call reference_problem(omega, steps_per_period, at, mass, stiffness, damping)
      call harmonic_steady_state(at, mass, stiffness, damping, dt, scene%time%theta, omega, harmonic, info)
      if (info /= 0) error stop 'zgesv: the harmonic system is singular'
      x = real(harmonic)
      n = size(mass, 1)
      gram = energy_gram(at, omega)
      steps = int(steps_per_period, int64)*scene%periodic%period_multiple
      ratio = max(omega/omega0, omega0/omega)
      noise = 8*epsilon(1.0_dp)*real(steps, dp)*cancellation(gram, x)
      relative = fixed_point_condition(gram, matrix_power(amplification_matrix(mass, stiffness, damping, dt, &
                                                                                scene%time%theta), steps))* &
                 (ratio**2*scene%periodic%tolerance + 2*noise)
      allocate (row(n, 1), source=0.0_dp)
      do a = 1, 4
         if (at%contacts%dofs(a, 1) /= 0) row(at%contacts%dofs(a, 1), 1) = at%contacts%weights(a, 1)
      end do
      weighted = row
      call solve_dense(gram(1:n, 1:n), weighted)
      orbit_gap_bound = relative*sqrt(dot_product(x, matmul(gram, x)))*sqrt(dot_product(row(:, 1), weighted(:, 1)))
   end function orbit_gap_bound
end program test_continuation_grazing
