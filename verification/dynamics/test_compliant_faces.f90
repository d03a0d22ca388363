!> Verification of compliant flat points of a beam of two planes (issue 21; docs/method.md,
!! "Compliant flat points"): compliant levels and compliant polygonal holes, whose springs
!! act along each face's fixed inward normal. On verification/dynamics/circle_planar.nml
!! (the cantilever with its tip in a hole of radius R = 1 mm) and compliant_friction.nml:
!! (a) planar reduction: with a tip load and initial data in y, the beam of two planes
!!     between two compliant levels at -R and +R along [0.4 m, 0.5 m] (seven nodes, each
!!     with its tributary share of the stiffness per length) equals the planar beam between
!!     the same levels (the planar compliant stops) at every step: z exactly 0, y within
!!     10 times the twin's own one-ulp divergence (as test_circle_holes);
!! (b) a compliant square hole (a polygon of 4 faces, orientation 0) at the tip with the
!!     data along y equals the same planar twin with the levels at the tip; turned by 45
!!     degrees with the data along 45 degrees, y and z equal cos 45 and sin 45 times it;
!! (c) a tube whirling in a compliant hexagonal hole, undamped, theta = 1/2, the 'gradient'
!!     rule: E + Phi is conserved to round-off over the steps (each face's force is the
!!     exact discrete gradient of its spring along its fixed normal), through steps that
!!     press two faces at once (a corner); with mu = 0.2 at the faces the ledger
!!     E + Phi - W + D stays E_0 to round-off and friction takes energy;
!! (d) Coulomb friction at a compliant level: the tube pressed on a level of stiffness k
!!     by a normal tip force F_n, then pulled along it (z): the friction angle's closed
!!     form tan a* = mu k/(k + k_b), k_b = 3 E I/L^3 (test_compliant_friction's, exact for
!!     a flat wall): at a* (1 - 1e-3) the tip does not move along the level and its friction
!!     force is the pull; at a* (1 + 1e-3) it slides by about (F_t - mu f)/k_b, its friction
!!     at the bound mu f.
program test_compliant_faces
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_obstacles, only: obstacle_type
   use vibrobeam_planes, only: direction_shares
   use vibrobeam_problem, only: run_problem
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, &
      start_test_stepper, advance_test_stepper, start_planar_twins, hole_levels, start_friction_case, &
      advance_planar_twins
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, levels, square, whirl, friction
   character(len=512) :: path
   real(dp), parameter :: eps = epsilon(1.0_dp)
   real(dp) :: radius
   integer :: steps
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   steps = nint(scene%time%t_end/scene%time%dt)
   radius = scene%obstacles(1)%radius
   scene%load%point_force = 2

   ! (a) two compliant levels along the beam's last 0.1 m, 1e7 N/m per m of length
   levels = scene
   levels%obstacles = hole_levels(obstacle_type(x_from=0.4_dp, x_to=0.5_dp, radius=radius, stiffness=1e7_dp))
   call planar_twin(levels, levels%obstacles, 'two compliant levels along [0.4, 0.5] m')

   ! (b) a compliant square hole at the tip against the levels at +-R there
   square = scene
   square%obstacles(1)%shape = 'polygon'
   square%obstacles(1)%sides = 4
   square%obstacles(1)%stiffness = 1e6_dp
   call planar_twin(square, hole_levels(square%obstacles(1)), 'compliant square hole')
   square%obstacles(1)%orientation = 45
   square%initial%direction = 45
   square%load%direction = 45
   call planar_twin(square, hole_levels(square%obstacles(1)), &
                    'compliant square hole turned by 45 degrees, data along 45 degrees', 45.0_dp)

   ! (c) a whirl in a compliant hexagonal hole: no load, no damping, theta = 1/2
   whirl = scene
   whirl%load%point_force = 0
   whirl%obstacles(1)%shape = 'polygon'
   whirl%obstacles(1)%sides = 6
   whirl%obstacles(1)%stiffness = 1e6_dp
   whirl%initial%displacement = 'mode'
   whirl%initial%displacement_amplitude = 0.5_dp*radius
   whirl%initial%velocity_amplitude = 0.6_dp
   whirl%initial%direction = 90
   call whirl_ledger(whirl, 'hexagonal hole, 1e6 N/m, frictionless', 20000)
   whirl%obstacles(1)%friction = 0.2_dp
   call whirl_ledger(whirl, 'hexagonal hole, 1e6 N/m, mu = 0.2', 20000)

   ! (d) the friction angle at a compliant level
   call get_command_argument(2, path)
   friction = read_test_scene(trim(path))
   associate (o => friction%obstacles(1))
      ! the circle's wall at the tip (centre 0.1 m below, radius 0.1 m) is y = 0 from below:
      ! a level above at 0 with the same spring and friction
      friction%obstacles = [obstacle_type(side='above', x_from=o%x_from, x_to=o%x_to, level_from=0.0_dp, &
                                          level_to=0.0_dp, stiffness=o%stiffness, friction=o%friction)]
   end associate
   call friction_angle(friction)
   call t%finish('test_compliant_faces')

contains

   !> The beam of two planes of `faces` against its planar twin (`planar_obstacles`, levels)
   !! every step: z exactly 0 (data along y), or y and z the twin's times cos and sin of
   !! `angle`, within 10 times how far rounding carries on this trajectory, measured on the
   !! twin itself (the twin started one ulp faster), as test_circle_holes: the two runs
   !! solve the same springs by different routes (a dense Newton method on the points' end
   !! velocities, the planar band Newton method) and round differently.
   subroutine planar_twin(faces, planar_obstacles, label, angle)
      type(scene_type), intent(in) :: faces
      type(obstacle_type), intent(in) :: planar_obstacles(:)
      character(len=*), intent(in) :: label
      real(dp), intent(in), optional :: angle   !! degrees: the data's direction, when not y
      class(time_stepper), allocatable :: reference, perturbed, stepper
      real(dp) :: deviation, own, scale, tolerance, depth, shares(2)
      integer :: n, j, k, iterations
      logical :: z_zero
      shares = [1.0_dp, 0.0_dp]
      if (present(angle)) shares = direction_shares(angle)
      call start_planar_twins(faces, planar_obstacles, stepper, reference, perturbed, j)
      deviation = 0
      own = 0
      scale = 0
      depth = 0
      iterations = 0
      z_zero = .true.
      do n = 1, steps
         call advance_planar_twins(stepper, reference, perturbed, shares, deviation, own, scale)
         if (.not. present(angle)) z_zero = z_zero .and. all(abs(stepper%u(j + 1:)) <= 0) .and. &
                                            all(abs(stepper%v(j + 1:)) <= 0)
         do k = 1, stepper%holes%circles%count
            depth = max(depth, stepper%holes%circles%penetration(k, stepper%u))
         end do
         iterations = max(iterations, stepper%report%iterations)
      end do
      tolerance = 10*max(own, eps*scale)/scale
      write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3,a,i0)') 'planar twin, '//label// &
         ': largest deviation of U, V / their largest ', deviation/scale, '; the twin one ulp faster: ', own/scale, &
         '; tolerance ', tolerance, '; largest penetration ', depth, ' m; Newton iterations at most ', iterations
      if (.not. present(angle)) call t%check_true(label//': z stays exactly 0', z_zero)
      call t%check_close(label//': y (and z) equal the planar twin''s at every step', deviation/scale, 0.0_dp, &
                         tolerance, 1.0_dp)
      call t%check_true(label//': the springs are entered (the run is not free flight)', depth > 0.01_dp*radius)
   end subroutine planar_twin

   !> Step `whirl` for `count` steps: E + Phi - E_0 and the ledger E + Phi - W + D - E_0 at
   !! every step (W = 0 and D = 0 but friction's and round-off here); how many steps press
   !! two faces at once (a corner).
   subroutine whirl_ledger(whirl, label, count)
      type(scene_type), intent(in) :: whirl
      character(len=*), intent(in) :: label
      integer, intent(in) :: count
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      real(dp) :: energy0, stored, ledger, worst_stored, worst_ledger
      integer :: n, corners, iterations
      logical :: frictional
      frictional = whirl%obstacles(1)%friction > 0
      call prepare_test_scene(whirl, prepared)
      call start_test_stepper(whirl, prepared, stepper)
      energy0 = stepper%kinetic_energy() + stepper%elastic_energy() + stepper%contact_potential()
      worst_stored = 0
      worst_ledger = 0
      corners = 0
      iterations = 0
      do n = 1, count
         call advance_test_stepper(stepper)
         stored = stepper%kinetic_energy() + stepper%elastic_energy() + stepper%contact_potential()
         associate (e => stepper%energy)
            ledger = stored - e%work + e%dissipated_impacts + e%dissipated_friction + e%dissipated_damping + &
                     e%dissipated_contact_damping + e%dissipated_numerical - energy0
         end associate
         worst_stored = max(worst_stored, abs(stored - energy0))
         worst_ledger = max(worst_ledger, abs(ledger))
         if (count_engaged(stepper) >= 2) corners = corners + 1
         iterations = max(iterations, stepper%report%iterations)
      end do
      write (output_unit, '(a,i0,a,es10.3,a,es10.3,a,es10.3,a,i0)') 'whirl, '//label//': ', corners, &
         ' steps at a corner; largest |E + Phi - E0|/E0 ', worst_stored/energy0, '; ledger |E + Phi - W + D - E0|/E0 ', &
         worst_ledger/energy0, '; friction took ', stepper%energy%dissipated_friction/energy0, &
         ' of E0; Newton iterations at most ', iterations
      call t%check_true(label//': the whirl presses two faces at once (a corner) in some steps', corners > 0)
      ! each step rounds E, Phi and the ledger's sums by a few eps of E0: 8 n eps
      call t%check_close(label//': energy ledger E + Phi - W + D = E0', worst_ledger/energy0, 0.0_dp, &
                         8*count*eps, 1.0_dp)
      if (frictional) then
         call t%check_true(label//': friction takes energy', stepper%energy%dissipated_friction > 0.01_dp*energy0)
      else
         call t%check_close(label//': E + Phi conserved (the gradient rule, theta = 1/2, no damping)', &
                            worst_stored/energy0, 0.0_dp, 8*count*eps, 1.0_dp)
      end if
   end subroutine whirl_ledger

   !> How many of the stepper's points carry a spring force in its last step.
   integer function count_engaged(stepper)
      class(time_stepper), intent(in) :: stepper
      count_engaged = count(stepper%holes%f(1:stepper%holes%circles%count) > 0)
   end function count_engaged

   !> Below and above the friction angle of the compliant level of `scene` (docs/method.md,
   !! "Coulomb friction at compliant circles", whose closed form holds exactly at a level).
   subroutine friction_angle(scene)
      type(scene_type), intent(inout) :: scene
      class(time_stepper), allocatable :: stepper
      real(dp) :: k_beam, k_wall, normal, critical, angle, pull, moved, slide, ratio, reach, v_max, bound, phi
      integer :: case, n, j, tip, iterations, count
      count = nint(scene%time%t_end/scene%time%dt)
      associate (b => scene%beam, o => scene%obstacles(1))
         k_wall = o%stiffness
         critical = atan(o%friction*k_wall/(k_wall + 3*b%youngs_modulus*b%inertia/b%length**3))
         do case = 1, 2
            call start_friction_case(scene, case, stepper, k_beam, normal, angle, pull)
            j = size(stepper%u)/2
            tip = stepper%holes%circles%dof(1)
            moved = 0
            ratio = 0
            reach = 0
            v_max = 0
            iterations = 0
            do n = 1, count
               call advance_test_stepper(stepper)
               moved = max(moved, abs(stepper%u(j + tip)))
               reach = max(reach, norm2(stepper%holes%circles%position(1, stepper%u)))
               v_max = max(v_max, abs(stepper%v(tip)), abs(stepper%v(j + tip)))
               iterations = max(iterations, stepper%report%iterations)
               if (stepper%holes%f(1) > 0) ratio = max(ratio, abs(stepper%holes%friction_force(1))/ &
                                                              (o%friction*stepper%holes%f(1)))
            end do
            phi = stepper%holes%friction_force(1)
            write (output_unit, '(a,f12.8,a,f12.8,a,es11.3,a,es11.3,a,es11.3,a,f18.15,a,i0)') 'level: angle ', &
               angle*180/acos(-1.0_dp), ' deg (critical ', critical*180/acos(-1.0_dp), '): largest |w(L)| ', moved, &
               ' m; friction force ', phi, ' N; wall force ', stepper%holes%f(1), ' N; largest |phi|/(mu f) ', ratio, &
               '; Newton iterations at most ', iterations
            if (case == 1) then
               ! each sticking step's tangential end velocity is a Newton residual: 16 eps of
               ! the velocities, or the last update moved the tip by 1024 eps of its reach
               ! (|(v, w)| + |b|, b = 0); summed over the steps
               bound = count*(16*eps*v_max*scene%time%dt + 1024*eps*reach)
               call t%check_close('level: below the friction angle the tip does not move along it', moved, 0.0_dp, &
                                  bound, 1.0_dp)
               ! the stuck tip takes the pull whole (t = (0, -1): phi = F_t), to the spring's
               ! force at Newton's floor, k 1024 eps of the reach
               call t%check_close('level: below it the friction force is the whole pull', phi, pull, &
                                  1024*k_wall*eps*reach, pull)
               call t%check_true('level: below it the friction stays inside the bound', ratio < 1)
            else
               slide = abs(stepper%u(j + tip))
               write (output_unit, '(a,es12.5,a,es12.5,a)') 'level: slide ', slide, ' m, quasi-static ', &
                  (pull - o%friction*normal)/k_beam, ' m'
               ! the quasi-static slide is the limit of a slow ramp; the damped beam's slide
               ! ends where the tip's velocity first vanishes (1.5 % beyond it at the circle)
               call t%check_close('level: above it the tip slides by (F_t - mu f)/k_b', slide, &
                                  (pull - o%friction*normal)/k_beam, 0.1_dp, (pull - o%friction*normal)/k_beam)
               ! at the bound mu f to the floor of f itself: a slow slide keeps p1 close to p0,
               ! where the discrete gradient's quotient (Phi(p1) - Phi(p0))/(p1 - p0) keeps
               ! eps/1e-5 of f (`step_force` takes the midpoint below a relative 1e-5)
               call t%check_close('level: while it slides its friction is at the bound mu f', ratio, 1.0_dp, &
                                  eps/1e-5_dp, 1.0_dp)
            end if
         end do
      end associate
   end subroutine friction_angle
end program test_compliant_faces
