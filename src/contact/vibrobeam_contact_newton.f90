!> The contact projection by a primal-dual active-set method globalized by a primal-dual
!! interior-point method, with an exact finish (`&solver contact_method = 'newton'`, the
!! default; docs/method.md "The contact projection", theory §5):
!!
!!     x = argmin 1/2 (x - x_free)^T W (x - x_free)  subject to  lower_k <= H_k x <= upper_k,
!!
!! k = 1..m over the contact points `points` (a side may be absent: +-no_bound), with the
!! multipliers P (W (x - x_free) = H^T P; P_k >= 0 where the lower bound holds, <= 0 where
!! the upper one does, 0 between).
!!
!! 0. If x_free satisfies every bound (to round-off) it is the solution: no solve.
!! 1. Active-set iterations (primal-dual active set, i.e. semismooth Newton on the
!!    complementarity conditions: Hintermüller, Ito & Kunisch, SIAM J. Optim. 13 (2002)
!!    865-888) from the set held in the previous projection plus the points x_free
!!    violates (warm start): solve exactly with the set F held (`solve_held`), drop the
!!    held points whose multiplier has the wrong sign, add the free points whose bound is
!!    violated, repeat; when nothing changes the result is exact. At most `warm_limit`
!!    iterations: they converge at once when the set is nearly right (persistent
!!    contact), but the method can cycle when W is not an M-matrix (Ben Gharbia &
!!    Gilbert, Math. Program. 134 (2012) 349-364), which the Hermite mass matrix and every
!!    beam stiffness are not, and far from the solution it moves the ends of the contact
!!    zones by a few nodes per iteration, so its iterations grow with N.
!! 2. Otherwise a primal-dual interior-point method (Mehrotra's predictor-corrector,
!!    SIAM J. Optim. 2 (1992) 575-601; Wright, Primal-Dual Interior-Point Methods, SIAM
!!    1997, ch. 11 for the monotone LCP) on the same conditions: it treats every point at
!!    once, so its iterations do not depend on how many points change side; each factors
!!    the band matrix W + H^T D H once (dpbtrf) and solves it twice. It ends either by a
!!    crossover (the active-set iteration restarted from the set the interior point
!!    indicates point by point, at least `polish_limit` iterations and on while they
!!    make progress, exact) or, when the complementarity products reach round-off, by
!!    the interior-point finish (P = y - z, x recomputed from P). Details at
!!    `interior_point`.
!! 3. If neither happens within `interior_limit` iterations, stat = stat_no_convergence and the caller falls
!!    back on principal pivoting.
!!
!! Consistency: whichever way it ends, x = x_free + W^-1 H^T P to the round-off of a band
!! solve; P has exactly the right sign (a held point with the wrong sign, however small,
!! is dropped and the set solved again; no multiplier is clipped); complementarity holds
!! exactly after an active-set finish (P = 0 off the held set, H x = bound on it to the
!! solve's accuracy) and to round-off after an interior-point finish; free points
!! satisfy their bounds to the tolerance below.
module vibrobeam_contact_newton
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_no_convergence, stat_residual_check_failed
   use vibrobeam_contact_set, only: contact_value, no_bound
   use vibrobeam_band, only: band_matvec
   use vibrobeam_contact_system, only: contact_system, solve_tally, scatter_rows
   implicit none
   private
   public :: newton_project, newton_report

   !> What one projection did.
   type :: newton_report
      integer :: active_set_iterations = 0   !! exact solves of a held set
      integer :: interior_iterations = 0     !! interior-point iterations
      integer :: crossovers = 0              !! active-set restarts from the interior point
   end type newton_report

   !> Active-set iterations from the warm start before the interior-point method: at least
   !! warm_minimum, at most warm_limit, and only while the number of points that change
   !! side decreases (a start far from the solution, e.g. statics from x_free, needs a few,
   !! each of which shrinks the changes; a cycling or creeping iteration does not).
   integer, parameter :: warm_minimum = 4, warm_limit = 40
   !> Active-set iterations of one crossover at least (at most warm_limit, while the changes shrink).
   integer, parameter :: polish_limit = 3
   !> An iterate of the interior-point method (`interior_point`): x, its contact values
   !! g = H x, the slacks s (lower side) and t (upper side) and their multipliers y, z.
   type :: barrier_iterate
      logical, allocatable :: has_lower(:), has_upper(:)   !! (points) the side has a bound
      real(dp), allocatable :: x(:), g(:), s(:), t(:), y(:), z(:)
   end type barrier_iterate

   !> The residuals of an iterate and the right-hand sides of the complementarity.
   type :: barrier_residuals
      real(dp), allocatable :: r_dual(:)             !! W x - b - H^T (y - z)
      real(dp), allocatable :: multiplier_rows(:)    !! H^T (y - z)
      real(dp), allocatable :: r_lower(:), r_upper(:), r_sy(:), r_tz(:)
   end type barrier_residuals

   !> A Newton direction of the iterate.
   type :: barrier_direction
      real(dp), allocatable :: dx(:), dg(:), ds(:), dt(:), dy(:), dz(:)
   end type barrier_direction

   !> Interior-point iterations before the fall-back.
   integer, parameter :: interior_limit = 100
   !> A free point may violate its bound by gap_factor eps scale + (largest |H x - bound|
   !! on the held points) + 2 (error estimate of the solve, `solve_held`), scale = the
   !! largest |H_k| |x| and |finite bound| of the iterate x: the round-off of evaluating
   !! H x (at most 3 products and sums, 3 eps |H||x|) with a margin, plus what the solve
   !! itself achieves. (The scale of x, not of x_free: in statics x_free = K^-1 F is some
   !! 10^10 times the solution and would let a contact zone keep holes.)
   real(dp), parameter :: gap_factor = 64
   !> Residual check of the exact finish: |H_k x - bound_k| on the held points must not
   !! exceed residual_limit * scale (a solve that loses all but 8 digits has failed).
   real(dp), parameter :: residual_limit = 1e-8_dp
   !> Crossover once mu <= crossover_reduction mu_0 and the indicated set did not change
   !! in the last iteration.
   real(dp), parameter :: crossover_reduction = 1e-6_dp
   !> Interior-point finish once every product s y, t z <= round_factor eps P_max scale.
   real(dp), parameter :: round_factor = 16
   !> Slacks of the interior-point start: at least start_fraction times the largest
   !! violation of x_free.
   real(dp), parameter :: start_fraction = 0.1_dp
   !> Fraction of the step to the boundary of the positive orthant (Mehrotra's eta).
   real(dp), parameter :: boundary_fraction = 0.995_dp

contains

   !> Solve the projection (module comment). side(k): in, the warm start (+1 lower held,
   !! -1 upper held, 0 free); out, the final held set. stat: stat_ok; stat_no_convergence
   !! (fall back); stat_linear_solver_failure (a factorization failed);
   !! stat_residual_check_failed (the residual check of the exact finish).
   subroutine newton_project(system, x_free, points, lower, upper, side, x, multiplier, report, tally, stat, errmsg, &
                             w_x_free_given)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: x_free(:)
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: lower(:), upper(:)
      integer, intent(inout) :: side(:)
      real(dp), intent(out) :: x(:), multiplier(:)
      type(newton_report), intent(out) :: report
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      !> b = W x_free when the caller knows it exactly (statics: the load vector; its product
      !! form loses the digits that K^-1 F lost); otherwise computed as W x_free
      real(dp), intent(in), optional :: w_x_free_given(:)
      real(dp) :: free_value(size(points)), value(size(points)), w_x_free(size(x_free)), scale, tolerance
      integer :: k, iteration, changes, previous_changes
      logical :: converged
      stat = 0
      errmsg = ''
      x = x_free
      multiplier = 0
      do k = 1, size(points)
         free_value(k) = contact_value(system%contacts, points(k), x_free)
      end do
      scale = problem_scale(free_value, lower, upper)
      tolerance = gap_factor*epsilon(1.0_dp)*scale
      ! x_free admissible (to round-off): it is the minimizer
      if (all(free_value >= lower - tolerance .and. free_value <= upper + tolerance)) then
         side = 0
         return
      end if
      if (present(w_x_free_given)) then
         w_x_free = w_x_free_given
      else
         call band_matvec(system%metric, x_free, w_x_free)
      end if
      ! warm start: the previous set where its bound exists, plus every violated point
      where (side == 1 .and. lower <= -no_bound) side = 0
      where (side == -1 .and. upper >= no_bound) side = 0
      where (free_value < lower - tolerance) side = 1
      where (free_value > upper + tolerance) side = -1
      changes = huge(1)
      do iteration = 1, warm_limit
         report%active_set_iterations = report%active_set_iterations + 1
         previous_changes = changes
         call active_set_step(system, x_free, w_x_free, points, lower, upper, scale, side, x, multiplier, value, &
                              converged, tally, stat, errmsg, changes)
         if (stat /= 0 .or. converged) return
         if (iteration >= warm_minimum .and. changes >= previous_changes) exit   ! no progress: globalize
      end do
      call interior_point(system, x_free, w_x_free, points, lower, upper, scale, &
                          max(maxval(lower - free_value), maxval(free_value - upper)), side, x, multiplier, value, &
                          report, tally, stat, errmsg)
   end subroutine newton_project

   !> The largest |finite bound| (0 if none).
   pure real(dp) function bound_scale(lower, upper)
      real(dp), intent(in) :: lower(:), upper(:)
      bound_scale = max(maxval(abs(lower), lower > -no_bound), maxval(abs(upper), upper < no_bound), 0.0_dp)
   end function bound_scale

   !> The largest |H x_free|, |finite bound| (never 0).
   pure function problem_scale(free_value, lower, upper) result(scale)
      real(dp), intent(in) :: free_value(:), lower(:), upper(:)
      real(dp) :: scale
      scale = max(maxval(abs(free_value)), maxval(abs(lower), lower > -no_bound), &
                  maxval(abs(upper), upper < no_bound), tiny(1.0_dp))
   end function problem_scale

   !> One active-set iteration: solve with the set `side` held; converged when no held
   !! multiplier has the wrong sign and no free point violates its bound beyond the
   !! tolerance; otherwise update `side` (drop the first, add the second).
   subroutine active_set_step(system, x_free, w_x_free, points, lower, upper, scale, side, x, multiplier, value, &
                              converged, tally, stat, errmsg, changes)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: x_free(:), w_x_free(:), lower(:), upper(:), scale
      integer, intent(in) :: points(:)
      integer, intent(inout) :: side(:)
      real(dp), intent(out) :: x(:), multiplier(:), value(:)
      logical, intent(out) :: converged
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(out), optional :: changes   !! points that changed side
      logical :: held(size(points)), wrong(size(points)), enter_lower(size(points)), enter_upper(size(points))
      real(dp) :: target(size(points)), accuracy, tolerance, error_estimate, value_scale, abs_x(size(x))
      integer :: k
      converged = .false.
      if (present(changes)) changes = 0
      held = side /= 0
      target = merge(lower, upper, side >= 0)
      call system%solve_held(x_free, w_x_free, points, held, target, x, multiplier, error_estimate, tally, stat, errmsg)
      if (stat /= 0) return
      value_scale = bound_scale(lower, upper)
      abs_x = abs(x)
      do k = 1, size(points)
         value(k) = contact_value(system%contacts, points(k), x)
         value_scale = max(value_scale, contact_value(system%contacts, points(k), abs_x))
      end do
      accuracy = max(maxval(abs(value - target), held), 0.0_dp)
      tolerance = gap_factor*epsilon(1.0_dp)*value_scale + accuracy + 2*error_estimate
      wrong = held .and. side*multiplier < 0
      enter_lower = .not. held .and. value < lower - tolerance
      enter_upper = .not. held .and. value > upper + tolerance
      if (.not. (any(wrong) .or. any(enter_lower) .or. any(enter_upper))) then
         converged = .true.
         ! exact finish: the residual check of the held bounds
         if (accuracy > residual_limit*max(scale, maxval(abs(value)))) then
            k = maxloc(abs(value - target), dim=1, mask=held)
            write (errmsg, '(a,i0,a,es10.3,a,es10.3)') 'contact projection: residual check failed at contact point ', &
               points(k), ': |H x - bound| = ', abs(value(k) - target(k)), ', scale ', scale
            stat = stat_residual_check_failed
         end if
         return
      end if
      if (present(changes)) changes = count(wrong) + count(enter_lower) + count(enter_upper)
      where (wrong) side = 0
      where (enter_lower) side = 1
      where (enter_upper) side = -1
   end subroutine active_set_step

   !> Mehrotra's predictor-corrector on the optimality conditions
   !!     W x - b = H^T (y - z),  H x - s = lower,  H x + t = upper,
   !!     s, t, y, z >= 0,  s y = t z = 0          (b = W x_free, P = y - z),
   !! an infeasible primal-dual method: every residual is evaluated from the iterate by a
   !! product with W, so the band solves only have to give a good direction (they lose
   !! accuracy like cond(W), ~N^4 for a beam's stiffness). Newton's equations reduce to
   !! (W + H^T D H) dx = -r_d + H^T rho, D = y/s + z/t (`factor_barrier`, `solve_barrier`:
   !! one factorization and two solves per iteration).
   !!
   !! Start: x = x_free; every slack at least start_fraction times the largest violation of
   !! x_free, and every product s y, t z equal to mu_0 = that floor times the largest
   !! multiplier of the last active-set solve: centred, with residuals only on the violated
   !! points and in W x - b - H^T (y - z). (Starting from the last active-set iterate
   !! instead, shifted into the interior as Mehrotra (1992) does, puts a floor multiplier
   !! on every free point; their sum moves the beam far from the bounds and cost 2-3 times
   !! more iterations in the slap.)
   !!
   !! Crossover: the indicated set is {(y_k + dy_k)/y_k > 1/2} (lower; likewise upper) at the
   !! affine-scaling (predictor) direction, the indicator of El-Bakry, Tapia &
   !! Zhang (SIAM Review 36 (1994) 45-72): since s dy + y ds = -s y, it is the
   !! same as (s_k + ds_k)/s_k < 1/2, i.e. the predictor removes more than half of the
   !! point's own gap. It compares each point with itself, in the scale of its own gap and
   !! multiplier. (The earlier y + dy > c_k (s + ds), c_k = H_k W H_k^T, asks for gaps
   !! below |P_k|/c_k ~ |q| h^4/24 in statics, under the round-off of the positions from
   !! N ~ 10^4: the crossover never succeeded there and the interior-point finish left
   !! reactions of up to 4 % of |q| h on lifted nodes.) The active-set iteration restarts
   !! from it once mu <= crossover_reduction mu_0 and the indicated set did not change in
   !! the last iteration, and once every product is below the round-off of the
   !! complementarity (round_factor eps P_max scale); it runs at least polish_limit
   !! iterations and continues while the number of points that change side decreases
   !! (as the warm start does). A set from which it failed is not tried again (the
   !! iteration from a set is deterministic).
   !!
   !! Interior-point finish, if that crossover fails: once the products have reached
   !! round-off and so have the residuals (|W x - b - H^T P| <= round_factor eps
   !! (|W| |x| + |b| + |H^T P|), |H x - s - bound| <= gap_factor eps scale), the iterate
   !! itself is the answer: P = y - z (exactly of the right sign on one-sided points), x
   !! consistent with it to round-off, complementarity residual y_k s_k, t_k z_k; the
   !! multipliers of the points indicated free are set to 0 when the sum of their rows
   !! H^T P is itself within that round-off. (No correction through W^-1: for statics its
   !! solves carry no digits at N ~ 10^4.)
   subroutine interior_point(system, x_free, w_x_free, points, lower, upper, scale, violation, side, x, multiplier, &
                             value, report, tally, stat, errmsg)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: x_free(:), w_x_free(:), lower(:), upper(:), scale
      real(dp), intent(in) :: violation          !! largest violation of x_free (> 0)
      integer, intent(in) :: points(:)
      integer, intent(inout) :: side(:)
      real(dp), intent(inout) :: x(:), multiplier(:), value(:)
      type(newton_report), intent(inout) :: report
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(barrier_iterate) :: it
      type(barrier_residuals) :: res
      type(barrier_direction) :: dir
      logical :: converged, round_off, round_off_tried
      real(dp), dimension(size(points)) :: y_gain, z_gain
      real(dp) :: mu, mu0, mu_affine, sigma, alpha, metric_norm
      integer :: indicated(size(points)), previous(size(points)), failed(size(points)), pairs, iteration
      stat = 0
      errmsg = ''
      call centred_start(system, x_free, points, lower, upper, violation, multiplier, it, mu0)
      pairs = count(it%has_lower) + count(it%has_upper)
      mu = mu0
      previous = 2
      failed = 2
      metric_norm = maxval(sum(abs(system%metric%lower), dim=1))   ! |W|_inf, within a factor 2
      round_off_tried = .false.
      do iteration = 1, interior_limit
         call evaluate_residuals(system, w_x_free, points, lower, upper, it, res)
         ! interior-point finish: every residual and product at round-off
         if (round_off_tried .and. at_round_off(it, res, w_x_free, scale, metric_norm)) then
            call interior_finish(system, points, w_x_free, metric_norm, it, res, previous, x, multiplier, value)
            side = previous
            return
         end if
         report%interior_iterations = report%interior_iterations + 1
         call system%factor_barrier(points, it%y/it%s + it%z/it%t, tally, stat, errmsg)
         if (stat /= 0) return
         ! predictor (affine scaling); its full step predicts the solution
         res%r_sy = -it%s*it%y
         res%r_tz = -it%t*it%z
         call newton_direction(system, points, it, res, dir, tally)
         y_gain = (it%y + dir%dy)/merge(it%y, 1.0_dp, it%has_lower) - 0.5_dp
         z_gain = (it%z + dir%dz)/merge(it%z, 1.0_dp, it%has_upper) - 0.5_dp
         alpha = min(1.0_dp, step_to_boundary(it, dir))
         mu_affine = (sum((it%s + alpha*dir%ds)*(it%y + alpha*dir%dy), it%has_lower) + &
                      sum((it%t + alpha*dir%dt)*(it%z + alpha*dir%dz), it%has_upper))/pairs
         sigma = (max(mu_affine, 0.0_dp)/mu)**3
         ! corrector and centring
         res%r_sy = merge(sigma*mu - it%s*it%y - dir%ds*dir%dy, 0.0_dp, it%has_lower)
         res%r_tz = merge(sigma*mu - it%t*it%z - dir%dt*dir%dz, 0.0_dp, it%has_upper)
         call newton_direction(system, points, it, res, dir, tally)
         alpha = min(1.0_dp, boundary_fraction*step_to_boundary(it, dir))
         call take_step(system, points, alpha, dir, it)
         mu = (sum(it%s*it%y, it%has_lower) + sum(it%t*it%z, it%has_upper))/pairs
         round_off = max(maxval(it%s*it%y, it%has_lower), maxval(it%t*it%z, it%has_upper)) <= &
                     round_factor*epsilon(1.0_dp)*max(maxval(it%y), maxval(it%z))*max(scale, maxval(abs(it%g)))
         ! crossover
         indicated = 0
         where (it%has_lower .and. y_gain > 0) indicated = 1
         where (it%has_upper .and. z_gain > 0 .and. (indicated == 0 .or. z_gain > y_gain)) indicated = -1
         if (((mu <= crossover_reduction*mu0 .and. all(indicated == previous)) .or. &
              (round_off .and. .not. round_off_tried)) .and. any(indicated /= failed)) then
            round_off_tried = round_off_tried .or. round_off
            report%crossovers = report%crossovers + 1
            side = indicated
            call crossover(system, x_free, w_x_free, points, lower, upper, scale, side, x, multiplier, value, &
                           converged, report, tally, stat, errmsg)
            if (stat /= 0 .or. converged) return
            failed = indicated   ! the iteration from a set is deterministic: do not retry it
         end if
         previous = indicated
         if (.not. (mu > 0 .and. alpha > 0)) exit   ! nothing left to reduce
      end do
      stat = stat_no_convergence
      write (errmsg, '(a,i0,a,es9.2,a)') 'contact projection: no solution after ', report%interior_iterations, &
         ' interior-point iterations (mu/mu0 = ', mu/mu0, ')'
   end subroutine interior_point

   !> The centred start at x_free (`interior_point`); returns mu_0. An absent side
   !! carries s = 1, y = 0 (t = 1, z = 0), which keeps it out of every product and sum.
   subroutine centred_start(system, x_free, points, lower, upper, violation, multiplier, it, mu0)
      type(contact_system), intent(in) :: system
      real(dp), intent(in) :: x_free(:), lower(:), upper(:), violation, multiplier(:)
      integer, intent(in) :: points(:)
      type(barrier_iterate), intent(out) :: it
      real(dp), intent(out) :: mu0
      real(dp) :: slack_floor
      it%has_lower = lower > -no_bound
      it%has_upper = upper < no_bound
      it%x = x_free
      allocate (it%g(size(points)))
      call row_values(system, points, it%x, it%g)
      slack_floor = start_fraction*violation
      mu0 = slack_floor*max(maxval(abs(multiplier)), tiny(1.0_dp))
      it%s = merge(max(it%g - lower, slack_floor), 1.0_dp, it%has_lower)
      it%t = merge(max(upper - it%g, slack_floor), 1.0_dp, it%has_upper)
      it%y = merge(mu0/it%s, 0.0_dp, it%has_lower)
      it%z = merge(mu0/it%t, 0.0_dp, it%has_upper)
   end subroutine centred_start

   !> The residuals of the iterate: r_dual = W x - b - H^T (y - z) (and H^T (y - z)
   !! itself), r_lower = H x - s - lower, r_upper = H x + t - upper.
   subroutine evaluate_residuals(system, w_x_free, points, lower, upper, it, res)
      type(contact_system), intent(in) :: system
      real(dp), intent(in) :: w_x_free(:), lower(:), upper(:)
      integer, intent(in) :: points(:)
      type(barrier_iterate), intent(in) :: it
      type(barrier_residuals), intent(inout) :: res
      if (.not. allocated(res%r_dual)) allocate (res%r_dual(size(it%x)), res%multiplier_rows(size(it%x)))
      call band_matvec(system%metric, it%x, res%r_dual)
      res%r_dual = res%r_dual - w_x_free
      res%multiplier_rows = 0
      call scatter_rows(system%contacts, points, merge(it%y, 0.0_dp, it%has_lower) - merge(it%z, 0.0_dp, it%has_upper), &
                        res%multiplier_rows)
      res%r_dual = res%r_dual - res%multiplier_rows
      res%r_lower = merge(it%g - it%s - lower, 0.0_dp, it%has_lower)
      res%r_upper = merge(it%g + it%t - upper, 0.0_dp, it%has_upper)
   end subroutine evaluate_residuals

   !> Whether every residual of the iterate is at round-off (`interior_point`, finish).
   logical function at_round_off(it, res, w_x_free, scale, metric_norm)
      type(barrier_iterate), intent(in) :: it
      type(barrier_residuals), intent(in) :: res
      real(dp), intent(in) :: w_x_free(:), scale, metric_norm
      at_round_off = maxval(abs(res%r_dual)) <= round_factor*epsilon(1.0_dp)*(2*metric_norm*maxval(abs(it%x)) + &
                                                  maxval(abs(w_x_free)) + maxval(abs(res%multiplier_rows))) .and. &
                     max(maxval(abs(res%r_lower)), maxval(abs(res%r_upper))) <= &
                     gap_factor*epsilon(1.0_dp)*max(scale, maxval(abs(it%g)))
   end function at_round_off

   !> The interior-point finish: the iterate is the answer, P = y - z, the multipliers
   !! of the points indicated free (`indicated` = 0) dropped where the equilibrium
   !! residual stays at round-off without them.
   subroutine interior_finish(system, points, w_x_free, metric_norm, it, res, indicated, x, multiplier, value)
      type(contact_system), intent(in) :: system
      integer, intent(in) :: points(:), indicated(:)
      real(dp), intent(in) :: w_x_free(:), metric_norm
      type(barrier_iterate), intent(in) :: it
      type(barrier_residuals), intent(in) :: res
      real(dp), intent(out) :: x(:), multiplier(:), value(:)
      real(dp) :: free_rows(size(it%x))
      multiplier = merge(it%y, 0.0_dp, it%has_lower) - merge(it%z, 0.0_dp, it%has_upper)
      free_rows = 0
      call scatter_rows(system%contacts, points, merge(multiplier, 0.0_dp, indicated == 0), free_rows)
      if (maxval(abs(free_rows)) <= round_factor*epsilon(1.0_dp)*(2*metric_norm*maxval(abs(it%x)) + &
                                    maxval(abs(w_x_free)) + maxval(abs(res%multiplier_rows)))) &
         where (indicated == 0) multiplier = 0
      x = it%x
      value = it%g
   end subroutine interior_finish

   !> Newton direction for the current right-hand sides (r_dual, r_lower, r_upper, r_sy,
   !! r_tz) with the factored barrier system.
   subroutine newton_direction(system, points, it, res, dir, tally)
      type(contact_system), intent(inout) :: system
      integer, intent(in) :: points(:)
      type(barrier_iterate), intent(in) :: it
      type(barrier_residuals), intent(in) :: res
      type(barrier_direction), intent(inout) :: dir
      type(solve_tally), intent(inout) :: tally
      real(dp) :: rho(size(points))
      rho = merge((res%r_sy - it%y*res%r_lower)/it%s, 0.0_dp, it%has_lower) - &
            merge((res%r_tz + it%z*res%r_upper)/it%t, 0.0_dp, it%has_upper)
      dir%dx = -res%r_dual
      call scatter_rows(system%contacts, points, rho, dir%dx)
      call system%solve_barrier(dir%dx, tally)
      if (.not. allocated(dir%dg)) allocate (dir%dg(size(points)))
      call row_values(system, points, dir%dx, dir%dg)
      dir%ds = merge(dir%dg + res%r_lower, 0.0_dp, it%has_lower)
      dir%dy = merge((res%r_sy - it%y*dir%ds)/it%s, 0.0_dp, it%has_lower)
      dir%dt = merge(-dir%dg - res%r_upper, 0.0_dp, it%has_upper)
      dir%dz = merge((res%r_tz - it%z*dir%dt)/it%t, 0.0_dp, it%has_upper)
   end subroutine newton_direction

   !> Move the iterate by alpha times the direction (on the sides that exist).
   subroutine take_step(system, points, alpha, dir, it)
      type(contact_system), intent(in) :: system
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: alpha
      type(barrier_direction), intent(in) :: dir
      type(barrier_iterate), intent(inout) :: it
      where (it%has_lower) it%s = it%s + alpha*dir%ds
      where (it%has_lower) it%y = it%y + alpha*dir%dy
      where (it%has_upper) it%t = it%t + alpha*dir%dt
      where (it%has_upper) it%z = it%z + alpha*dir%dz
      it%x = it%x + alpha*dir%dx
      call row_values(system, points, it%x, it%g)
   end subroutine take_step

   !> The active-set iteration restarted from the set `side` the interior point
   !! indicates: at least polish_limit iterations, at most warm_limit, on while the number
   !! of points that change side decreases.
   subroutine crossover(system, x_free, w_x_free, points, lower, upper, scale, side, x, multiplier, value, converged, &
                        report, tally, stat, errmsg)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: x_free(:), w_x_free(:), lower(:), upper(:), scale
      integer, intent(in) :: points(:)
      integer, intent(inout) :: side(:)
      real(dp), intent(inout) :: x(:), multiplier(:), value(:)
      logical, intent(out) :: converged
      type(newton_report), intent(inout) :: report
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: polish, changes, previous_changes
      changes = huge(1)
      do polish = 1, warm_limit
         report%active_set_iterations = report%active_set_iterations + 1
         previous_changes = changes
         call active_set_step(system, x_free, w_x_free, points, lower, upper, scale, side, x, multiplier, value, &
                              converged, tally, stat, errmsg, changes)
         if (stat /= 0 .or. converged) return
         if (polish >= polish_limit .and. changes >= previous_changes) exit
      end do
   end subroutine crossover

   !> H_k v for every point.
   subroutine row_values(system, points, v, values)
      type(contact_system), intent(in) :: system
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: v(:)
      real(dp), intent(out) :: values(:)
      integer :: i
      do i = 1, size(points)
         values(i) = contact_value(system%contacts, points(i), v)
      end do
   end subroutine row_values

   !> Largest alpha keeping s, t, y, z >= 0 along the direction (huge if unbounded).
   pure real(dp) function step_to_boundary(it, dir) result(alpha_max)
      type(barrier_iterate), intent(in) :: it
      type(barrier_direction), intent(in) :: dir
      alpha_max = min(ratio(it%s, dir%ds, it%has_lower), ratio(it%y, dir%dy, it%has_lower), &
                      ratio(it%t, dir%dt, it%has_upper), ratio(it%z, dir%dz, it%has_upper))
   end function step_to_boundary

   pure real(dp) function ratio(v, dv, mask)
      real(dp), intent(in) :: v(:), dv(:)
      logical, intent(in) :: mask(:)
      integer :: i
      ratio = huge(1.0_dp)
      do i = 1, size(v)
         if (mask(i) .and. dv(i) < 0) ratio = min(ratio, -v(i)/dv(i))
      end do
   end function ratio
end module vibrobeam_contact_newton
