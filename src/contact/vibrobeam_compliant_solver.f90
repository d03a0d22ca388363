!> The implicit solve of a step (or of statics) with compliant stops (docs/theory.md,
!! section "8. Compliant stops"; docs/method.md, "Compliant stops").
!!
!! Unknown x (the end-of-step velocity V^{n+1} in the velocity scheme, U in statics). Each
!! spring j has the penetration p_j(x) = q_j - s_j m H_j x, affine in x (m = theta dt for
!! the velocity scheme, 1 in statics), and the equation is
!!
!!     A (x - x_free) = f_scale sum_j s_j f_j(p_j(x)) H_j^T + H^T P        (f_scale = dt or 1)
!!
!! with P the impulses (forces) of the rigid obstacles. Newton's method: at iterate x^k
!! with forces f^k and slopes d^k = df/dp1, the linearized problem
!!
!!     J (y - x^k) = A (x_free - x^k) + f_scale sum_j s_j f_j^k H_j^T + H^T P,
!!     J = A + f_scale m sum_j d_j^k H_j^T H_j
!!
!! is solved exactly: J is a band matrix (each H_j^T H_j fits the band), factored once per
!! iteration, and the rigid constraints are the projection of theory §5 in the metric J.
!! Every spring's f is nondecreasing in p1, so the problem is the minimization of a strictly
!! convex function (plus the rigid constraints) and J is positive definite.
!!
!! For a piecewise-linear spring (exponent 1, no damping, rule 'mean') this is the active-set
!! method: the trial set of engaged springs defines J, and the iteration stops when the set
!! at the new iterate is the trial set, with the exact solution. Convergence test (any law):
!! the forces at the new iterate agree with the linearized ones,
!!
!!     max_j |f_j(p_j(y)) - f_j^k - d_j^k (p_j(y) - p_j^k)| <= tol max_j |f_j(p_j(y))|,
!!
!! tol = 1024 eps (the forces are then exact to round-off), or every spring's penetration
!! stops changing to its own round-off, |p_j(y) - p_j^k| <= tol (|q_j| + m |H_j| |y|) for
!! every j (the size of the terms p_j is computed from: a spring engaged by 1e-16 m beside
!! one 2 mm away is judged on its own scale). At most `max_newton` iterations; otherwise
!! stat = stat_no_convergence (the run stops with exit 3). The force the accepted step applied (`force`) and
!! the rule's force at the accepted penetrations (`law_force`) differ by the remaining
!! residual: the steppers book its work and stop a run in which it is not negligible
!! (docs/theory.md section 8, "Accuracy").
module vibrobeam_compliant_solver
   use vibrobeam_status, only: stat_linear_solver_failure, stat_no_convergence
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_factor, band_solve, band_matvec, band_add
   use vibrobeam_contact_set, only: contact_set, contact_value
   use vibrobeam_contact_projector, only: contact_projector
   use vibrobeam_compliant_law, only: spring_set, step_force
   implicit none
   private
   public :: compliant_solver, rigid_none, rigid_active, rigid_admissible, add_row_product

   integer, parameter :: rigid_none = 0, rigid_active = 1, rigid_admissible = 2
   integer, parameter :: max_newton = 60
   real(dp), parameter :: tol = 1024*epsilon(1.0_dp)

   type :: compliant_solver
      integer :: rule = 1
      character(len=16) :: regime = 'auto', method = 'newton'
      type(symmetric_band) :: jacobian
      type(band_cholesky) :: jacobian_factor
      type(contact_projector) :: projector           !! rigid projection in the metric J
      real(dp), allocatable :: p1(:)                 !! penetrations at the solution (m)
      real(dp), allocatable :: force(:)              !! step force f_j the momentum equation applied (N)
      real(dp), allocatable :: elastic(:)            !! its elastic part (N)
      !> the rule's force f_j(p0_j, p1_j) at the accepted penetrations (N): `force` up to
      !! the Newton residual
      real(dp), allocatable :: law_force(:)
      integer :: iterations = 0, linear_solves = 0
   contains
      procedure :: setup
      procedure :: solve
      procedure, private :: linearized_free
   end type compliant_solver

   !> The springs at an iterate x of Newton's method.
   type :: spring_iterate
      real(dp), allocatable :: penetration(:)   !! p_j(x) (m)
      real(dp), allocatable :: force(:)         !! f_j the step force (N)
      real(dp), allocatable :: slope(:)         !! d_j = df_j/dp1 (N/m)
      real(dp), allocatable :: elastic(:)       !! the elastic part of f_j (N)
      real(dp), allocatable :: floor(:)         !! |q_j| + m |H_j| |x|: the size of p_j's terms (m)
   end type spring_iterate

contains

   subroutine setup(self, springs, rule, regime, method)
      class(compliant_solver), intent(inout) :: self
      type(spring_set), intent(in) :: springs
      integer, intent(in) :: rule
      character(len=*), intent(in) :: regime, method
      self%rule = rule
      self%regime = regime
      self%method = method
      allocate (self%p1(springs%count), self%force(springs%count), self%elastic(springs%count), &
                self%law_force(springs%count))
      self%p1 = 0
      self%force = 0
      self%elastic = 0
      self%law_force = 0
   end subroutine setup

   !> Solve the step (module comment). `q` (per spring) and `motion_scale` m define
   !! p_j(x) = q_j - s_j m H_j x; `p0` the penetrations at the start of the step (for the
   !! step's force rule and damping); theta, dt as in `step_force`. Rigid constraints:
   !! rigid_kind = rigid_active (active(k), s(k), b(k) as `project`), rigid_admissible (all
   !! contact points' bounds, statics) or rigid_none. base_projector: the projection in the
   !! metric A (used when no spring is engaged). stat: 0 ok; 1 Newton did not converge;
   !! 2.. the projection's or factorization's failure.
   subroutine solve(self, springs, contacts, a, base_projector, x_free, q, p0, motion_scale, force_scale, theta, dt, &
                    rigid_kind, active, s, b, x, impulse, stat, errmsg)
      class(compliant_solver), intent(inout) :: self
      type(spring_set), intent(in) :: springs
      type(contact_set), intent(in) :: contacts
      type(symmetric_band), intent(in) :: a
      type(contact_projector), intent(inout) :: base_projector
      real(dp), intent(in) :: x_free(:), q(:), p0(:), motion_scale, force_scale, theta, dt
      integer, intent(in) :: rigid_kind
      integer, intent(in) :: active(:)
      real(dp), intent(in) :: s(:), b(:)
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(spring_iterate) :: now, next
      real(dp) :: y_free(size(x)), residual
      integer :: it
      stat = 0
      errmsg = ''
      self%iterations = 0
      self%linear_solves = 0
      x = x_free
      call evaluate_springs(self%rule, springs, contacts, q, p0, motion_scale, theta, dt, x, now)
      do it = 1, max_newton
         self%iterations = it
         if (any(now%force > 0) .or. any(now%slope > 0)) then
            ! engaged: the linearized problem in the metric J
            call self%linearized_free(springs, contacts, a, x_free, x, now, motion_scale, force_scale, y_free, stat, &
                                      errmsg)
            if (stat /= 0) return
            if (rigid_kind /= rigid_none) then
               call self%projector%setup(self%jacobian, self%jacobian_factor, contacts, self%regime, self%method)
               call project_rigid(self%projector, rigid_kind, y_free, active, s, b, x, impulse, self%linear_solves, &
                                  stat, errmsg)
            else
               x = y_free
               impulse = 0
            end if
         else
            y_free = x_free
            if (rigid_kind /= rigid_none) then
               call project_rigid(base_projector, rigid_kind, y_free, active, s, b, x, impulse, self%linear_solves, &
                                  stat, errmsg)
            else
               x = y_free
               impulse = 0
            end if
         end if
         if (stat /= 0) return
         call evaluate_springs(self%rule, springs, contacts, q, p0, motion_scale, theta, dt, x, next)
         residual = linearization_residual(now, next)
         ! the forces the momentum equation used are f + slope (p_new - p); they agree with
         ! f(p_new) to the tolerance, or no spring's penetration moves beyond its round-off
         if (residual <= tol*maxval(abs(next%force)) .or. all(abs(next%penetration - now%penetration) <= tol*next%floor)) then
            self%p1 = next%penetration
            self%force = now%force + now%slope*(next%penetration - now%penetration)   ! what the momentum equation applied
            self%elastic = next%elastic
            self%law_force = next%force
            return
         end if
         now = next
      end do
      stat = stat_no_convergence
      write (errmsg, '(a,i0,a,es10.3,a)') 'the compliant stops did not converge in ', max_newton, &
         ' Newton iterations (force residual ', residual, ' N); reduce dt, or the stiffness of a stop '// &
         'whose contact time scale (vibrobeam --check) is far below dt'
   end subroutine solve

   !> The free solution y_free of the problem linearized at the iterate x (module
   !! comment): J = A + f_scale m sum_j d_j H_j^T H_j factored into self%jacobian_factor,
   !! y_free = x + J^-1 (A (x_free - x) + f_scale sum_j s_j f_j H_j^T). stat = stat_linear_solver_failure when J
   !! cannot be factored.
   subroutine linearized_free(self, springs, contacts, a, x_free, x, now, motion_scale, force_scale, y_free, stat, &
                              errmsg)
      class(compliant_solver), intent(inout) :: self
      type(spring_set), intent(in) :: springs
      type(contact_set), intent(in) :: contacts
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: x_free(:), x(:), motion_scale, force_scale
      type(spring_iterate), intent(in) :: now
      real(dp), intent(out) :: y_free(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: rhs(size(x))
      integer :: j
      self%jacobian = a
      do j = 1, springs%count
         if (now%slope(j) > 0) call add_row_product(self%jacobian, contacts, springs%point(j), &
                                                    force_scale*motion_scale*now%slope(j))
      end do
      call band_factor(self%jacobian, self%jacobian_factor, stat, errmsg)
      if (stat /= 0) then
         stat = stat_linear_solver_failure
         return
      end if
      call band_matvec(a, x_free - x, rhs)
      do j = 1, springs%count
         if (now%force(j) > 0) call add_row(rhs, contacts, springs%point(j), force_scale*springs%sign(j)*now%force(j))
      end do
      call band_solve(self%jacobian_factor, rhs)
      self%linear_solves = self%linear_solves + 1
      y_free = x + rhs
   end subroutine linearized_free

   !> Penetrations, forces, slopes and elastic parts of the springs at x (`rule`'s step
   !! force, p_j = q_j - s_j m H_j x); `floor` the size of the terms of each penetration,
   !! |q_j| + m |H_j| |x| (its round-off is eps times that).
   subroutine evaluate_springs(rule, springs, contacts, q, p0, motion_scale, theta, dt, x, at)
      integer, intent(in) :: rule
      type(spring_set), intent(in) :: springs
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: q(:), p0(:), motion_scale, theta, dt, x(:)
      type(spring_iterate), intent(inout) :: at
      integer :: i, a
      if (.not. allocated(at%penetration)) allocate (at%penetration(springs%count), at%force(springs%count), &
                                                     at%slope(springs%count), at%elastic(springs%count), &
                                                     at%floor(springs%count))
      do i = 1, springs%count
         at%penetration(i) = q(i) - springs%sign(i)*motion_scale*contact_value(contacts, springs%point(i), x)
         at%floor(i) = abs(q(i))
         do a = 1, 4
            if (contacts%dofs(a, springs%point(i)) /= 0) at%floor(i) = at%floor(i) + motion_scale* &
               abs(contacts%weights(a, springs%point(i))*x(contacts%dofs(a, springs%point(i))))
         end do
         call step_force(rule, springs%stiffness(i), springs%exponent(i), springs%damping(i), theta, dt, &
                         p0(i), at%penetration(i), at%force(i), at%slope(i), at%elastic(i))
      end do
   end subroutine evaluate_springs

   !> max_j |f_j(p_j(y)) - f_j^k - d_j^k (p_j(y) - p_j^k)|: how far the forces at the new
   !! iterate `next` are from the linearization at `now`.
   pure real(dp) function linearization_residual(now, next) result(residual)
      type(spring_iterate), intent(in) :: now, next
      integer :: j
      residual = 0
      do j = 1, size(now%force)
         residual = max(residual, abs(next%force(j) - now%force(j) - now%slope(j)*(next%penetration(j) - &
                                                                                   now%penetration(j))))
      end do
   end function linearization_residual

   !> The rigid constraints' projection of y_free by `projector` (rigid_active: the
   !! active set `active`, `s`, `b` as `project`; rigid_admissible: every contact point's
   !! bounds); its linear solves are added to `linear_solves`, its failure is stat + 1.
   subroutine project_rigid(projector, rigid_kind, y_free, active, s, b, x, impulse, linear_solves, stat, errmsg)
      type(contact_projector), intent(inout) :: projector
      integer, intent(in) :: rigid_kind
      real(dp), intent(in) :: y_free(:), s(:), b(:)
      integer, intent(in) :: active(:)
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(inout) :: linear_solves
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: iterations
      if (rigid_kind == rigid_active) then
         call projector%project(y_free, active, s, b, x, impulse, iterations, stat, errmsg)
      else
         call projector%project_admissible(y_free, x, impulse, iterations, stat, errmsg)
      end if
      linear_solves = linear_solves + projector%linear_solves
      if (stat /= 0) stat = stat + 1
   end subroutine project_rigid

   !> J <- J + w H_c^T H_c.
   subroutine add_row_product(jacobian, contacts, c, w)
      type(symmetric_band), intent(inout) :: jacobian
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: c
      real(dp), intent(in) :: w
      integer :: i, k
      do i = 1, 4
         if (contacts%dofs(i, c) == 0) cycle
         do k = 1, 4
            if (contacts%dofs(k, c) == 0 .or. contacts%dofs(k, c) > contacts%dofs(i, c)) cycle
            call band_add(jacobian, contacts%dofs(i, c), contacts%dofs(k, c), &
                          w*contacts%weights(i, c)*contacts%weights(k, c))
         end do
      end do
   end subroutine add_row_product

   !> r <- r + w H_c^T.
   pure subroutine add_row(r, contacts, c, w)
      real(dp), intent(inout) :: r(:)
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: c
      real(dp), intent(in) :: w
      integer :: i
      do i = 1, 4
         if (contacts%dofs(i, c) /= 0) r(contacts%dofs(i, c)) = r(contacts%dofs(i, c)) + w*contacts%weights(i, c)
      end do
   end subroutine add_row
end module vibrobeam_compliant_solver
