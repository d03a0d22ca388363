!> Verification of static contact (theory §7, issue 3):
!! 1. static_tip.nml: tip reaction R = 3EI(qL^4/(8EI) - g)/L^3 for N = 1, 2, 16, 64, with
!!    both contact solvers: with a consistent load vector, Hermite cubic elements give the
!!    exact nodal values of a beam (the exact solution, a quartic, is matched at the
!!    nodes), so R is exact up to round-off.
!! 2. static_longitudinal.nml: beam pressed onto a flat obstacle along its length, N = 40,
!!    80, 160: reactions >= 0, no node penetrates, the nodes with a reaction span an
!!    interval that ends at the tip; inside it the beam may lift off between reacting
!!    nodes (only nodes are constrained, theory §2), by an amount that must vanish as h -> 0;
!!    the 'delassus' and 'band' solvers agree.
!! An optional second argument 'bspline' runs every case with cubic B-splines.
!! 3. static_longitudinal_pieces.nml: the same obstacle as pieces listed out of order:
!!    the same displacement and reactions with the same solver.
!! Every round-off allowance is derived: `static_error_bounds` bounds the error of each
!! computed U and R componentwise (first order, from the backward errors of the solves
!! and the conditioning of the contact problem, computed for each mesh: cond(K) reaches
!! 2e10 at N = 160, so no fixed relative tolerance fits every mesh); the contact solver's
!! own acceptance of a pivoting solution (a point off the held set may sit inside its
!! obstacle, or a held point pull, by max(1e-12, 16 m eps) of the largest gap or impulse)
!! is added where it applies.
program test_static
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_setup, only: prepared_scene
   use vibrobeam_static, only: solve_static
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_static_bounds, only: static_error_bounds
   use vibrobeam_band, only: band_cholesky, band_factor, band_solve
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(prepared_scene) :: prepared
   character(len=512) :: dir
   character(len=16) :: basis
   real(dp), allocatable :: u_delassus(:), u_band(:), r_delassus(:), r_band(:), u_pieces(:), r_pieces(:)
   real(dp) :: q, g, exact, scale, exact_error, slack
   real(dp), allocatable :: du_delassus(:), du_band(:), dr_delassus(:), dr_band(:), du_whole(:), dr_whole(:), &
                            u_free(:)
   integer, parameter :: meshes(4) = [1, 2, 16, 64]
   integer :: k, c, first, last
   real(dp), allocatable :: gap(:), u_whole(:), r_whole(:)
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
      call solve(prepared, 'delassus', u_delassus, r_delassus, du_delassus, dr_delassus)
      call solve(prepared, 'band', u_band, r_band, du_band, dr_band)
      write (output_unit, '(a,i3,a,es22.14,a,es22.14,a,es9.2,a,es9.2)') 'N = ', meshes(k), ': delassus ', r_delassus(1), &
         ', band ', r_band(1), '; round-off bounds ', dr_delassus(1), ', ', dr_band(1)
      write (label, '(a,i0)') 'tip reaction (delassus), N = ', meshes(k)
      call t%check_close(trim(label), abs(r_delassus(1) - exact), 0.0_dp, 1.0_dp, dr_delassus(1) + exact_error)
      write (label, '(a,i0)') 'tip reaction (band), N = ', meshes(k)
      call t%check_close(trim(label), abs(r_band(1) - exact), 0.0_dp, 1.0_dp, dr_band(1) + exact_error)
      write (label, '(a,i0)') 'tip rests on the obstacle, N = ', meshes(k)
      call t%check_close(trim(label), abs(contact_value(prepared%contacts, 1, u_band) + g), 0.0_dp, 1.0_dp, &
                         held_residual(1, u_band, du_band))
   end do

   ! 2. longitudinal obstacle
   scene = read_test_scene(trim(dir)//'/static_longitudinal.nml')
   scene%mesh%basis = basis
   do k = 1, 3
      call prepare_test_scene(scene, prepared)
      call solve(prepared, 'delassus', u_delassus, r_delassus, du_delassus, dr_delassus)
      call solve(prepared, 'band', u_band, r_band, du_band, dr_band)
      scale = maxval(abs(r_band))
      write (label, '(a,i0)') 'N = ', scene%mesh%elements
      ! the band solver accepts a held point whose impulse is below -slack max|P| (then
      ! set to 0) and a free point inside its obstacle by slack times the gap scale
      slack = max(1e-12_dp, 16*prepared%contacts%count*epsilon(1.0_dp))
      call t%check_true(trim(label)//': reactions are non-negative', all(r_band >= -(dr_band + slack*scale)))
      u_free = prepared%loads%at(0.0_dp)
      call solve_free(u_free)
      gap = [(contact_value(prepared%contacts, c, u_band) - prepared%contacts%lower(c), c=1, prepared%contacts%count)]
      call t%check_true(trim(label)//': no node penetrates', all(gap >= -[(held_residual(c, u_band, du_band) + &
         slack*(maxval(abs([(contact_value(prepared%contacts, c, u_free), c=1, prepared%contacts%count)])) + &
                maxval(abs(prepared%contacts%lower))), c=1, prepared%contacts%count)]))
      ! contact set: nodes with a reaction; between its ends the beam may lift off the
      ! obstacle, since only nodes are constrained: that lift-off must vanish as h -> 0
      first = findloc(r_band > 1e-12_dp*scale, .true., dim=1)
      last = findloc(r_band > 1e-12_dp*scale, .true., dim=1, back=.true.)
      lift_off(k) = maxval(gap(first:last))
      write (output_unit, '(a,i4,a,f6.3,a,f6.3,a,es10.3,a,es10.3)') 'N = ', scene%mesh%elements, ': contact from x = ', &
         prepared%contacts%x(first), ' to ', prepared%contacts%x(last), ', largest lift-off inside ', lift_off(k), &
         ' m, edge reaction ', r_band(first)
      call t%check_true(trim(label)//': contact set ends at the tip', last == prepared%contacts%count)
      ! the two solvers differ by at most the sum of their round-off bounds (which carry the
      ! conditioning of the contact problem: cond(K) ~ 1e8 at N = 40, growing like N^4)
      call t%check_close(trim(label)//': delassus vs band, displacement (largest difference / its bound)', &
                         maxval(abs(u_delassus - u_band)/(du_delassus + du_band)), 0.0_dp, 1.0_dp, 1.0_dp)
      call t%check_close(trim(label)//': delassus vs band, reactions (largest difference / its bound)', &
                         maxval(abs(r_delassus - r_band)/(dr_delassus + dr_band + slack*scale)), 0.0_dp, 1.0_dp, 1.0_dp)
      if (k == 1) then
         u_whole = u_band
         r_whole = r_band
         du_whole = du_band
         dr_whole = dr_band
      end if
      scene%mesh%elements = 2*scene%mesh%elements
   end do
   call t%check_true('contact set is an interval up to a lift-off that vanishes with h (at least like h^2)', &
                     lift_off(3) <= lift_off(1)/16)

   ! 3. the same obstacle in pieces, listed in another order
   scene = read_test_scene(trim(dir)//'/static_longitudinal_pieces.nml')
   scene%mesh%basis = basis
   call prepare_test_scene(scene, prepared)
   call solve(prepared, 'band', u_pieces, r_pieces, du_band, dr_band)   ! bounds of the pieces' solution
   ! both solutions lie within their round-off bounds of the same exact one (the pieces'
   ! levels, interpolated, may differ from the whole's in the last bit: inside the bounds)
   call t%check_close('pieces vs whole: displacement (largest difference / its bound)', &
                      maxval(abs(u_pieces - u_whole)/(du_whole + du_band)), 0.0_dp, 1.0_dp, 1.0_dp)
   call t%check_close('pieces vs whole: reactions (largest difference / its bound)', &
                      maxval(abs(r_pieces - r_whole)/(dr_whole + dr_band + tiny(1.0_dp))), 0.0_dp, 1.0_dp, 1.0_dp)
   call t%finish('test_static')

contains

   !> solve_static, and the round-off bounds of its U and R (`static_error_bounds`).
   subroutine solve(prepared, regime, u, reaction, u_error, reaction_error)
      type(prepared_scene), intent(in) :: prepared
      character(len=*), intent(in) :: regime
      real(dp), allocatable, intent(out) :: u(:), reaction(:), u_error(:), reaction_error(:)
      integer :: iterations, stat
      character(len=512) :: errmsg
      allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count))
      call solve_static(prepared%model%stiffness, prepared%contacts, prepared%loads%at(0.0_dp), regime, u, reaction, &
                        iterations, stat, errmsg)
      if (stat /= 0) then
         write (output_unit, '(a)') 'solve_static ('//regime//'): '//trim(errmsg)
         error stop 1
      end if
      allocate (u_error(size(u)), reaction_error(size(reaction)))
      call static_error_bounds(prepared%model%stiffness, prepared%contacts, prepared%loads%at(0.0_dp), u, reaction, &
                               regime, u_error, reaction_error)
   end subroutine solve

   !> K^-1 F (the free solution, for the solver's gap scale).
   subroutine solve_free(x)
      real(dp), intent(inout) :: x(:)
      type(band_cholesky) :: chol
      integer :: stat
      character(len=200) :: errmsg
      call band_factor(prepared%model%stiffness, chol, stat, errmsg)
      call band_solve(chol, x)
   end subroutine solve_free

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
