!> A string against a point obstacle (issue 18, "an exact multi-impact reference";
!! docs/theory.md §7, "A string against a point obstacle"; studies/string_obstacle).
!!
!! 1. The reference (verification/support/string_obstacle_reference.f90, characteristics)
!!    checked against itself and against closed forms:
!!    - no contact (the obstacle far below): it equals d'Alembert's free string (the odd
!!      2L-periodic extension) at every (x, t) of a grid;
!!    - a string released flat with a uniform velocity V upwards over an obstacle at its
!!      middle, level 0: it flies for L/c (u = V min(t, x/c, (L - x)/c, L/c - t)), lands
!!      flat with velocity -V, each half then moves as a string fixed at both ends (u = -V
!!      min(s, x'/c, (L/2 - x')/c, L/(2c) - s), s the time since landing, x' the distance
!!      from the half's left end) and leaves flat with velocity V after L/(2c): period
!!      3L/(2c), derived by hand; the reference equals it at every (x, t) of a grid;
!!    - the energy of a plucked string hitting an obstacle at L/4 (12 landings in 20 s) is
!!      constant, to the bound derived below.
!! 2. vibrobeam's velocity scheme (e = 1, EI = 1e-10 T L^2) against the reference on the
!!    plucked string (peak 0.6 L, height d, obstacle at L/4, level -0.3 d; 5 landings in
!!    8 s), N = 40 to 320 with dt = h/(2c), both bases: see `refine` for what is checked
!!    and why.
program test_string_obstacle
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text
   use vibrobeam_test_support, only: test_counter, fitted_order
   use vibrobeam_string_obstacle_reference, only: string_reference, new_string_reference
   use vibrobeam_string_obstacle_runs, only: string_run_errors, run_string_obstacle
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 1, c = 1, height = 0.01_dp
   call check_free_string()
   call check_uniform_velocity()
   call check_energy()
   call refine('hermite')
   call refine('bspline')
   call t%finish('test_string_obstacle')

contains

   !> The plucked string of the runs: peak at 0.6 L of height d, at rest; obstacle at L/4.
   function plucked(level) result(ref)
      real(dp), intent(in) :: level
      type(string_reference) :: ref
      ref = new_string_reference(length, c, 0.25_dp*length, level, [0.0_dp, 0.6_dp, 1.0_dp]*length, &
                                 [0.0_dp, height, 0.0_dp], [0.0_dp, 0.0_dp])
   end function plucked

   !> The bound on a history value's round-off: each pass of the waves through the point
   !! (every min(2 x0, 2(L - x0))/c) adds a few roundings of values of size `scale` and at
   !! most the pruning tolerance 1e-13 scale (string_obstacle_reference, drop_collinear).
   pure real(dp) function history_bound(ref, t_end, scale)
      type(string_reference), intent(in) :: ref
      real(dp), intent(in) :: t_end, scale
      history_bound = 2*(t_end*ref%c/(2*min(ref%x0, ref%length - ref%x0)) + 1)*(1e-13_dp + 4*epsilon(1.0_dp))*scale
   end function history_bound

   !> The odd 2L-periodic extension of the pluck.
   pure real(dp) function extended(x)
      real(dp), intent(in) :: x
      real(dp) :: y
      y = modulo(x, 2*length)
      if (y <= length) then
         extended = triangle(y)
      else
         extended = -triangle(2*length - y)
      end if
   end function extended

   pure real(dp) function triangle(x)
      real(dp), intent(in) :: x
      triangle = height*merge(x/0.6_dp, (length - x)/0.4_dp, x <= 0.6_dp)
   end function triangle

   subroutine check_free_string()
      type(string_reference) :: ref
      real(dp), parameter :: t_end = 8
      real(dp) :: time, x, error
      integer :: i, k
      ref = plucked(-10*height)
      call ref%build(t_end)
      error = 0
      do k = 0, 80
         time = t_end*k/80.0_dp + 0.0123_dp*mod(k, 3)
         time = min(time, t_end)
         do i = 0, 40
            x = length*i/40
            error = max(error, abs(ref%displacement(x, time) - 0.5_dp*(extended(x - c*time) + extended(x + c*time))))
         end do
      end do
      write (*, '(a,es10.2)') 'reference without contact: largest difference from d''Alembert / d', error/height
      call t%check_close('reference without contact = d''Alembert', error, 0.0_dp, 1.0_dp, &
                         history_bound(ref, t_end, height))
   end subroutine check_free_string

   subroutine check_uniform_velocity()
      type(string_reference) :: ref
      real(dp), parameter :: v = 1, t_end = 9, period = 1.5_dp*length/c
      real(dp) :: time, x, phase, error, exact, xs
      real(dp), allocatable :: starts(:), ends(:)
      real(dp) :: expected_starts(6), expected_ends(6)
      integer :: i, k, wrong_contact
      ref = new_string_reference(length, c, 0.5_dp*length, 0.0_dp, [0.0_dp, length], [0.0_dp, 0.0_dp], [v])
      call ref%build(t_end)
      error = 0
      wrong_contact = 0
      do k = 0, 90
         time = t_end*k/90.0_dp + 0.0071_dp*mod(k, 4)
         time = min(time, t_end)
         phase = modulo(time, period)
         do i = 0, 40
            x = length*i/40
            if (phase <= length/c) then
               exact = v*min(phase, x/c, (length - x)/c, length/c - phase)
            else
               xs = merge(x, x - 0.5_dp*length, x <= 0.5_dp*length)
               exact = -v*min(phase - length/c, xs/c, (0.5_dp*length - xs)/c, 1.5_dp*length/c - phase)
            end if
            error = max(error, abs(ref%displacement(x, time) - exact))
         end do
         ! in contact strictly inside (L/c, 3L/(2c)) of each period, off it strictly inside (0, L/c)
         if (phase > 1.01_dp*length/c .and. phase < 1.49_dp*length/c .and. .not. ref%in_contact(time)) &
            wrong_contact = wrong_contact + 1
         if (phase > 0.01_dp*length/c .and. phase < 0.99_dp*length/c .and. ref%in_contact(time)) &
            wrong_contact = wrong_contact + 1
      end do
      write (*, '(a,es10.2)') 'reference, uniform velocity onto the middle: largest difference from the closed form / VL/c', &
         error/(v*length/c)
      call t%check_close('reference = closed form of the uniform velocity onto the middle', error, 0.0_dp, 1.0_dp, &
                         history_bound(ref, t_end, v*length/c))
      call t%check_true('reference: contact exactly on (L/c, 3L/2c) of each period', wrong_contact == 0, &
                        integer_text(wrong_contact)//' sample times wrong')
      ! the force R = 2TV/c > 0 on the whole of each: the pressed intervals are the same,
      ! [L/c + k 3L/(2c), 3L/(2c) + k 3L/(2c)], k = 0..5 (the last cut at t_end = 9 L/c)
      call ref%contact_intervals(starts, ends, pressed=.true.)
      expected_starts = [(length/c + k*period, k=0, 5)]
      expected_ends = [(min(1.5_dp*length/c + k*period, t_end), k=0, 5)]
      call t%check_true('reference: 6 intervals of contact force', size(starts) == 6, integer_text(size(starts)))
      if (size(starts) == 6) then
         error = max(maxval(abs(starts - expected_starts)), maxval(abs(ends - expected_ends)))
         call t%check_close('reference: the intervals of contact force', error, 0.0_dp, 1.0_dp, &
                            history_bound(ref, t_end, length/c))
      end if
   end subroutine check_uniform_velocity

   !> E(t) from the waves the point emitted (string_reference%energy) against E(0) from the
   !! initial data. Its round-off: a slope (dy/dt on a piece of length dt) errs by at most
   !! 2 e_y/dt, e_y the history bound; its square by 2 |slope| 2 e_y/dt; summed over the
   !! pieces (each overlapping the window by at most dt): 4 c e_y sum |dy|/dt over the history.
   subroutine check_energy()
      type(string_reference) :: ref
      real(dp), parameter :: t_end = 20
      real(dp) :: drift, bound, time, energy_0
      integer :: k, landings
      ref = plucked(-0.3_dp*height)
      call ref%build(t_end)
      energy_0 = ref%initial_energy()
      drift = 0
      do k = 0, 100
         time = 1.5_dp*length/c + (t_end - 1.5_dp*length/c)*k/100
         drift = max(drift, abs(ref%energy(time) - energy_0))
      end do
      bound = 4*c*history_bound(ref, t_end, height)* &
              (sum(abs(ref%w(2:ref%points) - ref%w(:ref%points - 1))/(ref%t(2:ref%points) - ref%t(:ref%points - 1))) &
               + sum(abs(ref%a(2:ref%points) - ref%a(:ref%points - 1))/(ref%t(2:ref%points) - ref%t(:ref%points - 1))) &
               + sum(abs(ref%b(2:ref%points) - ref%b(:ref%points - 1))/(ref%t(2:ref%points) - ref%t(:ref%points - 1))))
      landings = count(ref%w(2:ref%points) <= ref%level .and. ref%w(:ref%points - 1) > ref%level)
      write (*, '(a,i0,a,es10.2,a,es10.2)') 'reference, pluck onto L/4: ', landings, ' landings in 20 s, energy drift/E0', &
         drift/energy_0, ', bound', bound/energy_0
      call t%check_true('reference: many landings (>= 10 in 20 s)', landings >= 10)
      call t%check_close('reference: energy conserved', drift, 0.0_dp, 1.0_dp, bound)
   end subroutine check_energy

   !> The velocity scheme against the reference, N = 40 to 320 with dt = h/(2c), 8 s (4
   !! contact intervals). What to expect (measured in studies/string_obstacle/REPORT.md, not
   !! fitted here): without the obstacle the L2 error of a pluck falls like h and its largest
   !! error like h^(2/3) (verification.plucked_string); the point obstacle's law is a
   !! supremum (theory §7), so each contact passes the largest error of the arriving waves
   !! on to the whole field, and the study measures orders near 2/3 (0.63 to 0.66 fitted
   !! over N = 160..1280, 20 s) for the L2 error and the cumulative contact impulse, lower
   !! (about 0.5) over N = 40..320, still pre-asymptotic. Checked: the RMS nodal error (the
   !! largest over samples every 0.25 s) and the error of the cumulative impulse (the
   !! largest over every step) and the largest error of the start or end of a contact force
   !! (the first and last step with an impulse against the exact interval of R > 0) fall at
   !! each refinement, their least-squares orders over N = 40..320 are at least 0.35 (the
   !! measured 0.47 to 0.8, printed, less a margin for the approach to the asymptote), and
   !! the discrete energy is conserved to its round-off bound (e = 1 and theta = 1/2
   !! conserve it exactly: theory §6).
   subroutine refine(basis)
      character(len=*), intent(in) :: basis
      integer, parameter :: levels = 4
      real(dp), parameter :: t_end = 8
      type(string_reference) :: ref
      type(string_run_errors) :: errors(levels)
      integer :: level, elements(levels), stat
      real(dp) :: order_rms, order_impulse, order_times, rms(levels), impulse(levels), times(levels)
      character(len=512) :: errmsg
      ref = plucked(-0.3_dp*height)
      call ref%build(t_end)
      elements = [(40*2**(level - 1), level=1, levels)]
      do level = 1, levels
         call run_string_obstacle(ref, basis, elements(level), 2.0_dp, t_end, 0.25_dp, 0.75_dp*length, height, &
                                  errors(level), stat, errmsg)
         call t%check_true(basis//' N = '//integer_text(elements(level))//': run', stat == 0, trim(errmsg))
         if (stat /= 0) return
         write (*, '(a,i4,a,es10.2,a,es10.2,a,es10.2,a,es10.2)') basis//' N = ', elements(level), ': RMS error/d', &
            errors(level)%rms, ', impulse error', errors(level)%impulse, ', energy drift', errors(level)%energy_drift, &
            ', bound', errors(level)%energy_bound
         call t%check_close(basis//' N = '//integer_text(elements(level))//': energy conserved', &
                            errors(level)%energy_drift, 0.0_dp, 1.0_dp, errors(level)%energy_bound)
      end do
      rms = errors%rms
      impulse = errors%impulse
      times = errors%contact_times
      order_rms = fitted_order(elements, rms, [(.true., level=1, levels)])
      order_impulse = fitted_order(elements, impulse, [(.true., level=1, levels)])
      order_times = fitted_order(elements, times, [(.true., level=1, levels)])
      write (*, '(a,4es10.2)') basis//' largest error of the start or end of a contact force (s), N = 40..320:', times
      write (*, '(a,f5.2,a,f5.2,a,f5.2)') basis//' orders (N = 40..320): L2', order_rms, ', cumulative impulse', &
         order_impulse, ', contact times', order_times
      call t%check_true(basis//': the L2 error falls at each refinement', all(rms(2:) < rms(:levels - 1)))
      call t%check_true(basis//': the impulse error falls at each refinement', &
                        all(impulse(2:) < impulse(:levels - 1)))
      call t%check_true(basis//': L2 order >= 0.35', order_rms >= 0.35_dp)
      call t%check_true(basis//': impulse order >= 0.35', order_impulse >= 0.35_dp)
      call t%check_true(basis//': the contact times'' error falls at each refinement', all(times(2:) < times(:levels - 1)))
      call t%check_true(basis//': contact times order >= 0.35', order_times >= 0.35_dp)
   end subroutine refine
end program test_string_obstacle
