!> Natural frequencies of beams on every pair of end supports and on end springs, from the
!! library's modes (`compute_modes`, both solver paths, both bases), against the continuum
!! (docs/theory.md §7, "Other supports"):
!!
!! - the ten pairs among clamped, pinned, sliding and free: the roots b_n of each pair's
!!   frequency equation quoted to 20 digits from `python3 scripts/support_roots.py`
!!   (60-digit decimal arithmetic), omega_n = b_n^2 sqrt(EI/(rho S))/L^2, and the rigid-body
!!   modes (free-free 2, pinned-free, sliding-free and sliding-sliding 1) reported as
!!   omega = 0 exactly; the closed forms of `boundary%natural_frequency` against the same
!!   roots;
!! - end springs: the frequency equation of the beam with springs written here as a 4 x 4
!!   determinant of the boundary rows (module `spring_determinant` below, derived in
!!   docs/theory.md §7 from the energy 1/2 int EI u''^2 + 1/2 k u(end)^2 + 1/2 k_r
!!   u'(end)^2), its roots by bisection; and the limits k -> 0 and k -> infinity against
!!   the pairs' roots.
!!
!! What is checked, and the tolerances:
!! - convergence: the relative error of omega falls like h^4 for conforming cubic elements
!!   [Strang & Fix 1973, ch. 6]; the observed order between N = 16 and N = 32 must lie in
!!   [3.5, 4.5] (asymptotic; measured 3.9 to 4.1), and at N = 128 the error must be below
!!   1.5 times the h^4 extrapolation of the N = 32 one plus the round-off of the Rayleigh
!!   quotient (8 N eps): h^4 down to about 1e-12;
!! - size: at N = 32 the relative error must be below (beta_n h)^4/100: the Hermite error
!!   constant of a clamped-free beam is 1/1440 [theory §7, measured], B-splines' about 6
!!   times larger, so 1/100 leaves a margin of 2 to 14 for the constants of the other
!!   supports (measured: the largest ratio is printed);
!! - round-off: the two solver paths (dense dsbgvx and shift-invert Lanczos) agree to
!!   1e-10 relative at N = 32: both return the Rayleigh quotient of an eigenvector whose
!!   error is at most eps cond(K + s M) ~ 1e-16 x 1e9, squared in the quotient;
!! - the rigid-body modes are exactly 0 (the structure counts them, `rigid_motions`);
!! - the closed forms of the module: the 20-digit roots to 8 eps (Newton's method ends
!!   within a few roundings of the root, squared in omega);
!! - springs: the spring's root by bisection to 1e-14 relative (the determinant's rows are
!!   O(1) for b < 12); the limits: with k L^3/EI = 1e-6 the frequency lies within 1e-5 of
!!   the free end's (the first-order shift is k phi(L)^2/(2 modal stiffness) = O(k L^3/EI)
!!   relative), with 1e7 within 1e-5 of the pinned end's (O(EI/(k L^3)) relative), plus the
!!   discretization error at N = 32.
program test_support_modes
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_model, only: beam_model, build_model, rigid_motions
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_boundary, only: boundary_conditions, end_clamped, end_pinned, end_sliding, end_free
   use vibrobeam_test_support, only: test_counter, wave_row, scanned_roots
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 0.8_dp, rho_s = 2.5_dp, ei = 40.0_dp
   ! roots b_1, b_2 of each equation, 20 digits (scripts/support_roots.py)
   real(dp), parameter :: root_cf(2) = [1.8751040687119611664_dp, 4.6940911329741745764_dp]
   real(dp), parameter :: root_cc(2) = [4.7300407448627040260_dp, 7.8532046240958375565_dp]
   real(dp), parameter :: root_cp(2) = [3.9266023120479187782_dp, 7.0685827456287320886_dp]
   real(dp), parameter :: root_cs(2) = [2.3650203724313520130_dp, 5.4978039190008354533_dp]
   real(dp), parameter :: root_pp(2) = [pi, 2*pi]
   real(dp), parameter :: root_sp(2) = [0.5_dp*pi, 1.5_dp*pi]
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   real(dp) :: worst_ratio = 0
   type(boundary_conditions) :: current_supports   !! the case `spring_roots` solves
   real(dp) :: current_kappa(4)
   integer :: b
   do b = 1, 2
      call check_pair(bases(b), end_clamped, end_free, root_cf, 0)
      call check_pair(bases(b), end_clamped, end_clamped, root_cc, 0)
      call check_pair(bases(b), end_free, end_free, root_cc, 2)
      call check_pair(bases(b), end_pinned, end_pinned, root_pp, 0)
      call check_pair(bases(b), end_sliding, end_sliding, root_pp, 1)
      call check_pair(bases(b), end_clamped, end_pinned, root_cp, 0)
      call check_pair(bases(b), end_pinned, end_free, root_cp, 1)
      call check_pair(bases(b), end_clamped, end_sliding, root_cs, 0)
      call check_pair(bases(b), end_sliding, end_free, root_cs, 1)
      call check_pair(bases(b), end_sliding, end_pinned, root_sp, 0)
      ! the mirror images: the same frequencies
      call check_pair(bases(b), end_free, end_clamped, root_cf, 0)
      call check_pair(bases(b), end_pinned, end_sliding, root_sp, 0)
      ! end springs (k L^3/EI = 10 at a cantilever's tip; k_r L/EI = 5 at both ends of a
      ! pinned-pinned beam; a free-free beam on two springs of k L^3/EI = 100)
      call check_springs(bases(b), boundary_conditions(end_clamped, end_free, right_spring=10*ei/length**3), &
                         [0.0_dp, 0.0_dp, 10.0_dp, 0.0_dp])
      call check_springs(bases(b), boundary_conditions(end_pinned, end_pinned, left_rotational_spring=5*ei/length, &
                                                       right_rotational_spring=5*ei/length), [0.0_dp, 5.0_dp, 0.0_dp, 5.0_dp])
      call check_springs(bases(b), boundary_conditions(end_free, end_free, left_spring=100*ei/length**3, &
                                                       right_spring=100*ei/length**3), [100.0_dp, 0.0_dp, 100.0_dp, 0.0_dp])
      ! the limits of a spring at a cantilever's tip
      call check_limit(bases(b), boundary_conditions(end_clamped, end_free, right_spring=1e-6_dp*ei/length**3), root_cf)
      call check_limit(bases(b), boundary_conditions(end_clamped, end_free, right_spring=1e7_dp*ei/length**3), root_cp)
   end do
   call check_closed_forms()
   print '(a,es10.3)', 'largest relative error / (beta h)^4 at N = 32: ', worst_ratio
   call t%finish('test_support_modes')

contains

   !> omega_n (rad/s) of the continuum for the root b of its frequency equation.
   pure real(dp) function omega_of(root)
      real(dp), intent(in) :: root
      omega_of = root**2*sqrt(ei/rho_s)/length**2
   end function omega_of

   !> The first `rigid` + 2 modes of the pair at N = 8, 16, 32: rigid ones 0, flexible ones
   !! against the roots, with the order of convergence; the dense and Lanczos paths at N = 32.
   subroutine check_pair(basis, left, right, roots, rigid)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: left, right, rigid
      real(dp), intent(in) :: roots(2)
      type(boundary_conditions) :: supports
      real(dp) :: error(5, 2), omega(rigid + 2), omega_dense(rigid + 2), omega_lanczos(rigid + 2)
      integer :: level, n, k
      character(len=:), allocatable :: label
      supports = boundary_conditions(left, right)
      label = basis//' '//supports%name()
      do level = 1, 5
         n = 8*2**(level - 1)
         call frequencies(basis, n, supports, rigid + 2, omega)
         if (level == 3) then
            call frequencies(basis, n, supports, rigid + 2, omega_dense, 'dense')
            call frequencies(basis, n, supports, rigid + 2, omega_lanczos, 'lanczos')
         end if
         do k = 1, 2
            error(level, k) = abs(omega(rigid + k) - omega_of(roots(k)))/omega_of(roots(k))
         end do
      end do
      write (*, '(a40,a,5es10.2)') label, ' rel. error of omega_1, N = 8..128:', error(:, 1)
      write (*, '(a40,a,5es10.2)') label, ' rel. error of omega_2, N = 8..128:', error(:, 2)
      call t%check_true(label//': '//digit(rigid)//' rigid-body modes at omega = 0', &
                        .not. (any(abs(omega_dense(1:rigid)) > 0) .or. any(abs(omega_lanczos(1:rigid)) > 0) .or. &
                               any(abs(omega(1:rigid)) > 0)))
      do k = 1, 2
         call t%check_close(label//': order of omega_'//digit(k)//' (N = 16 to 32)', &
                            log(error(2, k)/error(3, k))/log(2.0_dp), 4.0_dp, 0.5_dp/4)
         call t%check_close(label//': omega_'//digit(k)//' at N = 32, relative error', error(3, k), 0.0_dp, 1.0_dp, &
                            (roots(k)/32)**4/100)
         ! at N = 128 the h^4 law predicts (1/4)^4 of the N = 32 error; round-off of the Rayleigh
         ! quotient (a sum of 4N positive terms, 8N eps relative) and of the reference add to it
         call t%check_close(label//': omega_'//digit(k)//' at N = 128 follows h^4', error(5, k), 0.0_dp, 1.0_dp, &
                            1.5_dp*error(3, k)/256 + 8*128*epsilon(1.0_dp))
         worst_ratio = max(worst_ratio, error(3, k)/(roots(k)/32)**4)
         call t%check_close(label//': omega_'//digit(k)//' dense against Lanczos', omega_lanczos(rigid + k), &
                            omega_dense(rigid + k), 1e-10_dp)
      end do
   end subroutine check_pair

   !> The first two flexible modes with end springs against the roots of the spring
   !! determinant (`kappa`: k L^3/EI and k_r L/EI at the left end, then at the right end).
   subroutine check_springs(basis, supports, kappa)
      character(len=*), intent(in) :: basis
      type(boundary_conditions), intent(in) :: supports
      real(dp), intent(in) :: kappa(4)
      real(dp) :: roots(2), error(2, 2), omega(2)
      integer :: level, k
      character(len=:), allocatable :: label
      label = basis//' '//supports%name()
      roots = spring_roots(supports, kappa)
      do level = 1, 2
         call frequencies(basis, 16*level, supports, 2, omega)
         do k = 1, 2
            error(level, k) = abs(omega(k) - omega_of(roots(k)))/omega_of(roots(k))
         end do
      end do
      do k = 1, 2
         call t%check_close(label//': order of omega_'//digit(k)//' (N = 16 to 32)', &
                            log(error(1, k)/error(2, k))/log(2.0_dp), 4.0_dp, 0.5_dp/4)
         call t%check_close(label//': omega_'//digit(k)//' at N = 32, relative error', error(2, k), 0.0_dp, 1.0_dp, &
                            (roots(k)/32)**4/100)
      end do
   end subroutine check_springs

   !> A very soft or very stiff tip spring: the frequencies of the end it tends to.
   subroutine check_limit(basis, supports, roots)
      character(len=*), intent(in) :: basis
      type(boundary_conditions), intent(in) :: supports
      real(dp), intent(in) :: roots(2)
      real(dp) :: omega(2)
      integer :: k
      call frequencies(basis, 32, supports, 2, omega)
      do k = 1, 2
         call t%check_close(basis//' '//supports%name()//', k L^3/EI = '//trim(short_text(supports%right_spring*length**3/ei))// &
                            ': omega_'//digit(k)//' against its limit', omega(k), omega_of(roots(k)), &
                            1e-5_dp + (roots(k)/32)**4/100)
      end do
   end subroutine check_limit

   !> The module's closed forms against the quoted roots.
   subroutine check_closed_forms()
      call closed(end_clamped, end_free, root_cf, 0)
      call closed(end_clamped, end_clamped, root_cc, 0)
      call closed(end_free, end_free, root_cc, 2)
      call closed(end_pinned, end_pinned, root_pp, 0)
      call closed(end_sliding, end_sliding, root_pp, 1)
      call closed(end_pinned, end_clamped, root_cp, 0)
      call closed(end_free, end_pinned, root_cp, 1)
      call closed(end_sliding, end_clamped, root_cs, 0)
      call closed(end_free, end_sliding, root_cs, 1)
      call closed(end_pinned, end_sliding, root_sp, 0)
   end subroutine check_closed_forms

   subroutine closed(left, right, roots, rigid)
      integer, intent(in) :: left, right, rigid
      real(dp), intent(in) :: roots(2)
      type(boundary_conditions) :: supports
      integer :: k
      supports = boundary_conditions(left, right)
      call t%check_true('closed form '//supports%name()//' exists', supports%has_closed_form())
      do k = 1, rigid
         call t%check_true('closed form '//supports%name()//': rigid mode '//digit(k)//' at 0', &
                           .not. abs(supports%natural_frequency(k, length, ei/rho_s)) > 0)
      end do
      do k = 1, 2
         call t%check_close('closed form '//supports%name()//': omega_'//digit(rigid + k), &
                            supports%natural_frequency(rigid + k, length, ei/rho_s), omega_of(roots(k)), &
                            8*epsilon(1.0_dp))
      end do
   end subroutine closed

   !> The `count` lowest omega of the library's model (compute_modes, the given path).
   subroutine frequencies(basis, elements, supports, count, omega, method)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements, count
      type(boundary_conditions), intent(in) :: supports
      real(dp), intent(out) :: omega(:)
      character(len=*), intent(in), optional :: method
      type(beam_model) :: model
      real(dp), allocatable :: values(:), shapes(:,:), vectors(:,:)
      integer :: stat
      character(len=256) :: errmsg
      call build_model(basis, elements, length, rho_s, ei, model, stat, errmsg, boundary=supports)
      if (stat == 0) call compute_modes(model, count, values, shapes, vectors, stat, errmsg, method)
      if (stat /= 0) then
         call t%check_true(basis//' '//supports%name()//': modes computed', .false., errmsg)
         omega = -1
         return
      end if
      omega = values
      if (present(method)) then
         call t%check_true(basis//' '//supports%name()//': rigid_motions', rigid_motions(model) == count - 2)
      end if
   end subroutine frequencies

   !> The two lowest positive roots b of the spring determinant (bisection on sign changes
   !! of a scan of step 0.01 from b = 0.05: `scanned_roots`).
   function spring_roots(supports, kappa) result(roots)
      type(boundary_conditions), intent(in) :: supports
      real(dp), intent(in) :: kappa(4)
      real(dp) :: roots(2)
      current_supports = supports
      current_kappa = kappa
      roots = scanned_roots(spring_at, 2, 0.05_dp, 0.01_dp, 20.0_dp)
   end function spring_roots

   !> The spring determinant of `spring_roots`'s case at b.
   real(dp) function spring_at(root)
      real(dp), intent(in) :: root
      spring_at = spring_determinant(current_supports, current_kappa, root)
   end function spring_at

   !> det of the four boundary rows of phi(xi) = a cosh(b xi) + c sinh(b xi) + d cos(b xi)
   !! + e sin(b xi), xi = x/L, b = beta L: the natural conditions of the energy
   !! 1/2 int EI u''^2 + 1/2 k u(end)^2 + 1/2 k_r u'(end)^2, divided by EI/L^3 (shear) and
   !! EI/L^2 (moment): at a held deflection phi = 0, else +-phi''' + kappa phi = 0 (+ at
   !! x = 0, - at x = L, kappa = k L^3/EI); at a held rotation phi' = 0, else
   !! phi'' -+ kappa_r phi' = 0 (kappa_r = k_r L/EI); derivatives in xi.
   real(dp) function spring_determinant(supports, kappa, root) result(det)
      type(boundary_conditions), intent(in) :: supports
      real(dp), intent(in) :: kappa(4), root
      real(dp) :: rows(4, 4)
      integer :: side
      do side = 1, 2
         associate (xi => real(side - 1, dp), sgn => merge(1.0_dp, -1.0_dp, side == 1))
            if (supports%holds_deflection(side)) then
               rows(2*side - 1, :) = basis_row(root, xi, 0)
            else
               rows(2*side - 1, :) = sgn*root**3*basis_row(root, xi, 3) + kappa(2*side - 1)*basis_row(root, xi, 0)
            end if
            if (supports%holds_rotation(side)) then
               rows(2*side, :) = basis_row(root, xi, 1)
            else
               rows(2*side, :) = root**2*basis_row(root, xi, 2) - sgn*kappa(2*side)*root*basis_row(root, xi, 1)
            end if
         end associate
      end do
      det = determinant4(rows)
   end function spring_determinant

   !> The order-th xi-derivatives of cosh(b xi), sinh(b xi), cos(b xi), sin(b xi), / b^order.
   pure function basis_row(root, xi, order) result(row)
      real(dp), intent(in) :: root, xi
      integer, intent(in) :: order
      real(dp) :: row(4)
      row = wave_row(root*xi, order)
   end function basis_row

   !> Determinant of a 4 x 4 matrix by Laplace expansion along the first row.
   pure real(dp) function determinant4(a)
      real(dp), intent(in) :: a(4, 4)
      integer :: j, columns(3), k
      determinant4 = 0
      do j = 1, 4
         columns = pack([(k, k=1, 4)], [(k /= j, k=1, 4)])
         determinant4 = determinant4 + (-1)**(j + 1)*a(1, j)*determinant3(a(2:4, columns))
      end do
   end function determinant4

   pure real(dp) function determinant3(a)
      real(dp), intent(in) :: a(3, 3)
      determinant3 = a(1, 1)*(a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)) - a(1, 2)*(a(2, 1)*a(3, 3) - a(2, 3)*a(3, 1)) + &
                     a(1, 3)*(a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1))
   end function determinant3

   pure function digit(k) result(text)
      integer, intent(in) :: k
      character(len=1) :: text
      text = achar(48 + k)
   end function digit

   function short_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=16) :: text
      write (text, '(es9.2)') value
      text = adjustl(text)
   end function short_text
end program test_support_modes
