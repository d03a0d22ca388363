!> The damped bundled scenes damp their first two modes as their comment says (issue 24
!! item 7). Each input given that has Rayleigh damping C = a M + b K (&beam rayleigh_mass a,
!! rayleigh_stiffness b) must state its intended ratio in a comment line
!!    ! Damping: Z % in modes 1 and 2, ...
!! (or, for two different ratios, '! Damping: Z1 % in mode 1, Z2 % in mode 2', Z2 >= Z1)
!! and its damping ratios zeta_n = a/(2 omega_n) + b omega_n/2 (docs/theory.md section 1,
!! "Damping") of modes 1 and 2 must be what it states, with omega_n taken
!!  - from the continuum closed form of the beam (docs/theory.md section 7), independent of
!!    the solver, and
!!  - from the natural modes of the input's own mesh (what its run damps: C is diagonal in
!!    the discrete modes).
!! Mass damping alone (b = 0) leaves mode 2 at omega_1/omega_2 = 0.16 times mode 1's ratio
!! and fails (ctest input.bundled_damping_mass_only runs this check on such an input). An
!! undamped input that states a ratio fails too.
!!    usage: check_bundled_damping INPUT.nml...
!!
!! Tolerance on zeta_n/Z - 1, 1e-4: the inputs write a and b to 5 significant digits, each
!! within 5e-5 relative of the fitted value (scripts/rayleigh_damping.py), and zeta_n is a
!! sum of two positive terms, one in a and one in b, so it is within 5e-5 too (a scene that
!! states two ratios gives a and b exactly and the ratios to 6 digits: within 5e-6); a mesh
!! frequency differs from the closed form by the Hermite discretization error
!! (beta_n h)^4/1440 relative (verification.modes_convergence), at most 5.1e-6 for mode 2
!! of a mesh of 16 elements ((4.694/16)^4/1440) and 8.2e-5 for rattling_orbit's 8, which
!! moves zeta_n by at most as much (|d zeta/d omega| omega <= zeta); round-off is below
!! 1e-14. At most 5.6e-5, or 8.7e-5 for rattling_orbit (5e-6 + 8.2e-5).
program check_bundled_damping
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text
   use vibrobeam_scene, only: scene_type, structure_of
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_scene_read, only: read_scene
   use vibrobeam_sweep_settings, only: sweep_settings
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_scene_structure, only: scene_frequencies
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_test_support, only: test_counter
   implicit none
   real(dp), parameter :: tolerance = 1e-4_dp
   type(test_counter) :: t
   character(len=4096) :: file
   integer :: k, damped
   damped = 0
   do k = 1, command_argument_count()
      call get_command_argument(k, file)
      call check_input(trim(file))
   end do
   call t%check_true('damped inputs found', damped >= 1)
   call t%finish('check_bundled_damping')

contains

   subroutine check_input(path)
      character(len=*), intent(in) :: path
      type(scene_type) :: scene
      type(sweep_settings) :: sweep
      type(beam_model) :: model
      character(len=:), allocatable :: warnings
      character(len=512) :: errmsg
      real(dp), allocatable :: omega(:), shapes(:, :), vectors(:, :)
      real(dp) :: intended(2), a, b
      logical :: stated
      real(dp) :: reference(5)
      integer :: first
      logical :: closed_form
      integer :: stat, n
      warnings = ''
      call read_scene(path, scene, stat, errmsg, warnings, sweep)   ! a sweep's scene is its base scene
      if (stat == 0) call validate_scene(scene, stat, errmsg)
      call t%check_true(path//' is valid', stat == 0, errmsg)
      if (stat /= 0) return
      call stated_ratio(path, stated, intended)
      a = scene%beam%rayleigh_mass
      b = scene%beam%rayleigh_stiffness
      if (a <= 0 .and. b <= 0) then
         call t%check_true(path//' is undamped and states no damping ratio', .not. stated)
         return
      end if
      damped = damped + 1
      call t%check_true(path//" states its damping ratio ('! Damping: Z % in modes 1 and 2')", stated)
      if (.not. stated) return
      write (*, '(a)') path//': a = '//real_text(a)//' 1/s, b = '//real_text(b)//' s, intended '// &
         real_text(100*intended(1))//' % in mode 1, '//real_text(100*intended(2))//' % in mode 2'
      ! the trap of issue 24 item 7: mode 2 damped less than mode 1 (mass damping alone)
      call t%check_true(path//': mode 2 is damped at least as much as mode 1', intended(2) >= intended(1))
      ! the structure's reference frequencies: the continuum closed form of its end pair, or
      ! a model of 64 Hermite elements (supports, springs, masses)
      call scene_frequencies(scene, reference, first, closed_form)
      do n = 1, 2
         call check_mode(path, trim(merge('closed-form', 'reference  ', closed_form)), n, reference(first - 1 + n), &
                         a, b, intended(n))
      end do
      call build_model(scene%mesh%basis, scene%mesh%elements, scene%beam%length, scene%beam%rho_s(), scene%beam%ei(), &
                       model, stat, errmsg, structure=structure_of(scene))
      if (stat == 0) call compute_modes(model, 2, omega, shapes, vectors, stat, errmsg)
      call t%check_true(path//': modes 1 and 2 of its mesh', stat == 0, errmsg)
      if (stat /= 0) return
      do n = 1, 2
         call check_mode(path, 'mesh', n, omega(n), a, b, intended(n))
      end do
   end subroutine check_input

   !> Checks the damping ratio of mode n at the frequency omega (rad/s) against the intended one.
   subroutine check_mode(path, source, n, omega, a, b, intended)
      character(len=*), intent(in) :: path, source
      integer, intent(in) :: n
      real(dp), intent(in) :: omega, a, b, intended
      real(dp) :: zeta
      character(len=1) :: mode
      zeta = a/(2*omega) + b*omega/2
      write (mode, '(i1)') n
      write (*, '(a)') '  mode '//mode//', '//source//' omega = '//real_text(omega)//' rad/s: damping ratio '// &
         real_text(100*zeta)//' %'
      call t%check_close(path//': damping ratio of mode '//mode//' ('//source//' frequency)', zeta, intended, tolerance)
   end subroutine check_mode

   !> The ratio Z/100 of the input's comment line '! Damping: Z % in modes 1 and 2'.
   subroutine stated_ratio(path, stated, ratio)
      character(len=*), intent(in) :: path
      logical, intent(out) :: stated
      real(dp), intent(out) :: ratio(2)   !! the intended ratios of modes 1 and 2
      character(len=*), parameter :: prefix = '! Damping:', both = '% in modes 1 and 2', first = '% in mode 1,', &
                                     second = '% in mode 2'
      character(len=1000) :: line
      integer :: unit, iostat, at, at2
      stated = .false.
      ratio = 0
      open (newunit=unit, file=path, status='old', action='read', iostat=iostat)
      if (iostat /= 0) return
      do
         read (unit, '(a)', iostat=iostat) line
         if (iostat /= 0) exit
         line = adjustl(line)
         if (index(line, prefix) /= 1) cycle
         at = index(line, both)
         if (at > 0) then
            read (line(len(prefix) + 1:at - 1), *, iostat=iostat) ratio(1)
            ratio(2) = ratio(1)
         else
            at = index(line, first)
            at2 = index(line, second)
            if (at == 0 .or. at2 <= at) cycle
            read (line(len(prefix) + 1:at - 1), *, iostat=iostat) ratio(1)
            if (iostat == 0) read (line(at + len(first):at2 - 1), *, iostat=iostat) ratio(2)
         end if
         stated = iostat == 0 .and. all(ratio > 0)
         ratio = ratio/100
         exit
      end do
      close (unit)
   end subroutine stated_ratio
end program check_bundled_damping
