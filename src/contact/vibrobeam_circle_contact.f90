!> The contact step of a beam of two planes in circular holes (docs/method.md, "Circular
!! obstacles"): given the free velocity V_free of a step of the velocity scheme, the
!! velocity V^{n+1} = V_free + W^-1 H^T (impulses) that the holes' walls allow, for rigid
!! walls (Newton's law, Coulomb friction) or compliant ones (a radial spring, Coulomb
!! friction). The
!! state is stacked, y in 1:J and z in J+1:2J, and W is block diagonal (W_y, W_z), so
!! the blocks G_p of W_p^-1 between the points' deflections, computed once, make every
!! Delassus matrix of the step. The points: `vibrobeam_circle_set`; the time stepper
!! (`vibrobeam_velocity_stepper`) calls `rigid_step` or `compliant_step` in its step 3.
module vibrobeam_circle_contact
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_linear_solver_failure, stat_no_convergence
   use vibrobeam_band, only: band_cholesky, band_solve
   use vibrobeam_lapack, only: dgesv
   use vibrobeam_lcp, only: solve_lcp
   use vibrobeam_frictional_contact, only: solve_frictional_contact, frictional_contact_solution
   use vibrobeam_compliant_law, only: step_force, stop_potential
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

   !> Compliant walls: each point's spring pushes inwards with the force of
   !! `vibrobeam_compliant_law` on the radial penetration p = |r| - R (r = (v, w) - c),
   !! over the step from p0 (U^n) to p1 (U^{n+1}): magnitude f(p0, p1) (the `rule`'s, with
   !! Hunt-Crossley damping), direction d = (r0 + r1)/(|r0| + |r1|), F = -f d. Then
   !! F.(r1 - r0) = -f (p1 - p0) exactly (as a level's spring: the 'gradient' rule
   !! conserves E + Phi), and F is parallel to the midpoint (r0 + r1)/2, so a centred hole
   !! keeps the angular momentum about the axis. The points' end velocities x solve
   !! x = V_free + dt G F(x) by Newton's method with the 2 x 2 derivatives of F (dense,
   !! LAPACK dgesv), until the residual is 16 eps of the velocities or an update moves no
   !! point beyond 1024 eps of its distance from the centre (as the levels' springs: the
   !! discrete gradient loses digits when p1 is close to p0); then V^{n+1} = V_free + dt
   !! W^-1 H^T F into v_new. stat_no_convergence after 50 iterations.
   !! With friction (some point's mu > 0; docs/method.md, "Coulomb friction at compliant
   !! circles"): each point also carries a tangential force phi t (N) along the tangent
   !! t = (-h_z, h_y) of the midpoint's inward normal h = -(r0 + r1)/|r0 + r1|, exact
   !! Coulomb at V^{n+1} as the rigid step: t.x = 0 and |phi| <= mu f (stick) or
   !! phi = -mu f sign(t.x) (slip), written as Alart and Curnier's equation
   !! phi = proj[-mu f, mu f](phi - t.x/(dt g)), g = max(G_y(k, k), G_z(k, k)), and solved
   !! with x by the same Newton iteration (semismooth: the branch of the projection taken
   !! at the present iterate); it stops on the same residual (the friction rows in m/s)
   !! or on the same small update when, besides, no point changed between stick and slip
   !! and no phi's update moved its point by more than the same 1024 eps of its distance
   !! from the centre (dt theta dt g |d phi|: phi = mu f inherits f's floor). The
   !! tangential impulses dt phi t are the step's `tangential` entries (impulse 0) for the
   !! energy ledger, as the rigid step's.
   subroutine compliant_step(self, u, v, v_free, dt, theta, rule, v_new, stat, errmsg)
      class(circle_contact), intent(inout) :: self
      real(dp), intent(in) :: u(:), v(:), v_free(:)   !! U^n, V^n, V_free (2J)
      real(dp), intent(in) :: dt, theta
      integer, intent(in) :: rule                     !! `vibrobeam_compliant_law`'s rule
      real(dp), intent(out) :: v_new(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, parameter :: max_iterations = 50
      real(dp), parameter :: converged = 1024*epsilon(1.0_dp)
      real(dp), dimension(2, self%circles%count) :: x, v0, x_free, r0, total_force
      real(dp), allocatable :: jacobian(:, :), step(:)
      real(dp) :: derivative(2, 2, self%circles%count), scale
      ! friction, per point: the tangent t and dt/dx, df/dx, phi (N), the weight dt g (m/(N s))
      real(dp), dimension(2, self%circles%count) :: tangent, force_slope
      real(dp) :: tangent_slope(2, 2, self%circles%count)
      real(dp), dimension(self%circles%count) :: phi, weight
      logical, dimension(self%circles%count) :: sticks, stuck
      logical :: frictional, settled
      integer, allocatable :: pivots(:)
      integer :: k, l, c, m, j, n, iteration, info
      stat = 0
      errmsg = ''
      m = self%circles%count
      j = size(u)/2
      associate (circles => self%circles)
         frictional = circles%frictional()
         n = merge(3*m, 2*m, frictional)
         allocate (jacobian(n, n), step(n), pivots(n))
         do k = 1, m
            c = circles%dof(k)
            v0(:, k) = [v(c), v(j + c)]
            self%start_velocity(:, k) = v0(:, k)
            x_free(:, k) = [v_free(c), v_free(j + c)]
            r0(:, k) = circles%offset(k, u)
            self%p0(k) = norm2(r0(:, k)) - circles%radius(k)
            weight(k) = dt*max(self%delassus(k, k, 1), self%delassus(k, k, 2))
         end do
         phi = 0
         sticks = .false.
         x = x_free
         do iteration = 1, max_iterations
            call forces_at(x)
            ! the residual -(x - V_free - dt G F) and the Jacobian I - dt G dF/dx
            jacobian = 0
            do k = 1, m
               step(2*k - 1:2*k) = -(x(:, k) - x_free(:, k))
               do l = 1, m
                  step(2*k - 1) = step(2*k - 1) + dt*self%delassus(k, l, 1)*total_force(1, l)
                  step(2*k) = step(2*k) + dt*self%delassus(k, l, 2)*total_force(2, l)
                  jacobian(2*k - 1, 2*l - 1:2*l) = -dt*self%delassus(k, l, 1)*derivative(1, :, l)
                  jacobian(2*k, 2*l - 1:2*l) = -dt*self%delassus(k, l, 2)*derivative(2, :, l)
               end do
               jacobian(2*k - 1, 2*k - 1) = jacobian(2*k - 1, 2*k - 1) + 1
               jacobian(2*k, 2*k) = jacobian(2*k, 2*k) + 1
            end do
            stuck = sticks
            if (frictional) call friction_rows()
            scale = max(maxval(abs(x)), maxval(abs(x_free)), tiny(1.0_dp))
            if (maxval(abs(step)) <= 16*epsilon(1.0_dp)*scale) exit
            call dgesv(n, 1, jacobian, n, pivots, step, n, info)
            if (info /= 0) then
               stat = stat_linear_solver_failure
               errmsg = 'the compliant circular obstacles: the Newton matrix of a step is singular'
               return
            end if
            x = x + reshape(step(1:2*m), [2, m])
            settled = .true.
            if (frictional) then
               phi = phi + step(2*m + 1:)
               settled = all(sticks .eqv. stuck) .and. &
                         all(dt*theta*weight*abs(step(2*m + 1:)) <= converged*(norm2(r0, 1) + circles%radius))
            end if
            ! the points' positions r1 (and so p1 and the forces) no longer move beyond
            ! their round-off: |dt theta dx| <= 1024 eps |r|
            if (settled .and. all(dt*theta*norm2(reshape(step(1:2*m), [2, m]), 1) <= &
                                  converged*(norm2(r0, 1) + circles%radius))) then
               call forces_at(x)
               exit
            end if
         end do
         self%solves = iteration
         if (iteration > max_iterations) then
            stat = stat_no_convergence
            write (errmsg, '(a,i0,a)') 'the compliant circular obstacles: Newton''s method did not converge in ', &
               max_iterations, ' iterations (a stop too stiff for dt, or stick and slip alternating at a '// &
               'frictional wall: reduce dt)'
            return
         end if
         ! V^{n+1} = V_free + dt W^-1 H^T F, one band solve per plane
         self%push = 0
         do k = 1, m
            c = circles%dof(k)
            self%push(c) = dt*total_force(1, k)
            self%push(j + c) = dt*total_force(2, k)
         end do
         call band_solve(self%factor(1), self%push(1:j))
         call band_solve(self%factor(2), self%push(j + 1:))
         v_new = v_free + self%push
         ! no rigid impulse (no impact); the friction's impulses for the ledger and wear
         self%count = 0
         self%friction_force = phi
         if (frictional) then
            do k = 1, m
               if (abs(phi(k)) <= 0) cycle
               self%count = self%count + 1
               associate (a => self%count)
                  self%active(a) = k
                  self%normal(:, a) = [tangent(2, k), -tangent(1, k)]
                  self%impulse(a) = 0
                  self%tangential(a) = dt*phi(k)
                  self%before(a) = dot_product(self%normal(:, a), v0(:, k))
                  self%tangential_before(a) = dot_product(tangent(:, k), v0(:, k))
               end associate
            end do
         end if
      end associate

   contains

      !> The forces F at the points' end velocities `x` (force, with p1, f, elastic; and
      !! total_force, with the friction phi t) and their derivatives dF/dx = dt theta dF/dr1
      !! (derivative), dF/dr1 = -(f' d n1^T + f (I - d n1^T)/(|r0| + |r1|)), n1 = r1/|r1|;
      !! with friction the tangent t, dt/dx = dt theta P (I - o o^T)/|r0 + r1| (o the
      !! outward unit midpoint, P the quarter turn t = P o), df/dx = f' dt theta n1^T, and
      !! phi dt/dx in the derivative.
      subroutine forces_at(x)
         real(dp), intent(in) :: x(:, :)
         real(dp) :: r1(2), d(2), n1(2), total, slope, outward(2), turn(2, 2)
         integer :: k
         associate (circles => self%circles)
            do k = 1, m
               r1 = r0(:, k) + dt*(theta*x(:, k) + (1 - theta)*v0(:, k))
               self%p1(k) = norm2(r1) - circles%radius(k)
               call step_force(rule, circles%stiffness(k), circles%exponent(k), circles%damping(k), theta, dt, &
                               self%p0(k), self%p1(k), self%f(k), slope, self%elastic(k))
               tangent(:, k) = 0
               tangent_slope(:, :, k) = 0
               force_slope(:, k) = 0
               if (abs(self%f(k)) <= 0 .and. abs(slope) <= 0) then   ! free over the step
                  self%force(:, k) = 0
                  total_force(:, k) = 0
                  derivative(:, :, k) = 0
                  cycle
               end if
               total = norm2(r0(:, k)) + norm2(r1)
               d = (r0(:, k) + r1)/total
               n1 = r1/norm2(r1)
               self%force(:, k) = -self%f(k)*d
               derivative(:, :, k) = -(slope - self%f(k)/total)*spread(d, 2, 2)*spread(n1, 1, 2)
               derivative(1, 1, k) = derivative(1, 1, k) - self%f(k)/total
               derivative(2, 2, k) = derivative(2, 2, k) - self%f(k)/total
               derivative(:, :, k) = dt*theta*derivative(:, :, k)
               total_force(:, k) = self%force(:, k)
               if (.not. frictional) cycle
               outward = (r0(:, k) + r1)/norm2(r0(:, k) + r1)
               tangent(:, k) = [outward(2), -outward(1)]
               turn = -spread(outward, 2, 2)*spread(outward, 1, 2)
               turn(1, 1) = turn(1, 1) + 1
               turn(2, 2) = turn(2, 2) + 1
               turn = dt*theta*turn/norm2(r0(:, k) + r1)
               tangent_slope(1, :, k) = turn(2, :)
               tangent_slope(2, :, k) = -turn(1, :)
               force_slope(:, k) = slope*dt*theta*n1
               total_force(:, k) = total_force(:, k) + phi(k)*tangent(:, k)
               derivative(:, :, k) = derivative(:, :, k) + phi(k)*tangent_slope(:, :, k)
            end do
         end associate
      end subroutine forces_at

      !> The friction's rows of the residual (`step`, 2m + k: m/s) and of the Jacobian, and
      !! the phi columns of the velocity rows: -dt G(k, l) t_l. With the trial force
      !! phi - t.x/(dt g) and the bound mu f: inside it the point sticks, t.x = 0 (row
      !! t^T + x^T dt/dx); at or beyond it, it slides, dt g (phi - s mu f) = 0 with
      !! s = sign(trial) (row -dt g s mu df/dx, dt g on phi).
      subroutine friction_rows()
         real(dp) :: slip, bound, trial, s
         integer :: k, l
         do l = 1, m
            do k = 1, m
               jacobian(2*k - 1, 2*m + l) = -dt*self%delassus(k, l, 1)*tangent(1, l)
               jacobian(2*k, 2*m + l) = -dt*self%delassus(k, l, 2)*tangent(2, l)
            end do
         end do
         do k = 1, m
            slip = dot_product(tangent(:, k), x(:, k))
            bound = self%circles%friction(k)*self%f(k)
            trial = phi(k) - slip/weight(k)
            sticks(k) = abs(trial) < bound
            if (sticks(k)) then
               step(2*m + k) = -slip
               jacobian(2*m + k, 2*k - 1:2*k) = tangent(:, k) + matmul(x(:, k), tangent_slope(:, :, k))
            else
               s = sign(1.0_dp, trial)
               step(2*m + k) = -weight(k)*(phi(k) - s*bound)
               jacobian(2*m + k, 2*k - 1:2*k) = -weight(k)*s*self%circles%friction(k)*force_slope(:, k)
               jacobian(2*m + k, 2*m + k) = weight(k)
            end if
         end do
      end subroutine friction_rows
   end subroutine compliant_step

   !> The energy stored in the compliant walls at the stacked state `u` (J): sum_k
   !! Phi_k(p_k), p_k the radial penetration (0 for rigid walls).
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
