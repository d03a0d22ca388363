!> The velocity-based time stepper (SPEC §3), one step at a time.
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
module vibrobeam_velocity_stepper
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_not_finite
   use vibrobeam_band, only: band_solve, band_matvec
   use vibrobeam_model, only: beam_model
   use vibrobeam_contact_points, only: contact_set, contact_value
   use vibrobeam_loads, only: load_set
   use vibrobeam_stepper, only: time_stepper, save_stepper_state, restore_stepper_state
   use vibrobeam_state_record, only: state_record
   implicit none
   private
   public :: velocity_stepper

   type, extends(time_stepper) :: velocity_stepper
      real(dp) :: gamma = 0.5_dp                   !! activation at U^n + gamma dt V^n
      real(dp) :: activation_tolerance = 0         !! 1e-12 L (m): round-off allowance of the activation test
      !> restitution of an active point already moving away from its obstacle: 1 (our
      !! remedy, default) or `restitution` (the plain law of SPEC §3, for comparison)
      real(dp) :: separating_restitution = 1
      real(dp), allocatable :: force(:)            !! F(t_n)
      ! u = U^n, v = V^n; work = sum F^{n+theta}.(U^{n+1} - U^n),
      ! dissipated_impacts = -sum P.H (V^{n+1} + V^n)/2,
      ! dissipated_damping = sum dt V^{n+theta}.C V^{n+theta},
      ! dissipated_numerical = sum (theta - 1/2) (dV.M dV + dU.K dU - P.H dV)
   contains
      procedure :: init
      procedure :: step
      procedure :: restore_state
   end type velocity_stepper

contains

   !> Set up for a run: build and factor W, prepare the contact projection.
   subroutine init(self, model, contacts, loads, dt, theta, gamma, restitution, rayleigh_mass, &
                   rayleigh_stiffness, contact_regime, u0, v0, stat, errmsg)
      class(velocity_stepper), intent(inout) :: self
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      type(load_set), intent(in) :: loads
      real(dp), intent(in) :: dt, theta, gamma, restitution, rayleigh_mass, rayleigh_stiffness
      character(len=*), intent(in) :: contact_regime   !! 'auto' | 'delassus' | 'band'
      real(dp), intent(in) :: u0(:), v0(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      ! W = (1 + theta dt a) M + (theta^2 dt^2 + theta dt b) K
      call self%set_up_system(model, contacts, loads, dt, theta, restitution, rayleigh_mass, rayleigh_stiffness, &
                              1 + theta*dt*rayleigh_mass, theta**2*dt**2 + theta*dt*rayleigh_stiffness, &
                              contact_regime, stat, errmsg)
      if (stat /= 0) return
      self%gamma = gamma
      self%activation_tolerance = 1e-12_dp*model%length
      self%u = u0
      self%v = v0
      self%force = loads%at(0.0_dp)
   end subroutine init

   !> The base type's restore, then F(t_n) from the loads (which a continued run may change).
   subroutine restore_state(self, record, stat, errmsg)
      class(velocity_stepper), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call restore_stepper_state(self, record, stat, errmsg)
      self%force = self%loads%at(self%steps*self%dt)
   end subroutine restore_state

   !> Advance from t_n to t_{n+1}. stat: stat_ok; a contact solver failure (its code,
   !! errmsg says); stat_not_finite when the state is no longer finite.
   subroutine step(self, stat, errmsg)
      class(velocity_stepper), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), dimension(size(self%u)) :: rhs, work_vector, v_free, v_new, u_new, force_new, force_theta, v_theta
      real(dp) :: predicted, e_c, impulse_power
      real(dp) :: signs(self%contacts%count), offsets(self%contacts%count)
      integer :: c, m, k
      associate (dt => self%dt, theta => self%theta)
         ! 1. free velocity
         force_new = self%loads%at((self%steps + 1)*dt)   ! t_{n+1} from the global step number
         force_theta = theta*force_new + (1 - theta)*self%force
         call band_matvec(self%stiffness, self%u + theta*dt*self%v, work_vector)
         rhs = force_theta - work_vector
         if (self%rayleigh_mass > 0 .or. self%rayleigh_stiffness > 0) rhs = rhs - self%damping_times(self%v)
         rhs = dt*rhs
         call band_solve(self%iteration_factor, rhs)
         v_free = self%v + rhs
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
            self%active(m) = c
            self%velocity_before(m) = contact_value(self%contacts, c, self%v)
            self%approaching(m) = signs(m)*self%velocity_before(m) <= 0
            e_c = merge(self%restitution, self%separating_restitution, self%approaching(m))
            offsets(m) = -e_c*self%velocity_before(m)
         end do
         self%active_count = m
         ! 3. projection
         call self%projector%project(v_free, self%active(1:m), signs(1:m), offsets(1:m), v_new, &
                                     self%impulse(1:m), self%iterations, stat, errmsg)
         self%linear_solves = self%projector%linear_solves
         self%used_fallback = self%projector%used_fallback
         if (stat /= 0) return
         ! 4. positions
         v_theta = theta*v_new + (1 - theta)*self%v
         u_new = self%u + dt*v_theta
         if (.not. ieee_is_finite(sum(v_new)) .or. .not. ieee_is_finite(sum(u_new))) then
            stat = stat_not_finite
            write (errmsg, '(a,es12.5,a)') 'the solution is no longer finite at t = ', self%t + dt, ' s'
            return
         end if
         ! energy bookkeeping (docs/method.md "Energies"; theory §6). With dV = V^{n+1} - V^n,
         ! dU = U^{n+1} - U^n = dt V^{n+theta}, the step equations give exactly
         !   E^{n+1} - E^n = F^{n+theta}.dU - dt V^{n+theta}.C V^{n+theta}
         !                   + P.H (V^{n+1} + V^n)/2 - (theta - 1/2) (dV.M dV + dU.K dU - P.H dV),
         ! so the impacts take -P.H (V^{n+1} + V^n)/2 (>= 0 by Newton's law with e_c <= 1 on
         ! approaching points and e_c = 1 on separating ones) and the theta-method the last
         ! term (0 for theta = 1/2; >= 0 in every step without impulses for theta > 1/2).
         if (self%loads%present) self%work = self%work + dot_product(force_theta, u_new - self%u)
         impulse_power = 0
         do k = 1, m
            self%velocity_after(k) = contact_value(self%contacts, self%active(k), v_new)
            self%dissipated_impacts = self%dissipated_impacts - 0.5_dp*self%impulse(k)* &
                                      (self%velocity_after(k) + self%velocity_before(k))
            impulse_power = impulse_power + self%impulse(k)*(self%velocity_after(k) - self%velocity_before(k))
         end do
         if (self%rayleigh_mass > 0 .or. self%rayleigh_stiffness > 0) &
            self%dissipated_damping = self%dissipated_damping + dt*dot_product(v_theta, self%damping_times(v_theta))
         if (abs(theta - 0.5_dp) > 0) then
            call band_matvec(self%mass, v_new - self%v, work_vector)
            self%dissipated_numerical = self%dissipated_numerical + (theta - 0.5_dp)*dot_product(v_new - self%v, work_vector)
            call band_matvec(self%stiffness, u_new - self%u, work_vector)
            self%dissipated_numerical = self%dissipated_numerical + (theta - 0.5_dp)* &
                                        (dot_product(u_new - self%u, work_vector) - impulse_power)
         end if
         self%u = u_new
         self%v = v_new
         self%force = force_new
         self%steps = self%steps + 1
         self%t = self%steps*dt
         self%impulse_time = self%t   ! the impulse acts over [t_n, t_{n+1}]; recorded at its end
      end associate
   end subroutine step


end module vibrobeam_velocity_stepper
