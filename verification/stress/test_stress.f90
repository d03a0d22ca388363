!> Stress scenes of the contact projection (issue 10): runs a scene step by step with the
!! velocity scheme (theta = 1/2, the scene's contact solver) and checks after every step
!!
!! 1. the step succeeded and the contact solver did not need its fall-back;
!! 2. consistency: the step equations hold to round-off,
!!        rho = M dV + dt K Ubar - dt Fbar - H^T P,   |rho_i| <= 2 gamma_12 S_i,
!!    dV = V^{n+1} - V^n, Ubar = (U^{n+1} + U^n)/2, Fbar = (F(t_n) + F(t_{n+1}))/2,
!!    S = |L||L^T||V_f - V^n| + |W|(|V_f| + |V^{n+1}|) + |H^T||P| + dt|Fbar|
!!        + dt|K|(|U^n| + dt/2 |V^n|) + |M||dV| + dt|K||Ubar|
!!    (the free solve's backward error, Higham Thm 10.4 for the band Cholesky factor
!!    L L^T = W, and the evaluation of its right-hand side; the projection's residual
!!    W V^{n+1} - W V_f - H^T P; the test's own evaluation of rho; V_f = V^{n+1} -
!!    W^-1 H^T P, used only inside this scale; n = 3 kd + 3 = 12 terms at most per row);
!! 3. complementarity: sum_k |P_k| |H_k V^{n+1} - b_k| <= C = 80 eps s (sum_k |P_k| +
!!    m max|P|), s the largest |H_k V_f|, |H_k V^{n+1}|, |b_k| of the step (the solver's
!!    own scale), b_k = -e_k H_k V^n (a
!!    held point meets its bound to the round-off of H x and of the refined solve, at
!!    most 64 eps s; after an interior-point finish y_k s_k <= 16 eps max|P| s);
!! 4. the active constraints s_k (H_k V^{n+1} - b_k) >= -(64 + 2 cond(W)) eps s: the
!!    solver's tolerance for a free point (gap_factor = 64, plus twice its refinement
!!    estimate of the solve's error, at most cond(W) eps s; cond(W) by LAPACK dpbcon);
!! 5. energy: E = 1/2 V^T M V + 1/2 U^T K U never rises by more than a derived round-off
!!    bound beyond the work of the loads. For theta = 1/2 the step equations give exactly
!!        dE - Fbar.dU = P^T H Vbar + Vbar^T rho + (K Ubar - Fbar)^T dU_err,
!!        P^T H Vbar = 1/2 sum_k P_k (H_k V^{n+1} - b_k) + 1/2 sum_k (1 - e_k) P_k H_k V^n,
!!    dU_err the rounding of U^{n+1} = U^n + dt Vbar (at most eps |U^{n+1}|). The last sum
!!    is <= 0 (e_k < 1 only on approaching points, where s_k H_k V^n <= 0 <= s_k P_k), so
!!        rise = dE - Fbar.dU <= B = C/2 + 2 gamma_12 |Vbar|^T S + eps |K Ubar - Fbar|^T |U^{n+1}|
!!                                 + gamma_9 (|Vbar|^T |M| |dV| + |Ubar|^T |K| |dU|) + gamma_J |Fbar|^T |dU|,
!!    the last two terms the test's evaluation of dE = Vbar^T M dV + Ubar^T K dU (the
!!    difference form: E^{n+1} - E^n evaluated as two energies carries the rounding of
!!    U^T K U, eps |U|^T |K| |U|, which grows like N^4 relative to E for a smooth U and
!!    is reported beside, not asserted).
!!
!! usage: test_stress SCENE.nml [ELEMENTS]
!!        test_stress SCENE.nml static N_REFERENCE N_CHECK
!! The static form compares `solve_static` (in curvatures, docs/method.md "Statics") with
!! the dense LCP of the explicitly formed Delassus matrix H K^-1 H^T (dense Cholesky of K,
!! `solve_lcp`) at
!! N_REFERENCE elements, to 1e-10 and to the derived tolerance 4 (J + m) eps cond(K),
!! and checks the equilibrium K u - F = H^T R, the signs, bounds and complementarity at
!! N_CHECK.
program test_stress
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_velocity_stepper, only: velocity_stepper
   use vibrobeam_band, only: symmetric_band, band_matvec, band_solve
   use vibrobeam_contact_set, only: contact_set, contact_value, no_bound
   use vibrobeam_static, only: solve_static
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, band_abs_times, band_condition, &
                                     dense_lcp_reference, abs_factor_times
   implicit none


   type(test_counter) :: t
   type(scene_type) :: scene
   character(len=512) :: path, argument
   integer :: reference_elements, check_elements

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call get_command_argument(2, argument)
   if (argument == 'static') then
      call get_command_argument(3, argument)
      read (argument, *) reference_elements
      call get_command_argument(4, argument)
      read (argument, *) check_elements
      call static_checks(scene, reference_elements, check_elements)
   else
      if (len_trim(argument) > 0) read (argument, *) scene%mesh%elements
      call dynamic_checks(scene)
   end if
   call t%finish('test_stress')

contains

   real(dp) pure function rounding_gamma(n)
      integer, intent(in) :: n
      rounding_gamma = n*epsilon(1.0_dp)/(1 - n*epsilon(1.0_dp))
   end function rounding_gamma


   !> sum_k H_k^T value(k) over the active points (absolute values if `absolute`).
   function rows_transpose(contacts, active, value, absolute, n) result(v)
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: active(:)
      real(dp), intent(in) :: value(:)
      logical, intent(in) :: absolute
      integer, intent(in) :: n   !! number of unknowns
      real(dp) :: v(n)
      integer :: k, a, c
      v = 0
      do k = 1, size(active)
         c = active(k)
         do a = 1, 4
            if (contacts%dofs(a, c) == 0) cycle
            if (absolute) then
               v(contacts%dofs(a, c)) = v(contacts%dofs(a, c)) + abs(contacts%weights(a, c)*value(k))
            else
               v(contacts%dofs(a, c)) = v(contacts%dofs(a, c)) + contacts%weights(a, c)*value(k)
            end if
         end do
      end do
   end function rows_transpose


   subroutine dynamic_checks(scene)
      type(scene_type), intent(in) :: scene
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      real(dp), allocatable :: u_old(:), v_old(:), f_old(:), f_new(:), f_bar(:), dv(:), du(:), v_bar(:), u_bar(:), &
                               rho(:), scale(:), work(:), v_f(:), hp(:), k_u(:), b(:)
      real(dp) :: e_old, e_new, e0, rise, bound, comp, comp_bound, gap_scale, kappa, separating, e_k, g, &
                  worst_rise = -huge(1.0_dp), worst_bound_ratio = 0, worst_naive = -huge(1.0_dp), worst_residual = 0, &
                  worst_violation = 0, worst_comp = 0, de, e_scale
      integer :: n, steps, stat, k, m, contact_steps, largest_solves, total_solves, interior_steps, c, side
      real(dp) :: value
      logical :: consistent, complementary, admissible, below_bound
      character(len=512) :: errmsg
      character(len=200) :: detail
      call prepare_test_scene(scene, prepared)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) error stop 'start_time_stepper failed'
      if (scene%time%scheme /= 'velocity' .or. abs(scene%time%theta - 0.5_dp) > 0 .or. scene%beam%rayleigh_mass > 0 .or. &
          scene%beam%rayleigh_stiffness > 0) error stop 'test_stress: velocity scheme, theta = 1/2, no damping only'
      separating = 1
      select type (stepper)
      type is (velocity_stepper)
         separating = stepper%separating_restitution
      end select
      kappa = band_condition(stepper%iteration_matrix)
      steps = nint(scene%time%t_end/scene%time%dt)
      e0 = stepper%kinetic_energy() + stepper%elastic_energy()
      e_old = e0
      e_scale = tiny(1.0_dp)
      contact_steps = 0
      largest_solves = 0
      total_solves = 0
      interior_steps = 0
      consistent = .true.
      complementary = .true.
      admissible = .true.
      below_bound = .true.
      associate (dt => stepper%dt, contacts => stepper%contacts)
         do n = 1, steps
            u_old = stepper%u
            v_old = stepper%v
            f_old = stepper%loads%at(stepper%t)
            call stepper%step(stat, errmsg)
            if (stat /= 0) then
               call t%check_true('step succeeds', .false., trim(errmsg))
               exit
            end if
            if (stepper%report%used_fallback) call t%check_true('no fall-back', .false.)
            largest_solves = max(largest_solves, stepper%report%linear_solves)
            total_solves = total_solves + stepper%report%linear_solves
            if (stepper%projector%interior_iterations > 0) interior_steps = interior_steps + 1
            m = stepper%report%active_count
            if (count(abs(stepper%report%impulse(1:m)) > 0) > 0) contact_steps = contact_steps + 1
            f_new = stepper%loads%at(stepper%t)
            f_bar = 0.5_dp*(f_old + f_new)
            dv = stepper%v - v_old
            du = stepper%u - u_old
            v_bar = 0.5_dp*(stepper%v + v_old)
            u_bar = 0.5_dp*(stepper%u + u_old)
            ! 2. consistency of the step equations
            allocate (rho(size(dv)), work(size(dv)), k_u(size(dv)))
            call band_matvec(stepper%mass, dv, rho)
            call band_matvec(stepper%stiffness, u_bar, k_u)
            hp = rows_transpose(contacts, stepper%report%active(1:m), stepper%report%impulse(1:m), .false., size(dv))
            rho = rho + dt*k_u - dt*f_bar - hp
            v_f = hp
            call band_solve(stepper%iteration_factor, v_f)
            v_f = stepper%v - v_f
            scale = abs_factor_times(stepper%iteration_factor, v_f - v_old) &
                    + band_abs_times(stepper%iteration_matrix, abs(v_f) + abs(stepper%v)) &
                    + rows_transpose(contacts, stepper%report%active(1:m), stepper%report%impulse(1:m), .true., &
                       size(dv)) + dt*abs(f_bar) &
                    + dt*band_abs_times(stepper%stiffness, abs(u_old) + 0.5_dp*dt*abs(v_old)) &
                    + band_abs_times(stepper%mass, dv) + dt*band_abs_times(stepper%stiffness, u_bar)
            worst_residual = max(worst_residual, maxval(abs(rho)/(2*rounding_gamma(12)*scale + tiny(1.0_dp))))
            if (any(abs(rho) > 2*rounding_gamma(12)*scale)) consistent = .false.
            ! 3. complementarity and 4. the active constraints
            allocate (b(m))
            gap_scale = tiny(1.0_dp)
            comp = 0
            do k = 1, m
               e_k = merge(scene%impact%restitution, separating, stepper%report%approaching(k))
               b(k) = -e_k*stepper%report%velocity_before(k)
               gap_scale = max(gap_scale, abs(stepper%report%velocity_after(k)), abs(b(k)), &
                               abs(contact_value(contacts, stepper%report%active(k), v_f)))
            end do
            do k = 1, m
               g = stepper%report%velocity_after(k) - b(k)
               comp = comp + abs(stepper%report%impulse(k))*abs(g)
               ! the side of the point: the bound nearer to it at t_n
               c = stepper%report%active(k)
               value = contact_value(contacts, c, u_old)
               side = merge(1, -1, abs(value - contacts%lower(c)) <= abs(contacts%upper(c) - value))
               worst_violation = max(worst_violation, -side*g/gap_scale)
               if (-side*g > (64 + 2*kappa)*epsilon(1.0_dp)*gap_scale) admissible = .false.
            end do
            comp_bound = 80*epsilon(1.0_dp)*gap_scale*(sum(abs(stepper%report%impulse(1:m))) + &
                                                        m*maxval([abs(stepper%report%impulse(1:m)), 0.0_dp]))
            if (comp > comp_bound) complementary = .false.
            worst_comp = max(worst_comp, comp/max(comp_bound, tiny(1.0_dp)))
            ! 5. energy
            call band_matvec(stepper%mass, dv, work)
            de = dot_product(v_bar, work)
            call band_matvec(stepper%stiffness, du, work)
            de = de + dot_product(u_bar, work)
            rise = de - dot_product(f_bar, du)
            bound = 0.5_dp*comp_bound + 2*rounding_gamma(12)*dot_product(abs(v_bar), scale) &
                    + epsilon(1.0_dp)*dot_product(abs(k_u - f_bar), abs(stepper%u)) &
                    + rounding_gamma(9)*(dot_product(abs(v_bar), band_abs_times(stepper%mass, dv)) &
                                + dot_product(abs(u_bar), band_abs_times(stepper%stiffness, du))) &
                    + rounding_gamma(size(du))*dot_product(abs(f_bar), abs(du))
            if (rise > bound) below_bound = .false.
            e_scale = max(e_scale, e_old)
            worst_rise = max(worst_rise, rise)
            worst_bound_ratio = max(worst_bound_ratio, rise/bound)
            e_new = stepper%kinetic_energy() + stepper%elastic_energy()
            worst_naive = max(worst_naive, e_new - e_old - dot_product(f_bar, du))
            e_old = e_new
            deallocate (rho, work, k_u, b)
         end do
      end associate
      write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,i0,a)') 'N = ', scene%mesh%elements, ': ', n - 1, ' steps, ', &
         contact_steps, ' with impulses, ', interior_steps, ' with the interior-point method; linear solves: ', &
         total_solves, ' in all, at most ', largest_solves, ' in one step'
      e_scale = max(e_scale, e_old)
      write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3)') '  largest dE - F.dU in a step ', worst_rise, &
         ' J (largest rise / bound ', worst_bound_ratio, '); as a difference of two energies ', worst_naive, &
         ' J; largest E ', e_scale
      write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3)') '  consistency residual / bound ', worst_residual, &
         ', complementarity / bound ', worst_comp, ', largest violation / scale ', worst_violation, ', cond(W) ', kappa
      call t%check_true('every step completes', n - 1 == steps)
      write (detail, '(a,es10.3)') 'largest residual / bound ', worst_residual
      call t%check_true('step equations hold to round-off (consistency)', consistent, trim(detail))
      write (detail, '(a,es10.3)') 'largest sum |P| |gap| / bound ', worst_comp
      call t%check_true('complementarity to round-off', complementary, trim(detail))
      write (detail, '(a,es10.3)') 'largest violation / scale ', worst_violation
      call t%check_true('active constraints hold to round-off', admissible, trim(detail))
      write (detail, '(a,es10.3)') 'largest rise / bound ', worst_bound_ratio
      call t%check_true('energy never rises beyond the work of the loads and the round-off bound', below_bound, &
                        trim(detail))
   end subroutine dynamic_checks

   !> Static equilibrium: `solve_static` against the dense Delassus LCP, and the
   !! optimality conditions at a larger N.
   subroutine static_checks(scene_in, reference_elements, check_elements)
      type(scene_type), intent(in) :: scene_in
      integer, intent(in) :: reference_elements, check_elements
      type(scene_type) :: scene
      type(run_problem) :: prepared
      real(dp), allocatable :: u(:), r(:), u_ref(:), r_ref(:), f(:), residual(:)
      real(dp) :: tol, kappa, scale, value, force_scale
      integer :: stat, iterations, m, c, pass
      character(len=512) :: errmsg
      character(len=160) :: detail
      scene = scene_in
      do pass = 1, 2
         scene%mesh%elements = merge(reference_elements, check_elements, pass == 1)
         call prepare_test_scene(scene, prepared)
         associate (contacts => prepared%contacts, stiffness => prepared%model%stiffness)
            m = contacts%count
            f = prepared%loads%at(0.0_dp)
            allocate (u(stiffness%n), r(m))
            call solve_static(prepared%model, contacts, f, u, r, iterations, stat, errmsg)
            call t%check_true('solve_static succeeds', stat == 0, trim(errmsg))
            kappa = band_condition(stiffness)
            ! equilibrium K u - F = H^T R, to the round-off of the products
            allocate (residual(stiffness%n))
            call band_matvec(stiffness, u, residual)
            residual = residual - f - rows_transpose(contacts, [(c, c=1, m)], r, .false., stiffness%n)
            scale = maxval(band_abs_times(stiffness, u)) + maxval(abs(f)) + &
                    maxval(rows_transpose(contacts, [(c, c=1, m)], r, .true., stiffness%n))
            write (detail, '(a,es10.3,a,es10.3)') '|K u - F - H^T R| = ', maxval(abs(residual)), ', bound ', &
               2*rounding_gamma(12)*scale
            call t%check_true('static equilibrium holds to round-off', maxval(abs(residual)) <= 2*rounding_gamma(12)*scale, &
                              trim(detail))
            force_scale = maxval(abs(r)) + maxval(abs(f))
            do c = 1, m
               value = contact_value(contacts, c, u)
               call t%check_true('static reaction has the sign of its bound', &
                                 (r(c) >= 0 .or. abs(value - contacts%upper(c)) <= 64*kappa*epsilon(1.0_dp)* &
                                  maxval(abs(u))) .and. &
                                 (r(c) <= 0 .or. abs(value - contacts%lower(c)) <= 64*kappa*epsilon(1.0_dp)* &
                                  maxval(abs(u))))
               call t%check_true('static bounds hold', value >= contacts%lower(c) - 64*kappa*epsilon(1.0_dp)* &
                                 maxval(abs(u)))
            end do
            write (output_unit, '(a,i0,a,i0,a,i0,a,es9.2,a,es12.5)') 'static N = ', scene%mesh%elements, ': ', &
               count(abs(r) > 0), ' of ', m, ' points in contact; cond(K) ', kappa, '; sum of reactions ', sum(r)
            if (pass == 1) then
               ! dense reference: the LCP of A = H K^-1 H^T (dense Cholesky), q = H K^-1 F - lower
               if (any(contacts%upper < no_bound)) error stop 'static reference: one-sided bounds only'
               allocate (u_ref(stiffness%n), r_ref(m))
               call dense_lcp_reference(stiffness, contacts, [(1.0_dp, c=1, m)], u_ref, r_ref, stat, errmsg, load=f)
               call t%check_true('dense LCP reference solves', stat == 0, trim(errmsg))
               tol = 4*(stiffness%n + m)*epsilon(1.0_dp)*kappa
               write (output_unit, '(a,es10.3,a,es10.3,a,es10.3)') '  against the dense LCP: |u - u_ref|/|u_ref| ', &
                  maxval(abs(u - u_ref))/maxval(abs(u_ref)), ', |R - R_ref|/|R_ref| ', &
                  maxval(abs(r - r_ref))/maxval(abs(r_ref)), ', derived tolerance ', tol
               write (detail, '(a,es10.3)') 'relative difference ', maxval(abs(u - u_ref))/maxval(abs(u_ref))
               call t%check_true('static displacement agrees with the dense reference to 1e-10 and the derived tolerance', &
                                 maxval(abs(u - u_ref)) <= min(1e-10_dp, tol)*maxval(abs(u_ref)), trim(detail))
               write (detail, '(a,es10.3)') 'relative difference ', maxval(abs(r - r_ref))/force_scale
               call t%check_true('static reactions agree with the dense reference to 1e-10 and the derived tolerance', &
                                 maxval(abs(r - r_ref)) <= min(1e-10_dp, tol)*force_scale, trim(detail))
            end if
            deallocate (u, r, residual)
         end associate
      end do
   end subroutine static_checks
end program test_stress
