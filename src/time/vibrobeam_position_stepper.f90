!> The position-based scheme of Paoli and Schatzman used by Dumont & Paoli (2006)
!! (theory §4), for comparison with the velocity-based one:
!!
!!   M (U^{n+1} - 2U^n + U^{n-1})/dt^2 + C (U^{n+1} - U^{n-1})/(2 dt)
!!     + K (theta U^{n+1} + (1 - 2 theta) U^n + theta U^{n-1}) = F^n + H^T r^n,
!!   (U^{n+1} + e U^{n-1})/(1 + e) = Proj_{K_h}^W ((U_free^{n+1} + e U^{n-1})/(1 + e)),
!!
!! W = M + dt/2 C + theta dt^2 K (theory §4's M + theta dt^2 K when C = 0), U_free the
!! solution without reaction. The projection onto the whole admissible set K_h uses
!! `contact_projector%project_admissible`. With e = 0 every computed position is
!! admissible (to the solver's round-off); with e > 0 the law reflects U^{n-1} about the
!! obstacle, so U^{n+1} = (1 + e) Z - e U^{n-1} lies up to e (H U^{n-1} - g) inside it.
!!
!! Start: U^{-1} = U^0 - dt V^0 + dt^2/2 M^-1 (F^0 - K U^0 - C V^0) (second order).
!! What it reports: u = U^{n+1}; v = (U^{n+1} - U^n)/dt, the velocity at t_{n+1/2}; the
!! energy E_{n+1/2} = 1/2 v^T (M + (theta - 1/4) dt^2 K) v + 1/2 Ubar^T K Ubar, Ubar =
!! (U^{n+1} + U^n)/2, which the scheme conserves without load, damping or contact; the
!! work F^n.(U^{n+1} - U^{n-1})/2 and the impulses' -r^n.H(U^{n+1} - U^{n-1})/2 close the
!! balance for every theta, so `dissipated_numerical` stays 0 (theta enters the energy as
!! (theta - 1/4) dt^2 K). After the step t_n -> t_{n+1} the reported v and energies are
!! those of t_{n+1/2}. An impulse is r^n dt, stamped at t_n (the centre of the stencil);
!! the velocities before/after an impact are H(U^n - U^{n-1})/dt and H(U^{n+1} - U^n)/dt
!! (docs/method.md, "The position-based scheme").
module vibrobeam_position_stepper
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_not_finite
   use vibrobeam_band, only: band_cholesky, band_factor, band_solve, band_matvec
   use vibrobeam_contact_set, only: contact_set, contact_value
   use vibrobeam_loads, only: load_set
   use vibrobeam_time_stepper, only: time_stepper, stepper_settings, dynamic_state, save_stepper_state, &
      restore_stepper_state, checkpoint_state
   use vibrobeam_discrete_system, only: discrete_system
   use vibrobeam_state_record, only: state_record
   use vibrobeam_compliant_law, only: end_force, stop_potential
   use vibrobeam_compliant_solver, only: rigid_admissible
   implicit none
   private
   public :: position_stepper, position_state_of_record

   type, extends(time_stepper) :: position_stepper
      real(dp), allocatable :: u_previous(:)       !! U^n after a step (U^{-1} at the start)
      real(dp), allocatable :: multiplier(:)       !! projection multipliers per contact point
   contains
      procedure :: init
      procedure :: step
      procedure :: kinetic_energy => half_step_kinetic_energy
      procedure :: elastic_energy => half_step_elastic_energy
      procedure :: contact_potential => half_step_contact_potential
      procedure, private :: compliant_projection
      procedure :: save_state
      procedure :: restore_state
      procedure :: state => position_state
   end type position_stepper

contains

   !> Set up for a run: build and factor W, prepare the contact projection; U^0 = start%u
   !! and U^{-1} from start%extra when a run of this scheme hands it on (V = (U^0 - U^{-1})/dt),
   !! otherwise the second-order start from start%u and start%v (module header).
   subroutine init(self, system, settings, start, stat, errmsg)
      class(position_stepper), intent(inout) :: self
      type(discrete_system), intent(in) :: system
      type(stepper_settings), intent(in) :: settings
      type(dynamic_state), intent(in) :: start
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(band_cholesky) :: mass_factor
      real(dp) :: acceleration(size(start%u)), ku(size(start%u))
      associate (dt => settings%dt, u0 => start%u, v0 => start%v)
         ! W = (1 + dt a/2) M + (theta dt^2 + dt b/2) K
         call self%set_up_system(system, settings, 1 + 0.5_dp*dt*settings%rayleigh_mass, &
                                 settings%theta*dt**2 + 0.5_dp*dt*settings%rayleigh_stiffness, stat, errmsg)
         if (stat /= 0) return
         call band_factor(system%model%mass, mass_factor, stat, errmsg)
         if (stat /= 0) return
         call band_matvec(system%model%stiffness, u0, ku)
         acceleration = system%loads%at(0.0_dp) - ku
         if (settings%rayleigh_mass > 0 .or. settings%rayleigh_stiffness > 0) &
            acceleration = acceleration - self%damping_times(v0)
         if (self%modal) call self%add_modal_damping(-v0, acceleration)
         call band_solve(mass_factor, acceleration)
         self%u = u0
         self%u_previous = u0 - dt*v0 + 0.5_dp*dt**2*acceleration
         self%v = (self%u - self%u_previous)/dt
         allocate (self%multiplier(system%contacts%count), source=0.0_dp)
         if (allocated(start%extra)) then
            ! the state of an earlier run carried on (docs/sweeps.md, "Continuation")
            self%u_previous = start%extra
            self%v = (self%u - self%u_previous)/dt
         end if
      end associate
   end subroutine init

   subroutine step(self, stat, errmsg)
      class(position_stepper), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), dimension(size(self%u)) :: rhs, work_vector, u_free, z_free, z, u_new, force, stride, modal_force
      real(dp) :: e, before, after, reaction
      integer :: c, m
      associate (dt => self%dt, theta => self%theta, u => self%u, u_old => self%u_previous)
         e = self%restitution
         call self%loads%evaluate(self%t, force)
         call band_matvec(self%mass, 2*u - u_old, rhs)
         call band_matvec(self%stiffness, (1 - 2*theta)*u + theta*u_old, work_vector)
         rhs = rhs - dt**2*work_vector + dt**2*force
         if (self%rayleigh_mass > 0 .or. self%rayleigh_stiffness > 0) &
            rhs = rhs + 0.5_dp*dt*self%damping_times(u_old)
         if (self%modal) then
            ! the damping per mode at v^{n-1/2} = (U^n - U^{n-1})/dt (explicit: W keeps its band)
            modal_force = 0
            call self%add_modal_damping((u - u_old)/dt, modal_force)
            rhs = rhs - dt**2*modal_force
         end if
         call band_solve(self%iteration_factor, rhs)
         u_free = rhs
         z_free = (u_free + e*u_old)/(1 + e)
         if (self%contacts%springs%count > 0) then
            call self%compliant_projection(z_free, z, stat, errmsg)
         else
            call self%projector%project_admissible(z_free, z, self%multiplier, self%report%iterations, stat, errmsg)
            self%report%linear_solves = self%projector%linear_solves
         end if
         self%report%used_fallback = self%projector%used_fallback
         if (stat /= 0) return
         u_new = (1 + e)*z - e*u_old
         if (.not. ieee_is_finite(sum(u_new))) then
            stat = stat_not_finite
            write (errmsg, '(a,es12.5,a)') 'the solution is no longer finite at t = ', self%t + dt, ' s'
            return
         end if
         stride = u_new - u_old   ! U^{n+1} - U^{n-1}
         if (self%loads%present) self%energy%work = self%energy%work + 0.5_dp*dot_product(force, stride)
         if (self%rayleigh_mass > 0 .or. self%rayleigh_stiffness > 0) self%energy%dissipated_damping = &
            self%energy%dissipated_damping + 0.5_dp*dot_product(stride, self%damping_times(stride))/(2*dt)
         ! the damping per mode's force -C_m v^{n-1/2} at t_n does the work -1/2 stride.C_m v^{n-1/2}
         if (self%modal) self%energy%dissipated_damping = self%energy%dissipated_damping + &
                                                          0.5_dp*dot_product(stride, modal_force)
         ! contact record: reaction r = (1 + e) P_z/dt^2 (W (U^{n+1} - U_free) = dt^2 H^T r)
         m = 0
         do c = 1, self%contacts%count
            if (abs(self%multiplier(c)) <= 0) cycle
            m = m + 1
            reaction = (1 + e)*self%multiplier(c)/dt**2
            before = (contact_value(self%contacts, c, u) - contact_value(self%contacts, c, u_old))/dt
            after = (contact_value(self%contacts, c, u_new) - contact_value(self%contacts, c, u))/dt
            self%report%active(m) = c
            self%report%impulse(m) = reaction*dt
            self%report%velocity_before(m) = before
            self%report%velocity_after(m) = after
            self%report%approaching(m) = sign(1.0_dp, reaction)*before <= 0
            self%energy%dissipated_impacts = self%energy%dissipated_impacts &
               - 0.5_dp*reaction*contact_value(self%contacts, c, stride)
         end do
         self%report%active_count = m
         self%u_previous = u
         self%u = u_new
         self%v = (self%u - self%u_previous)/dt
         self%report%impulse_time = self%t   ! the scheme is centred at t_n, where r^n acts
         self%steps = self%steps + 1
         self%t = self%steps*dt
      end associate
   end subroutine step

   !> The base type's state and U^{n-1}.
   !> The projection with compliant stops (docs/theory.md section 8, "The position
   !! scheme"): the springs act at t_n through the half-step penetrations
   !! pbar^{n+1/2} = s (g - H (U^{n+1} + U^n)/2), with the step force of the scene's rule
   !! between pbar^{n-1/2} and pbar^{n+1/2} (the gradient rule conserves E^{n+1/2} +
   !! sum Phi(pbar^{n+1/2})). In the unknown Z = (U^{n+1} + e U^{n-1})/(1 + e):
   !! W (Z - Z_free) = dt^2/(1 + e) sum_j s_j f_j H_j^T + H^T multiplier, and
   !! pbar^{n+1/2} = s (g - H (U^n - e U^{n-1})/2) - s (1 + e)/2 H Z.
   subroutine compliant_projection(self, z_free, z, stat, errmsg)
      class(position_stepper), intent(inout) :: self
      real(dp), intent(in) :: z_free(:)
      real(dp), intent(out) :: z(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: p0(self%contacts%springs%count), q(self%contacts%springs%count), e
      integer :: no_points(0), j
      real(dp) :: no_values(0)
      e = self%restitution
      associate (springs => self%contacts%springs, c => self%compliant)
         p0 = self%spring_penetrations(0.5_dp*(self%u + self%u_previous))
         q = self%spring_penetrations(0.5_dp*(self%u - e*self%u_previous))
         call c%solve(springs, self%contacts, self%iteration_matrix, self%projector, z_free, q, p0, 0.5_dp*(1 + e), &
                      self%dt**2/(1 + e), 0.5_dp, self%dt, rigid_admissible, no_points, no_values, no_values, z, &
                      self%multiplier, stat, errmsg)
         self%report%iterations = c%iterations
         self%report%linear_solves = c%linear_solves
         if (stat /= 0) return   ! (the compliant solver's own code: docs/output.md, "Status codes")
         call self%check_compliant_work(p0, c%p1, stat, errmsg)
         if (stat /= 0) return
         ! energy: the beam's half-step energy loses sum f dpbar; Phi(pbar) stores it
         call self%compliant_energy(p0, c%p1)
         self%report%contact_force = 0
         do j = 1, springs%count
            self%report%contact_force(springs%point(j)) = self%report%contact_force(springs%point(j)) + springs%sign(j)* &
               end_force(springs%stiffness(j), springs%exponent(j), springs%damping(j), self%dt, p0(j), c%p1(j))
         end do
      end associate
   end subroutine compliant_projection

   !> sum_j Phi_j(pbar_j^{n+1/2}), the stops' part of the half-step energy (J).
   function half_step_contact_potential(self) result(energy)
      class(position_stepper), intent(in) :: self
      real(dp) :: energy
      energy = 0
      associate (springs => self%contacts%springs)
         if (springs%count > 0) energy = sum(stop_potential(springs%stiffness, springs%exponent, &
                                                            self%spring_penetrations(0.5_dp*(self%u + self%u_previous))))
      end associate
   end function half_step_contact_potential

   subroutine save_state(self, record)
      class(position_stepper), intent(in) :: self
      type(state_record), intent(inout) :: record
      call save_stepper_state(self, record)
      call record%put_reals('stepper.u_previous', self%u_previous)
   end subroutine save_state

   !> The state a run hands on: step, U^n, V and U^{n-1} (extra).
   function position_state(self) result(state)
      class(position_stepper), intent(in) :: self
      type(dynamic_state) :: state
      state%step = self%steps
      allocate (state%u, source=self%u)   ! (an assignment to the unallocated result warns in Debug builds)
      allocate (state%v, source=self%v)
      allocate (state%extra, source=self%u_previous)
   end function position_state

   !> The state a checkpoint of this scheme holds: the base's, and U^{n-1} as extra.
   subroutine position_state_of_record(record, unknowns, state, stat, errmsg)
      type(state_record), intent(in) :: record
      integer, intent(in) :: unknowns
      type(dynamic_state), intent(out) :: state
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call checkpoint_state(record, unknowns, state, stat, errmsg)
      if (stat /= 0) return
      allocate (state%extra(unknowns))
      call record%get_reals('stepper.u_previous', state%extra, stat, errmsg)
   end subroutine position_state_of_record

   !> Take back what `save_state` put into `record`.
   subroutine restore_state(self, record, stat, errmsg)
      class(position_stepper), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call restore_stepper_state(self, record, stat, errmsg)
      if (stat == 0) call record%get_reals('stepper.u_previous', self%u_previous, stat, errmsg)
   end subroutine restore_state

   !> 1/2 v^T (M + (theta - 1/4) dt^2 K) v at t_{n-1/2} (the scheme's kinetic part).
   function half_step_kinetic_energy(self) result(energy)
      class(position_stepper), intent(in) :: self
      real(dp) :: energy, mv(size(self%v)), kv(size(self%v))
      call band_matvec(self%mass, self%v, mv)
      call band_matvec(self%stiffness, self%v, kv)
      energy = 0.5_dp*dot_product(self%v, mv + (self%theta - 0.25_dp)*self%dt**2*kv)
   end function half_step_kinetic_energy

   !> 1/2 Ubar^T K Ubar, Ubar = (U^n + U^{n-1})/2 (the scheme's elastic part).
   function half_step_elastic_energy(self) result(energy)
      class(position_stepper), intent(in) :: self
      real(dp) :: energy, ku(size(self%u))
      call band_matvec(self%stiffness, 0.5_dp*(self%u + self%u_previous), ku)
      energy = 0.25_dp*dot_product(self%u + self%u_previous, ku)
   end function half_step_elastic_energy
end module vibrobeam_position_stepper
