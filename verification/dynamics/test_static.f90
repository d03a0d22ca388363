!> Verification of static contact (SPEC §6, issue 3):
!! 1. static_tip.nml: tip reaction R = 3EI(qL^4/(8EI) - g)/L^3 to 1e-8 relative for
!!    N = 1, 2, 16, 64, with both contact solvers: with a consistent load vector, Hermite
!!    cubic elements give the exact nodal values of a beam (the exact solution, a quartic,
!!    is matched at the nodes), so R is exact up to round-off.
!! 2. static_longitudinal.nml: beam pressed onto a flat obstacle along its length, N = 40,
!!    80, 160: reactions >= 0, no node penetrates, the nodes with a reaction span an
!!    interval that ends at the tip; inside it the beam may lift off between reacting
!!    nodes (only nodes are constrained, SPEC §2), by an amount that must vanish as h -> 0;
!!    the 'delassus' and 'band' solvers agree (1e-8 in U, 1e-6 in reactions: both carry
!!    the conditioning of K, ~1e8 at N = 40 and growing like N^4).
!! An optional second argument 'bspline' runs every case with cubic B-splines.
!! 3. static_longitudinal_pieces.nml: the same obstacle as pieces listed out of order:
!!    the same displacement and reactions with the same solver (to 1e-12).
program test_static
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type, ei_of
   use vibrobeam_setup, only: prepared_scene
   use vibrobeam_static, only: solve_static
   use vibrobeam_contact_points, only: contact_value
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(prepared_scene) :: prepared
   character(len=512) :: dir
   character(len=16) :: basis
   real(dp), allocatable :: u_delassus(:), u_band(:), r_delassus(:), r_band(:), u_pieces(:), r_pieces(:)
   real(dp) :: q, g, exact, scale
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
   scene%basis = basis
   q = -scene%distributed
   g = -scene%obstacles(1)%level_from
   exact = 3*ei_of(scene)*(q*scene%length**4/(8*ei_of(scene)) - g)/scene%length**3
   write (output_unit, '(a,es22.14,a)') 'closed-form tip reaction ', exact, ' N'
   do k = 1, size(meshes)
      scene%elements = meshes(k)
      call prepare_test_scene(scene, prepared)
      call solve(prepared, 'delassus', u_delassus, r_delassus)
      call solve(prepared, 'band', u_band, r_band)
      write (output_unit, '(a,i3,a,es22.14,a,es22.14)') 'N = ', meshes(k), ': delassus ', r_delassus(1), &
         ', band ', r_band(1)
      write (label, '(a,i0)') 'tip reaction (delassus), N = ', meshes(k)
      call t%check_close(trim(label), r_delassus(1), exact, 1e-8_dp)
      write (label, '(a,i0)') 'tip reaction (band), N = ', meshes(k)
      call t%check_close(trim(label), r_band(1), exact, 1e-8_dp)
      write (label, '(a,i0)') 'tip rests on the obstacle, N = ', meshes(k)
      call t%check_close(trim(label), contact_value(prepared%contacts, 1, u_band), -g, 1e-10_dp)
   end do

   ! 2. longitudinal obstacle
   scene = read_test_scene(trim(dir)//'/static_longitudinal.nml')
   scene%basis = basis
   do k = 1, 3
      call prepare_test_scene(scene, prepared)
      call solve(prepared, 'delassus', u_delassus, r_delassus)
      call solve(prepared, 'band', u_band, r_band)
      scale = maxval(abs(r_band))
      write (label, '(a,i0)') 'N = ', scene%elements
      call t%check_true(trim(label)//': reactions are non-negative', all(r_band >= -1e-12_dp*scale))
      gap = [(contact_value(prepared%contacts, c, u_band) - prepared%contacts%lower(c), c=1, prepared%contacts%count)]
      call t%check_true(trim(label)//': no node penetrates', all(gap >= -1e-12_dp*abs(prepared%contacts%lower)))
      ! contact set: nodes with a reaction; between its ends the beam may lift off the
      ! obstacle, since only nodes are constrained: that lift-off must vanish as h -> 0
      first = findloc(r_band > 1e-12_dp*scale, .true., dim=1)
      last = findloc(r_band > 1e-12_dp*scale, .true., dim=1, back=.true.)
      lift_off(k) = maxval(gap(first:last))
      write (output_unit, '(a,i4,a,f6.3,a,f6.3,a,es10.3,a,es10.3)') 'N = ', scene%elements, ': contact from x = ', &
         prepared%contacts%x(first), ' to ', prepared%contacts%x(last), ', largest lift-off inside ', lift_off(k), &
         ' m, edge reaction ', r_band(first)
      call t%check_true(trim(label)//': contact set ends at the tip', last == prepared%contacts%count)
      ! the two solvers differ by round-off amplified by the conditioning of K (~1e8 at N = 40,
      ! growing like N^4)
      call t%check_close(trim(label)//': delassus vs band, displacement', maxval(abs(u_delassus - u_band)), 0.0_dp, &
                         1.0_dp, 1e-8_dp*maxval(abs(u_band)))
      call t%check_close(trim(label)//': delassus vs band, reactions', maxval(abs(r_delassus - r_band)), 0.0_dp, &
                         1.0_dp, 1e-6_dp*scale)
      if (k == 1) then
         u_whole = u_band
         r_whole = r_band
      end if
      scene%elements = 2*scene%elements
   end do
   call t%check_true('contact set is an interval up to a lift-off that vanishes with h (at least like h^2)', &
                     lift_off(3) <= lift_off(1)/16)

   ! 3. the same obstacle in pieces, listed in another order
   scene = read_test_scene(trim(dir)//'/static_longitudinal_pieces.nml')
   scene%basis = basis
   call prepare_test_scene(scene, prepared)
   call solve(prepared, 'band', u_pieces, r_pieces)
   call t%check_close('pieces vs whole: displacement', maxval(abs(u_pieces - u_whole)), 0.0_dp, 1.0_dp, &
                      1e-12_dp*maxval(abs(u_whole)))
   call t%check_close('pieces vs whole: reactions', maxval(abs(r_pieces - r_whole)), 0.0_dp, 1.0_dp, &
                      1e-12_dp*maxval(abs(r_whole)))
   call t%finish('test_static')

contains

   subroutine solve(prepared, regime, u, reaction)
      type(prepared_scene), intent(in) :: prepared
      character(len=*), intent(in) :: regime
      real(dp), allocatable, intent(out) :: u(:), reaction(:)
      integer :: iterations, stat
      character(len=512) :: errmsg
      allocate (u(prepared%model%unknowns), reaction(prepared%contacts%count))
      call solve_static(prepared%model%stiffness, prepared%contacts, prepared%loads%at(0.0_dp), regime, u, reaction, &
                        iterations, stat, errmsg)
      if (stat /= 0) then
         write (output_unit, '(a)') 'solve_static ('//regime//'): '//trim(errmsg)
         error stop 1
      end if
   end subroutine solve
end program test_static
