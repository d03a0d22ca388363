!> The branch of twice the period, switched to at a period doubling and continued
!! (&periodic switch_branch; issue 20, item 2; docs/method.md, "Branch switching at a
!! period doubling"), against references that do not go through the switch.
!!
!! The scene (period_doubling_switch.nml: period_doubling.nml continued down to 176 rad/s,
!! so that its period-1 branch passes both doublings that bound the period-2 orbits on 4
!! elements) is continued as the analysis does (`continue_branch`, then `switch_branch`).
!! Checked:
!! (a) the period-1 branch holds two located period doublings (det(M + I) through zero, the
!!     map of 1 period); the switched branch (period_multiple 2) ends at each end in a
!!     located branch point (the map of 2 periods' orbit becoming one of 1 period: the test
!!     function rho - sqrt(tolerance)), and each branch point equals the doubling at that
!!     end: two computations on different maps with different test functions. Tolerance:
!!     `locate` stops when its bracket is below 1e-4 of the step (lambda, about linear in
!!     the arclength there, then within 1e-4 of the step's |d lambda|; `bracket_step`), its test function
!!     within 1e-10 or lambda stalls to 1e-9 relative; `locate_rejoin` when two
!!     extrapolations agree to 1e-9 relative or its step is below 1e-4 of the bracketing
!!     one's; and the doubling's det(M + I) is that of a monodromy by differences, whose
!!     multipliers err by up to 3e-4 (docs/method.md, "Finite differences"), which moves
!!     its zero by 3e-4/|d mu/d lambda|; so 1e-4 (|d lambda_1| + |d lambda_2|) + 3e-4/
!!     |d mu/d lambda| + 4e-9 lambda, the d lambda the two bracketing steps', d mu/d lambda
!!     the slope of the largest |mu| between the period-1 points around the doubling (the
!!     orbits' own errors, the corrector tolerance through ||(I - M)^-1||, move lambda by
!!     far less: 1e-9 relative over a slope of order 1). The branch point is found from
!!     the orbits alone (how far the map of 1 period moves them), not the monodromy.
!! (b) the switched branch's point nearest 181 rad/s equals the period-2 orbit plain
!!     shooting finds at its lambda from a transient of 50 periods (period_multiple = 2, as
!!     verification.periodic_marching_period_doubling_orbit, which shows that orbit equals
!!     what time marching settles to), at one of its two phases (x or Phi_1(x)), within
!!     ||(I - M)^-1|| (c^2 tolerance + tolerance + 2 noise) relative in the energy norm at
!!     that lambda: both are fixed points of the same map to their tolerances, the
!!     branch's residual measured in the norm of the switch's start (c = the ratio of the
!!     two forcing frequencies, bounding the ratio of the norms), noise = 8 eps P rho the
!!     round-off of one evaluation (test_periodic_linear); and it is not of period 1
!!     (||Phi_1(x) - x|| > 1e-3 ||x||).
!! (c) stability: every point of the switched branch lies between the two doublings and is
!!     stable, every point of the period-1 branch between them unstable (where the
!!     time-marching diagram reads period 2, verification.period_doubling); the shooting's
!!     orbit is stable and its largest |mu| equals the branch point's to 1e-3 (the
!!     monodromy by differences errs by up to 3e-4 in the multipliers: docs/method.md).
!! Usage: test_switched_branch SCENE.nml
program test_switched_branch
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: outcome_ok
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_periodic_analysis, only: find_periodic_orbit, periodic_orbit
   use vibrobeam_period_map, only: map_image, jacobian_none, period_map
   use vibrobeam_continuation, only: continuation_branch, continue_branch
   use vibrobeam_continuation_map, only: scene_at_parameter
   use vibrobeam_branch_point, only: kind_doubling, kind_branch_point
   use vibrobeam_branch_switch, only: switched_branch, switch_branch
   use vibrobeam_periodic_reference, only: energy_gram, energy_norm, cancellation, fixed_point_condition
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, local
   type(run_problem) :: prepared, at_point
   type(continuation_branch) :: first
   type(switched_branch) :: second
   type(periodic_orbit) :: shot
   type(period_map) :: single
   type(map_image) :: image
   character(len=512) :: path, errmsg
   real(dp), allocatable :: gram(:, :), doublings(:), rejoins(:), x(:)
   real(dp) :: tolerance, error, other, bound, noise, c, size_of_x, repeat, modulus, shot_modulus, low, high
   integer :: stat, j, nearest, end_index(2), n
   integer, allocatable :: where_doubling(:), where_rejoin(:)

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call continue_branch(scene, prepared, first, stat, errmsg)
   if (stat /= 0) error stop 'continue_branch'
   call switch_branch(scene, first, second, stat, errmsg)
   if (stat /= 0) error stop 'switch_branch'
   call t%check_true('the period-1 branch ends ok', first%status == outcome_ok, trim(first%failure))
   call t%check_true('the switch found the period-2 orbit and continued it', &
                     second%switched .and. second%branch%status == outcome_ok, trim(second%note)//trim(second%branch%failure))
   if (.not. second%switched) call t%finish('test_switched_branch')

   ! ---- (a) the branch points of the switched branch at the period-1 branch's doublings ----
   associate (found => first%bifurcations, joined => second%branch%bifurcations, points => second%branch%points)
      where_doubling = pack([(j, j=1, size(found))], found%kind == kind_doubling .and. found%located)
      where_rejoin = pack([(j, j=1, size(joined))], joined%kind == kind_branch_point .and. joined%located)
      doublings = found(where_doubling)%parameter
      rejoins = joined(where_rejoin)%parameter
      write (*, '(a,*(f14.8))') 'period-1 branch: located period doublings at ', doublings
      write (*, '(a,i0,a,f6.3,a,*(f14.8))') 'switched branch: ', size(points), ' points (move c = ', second%move, &
         '), located branch points at ', rejoins
      call t%check_true('the period-1 branch has two located period doublings', size(doublings) == 2)
      call t%check_true('the switched branch ends in two located branch points', size(rejoins) == 2)
      if (size(doublings) /= 2 .or. size(rejoins) /= 2) call t%finish('test_switched_branch')
      call t%check_close('the switch starts at the first located doubling', second%doubling, doublings(1), 0.0_dp)
      ! the end towards the doubling comes first (index 0: before the first point)
      end_index = [joined(where_rejoin(1))%index, joined(where_rejoin(2))%index]
      call t%check_true('the switched branch''s branch points lie at its two ends', &
                        end_index(1) == 0 .and. end_index(2) == size(points))
      do j = 1, 2
         tolerance = 1e-4_dp*(bracket_step(first%points, found(where_doubling(j))%index) + &
                              bracket_step(points, end_index(j))) + 4e-9_dp*doublings(j) + &
                     3e-4_dp/multiplier_slope(first%points, found(where_doubling(j))%index)
         write (*, '(a,i0,a,es10.3,a,es10.3,a)') 'doubling ', j, ': branch point - doubling = ', &
            rejoins(j) - doublings(j), ' rad/s (tolerance ', tolerance, ')'
         call t%check_close('the switched branch''s branch point equals the period-1 branch''s doubling', &
                            rejoins(j), doublings(j), tolerance, scale=1.0_dp)
      end do
      low = min(doublings(1), doublings(2))
      high = max(doublings(1), doublings(2))

      ! ---- (c) stability along both branches between the doublings ----
      do j = 1, size(points)
         modulus = hypot(points(j)%multipliers(1, 1), points(j)%multipliers(2, 1))
         call t%check_true('switched point between the doublings and stable', points(j)%parameter > low .and. &
                           points(j)%parameter < high .and. modulus < 1)
      end do
      do j = 1, size(first%points)
         if (first%points(j)%parameter <= low .or. first%points(j)%parameter >= high) cycle
         modulus = hypot(first%points(j)%multipliers(1, 1), first%points(j)%multipliers(2, 1))
         call t%check_true('period-1 point between the doublings unstable', modulus > 1)
      end do

      ! ---- (b) the point nearest 181 rad/s against plain shooting from a transient ----
      nearest = minloc(abs(points%parameter - 181.0_dp), dim=1)
      x = points(nearest)%x
      modulus = hypot(points(nearest)%multipliers(1, 1), points(nearest)%multipliers(2, 1))
      call scene_at_parameter(scene, first%axis, int(scene%periodic%steps_per_period, kind(first%orbit_steps)), &
                              points(nearest)%parameter, local, at_point, stat, errmsg)
      if (stat /= 0) error stop 'scene_at_parameter'
      local%periodic%parameter = ''
      local%periodic%period_multiple = 2
      local%periodic%transient_periods = 50
      call find_periodic_orbit(local, at_point, shot, stat, errmsg)
      call t%check_true('plain shooting finds the period-2 orbit', stat == 0 .and. shot%converged, &
                        trim(errmsg)//trim(shot%failure))
      if (.not. shot%converged) call t%finish('test_switched_branch')
      single = shot%map
      single%steps = shot%map%steps/2
      call single%evaluate(local, at_point, shot%x, jacobian_none, image, stat, errmsg)
      if (stat /= 0 .or. image%status /= outcome_ok) error stop 'map evaluation failed'
      gram = energy_gram(at_point, shot%map%omega)
      size_of_x = energy_norm(gram, shot%x)
      error = energy_norm(gram, x - shot%x)/size_of_x
      other = energy_norm(gram, x - image%state)/size_of_x
      repeat = energy_norm(gram, image%state - shot%x)/size_of_x
      n = size(x)
      noise = 8*epsilon(1.0_dp)*real(shot%map%steps, dp)*cancellation(gram, shot%x)
      c = max(points(nearest)%parameter/second%start, second%start/points(nearest)%parameter)
      bound = fixed_point_condition(gram, shot%image%jacobian)*((c**2 + 1)*scene%periodic%tolerance + 2*noise)
      shot_modulus = hypot(shot%multipliers(1, 1), shot%multipliers(2, 1))
      write (*, '(a,f10.5,a,es10.3,a,es10.3,a,es10.3,a,es10.3)') 'at ', points(nearest)%parameter, &
         ' rad/s: branch point - shot orbit ', min(error, other), ' (other phase ', max(error, other), &
         '; bound ', bound, '); ||Phi_1(x) - x||/||x|| ', repeat
      write (*, '(a,f9.6,a,f9.6)') 'largest |mu|: branch ', modulus, ', shooting ', shot_modulus
      call t%check_close('the switched branch''s point equals the shot period-2 orbit (energy norm, relative)', &
                         min(error, other), 0.0_dp, bound, scale=1.0_dp)
      call t%check_true('the bound tells orbits apart (< 1e-6)', bound < 1e-6_dp)
      call t%check_true('the shot orbit is not of period 1 (||Phi_1(x) - x|| > 1e-3 ||x||)', repeat > 1e-3_dp)
      call t%check_true('the shot orbit is stable', shot_modulus < 1)
      call t%check_close('its largest |mu| equals the branch point''s', modulus, shot_modulus, 1e-3_dp, scale=1.0_dp)
   end associate
   call t%finish('test_switched_branch')

contains

   !> |d lambda| of the step after point `index` (the one that bracketed a bifurcation):
   !! from point index to index + 1; when that step's end was not kept (beyond a bound, or
   !! the branch ended there: index 0 or the last point), 1.5 times the step next to it
   !! (a step grows by at most 1.5 times from one point to the next).
   real(dp) function bracket_step(points, index)
      use vibrobeam_branch_point, only: branch_point
      type(branch_point), intent(in) :: points(:)
      integer, intent(in) :: index
      integer :: i
      i = min(max(index, 1), size(points) - 1)
      bracket_step = abs(points(i + 1)%parameter - points(i)%parameter)
      if (index < 1 .or. index >= size(points)) bracket_step = 1.5_dp*bracket_step
   end function bracket_step

   !> |d |mu|/d lambda| of the largest multiplier between point `index` and the next (the
   !! point before when there is no next).
   real(dp) function multiplier_slope(points, index)
      use vibrobeam_branch_point, only: branch_point
      type(branch_point), intent(in) :: points(:)
      integer, intent(in) :: index
      integer :: i
      i = min(max(index, 1), size(points) - 1)
      multiplier_slope = abs((hypot(points(i + 1)%multipliers(1, 1), points(i + 1)%multipliers(2, 1)) - &
                              hypot(points(i)%multipliers(1, 1), points(i)%multipliers(2, 1)))/ &
                             (points(i + 1)%parameter - points(i)%parameter))
   end function multiplier_slope
end program test_switched_branch
