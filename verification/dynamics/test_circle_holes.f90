!> Verification of circular holes in the cross-section of a beam of two planes (issue 21;
!! docs/method.md, "Circular obstacles"), on verification/dynamics/circle_planar.nml:
!! (1) planar reduction: with loads and initial data in y, the beam in a hole of radius R
!!     equals the planar beam between two levels at -R and +R (its planar twin, made in
!!     code) at every step: the same points held with the same impulses, y to round-off
!!     and z exactly 0 (the circle's normal at a point on the y axis is +-e_y);
!! (2) a tube whirling in a centred frictionless hole, e = 1, theta = 1/2, no damping:
!!     the discrete energy is conserved to round-off over 1e5 steps (Newton's law with
!!     e = 1 makes each impulse's work p h.(V^{n+1} + V^n)/2 vanish), and the discrete
!!     angular momentum about the axis too: the impulses are radial at the step's midpoint
!!     (the normal's fixed point, docs/method.md), so they leave it unchanged (docs/
!!     theory.md section 11); the fixed point converges in every step;
!! (3) the same whirl in a compliant, undamped hole: E + Phi and L conserved to round-off
!!     over 1e5 steps (the spring's force is the discrete gradient of its potential along
!!     the midpoint's direction, docs/method.md);
!! and (1) again with compliant stops (the circle's radial spring against the levels'; a
!! compliant circle along the beam against levels along it, their stiffness per length
!! shared among the nodes alike), with
!! a square hole (a polygon of 4 faces) and with the square turned by 45 degrees and the
!! data along 45 degrees (y and z the twin's times cos 45 and sin 45).
program test_circle_holes
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_planes, only: direction_shares
   use vibrobeam_problem, only: run_problem
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, &
      start_test_stepper, advance_test_stepper, angular_momentum, start_planar_twins, hole_levels, &
      advance_planar_twins
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, whirl, compliant, square
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: stepper
   character(len=512) :: path
   real(dp), parameter :: eps = epsilon(1.0_dp)
   real(dp) :: energy0, moment0, worst, worst_moment, reach, radius
   integer :: n, steps, j, held, solves
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   steps = nint(scene%time%t_end/scene%time%dt)
   radius = scene%obstacles(1)%radius

   ! (1) the planar twin: levels at -R and +R over the same x, rigid and compliant
   call planar_reduction(scene, 'rigid')
   compliant = scene
   compliant%obstacles(1)%stiffness = 1e6_dp
   call planar_reduction(compliant, 'compliant (1e6 N/m)')
   ! a compliant hole along the beam (a long bearing): its stiffness per length shared
   ! among its nodes as the levels' (tributary lengths)
   compliant%obstacles(1)%x_from = 0.4_dp
   compliant%obstacles(1)%stiffness = 2e7_dp
   call planar_reduction(compliant, 'compliant along 0.4..0.5 m (2e7 N/m per m)')
   ! a square hole (a polygon of 4 faces, the first face's normal along y) is the two levels
   ! for data along y; turned by 45 degrees with data along 45 degrees, it is the twin turned
   square = scene
   square%obstacles(1)%shape = 'polygon'
   square%obstacles(1)%sides = 4
   call planar_reduction(square, 'square hole')
   square%obstacles(1)%orientation = 45
   square%initial%direction = 45
   call planar_reduction(square, 'square hole turned by 45 degrees, data along 45 degrees', 45.0_dp)

   ! (2) a whirl in the hole: e = 1, theta = 1/2, no damping, no load
   whirl = scene
   whirl%impact%restitution = 1
   whirl%initial%displacement = 'mode'
   whirl%initial%displacement_amplitude = 0.5_dp*radius
   whirl%initial%velocity_amplitude = 0.6_dp
   whirl%initial%direction = 90
   call prepare_test_scene(whirl, prepared)
   call start_test_stepper(whirl, prepared, stepper)
   energy0 = stepper%kinetic_energy() + stepper%elastic_energy()
   moment0 = angular_momentum(stepper)
   worst = 0
   worst_moment = 0
   held = 0
   reach = 0
   solves = 0
   do n = 1, 100000
      call advance_test_stepper(stepper)
      worst = max(worst, abs(stepper%kinetic_energy() + stepper%elastic_energy() - energy0))
      worst_moment = max(worst_moment, abs(angular_momentum(stepper) - moment0))
      held = held + count(stepper%report%circle_impulse(1:stepper%report%circle_count) > 0)
      reach = max(reach, norm2(stepper%holes%circles%offset(1, stepper%u)))
      solves = max(solves, stepper%report%iterations)
   end do
   write (output_unit, '(a,i0,a,es10.3,a,es10.3,a,es10.3)') 'whirl: ', held, ' impulses; largest |E - E0|/E0 ', &
      worst/energy0, ', |L - L0|/|L0| ', worst_moment/abs(moment0), '; largest |r|/R ', reach/radius
   call t%check_true('the whirl reaches the wall', held > 100)
   call t%check_close('energy conserved in the hole (e = 1, theta = 1/2) over 1e5 steps', worst/energy0, 0.0_dp, &
                      8*1e5_dp*eps, 1.0_dp)
   ! as the energy: each step rounds L by a few eps of its scale, 8 n eps over n steps
   call t%check_close('angular momentum about the axis conserved in the hole over 1e5 steps', &
                      worst_moment/abs(moment0), 0.0_dp, 8*1e5_dp*eps, 1.0_dp)
   write (output_unit, '(a,i0)') 'largest number of LCP solves of the midpoint normal in a step: ', solves
   call t%check_true('the midpoint normal''s fixed point converges in every step (fewer than 50 solves)', solves < 50)

   ! (3) the same whirl in a compliant, undamped hole (1e6 N/m, the 'gradient' rule):
   ! E + Phi and L conserved to round-off over 1e5 steps
   whirl%obstacles(1)%stiffness = 1e6_dp
   call prepare_test_scene(whirl, prepared)
   call start_test_stepper(whirl, prepared, stepper)
   energy0 = stepper%kinetic_energy() + stepper%elastic_energy() + stepper%contact_potential()
   moment0 = angular_momentum(stepper)
   worst = 0
   worst_moment = 0
   reach = 0
   solves = 0
   do n = 1, 100000
      call advance_test_stepper(stepper)
      worst = max(worst, abs(stepper%kinetic_energy() + stepper%elastic_energy() + stepper%contact_potential() - energy0))
      worst_moment = max(worst_moment, abs(angular_momentum(stepper) - moment0))
      reach = max(reach, stepper%holes%circles%penetration(1, stepper%u))
      solves = max(solves, stepper%report%iterations)
   end do
   write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,i0)') 'compliant whirl: largest |E + Phi - E0|/E0 ', &
      worst/energy0, ', |L - L0|/|L0| ', worst_moment/abs(moment0), '; largest penetration / R ', reach/radius, &
      '; Newton iterations at most ', solves
   call t%check_true('the compliant whirl enters the wall', reach > 0.01_dp*radius)
   call t%check_close('E + Phi conserved in the compliant hole (theta = 1/2) over 1e5 steps', worst/energy0, 0.0_dp, &
                      8*1e5_dp*eps, 1.0_dp)
   call t%check_close('angular momentum conserved in the compliant hole over 1e5 steps', worst_moment/abs(moment0), &
                      0.0_dp, 8*1e5_dp*eps, 1.0_dp)
   call t%finish('test_circle_holes')

contains

   !> The beam in the hole of `hole` against its planar twin between levels at -R and +R
   !! (the same stiffness), every step: z exactly 0, y (U and V) within 10 times how far
   !! rounding carries on this trajectory, measured on the twin itself: the largest
   !! difference between the twin and the twin started one ulp faster (its initial
   !! velocity's amplitude the next number up). The two runs round differently (a dense
   !! LCP or Newton solve of the circle's rotated row, the planar projection or springs),
   !! so they differ by their rounding carried on as the twin's own does. Rigid stops: the
   !! same points held in every step, with the same impulses to that tolerance.
   subroutine planar_reduction(hole, label, angle)
      type(scene_type), intent(in) :: hole
      character(len=*), intent(in) :: label
      !> the direction (degrees) of the hole scene's data, when not along y: then y and z
      !! are compared with cos(angle) and sin(angle) times the twin's y
      real(dp), intent(in), optional :: angle
      class(time_stepper), allocatable :: reference, perturbed, stepper
      real(dp) :: deviation, own, scale, impulse_deviation, impulse_scale, tolerance, depth, shares(2)
      integer :: held, k
      logical :: same_points, z_zero
      shares = [1.0_dp, 0.0_dp]
      if (present(angle)) shares = direction_shares(angle)
      call start_planar_twins(hole, hole_levels(hole%obstacles(1)), stepper, reference, perturbed, j)
      deviation = 0
      own = 0
      impulse_deviation = 0
      scale = 0
      impulse_scale = 0
      held = 0
      same_points = .true.
      z_zero = .true.
      depth = 0
      do n = 1, steps
         call advance_planar_twins(stepper, reference, perturbed, shares, deviation, own, scale)
         if (.not. present(angle)) z_zero = z_zero .and. all(abs(stepper%u(j + 1:)) <= 0) .and. &
                                            all(abs(stepper%v(j + 1:)) <= 0)
         do k = 1, stepper%holes%circles%count
            depth = max(depth, stepper%holes%circles%penetration(k, stepper%u))
         end do
         if (hole%obstacles(1)%stiffness > 0) cycle
         ! rigid: a level's point held from below or above is the circle's, with its impulse
         ! upwards (+y) from below and the circle's along its inward normal
         same_points = same_points .and. stepper%report%circle_count == reference%report%active_count
         if (.not. same_points) cycle
         do k = 1, reference%report%active_count
            same_points = same_points .and. stepper%holes%circles%node(stepper%report%circle_active(k)) == &
                          reference%contacts%node(reference%report%active(k))
            impulse_deviation = max(impulse_deviation, abs(abs(stepper%report%circle_impulse(k)) - &
                                                           abs(reference%report%impulse(k))))
            impulse_scale = max(impulse_scale, abs(reference%report%impulse(k)))
            if (abs(reference%report%impulse(k)) > 0) held = held + 1
         end do
      end do
      tolerance = 10*max(own, epsilon(1.0_dp)*scale)/scale
      write (output_unit, '(a,es10.3,a,es10.3,a,es10.3)') 'planar twin, '//label//': largest deviation of U, V / '// &
         'their largest ', deviation/scale, '; the twin one ulp faster: ', own/scale, '; tolerance ', tolerance
      if (.not. present(angle)) call t%check_true(label//': z stays exactly 0', z_zero)
      call t%check_close(label//': y (U and V) equals the planar twin''s at every step', deviation/scale, 0.0_dp, &
                         tolerance, 1.0_dp)
      if (hole%obstacles(1)%stiffness > 0) then
         write (output_unit, '(a,es10.3,a)') '   largest penetration ', depth, ' m'
         call t%check_true(label//': the stop is entered (the run is not free flight)', depth > 0.01_dp*hole%obstacles(1)%radius)
         return
      end if
      write (output_unit, '(a,i0,a,es10.3)') '   ', held, ' held steps; largest deviation of the impulses ', &
         impulse_deviation/impulse_scale
      call t%check_true(label//': the twin holds points (the test is not free flight)', held > 100)
      call t%check_true(label//': the circle holds the same points as the two levels at every step', same_points)
      call t%check_close(label//': the impulses equal the planar twin''s', impulse_deviation/impulse_scale, 0.0_dp, &
                         tolerance, 1.0_dp)
   end subroutine planar_reduction
end program test_circle_holes
