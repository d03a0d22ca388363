!> Verification of Coulomb friction at circular holes (issue 21; docs/method.md, "Circular
!! obstacles", "Frictional contact in two dimensions: the solver"), on
!! verification/dynamics/circle_friction.nml:
!! (1) the friction angle, a closed form: the tube rests on the wall, a constant tip
!!     force F at the angle a from the wall's normal presses it. The force acts at the
!!     contact node itself, so if the node sticks the contact's impulses take F dt whole
!!     in every step and nothing moves (V^{n+1} = W^-1 (F dt + H^T P) = 0); that is
!!     Coulomb-admissible exactly when |F_t| <= mu F_n, tan a <= mu. So the tube stays at
!!     rest to round-off for a = atan(mu) (1 - 1e-3) and slides for a = atan(mu) (1 + 1e-3),
!!     and the friction's energy (the integral of F_t v_t, -r_T t.(V^{n+1} + V^n)/2 per
!!     step) is then positive;
!! (2) the energy ledger with friction: a tube whirling in a centred hole, mu = 0.2,
!!     e = 0.9, theta = 1/2: E - W + D (impacts, friction) stays E_0 to round-off over 1e5
!!     steps; friction takes energy and the angular momentum about the axis falls.
program test_circle_friction
   use vibrobeam_kinds, only: dp, output_unit, pi
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, &
      start_test_stepper, advance_test_stepper, angular_momentum
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, whirl
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: stepper
   character(len=512) :: path
   real(dp), parameter :: eps = epsilon(1.0_dp)
   real(dp) :: angle, static, moved(2), friction(2), energy0, moment0, worst, scale, ledger
   integer :: n, steps, k
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   steps = nint(scene%time%t_end/scene%time%dt)
   ! the tip's static deflection under F, a scale for "at rest"
   static = scene%load%point_force*scene%beam%length**3/(3*scene%beam%youngs_modulus*scene%beam%inertia)

   ! (1) below and above the friction angle
   angle = atan(scene%obstacles(1)%friction)*180/pi
   do k = 1, 2
      scene%load%direction = angle*merge(1 - 1e-3_dp, 1 + 1e-3_dp, k == 1)
      call prepare_test_scene(scene, prepared)
      call start_test_stepper(scene, prepared, stepper)
      moved(k) = 0
      do n = 1, steps
         call advance_test_stepper(stepper)
         moved(k) = max(moved(k), maxval(abs(stepper%u)))
      end do
      friction(k) = stepper%energy%dissipated_friction
   end do
   write (output_unit, '(a,f10.6,a,es10.3,a)') 'friction angle ', angle, ' degrees; static deflection ', static, ' m'
   write (output_unit, '(a,2es11.3,a,2es11.3)') 'largest |U| below and above it (m): ', moved, &
      '; energy friction took (J): ', friction
   ! at rest to round-off: each step's solve leaves V^{n+1} at a few eps of the free
   ! velocity dt F/m, whose motion over the run stays below 1e-12 of the static deflection
   call t%check_close('below the friction angle the tube stays at rest', moved(1)/static, 0.0_dp, 1e-12_dp, 1.0_dp)
   call t%check_true('above it the tube slides (it moves by more than 1e-6 of the static deflection)', &
                     moved(2) > 1e-6_dp*static)
   call t%check_true('the sliding tube''s friction takes energy', friction(2) > 0)

   ! (2) a whirl in a centred hole with friction
   whirl = scene
   whirl%obstacles(1)%center_y = 0
   whirl%obstacles(1)%friction = 0.2_dp
   whirl%impact%restitution = 0.9_dp
   whirl%load%point_force = 0
   whirl%load%direction = 0
   whirl%initial%displacement = 'mode'
   whirl%initial%displacement_amplitude = 0.5_dp*whirl%obstacles(1)%radius
   whirl%initial%velocity = 'mode'
   whirl%initial%velocity_amplitude = 0.6_dp
   whirl%initial%direction = 90
   call prepare_test_scene(whirl, prepared)
   call start_test_stepper(whirl, prepared, stepper)
   energy0 = stepper%kinetic_energy() + stepper%elastic_energy()
   moment0 = angular_momentum(stepper)
   worst = 0
   scale = energy0
   do n = 1, 100000
      call advance_test_stepper(stepper)
      associate (e => stepper%energy)
         ledger = stepper%kinetic_energy() + stepper%elastic_energy() - e%work + e%dissipated_impacts + &
                  e%dissipated_friction + e%dissipated_damping + e%dissipated_numerical - energy0
      end associate
      worst = max(worst, abs(ledger))
   end do
   write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3)') 'whirl with friction: friction took ', &
      stepper%energy%dissipated_friction/energy0, ' of E0, impacts ', stepper%energy%dissipated_impacts/energy0, &
      '; L/L0 ', angular_momentum(stepper)/moment0, '; largest |E - W + D - E0|/E0 ', worst/energy0
   call t%check_true('friction takes energy from the whirl', stepper%energy%dissipated_friction > 0.01_dp*energy0)
   call t%check_true('friction slows the whirl: the angular momentum falls', &
                     abs(angular_momentum(stepper)) < 0.9_dp*abs(moment0))
   ! each step rounds E and the ledger's sums by a few eps of E0: 8 n eps
   call t%check_close('energy ledger with friction over 1e5 steps', worst/energy0, 0.0_dp, 8*1e5_dp*eps, 1.0_dp)
   call t%finish('test_circle_friction')

end program test_circle_friction
