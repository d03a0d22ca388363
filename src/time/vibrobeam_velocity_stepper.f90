!> The velocity-based time stepper (theory §3), one step at a time.
!!
!! With W = M + theta^2 dt^2 K + theta dt C (factored once), each step does
!!  1. free velocity  V_free = V^n + W^-1 dt [F^{n+theta} - K (U^n + theta dt V^n) - C V^n],
!!     F^{n+theta} = theta F(t_{n+1}) + (1 - theta) F(t_n);
!!  2. activation: contact point c is active from below (s = +1) if H_c U~ <= g1(x_c), from
!!     above (s = -1) if H_c U~ >= g2(x_c), with U~ = U^n + gamma dt V^n (to 1e-12 L);
!!  3. projection with Newton's law: V^{n+1} = V_free + W^-1 H^T P,
!!     0 <= s_c P_c _|_ s_c H_c (V^{n+1} + e_c V^n) >= 0 on the active points;
!!  4. positions U^{n+1} = U^n + dt (theta V^{n+1} + (1 - theta) V^n).
!!
!! Restitution per point (our remedy, docs/method.md): e_c = e for an active point that
!! approaches its obstacle (s_c H_c V^n <= 0) and e_c = 1 for one that already moves away.
!! For every theta the impacts take -P.H (V^{n+1} + V^n)/2 = -1/2 sum_c (1 - e_c) P_c H_c V^n
!! (Newton's law P_c H_c V^{n+1} = -e_c P_c H_c V^n); with e_c = e everywhere a separating
!! active point gives it the wrong sign and the energy can grow; with e_c = 1 there its
!! term vanishes, so impacts only dissipate. The rest of the energy change that is not
!! work or damping is the theta-method's own, `dissipated_numerical` (see `step`).
!!
!! Compliant stops (docs/theory.md section 8): their force enters step 3 implicitly, as
!! dt sum_j s_j f_j H_j^T with f_j the step force of `vibrobeam_compliant_law` at the
!! penetrations of U^{n+1}; `vibrobeam_compliant_solver` solves the step by Newton's method
!! with the rigid projection inside each iteration (`compliant_step`).
module vibrobeam_velocity_stepper
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_not_finite, stat_invalid_argument, stat_linear_solver_failure
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_residual_solve, band_solve, band_factor
   use vibrobeam_contact_set, only: contact_set, contact_value
   use vibrobeam_loads, only: load_set
   use vibrobeam_time_stepper, only: time_stepper, stepper_settings, dynamic_state, save_stepper_state, &
      restore_stepper_state
   use vibrobeam_discrete_system, only: discrete_system
   use vibrobeam_state_record, only: state_record
   use vibrobeam_compliant_law, only: end_force, stop_potential, step_force
   use vibrobeam_compliant_solver, only: rigid_active, add_row_product
   use vibrobeam_lapack, only: dpotrf, dpotrs
   implicit none
   private
   public :: velocity_stepper

   type, extends(time_stepper) :: velocity_stepper
      real(dp) :: gamma = 0.5_dp                   !! activation at U^n + gamma dt V^n
      real(dp) :: activation_tolerance = 0         !! 1e-12 L (m): round-off allowance of the activation test
      !> restitution of an active point already moving away from its obstacle: 1 (our
      !! remedy, default) or `restitution` (the plain law of theory §3, for comparison)
      real(dp) :: separating_restitution = 1
      real(dp), allocatable :: force(:)            !! F(t_n)
      !> work space of `step` (J each), allocated once by `init`: a step allocates nothing
      real(dp), allocatable :: rhs(:), work_vector(:), damping_vector(:), v_free(:), v_new(:), u_new(:), &
                               force_new(:), force_theta(:), modal_vector(:)
      real(dp), allocatable :: signs(:), offsets(:)   !! (contact points) work space of `step`
      real(dp), allocatable :: spring_start(:)        !! (springs) their penetrations at the last step's start (m)
   contains
      procedure :: init
      procedure :: step
      procedure :: restore_state
      procedure :: tangent
      procedure, private :: loads_at
      procedure, private :: report_holes
      procedure, private :: compliant_step
   end type velocity_stepper

contains

   !> Set up for a run: build and factor W, prepare the contact projection; U = start%u,
   !! V = start%v (the scheme needs nothing beyond them).
   subroutine init(self, system, settings, start, stat, errmsg)
      class(velocity_stepper), intent(inout) :: self
      type(discrete_system), intent(in) :: system
      type(stepper_settings), intent(in) :: settings
      type(dynamic_state), intent(in) :: start
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: n
      associate (dt => settings%dt, theta => settings%theta)
         ! W = (1 + theta dt a) M + (theta^2 dt^2 + theta dt b) K
         call self%set_up_system(system, settings, 1 + theta*dt*settings%rayleigh_mass, &
                                 theta**2*dt**2 + theta*dt*settings%rayleigh_stiffness, stat, errmsg)
      end associate
      if (stat /= 0) return
      self%gamma = settings%gamma
      self%separating_restitution = settings%separating_restitution
      self%activation_tolerance = 1e-12_dp*system%model%length
      self%u = start%u
      self%v = start%v
      n = size(start%u)
      allocate (self%force(n))
      call self%loads_at(0.0_dp, self%force)
      allocate (self%rhs(n), self%work_vector(n), self%damping_vector(n), self%v_free(n), self%v_new(n), &
                self%u_new(n), self%force_new(n), self%force_theta(n), self%modal_vector(n), source=0.0_dp)
      allocate (self%signs(system%contacts%count), self%offsets(system%contacts%count))
      allocate (self%spring_start(system%contacts%springs%count), source=0.0_dp)
      if (self%holes%circles%count > 0) then   ! W_z is W when z shares K
         if (self%own_z) then
            call self%holes%setup(system%circles, self%iteration_factor, self%iteration_factor_z)
         else
            call self%holes%setup(system%circles, self%iteration_factor, self%iteration_factor)
         end if
      end if
   end subroutine init


   !> The base type's restore, then F(t_n) from the loads (which a continued run may change).
   subroutine restore_state(self, record, stat, errmsg)
      class(velocity_stepper), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call restore_stepper_state(self, record, stat, errmsg)
      call self%loads_at(self%steps*self%dt, self%force)
   end subroutine restore_state

   !> Advance from t_n to t_{n+1}. stat: stat_ok; a contact solver failure (its code,
   !! errmsg says); stat_not_finite when the state is no longer finite.
   subroutine step(self, stat, errmsg)
      class(velocity_stepper), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: predicted, e_c
      integer :: c, m
      logical :: finite
      ! every vector lives in the stepper's work space (allocated by `init`); the new state
      ! is built there and swapped in (move_alloc moves descriptors, copies nothing)
      stat = 0
      errmsg = ''
      associate (dt => self%dt, theta => self%theta, rhs => self%rhs, work_vector => self%work_vector, &
                 v_free => self%v_free, force_new => self%force_new, force_theta => self%force_theta, &
                 signs => self%signs, offsets => self%offsets, damping_vector => self%damping_vector)
         ! 1. free velocity V_free = V^n + dt W^-1 (F^{n+theta} - C V^n - K (U^n + theta dt V^n)):
         ! the product with K inside the solve's forward pass (band_residual_solve)
         if (self%loads%present) then
            if (self%planes == 1) then
               call self%loads%evaluate((self%steps + 1)*dt, force_new)   ! t_{n+1} from the global step number
            else   ! the loads given in y, turned by &load direction (and point_direction)
               call self%loads%evaluate_planes((self%steps + 1)*dt, force_new)
            end if
            force_theta = theta*force_new + (1 - theta)*self%force
         end if                                                        ! (else both stay 0)
         if (self%loads%flow%active) then   ! the fluid-elastic force at V^n (theory §10)
            if (.not. self%loads%present) force_theta = 0
            call self%loads%flow%add_force(self%v, force_theta)
         end if
         rhs = self%u + theta*dt*self%v
         if (self%rayleigh_mass > 0 .or. self%rayleigh_stiffness > 0 .or. self%modal) then
            call self%damping_into(self%v, damping_vector, work_vector)
            if (self%modal) then
               ! the damping per mode at V^n (explicit: W keeps its band)
               self%modal_vector = 0
               call self%add_modal_damping(self%v, self%modal_vector)
               damping_vector = damping_vector + self%modal_vector
            end if
            damping_vector = force_theta - damping_vector
            call self%free_solve(rhs, damping_vector, v_free)
         else
            call self%free_solve(rhs, force_theta, v_free)
         end if
         v_free = self%v + dt*v_free
         ! 2. active set at U~ = U^n + gamma dt V^n
         m = 0
         do c = 1, self%contacts%count
            predicted = contact_value(self%contacts, c, self%u) + self%gamma*dt*contact_value(self%contacts, c, self%v)
            ! a point resting on its obstacle (a static equilibrium, a point held in the
            ! previous step) sits there up to round-off: the tolerance keeps it active
            if (predicted <= self%contacts%lower(c) + self%activation_tolerance) then
               m = m + 1
               signs(m) = 1
            else if (predicted >= self%contacts%upper(c) - self%activation_tolerance) then
               m = m + 1
               signs(m) = -1
            else
               cycle
            end if
            self%report%active(m) = c
            self%report%velocity_before(m) = contact_value(self%contacts, c, self%v)
            self%report%approaching(m) = signs(m)*self%report%velocity_before(m) <= 0
            e_c = merge(self%restitution, self%separating_restitution, self%report%approaching(m))
            offsets(m) = -e_c*self%report%velocity_before(m)
         end do
         self%report%active_count = m
      end associate
      ! 3. projection (with no active point it is the identity: V^{n+1} = V_free), with the
      ! compliant stops' forces when the scene has any
      if (self%contacts%springs%count > 0) then
         call self%compliant_step(self%v_free, self%signs(1:m), self%offsets(1:m), self%v_new, stat, errmsg)
         if (stat /= 0) return
         call complete(self%v_new)
      else if (self%holes%circles%compliant) then   ! two planes in compliant circular holes
         call self%holes%compliant_step(self%u, self%v, self%v_free, self%dt, self%theta, self%compliant_rule, &
                                        self%v_new, stat, errmsg)
         if (stat /= 0) then
            write (errmsg, '(a,es12.5,a)') trim(errmsg)//' at t = ', self%t + self%dt, ' s'
            return
         end if
         call self%report_holes()
         call complete(self%v_new)
      else if (self%holes%circles%count > 0) then   ! two planes in rigid circular holes (no planar point then)
         call self%holes%rigid_step(self%u, self%v, self%v_free, self%dt, self%theta, self%gamma, &
                                    self%activation_tolerance, self%restitution, self%separating_restitution, self%v_new, &
                                    stat, errmsg)
         if (stat /= 0) return
         call self%report_holes()
         call complete(self%v_new)
      else if (m > 0) then
         call self%projector%project(self%v_free, self%report%active(1:m), self%signs(1:m), self%offsets(1:m), self%v_new, &
                                     self%report%impulse(1:m), self%report%iterations, stat, errmsg)
         self%report%linear_solves = self%projector%linear_solves
         self%report%used_fallback = self%projector%used_fallback
         if (stat /= 0) return
         call complete(self%v_new)
      else
         call self%projector%record_free()
         self%report%iterations = 0
         self%report%linear_solves = 0
         self%report%used_fallback = .false.
         call complete(self%v_free)
      end if
      if (.not. finite) then
         stat = stat_not_finite
         write (errmsg, '(a,es12.5,a)') 'the solution is no longer finite at t = ', self%t + self%dt, ' s'
         return
      end if
      call swap(self%u, self%u_new)
      if (m > 0 .or. self%contacts%springs%count > 0 .or. self%holes%circles%count > 0) then
         call swap(self%v, self%v_new)
      else
         call swap(self%v, self%v_free)
      end if
      if (self%loads%present) call swap(self%force, self%force_new)
      self%steps = self%steps + 1
      self%t = self%steps*self%dt
      self%report%impulse_time = self%t   ! the impulse acts over [t_n, t_{n+1}]; recorded at its end

   contains

      !> 4. positions U^{n+1} = U^n + dt V^{n+theta} into u_new, and the energy bookkeeping,
      !! given V^{n+1} = v_next; `finite` says whether U^{n+1} and V^{n+1} are finite.
      subroutine complete(v_next)
         real(dp), intent(in) :: v_next(:)
         real(dp) :: impulse_power, v_theta, total, work
         integer :: i, k
         associate (dt => self%dt, theta => self%theta, u => self%u, v => self%v, u_new => self%u_new, &
                    rhs => self%rhs, work_vector => self%work_vector)
            ! one pass: positions, the finiteness test and the work of the loads
            total = 0
            work = 0
            do i = 1, size(u)
               v_theta = theta*v_next(i) + (1 - theta)*v(i)
               u_new(i) = u(i) + dt*v_theta
               total = total + (v_next(i) + u_new(i))
               work = work + self%force_theta(i)*(u_new(i) - u(i))
            end do
            finite = ieee_is_finite(total)
            if (.not. finite) return
            ! energy bookkeeping (docs/method.md "Energies"; theory §6 and §8). With
            ! dV = V^{n+1} - V^n, dU = U^{n+1} - U^n = dt V^{n+theta}, the step equations give exactly
            !   E^{n+1} - E^n = F^{n+theta}.dU - dt V^{n+theta}.C V^{n+theta}
            !                   + P.H (V^{n+1} + V^n)/2 - (theta - 1/2) (dV.M dV + dU.K dU - P.H dV)
            !                   - sum_j f_j (p_j^{n+1} - p_j^n),
            ! so the impacts take -P.H (V^{n+1} + V^n)/2 (>= 0 by Newton's law with e_c <= 1 on
            ! approaching points and e_c = 1 on separating ones) and the theta-method the
            ! (theta - 1/2) term (0 for theta = 1/2; >= 0 in every step without impulses for
            ! theta > 1/2). The springs' impulses dt s_j f_j H_j^T do the work
            ! dt s_j f_j H_j V^{n+theta} = -f_j dp_j whole, booked by `compliant_energy`: they
            ! have no part in the theta-term (theory §8, "Energy").
            if (self%loads%present .or. self%loads%flow%active) self%energy%work = self%energy%work + work
            impulse_power = 0
            do k = 1, m
               self%report%velocity_after(k) = contact_value(self%contacts, self%report%active(k), v_next)
               self%energy%dissipated_impacts = self%energy%dissipated_impacts - 0.5_dp*self%report%impulse(k)* &
                                         (self%report%velocity_after(k) + self%report%velocity_before(k))
               impulse_power = impulse_power + self%report%impulse(k)*(self%report%velocity_after(k) &
                  - self%report%velocity_before(k))
            end do
            ! the circles' impulses p_k along their inward normals h_k: the same two terms;
            ! their friction r_k along the tangents t_k takes -r_k t_k.(V^{n+1} + V^n)/2, at
            ! rigid and at compliant circles (there p_k = 0: the spring's force is booked by
            ! `circle_energy`, its friction dt phi_k here)
            do k = 1, self%report%circle_count
               associate (r => self%report, c => self%holes%circles%dof(self%report%circle_active(k)))
                  r%circle_after(k) = dot_product(r%circle_normal(:, k), [v_next(c), v_next(size(v_next)/2 + c)])
                  self%energy%dissipated_impacts = self%energy%dissipated_impacts - 0.5_dp*r%circle_impulse(k)* &
                                                   (r%circle_after(k) + r%circle_before(k))
                  impulse_power = impulse_power + r%circle_impulse(k)*(r%circle_after(k) - r%circle_before(k))
                  if (abs(r%circle_friction(k)) > 0) then
                     associate (after => dot_product([-r%circle_normal(2, k), r%circle_normal(1, k)], &
                                                     [v_next(c), v_next(size(v_next)/2 + c)]))
                        self%energy%dissipated_friction = self%energy%dissipated_friction - 0.5_dp*r%circle_friction(k)* &
                                                          (after + r%circle_tangential_before(k))
                        impulse_power = impulse_power + r%circle_friction(k)*(after - r%circle_tangential_before(k))
                     end associate
                  end if
               end associate
            end do
            if (self%rayleigh_mass > 0 .or. self%rayleigh_stiffness > 0) then
               rhs = theta*v_next + (1 - theta)*v
               call self%damping_into(rhs, self%damping_vector, work_vector)
               self%energy%dissipated_damping = self%energy%dissipated_damping + dt*dot_product(rhs, self%damping_vector)
            end if
            ! the damping per mode's force -C_m V^n does the work -dt V^{n+theta}.C_m V^n
            if (self%modal) self%energy%dissipated_damping = self%energy%dissipated_damping + &
                                                             dt*dot_product(theta*v_next + (1 - theta)*v, self%modal_vector)
            if (abs(theta - 0.5_dp) > 0) then
               rhs = v_next - v
               call self%mass_into(rhs, work_vector)
               self%energy%dissipated_numerical = self%energy%dissipated_numerical + (theta - 0.5_dp)*dot_product(rhs, work_vector)
               rhs = u_new - u
               call self%stiffness_into(rhs, work_vector)
               self%energy%dissipated_numerical = self%energy%dissipated_numerical + (theta - 0.5_dp)* &
                                           (dot_product(rhs, work_vector) - impulse_power)
            end if
            if (self%contacts%springs%count > 0) &
               call self%compliant_energy(self%spring_penetrations(u), self%spring_penetrations(u_new))
            if (self%holes%circles%compliant) call circle_energy()
         end associate
      end subroutine complete

      !> The compliant circles' share of the step's energy (as `compliant_energy` for the
      !! levels' springs): their force did the work F.(r1 - r0) on the beam, of which
      !! -(Phi(p1) - Phi(p0)) is what their potential gave, (f - elastic)(p1 - p0) >= 0
      !! what their damping took, and the rest (round-off with the 'gradient' rule and
      !! Newton converged) is the time discretization's.
      subroutine circle_energy()
         real(dp) :: work, stored
         integer :: k, c
         associate (circles => self%holes%circles, j => size(self%u)/2)
            do k = 1, circles%count
               c = circles%dof(k)
               work = dot_product(self%holes%force(:, k), [self%u_new(c) - self%u(c), self%u_new(j + c) - self%u(j + c)])
               stored = stop_potential(circles%stiffness(k), circles%exponent(k), circles%penetration(k, self%u_new)) - &
                        stop_potential(circles%stiffness(k), circles%exponent(k), circles%penetration(k, self%u))
               associate (damping => (self%holes%f(k) - self%holes%elastic(k))*(self%holes%p1(k) - self%holes%p0(k)))
                  self%energy%dissipated_contact_damping = self%energy%dissipated_contact_damping + damping
                  self%energy%dissipated_numerical = self%energy%dissipated_numerical - work - stored - damping
               end associate
            end do
         end associate
      end subroutine circle_energy
   end subroutine step

   !> The derivative of the last step, (U^n, V^n) -> (U^{n+1}, V^{n+1}), applied to the
   !! columns of (du, dv) in place: each column a perturbation of U^n and V^n in, the
   !! perturbation of U^{n+1} and V^{n+1} it makes out (docs/method.md, "Periodic orbits by
   !! shooting"). With the points h the step held (an impulse P_c /= 0) and their
   !! restitution e_c,
   !!   dV_free = dV + dt J^-1 (-(C + C_m - F_f) dV - K (dU + theta dt dV) - S),
   !!   dV' = dV_free - J^-1 H_h^T D^-1 (H_h dV_free + E_h H_h dV),  D = H_h J^-1 H_h^T,
   !!   dU' = dU + dt (theta dV' + (1 - theta) dV),
   !! C_m the damping per mode and F_f the fluid-elastic force's matrix (theory §10), both
   !! explicit in V^n as `step` takes them, J = W without compliant stops (S = 0): the step is affine in (U^n, V^n) as long as the
   !! same points are active, the same of them held and each approaches or separates as it
   !! did (the period map is piecewise affine; a piece ends where an activation test, an
   !! impulse's sign or an approach changes). With compliant stops (docs/method.md,
   !! "Compliant stops"), each spring j's step force f_j(p0_j, p1_j) of the penetrations at
   !! the step's start and end has the slopes a_j = df/dp1 and b_j = df/dp0 there, and
   !! differentiating W (V' - V_free) = dt sum_j s_j f_j H_j^T gives
   !!   J = W + theta dt^2 sum_j a_j H_j^T H_j,  S = sum_j ((a_j + b_j) H_j dU + a_j dt H_j dV) H_j^T,
   !! the held points projected in the metric J as the step's Newton solve does. The map is
   !! then smooth where every spring stays engaged or free (its pieces end where a spring
   !! engages or the contact damping's factor reaches 0). stat_linear_solver_failure when D
   !! or J is singular.
   subroutine tangent(self, du, dv, stat, errmsg)
      class(velocity_stepper), intent(in) :: self
      real(dp), intent(inout) :: du(:, :), dv(:, :)   !! (unknowns, columns)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: columns(:, :), delassus(:, :)
      real(dp), dimension(size(self%u)) :: v_free, y, x, b, z
      real(dp) :: e(self%report%active_count), q(self%report%active_count)
      real(dp) :: end_slope(self%contacts%springs%count), start_slope(self%contacts%springs%count)
      integer :: held(self%report%active_count), h, k, j, a, info
      type(symmetric_band) :: jacobian
      type(band_cholesky), target :: jacobian_factor
      type(band_cholesky), pointer :: factor
      stat = 0
      errmsg = ''
      factor => null()
      call spring_slopes(end_slope, start_slope)
      if (any(end_slope > 0 .or. abs(start_slope) > 0)) then
         ! J = W + theta dt^2 sum_j a_j H_j^T H_j, factored for this step
         jacobian = self%iteration_matrix
         do j = 1, self%contacts%springs%count
            if (end_slope(j) > 0) call add_row_product(jacobian, self%contacts, self%contacts%springs%point(j), &
                                                       self%theta*self%dt**2*end_slope(j))
         end do
         call band_factor(jacobian, jacobian_factor, stat, errmsg)
         if (stat /= 0) then
            stat = stat_linear_solver_failure
            errmsg = 'the tangent of a step with compliant stops: '//trim(errmsg)
            return
         end if
         factor => jacobian_factor
      end if
      h = 0
      do k = 1, self%report%active_count
         if (abs(self%report%impulse(k)) <= 0) cycle
         h = h + 1
         held(h) = self%report%active(k)
         e(h) = merge(self%restitution, self%separating_restitution, self%report%approaching(k))
      end do
      if (h > 0) then
         ! J^-1 H_c^T for each held point and the Delassus matrix D = H J^-1 H^T (h x h, SPD)
         allocate (columns(size(self%u), h), delassus(h, h))
         do k = 1, h
            columns(:, k) = 0
            do a = 1, 4
               if (self%contacts%dofs(a, held(k)) /= 0) columns(self%contacts%dofs(a, held(k)), k) = &
                  columns(self%contacts%dofs(a, held(k)), k) + self%contacts%weights(a, held(k))
            end do
            if (associated(factor)) then
               call band_solve(factor, columns(:, k))
            else
               call band_solve(self%iteration_factor, columns(:, k))
            end if
         end do
         do k = 1, h
            do j = 1, h
               delassus(j, k) = contact_value(self%contacts, held(j), columns(:, k))
            end do
         end do
         call dpotrf('L', h, delassus, h, info)
         if (info /= 0) then
            stat = stat_linear_solver_failure
            write (errmsg, '(a,i0,a)') 'the Delassus matrix of the ', h, ' held contact points is singular'
            return
         end if
      end if
      do j = 1, size(du, 2)
         x = du(:, j) + self%theta*self%dt*dv(:, j)
         ! the forces explicit in V^n: -C dV (Rayleigh), -C_m dV (per mode) and the
         ! fluid-elastic F_f(dV), linear in V as `step` adds them (theory §10)
         b = 0
         if (self%rayleigh_mass > 0 .or. self%rayleigh_stiffness > 0) then
            call self%damping_into(dv(:, j), b, z)
            b = -b
         end if
         if (self%modal) then
            z = 0
            call self%add_modal_damping(dv(:, j), z)
            b = b - z
         end if
         if (self%loads%flow%active) call self%loads%flow%add_force(dv(:, j), b)
         if (associated(factor)) then
            do k = 1, self%contacts%springs%count
               if (end_slope(k) <= 0 .and. abs(start_slope(k)) <= 0) cycle
               associate (point => self%contacts%springs%point(k))
                  call add_row(b, point, -((end_slope(k) + start_slope(k))*contact_value(self%contacts, point, du(:, j)) + &
                                          end_slope(k)*self%dt*contact_value(self%contacts, point, dv(:, j))))
               end associate
            end do
            call band_residual_solve(factor, self%stiffness, x, b, y)
         else
            call band_residual_solve(self%iteration_factor, self%stiffness, x, b, y)
         end if
         v_free = dv(:, j) + self%dt*y
         if (h > 0) then
            do k = 1, h
               q(k) = contact_value(self%contacts, held(k), v_free) + e(k)*contact_value(self%contacts, held(k), dv(:, j))
            end do
            call dpotrs('L', h, 1, delassus, h, q, h, info)
            v_free = v_free - matmul(columns, q(1:h))
         end if
         du(:, j) = du(:, j) + self%dt*(self%theta*v_free + (1 - self%theta)*dv(:, j))
         dv(:, j) = v_free
      end do

   contains

      !> a_j and b_j of every spring at the last step's start and end penetrations (0 for
      !! a spring the step left free).
      subroutine spring_slopes(end_slope, start_slope)
         real(dp), intent(out) :: end_slope(:), start_slope(:)
         real(dp) :: f, elastic
         integer :: i
         associate (springs => self%contacts%springs)
            do i = 1, springs%count
               call step_force(self%compliant_rule, springs%stiffness(i), springs%exponent(i), springs%damping(i), &
                               self%theta, self%dt, self%spring_start(i), self%compliant%p1(i), f, end_slope(i), &
                               elastic, start_slope(i))
            end do
         end associate
      end subroutine spring_slopes

      !> r <- r + w H_c^T.
      subroutine add_row(r, c, w)
         real(dp), intent(inout) :: r(:)
         integer, intent(in) :: c
         real(dp), intent(in) :: w
         integer :: i
         do i = 1, 4
            if (self%contacts%dofs(i, c) /= 0) r(self%contacts%dofs(i, c)) = r(self%contacts%dofs(i, c)) + &
                                                                                w*self%contacts%weights(i, c)
         end do
      end subroutine add_row
   end subroutine tangent

   !> Step 3 with compliant stops: V^{n+1} from Newton's method on
   !! W (V - V_free) = dt sum_j s_j f_j(p_j) H_j^T + H^T P, p_j = s_j (g_j - H_j U^{n+1}),
   !! U^{n+1} = U^n + dt ((1 - theta) V^n + theta V), with the rigid projection of the
   !! active points inside each iteration. stat 3 when Newton fails (exit 3), or the
   !! failure of `check_compliant_work` when the force residual it left is not negligible.
   subroutine compliant_step(self, v_free, signs, offsets, v_new, stat, errmsg)
      class(velocity_stepper), intent(inout) :: self
      real(dp), intent(in) :: v_free(:), signs(:), offsets(:)
      real(dp), intent(out) :: v_new(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: p0(self%contacts%springs%count), q(self%contacts%springs%count)
      integer :: m, j
      m = size(signs)
      associate (springs => self%contacts%springs, dt => self%dt, theta => self%theta)
         p0 = self%spring_penetrations(self%u)
         self%spring_start = p0
         q = self%spring_penetrations(self%u + dt*(1 - theta)*self%v)
         call self%compliant%solve(springs, self%contacts, self%iteration_matrix, self%projector, v_free, q, p0, &
                                   theta*dt, dt, theta, dt, rigid_active, self%report%active(1:m), signs, offsets, v_new, &
                                   self%report%impulse(1:m), stat, errmsg)
         self%report%iterations = self%compliant%iterations
         self%report%linear_solves = self%compliant%linear_solves
         self%report%used_fallback = self%projector%used_fallback
         if (stat /= 0) return   ! (the compliant solver's own code: docs/output.md, "Status codes")
         call self%check_compliant_work(p0, self%compliant%p1, stat, errmsg)
         if (stat /= 0) return
         self%report%contact_force = 0
         do j = 1, springs%count
            self%report%contact_force(springs%point(j)) = self%report%contact_force(springs%point(j)) + springs%sign(j)* &
               end_force(springs%stiffness(j), springs%exponent(j), springs%damping(j), dt, p0(j), self%compliant%p1(j))
         end do
      end associate
   end subroutine compliant_step




   !> The holes' last contact step into the step report (its rigid impulses: the recorder's
   !! impacts, the energy's bookkeeping) and its solves into `iterations`.
   subroutine report_holes(self)
      class(velocity_stepper), intent(inout) :: self
      integer :: m
      m = self%holes%count
      associate (r => self%report, holes => self%holes)
         r%circle_count = m
         r%circle_active(1:m) = holes%active(1:m)
         r%circle_normal(:, 1:m) = holes%normal(:, 1:m)
         r%circle_impulse(1:m) = holes%impulse(1:m)
         r%circle_friction(1:m) = holes%tangential(1:m)
         r%circle_before(1:m) = holes%before(1:m)
         r%circle_tangential_before(1:m) = holes%tangential_before(1:m)
         r%iterations = holes%solves
         r%linear_solves = 0
         r%used_fallback = .false.
      end associate
   end subroutine report_holes

   !> F(t) into f (planes x J values): the loads of the y plane, turned by &load direction
   !! when the beam bends in two planes.
   subroutine loads_at(self, t, f)
      class(velocity_stepper), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp), intent(out) :: f(:)
      if (self%planes == 1) then
         f = self%loads%at(t)
      else
         call self%loads%planes_at(t, f)
      end if
   end subroutine loads_at

   !> Exchange two allocated vectors of the same size (descriptors only).
   subroutine swap(a, b)
      real(dp), allocatable, intent(inout) :: a(:), b(:)
      real(dp), allocatable :: held(:)
      call move_alloc(a, held)
      call move_alloc(b, a)
      call move_alloc(held, b)
   end subroutine swap
end module vibrobeam_velocity_stepper
