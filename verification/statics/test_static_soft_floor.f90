!> Statics on a soft compliant floor against an independent exact discrete solution (docs/method.md
!! "Statics"): the beam of soft_floor.nml (L = 1 m, EI = 1 N m^2, q = -1 N/m, given by k2 with
!! rho S = 1) pressed on a linear compliant floor (exponent 1, k = 1e2 N/m per m) at l = -0.01 m
!! under its whole length, for each N given and both bases. Until the refinement of the
!! elastic supports stopped passing overlapping sections of one array as distinct outputs of
!! `held_equilibrium`, this scene failed its own a-posteriori check at N = 1000 (exit 3,
!! 2.3e-9 m against a bound of 3.6e-11 m; the tip reaction off by 4.7e-6 N of 7.4e-4 N).
!!
!! Reference. The floor is lumped at the nodes (docs/input.md: stiffness per unit length times
!! the tributary length, k_j = k h inside, k h/2 at the tip; the clamp gets none), so the
!! discrete model is the beam on point springs at the nodes. Both bases give the nodal values
!! of the continuum exactly under a uniform load and point forces at nodes (theory §7; the
!! argument of test_static_closed_forms.f90), so the nodal displacements are those of the
!! continuous clamped-free beam under q and the spring forces P_j, superposed:
!!
!!     w(x) = w_q(x) + sum_j G(x, x_j) P_j,   w_q(x) = q x^2 (6 L^2 - 4 L x + x^2)/(24 EI),
!!     G(x, s) = a^2 (3 b - a)/(6 EI),  a = min(x, s), b = max(x, s)
!!
!! (the cantilever's deflection at x under a unit upward force at s). A spring of exponent 1
!! pressed by p_j = l - w_j > 0 pushes P_j = k_j p_j, and nothing otherwise. On the set A of
!! nodes in contact, P_j/k_j = l - w_j gives
!!
!!     (C + G_AA) P_A = l - w_q(x_A),   C = diag(1/k_j),
!!
!! symmetric positive definite: G is a flexibility matrix (positive semi-definite), so every
!! eigenvalue is >= min_j 1/k_j and ||(C + G_AA)^-1||_2 <= max_j k_j (= k h: 0.1 N/m at
!! N = 1000); with Gershgorin's bound of the largest eigenvalue the condition number is at
!! most max_j k_j times the largest row sum (printed: 13 at N = 200 and 1000, where the
!! solver's moment equations have EI c/h^3 = 1e10 at N = 1000). Solved by dense Cholesky
!! (LAPACK dpotrf/dpotrs); A by a primal-dual active-set iteration from the nodes where
!! w_q < l (the problem is strictly convex: one solution), accepted only when every force of
!! A and every clearance outside it exceeds its bound (then the exact solution has the same
!! set).
!! With one node it is the closed form of a cantilever on a tip spring,
!! P = (l - w_q(L))/(1/k + L^3/(3 EI)) (verification.compliant_static).
!!
!! Tolerances, derived (first order, u = eps/2, gamma_n = n u/(1 - n u); Higham 2002):
!! - reference, forces: forming G and w_q from x_j = j (L/N) costs at most gamma_20 of each
!!   entry's magnitude (w_q with its terms' absolute values); with the computed residual
!!   r = b - (C + G) P, the true one is below rho = |r| + gamma_(m+22) ((C + |G|)|P| + |l| +
!!   |w_q|) (the residual's own rounding, gamma_(m+1), and the formation), so
!!   |dP_j| <= ||dP||_2 <= max_j k_j ||rho||_2;
!! - reference, displacements: |G| |dP| + gamma_(m+22) (|w_q| + |G| |P|);
!! - the solver's nodal displacements: its derived bound (`static_report%unknown_bound` at
!!   the nodes), plus the reference's;
!! - the solver's reactions, with f_j = k_j max(l - w_j, 0) its spring law at its own
!!   position and w_j within w_bound_j + the reference's bound of the exact position: at a
!!   supported node its a-posteriori check (stat 0) holds |P_j - f_j| <= 1024 eps
!!   max(|f_j|, |P_j|) + k_j tol_j (tol_j its position bound: w_bound_j, 32 eps |w_j| and
!!   4 eps |l|), so |P_j - P_exact| <= 1024 eps max(|f_j|, |P_j|) + k_j (tol_j + w_bound_j +
!!   the reference's w bound) + the reference's P bound; at a node it left free (P_j = 0)
!!   its Newton test (docs/method.md, "Statics") holds f_j <= 1024 eps of the largest force,
!!   so P_exact <= that + k_j (w_bound_j + the reference's w bound) (+ its P bound);
!! - the sum of the reactions: the solver's `reaction_sum_bound`, gamma_m of the test's sum
!!   and the reference's sum of |dP|.
!! Each tolerance must itself be below 1e-3 of the value it bounds, so that the comparison says
!! something (the solver's bounds with soft elastic supports are normwise, dpbcon's: 1.1e-4 of
!! the deflection at N = 1000); the errors measured are printed beside them.
!!
!! usage: test_static_soft_floor SCENE.nml N...
program test_static_soft_floor
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_lapack, only: dpotrf, dpotrs
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   character(len=512) :: path, argument
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   integer :: i, b, elements

   call get_command_argument(1, path)
   do i = 2, command_argument_count()
      call get_command_argument(i, argument)
      read (argument, *) elements
      do b = 1, size(bases)
         call soft_floor_case(trim(bases(b)), elements)
      end do
   end do
   call t%finish('test_static_soft_floor')

contains

   !> The cantilever's deflection at x under a unit upward force at s (m/N).
   real(dp) pure function green(x, s, ei)
      real(dp), intent(in) :: x, s, ei
      green = min(x, s)**2*(3*max(x, s) - min(x, s))/(6*ei)
   end function green

   !> The exact discrete equilibrium on the floor (module documentation): nodal displacements
   !! w(0:N) and spring forces p(1:N), with the bounds of their errors.
   subroutine reference_solution(length, ei, q, level, stiffness, elements, w, p, w_bound, p_bound, condition)
      real(dp), intent(in) :: length, ei, q, level, stiffness
      integer, intent(in) :: elements
      real(dp), intent(out) :: w(0:elements), p(elements), w_bound(0:elements), p_bound(elements)
      real(dp), intent(out) :: condition   !! bound of the 2-norm condition number of C + G_AA
      real(dp), allocatable :: a(:, :), factor(:, :), rhs(:), residual(:), magnitude(:)
      real(dp) :: x(0:elements), wq(0:elements), wq_abs(0:elements), k(elements), h, p_error
      logical :: contact(elements), next(elements)
      integer, allocatable :: nodes(:)
      integer :: j, l, m, info, iteration
      h = length/elements
      x = [(j*h, j=0, elements)]
      wq = q*x**2*(6*length**2 - 4*length*x + x**2)/(24*ei)
      wq_abs = abs(q)*x**2*(6*length**2 + 4*length*x + x**2)/(24*ei)
      k = stiffness*h
      k(elements) = stiffness*h/2
      contact = wq(1:) < level
      do iteration = 1, 100
         nodes = pack([(j, j=1, elements)], contact)
         m = size(nodes)
         allocate (a(m, m), rhs(m))
         do l = 1, m
            do j = 1, m
               a(j, l) = green(x(nodes(j)), x(nodes(l)), ei)
            end do
            a(l, l) = a(l, l) + 1/k(nodes(l))
            rhs(l) = level - wq(nodes(l))
         end do
         allocate (factor, source=a)
         p = 0
         if (m > 0) then
            call dpotrf('L', m, factor, m, info)
            if (info /= 0) error stop 'test_static_soft_floor: the reference''s Cholesky failed'
            call dpotrs('L', m, 1, factor, m, rhs, m, info)
            p(nodes) = rhs
         end if
         do j = 0, elements
            w(j) = wq(j) + sum([(green(x(j), x(nodes(l)), ei)*p(nodes(l)), l=1, m)])
         end do
         next = w(1:) < level
         if (all(next .eqv. contact)) exit
         contact = next
         deallocate (a, rhs, factor)
      end do
      if (iteration > 100) error stop 'test_static_soft_floor: the reference''s active set did not settle'
      ! the bounds (module documentation)
      allocate (residual(m), magnitude(m))
      do j = 1, m
         residual(j) = level - wq(nodes(j)) - sum(a(j, :)*p(nodes))
         magnitude(j) = sum(abs(a(j, :))*abs(p(nodes))) + abs(level) + wq_abs(nodes(j))
      end do
      p_error = maxval(k)*norm2(abs(residual) + gamma_n(m + 22)*magnitude)
      condition = 0
      if (m > 0) condition = maxval(k(nodes))*maxval(sum(abs(a), dim=2))
      p_bound = 0
      p_bound(nodes) = p_error
      do j = 0, elements
         w_bound(j) = sum([(green(x(j), x(nodes(l)), ei)*(p_error + gamma_n(m + 22)*abs(p(nodes(l)))), l=1, m)]) + &
                      gamma_n(m + 22)*wq_abs(j)
      end do
      ! the contact set is the exact one: every force and every free node's clearance
      ! beyond its bound
      do j = 1, elements
         if (contact(j) .and. .not. p(j) > p_bound(j)) error stop 'test_static_soft_floor: a reference force within its bound of 0'
         if (.not. contact(j) .and. .not. w(j) - level > w_bound(j)) &
            error stop 'test_static_soft_floor: a free node of the reference within its bound of the floor'
      end do
   end subroutine reference_solution

   !> The worst of |value - reference| / tolerance over a field, checked at that entry.
   subroutine check_field(label, value, reference, tolerance, scale)
      character(len=*), intent(in) :: label
      real(dp), intent(in) :: value(:), reference(:), tolerance(:)
      real(dp), intent(in) :: scale   !! the field's size, for the tolerance's own check
      character(len=160) :: detail
      real(dp) :: ratio(size(value))
      integer :: worst, j
      ! (a zero tolerance, the clamp's, allows only a zero difference)
      do j = 1, size(value)
         ratio(j) = 0
         if (tolerance(j) > 0) then
            ratio(j) = abs(value(j) - reference(j))/tolerance(j)
         else if (abs(value(j) - reference(j)) > 0) then
            ratio(j) = huge(1.0_dp)
         end if
      end do
      worst = maxloc(ratio, dim=1)
      write (output_unit, '(a,es10.3,a,es10.3,a,i0,a,es10.3,a,es10.3)') '  '//label//': largest error ', &
         maxval(abs(value - reference)), ' (scale ', scale, '); worst against its tolerance at entry ', worst, ': ', &
         abs(value(worst) - reference(worst)), ' of ', tolerance(worst)
      call t%check_close(label, abs(value(worst) - reference(worst)), 0.0_dp, 1.0_dp, tolerance(worst))
      write (detail, '(a,es10.3)') 'largest tolerance relative to the scale ', maxval(tolerance)/scale
      call t%check_true(label//': its derived tolerance is below 1e-3 of the scale', maxval(tolerance) <= 1e-3_dp*scale, &
                        trim(detail))
   end subroutine check_field

   !> The scene with N elements of `basis`: the solver against the reference.
   subroutine soft_floor_case(basis, elements)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(scene_type) :: scene
      type(run_problem) :: prepared
      type(static_report) :: report
      real(dp), allocatable :: u(:), reaction(:), w(:), w_bound(:), force(:), force_tolerance(:)
      real(dp) :: w_ref(0:elements), p_ref(elements), w_ref_bound(0:elements), p_ref_bound(elements)
      real(dp) :: length, ei, q, level, stiffness, h, position_tolerance, tolerance, condition, law, spring
      integer :: iterations, stat, c, j, m
      character(len=80) :: label
      character(len=512) :: errmsg
      scene = read_test_scene(trim(path))
      scene%mesh%elements = elements
      scene%mesh%basis = basis
      length = scene%beam%length
      ei = scene%beam%ei()
      q = scene%load%distributed
      level = scene%obstacles(1)%level_from
      stiffness = scene%obstacles(1)%stiffness
      if (abs(scene%obstacles(1)%exponent - 1) > 0 .or. abs(scene%obstacles(1)%level_to - level) > 0 .or. &
          abs(scene%obstacles(1)%x_from) > 0 .or. abs(scene%obstacles(1)%x_to - length) > 0 .or. &
          scene%obstacles(1)%side /= 'below') &
         error stop 'test_static_soft_floor: the scene must be a flat linear floor below the whole beam'
      call prepare_test_scene(scene, prepared)
      m = prepared%contacts%count
      allocate (u(prepared%model%unknowns), reaction(m))
      call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u, reaction, iterations, stat, &
                        errmsg, report=report)
      write (label, '(a,i0)') 'soft floor, '//basis//', N = ', elements
      write (output_unit, '(a,i0,a)') trim(label)//': ', count(abs(reaction) > 0), ' nodes in contact'
      call t%check_true(trim(label)//': the static solve succeeds (its a-posteriori check included)', stat == 0, &
                        trim(errmsg))
      w = nodal_displacement(prepared%model, u)
      w_bound = nodal_displacement(prepared%model, report%unknown_bound)
      call reference_solution(length, ei, q, level, stiffness, elements, w_ref, p_ref, w_ref_bound, p_ref_bound, condition)
      write (output_unit, '(a,i0,a,f6.2)') '  reference: ', count(p_ref > 0), ' nodes in contact; condition number <= ', &
         condition
      call check_field(trim(label)//', nodal displacements', w, w_ref, w_bound + w_ref_bound, maxval(abs(w_ref)))
      ! the reactions at the contact points (one per node 1..N), with the spring k_j of each
      h = length/elements
      allocate (force(m), force_tolerance(m))
      do c = 1, m
         j = prepared%contacts%node(c)
         spring = stiffness*merge(h/2, h, j == elements)
         force(c) = p_ref(j)
         law = spring*max(level - w(j + 1), 0.0_dp)
         if (abs(reaction(c)) > 0) then
            position_tolerance = w_bound(j + 1) + 32*epsilon(1.0_dp)*abs(w(j + 1)) + 4*epsilon(1.0_dp)*abs(level)
            force_tolerance(c) = 1024*epsilon(1.0_dp)*max(law, abs(reaction(c))) + &
                                 spring*(position_tolerance + w_bound(j + 1) + w_ref_bound(j)) + p_ref_bound(j)
         else
            force_tolerance(c) = 1024*epsilon(1.0_dp)*maxval(abs(reaction)) + spring*(w_bound(j + 1) + w_ref_bound(j)) + &
                                 p_ref_bound(j)
         end if
      end do
      call check_field(trim(label)//', reactions', reaction, force, force_tolerance, maxval(abs(force)))
      ! the contact set: the solver's agrees with the reference's wherever the reference's
      ! force or clearance exceeds what the tolerances allow
      call t%check_true(trim(label)//': the nodes in contact are the reference''s', &
                        all(reaction > 0 .or. .not. force > force_tolerance) .and. &
                        all(.not. reaction > 0 .or. force > 0 .or. .not. w_ref(prepared%contacts%node) - level > &
                            w_bound(prepared%contacts%node + 1) + w_ref_bound(prepared%contacts%node)))
      call t%check_true(trim(label)//': no reaction pulls', all(reaction >= 0))
      tolerance = report%reaction_sum_bound + gamma_n(m)*sum(abs(reaction)) + sum(p_ref_bound) + &
                  gamma_n(elements)*sum(p_ref)
      write (output_unit, '(a,es23.15,a,es23.15,a,es10.3,a,es10.3)') '  total reaction: ', sum(reaction), &
         ' reference ', sum(p_ref), ' error ', sum(reaction) - sum(p_ref), ' bound ', tolerance
      call t%check_close(trim(label)//', total reaction', abs(sum(reaction) - sum(p_ref)), 0.0_dp, 1.0_dp, tolerance)
      call t%check_true(trim(label)//', total reaction: its derived tolerance is below 1e-3 of it', &
                        tolerance <= 1e-3_dp*sum(p_ref))
   end subroutine soft_floor_case
end program test_static_soft_floor
