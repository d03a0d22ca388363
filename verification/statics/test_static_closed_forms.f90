!> Statics at large N against closed forms (issue 23, items 1 and 12; docs/theory.md §7,
!! docs/method.md "Statics"): the steel strip of verification/statics (L = 0.45 m,
!! EI = 21.33 N m^2, q = -50, per unit mass) for each N given and both bases.
!!
!! References, all exact for the discrete model (no discretization error to allow for):
!! 1. free (strip_free.nml, an obstacle 10 m away): tip deflection q L^4/(8 EI). Both bases
!!    give the nodal values of the continuum exactly (theory §7: the deflection under a point
!!    force at a node lies in both spaces, so by Galerkin orthogonality the nodal values are
!!    exact for any load).
!! 2. tip stop at -g (strip_tip_stop.nml): the same argument for the beam loaded by q and
!!    the tip reaction R: R = 3 EI (|q| L^4/(8 EI) - g)/L^3, and w(L) = -g.
!! 3. floor at -g under the whole beam (strip_floor.nml): by the same nodal exactness the
!!    discrete solution is that of the continuous beam on point supports at the nodes. The
!!    continuum touches down at a = (72 EI g/|q|)^(1/4) with w''(a) = 0 and the floor carries
!!    |q| L - 2 |q| a/3. On point supports, with a on a node (the scene puts a = 0.8 L, on a
!!    node for N a multiple of 5), the span [0, a] is the continuum's except for the rotation
!!    th_t of the touchdown node: beyond a every node is held at -g, the elements carry the
!!    fixed-end moment |q| h^2/12, the rotations of the held chain obey 2 th_(i-1) + 8 th_i +
!!    2 th_(i+1) = 0 (ratio r = sqrt(3) - 2 per node, rotational stiffness 2 sqrt(3) EI/h at
!!    the touchdown; test_liftoff_closed_form.f90), and the span, clamped at 0, resists a
!!    rotation of its far end with 4 EI/a; the first element of the chain pulls the node down
!!    with |q| h^2/12, so th_t = -(|q| h^2/12)/(2 sqrt(3) EI/h + 4 EI/a). The span's clamp
!!    shear, from w = q x^4/(24 EI) + c3 x^3 + c2 x^2 with w(a) = -g, w'(a) = th_t, is
!!    6 EI c3 = |q| a/2 + 12 EI g/a^3 + 6 EI th_t/a^2 = 2|q|a/3 + 6 EI th_t/a^2, so
!!
!!        sum of the reactions = |q| L - 2 |q| a/3 + (|q| h^3/2)/(a^2 (2 sqrt(3) + 4 h/a))
!!
!!    (the last term: 5.1e-9 at N = 1e3, relative 4.8e-10, falling like h^3); the free end
!!    carries an unbalanced |q| h^2/12 whose rotation reaches the touchdown damped by
!!    |r|^(N/5) < 1e-100. Every node from a on is in contact and none before it: the
!!    touchdown is the first node with a reaction, at a.
!!
!! Tolerances, derived beside each check: the solver's own derived round-off bounds
!! (`static_report`: unknown_bound, reaction_bound, reaction_sum_bound; derivation in
!! src/model/vibrobeam_support_moments.f90 and src/analysis/vibrobeam_static.f90), plus the
!! rounding of the closed form (gamma_12 of its terms) and of the test's sum (gamma_m of
!! sum |R|). Each derived tolerance must itself be below 1e-9 of the value it bounds:
!! the accuracy the statics promises, well below the 1e-6 of the issue.
!! The static solve must also succeed (stat 0: its a-posteriori check passed).
!!
!! Measured on the unfixed code (c78cc6d: U_free and the projection by band Cholesky of K;
!! this program with the solver's bounds replaced by the 1e-9 it allows at most: 42 of 84
!! checks failed), relative errors at N = 1e3, 1e4, 1e5, Hermite / B-splines:
!! - free tip: -4.7e-6, 1.1e-2, -1.0 (6.4e-7 m instead of 1.2e-2 m) / 2.6e-6, -9.1e-3, band
!!   Cholesky failure (K not numerically positive definite);
!! - tip stop reaction: -3.3e-6, -9.2e-3, 0 N instead of 4.93 / 2.0e-6, 6.7e-3, failure;
!! - floor total reaction: -9.3e-8 (200 of the 201 nodes in contact), -2.1e-3 (touchdown
!!   at 0.35995 m, 1987 of 2001 nodes), no contact at all with status 'ok' / 3.1e-7 (200 of
!!   201), 3.1e-4 (1997 of 2001), failure.
!!
!! usage: test_static_closed_forms SCENE_DIR N...
program test_static_closed_forms
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   character(len=512) :: dir, argument
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   integer :: i, b, elements

   call get_command_argument(1, dir)
   do i = 2, command_argument_count()
      call get_command_argument(i, argument)
      read (argument, *) elements
      do b = 1, size(bases)
         call closed_form_cases(trim(bases(b)), elements)
      end do
   end do
   call t%finish('test_static_closed_forms')

contains

   real(dp) pure function rounding_gamma(n)
      integer, intent(in) :: n
      rounding_gamma = n*0.5_dp*epsilon(1.0_dp)/(1 - n*0.5_dp*epsilon(1.0_dp))
   end function rounding_gamma

   !> The scene of `file` with N elements of `basis`, solved; stops the test if the solve fails.
   !! Also the scene's |q|, the depth g of its first obstacle, L and EI.
   subroutine solve(file, basis, elements, scene, prepared, w, w_bound, reaction, report, label, p, g, length, ei)
      character(len=*), intent(in) :: file, basis
      integer, intent(in) :: elements
      type(scene_type), intent(out) :: scene
      type(run_problem), intent(out) :: prepared
      real(dp), intent(out) :: p, g, length, ei
      real(dp), allocatable, intent(out) :: w(:), w_bound(:), reaction(:)
      type(static_report), intent(out) :: report
      character(len=*), intent(out) :: label
      real(dp), allocatable :: u(:)
      integer :: iterations, stat
      character(len=512) :: errmsg
      scene = read_test_scene(trim(dir)//'/'//file)
      scene%mesh%elements = elements
      scene%mesh%basis = basis
      call prepare_test_scene(scene, prepared)
      allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count))
      call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u, reaction, iterations, stat, &
                        errmsg, report=report)
      write (label, '(a,i0)') file(7:len(file) - 4)//', '//basis//', N = ', elements
      call t%check_true(trim(label)//': the static solve succeeds (its a-posteriori check included)', stat == 0, &
                        trim(errmsg))
      allocate (w(elements + 1), w_bound(elements + 1))
      w = nodal_displacement(prepared%model, u)
      ! the unknowns' bounds at the nodes (B-spline rows have non-negative weights)
      w_bound = nodal_displacement(prepared%model, report%unknown_bound)
      p = -scene%load%distributed
      g = -scene%obstacles(1)%level_from
      length = scene%beam%length
      ei = scene%beam%ei()
      write (output_unit, '(a)') trim(label)
   end subroutine solve

   !> |value - reference| <= tolerance, and the tolerance itself below 1e-9 of |reference|.
   subroutine check(label, value, reference, tolerance)
      character(len=*), intent(in) :: label
      real(dp), intent(in) :: value, reference, tolerance
      character(len=160) :: detail
      write (output_unit, '(a,es23.15,a,es23.15,a,es10.3,a,es10.3)') '  '//label//': ', value, ' reference ', reference, &
         ' error ', value - reference, ' bound ', tolerance
      call t%check_close(label, abs(value - reference), 0.0_dp, 1.0_dp, tolerance)
      write (detail, '(a,es10.3)') 'relative tolerance ', tolerance/abs(reference)
      call t%check_true(label//': its derived tolerance is below 1e-9 of the value', tolerance <= 1e-9_dp*abs(reference), &
                        trim(detail))
   end subroutine check

   !> The free tip (strip_free.nml), the tip stop (strip_tip_stop.nml) and the floor
   !! (strip_floor.nml).
   subroutine closed_form_cases(basis, elements)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(scene_type) :: scene
      type(run_problem) :: prepared
      type(static_report) :: report
      real(dp), allocatable :: w(:), w_bound(:), reaction(:)
      real(dp) :: p, g, length, ei, exact, a, h, total, tolerance
      integer :: touchdown, first, m
      character(len=80) :: label
      character(len=160) :: detail
      call solve('strip_free.nml', basis, elements, scene, prepared, w, w_bound, reaction, report, label, p, g, length, ei)
      exact = -p*length**4/(8*ei)
      ! tolerance: the solver's bound of the tip value, and the closed form's rounding
      call check(trim(label)//', tip deflection q L^4/(8 EI)', w(size(w)), exact, w_bound(size(w)) + rounding_gamma(12)*abs(exact))
      call t%check_true(trim(label)//': no reaction', .not. any(abs(reaction) > 0))
      call solve('strip_tip_stop.nml', basis, elements, scene, prepared, w, w_bound, reaction, report, label, p, g, length, ei)
      exact = 3*ei*(p*length**4/(8*ei) - g)/length**3
      ! tolerance: the solver's bound of the reaction, and gamma_12 of the closed form's terms
      call check(trim(label)//', tip reaction 3 EI (|q| L^4/(8 EI) - g)/L^3', reaction(1), exact, &
                 report%reaction_bound(1) + rounding_gamma(12)*3*ei*(p*length**4/(8*ei) + g)/length**3)
      ! the tip on the stop: to the solver's bound of the tip value
      call t%check_close(trim(label)//': the tip rests on the stop', abs(w(size(w)) + g), 0.0_dp, 1.0_dp, &
                         w_bound(size(w)) + rounding_gamma(1)*g)
      call solve('strip_floor.nml', basis, elements, scene, prepared, w, w_bound, reaction, report, label, p, g, length, ei)
      m = prepared%contacts%count
      h = length/elements
      a = (72*ei*g/p)**0.25_dp
      touchdown = nint(a/h)
      if (abs(touchdown*h - a) > 1e-12_dp*a) error stop 'test_static_closed_forms: the floor''s a must lie on a node'
      ! the touchdown: the first node with a reaction is the one at a, every node from it on
      ! is in contact, every reaction has the floor's sign
      first = findloc(abs(reaction) > 0, .true., dim=1)
      write (detail, '(a,es23.15,a,es23.15,a,i0,a,i0)') 'first contact at x = ', prepared%contacts%x(max(first, 1)), &
         ', a = ', a, '; nodes in contact ', count(abs(reaction) > 0), ' of ', elements - touchdown + 1
      write (output_unit, '(a)') '  touchdown: '//trim(detail)
      call t%check_true(trim(label)//': touchdown at a = (72 EI g/|q|)^(1/4)', &
                        first >= 1 .and. prepared%contacts%node(max(first, 1)) == touchdown, trim(detail))
      call t%check_true(trim(label)//': every node from a to L in contact, none before', &
                        count(abs(reaction) > 0) == elements - touchdown + 1 .and. all(reaction(first:) > 0), trim(detail))
      call t%check_true(trim(label)//': no reaction pulls', all(reaction >= 0))
      ! the sum: module comment, item 3; tolerance: the solver's bound of the sum, the
      ! rounding of summing m reactions, and of the closed form
      total = sum(reaction)
      exact = p*length - 2*p*a/3 + (p*h**3/2)/(a**2*(2*sqrt(3.0_dp) + 4*h/a))
      tolerance = report%reaction_sum_bound + rounding_gamma(m)*sum(abs(reaction)) + rounding_gamma(12)*p*length
      call check(trim(label)//', total reaction |q| L - 2|q|a/3 + (|q| h^3/2)/(a^2 (2 sqrt 3 + 4h/a))', total, exact, &
                 tolerance)
      write (output_unit, '(a,es10.3)') '  its difference from the continuum |q| L - 2 |q| a/3: ', &
         total - (p*length - 2*p*a/3)
   end subroutine closed_form_cases
end program test_static_closed_forms
