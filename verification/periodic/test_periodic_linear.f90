!> Linear exactness of the periodic-orbit analysis (issue 20; docs/method.md, "Periodic
!! orbits by shooting"). Without contact the velocity scheme is the linear recurrence
!!   W (V' - V) = dt (F^{n+theta} - C V - K (U + theta dt V)),  U' = U + dt (theta V' + (1 - theta) V),
!! W = M + theta dt C + theta^2 dt^2 K, so under F(t) = Re(F^ e^{i Omega t}) its periodic
!! solution is Re((U^, V^) z^n), z = e^{i Omega dt}, with
!!   (z - 1) W V^ = dt (F^ (theta z + 1 - theta) - K U^ - (C + theta dt K) V^),
!!   (z - 1) U^ = dt (theta z + 1 - theta) V^,
!! a complex linear system solved with LAPACK zgesv from the dense M, K of the scene's
!! stepped system (`harmonic_steady_state`, independently of the shooting code: no stepper, no period map);
!! F^ = F(0) - i F(T/4). The Floquet multipliers of that orbit are lambda_k^P, lambda_k the
!! eigenvalues of the one-step amplification matrix A (dense, LAPACK dgeevx), P the steps
!! of the orbit: exp(s_k T) for the scheme's own rates s_k = log(lambda_k)/dt.
!! With &flow (theory §10) the fluid-elastic force F_f = -E V^n, E from the modes of the
!! dense M, K and Connors' formula (`fluid_elastic_damping`), enters both as a damping
!! taken at V^n: -(C + E) V on the right, W unchanged; and so does the damping per mode of
!! `&beam modal_damping_ratios` (`modal_damping_excess`: the rates beyond Rayleigh's).
!!
!! Checked against the orbit `find_periodic_orbit` returns (converged, its state at
!! t = 0 and its tip over the period) and its multipliers, to round-off bounds derived
!! below. Usage: test_periodic_linear SCENE.nml (a scene of kind = 'periodic' whose
!! obstacles, if any, are never reached).
program test_periodic_linear
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_scene, only: scene_type, is_unset
   use vibrobeam_problem, only: run_problem
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_model, only: node_row
   use vibrobeam_periodic_reference, only: identity, solve_dense, energy_gram, energy_norm, cancellation, &
      fixed_point_condition, amplification_matrix, harmonic_steady_state, matrix_power, check_multipliers, &
      fluid_elastic_damping, modal_damping_excess
   use vibrobeam_periodic_analysis, only: find_periodic_orbit, periodic_orbit
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(periodic_orbit) :: orbit
   character(len=512) :: path, errmsg
   real(dp), allocatable :: mass(:, :), stiffness(:, :), damping(:, :), explicit(:, :), a(:, :), gram(:, :), &
                            tip_row(:), x_ref(:), &
                            tip_ref(:)
   complex(dp), allocatable :: rhs(:, :), harmonic(:)
   complex(dp) :: z
   real(dp) :: dt, theta, omega, period, error, bound, inverse_norm, noise, worst
   integer :: n, m, stat, info, k, dofs(4), ratios_given
   integer(int64) :: steps
   real(dp) :: weights(4)

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call find_periodic_orbit(scene, prepared, orbit, stat, errmsg)
   call t%check_true('find_periodic_orbit runs', stat == 0, trim(errmsg))
   if (stat /= 0) call t%finish('test_periodic_linear')
   call t%check_true('Newton''s method converged', orbit%converged, trim(orbit%failure))
   call t%check_true('no contact point was reached (a linear scene)', all(abs(orbit%image%tip(1, :)) < &
                     minval(abs([prepared%contacts%lower, prepared%contacts%upper]))))

   ! ---- the scheme's matrices, dense, from the stepped system's M and K ----
   n = prepared%system%model%unknowns
   m = 2*n
   allocate (mass(n, n), stiffness(n, n), damping(n, n), x_ref(m), gram(m, m))
   mass = band_to_dense(prepared%system%model%mass)
   stiffness = band_to_dense(prepared%system%model%stiffness)
   dt = scene%time%dt
   theta = scene%time%theta
   damping = scene%beam%rayleigh_mass*mass + scene%beam%rayleigh_stiffness*stiffness
   allocate (explicit(n, n), source=0.0_dp)
   if (scene%flow%velocity > 0) then
      ! the reference takes the modes of the mesh, over the whole span
      if (prepared%reduced .or. scene%flow%x_from > 0 .or. .not. (is_unset(scene%flow%x_to) .or. &
          scene%flow%x_to >= scene%beam%length)) &
         error stop 'test_periodic_linear: &flow over the whole span of a full model only'
      explicit = fluid_elastic_damping(mass, stiffness, scene%flow%velocity, scene%flow%density, &
                                       scene%flow%connors_constant, scene%beam%rho_s(), scene%flow%modes)
   end if
   if (scene%beam%modal()) then
      ! the ratios given, modes 1 to the last (the reference takes neither `modal_damping`'s
      ! cut-off nor rigid-body modes)
      ratios_given = count(.not. is_unset(scene%beam%modal_damping_ratios))
      if (.not. is_unset(scene%beam%modal_damping) .or. prepared%reduced .or. &
          any(is_unset(scene%beam%modal_damping_ratios(1:ratios_given)))) &
         error stop 'test_periodic_linear: damping per mode by modal_damping_ratios(1:k) of a full model only'
      explicit = explicit + modal_damping_excess(mass, stiffness, scene%beam%modal_damping_ratios(1:ratios_given), &
                                                 scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness)
   end if
   omega = maxval([scene%load%point_frequency, scene%load%base_frequency, scene%load%distributed_frequency])
   period = 2*pi/omega
   steps = nint(scene%periodic%period_multiple*period/dt, int64)

   ! ---- one-step amplification matrix A: V' = A21 U + A22 V, U' = A11 U + A12 V ----
   a = amplification_matrix(mass, stiffness, damping, dt, theta, explicit)

   ! ---- the harmonic steady state (complex system, zgesv) ----
   z = exp(cmplx(0.0_dp, omega*dt, dp))
   call harmonic_steady_state(prepared, mass, stiffness, damping, dt, theta, omega, harmonic, info, explicit)
   call t%check_true('zgesv solves the harmonic system', info == 0)
   rhs = reshape(harmonic, [m, 1])
   x_ref = real(rhs(:, 1))

   ! ---- the energy norm ||x||^2 = U^T (K + Omega^2 M) U + V^T M V, and the orbit's
   ! ||(I - M)^-1||, M = A^P, which bounds how a residual of the period map moves its
   ! fixed point ----
   gram = energy_gram(prepared, omega)
   inverse_norm = fixed_point_condition(gram, matrix_power(a, steps))
   ! noise: the relative round-off of one evaluation of the period map in the energy
   ! norm. Each of its P steps rounds each unknown relative to itself (a few operations:
   ! 8 eps), and the energy norm weighs such componentwise errors of a state x by up to
   ! rho(x) = sqrt(x^T diag(G) x / x^T G x) against the state's own norm (the cancellation
   ! between neighbouring unknowns that x^T K x hides; G the Gram matrix above); the steps
   ! are contractions in that norm (theta >= 1/2, damping), so the errors add:
   ! noise = 8 eps P rho(x_ref).
   noise = 8*epsilon(1.0_dp)*real(steps, dp)*cancellation(gram, x_ref)

   ! ---- the orbit: state at t = 0 and tip over the period ----
   ! Newton stops at a relative residual <= tolerance; with the map's own noise the fixed
   ! point it returns is within ||(I - M)^-1|| (tolerance + 2 noise) of the exact one
   ! (relative, energy norm), and the reference (a backward-stable solve of a system of
   ! size 2J) adds 4 m eps cond: negligible beside P eps.
   error = energy_norm(gram, orbit%x - x_ref)/energy_norm(gram, x_ref)
   bound = inverse_norm*(scene%periodic%tolerance + 2*noise)
   write (*, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3)') 'state at t = 0: relative error ', error, ', bound ', bound, &
      ' (||(I - M)^-1|| = ', inverse_norm, ', noise ', noise
   call t%check_close('orbit state at t = 0 against the harmonic steady state (energy norm, relative)', error, &
                      0.0_dp, bound, scale=1.0_dp)
   call t%check_true('the bound is a round-off bound (< 1e-6)', bound < 1e-6_dp)
   ! the tip, u = t^T U: a linear functional of U, bounded by the state's error in the
   ! energy norm times its dual norm |t|_{(K + Omega^2 M)^-1}, relative to the tip's peak
   call node_row(prepared%model, prepared%model%elements, dofs, weights)
   tip_row = tip_functional(dofs, weights)
   ! (allocated first: gfortran's -Wmaybe-uninitialized does not follow an array
   ! constructor's reallocation)
   allocate (tip_ref(int(steps) + 1))
   do k = 0, int(steps)
      tip_ref(k + 1) = real(dot_product(cmplx(tip_row, 0.0_dp, dp), rhs(1:n, 1))*z**k)
   end do
   error = maxval(abs(orbit%image%tip(1, :) - tip_ref))
   bound = (scene%periodic%tolerance + 2*noise)*inverse_norm*energy_norm(gram, x_ref)*dual_norm(tip_row)*2
   write (*, '(a,es10.3,a,es10.3,a,es10.3,a)') 'tip over the period: largest error ', error, ' m, bound ', bound, &
      ' m (peak ', maxval(abs(tip_ref)), ' m)'
   call t%check_close('tip displacement over the period against the harmonic steady state (m)', error, 0.0_dp, bound, &
                      scale=1.0_dp)

   ! ---- Floquet multipliers against lambda_k^P (bounds derived in check_multipliers) ----
   worst = check_multipliers(t, orbit%multipliers, a, steps, orbit%monodromy, noise, gram)
   write (*, '(a,es10.3)') 'Floquet multipliers: largest error / bound ', worst
   call t%finish('test_periodic_linear')

contains

   !> The row t of u at the tip on the stepped system's unknowns (through the reduced
   !! basis when the scene is reduced).
   function tip_functional(dofs, weights) result(row)
      integer, intent(in) :: dofs(4)
      real(dp), intent(in) :: weights(4)
      real(dp), allocatable :: row(:)
      integer :: i
      allocate (row(n), source=0.0_dp)
      do i = 1, 4
         if (dofs(i) == 0) cycle
         if (prepared%reduced) then
            row = row + weights(i)*prepared%reduction%transform(dofs(i), :)
         else
            row(dofs(i)) = row(dofs(i)) + weights(i)
         end if
      end do
   end function tip_functional

   !> sqrt(t^T (K + Omega^2 M)^-1 t): the largest |t^T U| over ||U||_(K + Omega^2 M) = 1.
   real(dp) function dual_norm(row)
      real(dp), intent(in) :: row(:)
      real(dp) :: b(size(row), 1)
      b(:, 1) = row
      call solve_dense(gram(1:n, 1:n), b)
      dual_norm = sqrt(dot_product(row, b(:, 1)))
   end function dual_norm

end program test_periodic_linear
