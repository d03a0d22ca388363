!> What every time stepper of vibrobeam holds and offers (the one-step
!! integrator, separate from the system and from the contact solver). The velocity-based
!! scheme (theory §3, `vibrobeam_velocity_stepper`) and the position-based one (theory §4,
!! `vibrobeam_position_stepper`) extend it; the recorder and the run loop see only this.
module vibrobeam_time_stepper
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_residual_check_failed
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_matvec, band_combination, band_factor, &
      band_residual_solve
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_contact_projector, only: contact_projector, contact_method_code
   use vibrobeam_contact_options, only: contact_options
   use vibrobeam_loads, only: load_set
   use vibrobeam_discrete_system, only: discrete_system
   use vibrobeam_circle_contact, only: circle_contact
   use vibrobeam_state_record, only: state_record
   use vibrobeam_compliant_law, only: stop_potential, rule_gradient
   use vibrobeam_compliant_solver, only: compliant_solver
   use vibrobeam_contact_set, only: contact_value, no_bound
   implicit none
   private
   public :: time_stepper, stepper_settings, dynamic_state, step_report, energy_ledger
   public :: save_stepper_state, restore_stepper_state, unresolved_fraction, checkpoint_state, energy_norm

   !> The largest share of the energy scale the compliant stops' unresolved work may reach
   !! before the run stops as a numerical failure (docs/theory.md section 8, "Accuracy"):
   !! sqrt(eps), the energy to half its digits.
   real(dp), parameter :: unresolved_fraction = sqrt(epsilon(1.0_dp))

   !> How a run is stepped: the scheme and its parameters, Newton's law at the rigid stops,
   !! the Rayleigh damping, the compliant stops' rule and the contact solver's options. One
   !! object handed to `init` (`vibrobeam_problem` makes it from the scene).
   type :: stepper_settings
      character(len=16) :: scheme = 'velocity'       !! a name of `scheme_names` (vibrobeam_stepper_factory)
      real(dp) :: dt = 1e-4_dp                       !! time step (s)
      real(dp) :: theta = 0.5_dp                     !! theta of the theta-method
      real(dp) :: gamma = 0.5_dp                     !! activation at U + gamma dt V (velocity scheme)
      real(dp) :: restitution = 1                    !! Newton's restitution coefficient e
      !> restitution of an active point already moving away from its obstacle (velocity
      !! scheme): 1, or e for the plain law of theory §3
      real(dp) :: separating_restitution = 1
      real(dp) :: rayleigh_mass = 0                  !! a in C = a M + b K (1/s)
      real(dp) :: rayleigh_stiffness = 0             !! b in C = a M + b K (s)
      !> damping per mode (docs/theory.md §1, "Damping"): C_m = Y diag(c) Y^T, Y = M Phi
      !! (J x K, the first K modes, M-orthonormal) and c_k = 2 zeta_k omega_k - a - b
      !! omega_k^2 (1/s), taken explicitly (at V^n); unallocated: none. A beam of two planes
      !! takes them in each plane, y and z, or the z plane's own modes (`modal_forces_z`,
      !! `modal_rates_z`) when it has a stiffness of its own
      real(dp), allocatable :: modal_forces(:,:), modal_rates(:)
      real(dp), allocatable :: modal_forces_z(:,:), modal_rates_z(:)
      integer :: compliant_rule = rule_gradient      !! how a step takes a compliant stop's force
      type(contact_options) :: contact               !! the contact projection's regime, method, iterations
   end type stepper_settings

   !> The state one run hands to the next (a sweep's continuation) or starts from: the step
   !! number, U and V, and what the scheme needs beyond them (`extra`, the position scheme's
   !! U^{n-1}), opaque to everyone but the scheme. A start without `extra` lets the scheme
   !! make its own from U and V.
   type :: dynamic_state
      integer(int64) :: step = 0                     !! t = step dt
      real(dp), allocatable :: u(:), v(:)            !! displacement (m) and velocity (m/s) unknowns
      real(dp), allocatable :: extra(:)              !! the scheme's own
   end type dynamic_state

   !> What the last step did, as the recorder and the observers read it (each scheme says
   !! when its impulses act and what its velocities before and after are).
   type :: step_report
      integer :: active_count = 0
      integer, allocatable :: active(:)            !! contact points with a constraint (first active_count)
      real(dp), allocatable :: impulse(:)          !! impulse of each (N s), positive upwards
      real(dp), allocatable :: velocity_before(:), velocity_after(:)   !! of each point (m/s)
      logical, allocatable :: approaching(:)       !! the point moved toward its obstacle
      integer :: iterations = 0                    !! contact solver iterations of the last step
      integer :: linear_solves = 0                 !! linear solves the contact solver made in the last step
      logical :: used_fallback = .false.           !! the contact solver needed its fall-back in the last step
      real(dp) :: impulse_time = 0                 !! when the last step's impulses act (s)
      !> force of the compliant stops on each contact point at t (N, positive upwards;
      !! 0 at rigid-only points)
      real(dp), allocatable :: contact_force(:)
      !> the circular holes' points the step held (two planes): the first circle_count of
      !! circle_active, each with its impulse (N s, along circle_normal, the inward unit
      !! normal at the predicted position) and normal velocities before and after (m/s,
      !! positive inwards)
      integer :: circle_count = 0
      integer, allocatable :: circle_active(:)
      real(dp), allocatable :: circle_impulse(:), circle_normal(:, :), circle_before(:), circle_after(:)
      !> their friction impulses (N s, along the tangent t = (-n_z, n_y)) and tangential
      !! velocities before (m/s)
      real(dp), allocatable :: circle_friction(:), circle_tangential_before(:)
   end type step_report

   !> The running sums of the energy balance since t = 0 (each scheme says how it defines
   !! them; docs/theory.md §6 and §8).
   type :: energy_ledger
      real(dp) :: work = 0                   !! work of the loads (J)
      real(dp) :: dissipated_impacts = 0     !! energy taken by impacts (J)
      real(dp) :: dissipated_damping = 0     !! energy taken by Rayleigh damping (J)
      real(dp) :: dissipated_friction = 0    !! energy taken by Coulomb friction at circular holes (J)
      real(dp) :: dissipated_numerical = 0   !! energy taken by the theta-method itself (J): velocity scheme,
                                             !! 0 for theta = 1/2; 0 for the position scheme
      ! compliant stops (docs/theory.md section 8); unused when contacts%springs%count = 0
      real(dp) :: dissipated_contact_damping = 0   !! energy taken by the stops' damping (J)
      !> sum over the steps of |sum_j (f_j - f_j^law)(p_j^{n+1} - p_j^n)|: the work of the
      !! force residual Newton's method left (J; part of dissipated_numerical, signed there)
      real(dp) :: unresolved_work = 0
      !> the energy scale max(|E|, |W|, |D|) at the last comparison with unresolved_work (J)
      real(dp) :: energy_scale = 0
   end type energy_ledger

   type, abstract :: time_stepper
      real(dp) :: dt = 0, theta = 0.5_dp, restitution = 1
      real(dp) :: rayleigh_mass = 0, rayleigh_stiffness = 0
      logical :: modal = .false.                   !! damping per mode (`modal_forces`, `modal_rates`)
      real(dp), allocatable :: modal_forces(:,:)   !! Y = M Phi (J x K)
      real(dp), allocatable :: modal_rates(:)      !! c_k (1/s)
      !> a beam of two planes whose z plane has a stiffness of its own: its modes' Y and c
      real(dp), allocatable :: modal_forces_z(:,:), modal_rates_z(:)
      type(symmetric_band) :: mass, stiffness
      type(symmetric_band) :: iteration_matrix     !! W of the scheme, factored once per run
      type(band_cholesky) :: iteration_factor
      !> bending planes (docs/method.md, "Two bending planes"): u and v hold planes x J
      !! unknowns, y then z; M is both planes', K and W the y plane's and, when the z plane
      !! has a stiffness of its own (own_z), stiffness_z and W_z (else z shares K and W)
      integer :: planes = 1
      logical :: own_z = .false.
      type(symmetric_band) :: stiffness_z, iteration_matrix_z
      type(band_cholesky) :: iteration_factor_z
      type(circle_contact) :: holes                !! the circular holes' points and contact step (two planes)
      type(contact_set) :: contacts
      type(contact_projector) :: projector
      type(load_set) :: loads
      real(dp), allocatable :: u(:)               !! displacement unknowns at t (m)
      real(dp), allocatable :: v(:)               !! velocity unknowns (m/s), see each scheme
      real(dp) :: t = 0                            !! time of u (s)
      integer(int64) :: steps = 0                  !! steps taken since t = 0 (t = steps dt)
      type(step_report) :: report                  !! what the last step did
      type(energy_ledger) :: energy                !! running sums since t = 0
      integer :: compliant_rule = rule_gradient    !! how a step takes the stop force (vibrobeam_compliant_law)
      type(compliant_solver) :: compliant          !! the step's Newton solve with springs
   contains
      procedure(init_interface), deferred :: init
      procedure(step_interface), deferred :: step
      procedure :: state => stepper_state
      procedure :: kinetic_energy
      procedure :: elastic_energy
      procedure :: contact_potential
      procedure :: compliant_energy
      procedure :: check_compliant_work
      procedure :: spring_penetrations
      procedure :: smallest_clearance
      procedure :: set_up_system
      procedure :: damping_times
      procedure :: damping_into
      procedure :: mass_into
      procedure :: stiffness_into
      procedure :: free_solve
      procedure :: add_modal_damping
      procedure :: save_state => save_stepper_state
      procedure :: restore_state => restore_stepper_state
   end type time_stepper

   abstract interface
      !> Set up for a run of `system` with `settings` from `start` (its U and V; its `extra`
      !! when it continues a run of the same scheme), at step 0.
      subroutine init_interface(self, system, settings, start, stat, errmsg)
         import :: time_stepper, discrete_system, stepper_settings, dynamic_state
         class(time_stepper), intent(inout) :: self
         type(discrete_system), intent(in) :: system
         type(stepper_settings), intent(in) :: settings
         type(dynamic_state), intent(in) :: start
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine init_interface

      !> Advance one step. stat: stat_ok; a contact solver failure; stat_not_finite.
      subroutine step_interface(self, stat, errmsg)
         import :: time_stepper
         class(time_stepper), intent(inout) :: self
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine step_interface
   end interface

contains

   !> 1/2 V^T M V (J; per unit mass when the beam is given by k2; both planes').
   function kinetic_energy(self) result(energy)
      class(time_stepper), intent(in) :: self
      real(dp) :: energy, mv(size(self%v))
      call self%mass_into(self%v, mv)
      energy = 0.5_dp*dot_product(self%v, mv)
   end function kinetic_energy

   !> sqrt(U^T (K + omega^2 M) U + V^T M V) of a state (U, V), or of a perturbation of one:
   !! twice its energy with U weighed at the frequency omega, so that U and V of any unit
   !! and the rotations of Hermite elements are measured alike, and the rigid-body motions
   !! that supports let the beam make have a norm too (J^(1/2); per unit mass with k2).
   !! The norm of the period map (docs/method.md, "Periodic orbits by shooting") and of the
   !! Lyapunov exponent's perturbation (docs/statistics.md).
   function energy_norm(mass, stiffness, omega, u, v) result(norm)
      type(symmetric_band), intent(in) :: mass, stiffness
      real(dp), intent(in) :: omega, u(:), v(:)
      real(dp) :: norm, mx(size(u)), kx(size(u))
      call band_matvec(mass, u, mx)
      call band_matvec(stiffness, u, kx)
      norm = dot_product(u, kx) + omega**2*dot_product(u, mx)
      call band_matvec(mass, v, mx)
      norm = sqrt(max(0.0_dp, norm + dot_product(v, mx)))
   end function energy_norm

   !> 1/2 U^T K U (J; both planes', K_z in z).
   function elastic_energy(self) result(energy)
      class(time_stepper), intent(in) :: self
      real(dp) :: energy, ku(size(self%u))
      call self%stiffness_into(self%u, ku)
      energy = 0.5_dp*dot_product(self%u, ku)
   end function elastic_energy

   !> Penetration p_j = s_j (g_j - H_c U) of every spring at the displacement `u` (m).
   function spring_penetrations(self, u) result(p)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: u(:)
      real(dp) :: p(self%contacts%springs%count)
      integer :: j
      associate (springs => self%contacts%springs)
         do j = 1, springs%count
            p(j) = springs%sign(j)*(springs%level(j) - contact_value(self%contacts, springs%point(j), u))
         end do
      end associate
   end function spring_penetrations

   !> The smallest clearance of the beam to its obstacles at the displacement `u` (m): over
   !! the contact points, the distance H_c U - lower(c) and upper(c) - H_c U to a rigid
   !! bound, -p_j of every compliant stop (`spring_penetrations`), and the distance to the
   !! wall of every cross-section point of a beam of two planes (`circle_set`'s gap);
   !! positive while every point is free, negative when one is beyond its obstacle (a
   !! compliant stop's penetration). huge(1.0_dp) without obstacles. The grazing test
   !! function of a continued branch (docs/method.md, "Continuation of periodic orbits").
   function smallest_clearance(self, u) result(gap)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: u(:)
      real(dp) :: gap, value
      integer :: c
      gap = huge(1.0_dp)
      do c = 1, self%contacts%count
         value = contact_value(self%contacts, c, u)
         if (self%contacts%lower(c) > -no_bound) gap = min(gap, value - self%contacts%lower(c))
         if (self%contacts%upper(c) < no_bound) gap = min(gap, self%contacts%upper(c) - value)
      end do
      if (self%contacts%springs%count > 0) gap = min(gap, -maxval(self%spring_penetrations(u)))
      do c = 1, self%holes%circles%count
         gap = min(gap, -self%holes%circles%penetration(c, u))
      end do
   end function smallest_clearance

   !> Energy stored in the compliant stops, sum_j Phi_j(p_j) (J), the compliant circles' too.
   function contact_potential(self) result(energy)
      class(time_stepper), intent(in) :: self
      real(dp) :: energy
      associate (springs => self%contacts%springs)
         energy = 0
         if (springs%count > 0) &
            energy = sum(stop_potential(springs%stiffness, springs%exponent, self%spring_penetrations(self%u)))
      end associate
      energy = energy + self%holes%potential(self%u)
   end function contact_potential

   !> Energy bookkeeping of the compliant stops over a step whose penetrations go from p0
   !! to p1 (both schemes: the velocity scheme's p(U^n), p(U^{n+1}); the position scheme's
   !! half-step ones): the beam lost sum_j f_j (p1_j - p0_j) to the stops (f_j the force
   !! the step applied), of which Phi_j(p1) - Phi_j(p0) is stored, (f_j^law - elastic_j) dp_j
   !! >= 0 is taken by the contact damping (f^law the rule's force at p0, p1, elastic its
   !! elastic part) and the rest is the time discretization's, `dissipated_numerical`:
   !! elastic_j dp_j - dPhi_j (round-off for the 'gradient' rule; the 'mean' rule's error at
   !! a step that engages or releases a stop) and (f_j - f_j^law) dp_j, the work of the
   !! residual Newton's method left (docs/theory.md section 8, "Energy" and "Accuracy").
   subroutine compliant_energy(self, p0, p1)
      class(time_stepper), intent(inout) :: self
      real(dp), intent(in) :: p0(:), p1(:)
      associate (springs => self%contacts%springs, c => self%compliant)
         self%energy%dissipated_contact_damping = self%energy%dissipated_contact_damping + sum((c%law_force - c%elastic)*(p1 - p0))
         self%energy%dissipated_numerical = self%energy%dissipated_numerical + sum(c%elastic*(p1 - p0)) - &
            sum(stop_potential(springs%stiffness, springs%exponent, p1) - &
                stop_potential(springs%stiffness, springs%exponent, p0)) + sum((c%force - c%law_force)*(p1 - p0))
      end associate
   end subroutine compliant_energy

   !> After the compliant solve of a step whose penetrations go from p0 to p1, before the
   !! step is taken: the work of the force residual Newton's method left, |sum_j (f_j -
   !! f_j^law)(p1_j - p0_j)|, is added to `unresolved_work`; stat_residual_check_failed
   !! (the run stops, exit 3) when the sum exceeds unresolved_fraction of the energy scale
   !! max(|E|, |W|, |D|, |sum_j f_j^law (p1_j - p0_j)|) (evaluated, at the start of the
   !! step and with the springs' work in it, only when the sum passes the fraction of the
   !! last scale). The rule's energy identity then no longer holds to
   !! half the digits: a stop too stiff for the arithmetic at this dt (docs/theory.md
   !! section 8, "Accuracy").
   subroutine check_compliant_work(self, p0, p1, stat, errmsg)
      class(time_stepper), intent(inout) :: self
      real(dp), intent(in) :: p0(:), p1(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: total, dissipated
      character(len=24) :: text(3)
      stat = 0
      errmsg = ''
      total = self%energy%unresolved_work + abs(sum((self%compliant%force - self%compliant%law_force)*(p1 - p0)))
      if (total > unresolved_fraction*self%energy%energy_scale) then
         dissipated = self%energy%dissipated_impacts + self%energy%dissipated_damping + self%energy%dissipated_numerical + &
                      self%energy%dissipated_contact_damping
         ! with the springs' own work in this step: a stop that touches a beam at rest (a
         ! zero gap) under a load meets an energy of 0 at the start of the first step, and
         ! any residual at all would be refused
         self%energy%energy_scale = max(self%energy%energy_scale, abs(self%kinetic_energy() + self%elastic_energy() + &
                                 self%contact_potential()), abs(self%energy%work), abs(dissipated), &
                                 abs(sum(self%compliant%law_force*(p1 - p0))))
         if (total > unresolved_fraction*self%energy%energy_scale) then
            stat = stat_residual_check_failed
            write (text(1), '(es10.3)') total
            write (text(2), '(es10.3)') total/max(self%energy%energy_scale, tiny(1.0_dp))
            write (text(3), '(es10.3)') unresolved_fraction
            errmsg = 'the compliant stops are not resolved: the force residual of their Newton solves has done '// &
                     trim(adjustl(text(1)))//' J of work, '//trim(adjustl(text(2)))//' of the energy scale (at most '// &
                     trim(adjustl(text(3)))//'); a stop is too stiff for dt: reduce dt or its stiffness '// &
                     '(docs/theory.md section 8, "Accuracy")'
            return
         end if
      end if
      self%energy%unresolved_work = total
   end subroutine check_compliant_work

   !> What both schemes set up the same way: the data of the run, the settings, the
   !! iteration matrix W = mass_coefficient M + stiffness_coefficient K (each scheme gives
   !! its own coefficients) with its Cholesky factor, the contact projection in the metric of
   !! W with its options, room for one record per contact point, and t = 0.
   subroutine set_up_system(self, system, settings, mass_coefficient, stiffness_coefficient, stat, errmsg)
      class(time_stepper), intent(inout) :: self
      type(discrete_system), intent(in) :: system
      type(stepper_settings), intent(in) :: settings
      real(dp), intent(in) :: mass_coefficient, stiffness_coefficient
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: n
      self%dt = settings%dt
      self%theta = settings%theta
      self%restitution = settings%restitution
      self%rayleigh_mass = settings%rayleigh_mass
      self%rayleigh_stiffness = settings%rayleigh_stiffness
      self%modal = allocated(settings%modal_rates)
      if (self%modal) then
         self%modal = size(settings%modal_rates) > 0
         self%modal_forces = settings%modal_forces
         self%modal_rates = settings%modal_rates
         if (allocated(settings%modal_rates_z)) then
            self%modal_forces_z = settings%modal_forces_z
            self%modal_rates_z = settings%modal_rates_z
         end if
      end if
      self%compliant_rule = settings%compliant_rule
      self%mass = system%model%mass
      self%stiffness = system%model%stiffness
      self%contacts = system%contacts
      self%loads = system%loads
      self%t = 0
      self%steps = 0
      n = system%contacts%count
      allocate (self%report%active(n), self%report%impulse(n), self%report%velocity_before(n), &
                self%report%velocity_after(n), self%report%approaching(n), self%report%contact_force(n))
      self%report%contact_force = 0
      self%report%active_count = 0
      self%iteration_matrix = band_combination(mass_coefficient, system%model%mass, stiffness_coefficient, &
                                               system%model%stiffness)
      call band_factor(self%iteration_matrix, self%iteration_factor, stat, errmsg)
      if (stat /= 0) return
      self%planes = system%planes
      self%holes%circles = system%circles
      n = system%circles%count
      allocate (self%report%circle_active(n), self%report%circle_impulse(n), self%report%circle_normal(2, n), &
                self%report%circle_before(n), self%report%circle_after(n), self%report%circle_friction(n), &
                self%report%circle_tangential_before(n))
      self%own_z = allocated(system%stiffness_z)
      if (self%own_z) then
         self%stiffness_z = system%stiffness_z
         self%iteration_matrix_z = band_combination(mass_coefficient, system%model%mass, stiffness_coefficient, &
                                                    system%stiffness_z)
         call band_factor(self%iteration_matrix_z, self%iteration_factor_z, stat, errmsg)
         if (stat /= 0) return
      end if
      associate (contact => settings%contact)
         call self%projector%setup(self%iteration_matrix, self%iteration_factor, system%contacts, contact%contact_solver)
         if (system%contacts%springs%count > 0) &
            call self%compliant%setup(system%contacts%springs, self%compliant_rule, contact%contact_solver, 'newton')
         self%projector%max_iterations = contact%contact_max_iterations
         self%projector%method = contact_method_code(trim(contact%contact_method))
         self%compliant%method = trim(contact%contact_method)
      end associate
   end subroutine set_up_system

   !> The state a run hands on: step, U, V (a scheme with more state extends this).
   function stepper_state(self) result(state)
      class(time_stepper), intent(in) :: self
      type(dynamic_state) :: state
      state%step = self%steps
      allocate (state%u, source=self%u)   ! (an assignment to the unallocated result warns in Debug builds)
      allocate (state%v, source=self%v)
   end function stepper_state

   !> The state that a checkpoint `record` holds (what `save_stepper_state` put there:
   !! step, U and V of `unknowns` values each). A scheme with more state adds its `extra`
   !! (`vibrobeam_stepper_factory`'s `state_from_record`). stat /= 0 when an item is
   !! missing or of another size.
   subroutine checkpoint_state(record, unknowns, state, stat, errmsg)
      type(state_record), intent(in) :: record
      integer, intent(in) :: unknowns
      type(dynamic_state), intent(out) :: state
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      allocate (state%u(unknowns), state%v(unknowns))
      call record%get_int64('stepper.steps', state%step, stat, errmsg)
      if (stat == 0) call record%get_reals('stepper.u', state%u, stat, errmsg)
      if (stat == 0) call record%get_reals('stepper.v', state%v, stat, errmsg)
   end subroutine checkpoint_state

   !> Put everything a continued run needs to go on bitwise into `record` (docs/output.md,
   !! "Checkpoint and restart"): the step number, U and V, and the running energy sums
   !! (with compliant stops or compliant holes their damping's and the balance's accuracy;
   !! with the holes of a beam of two planes the energy friction took).
   !! A scheme with more state extends this (the position scheme adds U^{n-1}); the contact
   !! solver's state between steps (a warm start), when it has one, belongs here too.
   subroutine save_stepper_state(self, record)
      class(time_stepper), intent(in) :: self
      type(state_record), intent(inout) :: record
      call record%put_int64('stepper.steps', self%steps)
      call record%put_reals('stepper.u', self%u)
      call record%put_reals('stepper.v', self%v)
      call record%put_reals('stepper.energy_sums', [self%energy%work, self%energy%dissipated_impacts, &
                                                    self%energy%dissipated_damping, self%energy%dissipated_numerical])
      if (compliant_contact(self)) &
         call record%put_reals('stepper.contact_damping', [self%energy%dissipated_contact_damping])
      if (self%contacts%springs%count > 0) call record%put_reals('stepper.contact_force', self%report%contact_force)
      if (compliant_contact(self)) &
         call record%put_reals('stepper.compliant_accuracy', [self%energy%unresolved_work, self%energy%energy_scale])
      if (self%holes%circles%count > 0) call record%put_reals('stepper.friction', [self%energy%dissipated_friction])
   end subroutine save_stepper_state

   !> Take back what `save_state` put into `record` (same sizes); t = steps dt.
   subroutine restore_stepper_state(self, record, stat, errmsg)
      class(time_stepper), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: sums(4), damping(1), accuracy(2), friction(1)
      damping = 0
      accuracy = 0
      friction = 0
      call record%get_int64('stepper.steps', self%steps, stat, errmsg)
      if (stat == 0) call record%get_reals('stepper.u', self%u, stat, errmsg)
      if (stat == 0) call record%get_reals('stepper.v', self%v, stat, errmsg)
      if (stat == 0) call record%get_reals('stepper.energy_sums', sums, stat, errmsg)
      if (stat == 0 .and. self%contacts%springs%count > 0) &
         call record%get_reals('stepper.contact_force', self%report%contact_force, stat, errmsg)
      if (stat == 0 .and. compliant_contact(self)) call record%get_reals('stepper.contact_damping', damping, stat, errmsg)
      ! checkpoints written before issue 23 do not hold it: the sum starts again at 0
      if (stat == 0 .and. compliant_contact(self) .and. record%find('stepper.compliant_accuracy') > 0) &
         call record%get_reals('stepper.compliant_accuracy', accuracy, stat, errmsg)
      if (stat == 0 .and. self%holes%circles%count > 0) call record%get_reals('stepper.friction', friction, stat, errmsg)
      if (stat /= 0) return
      self%energy%work = sums(1)
      self%energy%dissipated_impacts = sums(2)
      self%energy%dissipated_damping = sums(3)
      self%energy%dissipated_numerical = sums(4)
      self%energy%dissipated_contact_damping = damping(1)
      self%energy%unresolved_work = accuracy(1)
      self%energy%energy_scale = accuracy(2)
      self%energy%dissipated_friction = friction(1)
      self%t = self%steps*self%dt
   end subroutine restore_stepper_state

   !> Does the scene have compliant stops (the springs of levels) or compliant holes?
   pure logical function compliant_contact(self)
      class(time_stepper), intent(in) :: self
      compliant_contact = self%contacts%springs%count > 0 .or. self%holes%circles%compliant
   end function compliant_contact

   !> y = C x = a M x + b K x into preallocated y, with z (same size) as work space (the
   !! steppers' form, without a temporary; `damping_times` is the function form).
   subroutine damping_into(self, x, y, z)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: y(:), z(:)
      y = 0
      if (self%rayleigh_mass > 0) then
         call self%mass_into(x, z)
         y = self%rayleigh_mass*z
      end if
      if (self%rayleigh_stiffness > 0) then
         call self%stiffness_into(x, z)
         y = y + self%rayleigh_stiffness*z
      end if
   end subroutine damping_into

   !> y = M x into preallocated y: one band product per plane (the planes share M).
   subroutine mass_into(self, x, y)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: y(:)
      integer :: j
      if (self%planes == 1) then
         call band_matvec(self%mass, x, y)
      else
         j = size(x)/2
         call band_matvec(self%mass, x(1:j), y(1:j))
         call band_matvec(self%mass, x(j + 1:), y(j + 1:))
      end if
   end subroutine mass_into

   !> y = K x into preallocated y: K in y, K_z (or K) in z.
   subroutine stiffness_into(self, x, y)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: y(:)
      integer :: j
      if (self%planes == 1) then
         call band_matvec(self%stiffness, x, y)
      else
         j = size(x)/2
         call band_matvec(self%stiffness, x(1:j), y(1:j))
         if (self%own_z) then
            call band_matvec(self%stiffness_z, x(j + 1:), y(j + 1:))
         else
            call band_matvec(self%stiffness, x(j + 1:), y(j + 1:))
         end if
      end if
   end subroutine stiffness_into

   !> y = W^-1 (b - K x), plane by plane (`band_residual_solve`: the fused kernel of each
   !! plane's band; W_z and K_z in z when it has its own, else W and K again).
   subroutine free_solve(self, x, b, y)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: x(:), b(:)
      real(dp), intent(out) :: y(:)
      integer :: j
      if (self%planes == 1) then
         call band_residual_solve(self%iteration_factor, self%stiffness, x, b, y)
      else
         j = size(x)/2
         call band_residual_solve(self%iteration_factor, self%stiffness, x(1:j), b(1:j), y(1:j))
         if (self%own_z) then
            call band_residual_solve(self%iteration_factor_z, self%stiffness_z, x(j + 1:), b(j + 1:), y(j + 1:))
         else
            call band_residual_solve(self%iteration_factor, self%stiffness, x(j + 1:), b(j + 1:), y(j + 1:))
         end if
      end if
   end subroutine free_solve

   !> y := y + C_m x = y + Y (c * (Y^T x)): the damping per mode (`stepper_settings`), 4 J K
   !! operations (docs/method.md, "Damping per mode"); a beam of two planes (x of 2J values,
   !! y then z): in each plane, with the z plane's own modes when it has them.
   subroutine add_modal_damping(self, x, y)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(inout) :: y(:)
      integer :: j
      j = size(self%modal_forces, 1)
      call add_plane(self%modal_forces, self%modal_rates, x(1:j), y(1:j))
      if (size(x) == j) return
      if (allocated(self%modal_rates_z)) then
         call add_plane(self%modal_forces_z, self%modal_rates_z, x(j + 1:), y(j + 1:))
      else
         call add_plane(self%modal_forces, self%modal_rates, x(j + 1:), y(j + 1:))
      end if
   contains
      subroutine add_plane(forces, rates, x, y)
         real(dp), intent(in) :: forces(:, :), rates(:), x(:)
         real(dp), intent(inout) :: y(:)
         real(dp) :: coordinates(size(rates))
         coordinates = rates*matmul(x, forces)
         y = y + matmul(forces, coordinates)
      end subroutine add_plane
   end subroutine add_modal_damping

   !> C x = a M x + b K x (Rayleigh damping).
   function damping_times(self, x) result(y)
      class(time_stepper), intent(in) :: self
      real(dp), intent(in) :: x(:)
      real(dp) :: y(size(x)), z(size(x))
      call self%damping_into(x, y, z)
   end function damping_times
end module vibrobeam_time_stepper
