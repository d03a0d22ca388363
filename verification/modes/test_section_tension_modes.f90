!> Natural frequencies of non-uniform beams (&sections) and of beams under an axial force
!! (&beam axial_force; issue 18, items 4 and 5), from the library's modes (`compute_modes`)
!! through a scene (`build_problem`: the input's path), against references written here
!! independently of the solver (docs/theory.md §7, "Sections and axial force"):
!!
!! - a stepped cantilever of two sections (EI_1, rho S_1 on [0, a], EI_2, rho S_2 on
!!   [a, L]): on section j, phi = A_j cosh(beta_j s) + B_j sinh(beta_j s) + C_j cos(beta_j s)
!!   + D_j sin(beta_j s), s measured from the section's start, beta_j^4 = omega^2 rho S_j/
!!   EI_j; the clamp (phi = phi' = 0 at 0), the continuity at a of phi, phi', the moment
!!   EI phi'' and the shear EI phi''' (the natural conditions of the energy 1/2 int EI u''^2
!!   - omega^2/2 int rho S u^2 at an interior point), and the free end (phi'' = phi''' = 0)
!!   make an 8 x 8 transfer system whose determinant vanishes at the frequencies; its roots
!!   in b = beta_1 L by a scan of step 0.01 and bisection to 4 eps (`lu_determinant`:
!!   LAPACK dgetrf for the determinant's sign). Checked against itself: with equal
!!   sections its roots are the cantilever's 1.8751040687, 4.6940911330 (to 4 eps e^b,
!!   the cancellation of its rows);
!! - a tensioned pinned-pinned beam: sin(n pi x/L) are its modes for any EI and T, with
!!   omega_n^2 = (n pi/L)^4 EI/(rho S) + (n pi/L)^2 T/(rho S) (theory §7);
!! - its string limit EI -> 0: omega_n = (n pi/L) sqrt(T/(rho S)); a beam of EI =
!!   1e-8 T L^2 lies above it by (n pi/L)^2 EI/(2T) relative (first order of the square
!!   root), which with the discretization bound below makes the derived tolerance.
!!
!! Tolerances (as test_support_modes.f90): for both bases the observed order of omega_1,
!! omega_2 between N = 20 and N = 40 in [3.5, 4.5]; the relative error below
!! (b_n/N)^4/100 at N = 40 (b_n = beta_n L; the section end on a node, so the kink of u''
!! lies in the space); at N = 160, below 1.5 times the h^4 extrapolation of the N = 40
!! error plus the round-off of the Rayleigh quotient, 8 N eps (h^4 down to round-off). The
!! string: cubic elements approximate -T u'' with an eigenvalue error of order h^6
!! (conforming elements of degree 3 on a second-order operator [Strang & Fix 1973,
!! ch. 6]), well inside (n pi/N)^4/100 at N = 32, the bound used.
!! B-splines and a jump of EI: C^2 splines cannot follow the jump of u'' = M/EI at the
!! section's end; they are refused there (as a point moment inside the beam, theory §2;
!! measured before refusing: order 1.5 on omega_1, 1.6e-4 at N = 40); a section of its
!! own rho S under the same EI leaves u'' continuous and keeps h^4 in both bases (checked).
program test_section_tension_modes
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type, section_settings, unset
   use vibrobeam_problem, only: run_problem, build_problem
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_test_support, only: test_counter, wave_row, lu_determinant, scanned_roots
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 1.2_dp, step_at = 0.48_dp    ! a = 0.4 L: a node for N = 5 k
   ! the sections (E, rho, S, I): EI_1 = 60, rho S_1 = 3; EI_2 = 15, rho S_2 = 1.2 N m^2, kg/m
   real(dp), parameter :: ei_1 = 60, rho_s_1 = 3, ei_2 = 15, rho_s_2 = 1.2_dp
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   real(dp) :: roots(2)
   real(dp) :: current(4)   !! EI_1, rho S_1, EI_2, rho S_2 of the determinant being solved
   integer :: b
   ! the determinant against the uniform cantilever's roots
   roots = stepped_roots(ei_1, rho_s_1, ei_1, rho_s_1)
   call t%check_close('transfer determinant, equal sections: root 1', roots(1), 1.8751040687119611664_dp, &
                      4*epsilon(1.0_dp)*exp(roots(1)))
   call t%check_close('transfer determinant, equal sections: root 2', roots(2), 4.6940911329741745764_dp, &
                      4*epsilon(1.0_dp)*exp(roots(2)))
   do b = 1, 2
      if (b == 1) then
         call stepped(bases(b), ei_2, rho_s_2)
      else
         call stepped_refused(ei_2, rho_s_2)
      end if
      call stepped(bases(b), ei_1, rho_s_2)   ! a step of rho S alone
      call tensioned(bases(b))
      call string_limit(bases(b))
   end do
   call t%finish('test_section_tension_modes')

contains

   !> A scene of N elements of `basis`: clamped-free (default) or pinned-pinned, given by
   !! E, rho, S, I (E = EI, I = 1, rho = rho S, S = 1).
   function beam_scene(basis, elements, ei, rho_s) result(scene)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), intent(in) :: ei, rho_s
      type(scene_type) :: scene
      scene%beam%length = length
      scene%beam%youngs_modulus = ei
      scene%beam%inertia = 1
      scene%beam%density = rho_s
      scene%beam%area = 1
      scene%mesh%basis = basis
      scene%mesh%elements = elements
      scene%analysis%kind = 'modes'
      allocate (scene%obstacles(0))
   end function beam_scene

   !> The two sections of the stepped cantilever, the second of EI_2, rho S_2.
   function stepped_scene(basis, elements, ei_right, rho_s_right) result(scene)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), intent(in) :: ei_right, rho_s_right
      type(scene_type) :: scene
      scene = beam_scene(basis, elements, 1.0_dp, 1.0_dp)
      scene%beam%youngs_modulus = unset   ! the sections give the beam
      scene%beam%inertia = unset
      scene%beam%density = unset
      scene%beam%area = unset
      scene%beam%sections = [section_settings(x_to=step_at, youngs_modulus=ei_1, density=rho_s_1, area=1, inertia=1), &
                             section_settings(x_to=length, youngs_modulus=ei_right, density=rho_s_right, area=1, &
                                              inertia=1)]
   end function stepped_scene

   !> The `count` lowest omega of a scene's model (through build_problem).
   function frequencies(scene, count) result(omega)
      type(scene_type), intent(in) :: scene
      integer, intent(in) :: count
      real(dp) :: omega(count)
      type(run_problem) :: prepared
      real(dp), allocatable :: values(:), shapes(:,:), vectors(:,:)
      character(len=:), allocatable :: warnings
      integer :: stat
      character(len=512) :: errmsg
      warnings = ''
      omega = -1
      call build_problem(scene, prepared, warnings, stat, errmsg)
      if (stat == 0) call compute_modes(prepared%model, count, values, shapes, vectors, stat, errmsg)
      call t%check_true(trim(scene%mesh%basis)//' N = '//integer_text(scene%mesh%elements)//': modes computed', &
                        stat == 0, trim(errmsg))
      if (stat == 0) omega = values(1:count)
   end function frequencies

   !> Relative errors of omega_1, omega_2 at N = 20, 40, 80, 160 against `exact`; the order,
   !! the size at N = 40 (roots b_n = beta_n L) and the round-off floor at N = 160.
   subroutine convergence(label, template, exact, b_roots)
      character(len=*), intent(in) :: label
      type(scene_type), intent(in) :: template   !! the scene, its mesh refined here
      real(dp), intent(in) :: exact(2), b_roots(2)
      real(dp) :: error(4, 2), omega(2)
      type(scene_type) :: scene
      integer :: level, k
      scene = template
      do level = 1, 4
         scene%mesh%elements = 20*2**(level - 1)
         omega = frequencies(scene, 2)
         error(level, :) = abs(omega - exact)/exact
      end do
      write (*, '(a,a,4es10.2,a,4es10.2)') label, ': relative errors of omega_1 at N = 20..160:', error(:, 1), &
         '; omega_2:', error(:, 2)
      do k = 1, 2
         call t%check_close(label//': order of omega_'//integer_text(k)//' (N = 20 to 40)', &
                            log(error(1, k)/error(2, k))/log(2.0_dp), 4.0_dp, 0.5_dp/4)
         call t%check_close(label//': omega_'//integer_text(k)//' at N = 40, relative error', error(2, k), 0.0_dp, 1.0_dp, &
                            (b_roots(k)/40)**4/100)
         call t%check_close(label//': omega_'//integer_text(k)//' at N = 160 (h^4 to round-off)', error(4, k), 0.0_dp, &
                            1.0_dp, 1.5_dp*error(2, k)/16 + 8*160*epsilon(1.0_dp))
      end do
   end subroutine convergence

   !> The stepped cantilever against the transfer determinant's roots.
   subroutine stepped(basis, ei_right, rho_s_right)
      character(len=*), intent(in) :: basis
      real(dp), intent(in) :: ei_right, rho_s_right
      real(dp) :: b_roots(2)
      b_roots = stepped_roots(ei_1, rho_s_1, ei_right, rho_s_right)
      call convergence(basis//' stepped cantilever (EI '//trim(four_digits(ei_1))//'/'//trim(four_digits(ei_right))// &
                       ', rho S '//trim(four_digits(rho_s_1))//'/'//trim(four_digits(rho_s_right))//')', &
                       stepped_scene(basis, 20, ei_right, rho_s_right), b_roots**2*sqrt(ei_1/rho_s_1)/length**2, b_roots)
   end subroutine stepped

   !> B-splines refuse a jump of EI at a section's end, naming the sections.
   subroutine stepped_refused(ei_right, rho_s_right)
      real(dp), intent(in) :: ei_right, rho_s_right
      type(run_problem) :: prepared
      character(len=:), allocatable :: warnings
      integer :: stat
      character(len=512) :: errmsg
      warnings = ''
      call build_problem(stepped_scene('bspline', 40, ei_right, rho_s_right), prepared, warnings, stat, errmsg)
      call t%check_true('bspline: a jump of EI at a section''s end is refused, naming &sections', &
                        stat /= 0 .and. index(errmsg, '&sections') == 1, trim(errmsg))
   end subroutine stepped_refused

   !> The tensioned pinned-pinned beam (EI = 4, rho S = 0.5, T = 30: the tension's share
   !! of omega_1^2 is T/(T + (pi/L)^2 EI) = 0.52) against its closed form.
   subroutine tensioned(basis)
      character(len=*), intent(in) :: basis
      real(dp), parameter :: ei = 4, rho_s = 0.5_dp, tension = 30
      real(dp) :: exact(2), k(2)
      type(scene_type) :: scene
      k = [1, 2]*pi/length
      exact = sqrt(k**4*ei/rho_s + k**2*tension/rho_s)
      scene = beam_scene(basis, 20, ei, rho_s)
      scene%beam%left_end = 'pinned'
      scene%beam%right_end = 'pinned'
      scene%beam%axial_force = tension
      call convergence(basis//' tensioned pinned-pinned beam', scene, exact, [pi, 2*pi])
   end subroutine tensioned

   !> The string limit: EI = 1e-8 T L^2 against (n pi/L) sqrt(T/rho S), n = 1..3, at N = 32,
   !! with the tolerance of the module documentation; printed: the discretization error
   !! (against the beam's own closed form) and its order from N = 16.
   subroutine string_limit(basis)
      character(len=*), intent(in) :: basis
      real(dp), parameter :: rho_s = 0.5_dp, tension = 30
      real(dp) :: ei, string(3), beam(3), omega(3), coarse(3), tolerance, k(3)
      type(scene_type) :: scene
      integer :: n
      ei = 1e-8_dp*tension*length**2
      k = [(n*pi/length, n=1, 3)]
      string = k*sqrt(tension/rho_s)
      beam = sqrt(k**4*ei/rho_s + k**2*tension/rho_s)
      scene = beam_scene(basis, 16, ei, rho_s)
      scene%beam%left_end = 'pinned'
      scene%beam%right_end = 'pinned'
      scene%beam%axial_force = tension
      coarse = frequencies(scene, 3)
      scene%mesh%elements = 32
      omega = frequencies(scene, 3)
      write (*, '(a,3es10.2,a,3es10.2,a,3f6.2)') basis//' string limit, N = 32: relative distance to the string', &
         abs(omega - string)/string, '; discretization error', abs(omega - beam)/beam, ', its order from N = 16', &
         log(abs(coarse - beam)/abs(omega - beam))/log(2.0_dp)
      do n = 1, 3
         tolerance = (n*pi/length)**2*ei/(2*tension) + (n*pi/32)**4/100
         call t%check_close(basis//' string limit: omega_'//integer_text(n)//' = (n pi/L) sqrt(T/rho S)', omega(n), &
                            string(n), tolerance)
      end do
   end subroutine string_limit

   !> The first two roots b = beta_1 L of the stepped cantilever's transfer determinant
   !! (a scan of step 0.01 from 0.05, bisection to 4 eps: `scanned_roots`).
   function stepped_roots(ei_left, rho_s_left, ei_right, rho_s_right) result(roots)
      real(dp), intent(in) :: ei_left, rho_s_left, ei_right, rho_s_right
      real(dp) :: roots(2)
      current = [ei_left, rho_s_left, ei_right, rho_s_right]
      roots = scanned_roots(stepped_at, 2, 0.05_dp, 0.01_dp, 30.0_dp)
   end function stepped_roots

   !> The determinant of the sections of `stepped_roots` at b.
   real(dp) function stepped_at(root)
      real(dp), intent(in) :: root
      stepped_at = stepped_determinant(root, current(1), current(2), current(3), current(4))
   end function stepped_at

   !> The 8 x 8 determinant at b = beta_1 L (module documentation); each row divided by
   !! the power of beta its derivative carries, the moment and shear rows by EI_1.
   real(dp) function stepped_determinant(root, ei_left, rho_s_left, ei_right, rho_s_right) result(determinant)
      real(dp), intent(in) :: root, ei_left, rho_s_left, ei_right, rho_s_right
      real(dp) :: a(8, 8), beta_1, beta_2, ratio, lengths(2), ei_ratio
      integer :: i
      beta_1 = root/length
      beta_2 = beta_1*(rho_s_right*ei_left/(rho_s_left*ei_right))**0.25_dp
      ratio = beta_2/beta_1
      ei_ratio = ei_right/ei_left
      lengths = [step_at, length - step_at]
      a = 0
      a(1, 1:4) = wave_row(0.0_dp, 0)                 ! phi_1(0) = 0
      a(2, 1:4) = wave_row(0.0_dp, 1)                 ! phi_1'(0) = 0
      do i = 0, 3                                      ! phi, phi', EI phi'', EI phi''' at a
         a(3 + i, 1:4) = wave_row(beta_1*lengths(1), i)
         a(3 + i, 5:8) = -ratio**i*merge(ei_ratio, 1.0_dp, i >= 2)*wave_row(0.0_dp, i)
      end do
      a(7, 5:8) = wave_row(beta_2*lengths(2), 2)      ! phi_2''(L) = 0
      a(8, 5:8) = wave_row(beta_2*lengths(2), 3)      ! phi_2'''(L) = 0
      determinant = lu_determinant(a)
   end function stepped_determinant


   function four_digits(value) result(text)
      real(dp), intent(in) :: value
      character(len=12) :: text
      write (text, '(g0.4)') value
   end function four_digits
end program test_section_tension_modes
