!> Verification of compliant stops (docs/theory.md section 8).
!!
!! usage: test_compliant static STATIC_TIP.nml
!!   A cantilever under a uniform load q whose tip rests on a spring k at gap g has the tip
!!   reaction R = (q L^4/(8EI) - g) / (L^3/(3EI) + 1/k) (superposition of the clamped-free
!!   deflections of q and of the tip force; Hermite elements with a consistent load vector
!!   are exact at the nodes). Checked for k = 1e2 .. 1e10 N/m and N = 1, 2, 4, 8 to
!!   1e-10 relative; the derived round-off bound (below) must itself be below 1e-10. Then
!!   R -> R_rigid = 3EI(qL^4/(8EI) - g)/L^3 as k -> infinity: exactly,
!!   R_rigid - R = R_rigid / (1 + k L^3/(3EI)), so the fitted slope of log(R_rigid - R)
!!   against log k must be -1 (within 0.02 over k = 1e6 .. 1e9).
!!   Round-off: the solver's derived bound of the reaction (`static_report`: the spring is
!!   an elastic support of the moment equations, src/model/vibrobeam_support_moments.f90),
!!   Newton's acceptance of the spring law (1024 eps of the force) and the closed form's
!!   rounding (gamma_12); the check uses 1e-10 or that bound if larger, and asserts the
!!   bound below 1e-10 for k <= 1e8 and N <= 4 (the stiffest springs cancel in p = R/k).
!!
!! usage: test_compliant energy SCENE.nml
!!   No load, no damping, theta = 1/2, the 'gradient' rule: the discrete energy
!!   E = 1/2 V^T M V + 1/2 U^T K U + sum_j Phi_j(p_j) stays constant at every step to its
!!   round-off bound: the beam's per-step bound of `vibrobeam_roundoff_bounds` (the free
!!   step and rigid impulses) plus, per step and spring, the terms the springs add:
!!   - the Newton acceptance: |f_applied - f(p)| <= 1024 eps max_j f_j, times |dp_j|;
!!   - the discrete gradient's rounding: gamma_8 (Phi_j(p^n) + Phi_j(p^{n+1})) + the
!!     midpoint replacement's a|a-1| k p^(a-1) |dp|^3 / 24 when |dp| <= 1e-5 |p|;
!!   - the penetrations' rounding, gamma_6 (|g_j| + |H_j| |U^n| + |H_j| |U^{n+1}|), times f_j;
!!   - the solve with J = W + dt^2 theta sum d_j H^T H: gamma_{3kd+4} |V^{n+1/2}|^T |L||D||L^T|
!!     |V^{n+1} - V_free| (the last correction bounded by the whole one) and
!!     gamma_{2kd+5} |V^{n+1/2}|^T (|W| (|V_free| + 2|V^{n+1}|) + dt sum_j f_j |H_j^T|);
!!   combined like the ledger's b_k (min of the sum and 6 sqrt(sum of squares)), plus
!!   gamma_4 of the potential at both ends. Also checks that the run engages every spring
!!   and that the rigid stop is hit, and prints the same measurement for the 'mean' rule.
!!
!! usage: test_compliant balance SCENE.nml
!!   theta = 1 and 0.75 (both rules): the balance B = E - W + D (E with the stops'
!!   potential, D with dissipated_numerical and the contact damping, as /energy/balance
!!   forms it) stays constant at every step to its round-off bound (docs/theory.md section 8,
!!   "Energy"): the ledger's bound for the beam (`vibrobeam_roundoff_bounds`, theta-terms
!!   included) plus the springs' terms above with V^{n+1/2} replaced by V^{n+theta} (the
!!   velocity the identity is dotted with), the rounding of the springs' booking
!!   gamma_{m+3} sum_j (|f_j| + 2|elastic_j|)|dp_j| + u |D_c| per step, and gamma_8 of the
!!   potential and of D_c where the balance is formed. Until issue 23 the theta-term
!!   counted the springs' impulses (theta - 1/2) sum_j dt s_j f_j H_j dV although their
!!   work was booked whole: the balance drifted by 1.3 % of the energy in 0.6 s.
program test_compliant
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_compliant_law, only: stop_potential
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_add, band_factor, band_matvec, band_solve
   use vibrobeam_roundoff_bounds, only: gamma_n, energy_ledger, abs_band_times, hoeffding_lambda, abs_row, unit_roundoff, &
                                        stepper_balance
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, abs_factor_times
   implicit none
   type(test_counter) :: t
   character(len=512) :: mode, path
   call get_command_argument(1, mode)
   call get_command_argument(2, path)
   select case (mode)
   case ('static')
      call static_checks()
   case ('energy')
      call energy_checks()
   case ('balance')
      call balance_checks()
   case default
      error stop 'usage: test_compliant static|energy|balance SCENE.nml'
   end select
   call t%finish('test_compliant')

contains

   subroutine static_checks()
      type(scene_type) :: scene
      type(run_problem) :: prepared
      real(dp), parameter :: stiffnesses(9) = [1e2_dp, 1e3_dp, 1e4_dp, 1e5_dp, 1e6_dp, 1e7_dp, 1e8_dp, 1e9_dp, 1e10_dp]
      integer, parameter :: meshes(4) = [1, 2, 4, 8]
      real(dp), allocatable :: u(:), reaction(:)
      real(dp) :: q, g, ei, length, exact, rigid, bound, error, x(4), y(4), slope
      type(static_report) :: report
      integer :: i, k, iterations, stat, fit
      character(len=256) :: errmsg
      character(len=80) :: label
      scene = read_test_scene(trim(path))
      q = -scene%load%distributed
      g = -scene%obstacles(1)%level_from
      ei = scene%beam%ei()
      length = scene%beam%length
      rigid = 3*ei*(q*length**4/(8*ei) - g)/length**3
      fit = 0
      do i = 1, size(meshes)
         scene%mesh%elements = meshes(i)
         do k = 1, size(stiffnesses)
            scene%obstacles(1)%stiffness = stiffnesses(k)
            call prepare_test_scene(scene, prepared)
            allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count))
            call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u, reaction, iterations, &
                              stat, errmsg, report=report)
            if (stat /= 0) error stop 'static solve failed'
            exact = (q*length**4/(8*ei) - g)/(length**3/(3*ei) + 1/stiffnesses(k))
            ! derived bound of the relative error of R: the solver's (`static_report`), Newton's
            ! acceptance of the spring law (1024 eps of the force) and the closed form's rounding
            bound = (report%reaction_bound(1) + 1024*epsilon(1.0_dp)*abs(reaction(1)))/abs(exact) + gamma_n(12)
            error = abs(reaction(1) - exact)/abs(exact)
            write (output_unit, '(a,i2,a,es8.1,a,es22.14,a,es9.2,a,es9.2)') 'N = ', meshes(i), ', k = ', &
               stiffnesses(k), ': R = ', reaction(1), ', relative error ', error, ', bound ', bound
            write (label, '(a,i0,a,es8.1)') 'tip reaction on a spring, N = ', meshes(i), ', k = ', stiffnesses(k)
            ! 1e-10 relative where the round-off bound allows it; beyond (a stiff spring: R = k p
            ! with p = -g - u cancelling) the derived bound itself
            call t%check_close(trim(label), reaction(1), exact, max(1e-10_dp, bound))
            if (stiffnesses(k) <= 1e8_dp .and. meshes(i) <= 4) &
               call t%check_true(trim(label)//': round-off bound below 1e-10', bound < 1e-10_dp)
            if (i == size(meshes) .and. k >= 5 .and. k <= 8) then
               fit = fit + 1
               x(fit) = log(stiffnesses(k))
               y(fit) = log(abs(rigid - reaction(1)))
            end if
            deallocate (u, reaction)
         end do
      end do
      slope = (4*sum(x*y) - sum(x)*sum(y))/(4*sum(x**2) - sum(x)**2)
      write (output_unit, '(a,f8.4,a)') 'rigid limit: R_rigid - R ~ k^', slope, ' (exact: k^-1)'
      call t%check_close('rate of R -> R_rigid', slope, -1.0_dp, 0.02_dp)
   end subroutine static_checks

   subroutine energy_checks()
      type(scene_type) :: scene
      type(run_problem) :: prepared
      real(dp) :: drift(2), bound(2), ratio(2), balance_drift, balance_ratio, numerical
      logical :: engaged(2), rigid_hit(2), damped
      integer :: r
      character(len=8), parameter :: rules(2) = [character(len=8) :: 'gradient', 'mean']
      scene = read_test_scene(trim(path))
      call prepare_test_scene(scene, prepared)
      do r = 1, 2
         scene%time%compliant_rule = rules(r)
         call run(scene, prepared, drift(r), bound(r), ratio(r), engaged(r), rigid_hit(r), balance_drift, &
                  balance_ratio, numerical, damped)
         write (output_unit, '(a,a8,a,es10.3,a,es10.3,a,es10.3)') 'rule ', rules(r), ': max |E^n - E^0| = ', &
            drift(r), ' J, final round-off bound ', bound(r), ' J, largest |E^n - E^0|/bound_n ', ratio(r)
      end do
      call t%check_true('every spring engaged', engaged(1))
      call t%check_true('the rigid stop is hit', rigid_hit(1))
      call t%check_true('gradient rule: |E^n - E^0| <= round-off bound at every step', ratio(1) <= 1)
      call t%check_true('mean rule: energy not conserved (engagement steps), so the test can fail', ratio(2) > 1)
   end subroutine energy_checks

   !> One run of `scene`, step by step with its round-off bounds. The energy E (with the
   !! stops' potential): its largest |E^n - E^0| (J), the final bound and the largest
   !! |E^n - E^0|/bound_n; the balance B (`full_balance`): the same for |B^n - B^0| (the
   !! bound adds the rounding of the potential and of D_c where B is formed). Also whether
   !! every spring was engaged and the rigid stop hit, the final dissipated_numerical and
   !! whether the contact damping took energy.
   subroutine run(scene, prepared, drift, bound, ratio, engaged, rigid_hit, balance_drift, balance_ratio, &
                  numerical, damped)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      real(dp), intent(out) :: drift, bound, ratio, balance_drift, balance_ratio, numerical
      logical, intent(out) :: engaged, rigid_hit, damped
      class(time_stepper), allocatable :: s
      type(energy_ledger) :: ledger
      real(dp), allocatable :: u0(:), v0(:), p0(:), p1(:)
      real(dp) :: e0, b0, energy, balance, spring_step, linear, squares, potential_bound, ends_bound
      logical, allocatable :: seen(:)
      integer :: n, steps, stat
      character(len=256) :: errmsg
      call new_stepper(scene, prepared, s, stat, errmsg)
      if (stat /= 0) error stop 'cannot start the stepper'
      steps = nint(scene%time%t_end/scene%time%dt)
      associate (springs => s%contacts%springs)
         allocate (seen(springs%count), source=.false.)
         e0 = s%kinetic_energy() + s%elastic_energy() + s%contact_potential()
         b0 = full_balance(s)
         call ledger%start(s)
         drift = 0
         ratio = 0
         balance_drift = 0
         balance_ratio = 0
         linear = 0
         squares = 0
         rigid_hit = .false.
         potential_bound = gamma_n(4)*s%contact_potential()
         ends_bound = gamma_n(8)*(s%contact_potential() + abs(s%energy%dissipated_contact_damping))
         do n = 1, steps
            u0 = s%u
            v0 = s%v
            p0 = s%spring_penetrations(u0)
            call ledger%before_step(s)
            call s%step(stat, errmsg)
            if (stat /= 0) error stop 'step failed'
            call ledger%after_step(s)
            if (s%report%active_count > 0) rigid_hit = rigid_hit .or. any(abs(s%report%impulse(1:s%report%active_count)) > 0)
            p1 = s%spring_penetrations(s%u)
            seen = seen .or. p1 > 0
            spring_step = spring_step_bound(s, u0, v0, p0, p1)
            linear = linear + spring_step
            squares = squares + spring_step**2
            energy = s%kinetic_energy() + s%elastic_energy() + s%contact_potential()
            bound = ledger%drift() + min(linear, hoeffding_lambda*sqrt(squares)) + potential_bound + &
                    gamma_n(4)*s%contact_potential()
            ! drift: the largest |E^n - E^0| over the run; ratio: the largest |E^n - E^0|/bound_n
            drift = max(drift, abs(energy - e0))
            ratio = max(ratio, abs(energy - e0)/bound)
            ! the balance: the same bound (the ledger's drift covers the beam, the theta-terms
            ! and the five-term sum at both ends), plus the potential and D_c at both ends
            balance = full_balance(s)
            balance_drift = max(balance_drift, abs(balance - b0))
            balance_ratio = max(balance_ratio, abs(balance - b0)/(bound + ends_bound + &
                                gamma_n(8)*(s%contact_potential() + abs(s%energy%dissipated_contact_damping))))
         end do
         engaged = all(seen)
         numerical = s%energy%dissipated_numerical
         damped = s%energy%dissipated_contact_damping > 0
      end associate
   end subroutine run

   !> The springs' terms of the round-off bound of one velocity step from (U^n, V^n) = (u0,
   !! v0) to the stepper's state, p0 and p1 the penetrations at both ends (module comment):
   !! the identity of the step is dotted with V^{n+theta}. The scene has no load and no
   !! Rayleigh damping (V_free below, for its size, leaves them out).
   function spring_step_bound(s, u0, v0, p0, p1) result(bound)
      class(time_stepper), intent(in) :: s
      real(dp), intent(in) :: u0(:), v0(:), p0(:), p1(:)
      real(dp) :: bound, fmax
      real(dp), dimension(size(u0)) :: v_theta, v_free, work, hrow
      integer :: j, kd
      associate (springs => s%contacts%springs, c => s%compliant)
         kd = s%stiffness%kd
         fmax = maxval(abs(c%force))
         v_theta = s%theta*s%v + (1 - s%theta)*v0
         ! V_free as the stepper computed it, for its size
         call band_matvec(s%stiffness, u0 + s%theta*s%dt*v0, work)
         work = -s%dt*work
         call band_solve(s%iteration_factor, work)
         v_free = v0 + work
         bound = 0
         hrow = 0
         do j = 1, springs%count
            bound = bound + 1024*epsilon(1.0_dp)*fmax*abs(p1(j) - p0(j)) &
               + gamma_n(8)*(stop_potential(springs%stiffness(j), springs%exponent(j), p0(j)) + &
                             stop_potential(springs%stiffness(j), springs%exponent(j), p1(j))) &
               + springs%exponent(j)*abs(springs%exponent(j) - 1)*springs%stiffness(j)* &
                 max(p0(j), p1(j), 0.0_dp)**(springs%exponent(j) - 1)*abs(p1(j) - p0(j))**3/24 &
               + gamma_n(6)*abs(c%force(j))*(abs(springs%level(j)) + &
                 abs_row(s%contacts, springs%point(j), u0) + abs_row(s%contacts, springs%point(j), s%u)) &
               + gamma_n(springs%count + 3)*(abs(c%force(j)) + 2*abs(c%elastic(j)))*abs(p1(j) - p0(j))
            call add_abs_row(s%contacts, hrow, springs%point(j), s%dt*abs(c%force(j)))
         end do
         bound = bound + unit_roundoff*abs(s%energy%dissipated_contact_damping)
         if (any(abs(c%force) > 0)) then
            bound = bound + gamma_n(3*kd + 4)*dot_product(abs(v_theta), &
               abs_factor_times(c%jacobian_factor, abs(s%v - v_free))) &
               + gamma_n(2*kd + 5)*dot_product(abs(v_theta), abs_band_times(s%iteration_matrix, &
               abs(v_free) + 2*abs(s%v)) + hrow)
         end if
      end associate
   end function spring_step_bound

   !> theta = 1 and 0.75, both rules: the balance stays constant to its bound at every step.
   subroutine balance_checks()
      type(scene_type) :: scene
      type(run_problem) :: prepared
      real(dp), parameter :: thetas(2) = [1.0_dp, 0.75_dp]
      character(len=8), parameter :: rules(2) = [character(len=8) :: 'gradient', 'mean']
      real(dp) :: drift, ratio, numerical, energy_drift, energy_ratio, bound
      logical :: rigid_hit, damped, engaged
      integer :: i, r
      character(len=80) :: label
      scene = read_test_scene(trim(path))
      if (abs(scene%load%distributed) + abs(scene%load%point_force) + abs(scene%load%base_amplitude) + &
          abs(scene%load%base_acceleration) + scene%beam%rayleigh_mass + scene%beam%rayleigh_stiffness > 0) &
         error stop 'test_compliant balance: the scene must have no load and no Rayleigh damping'
      do i = 1, size(thetas)
         do r = 1, size(rules)
            scene%time%theta = thetas(i)
            scene%time%compliant_rule = rules(r)
            call prepare_test_scene(scene, prepared)
            call run(scene, prepared, energy_drift, bound, energy_ratio, engaged, rigid_hit, drift, ratio, &
                     numerical, damped)
            write (output_unit, '(a,f5.2,a,a8,a,es10.3,a,es10.3,a,es10.3,a)') 'theta = ', thetas(i), ', rule ', &
               rules(r), ': max |B^n - B^0| = ', drift, ' J, largest |B^n - B^0|/bound_n ', ratio, &
               ', dissipated_numerical ', numerical, ' J'
            write (label, '(a,f5.2,a,a)') 'theta = ', thetas(i), ', rule ', trim(rules(r))
            call t%check_true(trim(label)//': |B^n - B^0| <= round-off bound at every step', ratio <= 1)
            call t%check_true(trim(label)//': the rigid stop is hit and the damped spring dissipates', &
                              rigid_hit .and. damped)
         end do
      end do
   end subroutine balance_checks

   !> B = E - W + D as /energy/balance forms it (E with the stops' potential, D with the
   !! contact damping).
   real(dp) function full_balance(s)
      class(time_stepper), intent(in) :: s
      full_balance = stepper_balance(s) + s%contact_potential() + s%energy%dissipated_contact_damping
   end function full_balance

   subroutine add_abs_row(contacts, y, c, w)
      type(contact_set), intent(in) :: contacts
      real(dp), intent(inout) :: y(:)
      integer, intent(in) :: c
      real(dp), intent(in) :: w
      integer :: a
      do a = 1, 4
         if (contacts%dofs(a, c) /= 0) y(contacts%dofs(a, c)) = y(contacts%dofs(a, c)) + w*abs(contacts%weights(a, c))
      end do
   end subroutine add_abs_row
end program test_compliant
