!> Statics of a non-uniform beam and of a beam under an axial force (issue 18, items 4 and
!! 5; docs/method.md "Statics", `vibrobeam_static_band`) against closed forms written here
!! (docs/theory.md §7, "Sections and axial force"): the whole path of a run (a scene built
!! here, `build_problem`, `solve_static`).
!!
!! - A stepped cantilever (clamped at 0, free at L = 0.8 m; EI_1 = 60 N m^2 on [0, a],
!!   EI_2 = 15 on [a, L], a = 0.3 m, a node for N = 8 k) under a uniform load f = -q, q = 3
!!   N/m: the moment M = -q (L - x)^2/2 integrated twice piecewise from the clamp,
!!     u = -q/(6 EI_1) (L^3 x + ((L - x)^4 - L^4)/4)                              on [0, a],
!!     u = u(a) + u'(a) (x - a) - q/(6 EI_2) ((L - a)^3 (x - a) + ((L - x)^4 - (L - a)^4)/4)
!!   on [a, L], u'(a) = -q/(6 EI_1) (L^3 - (L - a)^3). Hermite elements reproduce it at the
!!   nodes exactly (the Green's function of a point force at a node, cubic between nodes,
!!   C^1 with u'' jumping at a node, lies in their space; theory §7), so the error is
!!   round-off: the solver's position bound (`static_report`, 4 FERR of LAPACK dpbrfs)
!!   plus gamma_12 of the closed form's terms. (B-splines refuse a step of EI, theory §2.)
!! - A tensioned pinned-pinned beam (EI = 40 N m^2, T = 200 N, rho S = 1: k L = sqrt(T/EI) L
!!   = 1.79, bending and tension alike) under the same load:
!!     u = -q x (L - x)/(2T) + (q EI/T^2) (1 - cosh(k (x - L/2))/cosh(k L/2)),  k^2 = T/EI.
!!   Its Green's function holds sinh and cosh, which no cubic reproduces: the nodal values
!!   converge. Checked, both bases: the observed order of the largest nodal error between
!!   N = 8 and 16 in [3.5, 4.5] (h^4, measured 4.0), and at N = 128 the error below 1.5
!!   times the h^4 extrapolation of the N = 16 one plus the solver's position bound
!!   (h^4 down to the solver's round-off).
program test_static_sections_tension
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type, section_settings, unset
   use vibrobeam_static, only: static_report
   use vibrobeam_test_support, only: test_counter, static_deflection
   use vibrobeam_roundoff_bounds, only: gamma_n
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 0.8_dp, q = 3, step_at = 0.3_dp, ei_1 = 60, ei_2 = 15
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   integer :: b
   call stepped_cantilever(16)
   call stepped_cantilever(64)
   do b = 1, 2
      call tensioned(trim(bases(b)))
   end do
   call t%finish('test_static_sections_tension')

contains

   !> kind = 'static' under the uniform load f = -q, no obstacle.
   function static_scene(basis, elements) result(scene)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(scene_type) :: scene
      scene%beam%length = length
      scene%mesh%basis = basis
      scene%mesh%elements = elements
      scene%analysis%kind = 'static'
      scene%load%distributed = -q
      allocate (scene%obstacles(0))
   end function static_scene

   !> Solve; the nodal deflections and the solver's report.
   subroutine solve(scene, label, w, report)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: label
      real(dp), allocatable, intent(out) :: w(:)
      type(static_report), intent(out) :: report
      integer :: stat
      character(len=512) :: errmsg
      call static_deflection(scene, w, report, stat, errmsg)
      call t%check_true(label//': the static solve succeeds (its a-posteriori check included)', stat == 0, trim(errmsg))
   end subroutine solve

   !> The stepped cantilever at N elements (Hermite): every node to round-off.
   subroutine stepped_cantilever(elements)
      integer, intent(in) :: elements
      type(scene_type) :: scene
      type(static_report) :: report
      real(dp), allocatable :: w(:)
      real(dp) :: x, exact(elements + 1), terms(elements + 1), slope_a, value_a, bound
      integer :: i, worst
      character(len=:), allocatable :: label
      label = 'hermite stepped cantilever, N = '//integer_text(elements)
      scene = static_scene('hermite', elements)
      scene%beam%youngs_modulus = unset
      scene%beam%sections = [section_settings(x_to=step_at, youngs_modulus=ei_1, density=1, area=1, inertia=1), &
                             section_settings(x_to=length, youngs_modulus=ei_2, density=1, area=1, inertia=1)]
      call solve(scene, label, w, report)
      slope_a = -q/(6*ei_1)*(length**3 - (length - step_at)**3)
      value_a = -q/(6*ei_1)*(length**3*step_at + ((length - step_at)**4 - length**4)/4)
      do i = 0, elements
         x = length*i/elements
         if (x <= step_at) then
            exact(i + 1) = -q/(6*ei_1)*(length**3*x + ((length - x)**4 - length**4)/4)
            terms(i + 1) = q/(6*ei_1)*(length**3*x + length**4/4 + (length - x)**4/4)
         else
            exact(i + 1) = value_a + slope_a*(x - step_at) - q/(6*ei_2)*((length - step_at)**3*(x - step_at) + &
                                                                          ((length - x)**4 - (length - step_at)**4)/4)
            terms(i + 1) = abs(value_a) + abs(slope_a)*(x - step_at) + q/(6*ei_2)*((length - step_at)**3*(x - step_at) + &
                                                                                     ((length - x)**4 + (length - step_at)**4)/4)
         end if
      end do
      worst = maxloc(abs(w - exact)/(report%position_bound + gamma_n(12)*terms), dim=1)
      bound = report%position_bound + gamma_n(12)*terms(worst)
      write (*, '(a,es10.3,a,es10.3,a,es10.3)') label//': largest error ', maxval(abs(w - exact)), ' (relative ', &
         maxval(abs(w - exact))/maxval(abs(exact)), '), position bound ', report%position_bound
      call t%check_close(label//': nodal deflection at the worst node', abs(w(worst) - exact(worst)), 0.0_dp, 1.0_dp, &
                         bound)
   end subroutine stepped_cantilever

   !> The tensioned pinned-pinned beam at N = 8, 16, 32, 64, 128: order and floor.
   subroutine tensioned(basis)
      character(len=*), intent(in) :: basis
      real(dp), parameter :: ei = 40, tension = 200
      type(scene_type) :: scene
      type(static_report) :: report
      real(dp), allocatable :: w(:), exact(:)
      real(dp) :: error(5), k, x
      integer :: level, n, i
      k = sqrt(tension/ei)
      do level = 1, 5
         n = 8*2**(level - 1)
         scene = static_scene(basis, n)
         scene%beam%k2 = ei
         scene%beam%left_end = 'pinned'
         scene%beam%right_end = 'pinned'
         scene%beam%axial_force = tension
         call solve(scene, basis//' tensioned pinned-pinned beam, N = '//integer_text(n), w, report)
         allocate (exact(n + 1))
         do i = 0, n
            x = length*i/n
            exact(i + 1) = -q*x*(length - x)/(2*tension) + &
                           q*ei/tension**2*(1 - cosh(k*(x - length/2))/cosh(k*length/2))
         end do
         error(level) = maxval(abs(w - exact))/maxval(abs(exact))
         deallocate (exact)
      end do
      write (*, '(a,5es10.2)') basis//' tensioned pinned-pinned beam: relative nodal error at N = 8..128:', error
      call t%check_close(basis//' tensioned pinned-pinned beam: order of the nodal error (N = 8 to 16)', &
                         log(error(1)/error(2))/log(2.0_dp), 4.0_dp, 0.5_dp/4)
      call t%check_close(basis//' tensioned pinned-pinned beam: nodal error at N = 128 (h^4 to round-off)', error(5), &
                         0.0_dp, 1.0_dp, 1.5_dp*error(2)/8.0_dp**4 + report%position_bound/maxval(abs(w)))
   end subroutine tensioned
end program test_static_sections_tension
