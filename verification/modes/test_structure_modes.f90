!> Natural frequencies of beams with intermediate supports and point masses (issue 18,
!! item 2), from the library's modes (`compute_modes`, both solver paths, both bases),
!! against the frequency equations of the continuum written here independently
!! (docs/theory.md §7, "Intermediate supports and point masses"):
!!
!! - a transfer-matrix determinant: on each span between the points (x_0 = 0 < ... < 1,
!!   in xi = x/L) phi = A cosh(b xi) + B sinh(b xi) + C cos(b xi) + D sin(b xi),
!!   b = beta L, omega^2 = b^4 EI/(rho S L^4); four rows per end and per interior point
!!   from the energy 1/2 int EI u''^2 + 1/2 k u(x_p)^2 + 1/2 k_r u'(x_p)^2 - omega^2
!!   (1/2 int rho S u^2 + 1/2 m u(x_p)^2 + 1/2 J u'(x_p)^2): at a pinned point
!!   phi_left = phi_right = 0 and phi', phi'' continuous; at a clamped one both values and
!!   both slopes 0; at an elastic point or a mass, phi and phi' continuous,
!!   phi''_left - phi''_right + (kappa_r - b^4 j) phi' = 0 and
!!   phi'''_right - phi'''_left + (kappa - b^4 mu) phi = 0 (kappa = k L^3/EI,
!!   kappa_r = k_r L/EI, mu = m/(rho S L), j = J/(rho S L^3)); the ends as in
!!   test_support_modes.f90 with the end mass's terms. Its roots: sign changes of the
!!   determinant (`lu_determinant`: LAPACK dgetrf, the product of U's diagonal and the
!!   pivots' sign) on a scan of step 0.01, then bisection to 4 eps.
!! - closed forms where they exist: the two-span beam on three pinned supports with equal
!!   spans vibrates in pinned-pinned modes of each span, b_1 = 2 pi, and in
!!   clamped-pinned ones, b_2 = 2 x 3.9266023120479187782 (Blevins 1979, table 8-1); a
!!   vanishing tip mass or a very stiff spring support gives the roots of the pair without
!!   them (the limits, within O(mu) and O(1/kappa)).
!!
!! Cases: the two-span beam with equal and unequal spans (support at 3L/8), a cantilever
!! with a tip mass and rotary inertia (mu = 0.5, j = 0.02) and its mu -> 0 limit, a
!! cantilever on a spring support at midspan (kappa = 50, and kappa_r = 5 with Hermite
!! elements), a stiff spring support's limit (two spans), a free-free beam carrying two
!! masses (one with a rotary inertia, Hermite), and with Hermite elements a pinned-pinned
!! beam clamped at 3L/8 (two clamped-pinned spans: b = 3.9266/0.625, 3.9266/0.375). A
!! point moment inside a B-spline beam (a clamped or rotational-spring support, an inner
!! mass's rotary inertia) makes u'' jump, which C^2 splines cannot follow (measured: order 1,
!! 3.6e-3 at N = 32): B-splines refuse it, with a message naming the variable (checked).
!!
!! Tolerances (as test_support_modes.f90): the observed order between N = 16 and 32 in
!! [3.5, 4.5]; at N = 32 a relative error below (b_n/32)^4/100 (the supports sit on
!! nodes, so the kinks of the modes lie in the space and the order stays h^4); the dense
!! and Lanczos paths agree to 1e-10; the roots of the determinant to 4 eps by bisection.
!!
!! Also: the base excitation's load (`load_set`) on a free-free beam with masses equals
!! -s''(t) M r, r the rigid translation, to round-off (gamma_8 of |M| |r|): the inertial
!! load acts on the masses (theory §1) and the load vector and M are assembled apart.
program test_structure_modes
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: integer_text
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_boundary, only: boundary_conditions, end_clamped, end_pinned, end_free
   use vibrobeam_structure, only: beam_structure, support_pinned, support_clamped, support_spring
   use vibrobeam_loads, only: load_settings, load_set, build_loads
   use vibrobeam_band, only: band_matvec
   use vibrobeam_test_support, only: test_counter, wave_row, lu_determinant, scanned_roots
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 0.8_dp, rho_s = 2.5_dp, ei = 40.0_dp
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   !> an interior point: position xi, kind (0: elastic/mass, pinned, clamped), kappa,
   !! kappa_r, mu, j
   type :: point_data
      real(dp) :: xi = 0
      integer :: kind = 0
      real(dp) :: kappa = 0, kappa_r = 0, mu = 0, j = 0
   end type point_data
   type(beam_structure) :: s
   type(point_data), allocatable :: points(:)
   type(boundary_conditions) :: current_ends              !! the case `determinant_roots` solves
   type(point_data), allocatable :: current_points(:)
   integer :: b
   do b = 1, 2
      ! two spans on three pinned supports: equal (closed form too) and unequal
      s = structure(end_pinned, end_pinned)
      call add_support(s, 0.5_dp, support_pinned)
      points = [point_data(xi=0.5_dp, kind=support_pinned)]
      call check(bases(b), 'two equal spans', s, points, 0, [2*pi, 2*3.9266023120479187782_dp])
      s = structure(end_pinned, end_pinned)
      call add_support(s, 0.375_dp, support_pinned)
      points = [point_data(xi=0.375_dp, kind=support_pinned)]
      call check(bases(b), 'two spans 3:5', s, points, 0)
      ! a cantilever with a tip mass and rotary inertia, and its vanishing limit
      s = structure(end_clamped, end_free)
      call add_mass(s, 1.0_dp, 0.5_dp, 0.02_dp)
      points = [point_data(xi=1.0_dp, mu=0.5_dp, j=0.02_dp)]
      call check(bases(b), 'cantilever, tip mass 0.5, rotary inertia 0.02', s, points, 0)
      s = structure(end_clamped, end_free)
      call add_mass(s, 1.0_dp, 1e-7_dp, 0.0_dp)
      call limit(bases(b), 'cantilever, tip mass 1e-7', s, [1.8751040687119611664_dp, 4.6940911329741745764_dp])
      ! a cantilever on a spring support at midspan (with a rotational spring: Hermite only,
      ! B-splines refuse a point moment inside the beam), and a stiff support's limit
      s = structure(end_clamped, end_free)
      if (b == 1) then
         call add_support(s, 0.5_dp, support_spring, 50.0_dp, 5.0_dp)
         points = [point_data(xi=0.5_dp, kappa=50.0_dp, kappa_r=5.0_dp)]
      else
         call add_support(s, 0.5_dp, support_spring, 50.0_dp)
         points = [point_data(xi=0.5_dp, kappa=50.0_dp)]
      end if
      call check(bases(b), 'cantilever on a spring support', s, points, 0)
      s = structure(end_pinned, end_pinned)
      call add_support(s, 0.5_dp, support_spring, 1e8_dp)
      call limit(bases(b), 'two spans on a stiff spring support', s, [2*pi, 2*3.9266023120479187782_dp])
      ! a free-free beam carrying two masses (two rigid-body modes first; the inner one's
      ! rotary inertia with Hermite elements only)
      s = structure(end_free, end_free)
      call add_mass(s, 0.25_dp, 0.3_dp, 0.0_dp)
      if (b == 1) then
         call add_mass(s, 0.875_dp, 0.1_dp, 0.01_dp)
         points = [point_data(xi=0.25_dp, mu=0.3_dp), point_data(xi=0.875_dp, mu=0.1_dp, j=0.01_dp)]
      else
         call add_mass(s, 0.875_dp, 0.1_dp, 0.0_dp)
         points = [point_data(xi=0.25_dp, mu=0.3_dp), point_data(xi=0.875_dp, mu=0.1_dp)]
      end if
      call check(bases(b), 'free-free with two masses', s, points, 2)
      if (b == 1) then
         ! a pinned-pinned beam clamped at 3L/8: two clamped-pinned spans, b = 3.9266../0.625
         ! and 3.9266../0.375
         s = structure(end_pinned, end_pinned)
         call add_support(s, 0.375_dp, support_clamped)
         points = [point_data(xi=0.375_dp, kind=support_clamped)]
         call check(bases(b), 'pinned-pinned clamped at 3L/8', s, points, 0, &
                    [3.9266023120479187782_dp/0.625_dp, 3.9266023120479187782_dp/0.375_dp])
      else
         ! the point moments B-splines refuse, each with a message
         s = structure(end_pinned, end_pinned)
         call add_support(s, 0.375_dp, support_clamped)
         call refused('a clamped support inside the beam', s, '&supports kind(1)')
         s = structure(end_clamped, end_free)
         call add_support(s, 0.5_dp, support_spring, 50.0_dp, 5.0_dp)
         call refused('a rotational spring inside the beam', s, '&supports rotational_stiffness(1)')
         s = structure(end_free, end_free)
         call add_mass(s, 0.5_dp, 0.1_dp, 0.01_dp)
         call refused('a rotary inertia inside the beam', s, '&masses rotary_inertia(1)')
      end if
      call base_load_on_masses(bases(b))
   end do
   call t%finish('test_structure_modes')

contains

   function structure(left, right) result(st)
      integer, intent(in) :: left, right
      type(beam_structure) :: st
      st%boundary = boundary_conditions(left, right)
      allocate (st%support_x(0), st%support_kind(0), st%support_stiffness(0), st%support_rotational_stiffness(0))
      allocate (st%mass_position(0), st%mass_value(0), st%mass_rotary_inertia(0))
   end function structure

   !> A support at xi (kappa = k L^3/EI, kappa_r = k_r L/EI).
   subroutine add_support(st, xi, kind, kappa, kappa_r)
      type(beam_structure), intent(inout) :: st
      real(dp), intent(in) :: xi
      integer, intent(in) :: kind
      real(dp), intent(in), optional :: kappa, kappa_r
      real(dp) :: k, k_r
      k = 0
      k_r = 0
      if (present(kappa)) k = kappa*ei/length**3
      if (present(kappa_r)) k_r = kappa_r*ei/length
      st%support_x = [st%support_x, xi*length]
      st%support_kind = [st%support_kind, kind]
      st%support_stiffness = [st%support_stiffness, k]
      st%support_rotational_stiffness = [st%support_rotational_stiffness, k_r]
   end subroutine add_support

   !> A mass at xi (mu = m/(rho S L), j = J/(rho S L^3)).
   subroutine add_mass(st, xi, mu, j)
      type(beam_structure), intent(inout) :: st
      real(dp), intent(in) :: xi, mu, j
      st%mass_position = [st%mass_position, xi*length]
      st%mass_value = [st%mass_value, mu*rho_s*length]
      st%mass_rotary_inertia = [st%mass_rotary_inertia, j*rho_s*length**3]
   end subroutine add_mass

   pure real(dp) function omega_of(root)
      real(dp), intent(in) :: root
      omega_of = root**2*sqrt(ei/rho_s)/length**2
   end function omega_of

   !> The first two flexible modes at N = 16, 32 against the determinant's roots (and the
   !! closed form `exact` when given), with the order; dense against Lanczos at N = 32.
   subroutine check(basis, name, st, interior, rigid, exact)
      character(len=*), intent(in) :: basis, name
      type(beam_structure), intent(in) :: st
      type(point_data), intent(in) :: interior(:)
      integer, intent(in) :: rigid
      real(dp), intent(in), optional :: exact(2)
      real(dp) :: roots(2), error(2, 2), omega(rigid + 2), omega_dense(rigid + 2), omega_lanczos(rigid + 2)
      integer :: level, k
      character(len=:), allocatable :: label
      label = basis//' '//name
      roots = determinant_roots(st%boundary, interior)
      if (present(exact)) then
         ! the determinant's entries reach cosh(b) (3e3 at b = 8, 1.8e4 at b = 10.5), and its
         ! rows lose that factor to cancellation: its roots are good to about eps e^b
         do k = 1, 2
            call t%check_close(label//': determinant root '//integer_text(k)//' against the closed form', roots(k), &
                               exact(k), 4*epsilon(1.0_dp)*exp(roots(k)))
         end do
      end if
      do level = 1, 2
         call frequencies(basis, 16*level, st, rigid + 2, omega)
         do k = 1, 2
            error(level, k) = abs(omega(rigid + k) - omega_of(roots(k)))/omega_of(roots(k))
         end do
      end do
      call frequencies(basis, 32, st, rigid + 2, omega_dense, 'dense')
      call frequencies(basis, 32, st, rigid + 2, omega_lanczos, 'lanczos')
      write (*, '(a50,a,2es10.2,a,2es10.2)') label, ': rel. error of omega_1, omega_2 at N = 16:', error(1, :), &
         ', N = 32:', error(2, :)
      call t%check_true(label//': '//integer_text(rigid)//' rigid-body modes at omega = 0', &
                        .not. (any(abs(omega_dense(1:rigid)) > 0) .or. any(abs(omega_lanczos(1:rigid)) > 0)))
      do k = 1, 2
         call t%check_close(label//': order of omega_'//integer_text(k)//' (N = 16 to 32)', &
                            log(error(1, k)/error(2, k))/log(2.0_dp), 4.0_dp, 0.5_dp/4)
         call t%check_close(label//': omega_'//integer_text(k)//' at N = 32, relative error', error(2, k), 0.0_dp, &
                            1.0_dp, (roots(k)/32)**4/100)
         call t%check_close(label//': omega_'//integer_text(k)//' dense against Lanczos', omega_lanczos(rigid + k), &
                            omega_dense(rigid + k), 1e-10_dp)
      end do
   end subroutine check

   !> A structure tending to a pair without its point: the pair's roots, to the limit's
   !! O(mu) or O(1/kappa) (1e-6 here) plus the discretization error at N = 32.
   subroutine limit(basis, name, st, roots)
      character(len=*), intent(in) :: basis, name
      type(beam_structure), intent(in) :: st
      real(dp), intent(in) :: roots(2)
      real(dp) :: omega(2)
      integer :: k
      call frequencies(basis, 32, st, 2, omega)
      do k = 1, 2
         call t%check_close(basis//' '//name//': omega_'//integer_text(k)//' against its limit', omega(k), &
                            omega_of(roots(k)), 1e-6_dp + (roots(k)/32)**4/100)
      end do
   end subroutine limit

   !> B-splines refuse the structure with a message that names `names`.
   subroutine refused(what, st, names)
      character(len=*), intent(in) :: what, names
      type(beam_structure), intent(in) :: st
      type(beam_model) :: model
      integer :: stat
      character(len=256) :: errmsg
      call build_model('bspline', 32, length, rho_s, ei, model, stat, errmsg, structure=st)
      call t%check_true('bspline: '//what//' is refused, naming '//names, stat /= 0 .and. index(errmsg, names) == 1, &
                        trim(errmsg))
   end subroutine refused

   !> The `count` lowest omega of the library's model.
   subroutine frequencies(basis, elements, st, count, omega, method)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements, count
      type(beam_structure), intent(in) :: st
      real(dp), intent(out) :: omega(:)
      character(len=*), intent(in), optional :: method
      type(beam_model) :: model
      real(dp), allocatable :: values(:), shapes(:,:), vectors(:,:)
      integer :: stat
      character(len=256) :: errmsg
      call build_model(basis, elements, length, rho_s, ei, model, stat, errmsg, structure=st)
      if (stat == 0) call compute_modes(model, count, values, shapes, vectors, stat, errmsg, method)
      if (stat /= 0) then
         call t%check_true(basis//': modes computed', .false., errmsg)
         omega = -1
         return
      end if
      omega = values
   end subroutine frequencies

   !> The base excitation's load on a free-free beam with masses against -s'' M r.
   subroutine base_load_on_masses(basis)
      character(len=*), intent(in) :: basis
      type(beam_structure) :: st
      type(beam_model) :: model
      type(load_settings) :: settings
      type(load_set) :: loads
      real(dp), allocatable :: r(:), mass_r(:), abs_mass_r(:), f(:)
      real(dp) :: time, s_ddot
      integer :: stat, i
      character(len=256) :: errmsg
      st = structure(end_free, end_free)
      call add_mass(st, 0.25_dp, 0.3_dp, 0.0_dp)
      call add_mass(st, 0.6_dp, 0.1_dp, merge(0.01_dp, 0.0_dp, basis == 'hermite'))
      call build_model(basis, 16, length, rho_s, ei, model, stat, errmsg, structure=st)
      call t%check_true(basis//' free-free beam with masses: model', stat == 0, trim(errmsg))
      if (stat /= 0) return
      settings%base_amplitude = 2e-3_dp
      settings%base_frequency = 30
      call build_loads(settings, model, rho_s, loads)
      ! the rigid translation: every nodal value 1 (Hermite: w_i = 1, theta_i = 0; B-splines:
      ! every coefficient 1, the partition of unity)
      allocate (r(model%unknowns), mass_r(model%unknowns), abs_mass_r(model%unknowns))
      r = 1
      if (model%hermite) then
         do i = 0, model%elements
            if (model%unknown_of(2*i + 2) > 0) r(model%unknown_of(2*i + 2)) = 0
         end do
      end if
      call band_matvec(model%mass, r, mass_r)
      model%mass%lower = abs(model%mass%lower)
      call band_matvec(model%mass, abs(r), abs_mass_r)
      time = 0.01_dp
      s_ddot = -settings%base_amplitude*settings%base_frequency**2*sin(settings%base_frequency*time)
      f = loads%at(time)
      call t%check_close(basis//' base excitation on a free-free beam with masses: F(t) = -s'''' M r', &
                         maxval(abs(f + s_ddot*mass_r)/max(abs_mass_r*abs(s_ddot), tiny(1.0_dp))), 0.0_dp, 1.0_dp, &
                         64*epsilon(1.0_dp))
   end subroutine base_load_on_masses

   !> The two lowest positive roots of the determinant (scan of step 0.01 from 0.05, then
   !! bisection: `scanned_roots`).
   function determinant_roots(ends, interior) result(roots)
      type(boundary_conditions), intent(in) :: ends
      type(point_data), intent(in) :: interior(:)
      real(dp) :: roots(2)
      current_ends = ends
      current_points = interior
      roots = scanned_roots(determinant_at, 2, 0.05_dp, 0.01_dp, 30.0_dp)
   end function determinant_roots

   !> The determinant of `determinant_roots`'s case at b.
   real(dp) function determinant_at(root)
      real(dp), intent(in) :: root
      determinant_at = determinant(current_ends, current_points, root)
   end function determinant_at

   !> The determinant of the 4 (points + 1) rows of the spans' coefficients at b (the end
   !! masses and springs of the ends of `ends` are none here: a point at xi = 1 with mu, j
   !! is the tip mass).
   real(dp) function determinant(ends, interior, root)
      type(boundary_conditions), intent(in) :: ends
      type(point_data), intent(in) :: interior(:)
      real(dp), intent(in) :: root
      real(dp), allocatable :: a(:,:)
      type(point_data), allocatable :: inner(:)
      type(point_data) :: tip
      integer :: spans, n, p, c, row
      ! a point at xi = 1 is the right end's mass
      tip = point_data(xi=1.0_dp)
      allocate (inner, source=interior)
      if (size(interior) > 0) then
         if (interior(size(interior))%xi >= 1) then
            tip = interior(size(interior))
            deallocate (inner)
            allocate (inner, source=interior(1:size(interior) - 1))
         end if
      end if
      spans = size(inner) + 1
      n = 4*spans
      allocate (a(n, n), source=0.0_dp)
      ! left end (span 1 at xi = 0)
      call end_rows(a, root, 1, 0.0_dp, 1, ends%holds_deflection(1), ends%holds_rotation(1), point_data())
      ! interior points
      row = 2
      do p = 1, size(inner)
         c = 4*(p - 1)   ! columns of the span on its left; c + 4 on its right
         associate (q => inner(p), x => inner(p)%xi)
            select case (q%kind)
            case (support_pinned)
               a(row + 1, c + 1:c + 4) = basis_row(root, x, 0)
               a(row + 2, c + 5:c + 8) = basis_row(root, x, 0)
               a(row + 3, c + 1:c + 4) = root*basis_row(root, x, 1)
               a(row + 3, c + 5:c + 8) = -root*basis_row(root, x, 1)
               a(row + 4, c + 1:c + 4) = root**2*basis_row(root, x, 2)
               a(row + 4, c + 5:c + 8) = -root**2*basis_row(root, x, 2)
            case (support_clamped)
               a(row + 1, c + 1:c + 4) = basis_row(root, x, 0)
               a(row + 2, c + 5:c + 8) = basis_row(root, x, 0)
               a(row + 3, c + 1:c + 4) = basis_row(root, x, 1)
               a(row + 4, c + 5:c + 8) = basis_row(root, x, 1)
            case default
               a(row + 1, c + 1:c + 4) = basis_row(root, x, 0)
               a(row + 1, c + 5:c + 8) = -basis_row(root, x, 0)
               a(row + 2, c + 1:c + 4) = basis_row(root, x, 1)
               a(row + 2, c + 5:c + 8) = -basis_row(root, x, 1)
               a(row + 3, c + 1:c + 4) = root**2*basis_row(root, x, 2) + (q%kappa_r - root**4*q%j)*root*basis_row(root, x, 1)
               a(row + 3, c + 5:c + 8) = -root**2*basis_row(root, x, 2)
               a(row + 4, c + 5:c + 8) = root**3*basis_row(root, x, 3)
               a(row + 4, c + 1:c + 4) = -root**3*basis_row(root, x, 3) + (q%kappa - root**4*q%mu)*basis_row(root, x, 0)
            end select
         end associate
         row = row + 4
      end do
      ! right end (the last span at xi = 1)
      call end_rows(a, root, row + 1, 1.0_dp, spans, ends%holds_deflection(2), ends%holds_rotation(2), tip)
      determinant = lu_determinant(a)
   end function determinant

   !> The two rows of an end at xi (0 or 1) of span `span`, from `first` (the left end
   !! writes rows 1, 2; the right end the last two): a held value, else the natural
   !! condition with the end point's mass (and no spring: the ends here have none).
   subroutine end_rows(a, root, first, xi, span, deflection, rotation, q)
   real(dp), intent(inout) :: a(:,:)
   real(dp), intent(in) :: root
   integer, intent(in) :: first, span
      real(dp), intent(in) :: xi
      logical, intent(in) :: deflection, rotation
      type(point_data), intent(in) :: q
      real(dp) :: sgn
      integer :: r0, c0
      sgn = merge(1.0_dp, -1.0_dp, xi < 0.5_dp)
      r0 = merge(1, first, xi < 0.5_dp)
      c0 = 4*(span - 1)
      if (deflection) then
         a(r0, c0 + 1:c0 + 4) = basis_row(root, xi, 0)
      else
         a(r0, c0 + 1:c0 + 4) = sgn*root**3*basis_row(root, xi, 3) + (q%kappa - root**4*q%mu)*basis_row(root, xi, 0)
      end if
      if (rotation) then
         a(r0 + 1, c0 + 1:c0 + 4) = basis_row(root, xi, 1)
      else
         a(r0 + 1, c0 + 1:c0 + 4) = root**2*basis_row(root, xi, 2) - sgn*(q%kappa_r - root**4*q%j)*root*basis_row(root, xi, 1)
      end if
   end subroutine end_rows

   !> The order-th xi-derivatives of cosh(b xi), sinh(b xi), cos(b xi), sin(b xi), / b^order.
   pure function basis_row(root, xi, order) result(row)
      real(dp), intent(in) :: root, xi
      integer, intent(in) :: order
      real(dp) :: row(4)
      row = wave_row(root*xi, order)
   end function basis_row
end program test_structure_modes
