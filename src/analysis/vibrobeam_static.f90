!> Static equilibrium against the obstacles (theory §5 "Statics", &analysis kind = 'static'
!! and &initial displacement = 'static'):
!!
!!     U = argmin 1/2 U^T K U - F^T U + sum_j Phi_j(p_j(U))   subject to   g1(x_c) <= H_c U <= g2(x_c),
!!
!! rigid bounds at the contact points and the potentials Phi_j of the compliant stops
!! (docs/theory.md section 8; no damping in statics). Reactions are the forces of the
!! obstacles on the beam at the contact points (N; per unit mass when the beam is given by
!! k2), positive upwards: a rigid bound's multiplier plus the springs' forces there.
!!
!! Why not the contact projection of the steppers in the metric K: every solve with K (its
!! band Cholesky, the held problem K_RR, the Delassus matrix of a floor) loses digits like
!! cond(K) ~ N^4, and the run answered wrong with status 'ok' (issue 23: the free tip off by
!! 1.1e-2 at N = 1e4 and by 100 % at N = 1e5, a floor with no contact at N = 1e5). Here
!! nothing of order J is factored (docs/method.md, "Statics"):
!! - the free equilibrium K^-1 F by double integration (`vibrobeam_flexibility`);
!! - every linear solve with a set of held nodes in curvatures, as a three-moment system
!!   (`vibrobeam_support_moments`: tridiagonal, condition <= 3; compliant stops linearized
!!   as elastic supports, pentadiagonal);
!! - the set by an active-set Newton iteration (a held node whose reaction pulls is freed,
!!   a free node beyond its bound is held, every compliant stop linearized at the iterate),
!!   block changes while their number reaches new minima and Murty's least-index single
!!   change otherwise (Judice & Pires 1994, as in theory §5), started on nested subsets of
!!   the contact points (every 2^l-th node and the ends of each run of nodes, coarsest
!!   first), so that each level only moves the ends of the contact zones by a node or two;
!! - (other structures than the uniform clamped-free beam, where this double integration
!!   from the clamp does not apply, go to `vibrobeam_static_band`: a band Cholesky of K
!!   and the contact points' dense coupling)
!! - an a-posteriori check (`check_equilibrium`): the held nodes on their bounds, the free
!!   ones within them and the springs' forces on their laws to the derived round-off bound
!!   of the positions, and U against K^-1 (F + H^T P) recomputed independently to its
!!   bound; and, when the caller asks for a tolerance (&solver static_tolerance), the
!!   derived bound of every nodal displacement within it. An answer that fails it is not
!!   returned as a solution: stat /= 0, and the caller publishes it marked 'failed' (exit
!!   status 3).
module vibrobeam_static
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_no_convergence, stat_residual_check_failed
   use vibrobeam_model, only: beam_model, nodal_displacement, flexibility_applies
   use vibrobeam_static_report, only: static_report
   use vibrobeam_static_band, only: solve_static_band
   use vibrobeam_flexibility, only: cantilever_flexibility, flexibility_rounding
   use vibrobeam_contact_set, only: contact_set, no_bound
   use vibrobeam_static_iterate, only: static_state, solve_supported, index_springs, has_springs, spring_law, &
      rigid_reaction, rows_transpose
   implicit none
   private
   public :: solve_static, static_report

   !> Contact points in the coarsest level of the nested subsets (fewer: one level).
   integer, parameter :: coarsest_points = 32
   !> Active-set iterations (held-set solves) allowed per level when `max_iterations` is 0.
   integer, parameter :: default_level_iterations = 100

contains

   !> Solve the static problem of the model under the loads `force` (theory §5 "Statics").
   !! stat: 0; stat_no_convergence (the active set or the compliant stops did not settle
   !! within the iterations allowed); stat_residual_check_failed (the answer fails its
   !! a-posteriori check, or its displacements' bound exceeds `tolerance`);
   !! stat_linear_solver_failure. On failure u and reaction hold the last iterate (published
   !! marked 'failed' by the program).
   subroutine solve_static(model, contacts, force, u, reaction, iterations, stat, errmsg, max_iterations, report, &
                           tolerance)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:)                 !! F (J)
      real(dp), intent(out) :: u(:)                    !! equilibrium (J)
      real(dp), intent(out) :: reaction(:)             !! (contacts%count) P_c, 0 if not in contact
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      !> held-set solves allowed per level (&solver contact_max_iterations; 0: the default, 100)
      integer, intent(in), optional :: max_iterations
      type(static_report), intent(out), optional :: report
      !> the largest derived round-off bound of a nodal displacement accepted (m; &solver
      !! static_tolerance); absent or 0: any
      real(dp), intent(in), optional :: tolerance
      type(cantilever_flexibility) :: flexibility
      type(static_state) :: state
      type(static_report) :: done
      real(dp), allocatable :: free_curvature(:), curvature_error(:)
      integer :: limit
      real(dp) :: required
      required = 0
      if (present(tolerance)) required = tolerance
      if (.not. flexibility_applies(model)) then
         ! every other structure: the band Cholesky of K (docs/method.md, "Statics"), its
         ! position bound held to static_tolerance as the clamped-free path's is
         call solve_static_band(model, contacts, force, u, reaction, iterations, stat, errmsg, max_iterations, done)
         if (stat == 0 .and. required > 0 .and. done%position_bound > required) then
            stat = stat_residual_check_failed
            write (errmsg, '(a,es10.3,a,es10.3,a)') 'the static answer fails its check: its displacements are '// &
               'bounded to ', done%position_bound, ' m (4 FERR of LAPACK dpbrfs), not to &solver static_tolerance = ', &
               required, ' m; not trusted to it (docs/method.md, "Statics")'
         end if
         if (present(report)) report = done
         return
      end if
      iterations = 0
      u = 0
      reaction = 0
      call flexibility%setup(model, stat, errmsg)
      if (stat /= 0) return
      allocate (free_curvature(model%unknowns))
      call flexibility%curvature_of_loads(force, free_curvature)
      allocate (curvature_error(model%unknowns))
      call flexibility%curvature_magnitude(abs(force), curvature_error)
      curvature_error = flexibility_rounding(model%elements)*curvature_error
      limit = default_level_iterations
      if (present(max_iterations)) then
         if (max_iterations > 0) limit = max_iterations
      end if
      call settle(flexibility, contacts, force, free_curvature, curvature_error, limit, state, done, stat, errmsg)
      u = state%u
      reaction = state%reaction
      iterations = done%iterations
      if (stat == 0) call check_equilibrium(flexibility, model, contacts, force, state, required, done, stat, errmsg)
      if (present(report)) report = done
   end subroutine solve_static

   !> The active-set Newton iteration on nested subsets of the contact points (module
   !! documentation), from the free equilibrium.
   subroutine settle(flexibility, contacts, force, free_curvature, curvature_error, limit, state, report, stat, errmsg)
      type(cantilever_flexibility), intent(in) :: flexibility
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:), free_curvature(:), curvature_error(:)
      integer, intent(in) :: limit
      type(static_state), intent(inout) :: state
      type(static_report), intent(inout) :: report
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, allocatable :: finest_level(:)
      integer :: n, level, top, c
      logical, allocatable :: included(:)
      n = contacts%count
      allocate (state%side(n), source=0)
      allocate (state%position(n), state%tolerance(n), state%reached(n), state%reaction(n), state%rounding(n), &
                state%reaction_bound(n), source=0.0_dp)
      allocate (state%unknown_bound(flexibility%unknowns), source=0.0_dp)
      call index_springs(contacts, state)
      allocate (state%released(n), source=.false.)
      allocate (state%releases(n), source=0)
      allocate (state%u(flexibility%unknowns), state%z(flexibility%unknowns))
      call solve_supported(flexibility, contacts, force, free_curvature, curvature_error, [(.false., c=1, n)], state, stat, errmsg)
      if (stat /= 0 .or. n == 0) return
      ! level of each point: the largest l with node divisible by 2^l; the ends of each run of
      ! consecutive nodes (a punctual stop is both) belong to every level
      allocate (finest_level(n))
      do c = 1, n
         finest_level(c) = trailz(contacts%node(c))
         if (c == 1) then
            finest_level(c) = huge(1)
         else if (contacts%node(c - 1) /= contacts%node(c) - 1) then
            finest_level(c) = huge(1)
         end if
         if (c == n) then
            finest_level(c) = huge(1)
         else if (contacts%node(c + 1) /= contacts%node(c) + 1) then
            finest_level(c) = huge(1)
         end if
      end do
      top = 0
      do while (count(finest_level >= top) > coarsest_points .and. top < 30)
         top = top + 1
      end do
      do level = top, 0, -1
         included = finest_level >= level
         if (level < top) then
            if (count(included) == count(finest_level >= level + 1)) cycle
         end if
         report%levels = report%levels + 1
         state%released = .false.
         state%releases = 0
         call settle_level(flexibility, contacts, force, free_curvature, curvature_error, included, limit, state, report, &
                           stat, errmsg)
         if (stat /= 0) then
            write (errmsg, '(a,i0,a,i0,a)') trim(errmsg)//' (level ', level, ': ', count(included), ' of the contact points)'
            return
         end if
      end do
   end subroutine settle

   !> Iterate on the points `included` until no held point pulls, no free point lies beyond
   !! a bound and every compliant stop's force matches its law at the iterate.
   subroutine settle_level(flexibility, contacts, force, free_curvature, curvature_error, included, limit, state, report, &
                           stat, errmsg)
      type(cantilever_flexibility), intent(in) :: flexibility
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:), free_curvature(:), curvature_error(:)
      logical, intent(in) :: included(:)
      integer, intent(in) :: limit
      type(static_state), intent(inout) :: state
      type(static_report), intent(inout) :: report
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: new_side(size(included)), changes, best, since_best, iteration, c, first, amnesties
      logical :: springs_settled
      real(dp), allocatable :: previous(:)
      allocate (previous, source=state%position)
      stat = 0
      errmsg = ''
      best = huge(1)
      since_best = 0
      amnesties = 0
      do iteration = 1, limit + 1
         new_side = proposed_sides(contacts, included, state)
         springs_settled = compliant_settled(contacts, included, state, previous, iteration > 1)
         changes = count(new_side /= state%side)
         if (changes == 0 .and. springs_settled .and. amnesties < 2) then
            ! settled; points freed earlier for pulling may pull no more now that the set
            ! changed around them (a floor's nodes freed while the touchdown moved): once or
            ! twice, forget why they were freed and let them be held again if they touch;
            ! not those freed twice already (a point that pulls when held and touches within
            ! round-off when free: either answer holds to round-off, and free is final)
            where (state%releases < 2) state%released = .false.
            new_side = proposed_sides(contacts, included, state)
            changes = count(new_side /= state%side)
            amnesties = amnesties + 1
            best = huge(1)
            since_best = 0
         end if
         if (changes == 0 .and. springs_settled) return
         if (iteration > limit) exit
         ! block changes while their number reaches new minima; after 3 block changes
         ! without one, Murty's least-index rule (one change) until it does
         if (changes < best) then
            best = changes
            since_best = 0
         else
            since_best = since_best + 1
         end if
         if (since_best > 3 .and. changes > 0) then
            first = findloc(new_side /= state%side, .true., dim=1)
            if (new_side(first) == 0) then
               state%released(first) = .true.
               state%releases(first) = state%releases(first) + 1
            end if
            state%side(first) = new_side(first)
         else
            where (new_side == 0 .and. state%side /= 0)
               state%released = .true.
               state%releases = state%releases + 1
            end where
            state%side = new_side
         end if
         previous = state%position
         call solve_supported(flexibility, contacts, force, free_curvature, curvature_error, included, state, stat, errmsg)
         report%iterations = report%iterations + 1
         if (stat /= 0) return
      end do
      stat = stat_no_convergence
      c = count(new_side /= state%side)
      write (errmsg, '(a,i0,a,i0,a)') 'static contact: no equilibrium after ', limit, ' active-set iterations (', c, &
         ' contact points still change side'//trim(merge(', compliant stops not settled', '                             ', &
         .not. springs_settled))//'); raise &solver contact_max_iterations'
      if (.not. springs_settled) errmsg = trim(errmsg)//', or use fewer elements or stiffer stops (soft springs on '// &
                                          'many nodes, docs/method.md "Statics")'
   end subroutine settle_level

   !> The sides the iterate asks for: a held point whose rigid reaction pulls is freed; a
   !! free point at or beyond a bound within the accuracy the positions reach is held there
   !! (its reaction then decides: positions cannot tell a node that touches from one that
   !! misses by less than their round-off, e.g. the nodes of a floor between held ones at
   !! N = 1e5 sag by 4e-23 m), unless it was freed for pulling in this level, which is held
   !! again only when it lies beyond the bound by more than that accuracy.
   pure function proposed_sides(contacts, included, state) result(side)
      type(contact_set), intent(in) :: contacts
      logical, intent(in) :: included(:)
      type(static_state), intent(in) :: state
      integer :: side(size(included))
      integer :: c
      real(dp) :: margin
      side = state%side
      do c = 1, size(included)
         if (.not. included(c)) cycle
         if (state%side(c) /= 0) then
            if (state%side(c)*rigid_reaction(contacts, state, c, state%reaction(c), state%position(c)) < 0) side(c) = 0
            cycle
         end if
         margin = state%reached(c)
         if (state%released(c)) margin = -state%reached(c)
         if (contacts%lower(c) > -no_bound .and. state%position(c) < contacts%lower(c) + margin) then
            side(c) = 1
         else if (contacts%upper(c) < no_bound .and. state%position(c) > contacts%upper(c) - margin) then
            side(c) = -1
         end if
      end do
   end function proposed_sides

   !> Newton's test for the compliant stops (theory §8, "Solving the step"): at every
   !! included point with springs and no rigid bound held, the force of the linearization
   !! (the reaction solved for; 0 at a point not supported) matches the law at the new
   !! iterate to 1024 eps of the largest force, or (after a Newton step) the positions
   !! stopped changing (1024 eps of the largest).
   pure logical function compliant_settled(contacts, included, state, previous, stepped) result(settled)
      type(contact_set), intent(in) :: contacts
      logical, intent(in) :: included(:)
      type(static_state), intent(in) :: state
      real(dp), intent(in) :: previous(:)
      logical, intent(in) :: stepped     !! previous is the iterate before the last solve
      real(dp) :: force, slope, worst_force, largest_force, worst_move, largest_move
      integer :: c
      settled = .true.
      if (contacts%springs%count == 0) return
      worst_force = 0
      largest_force = 0
      worst_move = 0
      largest_move = 0
      do c = 1, size(included)
         if (.not. included(c) .or. state%side(c) /= 0) cycle
         if (.not. has_springs(state, c)) cycle
         call spring_law(contacts, state, c, state%position(c), force, slope)
         worst_force = max(worst_force, abs(force - state%reaction(c)))
         largest_force = max(largest_force, abs(force), abs(state%reaction(c)))
         worst_move = max(worst_move, abs(state%position(c) - previous(c)))
         largest_move = max(largest_move, abs(state%position(c)))
      end do
      settled = worst_force <= 1024*epsilon(1.0_dp)*largest_force .or. &
                (stepped .and. worst_move <= 1024*epsilon(1.0_dp)*largest_move)
   end function compliant_settled

   !> The a-posteriori check of a static answer (module documentation), and the report of
   !! its accuracy:
   !! - the nodal displacements against K^-1 (F + H^T P) computed independently (the loads
   !!   and the reactions summed from the tip), to the round-off of both computations (each
   !!   `flexibility_rounding` of the magnitude of |F| + |H^T| |P|) and of forming P from
   !!   the moments (`rounding`); the moments' own error is common to both and cancels;
   !! - held points on their bounds, free points within them and elastic supports on their
   !!   spring law, to the bound of their positions (`tolerance`);
   !! - with `required` > 0, the derived bound of every nodal displacement within it.
   subroutine check_equilibrium(flexibility, model, contacts, force, state, required, report, stat, errmsg)
      type(cantilever_flexibility), intent(inout) :: flexibility
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:)
      type(static_state), intent(in) :: state
      real(dp), intent(in) :: required   !! largest position bound accepted (m); 0: any
      type(static_report), intent(inout) :: report
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: recomputed(:), bound(:), rounding_bound(:), w(:), w_check(:), w_bound(:)
      real(dp) :: excess, force_c, slope, gap
      integer :: c, worst
      !> what to do about it: the one known cause is soft springs on many nodes
      character(len=*), parameter :: advice = '; not trusted. Compliant stops far softer than the beam '// &
         'between many nodes make the equations ill-conditioned: use fewer elements or stiffer stops '// &
         '(docs/method.md, "Statics")'
      stat = 0
      errmsg = ''
      report%unknown_bound = state%unknown_bound
      report%reaction_bound = state%reaction_bound
      report%reaction_sum_bound = state%reaction_sum_bound
      recomputed = force + rows_transpose(contacts, state%reaction, model%unknowns)
      call flexibility%solve(recomputed)
      allocate (bound(model%unknowns), rounding_bound(model%unknowns))
      call flexibility%magnitude(abs(force) + rows_transpose(contacts, abs(state%reaction), model%unknowns), bound)
      call flexibility%magnitude(rows_transpose(contacts, state%rounding, model%unknowns), rounding_bound)
      allocate (w(model%elements + 1), w_check(model%elements + 1), w_bound(model%elements + 1))
      w = nodal_displacement(model, state%u)
      w_check = nodal_displacement(model, recomputed)
      w_bound = 2*flexibility_rounding(model%elements)*nodal_displacement(model, bound) + &
                (1 + flexibility_rounding(model%elements))*nodal_displacement(model, rounding_bound)
      report%error_estimate = maxval(abs(w - w_check))
      report%error_bound = maxval(w_bound)
      report%displacement_scale = maxval(abs(w))
      report%position_bound = maxval(nodal_displacement(model, state%unknown_bound))
      worst = maxloc(abs(w - w_check) - w_bound, dim=1)
      if (abs(w(worst) - w_check(worst)) > w_bound(worst)) then
         stat = stat_residual_check_failed
         write (errmsg, '(a,es10.3,a,es10.3,a,es10.3,a)') 'the static answer fails its check: at x = ', &
            model%x(worst), ' m the displacement differs from K^-1 (F + H^T P) by ', abs(w(worst) - w_check(worst)), &
            ' m, beyond its round-off bound ', w_bound(worst), ' m'//advice
         return
      end if
      do c = 1, contacts%count
         excess = 0
         if (state%side(c) > 0) then
            excess = abs(state%position(c) - contacts%lower(c))
         else if (state%side(c) < 0) then
            excess = abs(state%position(c) - contacts%upper(c))
         else
            excess = max(contacts%lower(c) - state%position(c), state%position(c) - contacts%upper(c), 0.0_dp)
            if (abs(state%reaction(c)) > 0) then
               ! an elastic support: its force on the law, to the law's slope times the
               ! position bound and 1024 eps of the force (Newton's test)
               call spring_law(contacts, state, c, state%position(c), force_c, slope)
               gap = abs(force_c - state%reaction(c)) - 1024*epsilon(1.0_dp)*max(abs(force_c), abs(state%reaction(c)))
               if (slope > 0) excess = max(excess, gap/slope)
            end if
         end if
         if (excess > state%tolerance(c)) then
            stat = stat_residual_check_failed
            write (errmsg, '(a,es10.3,a,es10.3,a,es10.3,a)') 'the static answer fails its check: at the contact '// &
               'point x = ', contacts%x(c), ' m the position misses its bound or spring law by ', excess, &
               ' m, beyond its round-off bound ', state%tolerance(c), ' m'//advice
            return
         end if
      end do
      if (required > 0 .and. report%position_bound > required) then
         stat = stat_residual_check_failed
         write (errmsg, '(a,es10.3,a,es10.3,a)') 'the static answer fails its check: its displacements are bounded to ', &
            report%position_bound, ' m (their derived round-off bound), not to &solver static_tolerance = ', required, &
            ' m; not trusted to it. Ask for no less than the round-off allows or, with compliant stops far softer '// &
            'than the beam between many nodes, use fewer elements or stiffer stops (docs/method.md, "Statics")'
      end if
   end subroutine check_equilibrium
end module vibrobeam_static
