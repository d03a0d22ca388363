!> The compliant step of a beam of two planes (docs/method.md, "Circular obstacles",
!! "Compliant flat points", "Coulomb friction at compliant circles"): the springs of the
!! compliant circles and flat points (levels, polygons' faces) of the cross-section, with
!! their exact Coulomb friction, solved for the points' end velocities by one (semismooth)
!! Newton method. A submodule of `vibrobeam_circle_contact`, whose G_y, G_z and factors of
!! W it uses.
submodule(vibrobeam_circle_contact) vibrobeam_circle_springs
   use vibrobeam_status, only: stat_linear_solver_failure, stat_no_convergence
   use vibrobeam_lapack, only: dgesv
   use vibrobeam_compliant_law, only: step_force
   implicit none

contains

   !> Compliant walls: each point's spring pushes inwards with the force of
   !! `vibrobeam_compliant_law` on its penetration p, over the step from p0 (U^n) to p1
   !! (U^{n+1}): magnitude f(p0, p1) (the `rule`'s, with Hunt-Crossley damping). At a
   !! circle, p = |r| - R (r = (v, w) - c), direction d = (r0 + r1)/(|r0| + |r1|), F = -f d.
   !! Then F.(r1 - r0) = -f (p1 - p0) exactly (as a level's spring: the 'gradient' rule
   !! conserves E + Phi), and F is parallel to the midpoint (r0 + r1)/2, so a centred hole
   !! keeps the angular momentum about the axis. At a flat point (a level, a polygon's
   !! face; docs/method.md, "Compliant flat points"), p = b - h.(v, w) along its fixed inward
   !! normal h and F = f h, so F.(r1 - r0) = -f (p1 - p0) exactly as well. The points' end
   !! velocities x solve x = V_free + dt G F(x) by Newton's method with the 2 x 2 derivatives
   !! of F (dense, LAPACK dgesv), until the residual is 16 eps of the velocities or an
   !! update moves no point beyond 1024 eps of its reach (|r| + R at a circle, its distance
   !! from the centre; |(v, w)| + |b| at a flat point) (as the levels' springs: the
   !! discrete gradient loses digits when p1 is close to p0); then V^{n+1} = V_free + dt
   !! W^-1 H^T F into v_new. stat_no_convergence after 50 iterations.
   !! With friction (some point's mu > 0; docs/method.md, "Coulomb friction at compliant
   !! circles"): each point also carries a tangential force phi t (N) along the tangent
   !! t = (-h_z, h_y) of the inward normal h (at a circle the midpoint's,
   !! h = -(r0 + r1)/|r0 + r1|; at a flat point its fixed one), exact
   !! Coulomb at V^{n+1} as the rigid step: t.x = 0 and |phi| <= mu f (stick) or
   !! phi = -mu f sign(t.x) (slip), written as Alart and Curnier's equation
   !! phi = proj[-mu f, mu f](phi - t.x/(dt g)), g = max(G_y(k, k), G_z(k, k)), and solved
   !! with x by the same Newton iteration (semismooth: the branch of the projection taken
   !! at the present iterate); it stops on the same residual (the friction rows in m/s)
   !! or on the same small update when, besides, no point changed between stick and slip
   !! and no phi's update moved its point by more than the same 1024 eps of its reach
   !! (dt theta dt g |d phi|: phi = mu f inherits f's floor). The
   !! tangential impulses dt phi t are the step's `tangential` entries (impulse 0) for the
   !! energy ledger, as the rigid step's.
   module subroutine compliant_step(self, u, v, v_free, dt, theta, rule, v_new, stat, errmsg)
      class(circle_contact), intent(inout) :: self
      real(dp), intent(in) :: u(:), v(:), v_free(:)
      real(dp), intent(in) :: dt, theta
      integer, intent(in) :: rule
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
      real(dp), dimension(self%circles%count) :: phi, weight, reach
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
            if (circles%flat(k)) then
               self%p0(k) = circles%penetration(k, u)
               reach(k) = norm2(r0(:, k)) + abs(circles%bound(k))
            else
               self%p0(k) = norm2(r0(:, k)) - circles%radius(k)
               reach(k) = norm2(r0(:, k)) + circles%radius(k)
            end if
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
               errmsg = 'the compliant obstacles of the cross-section: the Newton matrix of a step is singular'
               return
            end if
            x = x + reshape(step(1:2*m), [2, m])
            settled = .true.
            if (frictional) then
               phi = phi + step(2*m + 1:)
               settled = all(sticks .eqv. stuck) .and. &
                         all(dt*theta*weight*abs(step(2*m + 1:)) <= converged*reach)
            end if
            ! the points' positions r1 (and so p1 and the forces) no longer move beyond
            ! their round-off: |dt theta dx| <= 1024 eps of their reach
            if (settled .and. all(dt*theta*norm2(reshape(step(1:2*m), [2, m]), 1) <= &
                                  converged*reach)) then
               call forces_at(x)
               exit
            end if
         end do
         self%solves = iteration
         if (iteration > max_iterations) then
            stat = stat_no_convergence
            write (errmsg, '(a,i0,a)') 'the compliant obstacles of the cross-section: Newton''s method did not '// &
               'converge in ', &
               max_iterations, ' iterations (a stop too stiff for dt, or stick and slip alternating at a '// &
               'frictional wall: reduce dt)'
            return
         end if
         ! V^{n+1} = V_free + dt W^-1 H^T F, one band solve per plane
         self%push = 0
         do k = 1, m
            c = circles%dof(k)
            self%push(c) = self%push(c) + dt*total_force(1, k)
            self%push(j + c) = self%push(j + c) + dt*total_force(2, k)
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
               if (circles%flat(k)) then
                  self%p1(k) = -circles%gap_at(k, circles%center(:, k) + r1)
               else
                  self%p1(k) = norm2(r1) - circles%radius(k)
               end if
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
               if (circles%flat(k)) then
                  call flat_force(k, slope)
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

      !> The force of flat point k (`forces_at`, its spring engaged; slope = f'): F = f h along
      !! the fixed inward normal h, dF/dx = -dt theta f' h h^T (p = b - h.r); with friction
      !! the fixed tangent t = (-h_z, h_y) (dt/dx = 0) and df/dx = -f' dt theta h^T.
      subroutine flat_force(k, slope)
         integer, intent(in) :: k
         real(dp), intent(in) :: slope
         real(dp) :: h(2)
         h = self%circles%normal(:, k)
         self%force(:, k) = self%f(k)*h
         derivative(:, :, k) = -dt*theta*slope*spread(h, 2, 2)*spread(h, 1, 2)
         total_force(:, k) = self%force(:, k)
         if (.not. frictional) return
         tangent(:, k) = [-h(2), h(1)]
         force_slope(:, k) = -slope*dt*theta*h
         total_force(:, k) = total_force(:, k) + phi(k)*tangent(:, k)
      end subroutine flat_force

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
end submodule vibrobeam_circle_springs
