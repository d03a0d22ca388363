!> The contact step of a beam of two planes in circular holes (docs/method.md, "Circular
!! obstacles"): given the free velocity V_free of a step of the velocity scheme, the
!! velocity V^{n+1} = V_free + W^-1 H^T (impulses) that the holes' walls allow, for rigid
!! walls (Newton's law, Coulomb friction) or compliant ones (a spring on each point's
!! penetration, Coulomb friction: `compliant_step`, in the submodule
!! `vibrobeam_circle_springs`). The state is stacked, y in 1:J and z in J+1:2J, and W is block diagonal (W_y, W_z), so
!! the blocks G_p of W_p^-1 between the points' deflections, computed once, make every
!! Delassus matrix of the step. The points: `vibrobeam_circle_set`; the time stepper
!! (`vibrobeam_velocity_stepper`) calls `rigid_step` or `compliant_step` in its step 3.
module vibrobeam_circle_contact
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: band_cholesky, band_solve
   use vibrobeam_lcp, only: solve_lcp
   use vibrobeam_frictional_contact, only: solve_frictional_contact, frictional_contact_solution
   use vibrobeam_compliant_law, only: stop_potential
   use vibrobeam_circle_set, only: circle_set
   implicit none
   private
   public :: circle_contact

   type :: circle_contact
      type(circle_set) :: circles
      type(band_cholesky) :: factor(2)             !! W_y and W_z (the same when z has no K of its own)
      !> G_p(k, l) = e_dof(k)^T W_p^-1 e_dof(l) (circles x circles x 2)
      real(dp), allocatable :: delassus(:, :, :)
      real(dp), allocatable :: push(:)             !! (2J) work space: W^-1 H^T (impulses)
      ! what the last rigid step did: its active points (the first `count` of `active`),
      ! each with its inward unit normal, normal impulse (N s), tangential impulse (N s,
      ! along the tangent t = (-n_z, n_y)) and normal and tangential velocities before (m/s);
      ! of a compliant step, the points with a friction force (normal impulse 0)
      integer :: count = 0
      integer, allocatable :: active(:)
      real(dp), allocatable :: normal(:, :), impulse(:), tangential(:), before(:), tangential_before(:)
      integer :: solves = 0                        !! solves of the last step (the midpoint normal's fixed point, Newton)
      ! what the last compliant step did, per point: radial penetrations at its start and
      ! end (m), force magnitude and its elastic part (N), force vector on the beam (N)
      real(dp), allocatable :: p0(:), p1(:), f(:), elastic(:), force(:, :)
      real(dp), allocatable :: start_velocity(:, :)   !! (2, circles) each point's (v, w) rate at the step's start
      real(dp), allocatable :: friction_force(:)      !! (circles) phi (N): the tangential force along t (0: frictionless)
   contains
      procedure :: setup
      procedure :: rigid_step
      procedure :: compliant_step
      procedure :: potential
      procedure, private :: apply
   end type circle_contact

   interface
      !> Compliant walls (circles and flat points): the step's end velocity V^{n+1} with the
      !! points' springs and their Coulomb friction, by Newton's method (submodule
      !! `vibrobeam_circle_springs`, where the method is described).
      module subroutine compliant_step(self, u, v, v_free, dt, theta, rule, v_new, stat, errmsg)
         class(circle_contact), intent(inout) :: self
         real(dp), intent(in) :: u(:), v(:), v_free(:)   !! U^n, V^n, V_free (2J)
         real(dp), intent(in) :: dt, theta
         integer, intent(in) :: rule                     !! `vibrobeam_compliant_law`'s rule
         real(dp), intent(out) :: v_new(:)
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine compliant_step
   end interface

contains

   !> Keep the points and the factors of W_y and W_z (`factor_z` = `factor_y` when z shares
   !! K), and compute G_y and G_z: one band solve per point and plane, once per run.
   subroutine setup(self, circles, factor_y, factor_z)
      class(circle_contact), intent(inout) :: self
      type(circle_set), intent(in) :: circles
      type(band_cholesky), intent(in) :: factor_y, factor_z
      real(dp) :: column(factor_y%n)
      integer :: k, plane, m
      self%circles = circles
      self%factor = [factor_y, factor_z]
      m = circles%count
      allocate (self%delassus(m, m, 2), self%push(2*factor_y%n), self%active(m), self%normal(2, m), self%impulse(m), &
                self%tangential(m), self%before(m), self%tangential_before(m))
      allocate (self%p0(m), self%p1(m), self%f(m), self%elastic(m), self%force(2, m), self%start_velocity(2, m), &
                self%friction_force(m), source=0.0_dp)
      do plane = 1, 2
         do k = 1, m
            column = 0
            column(circles%dof(k)) = 1
            call band_solve(self%factor(plane), column)
            self%delassus(:, k, plane) = column(circles%dof)
         end do
      end do
   end subroutine setup

   !> Rigid walls: point k is active when its gap (R_k - |r~_k - c_k| for a circle, h_k.r~_k -
   !! b_k for a flat point) is at most `tolerance` at the predicted position r~ = (v, w) of
   !! U^n + gamma dt V^n. Its constraint row is an inward unit normal h_k, frozen over each
   !! solve (the tangent half-plane of the circle; a flat point's fixed normal), its
   !! friction row the tangent t_k = (-h_z, h_y). Frictionless, Newton's law
   !! 0 <= p _|_ H (V^{n+1} + E V^n) >= 0 is the LCP(D, q) of the active points,
   !! D = H W^-1 H^T (from G_y, G_z), q = H V_free + E H V^n (`solve_lcp`); with friction
   !! (some active point's mu > 0) the normal and tangential rows together make the 2-D
   !! frictional contact problem (`solve_frictional_contact`: Signorini with Newton's law,
   !! Coulomb at V^{n+1}). E: e for a point moving outwards, else `separating`. The normal
   !! is that of the step's midpoint, h = -r/|r| at r = U^n + dt (theta V^{n+1} + (1 -
   !! theta) V^n)/2 - c: a fixed point from the predicted normal, one solve per iteration,
   !! until no normal moves by more than 16 eps. V^{n+1} into v_new.
   subroutine rigid_step(self, u, v, v_free, dt, theta, gamma, tolerance, restitution, separating, v_new, stat, errmsg)
      class(circle_contact), intent(inout) :: self
      real(dp), intent(in) :: u(:), v(:), v_free(:)   !! U^n, V^n, V_free (2J)
      real(dp), intent(in) :: dt, theta, gamma
      real(dp), intent(in) :: tolerance               !! of the activation (m)
      real(dp), intent(in) :: restitution, separating !! e, and e of a point already moving inwards
      real(dp), intent(out) :: v_new(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), parameter :: normal_tolerance = 16*epsilon(1.0_dp)
      integer, parameter :: max_solves = 50
      real(dp), allocatable :: d(:, :), q(:), p(:), w(:), next(:, :), mu(:)
      type(frictional_contact_solution) :: solution
      real(dp) :: r(2), moved
      integer :: k, a, m, j, iterations, solve
      logical :: frictional
      stat = 0
      errmsg = ''
      j = size(u)/2
      m = 0
      associate (circles => self%circles)
         do k = 1, circles%count
            r = circles%position(k, u) + gamma*dt*point(v, k)
            if (circles%gap_at(k, r) > tolerance) cycle
            m = m + 1
            self%active(m) = k
            self%normal(:, m) = circles%normal_at(k, r)
         end do
         self%count = m
         self%solves = 0
         self%tangential(1:m) = 0
         if (m == 0) then
            v_new = v_free
            return
         end if
         mu = circles%friction(self%active(1:m))
         frictional = any(mu > 0)
         allocate (next(2, m))
         if (frictional) then
            allocate (d(2*m, 2*m), q(2*m))
         else
            allocate (d(m, m), q(m), p(m), w(m))
         end if
         do solve = 1, max_solves
            call assemble()
            if (frictional) then
               call solve_frictional_contact(d, q, mu, solution, stat, errmsg)
               if (stat == 0) then
                  self%impulse(1:m) = solution%impulse(1::2)
                  self%tangential(1:m) = solution%impulse(2::2)
               end if
            else
               call solve_lcp(d, q, p, w, iterations, stat, errmsg)
               if (stat == 0) self%impulse(1:m) = p
            end if
            if (stat /= 0) then
               errmsg = 'the contact problem of the circular obstacles: '//trim(errmsg)
               return
            end if
            self%solves = solve
            call self%apply(v_free, v_new)
            ! the normals at the midpoint r = U^n + dt/2 (theta V^{n+1} + (1 - theta) V^n) - c
            moved = 0
            do a = 1, m
               k = self%active(a)
               r = circles%position(k, u) + 0.5_dp*dt*(theta*point(v_new, k) + (1 - theta)*point(v, k))
               next(:, a) = circles%normal_at(k, r)
               moved = max(moved, maxval(abs(next(:, a) - self%normal(:, a))))
            end do
            if (moved <= normal_tolerance) exit
            self%normal(:, 1:m) = next
         end do
      end associate

   contains

      !> D and q of the active points with the present normals (and tangents), and the
      !! velocities before.
      subroutine assemble()
         real(dp) :: t_a(2), t_b(2)
         integer :: a, b, ka, kb
         do a = 1, m
            ka = self%active(a)
            t_a = [-self%normal(2, a), self%normal(1, a)]
            self%before(a) = dot_product(self%normal(:, a), point(v, ka))
            self%tangential_before(a) = dot_product(t_a, point(v, ka))
            do b = 1, m
               kb = self%active(b)
               t_b = [-self%normal(2, b), self%normal(1, b)]
               if (frictional) then
                  d(2*a - 1, 2*b - 1) = form(self%normal(:, a), ka, self%normal(:, b), kb)
                  d(2*a - 1, 2*b) = form(self%normal(:, a), ka, t_b, kb)
                  d(2*a, 2*b - 1) = form(t_a, ka, self%normal(:, b), kb)
                  d(2*a, 2*b) = form(t_a, ka, t_b, kb)
               else
                  d(a, b) = form(self%normal(:, a), ka, self%normal(:, b), kb)
               end if
            end do
            associate (normal_q => dot_product(self%normal(:, a), point(v_free, ka)) + &
                                   merge(restitution, separating, self%before(a) <= 0)*self%before(a))
               if (frictional) then
                  q(2*a - 1) = normal_q
                  q(2*a) = dot_product(t_a, point(v_free, ka))
               else
                  q(a) = normal_q
               end if
            end associate
         end do
      end subroutine assemble

      !> x^T G(k, l) y with G(k, l) = diag(G_y(k, l), G_z(k, l)).
      pure real(dp) function form(x, k, y, l)
         real(dp), intent(in) :: x(2), y(2)
         integer, intent(in) :: k, l
         form = x(1)*y(1)*self%delassus(k, l, 1) + x(2)*y(2)*self%delassus(k, l, 2)
      end function form

      !> (y, z) of a stacked vector at point k's node.
      pure function point(x, k) result(pair)
         real(dp), intent(in) :: x(:)
         integer, intent(in) :: k
         real(dp) :: pair(2)
         pair = [x(self%circles%dof(k)), x(j + self%circles%dof(k))]
      end function point
   end subroutine rigid_step

   !> v_new = v_free + W^-1 sum_a (p_a h_a + r_a t_a) at the active points' nodes: one band
   !! solve per plane.
   subroutine apply(self, v_free, v_new)
      class(circle_contact), intent(inout) :: self
      real(dp), intent(in) :: v_free(:)
      real(dp), intent(out) :: v_new(:)
      real(dp) :: t(2)
      integer :: a, c, j
      j = size(v_free)/2
      self%push = 0
      do a = 1, self%count
         c = self%circles%dof(self%active(a))
         t = [-self%normal(2, a), self%normal(1, a)]
         self%push(c) = self%push(c) + self%impulse(a)*self%normal(1, a) + self%tangential(a)*t(1)
         self%push(j + c) = self%push(j + c) + self%impulse(a)*self%normal(2, a) + self%tangential(a)*t(2)
      end do
      call band_solve(self%factor(1), self%push(1:j))
      call band_solve(self%factor(2), self%push(j + 1:))
      v_new = v_free + self%push
   end subroutine apply

   !> The energy stored in the compliant walls at the stacked state `u` (J): sum_k
   !! Phi_k(p_k), p_k the point's penetration (0 for rigid walls).
   real(dp) function potential(self, u)
      class(circle_contact), intent(in) :: self
      real(dp), intent(in) :: u(:)
      integer :: k
      potential = 0
      if (.not. self%circles%compliant) return
      do k = 1, self%circles%count
         potential = potential + stop_potential(self%circles%stiffness(k), self%circles%exponent(k), &
                                                self%circles%penetration(k, u))
      end do
   end function potential
end module vibrobeam_circle_contact
