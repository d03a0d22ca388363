!> Round-off bounds of the energy checks (the static ones: `vibrobeam_static_bounds`), derived from the standard model of floating-point
!! arithmetic and computed from the run itself (a posteriori), so that a check holds on any
!! conforming BLAS/LAPACK - whatever its summation order, blocking or use of FMA - and
!! still fails when the scheme's energy identity does not hold.
!!
!! Standard model (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002,
!! ch. 2-3): fl(a op b) = (a op b)(1 + d), |d| <= u = eps/2, and gamma_n = n u/(1 - n u).
!! A sum of n products computed in ANY order has an error <= gamma_n sum |products| (§3.1).
!! A Cholesky solve (A + dA) x = b has |dA| <= gamma_{3(kd+1)+1} |L||L^T| for a band of kd
!! sub-diagonals (Thm 10.3-10.4, n replaced by the kd + 1 terms of each inner product).
!! All bounds below are first order in u (the O(u^2) terms are below 1e-20 relative here).
!!
!! 1. Evaluating an energy. E = 1/2 x^T (A x) computed as dot(x, dsbmv(A, x)): each row of
!!    A x is a sum of at most 2 kd + 1 products and the dot product a sum of n, so
!!      |fl(E) - E| <= 1/2 [gamma_{2kd+1} |x|^T |A| |x| + gamma_n |x|^T |A x|].
!!    The first term is the conditioning of the energy: for a smooth x, |x|^T|K||x| exceeds
!!    x^T K x by about (omega_max/omega)^2 (measured 3.6e4 for the 24-element k2 = 1 beam,
!!    1.2e7 for the 48-element steel beam), because K x cancels while |K||x| does not.
!!    This term, not the scheme, is what differs between BLAS libraries (OpenBLAS's
!!    SkylakeX dsbmv kernel rounds differently from the reference one; both stay below it).
!! 2. One step. The computed step satisfies the scheme's equations with a residual rho
!!    (rounding of the right-hand side, of the solves and of the vector updates); by the
!!    energy identity of the scheme the balance E - W + D then moves by rho . (velocity of
!!    the identity) plus the rounding of the position update and of the running sums.
!!    `velocity_step_bound` and `position_step_bound` bound this, b_k, term by term.
!! 3. Many steps. The b_k bound errors of different sign whose signs come from rounding;
!!    modelled as independent with mean zero (the model of Higham & Mary, SIAM J. Sci.
!!    Comput. 41 (2019) A2815; measured: |sum| is 0.01 % to 3 % of sum |.| over 1e4 steps
!!    or more, up to 22 % over 300),
!!    the Azuma-Hoeffding inequality gives P(max_n |sum_{k<=n} eps_k| >= lambda
!!    sqrt(sum b_k^2)) <= 2 exp(-lambda^2/2): with lambda = 6 a false failure has
!!    probability 3e-8 per run. The worst case without that model, sum b_k, is reported
!!    beside it (`ledger%linear`).
module vibrobeam_roundoff_bounds
   use vibrobeam_kinds, only: dp, error_unit
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_matvec, band_solve
   use vibrobeam_contact_set, only: contact_set, contact_value, no_bound
   use vibrobeam_contact_projector, only: regime_band
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_velocity_stepper, only: velocity_stepper
   use vibrobeam_position_stepper, only: position_stepper
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene, abs_factor_times
   implicit none
   private
   public :: unit_roundoff, gamma_n, abs_band_times, abs_factor_times, energy_form_bound, stepper_energy_bound
   public :: energy_ledger, hoeffding_lambda, stepper_balance, balance_bounds, balance_bounds_at, abs_row

   real(dp), parameter :: unit_roundoff = epsilon(1.0_dp)/2   !! u
   real(dp), parameter :: hoeffding_lambda = 6                 !! 2 exp(-18) = 3e-8

   !> The round-off budget of a run, step by step (see 2. and 3. above).
   type :: energy_ledger
      real(dp) :: initial_energy_bound = 0    !! bound of the evaluation error of E^0
      real(dp) :: energy_bound = 0            !! of the last E^n
      real(dp) :: previous_energy_bound = 0   !! of E^{n-1}
      real(dp) :: step = 0                    !! b_k of the last step
      real(dp) :: impacts = 0                 !! how far below 0 round-off may put the last
                                              !! step's dissipated_impacts increment
      real(dp) :: numerical = 0               !! the same for dissipated_numerical
      real(dp) :: penetration = 0             !! position scheme, e = 0: how far U^{n+1} may lie
                                              !! inside an obstacle (round-off and the solver's
                                              !! admissibility threshold)
      real(dp) :: magnitude = 0               !! E + |W| + |D| at the last step (rounding of the balance)
      real(dp) :: previous_magnitude = 0, initial_magnitude = 0
      real(dp) :: sum_squares = 0             !! sum b_k^2
      real(dp) :: linear = 0                  !! sum b_k (worst case)
      real(dp), allocatable :: u_before(:), v_before(:), u_before_previous(:)
      real(dp), allocatable :: residual(:)    !! position scheme: bound of each row of rho, the
                                              !! residual of W U^{n+1} = rhs + dt^2 H^T r
      real(dp) :: work_before = 0, impacts_before = 0, damping_before = 0, numerical_before = 0
   contains
      procedure :: start => ledger_start
      procedure :: before_step => ledger_before_step
      procedure :: after_step => ledger_after_step
      procedure :: drift => ledger_drift
      procedure :: one_step => ledger_one_step
   end type energy_ledger

contains

   pure real(dp) function gamma_n(n)
      integer, intent(in) :: n
      gamma_n = n*unit_roundoff/(1 - n*unit_roundoff)
   end function gamma_n

   !> |A| |x| for a symmetric band matrix (plain loops: no BLAS in the bound).
   pure function abs_band_times(a, x) result(y)
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: x(:)
      real(dp) :: y(size(x))
      integer :: i, j
      y = 0
      do j = 1, a%n
         y(j) = y(j) + abs(a%lower(1, j)*x(j))
         do i = j + 1, min(a%n, j + a%kd)
            y(i) = y(i) + abs(a%lower(1 + i - j, j)*x(j))
            y(j) = y(j) + abs(a%lower(1 + i - j, j)*x(i))
         end do
      end do
   end function abs_band_times

   !> Bound of |fl(1/2 x^T A x) - 1/2 x^T A x| for the product dot(x, dsbmv(A, x)) (1.).
   function energy_form_bound(a, x) result(bound)
      type(symmetric_band), intent(in) :: a
      real(dp), intent(in) :: x(:)
      real(dp) :: bound, ax(size(x))
      call band_matvec(a, x, ax)
      bound = 0.5_dp*(gamma_n(2*a%kd + 1)*dot_product(abs(x), abs_band_times(a, x)) + &
                      gamma_n(size(x))*dot_product(abs(x), abs(ax)))
   end function energy_form_bound

   !> Bound of the evaluation error of kinetic_energy() + elastic_energy() of a stepper.
   !! The position scheme's kinetic part is 1/2 v^T (M + c K) v, c = (theta - 1/4) dt^2,
   !! computed from v = (U^n - U^{n-1})/dt and Ubar = (U^n + U^{n-1})/2, both rounded
   !! (gamma_2 relative per entry, hence 2 gamma_2 relative on each quadratic form).
   function stepper_energy_bound(stepper, energy) result(bound)
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: energy   !! kinetic_energy() + elastic_energy(), as evaluated
      real(dp) :: bound, c
      select type (stepper)
      type is (position_stepper)
         c = (stepper%theta - 0.25_dp)*stepper%dt**2
         bound = energy_form_bound(stepper%mass, stepper%v) + abs(c)*energy_form_bound(stepper%stiffness, stepper%v) &
                 + energy_form_bound(stepper%stiffness, 0.5_dp*(stepper%u + stepper%u_previous)) + 2*gamma_n(2)*abs(energy) &
                 + gamma_n(2)*0.5_dp*abs(c)*dot_product(abs(stepper%v), abs_band_times(stepper%stiffness, stepper%v))
      class default
         bound = energy_form_bound(stepper%mass, stepper%v) + energy_form_bound(stepper%stiffness, stepper%u)
      end select
      bound = bound + unit_roundoff*abs(energy)
   end function stepper_energy_bound

   subroutine ledger_start(self, stepper)
      class(energy_ledger), intent(out) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp) :: energy
      energy = stepper%kinetic_energy() + stepper%elastic_energy()
      self%initial_energy_bound = stepper_energy_bound(stepper, energy)
      self%energy_bound = self%initial_energy_bound
      self%previous_energy_bound = self%energy_bound
      self%initial_magnitude = magnitude_of(stepper, energy)
      self%magnitude = self%initial_magnitude
      self%previous_magnitude = self%magnitude
   end subroutine ledger_start

   !> Remember the state before a step.
   subroutine ledger_before_step(self, stepper)
      class(energy_ledger), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      self%u_before = stepper%u
      self%v_before = stepper%v
      select type (stepper)
      type is (position_stepper)
         self%u_before_previous = stepper%u_previous
      end select
      self%work_before = stepper%energy%work
      self%impacts_before = stepper%energy%dissipated_impacts
      self%damping_before = stepper%energy%dissipated_damping
      self%numerical_before = stepper%energy%dissipated_numerical
   end subroutine ledger_before_step

   !> Account for the step just taken: its bound b_k and the evaluation bound of the new E.
   subroutine ledger_after_step(self, stepper)
      class(energy_ledger), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp) :: energy
      self%impacts = 0
      self%numerical = 0
      select type (stepper)
      type is (velocity_stepper)
         call velocity_step_bound(stepper, self%u_before, self%v_before, self%step, self%impacts, self%numerical)
      type is (position_stepper)
         if (.not. allocated(self%residual)) allocate (self%residual(size(stepper%u)))
         call position_step_bound(stepper, self%u_before, self%u_before_previous, self%step, self%impacts, &
                                  self%penetration, self%residual)
      class default
         error stop 'energy_ledger: unknown scheme'
      end select
      ! rounding of the running sums (one addition each per step)
      self%step = self%step + unit_roundoff*(abs(stepper%energy%work) + abs(stepper%energy%dissipated_impacts) + &
                                             abs(stepper%energy%dissipated_damping) + abs(stepper%energy%dissipated_numerical))
      self%sum_squares = self%sum_squares + self%step**2
      self%linear = self%linear + self%step
      energy = stepper%kinetic_energy() + stepper%elastic_energy()
      self%previous_energy_bound = self%energy_bound
      self%energy_bound = stepper_energy_bound(stepper, energy)
      self%previous_magnitude = self%magnitude
      self%magnitude = magnitude_of(stepper, energy)
   end subroutine ledger_after_step

   !> The balance E - W + D_impacts + D_damping + D_numerical as the checks form it.
   real(dp) function stepper_balance(stepper)
      class(time_stepper), intent(in) :: stepper
      stepper_balance = stepper%kinetic_energy() + stepper%elastic_energy() - stepper%energy%work + &
                       stepper%energy%dissipated_impacts + stepper%energy%dissipated_damping + stepper%energy%dissipated_numerical
   end function stepper_balance

   !> E + |W| + |D_impacts| + |D_damping| + |D_numerical|: forming the balance (5 terms)
   !! costs at most gamma_5 times this.
   real(dp) function magnitude_of(stepper, energy)
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: energy   !! kinetic + elastic (both >= 0)
      magnitude_of = abs(energy) + abs(stepper%energy%work) + &
                     abs(stepper%energy%dissipated_impacts) + abs(stepper%energy%dissipated_damping) &
                        + abs(stepper%energy%dissipated_numerical)
   end function magnitude_of

   !> Bound of |balance^n - balance^0| (3.): the two evaluations (energies and the sum of
   !! five terms) plus the smaller of sum b_k and lambda sqrt(sum b_k^2).
   pure real(dp) function ledger_drift(self)
      class(energy_ledger), intent(in) :: self
      ledger_drift = self%initial_energy_bound + self%energy_bound + gamma_n(5)*(self%initial_magnitude + self%magnitude) &
                     + min(self%linear, hoeffding_lambda*sqrt(self%sum_squares))
   end function ledger_drift

   !> Bound of the round-off in the change of the balance over the last step (rigorous to
   !! first order: the two evaluations and b_k, no statistical model).
   pure real(dp) function ledger_one_step(self)
      class(energy_ledger), intent(in) :: self
      ledger_one_step = self%previous_energy_bound + self%energy_bound + &
                        gamma_n(5)*(self%previous_magnitude + self%magnitude) + self%step
   end function ledger_one_step

   !> The round-off bound of |balance^n - balance^0| after every step n = 0..steps of a run
   !! of `scene` (the drift bound plus the impacts' complementarity round-off summed, which
   !! the balance of a result file carries too): for checks of result files, whose run is
   !! repeated here step by step (the same computation, so the same states).
   subroutine balance_bounds(scene, prepared, steps, bounds, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      integer, intent(in) :: steps
      real(dp), intent(out) :: bounds(0:steps)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      class(time_stepper), allocatable :: stepper
      type(energy_ledger) :: ledger
      real(dp) :: impacts_total
      integer :: n
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) return
      call ledger%start(stepper)
      bounds(0) = 0
      impacts_total = 0
      do n = 1, steps
         call ledger%before_step(stepper)
         call stepper%step(stat, errmsg)
         if (stat /= 0) return
         call ledger%after_step(stepper)
         impacts_total = impacts_total + ledger%impacts
         bounds(n) = ledger%drift() + impacts_total
      end do
   end subroutine balance_bounds

   !> `balance_bounds` of the scene of namelist file `path`, at the output times `time` of
   !! a result file of that scene (the bound after step nint(t/dt)); stops the test if the
   !! scene cannot be read or run.
   function balance_bounds_at(path, time) result(bound)
      character(len=*), intent(in) :: path
      real(dp), intent(in) :: time(:)
      real(dp) :: bound(size(time))
      type(scene_type) :: scene
      type(run_problem) :: prepared
      real(dp), allocatable :: bounds(:)
      integer :: steps, j, stat
      character(len=512) :: errmsg
      scene = read_test_scene(path)
      call prepare_test_scene(scene, prepared)
      steps = nint(scene%time%t_end/scene%time%dt)
      allocate (bounds(0:steps))
      call balance_bounds(scene, prepared, steps, bounds, stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a)') 'FAIL repeating the run for its round-off bounds: '//trim(errmsg)
         error stop 1
      end if
      do j = 1, size(time)
         bound(j) = bounds(min(steps, max(0, nint(time(j)/scene%time%dt))))
      end do
   end function balance_bounds_at

   !> b_k of one step of the velocity scheme, from (U^n, V^n) to the stepper's state.
   !! The computed step satisfies W dV = dt r + H^T P + rho with (every |.| entrywise)
   !!   |rho| <= gamma_{2kd+5} dt (|F| + |K|(|U| + theta dt |V|) + |C||V|)      r and its terms
   !!          + gamma_{3kd+4} |L||L^T| (|x| + Y)            Cholesky solves of x and of W^-1 H^T
   !!          + gamma_{m+3} |W| (|V_free| + |V^{n+1}| + Y)   the vector additions
   !! (x = V_free - V^n, Y = sum_k |W^-1 H_k^T| |P_k|), in the 'band' regime instead of the
   !! column terms the saddle-point LU solve (kl = ku <= 2 kd + 2, growth allowed: 8) and
   !! the solver's clipping of round-off impulses (slack max(1e-12, 16 m eps) |P|max);
   !! the balance moves by V^{n+theta}.rho, plus (K U^{n+1}).(rounding of U^{n+1}) and the
   !! rounding of the work and dissipation increments.
   !! `impacts` bounds how negative the computed increment of dissipated_impacts may be:
   !! Newton's law makes -P_c H_c (V^{n+1} + V^n)/2 = -(1 - e_c)/2 P_c H_c V^n >= 0 exactly
   !! only if 0 = P_c H_c (V^{n+1} + e_c V^n); the computed V^{n+1} meets the held
   !! constraint to the residual of the solves (gamma_{3kd+4+m} (|H_c||V_free| + |H_c| Y))
   !! and the sum itself rounds (gamma_5). `numerical` bounds the rounding of the increment
   !! of dissipated_numerical, (theta - 1/2)(dV.M dV + dU.K dU - P.H dV).
   subroutine velocity_step_bound(s, u_old, v_old, bound, impacts, numerical)
      type(velocity_stepper), intent(in) :: s
      real(dp), intent(in) :: u_old(:), v_old(:)
      real(dp), intent(out) :: bound, impacts, numerical
      real(dp), dimension(size(u_old)) :: v_theta, a_theta, force, rhs, v_free, x, y, ku, cv, dv, du
      real(dp) :: slack, largest
      integer :: k, m, kd, n
      m = s%report%active_count
      kd = s%stiffness%kd
      n = size(u_old)
      associate (theta => s%theta, dt => s%dt, h => s%contacts)
         v_theta = theta*s%v + (1 - theta)*v_old
         a_theta = theta*abs(s%v) + (1 - theta)*abs(v_old)
         ! F^{n+theta} as the step used it (the loads, and a fluid-elastic force at V^n): the
         ! loads' `at` would recompute a random signal's block at every call
         force = s%force_theta
         ! V_free as the stepper computed it (for its size only)
         call band_matvec(s%stiffness, u_old + theta*dt*v_old, ku)
         rhs = force - ku
         cv = 0
         if (s%rayleigh_mass > 0 .or. s%rayleigh_stiffness > 0) rhs = rhs - s%damping_times(v_old)
         rhs = dt*rhs
         call band_solve(s%iteration_factor, rhs)
         x = rhs
         v_free = v_old + x
         y = responses(s%iteration_factor, s%contacts, s%report%active(1:m), s%report%impulse(1:m))
         if (s%rayleigh_mass > 0) cv = s%rayleigh_mass*abs_band_times(s%mass, abs(v_old))
         if (s%rayleigh_stiffness > 0) cv = cv + s%rayleigh_stiffness*abs_band_times(s%stiffness, abs(v_old))
         bound = gamma_n(2*kd + 5)*dt*dot_product(abs(v_theta), abs(force) + &
                    abs_band_times(s%stiffness, abs(u_old) + theta*dt*abs(v_old)) + cv)
         bound = bound + gamma_n(3*kd + 4)*dot_product(abs(v_theta), abs_factor_times(s%iteration_factor, abs(x) + y))
         bound = bound + gamma_n(m + 3)*dot_product(abs(v_theta), abs_band_times(s%iteration_matrix, &
                                                  abs(v_free) + abs(s%v) + y))
         if (m > 0 .and. s%projector%regime == regime_band) then
            ! saddle-point LU, bandwidth <= 2 kd + 2, a growth of up to 8 allowed for
            bound = bound + 8*gamma_n(3*(2*kd + 2) + 1 + 2*kd + 1)*dot_product(abs(v_theta), &
                       abs_band_times(s%iteration_matrix, abs(v_free) + abs(s%v)) + abs(rows_transpose(s, &
                          abs(s%report%impulse(1:m)))))
            slack = max(1e-12_dp, 16*m*epsilon(1.0_dp))
            largest = maxval(abs(s%report%impulse(1:m)))
            do k = 1, m
               bound = bound + slack*largest*abs(contact_value(s%contacts, s%report%active(k), v_theta))
            end do
         end if
         ! rounding of U^{n+1} = U^n + dt (theta V^{n+1} + (1 - theta) V^n): gamma_4 per entry
         call band_matvec(s%stiffness, s%u, ku)
         bound = bound + gamma_n(4)*dot_product(abs(ku), abs(u_old) + dt*a_theta)
         ! the increments of the running sums
         du = s%u - u_old
         dv = s%v - v_old
         bound = bound + gamma_n(n + 2)*dot_product(abs(force), abs(du))
         impacts = 0
         do k = 1, m
            impacts = impacts + gamma_n(5)*abs(s%report%impulse(k))*(abs_row(h, s%report%active(k), s%v) + abs_row(h, &
               s%report%active(k), v_old)) &
                      + gamma_n(3*kd + 4 + m)*abs(s%report%impulse(k))*(abs_row(h, s%report%active(k), &
                         v_free) + abs_row(h, s%report%active(k), y) &
                                                               + abs_row(h, s%report%active(k), s%v))
         end do
         if (m > 0 .and. s%projector%regime == regime_band) impacts = impacts + &
            8*gamma_n(3*(2*kd + 2) + 1 + 2*kd + 1)*sum(abs(s%report%impulse(1:m))*[(abs_row(h, s%report%active(k), v_free) + &
            abs_row(h, s%report%active(k), s%v), k=1, m)])
         bound = bound + impacts
         if (s%rayleigh_mass > 0 .or. s%rayleigh_stiffness > 0) then
            cv = 0
            if (s%rayleigh_mass > 0) cv = s%rayleigh_mass*abs_band_times(s%mass, abs(v_theta))
            if (s%rayleigh_stiffness > 0) cv = cv + s%rayleigh_stiffness*abs_band_times(s%stiffness, abs(v_theta))
            bound = bound + gamma_n(2*kd + n + 4)*dt*dot_product(abs(v_theta), cv)
         end if
         numerical = 0
         if (abs(theta - 0.5_dp) > 0) then
            numerical = (theta - 0.5_dp)*(gamma_n(2*kd + n + 3)*(dot_product(abs(dv), abs_band_times(s%mass, abs(dv))) &
                        + dot_product(abs(du), abs_band_times(s%stiffness, abs(du)))) &
                        + gamma_n(5 + m)*sum(abs(s%report%impulse(1:m))*[(abs_row(h, s%report%active(k), s%v) + &
                                                                 abs_row(h, s%report%active(k), v_old), k=1, m)]))
         end if
         bound = bound + numerical
      end associate
   end subroutine velocity_step_bound

   !> b_k of one step of the position scheme, from (U^n, U^{n-1}) to the stepper's state.
   !! The computed U^{n+1} satisfies W U^{n+1} = rhs + dt^2 H^T r + rho with
   !!   |rho| <= gamma_{2kd+5} (|M|(2|U^n| + |U^{n-1}|) + dt^2 |K|(|1 - 2 theta||U^n| + theta|U^{n-1}|)
   !!                           + dt^2 |F| + dt/2 |C||U^{n-1}|)                      the right-hand side
   !!          + gamma_{3kd+4} |L||L^T| (|U_free| + (1 + e) Y)                        the solves
   !!          + gamma_{m+7} |W| (|U_free| + 2 e |U^{n-1}| + (1 + e)(|Z| + Y))        the additions
   !! (Y = sum_c |W^-1 H_c^T| |multiplier_c|, Z the projected average), with the 'band'
   !! regime terms of `velocity_step_bound`; the scheme's energy identity is its equation
   !! times (U^{n+1} - U^{n-1})/(2 dt^2), so the balance moves by that times rho.
   !! `penetration`: a held point meets its level to the residual of the solves,
   !! gamma_{3kd+m+11} (|H_c||U_free| + (1 + e)|H_c| Y + |H_c||U^{n+1}| + |g_c|), and a point
   !! is only made a candidate when the projection finds it inside by more than 1e-12 of
   !! max(|Z_free|, |levels|) (`project_admissible`); with e = 0, U^{n+1} = Z.
   !! `impacts` (e = 0): -r_c H_c (U^{n+1} - U^{n-1})/2 >= 0 because H_c U^{n+1} = g_c and
   !! U^{n-1} is admissible; each of the two holds to `penetration`, and the sum rounds.
   subroutine position_step_bound(s, u_old, u_older, bound, impacts, penetration, residual)
      type(position_stepper), intent(in) :: s
      real(dp), intent(in) :: u_old(:), u_older(:)   !! U^n, U^{n-1}
      real(dp), intent(out) :: bound, impacts, penetration
      real(dp), intent(out) :: residual(:)           !! the bound of |rho| row by row
      real(dp), dimension(size(u_old)) :: stride, rhs, u_free, y, column, z, cu, force
      real(dp) :: e, slack, largest, rho, level_scale, held
      integer :: kd, n, c, m
      kd = s%stiffness%kd
      n = size(u_old)
      e = s%restitution
      associate (theta => s%theta, dt => s%dt, h => s%contacts)
         stride = s%u - u_older
         force = s%loads%at(s%t - dt)
         ! U_free as the stepper computed it (for its size only)
         call band_matvec(s%mass, 2*u_old - u_older, rhs)
         call band_matvec(s%stiffness, (1 - 2*theta)*u_old + theta*u_older, column)
         rhs = rhs - dt**2*column + dt**2*force
         if (s%rayleigh_mass > 0 .or. s%rayleigh_stiffness > 0) rhs = rhs + 0.5_dp*dt*s%damping_times(u_older)
         call band_solve(s%iteration_factor, rhs)
         u_free = rhs
         z = (s%u + e*u_older)/(1 + e)
         m = count(abs(s%multiplier) > 0)
         y = responses(s%iteration_factor, s%contacts, pack([(c, c=1, s%contacts%count)], abs(s%multiplier) > 0), &
                       pack(s%multiplier, abs(s%multiplier) > 0))
         cu = 0
         if (s%rayleigh_mass > 0) cu = s%rayleigh_mass*abs_band_times(s%mass, abs(u_older))
         if (s%rayleigh_stiffness > 0) cu = cu + s%rayleigh_stiffness*abs_band_times(s%stiffness, abs(u_older))
         residual = gamma_n(2*kd + 5)*(abs_band_times(s%mass, 2*abs(u_old) + abs(u_older)) &
                    + dt**2*abs_band_times(s%stiffness, abs(1 - 2*theta)*abs(u_old) + theta*abs(u_older)) &
                    + dt**2*abs(force) + 0.5_dp*dt*cu)
         residual = residual + gamma_n(3*kd + 4)*abs_factor_times(s%iteration_factor, abs(u_free) + (1 + e)*y)
         residual = residual + gamma_n(m + 7)*abs_band_times(s%iteration_matrix, &
                                                             abs(u_free) + 2*e*abs(u_older) + (1 + e)*(abs(z) + y))
         if (m > 0 .and. s%projector%regime == regime_band) then
            residual = residual + 8*gamma_n(3*(2*kd + 2) + 1 + 2*kd + 1)*(abs_band_times(s%iteration_matrix, &
                          abs(u_free) + abs(z)) + (1 + e)*abs(all_rows_transpose(s)))
         end if
         rho = dot_product(abs(stride), residual)
         if (m > 0 .and. s%projector%regime == regime_band) then
            slack = max(1e-12_dp, 16*m*epsilon(1.0_dp))
            largest = maxval(abs(s%multiplier))
            do c = 1, s%contacts%count
               if (abs(s%multiplier(c)) > 0) &
                  rho = rho + (1 + e)*slack*largest*abs(contact_value(s%contacts, c, stride))
            end do
         end if
         bound = rho/(2*dt**2)
         ! held constraints and the admissibility threshold
         level_scale = maxval(abs((u_free + e*u_older)/(1 + e)))
         do c = 1, s%contacts%count
            if (s%contacts%lower(c) > -no_bound) level_scale = max(level_scale, abs(s%contacts%lower(c)))
            if (s%contacts%upper(c) < no_bound) level_scale = max(level_scale, abs(s%contacts%upper(c)))
         end do
         penetration = 1e-12_dp*level_scale
         impacts = 0
         do c = 1, s%contacts%count
            if (abs(s%multiplier(c)) <= 0) cycle
            held = gamma_n(3*kd + m + 11)*(abs_row(h, c, u_free) + (1 + e)*abs_row(h, c, y) + abs_row(h, c, s%u) + &
                                         abs(merge(s%contacts%lower(c), s%contacts%upper(c), s%multiplier(c) > 0)))
            penetration = max(penetration, 1e-12_dp*level_scale + held)
         end do
         do c = 1, s%contacts%count
            if (abs(s%multiplier(c)) <= 0) cycle
            impacts = impacts + 0.5_dp*(1 + e)*abs(s%multiplier(c))/dt**2*(2*penetration + gamma_n(8)*abs_row(h, c, stride))
         end do
         ! the increments of the running sums: work F.stride/2, impacts r.H stride/2, damping
         bound = bound + gamma_n(n + 2)*0.5_dp*dot_product(abs(force), abs(stride))
         do c = 1, s%contacts%count
            if (abs(s%multiplier(c)) > 0) bound = bound + gamma_n(8)*0.5_dp*(1 + e)*abs(s%multiplier(c))/dt**2* &
                                                  abs_row(h, c, stride)
         end do
         if (s%rayleigh_mass > 0 .or. s%rayleigh_stiffness > 0) then
            cu = 0
            if (s%rayleigh_mass > 0) cu = s%rayleigh_mass*abs_band_times(s%mass, abs(stride))
            if (s%rayleigh_stiffness > 0) cu = cu + s%rayleigh_stiffness*abs_band_times(s%stiffness, abs(stride))
            bound = bound + gamma_n(2*kd + n + 5)*dot_product(abs(stride), cu)/(4*dt)
         end if
      end associate
   contains
      function all_rows_transpose(s) result(h)
         type(position_stepper), intent(in) :: s
         real(dp) :: h(size(s%u))
         integer :: a, c
         h = 0
         do c = 1, s%contacts%count
            do a = 1, 4
               if (s%contacts%dofs(a, c) /= 0) h(s%contacts%dofs(a, c)) = h(s%contacts%dofs(a, c)) + &
                  abs(s%contacts%weights(a, c)*s%multiplier(c))
            end do
         end do
      end function all_rows_transpose
   end subroutine position_step_bound

   !> Y = sum_k |W^-1 H_{c_k}^T| |P_k|: the size of the terms of the projection's
   !! correction W^-1 H^T P, one band solve per point (as the projector's own columns).
   function responses(factor, contacts, points, impulses) result(y)
      type(band_cholesky), intent(in) :: factor
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: impulses(:)
      real(dp) :: y(factor%n), column(factor%n)
      integer :: k, a
      y = 0
      do k = 1, size(points)
         column = 0
         do a = 1, 4
            if (contacts%dofs(a, points(k)) /= 0) column(contacts%dofs(a, points(k))) = contacts%weights(a, points(k))
         end do
         call band_solve(factor, column)
         y = y + abs(column*impulses(k))
      end do
   end function responses

   !> |H_c| |x|: the size of the terms of H_c x.
   pure real(dp) function abs_row(contacts, c, x)
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: c
      real(dp), intent(in) :: x(:)
      integer :: a
      abs_row = 0
      do a = 1, 4
         if (contacts%dofs(a, c) /= 0) abs_row = abs_row + abs(contacts%weights(a, c)*x(contacts%dofs(a, c)))
      end do
   end function abs_row

   !> |H|^T |P| over the active points of a velocity step.
   function rows_transpose(s, p) result(h)
      type(velocity_stepper), intent(in) :: s
      real(dp), intent(in) :: p(:)
      real(dp) :: h(size(s%u))
      integer :: a, k, c
      h = 0
      do k = 1, size(p)
         c = s%report%active(k)
         do a = 1, 4
            if (s%contacts%dofs(a, c) /= 0) h(s%contacts%dofs(a, c)) = h(s%contacts%dofs(a, c)) + &
               abs(s%contacts%weights(a, c))*p(k)
         end do
      end do
   end function rows_transpose
end module vibrobeam_roundoff_bounds
