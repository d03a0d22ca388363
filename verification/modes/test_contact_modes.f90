!> Modes in contact (issue 18, item 7; &analysis contact_modes): the natural modes of the
!! beam with every contact point held at its obstacle (`contact_modes`), both bases,
!! against the closed forms of the beams they are (docs/theory.md §7):
!! - a cantilever with a stop at its tip: the clamped-pinned beam, tan b = tanh b,
!!   b = 3.9266023120479187782, 7.0685827456287320886 (scripts/support_roots.py);
!! - a pinned-pinned beam with a stop at midspan: two pinned-pinned spans and two
!!   clamped-pinned ones, b = 2 pi, 2 x 3.9266023120479187782;
!! - a free-free beam with stops at both ends (K singular: the dense path): pinned-pinned,
!!   b = pi, 2 pi.
!! The contact points' own frequencies (the holding) must be gone: exactly J - m modes
!! exist. Tolerances as test_support_modes.f90: the observed order between N = 16 and 32
!! in [3.5, 4.5], the relative error at N = 32 below (b/32)^4/100.
program test_contact_modes
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: integer_text
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_boundary, only: boundary_conditions, end_clamped, end_pinned, end_free
   use vibrobeam_obstacles, only: obstacle_type, build_contact_points
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_reduction, only: contact_modes
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 0.8_dp, rho_s = 2.5_dp, ei = 40.0_dp
   real(dp), parameter :: clamped_pinned(2) = [3.9266023120479187782_dp, 7.0685827456287320886_dp]
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   integer :: b
   do b = 1, 2
      call check(bases(b), 'cantilever with a tip stop', boundary_conditions(end_clamped, end_free), [length], &
                 clamped_pinned)
      call check(bases(b), 'pinned-pinned with a midspan stop', boundary_conditions(end_pinned, end_pinned), &
                 [length/2], [2*pi, 2*clamped_pinned(1)])
      call check(bases(b), 'free-free with stops at both ends', boundary_conditions(end_free, end_free), &
                 [0.0_dp, length], [pi, 2*pi])
   end do
   call t%finish('test_contact_modes')

contains

   subroutine check(basis, name, ends, stops, roots)
      character(len=*), intent(in) :: basis, name
      type(boundary_conditions), intent(in) :: ends
      real(dp), intent(in) :: stops(:), roots(2)
      real(dp) :: error(2, 2)
      integer :: level, k
      character(len=:), allocatable :: label
      real(dp), allocatable :: omega(:)
      label = basis//' '//name
      do level = 1, 2
         call held_frequencies(basis, 16*level, ends, stops, omega)
         if (size(omega) < 2) return
         do k = 1, 2
            error(level, k) = abs(omega(k) - roots(k)**2*sqrt(ei/rho_s)/length**2)/(roots(k)**2*sqrt(ei/rho_s)/length**2)
         end do
      end do
      write (*, '(a45,a,2es10.2,a,2es10.2)') label, ': rel. error of omega_1, omega_2 at N = 16:', error(1, :), &
         ', N = 32:', error(2, :)
      do k = 1, 2
         call t%check_close(label//': order of omega_'//integer_text(k)//' (N = 16 to 32)', &
                            log(error(1, k)/error(2, k))/log(2.0_dp), 4.0_dp, 0.5_dp/4)
         call t%check_close(label//': omega_'//integer_text(k)//' at N = 32, relative error', error(2, k), 0.0_dp, &
                            1.0_dp, (roots(k)/32)**4/100)
      end do
   end subroutine check

   !> The modes in contact of the beam on `ends` with a rigid stop under each x of `stops`.
   subroutine held_frequencies(basis, elements, ends, stops, omega)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(boundary_conditions), intent(in) :: ends
      real(dp), intent(in) :: stops(:)
      real(dp), allocatable, intent(out) :: omega(:)
      type(beam_model) :: model
      type(contact_set) :: contacts
      type(obstacle_type) :: obstacles(size(stops))
      real(dp), allocatable :: shapes(:,:), all_omega(:)
      character(len=:), allocatable :: warnings
      character(len=256) :: errmsg
      integer :: stat, k
      do k = 1, size(stops)
         obstacles(k) = obstacle_type(side='below', x_from=stops(k), x_to=stops(k), level_from=-1e-3_dp, &
                                      level_to=-1e-3_dp)
      end do
      allocate (character(len=0) :: warnings)
      allocate (omega(0))
      call build_model(basis, elements, length, rho_s, ei, model, stat, errmsg, boundary=ends)
      if (stat == 0) call build_contact_points(obstacles, model, contacts, warnings, stat, errmsg)
      if (stat == 0) call contact_modes(model, contacts, 2, omega, shapes, stat, errmsg)
      call t%check_true(basis//': contact modes computed', stat == 0, trim(errmsg))
      if (stat /= 0) return
      ! every mode of the held beam, and no more: J - m
      call contact_modes(model, contacts, model%unknowns - contacts%count, all_omega, shapes, stat, errmsg)
      call t%check_true(basis//': the held beam has J - m modes, all with omega > 0', &
                        stat == 0 .and. all(all_omega > 0), trim(errmsg))
      call contact_modes(model, contacts, model%unknowns - contacts%count + 1, all_omega, shapes, stat, errmsg)
      call t%check_true(basis//': J - m + 1 modes are refused', stat /= 0)
   end subroutine held_frequencies
end program test_contact_modes
