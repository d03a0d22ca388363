!> Verification of static contact (theory §7, issue 3):
!! 1. static_tip.nml: tip reaction R = 3EI(qL^4/(8EI) - g)/L^3 for N = 1, 2, 16, 64: with
!!    a consistent load vector, Hermite cubic elements (and B-splines) give the exact nodal
!!    values of a beam (the exact solution, a quartic, is matched at the nodes), so R is
!!    exact up to round-off.
!! 2. static_longitudinal.nml: beam pressed onto a flat obstacle along its length, N = 40,
!!    80, 160: reactions >= 0 (exactly: the active-set finish frees every held point that
!!    pulls), no node penetrates beyond its position's round-off bound, the nodes with a
!!    reaction span an interval that ends at the tip; inside it the beam may lift off
!!    between reacting nodes (only nodes are constrained, theory §2), by an amount that must
!!    vanish as h -> 0.
!! An optional second argument 'bspline' runs every case with cubic B-splines.
!! 3. static_longitudinal_pieces.nml: the same obstacle as pieces listed out of order:
!!    the same displacement and reactions, each within the round-off bounds of both.
!! Every round-off allowance is derived: the solver's own bounds of each unknown and each
!! reaction (`static_report`; derivation in src/model/vibrobeam_support_moments.f90 and
!! src/analysis/vibrobeam_static.f90, docs/method.md "Statics"), plus the closed form's and
!! the levels' own rounding.
program test_static
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   character(len=512) :: dir
   character(len=16) :: basis
   real(dp), allocatable :: u(:), r(:), du(:), dr(:), u_whole(:), r_whole(:), du_whole(:), dr_whole(:), gap(:)
   real(dp) :: q, g, exact, scale, exact_error
   integer, parameter :: meshes(4) = [1, 2, 16, 64]
   integer :: k, c, first, last
   real(dp) :: lift_off(3)
   character(len=64) :: label
   call get_command_argument(1, dir)
   call get_command_argument(2, basis)   ! optional: 'bspline' reruns every case with B-splines
   if (len_trim(basis) == 0) basis = 'hermite'

   ! 1. tip reaction
   scene = read_test_scene(trim(dir)//'/static_tip.nml')
   scene%mesh%basis = basis
   q = -scene%load%distributed
   g = -scene%obstacles(1)%level_from
   exact = 3*scene%beam%ei()*(q*scene%beam%length**4/(8*scene%beam%ei()) - g)/scene%beam%length**3
   ! its own rounding: 10 operations on terms of size 3EI(|q|L^4/(8EI) + |g|)/L^3
   exact_error = gamma_n(10)*3*scene%beam%ei()*(abs(q)*scene%beam%length**4/(8*scene%beam%ei()) + abs(g))/scene%beam%length**3
   write (output_unit, '(a,es22.14,a)') 'closed-form tip reaction ', exact, ' N'
   do k = 1, size(meshes)
      scene%mesh%elements = meshes(k)
      call prepare_test_scene(scene, prepared)
      call solve(prepared, u, r, du, dr)
      write (output_unit, '(a,i3,a,es22.14,a,es9.2)') 'N = ', meshes(k), ': R = ', r(1), '; round-off bound ', dr(1)
      write (label, '(a,i0)') 'tip reaction, N = ', meshes(k)
      call t%check_close(trim(label), abs(r(1) - exact), 0.0_dp, 1.0_dp, dr(1) + exact_error)
      write (label, '(a,i0)') 'tip rests on the obstacle, N = ', meshes(k)
      call t%check_close(trim(label), abs(contact_value(prepared%contacts, 1, u) + g), 0.0_dp, 1.0_dp, &
                         held_residual(1, u, du))
   end do

   ! 2. longitudinal obstacle
   scene = read_test_scene(trim(dir)//'/static_longitudinal.nml')
   scene%mesh%basis = basis
   do k = 1, 3
      call prepare_test_scene(scene, prepared)
      call solve(prepared, u, r, du, dr)
      scale = maxval(abs(r))
      write (label, '(a,i0)') 'N = ', scene%mesh%elements
      call t%check_true(trim(label)//': reactions are non-negative', all(r >= 0))
      gap = [(contact_value(prepared%contacts, c, u) - prepared%contacts%lower(c), c=1, prepared%contacts%count)]
      call t%check_true(trim(label)//': no node penetrates beyond its round-off bound', &
                        all(gap >= -[(held_residual(c, u, du), c=1, prepared%contacts%count)]))
      ! contact set: nodes with a reaction; between its ends the beam may lift off the
      ! obstacle, since only nodes are constrained: that lift-off must vanish as h -> 0
      first = findloc(r > 0, .true., dim=1)
      last = findloc(r > 0, .true., dim=1, back=.true.)
      lift_off(k) = maxval(gap(first:last))
      write (output_unit, '(a,i4,a,f6.3,a,f6.3,a,es10.3,a,es10.3)') 'N = ', scene%mesh%elements, ': contact from x = ', &
         prepared%contacts%x(first), ' to ', prepared%contacts%x(last), ', largest lift-off inside ', lift_off(k), &
         ' m, edge reaction ', r(first)
      call t%check_true(trim(label)//': contact set ends at the tip', last == prepared%contacts%count)
      if (k == 1) then
         u_whole = u
         r_whole = r
         du_whole = du
         dr_whole = dr
      end if
      scene%mesh%elements = 2*scene%mesh%elements
   end do
   call t%check_true('contact set is an interval up to a lift-off that vanishes with h (at least like h^2)', &
                     lift_off(3) <= lift_off(1)/16)

   ! 3. the same obstacle in pieces, listed in another order
   scene = read_test_scene(trim(dir)//'/static_longitudinal_pieces.nml')
   scene%mesh%basis = basis
   call prepare_test_scene(scene, prepared)
   call solve(prepared, u, r, du, dr)
   ! both solutions lie within their round-off bounds of the same exact one (the pieces'
   ! levels, interpolated, may differ from the whole's in the last bit: inside the bounds)
   call t%check_close('pieces vs whole: displacement (largest difference / its bound)', &
                      maxval(abs(u - u_whole)/(du_whole + du)), 0.0_dp, 1.0_dp, 1.0_dp)
   call t%check_close('pieces vs whole: reactions (largest difference / its bound)', &
                      maxval(abs(r - r_whole)/(dr_whole + dr + tiny(1.0_dp))), 0.0_dp, 1.0_dp, 1.0_dp)
   call t%finish('test_static')

contains

   !> solve_static, and the derived round-off bounds of its U and R (`static_report`).
   subroutine solve(prepared, u, reaction, u_error, reaction_error)
      type(run_problem), intent(in) :: prepared
      real(dp), allocatable, intent(out) :: u(:), reaction(:), u_error(:), reaction_error(:)
      type(static_report) :: report
      integer :: iterations, stat
      character(len=512) :: errmsg
      allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count))
      call solve_static(prepared%model, prepared%contacts, prepared%loads%at(0.0_dp), u, reaction, iterations, stat, &
                        errmsg, report=report)
      if (stat /= 0) then
         write (output_unit, '(a)') 'solve_static: '//trim(errmsg)
         error stop 1
      end if
      u_error = report%unknown_bound
      reaction_error = report%reaction_bound
   end subroutine solve

   !> How far a held point's H_c U may be from its level: |H_c| times U's bound, plus the
   !! rounding of the sum H_c U (gamma_4) and of the level (gamma_3, interpolated).
   real(dp) function held_residual(c, u, u_error)
      integer, intent(in) :: c
      real(dp), intent(in) :: u(:), u_error(:)
      integer :: a
      held_residual = gamma_n(3)*abs(prepared%contacts%lower(c))
      do a = 1, 4
         if (prepared%contacts%dofs(a, c) == 0) cycle
         held_residual = held_residual + abs(prepared%contacts%weights(a, c))* &
                         (u_error(prepared%contacts%dofs(a, c)) + gamma_n(4)*abs(u(prepared%contacts%dofs(a, c))))
      end do
   end function held_residual
end program test_static
