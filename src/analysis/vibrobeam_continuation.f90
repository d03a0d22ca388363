!> Pseudo-arclength continuation of the fixed point of the period map in (x, lambda)
!! (&periodic parameter; docs/method.md, "Continuation of periodic orbits"): from the orbit
!! Newton's method finds at the scene's value of the parameter (`find_periodic_orbit`),
!! each next point is predicted along the branch's tangent, the null vector of
!! [M - I, dPhi/dlambda], and corrected by Newton's method on the bordered system
!! (Phi(x, lambda) - x = 0 and the arclength condition; LAPACK dgesv); the step halves
!! when the corrector fails and grows when it converges easily. Along the branch: the
!! Floquet multipliers, stability, and the sign changes of four test functions (fold,
!! period doubling, Neimark-Sacker, grazing; `vibrobeam_branch_point`), and on a branch
!! of an even period_multiple 2k a fifth (where the orbit becomes one of k periods: a
!! branch point, which ends the branch), each located by regula falsi on the arclength.
!!
!! lambda is any input a sweep may vary (`vibrobeam_continuation_axis`), set through the
!! sweep's setter (`set_real_input`); each evaluation at a new lambda builds its problem
!! anew (`build_problem`), with dt = T/P for the P steps per forcing period of the start,
!! so that a forcing frequency can be continued in with P dt = T kept.
module vibrobeam_continuation
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_ok, stat_failure, outcome_ok, outcome_failed, outcome_interrupted
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type, forcing_period_steps
   use vibrobeam_scene_values, only: set_real_input
   use vibrobeam_schema_visitor, only: is_unset
   use vibrobeam_sweep_axis, only: sweep_axis
   use vibrobeam_continuation_axis, only: resolve_continuation
   use vibrobeam_periodic_settings, only: forcing_frequency, period_step
   use vibrobeam_problem, only: run_problem
   use vibrobeam_continuation_map, only: continuation_context, omega_at, problem_at, evaluate_at, &
      parameter_derivative, residual
   use vibrobeam_period_map, only: period_map, map_image, jacobian_none, jacobian_linearised, jacobian_differences, &
      difference_fraction
   use vibrobeam_periodic_analysis, only: find_periodic_orbit, periodic_orbit, floquet_multipliers
   use vibrobeam_signals, only: interrupt_requested
   use vibrobeam_branch_point, only: branch_point, bifurcation_point, bifurcation_names, test_count, &
      set_test_functions, changes_sign, half_period_test, kind_fold, kind_branch_point
   use vibrobeam_lapack, only: dgesv
   implicit none
   private
   public :: continuation_branch, branch_point, bifurcation_point, continue_branch, bifurcation_names
   ! (the step's rules, which the backbone of an autonomous orbit follows too: `vibrobeam_backbone`)
   public :: corrector_iterations, easy_iterations, step_growth, largest_step, max_halvings

   !> Newton iterations of one corrector before its step is halved: from a predictor on
   !! the tangent the corrector converges quadratically in 2 to 4; more means the step is
   !! too long for the branch's curvature.
   integer, parameter :: corrector_iterations = 8
   !> A corrector that converged in at most this many iterations lets the step grow.
   integer, parameter :: easy_iterations = 3
   !> Growth of the step after an easy corrector, and its largest multiple of the first step.
   real(dp), parameter :: step_growth = 1.5_dp, largest_step = 10
   !> Halvings of the first step before the branch is given up.
   integer, parameter :: max_halvings = 10
   !> Regula falsi iterations that locate a bifurcation between two branch points, and
   !! when it stops: the bracket below locate_bracket of the arclength step (lambda at a
   !! fold is stationary in s: its error is of the bracket's square), or a test function
   !! within locate_tolerance of 0 (the unit tangent's component, det(M + I), |mu|^2 - 1;
   !! the smallest clearance, in m).
   integer, parameter :: locate_iterations = 12
   !! Or when two trials in a row give lambda within locate_lambda of each other,
   !! relative: at a fold, where the test function's zero is no sharper than the noise of
   !! a monodromy by differences (measured: the bracket of the bundled scene's upper fold
   !! stalls at 2e-3 of the step while lambda no longer moves in its 7th digit).
   real(dp), parameter :: locate_bracket = 1e-4_dp, locate_tolerance = 1e-10_dp, locate_lambda = 1e-9_dp
   !> The branch and how its computation went.
   type :: continuation_branch
      type(sweep_axis) :: axis                         !! the parameter
      type(branch_point), allocatable :: points(:)
      type(bifurcation_point), allocatable :: bifurcations(:)
      integer :: status = outcome_ok                   !! outcome_ok, outcome_failed, outcome_interrupted
      character(len=512) :: failure = ''
      character(len=16) :: monodromy = ''
      integer(int64) :: steps_taken = 0                !! every time step of every evaluation
      integer(int64) :: orbit_steps = 0                !! steps of one orbit, k P
      integer :: first_iterations = 0                  !! Newton iterations of the first orbit
      !> the backbone of an autonomous orbit (`vibrobeam_backbone`): each point's
      !! stable_margin written, no test functions
      logical :: backbone = .false.
   end type continuation_branch

contains

   !> The branch through the orbit of `scene` (kind = 'periodic', &periodic parameter
   !! given; `prepared` its problem) in `branch`. stat /= 0 (errmsg): invalid continuation
   !! input, a stepper or problem that cannot be made; a branch that ends early is
   !! branch%status = outcome_failed with the reason, its points kept. `start_state` (optional,
   !! (U, V)): Newton's start for the first orbit instead of the scene's transient (a
   !! branch switch, `vibrobeam_branch_switch`).
   subroutine continue_branch(scene, prepared, branch, stat, errmsg, start_state)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(continuation_branch), intent(out) :: branch
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), intent(in), optional :: start_state(:)
      type(continuation_context) :: run
      type(periodic_orbit) :: orbit
      type(branch_point) :: first, next
      real(dp) :: start, first_step, ds, lambda_scale
      real(dp), allocatable :: seed(:)
      logical :: converged, beyond, rejoins
      integer :: halvings, m, before, kind, kept
      call resolve_continuation(scene, branch%axis, start, stat, errmsg)
      if (stat /= 0) return
      run%scene = scene
      run%scene%initial%from_file = ''
      run%axis = branch%axis
      run%period_steps = forcing_period_steps(scene)
      run%reference = prepared
      run%tolerance = scene%periodic%tolerance
      allocate (branch%points(0), branch%bifurcations(0))
      call find_periodic_orbit(scene, prepared, orbit, stat, errmsg, start=start_state)
      if (stat /= 0) return
      branch%monodromy = orbit%monodromy
      branch%first_iterations = orbit%iterations
      run%map = orbit%map
      if (mod(scene%periodic%period_multiple, 2) == 0) then
         run%half_map = orbit%map
         run%half_map%steps = orbit%map%steps/2
         run%half_map%steps_taken = 0
      end if
      branch%orbit_steps = orbit%map%steps
      run%jacobian = merge(jacobian_linearised, jacobian_differences, orbit%monodromy == 'linearised')
      if (.not. orbit%converged .or. orbit%status /= outcome_ok) then
         branch%status = merge(outcome_interrupted, outcome_failed, orbit%status == outcome_interrupted)
         branch%failure = 'the first orbit, at '//trim(branch%axis%parameter)//' = '//real_text(start)//': '// &
                          trim(orbit%failure)
         branch%steps_taken = run%map%steps_taken
         return
      end if
      ! the weights of the scaled coordinates (`point_scale`): each unknown by the square
      ! root of its diagonal weight in the energy norm (K + Omega^2 M for U, M for V);
      ! lambda relative to the parameter's range (or the larger of its start and the step)
      m = size(orbit%x)
      allocate (run%weights(m + 1))
      run%weights(1:m) = run%map%weights(prepared)
      lambda_scale = max(abs(start), abs(scene%periodic%step))
      if (.not. (is_unset(scene%periodic%parameter_min) .or. is_unset(scene%periodic%parameter_max))) then
         if (scene%periodic%parameter_max > scene%periodic%parameter_min) &
            lambda_scale = scene%periodic%parameter_max - scene%periodic%parameter_min
      end if
      run%weights(m + 1) = 1/lambda_scale
      ! the first point: its tangent oriented by the sign of step
      allocate (seed(m + 1), source=0.0_dp)
      seed(m + 1) = sign(run%weights(m + 1), scene%periodic%step)
      first%x = orbit%x
      first%parameter = start
      call finish_point(run, orbit%image, seed, first, stat, errmsg)
      if (stat /= 0) return
      if (first%iterations < 0) then
         branch%status = outcome_failed
         branch%failure = 'the tangent at the first orbit: '//trim(errmsg)
         stat = 0
         errmsg = ''
         branch%steps_taken = run%map%steps_taken
         return
      end if
      branch%points = [first]
      first_step = abs(scene%periodic%step)*run%weights(m + 1)
      ds = first_step
      halvings = 0
      do while (size(branch%points) < scene%periodic%max_points)
         if (interrupt_requested()) then
            branch%status = outcome_interrupted
            exit
         end if
         associate (last => branch%points(size(branch%points)))
            if (allocated(last%half_shift)) run%shift_reference = last%half_shift
            call correct(run, last, ds, next, converged, stat, errmsg)
         end associate
         if (stat /= 0) return
         if (.not. converged) then
            ds = ds/2
            halvings = halvings + 1
            if (halvings > max_halvings) then
               branch%status = outcome_failed
               branch%failure = 'the branch could not be continued beyond point '//integer_text(size(branch%points))// &
                                ' ('//trim(branch%axis%parameter)//' = '// &
                                real_text(branch%points(size(branch%points))%parameter)//'): the corrector failed '// &
                                'with steps down to 2^-'//integer_text(max_halvings)//' of the first ('// &
                                trim(errmsg)//')'
               errmsg = ''
               exit
            end if
            errmsg = ''
            cycle
         end if
         halvings = 0
         ! the point, and each test function's sign change since the point before, located;
         ! a point beyond the bounds ends the branch unkept, but a bifurcation between the
         ! last point and it that lies within them is kept; so does a branch point of the
         ! 2k-period map (the point is on the orbit of k periods; the lambda-tangent's sign
         ! change that comes with it where the branch turns onto the orbit's other phase is
         ! that point, not a fold)
         beyond = outside(scene, next%parameter)
         before = size(branch%points)
         rejoins = changes_sign(branch%points(before)%tests(kind_branch_point), next%tests(kind_branch_point))
         if (.not. (beyond .or. rejoins)) branch%points = [branch%points, next]
         do kind = 1, test_count
            if (kind == kind_fold .and. rejoins) cycle
            if (.not. changes_sign(branch%points(before)%tests(kind), next%tests(kind))) cycle
            kept = size(branch%bifurcations)
            if (kind == kind_branch_point) then
               call locate_rejoin(run, branch%points(before), next, before, branch%bifurcations, stat, errmsg)
            else
               call locate(run, branch%points(before), next, kind, before, branch%bifurcations, stat, errmsg)
            end if
            if (stat /= 0) return
            if (beyond) then
               if (outside(scene, branch%bifurcations(kept + 1)%parameter)) branch%bifurcations = branch%bifurcations(1:kept)
            end if
         end do
         if (beyond .or. rejoins) exit
         if (next%iterations <= easy_iterations) ds = min(step_growth*ds, largest_step*first_step)
      end do
      branch%steps_taken = run%map%steps_taken + run%half_map%steps_taken
      stat = 0
      errmsg = ''

   end subroutine continue_branch

   !> lambda beyond &periodic parameter_min or parameter_max.
   logical function outside(scene, lambda)
      type(scene_type), intent(in) :: scene
      real(dp), intent(in) :: lambda
      outside = .false.
      if (.not. is_unset(scene%periodic%parameter_min)) outside = lambda < scene%periodic%parameter_min
      if (.not. is_unset(scene%periodic%parameter_max)) outside = outside .or. lambda > scene%periodic%parameter_max
   end function outside

   !> Predictor from `base` along its tangent by the arclength `ds` (scaled), corrector
   !! Newton on the bordered system [M - I, Phi_lambda; t^T S] (dx, dlambda) = -(Phi - x, g),
   !! g the arclength condition t . S((x, lambda) - predictor) = 0. `converged` false (the
   !! reason in errmsg, stat 0) when it does not reach the tolerance in
   !! corrector_iterations, its residual grows after the second iteration, or a step fails.
   subroutine correct(run, base, ds, point, converged, stat, errmsg)
      type(continuation_context), intent(inout) :: run
      type(branch_point), intent(in) :: base
      real(dp), intent(in) :: ds
      type(branch_point), intent(out) :: point
      logical, intent(out) :: converged
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(map_image) :: image
      real(dp), allocatable :: predicted(:), z(:), derivative(:), matrix(:, :), rhs(:)
      integer, allocatable :: pivots(:)
      real(dp) :: relative, previous
      integer :: iteration, m, j, info
      logical :: ok
      m = size(base%x)
      converged = .false.
      allocate (predicted(m + 1), z(m + 1))
      predicted(1:m) = base%x + ds*base%tangent(1:m)/base%scale(1:m)
      predicted(m + 1) = base%parameter + ds*base%tangent(m + 1)/base%scale(m + 1)
      z(:) = predicted
      previous = huge(1.0_dp)
      do iteration = 0, corrector_iterations
         call evaluate_at(run, z(1:m), z(m + 1), run%jacobian, image, stat, errmsg)
         if (stat /= 0) return
         if (image%status /= outcome_ok) then
            errmsg = trim(image%failure)
            return
         end if
         relative = residual(run, z(1:m), image)
         if (relative <= run%tolerance) then
            point%x = z(1:m)
            point%parameter = z(m + 1)
            point%step = ds
            call finish_point(run, image, base%tangent*base%scale, point, stat, errmsg)
            point%iterations = iteration
            converged = stat == 0 .and. allocated(point%tangent)
            return
         end if
         if (iteration == corrector_iterations .or. (iteration >= 2 .and. relative > previous)) then
            errmsg = 'corrector residual '//real_text(relative)//' after '//integer_text(iteration)//' iterations'
            return
         end if
         previous = relative
         call parameter_derivative(run, z(1:m), z(m + 1), image, derivative, ok, stat, errmsg)
         if (stat /= 0 .or. .not. ok) return
         allocate (matrix(m + 1, m + 1), rhs(m + 1), pivots(m + 1))
         matrix(1:m, 1:m) = image%jacobian
         do j = 1, m
            matrix(j, j) = matrix(j, j) - 1
         end do
         matrix(1:m, m + 1) = derivative
         matrix(m + 1, :) = base%tangent*base%scale
         rhs(1:m) = z(1:m) - image%state
         rhs(m + 1) = -dot_product(base%tangent*base%scale, z - predicted)
         call dgesv(m + 1, 1, matrix, m + 1, pivots, rhs, m + 1, info)
         if (info /= 0) then
            errmsg = 'the bordered system is singular'
            return
         end if
         z = z + rhs
         deallocate (matrix, rhs, pivots)
      end do
   end subroutine correct

   !> What a converged point carries: multipliers, amplitude, smallest clearance, period,
   !! its tangent (the null vector of [M - I, Phi_lambda], from the bordered system whose
   !! last row is `previous`, the tangent before in the unscaled variables, so that the
   !! branch keeps its direction) in its own scaled coordinates, and the test functions
   !! (`set_test_functions`).
   !! point%iterations = -1 and errmsg when the tangent cannot be taken (stat 0).
   subroutine finish_point(run, image, previous, point, stat, errmsg)
      type(continuation_context), intent(inout) :: run
      type(map_image), intent(in) :: image
      real(dp), intent(in) :: previous(:)   !! (2 J + 1) the previous tangent times its scale
      type(branch_point), intent(inout) :: point
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: derivative(:), matrix(:, :), rhs(:)
      integer, allocatable :: pivots(:)
      integer :: m, j, info
      logical :: ok
      m = size(point%x)
      call floquet_multipliers(image%jacobian, point%multipliers, stat, errmsg)
      if (stat /= 0) return
      point%amplitude = maxval(abs(image%tip(1, :)))
      point%minimum_gap = image%minimum_gap
      point%period = run%map%steps*period_step(omega_at(run, point%parameter), int(run%period_steps))
      call parameter_derivative(run, point%x, point%parameter, image, derivative, ok, stat, errmsg)
      if (stat /= 0) return
      if (.not. ok) then
         point%iterations = -1
         return
      end if
      allocate (matrix(m + 1, m + 1), rhs(m + 1), pivots(m + 1))
      matrix(1:m, 1:m) = image%jacobian
      do j = 1, m
         matrix(j, j) = matrix(j, j) - 1
      end do
      matrix(1:m, m + 1) = derivative
      matrix(m + 1, :) = previous
      rhs = 0
      rhs(m + 1) = 1
      call dgesv(m + 1, 1, matrix, m + 1, pivots, rhs, m + 1, info)
      if (info /= 0) then
         point%iterations = -1
         errmsg = 'the tangent''s bordered system is singular'
         return
      end if
      call point_scale(run, point)
      rhs = rhs*point%scale
      point%tangent = rhs/norm2(rhs)
      call set_test_functions(point)
      if (run%half_map%steps > 0) call branch_point_test(run, point, stat, errmsg)
   end subroutine finish_point

   !> The branch point test of `point` on a branch of 2k periods (`half_period_test`):
   !! Phi_k(x) - x by one run of k periods, its sign against the last point kept's.
   !! point%iterations = -1, no tangent (the corrector's point is not taken) and errmsg
   !! when that run fails (stat 0).
   subroutine branch_point_test(run, point, stat, errmsg)
      type(continuation_context), intent(inout) :: run
      type(branch_point), intent(inout) :: point
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(scene_type) :: local
      type(run_problem) :: prepared
      type(map_image) :: image
      logical :: same_way
      integer :: m
      call problem_at(run, point%parameter, local, prepared, stat, errmsg)
      if (stat == 0) call run%half_map%evaluate(local, prepared, point%x, jacobian_none, image, stat, errmsg)
      if (stat /= 0) return
      if (image%status /= outcome_ok) then
         point%iterations = -1
         deallocate (point%tangent)
         errmsg = 'the map of half the period: '//trim(image%failure)
         return
      end if
      m = size(point%x)
      point%half_shift = image%state - point%x
      same_way = .true.
      if (allocated(run%shift_reference)) &
         same_way = dot_product(run%weights(1:m)**2*run%shift_reference, point%half_shift) >= 0
      point%tests(kind_branch_point) = half_period_test(run%map%norm(run%reference, point%half_shift), &
                                                        max(run%map%norm(run%reference, point%x), &
                                                            run%map%norm(run%reference, image%state)), &
                                                        same_way, run%tolerance)
   end subroutine branch_point_test

   !> The scaled coordinates of `point`: x by the weights over the point's own size
   !! ||weights x|| (so that a step is a relative change of the orbit: a resonance peak
   !! many times the orbit where the branch started takes steps of its own size), floored
   !! at 1e-6 of the largest size so far (an orbit through zero); lambda by its weight.
   subroutine point_scale(run, point)
      type(continuation_context), intent(inout) :: run
      type(branch_point), intent(inout) :: point
      real(dp) :: size_of_x
      integer :: m
      m = size(point%x)
      size_of_x = norm2(run%weights(1:m)*point%x)
      run%largest_size = max(run%largest_size, size_of_x)
      size_of_x = max(size_of_x, 1e-6_dp*run%largest_size)
      if (.not. size_of_x > 0) size_of_x = 1
      point%scale = [run%weights(1:m)/size_of_x, run%weights(m + 1)]
   end subroutine point_scale

   !> The bifurcation of test function `kind` between branch points `a` (index `before`)
   !! and `b`: regula falsi (Illinois) on the test function over the arclength s from a,
   !! each trial a corrector from a along its tangent (from b backwards along its own when
   !! that fails), until the bracket is below locate_bracket of the step, the test
   !! function below locate_tolerance, lambda moves by less than locate_lambda between
   !! two trials, or after locate_iterations; lambda and the amplitude
   !! interpolated linearly in the last bracket; a trial whose correctors both fail leaves
   !! that estimate with located = .false. (A branch point: `locate_rejoin`.)
   subroutine locate(run, a, b, kind, before, found, stat, errmsg)
      type(continuation_context), intent(inout) :: run
      type(branch_point), intent(in) :: a, b
      integer, intent(in) :: kind, before
      type(bifurcation_point), allocatable, intent(inout) :: found(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(bifurcation_point) :: located
      type(branch_point) :: trial
      real(dp) :: s_low, s_high, f_low, f_high, s, weight
      real(dp) :: lambda_low, lambda_high, amplitude_low, amplitude_high, previous_lambda
      integer :: iteration, side, last_side
      logical :: converged
      stat = 0
      errmsg = ''
      s_low = 0
      s_high = b%step
      f_low = a%tests(kind)
      f_high = b%tests(kind)
      lambda_low = a%parameter
      lambda_high = b%parameter
      amplitude_low = a%amplitude
      amplitude_high = b%amplitude
      last_side = 0
      previous_lambda = huge(1.0_dp)
      located%kind = kind
      located%index = before
      do iteration = 1, locate_iterations
         s = s_low + f_low*(s_high - s_low)/(f_low - f_high)
         call correct(run, a, s, trial, converged, stat, errmsg)
         ! (a corrector from a that fails: the same point from b, backwards along its tangent)
         if (stat == 0 .and. .not. converged) call correct(run, b, s - b%step, trial, converged, stat, errmsg)
         if (stat /= 0) return
         if (.not. converged) exit
         if (trial%tests(kind)*f_low > 0) then
            s_low = s
            f_low = trial%tests(kind)
            lambda_low = trial%parameter
            amplitude_low = trial%amplitude
            side = -1
         else
            s_high = s
            f_high = trial%tests(kind)
            lambda_high = trial%parameter
            amplitude_high = trial%amplitude
            side = 1
         end if
         ! Illinois: halve the value at the end that stayed twice
         if (side == last_side) then
            if (side < 0) f_high = f_high/2
            if (side > 0) f_low = f_low/2
         end if
         last_side = side
         if (s_high - s_low <= locate_bracket*b%step .or. abs(trial%tests(kind)) <= locate_tolerance .or. &
             abs(trial%parameter - previous_lambda) <= locate_lambda*max(abs(trial%parameter), &
                                                                         1/run%weights(size(run%weights)))) then
            located%located = .true.
            exit
         end if
         previous_lambda = trial%parameter
      end do
      errmsg = ''
      weight = f_low/(f_low - f_high)
      located%parameter = lambda_low + weight*(lambda_high - lambda_low)
      located%amplitude = amplitude_low + weight*(amplitude_high - amplitude_low)
      found = [found, located]
   end subroutine locate

   !> The branch point of the 2k-period map between branch point `a` (index `before`, an
   !! orbit of 2k periods) and `b` beyond it (an orbit of k periods, or the other phase):
   !! the branch followed from a towards it with each trial's own tangent, the step (half
   !! of b's at first) halved when a trial lands beyond (the test function not positive)
   !! and kept when it lands before it (that trial the next base). (Trials all from a, as
   !! `locate` takes them, land on the orbit of k periods long before the branch point: a's
   !! hyperplane leaves the branch where it turns.) lambda and the amplitude extrapolated
   !! from the last two bases linearly in rho^2 to rho = 0 (near the pitchfork both move
   !! like the square of the phases' distance, rho like the distance); located when the
   !! step is below locate_bracket of b's (`locate`'s bracket rule) with an estimate made;
   !! after 3 locate_iterations trials the last estimate, not located.
   subroutine locate_rejoin(run, a, b, before, found, stat, errmsg)
      type(continuation_context), intent(inout) :: run
      type(branch_point), intent(in) :: a, b
      integer, intent(in) :: before
      type(bifurcation_point), allocatable, intent(inout) :: found(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(bifurcation_point) :: located
      type(branch_point) :: base, previous, trial
      real(dp) :: h, rho_base, rho_previous, weight
      integer :: iteration
      logical :: converged, estimated
      located%kind = kind_branch_point
      located%index = before
      weight = a%tests(kind_branch_point)/(a%tests(kind_branch_point) - b%tests(kind_branch_point))
      located%parameter = a%parameter + weight*(b%parameter - a%parameter)
      located%amplitude = a%amplitude + weight*(b%amplitude - a%amplitude)
      base = a
      h = b%step/2
      estimated = .false.
      do iteration = 1, 3*locate_iterations
         if (allocated(base%half_shift)) run%shift_reference = base%half_shift
         call correct(run, base, h, trial, converged, stat, errmsg)
         if (stat /= 0) return
         if (.not. (converged .and. trial%tests(kind_branch_point) > 0)) then
            h = h/2
            located%located = h <= locate_bracket*b%step .and. estimated
            if (h <= locate_bracket*b%step) exit
            cycle
         end if
         previous = base
         base = trial
         rho_base = base%tests(kind_branch_point) + sqrt(run%tolerance)
         rho_previous = previous%tests(kind_branch_point) + sqrt(run%tolerance)
         if (.not. rho_previous > rho_base) cycle
         weight = rho_base**2/(rho_previous**2 - rho_base**2)
         located%parameter = base%parameter - weight*(previous%parameter - base%parameter)
         located%amplitude = base%amplitude - weight*(previous%amplitude - base%amplitude)
         estimated = .true.
      end do
      stat = 0
      errmsg = ''
      found = [found, located]
   end subroutine locate_rejoin
end module vibrobeam_continuation
