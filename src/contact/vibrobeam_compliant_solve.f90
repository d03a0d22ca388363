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
!! stat = 1 (the run stops with exit 3). The force the accepted step applied (`force`) and
!! the rule's force at the accepted penetrations (`law_force`) differ by the remaining
!! residual: the steppers book its work and stop a run in which it is not negligible
!! (docs/theory.md section 8, "Accuracy").
module vibrobeam_compliant_solve
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_factor, band_solve, band_matvec, band_add
   use vibrobeam_contact_points, only: contact_set, contact_value
   use vibrobeam_contact_solver, only: contact_projector
   use vibrobeam_compliant_law, only: spring_set, step_force
   implicit none
   private
   public :: compliant_solver, rigid_none, rigid_active, rigid_admissible

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
   end type compliant_solver

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
      real(dp), dimension(springs%count) :: p, f, slope, elastic, p_new, f_new, slope_new, elastic_new, floor
      real(dp) :: y_free(size(x)), rhs(size(x)), residual, scale
      integer :: it, j, iterations
      logical :: engaged
      stat = 0
      errmsg = ''
      self%iterations = 0
      self%linear_solves = 0
      x = x_free
      call evaluate(x, p, f, slope, elastic)
      do it = 1, max_newton
         self%iterations = it
         engaged = any(f > 0) .or. any(slope > 0)
         if (engaged) then
            self%jacobian = a
            do j = 1, springs%count
               if (slope(j) > 0) call add_row_product(self%jacobian, contacts, springs%point(j), &
                                                      force_scale*motion_scale*slope(j))
            end do
            call band_factor(self%jacobian, self%jacobian_factor, stat, errmsg)
            if (stat /= 0) then
               stat = 2
               return
            end if
            call band_matvec(a, x_free - x, rhs)
            do j = 1, springs%count
               if (f(j) > 0) call add_row(rhs, contacts, springs%point(j), force_scale*springs%sign(j)*f(j))
            end do
            call band_solve(self%jacobian_factor, rhs)
            self%linear_solves = self%linear_solves + 1
            y_free = x + rhs
            if (rigid_kind /= rigid_none) then
               call self%projector%setup(self%jacobian, self%jacobian_factor, contacts, self%regime, self%method)
               call project(self%projector)
            else
               x = y_free
               impulse = 0
            end if
         else
            y_free = x_free
            if (rigid_kind /= rigid_none) then
               call project(base_projector)
            else
               x = y_free
               impulse = 0
            end if
         end if
         if (stat /= 0) return
         call evaluate(x, p_new, f_new, slope_new, elastic_new)
         scale = maxval(abs(f_new))
         residual = 0
         do j = 1, springs%count
            residual = max(residual, abs(f_new(j) - f(j) - slope(j)*(p_new(j) - p(j))))
         end do
         ! the forces the momentum equation used are f + slope (p_new - p); they agree with
         ! f(p_new) to the tolerance, or no spring's penetration moves beyond its round-off
         if (residual <= tol*scale .or. all(abs(p_new - p) <= tol*floor)) then
            self%p1 = p_new
            self%force = f + slope*(p_new - p)   ! what the momentum equation applied
            self%elastic = elastic_new
            self%law_force = f_new
            return
         end if
         p = p_new
         f = f_new
         slope = slope_new
         elastic = elastic_new
      end do
      stat = 1
      write (errmsg, '(a,i0,a,es10.3,a)') 'the compliant stops did not converge in ', max_newton, &
         ' Newton iterations (force residual ', residual, ' N); reduce dt, or the stiffness of a stop '// &
         'whose contact time scale (vibrobeam --check) is far below dt'
   contains
      !> Penetrations, forces, slopes and elastic parts at xx; `floor` the size of the terms
      !! of each penetration, |q_j| + m |H_j| |xx| (its round-off is eps times that).
      subroutine evaluate(xx, pp, ff, ss, ee)
         real(dp), intent(in) :: xx(:)
         real(dp), intent(out) :: pp(:), ff(:), ss(:), ee(:)
         integer :: i, a
         do i = 1, springs%count
            pp(i) = q(i) - springs%sign(i)*motion_scale*contact_value(contacts, springs%point(i), xx)
            floor(i) = abs(q(i))
            do a = 1, 4
               if (contacts%dofs(a, springs%point(i)) /= 0) floor(i) = floor(i) + motion_scale* &
                  abs(contacts%weights(a, springs%point(i))*xx(contacts%dofs(a, springs%point(i))))
            end do
            call step_force(self%rule, springs%stiffness(i), springs%exponent(i), springs%damping(i), theta, dt, &
                            p0(i), pp(i), ff(i), ss(i), ee(i))
         end do
      end subroutine evaluate

      subroutine project(projector)
         type(contact_projector), intent(inout) :: projector
         if (rigid_kind == rigid_active) then
            call projector%project(y_free, active, s, b, x, impulse, iterations, stat, errmsg)
         else
            call projector%project_admissible(y_free, x, impulse, iterations, stat, errmsg)
         end if
         self%linear_solves = self%linear_solves + projector%linear_solves
         if (stat /= 0) stat = stat + 1
      end subroutine project
   end subroutine solve

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
end module vibrobeam_compliant_solve
