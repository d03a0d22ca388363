!> Statics of beams on other end supports than the cantilever's (issue 18, item 1;
!! docs/method.md "Statics", `vibrobeam_static_band`) against closed forms, for both bases:
!! the whole path of a run (a scene built here, `build_problem`, `solve_static`).
!!
!! L = 0.8 m, EI = 40 N m^2 (given by k2, per unit mass), a uniform load f = -q, q = 3.
!! References (Euler-Bernoulli beam, EI w'''' = -q, integrated four times with the end
!! conditions; Roark's Formulas for Stress and Strain, table 8.1, cases 2e, 2a, 2c, 2d for
!! the first four), at every node, w(x) with xi = x/L and c = q L^4/(24 EI):
!! - clamped-clamped:  w = -c xi^2 (1 - xi)^2;
!! - pinned-pinned:    w = -c xi (1 - 2 xi^2 + xi^3);
!! - clamped-pinned:   w = -c/2 xi^2 (3 - 5 xi + 2 xi^2);
!! - clamped-sliding (rotation held at L, no shear there): w = -c ((xi - 1)^4 - 1 - 2 xi^2 + 4 xi);
!! - sliding-pinned:   half of a pinned-pinned beam of length 2L, xi' = (x + L)/(2L):
!!                     w = -16 c xi' (1 - 2 xi'^2 + xi'^3);
!! and the mirror images (x -> L - x) of the last three;
!! - a cantilever propped by a pinned support at a = 3L/4 (&supports): the prop's reaction
!!   R = q (6L^2 - 4La + a^2)/(8a) (the clamped-free deflection under q at a, cancelled by
!!   R a^3/(3 EI)), w = -q x^2 (6L^2 - 4Lx + x^2)/(24 EI) + R x^2 (3a - x)/(6 EI) up to a and
!!   + R a^2 (3x - a)/(6 EI) beyond (the overhang carries no reaction);
!! - end springs: a cantilever with a tip spring k (k L^3/EI = 5): the tip reaction
!!   R = (q L^4/(8 EI))/(1/k + L^3/(3 EI)) upwards, w = -q x^2 (6L^2 - 4Lx + x^2)/(24 EI)
!!   + R x^2 (3L - x)/(6 EI); a pinned-free beam held by a rotational spring k_r at the pin
!!   (k_r L/EI = 2): its rotation -q L^2/(2 k_r) plus the cantilever's deflection;
!! - a contact: a pinned-pinned beam over a stop at midspan at -g: the midspan reaction
!!   R = 48 EI (5 q L^4/(384 EI) - g)/L^3 and w(L/2) = -g when positive, with g = 1e-4 m
!!   (contact: 5 q L^4/(384 EI) = 4.0e-4 m) and g = 1e-3 m (none, R = 0); a linear
!!   compliant stop of stiffness k there (k L^3/(48 EI) = 1): R = k (delta - g)/(1 + k L^3/(48 EI)).
!!
!! Both bases reproduce these nodal values exactly (the Green's function of a point force
!! at a node, cubic between nodes with the supports' end conditions, lies in both spaces:
!! theory §7), so the error is round-off. Tolerance: the solver's own position bound
!! (`static_report`: 4 FERR of LAPACK dpbrfs in the scaled unknowns,
!! src/analysis/vibrobeam_static_band.f90) plus gamma_12 of the closed form's terms; the
!! solver refuses its answer when that bound exceeds 1e-6 of its displacement scale, so a
!! solve that succeeds promises six digits (N = 16, 64: cond(K) ~ N^4; the bound is
!! guaranteed, measured 10 to 1000 times above the actual errors, which reach 1.2e-9
!! relative at N = 64). Reactions: R against its closed form to the solver's reaction
!! bound plus gamma_12 R.
program test_static_supports
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_scene, only: scene_type, obstacle_type, support_settings
   use vibrobeam_static, only: static_report
   use vibrobeam_test_support, only: test_counter, static_deflection
   use vibrobeam_roundoff_bounds, only: gamma_n
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 0.8_dp, ei = 40, q = 3
   real(dp), parameter :: c = q*length**4/(24*ei)
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   integer, parameter :: meshes(2) = [16, 64]
   integer :: b, m
   do b = 1, 2
      do m = 1, 2
         call end_pair(bases(b), meshes(m), 'clamped', 'clamped', 1)
         call end_pair(bases(b), meshes(m), 'pinned', 'pinned', 2)
         call end_pair(bases(b), meshes(m), 'clamped', 'pinned', 3)
         call end_pair(bases(b), meshes(m), 'pinned', 'clamped', -3)
         call end_pair(bases(b), meshes(m), 'clamped', 'sliding', 4)
         call end_pair(bases(b), meshes(m), 'sliding', 'clamped', -4)
         call end_pair(bases(b), meshes(m), 'sliding', 'pinned', 5)
         call end_pair(bases(b), meshes(m), 'pinned', 'sliding', -5)
         call springs(bases(b), meshes(m))
         call propped(bases(b), meshes(m))
         call midspan_stop(bases(b), meshes(m), 1e-4_dp, 0.0_dp)
         call midspan_stop(bases(b), meshes(m), 1e-3_dp, 0.0_dp)
         call midspan_stop(bases(b), meshes(m), 1e-4_dp, 48*ei/length**3)
      end do
   end do
   call t%finish('test_static_supports')

contains

   !> The scene: the beam, its mesh, the uniform load; kind = 'static'.
   function static_scene(basis, elements, left, right) result(scene)
      character(len=*), intent(in) :: basis, left, right
      integer, intent(in) :: elements
      type(scene_type) :: scene
      scene%beam%length = length
      scene%beam%k2 = ei
      scene%beam%left_end = left
      scene%beam%right_end = right
      scene%mesh%basis = basis
      scene%mesh%elements = elements
      scene%analysis%kind = 'static'
      scene%load%distributed = -q
      allocate (scene%obstacles(0))
   end function static_scene

   !> Solve, check the solve succeeded; the nodal deflections, the reactions and the report.
   subroutine solve(scene, label, w, reaction, report)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: label
      real(dp), allocatable, intent(out) :: w(:), reaction(:)
      type(static_report), intent(out) :: report
      integer :: stat
      character(len=512) :: errmsg
      call static_deflection(scene, w, report, stat, errmsg, reaction)
      call t%check_true(label//': the static solve succeeds (its a-posteriori check included)', stat == 0, trim(errmsg))
   end subroutine solve

   !> Every nodal deflection against `exact` to the position bound plus gamma_12 |exact|.
   subroutine check_deflection(label, w, exact, report)
      character(len=*), intent(in) :: label
      real(dp), intent(in) :: w(:), exact(:)
      type(static_report), intent(in) :: report
      real(dp) :: bound(size(w))
      integer :: worst
      bound = report%position_bound + gamma_n(12)*abs(exact)
      worst = maxloc(abs(w - exact)/bound, dim=1)
      write (*, '(a,es10.3,a,es10.3,a,es10.3)') label//': largest error ', maxval(abs(w - exact)), &
         ' (relative ', maxval(abs(w - exact))/maxval(abs(exact)), '), position bound ', report%position_bound
      call t%check_close(label//': nodal deflection at the worst node', abs(w(worst) - exact(worst)), 0.0_dp, 1.0_dp, &
                         bound(worst))
   end subroutine check_deflection

   !> An end pair with no obstacle, `case` the closed form (module documentation; negative:
   !! the mirror image).
   subroutine end_pair(basis, elements, left, right, case)
      character(len=*), intent(in) :: basis, left, right
      integer, intent(in) :: elements, case
      real(dp), allocatable :: w(:), reaction(:)
      real(dp) :: xi(elements + 1), exact(elements + 1)
      type(static_report) :: report
      character(len=:), allocatable :: label
      integer :: i
      label = basis//' '//left//'-'//right//', N = '//integer_text(elements)
      call solve(static_scene(basis, elements, left, right), label, w, reaction, report)
      xi = [(real(i, dp)/elements, i=0, elements)]
      if (case < 0) xi = 1 - xi
      select case (abs(case))
      case (1)
         exact = -c*xi**2*(1 - xi)**2
      case (2)
         exact = -c*xi*(1 - 2*xi**2 + xi**3)
      case (3)
         exact = -c/2*xi**2*(3 - 5*xi + 2*xi**2)
      case (4)
         exact = -c*((xi - 1)**4 - 1 - 2*xi**2 + 4*xi)
      case default
         xi = (xi + 1)/2
         exact = -16*c*xi*(1 - 2*xi**2 + xi**3)
      end select
      call check_deflection(label, w, exact, report)
   end subroutine end_pair

   !> A cantilever with a tip spring; a pinned-free beam with a rotational spring at the pin.
   subroutine springs(basis, elements)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(scene_type) :: scene
      real(dp), allocatable :: w(:), reaction(:)
      real(dp) :: x(elements + 1), exact(elements + 1)
      type(static_report) :: report
      real(dp) :: k, tip_reaction, k_r
      integer :: i
      x = [(length*i/elements, i=0, elements)]
      scene = static_scene(basis, elements, 'clamped', 'free')
      k = 5*ei/length**3
      scene%beam%right_spring = k
      call solve(scene, basis//' cantilever with a tip spring, N = '//integer_text(elements), w, reaction, report)
      tip_reaction = (q*length**4/(8*ei))/(1/k + length**3/(3*ei))
      exact = -q*x**2*(6*length**2 - 4*length*x + x**2)/(24*ei) + tip_reaction*x**2*(3*length - x)/(6*ei)
      call check_deflection(basis//' cantilever with a tip spring, N = '//integer_text(elements), w, exact, report)
      scene = static_scene(basis, elements, 'pinned', 'free')
      k_r = 2*ei/length
      scene%beam%left_rotational_spring = k_r
      call solve(scene, basis//' pinned-free on a rotational spring, N = '//integer_text(elements), w, reaction, report)
      exact = -q*length**2/(2*k_r)*x - q*x**2*(6*length**2 - 4*length*x + x**2)/(24*ei)
      call check_deflection(basis//' pinned-free on a rotational spring, N = '//integer_text(elements), w, exact, report)
   end subroutine springs

   !> A cantilever propped by a pinned support at a = 3L/4 (&supports; its overhang beyond).
   subroutine propped(basis, elements)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(scene_type) :: scene
      real(dp), allocatable :: w(:), reaction(:)
      real(dp) :: x(elements + 1), exact(elements + 1)
      type(static_report) :: report
      real(dp) :: a, prop
      integer :: i
      character(len=:), allocatable :: label
      a = 0.75_dp*length
      x = [(length*i/elements, i=0, elements)]
      scene = static_scene(basis, elements, 'clamped', 'free')
      scene%supports = [support_settings(x=a)]
      label = basis//' cantilever propped at 3L/4, N = '//integer_text(elements)
      call solve(scene, label, w, reaction, report)
      prop = q*(6*length**2 - 4*length*a + a**2)/(8*a)
      exact = -q*x**2*(6*length**2 - 4*length*x + x**2)/(24*ei) + &
              prop*merge(x**2*(3*a - x), a**2*(3*x - a), x <= a)/(6*ei)
      call check_deflection(label, w, exact, report)
   end subroutine propped

   !> A pinned-pinned beam over a stop at midspan at -g (rigid, or linear of stiffness k).
   subroutine midspan_stop(basis, elements, g, k)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), intent(in) :: g, k
      type(scene_type) :: scene
      real(dp), allocatable :: w(:), reaction(:)
      type(static_report) :: report
      real(dp) :: delta, flexibility, exact, w_exact
      character(len=:), allocatable :: label
      scene = static_scene(basis, elements, 'pinned', 'pinned')
      deallocate (scene%obstacles)
      allocate (scene%obstacles(1))
      scene%obstacles(1) = obstacle_type(side='below', x_from=length/2, x_to=length/2, level_from=-g, level_to=-g, &
                                         stiffness=k)
      label = basis//' pinned-pinned over a midspan stop, g = '//real_text(g)//', k = '//real_text(k)// &
              ', N = '//integer_text(elements)
      call solve(scene, label, w, reaction, report)
      delta = 5*q*length**4/(384*ei)
      flexibility = length**3/(48*ei)
      if (k > 0) then
         exact = max(0.0_dp, k*(delta - g)/(1 + k*flexibility))
      else
         exact = max(0.0_dp, (delta - g)/flexibility)
      end if
      w_exact = -delta + exact*flexibility
      call t%check_true(label//': one contact point', size(reaction) == 1)
      if (size(reaction) /= 1) return
      write (*, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3)') label//': reaction ', reaction(1), ' error ', &
         reaction(1) - exact, ' bound ', report%reaction_bound(1), '; midspan error ', w(elements/2 + 1) - w_exact
      call t%check_close(label//': reaction (N)', abs(reaction(1) - exact), 0.0_dp, 1.0_dp, &
                         report%reaction_bound(1) + gamma_n(12)*abs(exact))
      call t%check_close(label//': midspan deflection (m)', abs(w(elements/2 + 1) - w_exact), 0.0_dp, 1.0_dp, &
                         report%position_bound + gamma_n(12)*delta)
   end subroutine midspan_stop
end program test_static_supports
