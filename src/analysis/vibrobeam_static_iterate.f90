!> The iterate of the static active-set Newton iteration (`vibrobeam_static`) and its
!! solve with the current supports (theory §5 "Statics"; docs/method.md, "Statics"): the
!! held points on their bounds and the free points' compliant stops linearized as elastic
!! supports, solved in curvatures (`held_equilibrium`), refined, with the round-off bound
!! of every unknown, position and reaction; and the springs' law at a contact point.
module vibrobeam_static_iterate
   use vibrobeam_kinds, only: dp
   use vibrobeam_flexibility, only: cantilever_flexibility, flexibility_rounding
   use vibrobeam_support_moments, only: held_equilibrium, add_moment_line
   use vibrobeam_contact_set, only: contact_set, contact_value, no_bound
   use vibrobeam_compliant_law, only: elastic_force, elastic_slope
   use vibrobeam_contact_system, only: scatter_rows
   implicit none
   private
   public :: static_state, solve_supported, index_springs, has_springs, spring_law, rigid_reaction, rows_transpose

   !> The iterate of the active-set Newton iteration.
   type :: static_state
      integer, allocatable :: side(:)        !! (contact points) +1 lower bound held, -1 upper, 0 not
      real(dp), allocatable :: position(:)   !! (contact points) H_c U (m)
      real(dp), allocatable :: tolerance(:)  !! (contact points) round-off bound of the position (m)
      !> (contact points) the accuracy the positions reach (m): 4 times the largest miss of a
      !! held point plus 16 eps of the point's scale
      real(dp), allocatable :: reached(:)
      !> (contact points) freed in this level because its reaction pulled: held again only
      !! beyond its bound by more than `reached`
      logical, allocatable :: released(:)
      integer, allocatable :: releases(:)    !! (contact points) times freed for pulling in this level
      real(dp), allocatable :: reaction(:)   !! (contact points) P_c (N), 0 where not supported
      real(dp), allocatable :: rounding(:)   !! (contact points) bound of the rounding of P_c formed from lambda (N)
      real(dp), allocatable :: reaction_bound(:)  !! (contact points) bound of the error of P_c (N)
      real(dp), allocatable :: unknown_bound(:)   !! (J) bound of the error of each unknown
      real(dp) :: reaction_sum_bound = 0          !! bound of the error of the sum of the reactions (N)
      real(dp), allocatable :: u(:), z(:)    !! (J) unknowns and curvature
      !> the springs of contact point c are spring_index(spring_first(c):spring_first(c+1)-1)
      !! (so that a point's springs cost their number, not the count of all springs)
      integer, allocatable :: spring_first(:), spring_index(:)
   end type static_state

contains

   !> Solve with the current sides held and the springs of the free included points
   !! linearized at the current positions (elastic supports); update positions, reactions,
   !! their round-off bounds and the accuracy the positions reach.
   subroutine solve_supported(flexibility, contacts, force, free_curvature, curvature_error, included, state, stat, errmsg)
      type(cantilever_flexibility), intent(in) :: flexibility
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:), free_curvature(:)
      real(dp), intent(in) :: curvature_error(:)   !! bound of the error of free_curvature
      logical, intent(in) :: included(:)
      type(static_state), intent(inout) :: state
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, allocatable :: held(:)
      real(dp), allocatable :: targets(:), compliance(:), reaction(:), moment(:), moment_error(:), rounding(:), &
                               reaction_error(:)
      integer :: m
      call supports(contacts, included, state, held, targets, compliance)
      m = size(held)
      allocate (reaction(m), moment(0:m), moment_error(0:m), rounding(m), reaction_error(m))
      call held_equilibrium(flexibility, free_curvature, curvature_error, contacts%node(held), targets, compliance, &
                            state%z, state%u, reaction, moment, moment_error, rounding, reaction_error, stat, errmsg)
      if (stat /= 0) return
      call refine(flexibility, contacts, held, targets, compliance, state, reaction, stat, errmsg)
      if (stat /= 0) return
      state%reaction = 0
      state%rounding = 0
      state%reaction_bound = 0
      state%reaction(held) = reaction
      state%rounding(held) = rounding
      state%reaction_bound(held) = reaction_error
      state%reaction_sum_bound = 0
      if (m > 0) state%reaction_sum_bound = (moment_error(0) + moment_error(min(1, m)) + &
                                             2*epsilon(1.0_dp)*abs(moment(0) - moment(min(1, m))))/ &
                                            flexibility%position(contacts%node(held(1))) + &
                                            epsilon(1.0_dp)*sum(abs(reaction))
      call update_bounds(flexibility, contacts, force, held, targets, compliance, moment_error, state)
   end subroutine solve_supported

   !> The supports of the solve: the included points held on a bound (`targets` the
   !! bound, compliance 0), and the free included points whose springs push (slope > 0),
   !! linearized at their position: P = F0 + d (w0 - w) = d (t - w), t = w0 + F0/d,
   !! compliance 1/d.
   subroutine supports(contacts, included, state, held, targets, compliance)
      type(contact_set), intent(in) :: contacts
      logical, intent(in) :: included(:)
      type(static_state), intent(in) :: state
      integer, allocatable, intent(out) :: held(:)
      real(dp), allocatable, intent(out) :: targets(:), compliance(:)
      real(dp) :: spring_force, slope
      integer :: c, k
      logical :: supported(size(included))
      do c = 1, size(included)
         supported(c) = included(c) .and. state%side(c) /= 0
         if (included(c) .and. state%side(c) == 0 .and. has_springs(state, c)) then
            call spring_law(contacts, state, c, state%position(c), spring_force, slope)
            supported(c) = slope > 0
         end if
      end do
      held = pack([(c, c=1, size(included))], supported)
      allocate (targets(size(held)), compliance(size(held)))
      do k = 1, size(held)
         c = held(k)
         compliance(k) = 0
         if (state%side(c) > 0) then
            targets(k) = contacts%lower(c)
         else if (state%side(c) < 0) then
            targets(k) = contacts%upper(c)
         else
            call spring_law(contacts, state, c, state%position(c), spring_force, slope)
            targets(k) = state%position(c) + spring_force/slope
            compliance(k) = 1/slope
         end if
      end do
   end subroutine supports

   !> Iterative refinement of the solve. Rigid supports only: one step, of the positions:
   !! the held nodes miss their targets by the rounding accumulated along the beam (1e-16 m
   !! at N = 1e5 with B-splines, smooth), more than the gaps that decide a contact near a
   !! touchdown (4e-18 m one node before it); the same solve with no load and the misses as
   !! targets corrects them to the local rounding (1e-19 m). Not the reactions: the misses
   !! also hold that local rounding, node to node, whose fourth difference over h^3
   !! (EI 16 eps |w|/h^3, 0.4 N at N = 1e5 against reactions of 2e-4 N on a floor) would
   !! swamp them; they keep the accuracy of the first solve. With elastic supports their
   !! law w = t - c P is part of the equations, and soft springs on short spans make them
   !! ill-conditioned (a compliant floor: EI c/h^3 >> 1); there the whole solution is
   !! refined, up to 4 steps while the largest miss falls (each step gains a factor
   !! eps cond), and a spring's force changes with its miss by at most its stiffness.
   subroutine refine(flexibility, contacts, held, targets, compliance, state, reaction, stat, errmsg)
      type(cantilever_flexibility), intent(in) :: flexibility
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: held(:)
      real(dp), intent(in) :: targets(:), compliance(:)
      type(static_state), intent(inout) :: state
      real(dp), intent(inout) :: reaction(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: miss(:), correction_z(:), correction_u(:), correction_reaction(:), zeros(:)
      ! outputs of held_equilibrium the refinement does not use; each its own array (Fortran
      ! forbids actual arguments that overlap when one of them is written)
      real(dp), allocatable :: unused_moment(:), unused_moment_error(:), unused_rounding(:), unused_reaction_error(:)
      real(dp) :: previous_miss
      integer :: k, m, n, step
      stat = 0
      errmsg = ''
      m = size(held)
      n = flexibility%unknowns
      allocate (miss(m), correction_z(n), correction_u(n), correction_reaction(m), zeros(n))
      allocate (unused_moment(0:m), unused_moment_error(0:m), unused_rounding(m), unused_reaction_error(m))
      zeros = 0
      previous_miss = huge(1.0_dp)
      do step = 1, merge(4, 1, any(compliance > 0))
         do k = 1, m
            miss(k) = targets(k) - compliance(k)*reaction(k) - contact_value(contacts, held(k), state%u)
         end do
         if (m == 0) exit
         if (.not. maxval(abs(miss)) < previous_miss) exit
         previous_miss = maxval(abs(miss))
         ! (the correction's own bounds are second order: those of the first solve stand)
         call held_equilibrium(flexibility, zeros, zeros, contacts%node(held), miss, compliance, correction_z, &
                               correction_u, correction_reaction, unused_moment, unused_moment_error, unused_rounding, &
                               unused_reaction_error, stat, errmsg)
         if (stat /= 0) return
         state%z = state%z + correction_z
         state%u = state%u + correction_u
         if (any(compliance > 0)) reaction = reaction + correction_reaction
      end do
   end subroutine refine

   !> The positions of the iterate and their bounds (module documentation of
   !! `vibrobeam_static`): the unknowns' round-off (the flexibility's of F and of the
   !! reactions, |kappa| <= the curvature magnitude of |F| + |H^T| |P|, and the moment
   !! line's error integrated: T has non-negative coefficients), each point's position
   !! bound and the accuracy the positions reach.
   subroutine update_bounds(flexibility, contacts, force, held, targets, compliance, moment_error, state)
      type(cantilever_flexibility), intent(in) :: flexibility
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: force(:), targets(:), compliance(:), moment_error(0:)
      integer, intent(in) :: held(:)
      type(static_state), intent(inout) :: state
      real(dp), allocatable :: line_error(:), line_u(:), u_abs(:)
      real(dp) :: missed
      integer :: c, k, m, n
      m = size(held)
      n = flexibility%unknowns
      do c = 1, size(state%position)
         state%position(c) = contact_value(contacts, c, state%u)
      end do
      call flexibility%magnitude(abs(force) + rows_transpose(contacts, abs(state%reaction), n), state%unknown_bound)
      allocate (line_error(n), source=0.0_dp)
      allocate (line_u(n))
      call add_moment_line(flexibility, contacts%node(held), moment_error(0:m - 1)/flexibility%ei, line_error)
      call flexibility%displacement_of_curvature(line_error, line_u)
      state%unknown_bound = flexibility_rounding(flexibility%elements)*state%unknown_bound + line_u
      missed = 0
      do k = 1, m
         if (compliance(k) > 0) cycle
         missed = max(missed, abs(state%position(held(k)) - targets(k)))
      end do
      ! a point's position bound: its row applied to the unknowns' bound, the rounding of the
      ! B-spline row weights and of the row product (32 eps |H_c| |U|; the row weights are
      ! >= 0), and that of the bound (4 eps |g|)
      u_abs = abs(state%u)
      do c = 1, size(state%position)
         state%tolerance(c) = contact_value(contacts, c, state%unknown_bound) + &
                              32*epsilon(1.0_dp)*contact_value(contacts, c, u_abs) + &
                              4*epsilon(1.0_dp)*finite_bound_scale(contacts, c)
         state%reached(c) = min(4*missed + 16*epsilon(1.0_dp)*max(abs(state%position(c)), finite_bound_scale(contacts, c)), &
                                state%tolerance(c))
      end do
   end subroutine update_bounds

   !> The rigid bound's share of the reaction P at point c: P minus the springs' forces at
   !! the point's position.
   pure real(dp) function rigid_reaction(contacts, state, c, total, position)
      type(contact_set), intent(in) :: contacts
      type(static_state), intent(in) :: state
      integer, intent(in) :: c
      real(dp), intent(in) :: total, position
      real(dp) :: force, slope
      call spring_law(contacts, state, c, position, force, slope)
      rigid_reaction = total - force
   end function rigid_reaction

   !> The springs of each contact point (state%spring_first, state%spring_index): counted,
   !! then listed in the order of their points.
   pure subroutine index_springs(contacts, state)
      type(contact_set), intent(in) :: contacts
      type(static_state), intent(inout) :: state
      integer :: j, c, next(contacts%count)
      allocate (state%spring_first(contacts%count + 1), source=0)
      allocate (state%spring_index(contacts%springs%count))
      do j = 1, contacts%springs%count
         c = contacts%springs%point(j)
         state%spring_first(c + 1) = state%spring_first(c + 1) + 1
      end do
      state%spring_first(1) = 1
      do c = 1, contacts%count
         state%spring_first(c + 1) = state%spring_first(c + 1) + state%spring_first(c)
      end do
      next = state%spring_first(1:contacts%count)
      do j = 1, contacts%springs%count
         c = contacts%springs%point(j)
         state%spring_index(next(c)) = j
         next(c) = next(c) + 1
      end do
   end subroutine index_springs

   !> Whether contact point c carries springs.
   pure logical function has_springs(state, c)
      type(static_state), intent(in) :: state
      integer, intent(in) :: c
      has_springs = state%spring_first(c + 1) > state%spring_first(c)
   end function has_springs

   !> Sum over the springs of point c at displacement w: force sum s_j f_j(p_j) (N, upwards)
   !! and its derivative with respect to -w, sum f_j'(p_j) (N/m), p_j = s_j (g_j - w).
   pure subroutine spring_law(contacts, state, c, w, force, slope)
      type(contact_set), intent(in) :: contacts
      type(static_state), intent(in) :: state
      integer, intent(in) :: c
      real(dp), intent(in) :: w
      real(dp), intent(out) :: force, slope
      real(dp) :: p
      integer :: k, j
      force = 0
      slope = 0
      associate (springs => contacts%springs)
         do k = state%spring_first(c), state%spring_first(c + 1) - 1
            j = state%spring_index(k)
            p = springs%sign(j)*(springs%level(j) - w)
            force = force + springs%sign(j)*elastic_force(springs%stiffness(j), springs%exponent(j), p)
            slope = slope + elastic_slope(springs%stiffness(j), springs%exponent(j), p)
         end do
      end associate
   end subroutine spring_law

   !> H^T p: the generalized forces of forces p_c at the contact points.
   pure function rows_transpose(contacts, p, unknowns) result(f)
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: p(:)
      integer, intent(in) :: unknowns   !! J
      real(dp) :: f(unknowns)
      integer :: c
      f = 0
      call scatter_rows(contacts, [(c, c=1, contacts%count)], p, f)
   end function rows_transpose

   !> The largest |bound| of point c among its finite ones (0 if none).
   pure real(dp) function finite_bound_scale(contacts, c)
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: c
      finite_bound_scale = 0
      if (contacts%lower(c) > -no_bound) finite_bound_scale = abs(contacts%lower(c))
      if (contacts%upper(c) < no_bound) finite_bound_scale = max(finite_bound_scale, abs(contacts%upper(c)))
   end function finite_bound_scale

end module vibrobeam_static_iterate
