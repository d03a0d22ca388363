!> Verification of Coulomb friction at a compliant circle (issue 21; docs/method.md,
!! "Coulomb friction at compliant circles"), on verification/dynamics/compliant_friction.nml:
!! (1) the friction angle, a closed form: a normal tip force F_n presses the tube's tip
!!     into the wall (stiffness k), which at rest carries f = F_n k/(k + k_b) of it, k_b =
!!     3 E I/L^3 the cantilever's tip stiffness (exact on Hermite elements); then a
!!     tangential tip force F_t is ramped in. While the tip sticks it takes F_t whole
!!     (|phi| = F_t, nothing moves along z), which Coulomb allows while F_t <= mu f: the
!!     critical angle is tan a* = F_t/F_n = mu k/(k + k_b). At a = a* (1 - 1e-3) the tip
!!     does not move along the wall (to round-off, bound below) and its friction force is
!!     F_t; at a = a* (1 + 1e-3) it slides, by about s* = (F_t - mu f)/k_b (where the
!!     beam's elastic force takes the excess), its friction at the bound mu f while it
!!     slides. Wear (`support_wear`) over the ramp and hold: contact fraction 1, the
!!     sliding fraction the steps whose end velocity along the wall is beyond Newton's
!!     floor (0 below the angle), the work rate (1/T) sum f dt |v_t| from the states;
!! (2) the energy ledger with friction: a tube whirling in a centred compliant hole,
!!     mu = 0.2, theta = 1/2: E + Phi - W + D (friction, contact damping, time
!!     discretization) stays E_0 to round-off over 2e4 steps, and the dissipated friction
!!     equals the sum over the steps of -r_T t.(V^{n+1} + V^n)/2, r_T the reported
!!     tangential impulse, t and the velocities recomputed here from the states;
!! (3) mu = 1e-300 (the frictional Newton iteration, its friction force mu f at most
!!     1e-297 N) gives the frictionless whirl to round-off, and mu = 0 given is the run
!!     without friction given, bit for bit (mu = 0 keeps the frictionless step);
!! (4) a stiff wall (1e9 N/m) with mu = 5 under the whirl: the step converges and the
!!     ledger closes (nothing wild).
program test_compliant_friction
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_schema_visitor, only: unset
   use vibrobeam_kinds, only: int64
   use vibrobeam_support_wear, only: support_wear
   use vibrobeam_statistics_layout, only: wear_quantities
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, &
      start_test_stepper, advance_test_stepper, same_bits, start_friction_case
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, whirl, other
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: stepper, twin
   character(len=512) :: path
   real(dp), parameter :: eps = epsilon(1.0_dp)
   real(dp) :: k_beam, k_wall, normal, angle, pull, moved(2), slide, phi(2), v_max, bound, ratio(2)
   real(dp) :: energy0, worst, ledger, sum_friction, sum_abs, largest, difference
   integer :: n, steps, case, tip, j, iterations, whirl_steps, new(1), count
   logical :: same
   type(support_wear) :: wear(2)
   real(dp) :: wear_value(1, wear_quantities), wear_error(1, wear_quantities), work_rate
   integer :: slid, first, at_bound
   real(dp) :: r0(2), r1(2), outward(2), tangent(2)
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   steps = nint(scene%time%t_end/scene%time%dt)

   ! (1) below and above the friction angle of the compliant wall
   associate (o => scene%obstacles(1))
      k_wall = o%stiffness
      do case = 1, 2
         call start_friction_case(scene, case, stepper, k_beam, normal, angle, pull)
         j = size(stepper%u)/2
         tip = stepper%holes%circles%dof(1)
         ! the wear window: from the ramp's start (0.02 s) to the end, the steps first, first + 1, ... (to the end)
         ! (the window from the state of step first - 1)
         first = nint(0.02_dp/scene%time%dt) + 1
         call wear(case)%init(stepper, stepper%v, 1e-12_dp, int(first - 1, int64), [-1.0_dp])
         slid = 0
         at_bound = 0
         work_rate = 0
         moved(case) = 0
         v_max = 0
         iterations = 0
         ratio(case) = 0
         do n = 1, steps
            r0 = stepper%holes%circles%offset(1, stepper%u)
            call advance_test_stepper(stepper)
            call wear(case)%observe_step(stepper, new, count)
            ! independently of the friction force: a step slid when the tip's end velocity
            ! along the wall, t.V^{n+1} (where Coulomb's law is posed), is beyond what a
            ! sticking step leaves, Newton's floor 1024 eps (|r| + R)/(dt theta); the work
            ! rate sums f dt |v_t|, v_t = t.(r1 - r0)/dt = t.V^{n+theta}
            if (n >= first) then
               r1 = stepper%holes%circles%offset(1, stepper%u)
               outward = (r0 + r1)/norm2(r0 + r1)
               tangent = [outward(2), -outward(1)]
               if (abs(dot_product(tangent, [stepper%v(tip), stepper%v(j + tip)])) > &
                   1024*eps*(norm2(r0) + o%radius)/(scene%time%dt/2)) then
                  slid = slid + 1
               else if (abs(stepper%holes%friction_force(1)) >= o%friction*stepper%holes%f(1)*(1 - 1e-9_dp)) then
                  at_bound = at_bound + 1   ! both stick and slip: at the bound, not moving
               end if
               work_rate = work_rate + stepper%holes%f(1)*abs(dot_product(tangent, r1 - r0))
            end if
            moved(case) = max(moved(case), abs(stepper%u(j + tip)))
            v_max = max(v_max, abs(stepper%v(tip)), abs(stepper%v(j + tip)))
            iterations = max(iterations, stepper%report%iterations)
            if (stepper%holes%f(1) > 0) ratio(case) = max(ratio(case), abs(stepper%holes%friction_force(1))/ &
                                                                     (o%friction*stepper%holes%f(1)))
         end do
         phi(case) = stepper%holes%friction_force(1)
         call wear(case)%result(wear_value, wear_error)
         work_rate = work_rate/((steps - first + 1)*scene%time%dt)
         write (output_unit, '(a,i0,a,i0,a,f10.6,a,f10.6,a,es12.5,a,es12.5,a)') 'wear: ', slid, ' steps slid, ', &
            at_bound, ' at the bound without moving; sliding fraction ', &
            wear_value(1, 5), ', contact fraction ', wear_value(1, 4), '; work rate ', wear_value(1, 1), &
            ' W (from the states ', work_rate, ' W)'
         ! the fractions count whole steps (exact up to the division's rounding)
         call t%check_close('wear: contact fraction 1', wear_value(1, 4), 1.0_dp, 4*eps, 1.0_dp)
         ! a step at the bound whose end velocity is below the floor is both stick and slip
         ! (the law's boundary): wear counts it as sliding
         call t%check_close('wear: sliding fraction = the steps the tip moved along the wall (and at the bound)', &
                            wear_value(1, 5), real(slid + at_bound, dp)/(steps - first + 1), 4*eps, 1.0_dp)
         if (case == 2) then
            slide = abs(stepper%u(j + tip))
            write (output_unit, '(a,es12.5,a,es12.5,a)') 'slide ', slide, ' m, closed form ', &
               (pull - scene%obstacles(1)%friction*normal)/k_beam, ' m'
         end if
         write (output_unit, '(a,f12.8,a,es11.3,a,es11.3,a,es11.3,a,f18.15,a,i0)') 'angle ', angle*180/acos(-1.0_dp), &
            ' deg: largest |w(L)| ', moved(case), ' m; friction force ', phi(case), ' N; wall force ', &
            stepper%holes%f(1), ' N; largest |phi|/(mu f) ', ratio(case), '; Newton iterations at most ', iterations
         if (case == 1) then
            ! sticking, each step's tangential end velocity is a Newton residual: at most 16
            ! eps of the velocities (v_max), or the update that stopped Newton moved the tip by
            ! at most 1024 eps of its distance from the centre (R); summed over the steps
            bound = steps*(16*eps*v_max*scene%time%dt + 1024*eps*o%radius)
            call t%check_close('below the friction angle the tip does not move along the wall', moved(1), 0.0_dp, &
                               bound, 1.0_dp)
            ! the stuck tip takes the pull whole: |phi| = F_t (t = (0, -1) here, so phi = F_t),
            ! as exactly as the residual's floor: the spring's force rounded at k eps R
            call t%check_close('below it the friction force is the whole pull', phi(1), pull, &
                               16*k_wall*eps*o%radius, pull)
            call t%check_true('below it the friction stays inside the bound', ratio(1) < 1)
            call t%check_true('below it no step slides and the wear work rate is 0 to round-off', &
                              slid == 0 .and. wear_value(1, 1) <= bound*normal/(steps*scene%time%dt))
         else
            ! the slide against the beam's tip stiffness: the quasi-static s* = (F_t - mu f)/k_b is
            ! the limit of a slow ramp; here the slide stops where the tip's velocity first
            ! vanishes while the damped beam still moves (measured 1.5 % beyond s*), and the
            ! wall's curvature turns the normal by s/R = 2e-6: within 10 % of s*
            call t%check_close('above it the tip slides by (F_t - mu f)/k_b', slide, &
                               (pull - o%friction*normal)/k_beam, 0.1_dp, (pull - o%friction*normal)/k_beam)
            ! the work rate from the states: the same sum, each term rounded by a few eps
            ! (the tangent's normalisation, the products), the sums by eps each addition
            call t%check_close('wear work rate = (1/T) sum f dt |v_t|', wear_value(1, 1), work_rate, &
                               (16 + steps - first + 1)*eps, work_rate)
            call t%check_true('above it some steps slide', slid > 0)
            ! while it slides its friction is at the bound: |phi| = mu f, solved to the floor of
            ! the slip rows, the spring's force rounded at k eps R (16 of it, relative to mu f)
            call t%check_close('while it slides its friction is at the bound mu f', ratio(2), 1.0_dp, &
                               16*k_wall*eps*o%radius/(o%friction*normal), 1.0_dp)
         end if
      end do
   end associate

   ! (2) a whirl in a centred compliant hole with friction
   whirl = scene
   whirl%beam%rayleigh_mass = 0
   whirl%obstacles(1)%radius = 1e-3_dp
   whirl%obstacles(1)%center_y = 0
   whirl%obstacles(1)%friction = 0.2_dp
   whirl%load%point_force = 0
   whirl%forces%load(1)%amplitude = 0
   whirl%initial%displacement = 'mode'
   whirl%initial%displacement_amplitude = 0.5_dp*whirl%obstacles(1)%radius
   whirl%initial%velocity = 'mode'
   whirl%initial%velocity_amplitude = 0.6_dp
   whirl%initial%direction = 90
   whirl_steps = 20000
   call whirl_ledger(whirl, 'whirl, mu = 0.2, k = 1e6 N/m')

   ! (3) a vanishing mu through the frictional path, and mu = 0 given
   other = whirl
   other%obstacles(1)%friction = 0
   call prepare_test_scene(other, prepared)
   call start_test_stepper(other, prepared, twin)
   other%obstacles(1)%friction = 1e-300_dp   ! positive, so the frictional path, but mu f is 0 to the last bit
   call prepare_test_scene(other, prepared)
   call start_test_stepper(other, prepared, stepper)
   same = .true.
   difference = 0
   largest = 0
   do n = 1, whirl_steps
      call advance_test_stepper(twin)
      call advance_test_stepper(stepper)
      difference = max(difference, maxval(abs(stepper%u - twin%u)))
      largest = max(largest, maxval(abs(twin%u)))
   end do
   write (output_unit, '(a,es11.3,a,es11.3)') 'mu = 1e-300 against mu = 0: largest |dU| ', difference, &
      ' of |U| ', largest
   ! the two paths solve the same equations (phi = 0) with matrices of 2 and 3 rows: round-off
   ! per step, carried by the whirl over the steps: 8 n eps of |U|
   call t%check_close('a vanishing mu gives the frictionless whirl to round-off', difference, 0.0_dp, &
                      8*whirl_steps*eps*largest, 1.0_dp)
   ! friction(1) = 0 given against friction(1) not given (the default 0)
   other = whirl
   other%obstacles(1)%friction = 0
   call prepare_test_scene(other, prepared)
   call start_test_stepper(other, prepared, twin)
   other%obstacles(1)%friction = unset
   call prepare_test_scene(other, prepared)
   call start_test_stepper(other, prepared, stepper)
   do n = 1, whirl_steps
      call advance_test_stepper(twin)
      call advance_test_stepper(stepper)
      same = same .and. all(same_bits(stepper%u, twin%u)) .and. all(same_bits(stepper%v, twin%v))
   end do
   call t%check_true('mu = 0 is the frictionless compliant run bit for bit', same)

   ! (4) a stiff wall with a large mu
   other = whirl
   other%obstacles(1)%stiffness = 1e9_dp
   other%obstacles(1)%friction = 5
   other%time%dt = 1e-6_dp
   whirl_steps = 20000
   call whirl_ledger(other, 'whirl, mu = 5, k = 1e9 N/m')
   call t%finish('test_compliant_friction')

contains

   !> Step `whirl` for whirl_steps: the ledger E + Phi - W + D - E_0 at every step, and the
   !! friction's energy against -sum r_T t.(V^{n+1} + V^n)/2 recomputed from the states.
   subroutine whirl_ledger(whirl, name)
      type(scene_type), intent(in) :: whirl
      character(len=*), intent(in) :: name
      real(dp) :: r0(2), r1(2), v0(2), v1(2), outward(2), tangent(2), term
      integer :: a
      call prepare_test_scene(whirl, prepared)
      call start_test_stepper(whirl, prepared, stepper)
      j = size(stepper%u)/2
      tip = stepper%holes%circles%dof(1)
      energy0 = stepper%kinetic_energy() + stepper%elastic_energy() + stepper%contact_potential()
      worst = 0
      sum_friction = 0
      sum_abs = 0
      iterations = 0
      do n = 1, whirl_steps
         r0 = stepper%holes%circles%offset(1, stepper%u)
         v0 = [stepper%v(tip), stepper%v(j + tip)]
         call advance_test_stepper(stepper)
         r1 = stepper%holes%circles%offset(1, stepper%u)
         v1 = [stepper%v(tip), stepper%v(j + tip)]
         iterations = max(iterations, stepper%report%iterations)
         do a = 1, stepper%report%circle_count
            outward = (r0 + r1)/norm2(r0 + r1)
            tangent = [outward(2), -outward(1)]
            term = -stepper%report%circle_friction(a)*dot_product(tangent, v1 + v0)/2
            sum_friction = sum_friction + term
            sum_abs = sum_abs + abs(stepper%report%circle_friction(a))*(abs(dot_product(tangent, v1)) + &
                                                                         abs(dot_product(tangent, v0)))/2
         end do
         associate (e => stepper%energy)
            ledger = stepper%kinetic_energy() + stepper%elastic_energy() + stepper%contact_potential() - e%work + &
                     e%dissipated_impacts + e%dissipated_friction + e%dissipated_damping + &
                     e%dissipated_contact_damping + e%dissipated_numerical - energy0
         end associate
         worst = max(worst, abs(ledger))
      end do
      write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3,a,i0)') name//': friction took ', &
         stepper%energy%dissipated_friction/energy0, ' of E0 (from the states: ', sum_friction/energy0, &
         '); largest |E + Phi - W + D - E0|/E0 ', worst/energy0, '; time discretization ', &
         stepper%energy%dissipated_numerical/energy0, '; Newton iterations at most ', iterations
      call t%check_true(name//': friction takes energy', stepper%energy%dissipated_friction > 0.01_dp*energy0)
      ! each step rounds E, Phi and the ledger's sums by a few eps of E0: 8 n eps
      call t%check_close(name//': energy ledger with friction', worst/energy0, 0.0_dp, 8*whirl_steps*eps, 1.0_dp)
      ! each term rounded within a few eps of its size (the tangent's normalisation, two
      ! dot products), and each sum's addition by eps of the sum: 8 eps sum|terms| + n eps D
      call t%check_close(name//': dissipated friction = sum of -r_T t.(V^{n+1} + V^n)/2', &
                         stepper%energy%dissipated_friction, sum_friction, &
                         8*eps*sum_abs + whirl_steps*eps*abs(sum_friction), 1.0_dp)
   end subroutine whirl_ledger
end program test_compliant_friction
