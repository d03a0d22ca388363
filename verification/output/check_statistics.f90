!> Every statistic of /statistics recomputed from the histories of the same run (/time,
!! /tip, /points, /energy, /impacts, /episodes, written at every step) by the definitions
!! of docs/statistics.md, without the statistics module, and compared with what the run
!! reports.   usage: check_statistics FILE.h5
!!
!! The scene has its contact points at the tip only (two stops there), so /tip/impulse
!! (the impulse of each step, every = 1) gives the steps in contact and the contact
!! force; which stop gives an impulse follows from its sign (upwards: the 'below' one).
!! With a compliant stop (/contact/force written, every = 1) the force statistics are
!! recomputed from /contact/force at every step, and the compliant episodes (maximal runs
!! of steps with nonzero force) from it too; the powers of the contact damping and of the
!! stored energy (with the stops' potential) from /energy/dissipated_contact_damping and
!! /energy/total.
!!
!! Tolerances, derived:
!! - a sum of K terms computed in two orders differs by at most 2 (K - 1) eps sum |x_i|
!!   (each order errs by (K - 1) eps sum |x_i| at most; N. J. Higham, Accuracy and
!!   Stability of Numerical Algorithms, 2nd ed., 2002, eq. 4.4); a mean by 2 K eps max |x|,
!!   a root mean square by K eps relative (half the relative error of its square);
!! - min, max, counts and rates (a count divided by the same product K dt) are exact, and
!!   so are the force peak, the contact fraction by force and the episode durations (sums
!!   of whole step counts, exact in binary, times dt: a few roundings, 4 eps relative);
!!   the mean force while in contact is a sum of m terms over m (2 m eps max |f|), its
!!   RMS m eps relative;
!!   so are powers and the balance residual: differences of the same stored sums over the
!!   same duration (one rounding each: 2 eps relative to the values subtracted);
!! - a standard error of c batch values, each within delta of the reference, is within
!!   delta/sqrt(c - 1) (a perturbation of the centred vector) plus its own rounding;
!! - spectrum: a direct DFT of K samples here against FFTW there, amplitudes within
!!   4 K eps max |x - mean|; an interpolated peak moves by at most 3 delta_a/|curvature| of
!!   a bin (its derivative with respect to each of the three amplitudes is at most
!!   1/|curvature|), its amplitude by 2 delta_a + |left - right| delta_a/|curvature|;
!! - Poincare samples: the same interpolation formula of the same stored values, to
!!   4 eps of the largest value.
program check_statistics
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_real_2d, read_attr_real, read_attr_string
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_test_support, only: test_counter
   implicit none
   real(dp), parameter :: eps = epsilon(1.0_dp)
   type(test_counter) :: t
   character(len=4096) :: file
   character(len=512) :: errmsg
   integer :: stat
   real(dp), allocatable :: time(:), tip_u(:), tip_v(:), tip_impulse(:), point_u(:, :), point_v(:, :)
   real(dp), allocatable :: observed(:, :, :)   ! (steps + 1, points, 2)
   real(dp) :: dt, measure_from, duration
   integer(int64) :: last, first, samples, block, batches, n
   integer :: points, below, above, offset_position
   character(len=:), allocatable :: scheme
   ! impacts and episodes, and the target of the contact statistics being checked
   real(dp), allocatable :: impact_time(:), impact_impulse(:), episode_start(:), episode_impulse(:), step_impulse(:)
   integer(int64), allocatable :: impact_step(:), episode_step(:)
   real(dp) :: wanted   ! sign of the impulses of the target (0: any)

   call get_command_argument(1, file)
   call read_attr_real(trim(file), '/', 'time.dt', dt, stat, errmsg)
   call read_attr_real(trim(file), '/', 'output.measure_from', measure_from, stat, errmsg)
   call read_attr_string(trim(file), '/', 'time.scheme', scheme, stat, errmsg)
   ! the position scheme's impulses act at t_n, in the step from t_n to t_{n+1}
   offset_position = merge(1, 0, scheme == 'position')
   call load('/time', time)
   call load('/tip/displacement', tip_u)
   call load('/tip/velocity', tip_v)
   call load('/tip/impulse', tip_impulse)
   call read_real_2d(trim(file), '/points/displacement', point_u, stat, errmsg)
   call read_real_2d(trim(file), '/points/velocity', point_v, stat, errmsg)
   last = size(time) - 1
   call t%check_true('every step written', all(abs(time - [(real(n, dp)*dt, n = 0, last)]) <= 0))
   points = 1 + size(point_u, 1)
   allocate (observed(0:last, points, 2))
   observed(:, 1, 1) = tip_u
   observed(:, 1, 2) = tip_v
   observed(:, 2:, 1) = transpose(point_u)
   observed(:, 2:, 2) = transpose(point_v)
   ! the window: steps first+1 .. last
   first = max(0_int64, ceiling(measure_from/dt - 1e-9_dp, int64))
   samples = last - first
   duration = samples*dt
   block = 1
   do while (samples/(2*block) >= 8)
      block = 2*block
   end do
   batches = samples/block
   call t%check_true('window', samples >= 16, integer_text(int(samples))//' steps')
   call check_attribute_int('window_steps', samples)
   call check_attribute_int('batches', batches)
   call check_attribute_int('batch_steps', block)
   call find_stops(below, above)

   call check_points()
   call check_contacts()
   call check_energy()
   call check_forces()
   call check_spectrum()
   call check_poincare()
   call t%finish('check_statistics '//trim(file))

contains

   subroutine load(path, values)
      character(len=*), intent(in) :: path
      real(dp), allocatable, intent(out) :: values(:)
      call read_real_1d(trim(file), path, values, stat, errmsg)
      call t%check_true('read '//path, stat == 0, errmsg)
      if (stat /= 0) allocate (values(0))
   end subroutine load

   !> /statistics/<path> (or its error).
   function reported(path) result(values)
      character(len=*), intent(in) :: path
      real(dp), allocatable :: values(:)
      call load('/statistics/'//path, values)
   end function reported

   subroutine check_attribute_int(name, expected)
      character(len=*), intent(in) :: name
      integer(int64), intent(in) :: expected
      integer(int64) :: value
      type(h5_reader) :: h5
      call h5%open(trim(file), stat, errmsg)
      if (stat == 0) call h5%attr_int64('/statistics', name, value, stat, errmsg)
      call h5%close()
      call t%check_true('/statistics '//name, stat == 0 .and. value == expected, &
                        integer_text(int(value))//' instead of '//integer_text(int(expected)))
   end subroutine check_attribute_int

   !> The obstacles at the tip: one 'below' (index below), one 'above' (index above).
   subroutine find_stops(below, above)
      integer, intent(out) :: below, above
      character(len=:), allocatable :: side
      real(dp) :: count, x
      integer :: i
      below = 0
      above = 0
      call read_attr_real(trim(file), '/', 'obstacles.count', count, stat, errmsg)
      do i = 1, nint(count)
         call read_attr_string(trim(file), '/', 'obstacles.side('//integer_text(i)//')', side, stat, errmsg)
         call read_attr_real(trim(file), '/', 'obstacles.x_from('//integer_text(i)//')', x, stat, errmsg)
         if (side == 'below') below = i
         if (side == 'above') above = i
      end do
      call t%check_true('two stops', below > 0 .and. above > 0 .and. nint(count) == 2)
   end subroutine find_stops

   !> Mean, RMS, min, max of u and v at each observation point, with batch errors.
   subroutine check_points()
      character(len=*), parameter :: which(2) = ['displacement', 'velocity    ']
      real(dp), allocatable :: mean(:), rms(:), low(:), high(:), e_mean(:), e_rms(:), e_low(:), e_high(:)
      real(dp), allocatable :: x(:), batch(:, :)
      real(dp) :: largest
      integer :: q, p, b
      do q = 1, 2
         mean = reported('points/'//trim(which(q))//'_mean')
         rms = reported('points/'//trim(which(q))//'_rms')
         low = reported('points/'//trim(which(q))//'_min')
         high = reported('points/'//trim(which(q))//'_max')
         e_mean = reported('points/'//trim(which(q))//'_mean_error')
         e_rms = reported('points/'//trim(which(q))//'_rms_error')
         e_low = reported('points/'//trim(which(q))//'_min_error')
         e_high = reported('points/'//trim(which(q))//'_max_error')
         call t%check_true(trim(which(q))//' statistics at every point', size(mean) == points)
         if (size(mean) /= points) cycle
         do p = 1, points
            x = observed(first + 1:last, p, q)
            largest = maxval(abs(x))
            call close_to(trim(which(q))//' mean at point '//integer_text(p), mean(p), sum(x)/samples, &
                          2*samples*eps*largest)
            call close_to(trim(which(q))//' rms at point '//integer_text(p), rms(p), sqrt(sum(x**2)/samples), &
                          samples*eps*sqrt(sum(x**2)/samples))
            call close_to(trim(which(q))//' min at point '//integer_text(p), low(p), minval(x), 0.0_dp)
            call close_to(trim(which(q))//' max at point '//integer_text(p), high(p), maxval(x), 0.0_dp)
            allocate (batch(4, batches))
            do b = 1, int(batches)
               associate (y => x((b - 1)*block + 1:b*block))
                  batch(:, b) = [sum(y)/block, sqrt(sum(y**2)/block), minval(y), maxval(y)]
               end associate
            end do
            call close_to(trim(which(q))//' mean error at point '//integer_text(p), e_mean(p), error_of(batch(1, :)), &
                          2*block*eps*largest/sqrt(batches - 1.0_dp) + 4*batches*eps*error_of(batch(1, :)))
            call close_to(trim(which(q))//' rms error at point '//integer_text(p), e_rms(p), error_of(batch(2, :)), &
                          block*eps*largest/sqrt(batches - 1.0_dp) + 4*batches*eps*error_of(batch(2, :)))
            call close_to(trim(which(q))//' min error at point '//integer_text(p), e_low(p), error_of(batch(3, :)), &
                          4*batches*eps*largest)
            call close_to(trim(which(q))//' max error at point '//integer_text(p), e_high(p), error_of(batch(4, :)), &
                          4*batches*eps*largest)
            deallocate (batch)
         end do
      end do
   end subroutine check_points

   !> The seven contact statistics of the tip contact point, of each stop and of the beam.
   subroutine check_contacts()
      integer :: k
      step_impulse = tip_impulse(first + 2:last + 1)   ! the impulse of steps first+1 .. last
      call load('/impacts/time', impact_time)
      call load('/impacts/impulse', impact_impulse)
      call load('/episodes/start', episode_start)
      call load('/episodes/impulse', episode_impulse)
      impact_step = [(nint(impact_time(k)/dt, int64) + offset_position, k = 1, size(impact_time))]
      episode_step = [(nint(episode_start(k)/dt, int64) + offset_position, k = 1, size(episode_start))]
      call t%check_true('impacts in the window', count(impact_step > first) > 10)
      ! contact point 1 (the tip), the stops, the beam
      call target('contacts', 1, 0.0_dp)
      call target('obstacles', below, 1.0_dp)
      call target('obstacles', above, -1.0_dp)
      call target('beam', 1, 0.0_dp)
   end subroutine check_contacts

   !> Statistics of the impulses with the sign `sign` (0: any) at entry `index` of `group`.
   subroutine target(group, index, sign)
      character(len=*), intent(in) :: group
      integer, intent(in) :: index
      real(dp), intent(in) :: sign
      character(len=*), parameter :: names(7) = [character(len=24) :: 'impact_rate', 'episode_rate', &
         'episode_impulse_mean', 'episode_impulse_max', 'episode_impulse_rms', 'contact_fraction', 'contact_force']
      real(dp) :: expected(7), batch(7, batches), bound(7), largest_impulse, largest_force
      real(dp), allocatable :: values(:), errors(:)
      integer :: j, b
      character(len=:), allocatable :: label
      wanted = sign
      call statistics_over(first, last, expected)
      do b = 1, int(batches)
         call statistics_over(first + (b - 1)*block, first + b*block, batch(:, b))
      end do
      largest_impulse = maxval([0.0_dp, pack(abs(episode_impulse), matches(episode_impulse))])
      largest_force = maxval(abs(step_impulse))
      ! counts and rates exact; sums of K (or of the episodes') terms as in the header
      bound = [0.0_dp, 0.0_dp, 2*size(episode_impulse)*eps*largest_impulse, 0.0_dp, &
               size(episode_impulse)*eps*largest_impulse, 0.0_dp, 2*samples*eps*largest_force/dt]
      do j = 1, 7
         label = group//' '//trim(names(j))//'('//integer_text(index)//')'
         values = reported(group//'/'//trim(names(j)))
         errors = reported(group//'/'//trim(names(j))//'_error')
         if (size(values) < index .or. size(errors) < index) then
            call t%check_true(label//' present', .false.)
            cycle
         end if
         call close_to(label, values(index), expected(j), bound(j) + 2*eps*abs(expected(j)))
         ! a block's sums hold fewer terms than the window's: bound(j) bounds them too
         call close_to(label//' error', errors(index), error_of(batch(j, :)), &
                       (bound(j) + 2*eps*maxval(abs(batch(j, :))))/sqrt(batches - 1.0_dp) + &
                       4*batches*eps*error_of(batch(j, :)))
      end do
   end subroutine target

   !> Impacts, episodes and impulses of steps from+1 .. to with the wanted sign.
   subroutine statistics_over(from, to, values)
      integer(int64), intent(in) :: from, to
      real(dp), intent(out) :: values(7)
      logical, allocatable :: in_episode(:), in_step(:)
      real(dp) :: steps, span
      integer :: n
      steps = real(to - from, dp)
      span = steps*dt
      values(1) = count(impact_step > from .and. impact_step <= to .and. matches(impact_impulse))/span
      in_episode = episode_step > from .and. episode_step <= to .and. matches(episode_impulse)
      associate (chosen => abs(pack(episode_impulse, in_episode)))
         values(2) = size(chosen)/span
         values(3:5) = 0
         if (size(chosen) > 0) values(3:5) = [sum(chosen)/size(chosen), maxval(chosen), &
                                              sqrt(sum(chosen**2)/size(chosen))]
      end associate
      allocate (in_step(to - from))
      do n = int(from) + 1, int(to)
         in_step(n - from) = abs(tip_impulse(n + 1)) > 0 .and. matches(tip_impulse(n + 1))
      end do
      values(6) = count(in_step)/steps
      values(7) = sum(abs(tip_impulse(from + 2:to + 1)), mask=in_step)/span
   end subroutine statistics_over

   !> The impulses pushed by the target: positive ones by the stop below, negative by the
   !! one above, any for the tip and the beam.
   elemental logical function matches(impulse)
      real(dp), intent(in) :: impulse
      matches = abs(wanted) <= 0 .or. impulse*wanted > 0
   end function matches

   !> Powers: changes of the stored energy sums over the window and over each block.
   subroutine check_energy()
      character(len=*), parameter :: names(8) = [character(len=24) :: 'power_input', 'power_impacts', &
         'power_damping', 'power_numerical', 'power_contact_damping', 'power_dissipated', 'power_stored', &
         'balance_residual']
      character(len=*), parameter :: paths(8) = [character(len=36) :: '/energy/work', '/energy/dissipated_impacts', &
         '/energy/dissipated_damping', '/energy/dissipated_numerical', '/energy/dissipated_contact_damping', &
         '/energy/dissipated', '/energy/total', '/energy/balance']
      real(dp), allocatable :: level(:), values(:), errors(:)
      real(dp) :: batch(batches), scale, expected
      integer :: j, b
      do j = 1, 8
         if (j == 5 .and. .not. compliant()) then
            ! rigid stops only: no contact damping
            values = reported('energy/'//trim(names(j)))
            call t%check_true('energy '//trim(names(j))//' 0 without springs', size(values) == 1 .and. &
                              all(abs(values) <= 0))
            cycle
         end if
         call load(trim(paths(j)), level)
         values = reported('energy/'//trim(names(j)))
         errors = reported('energy/'//trim(names(j))//'_error')
         if (size(values) /= 1 .or. size(level) /= last + 1) cycle
         expected = (level(last + 1) - level(first + 1))/duration
         do b = 1, int(batches)
            batch(b) = (level(first + b*block + 1) - level(first + (b - 1)*block + 1))/(block*dt)
         end do
         ! one rounding per subtraction and division; 'dissipated' is a sum of four powers
         ! there and a difference of the stored sum here: 4 eps of the largest sum
         scale = 4*eps*maxval(abs(level))/(block*dt)
         call close_to('energy '//trim(names(j)), values(1), expected, scale*block/samples + 2*eps*abs(expected))
         call close_to('energy '//trim(names(j))//' error', errors(1), error_of(batch), &
                       scale/sqrt(batches - 1.0_dp) + 4*batches*eps*error_of(batch))
      end do
   end subroutine check_energy

   !> True when the run has compliant stops (it wrote /contact/force).
   logical function compliant()
      real(dp), allocatable :: peak(:)
      call read_real_1d(trim(file), '/contact/peak_force', peak, stat, errmsg)
      compliant = stat == 0
   end function compliant

   !> The force statistics of the compliant stops at each contact point (0 without springs).
   subroutine check_forces()
      character(len=*), parameter :: names(7) = [character(len=28) :: 'force_peak', 'force_mean', &
         'force_contact_mean', 'force_contact_rms', 'force_contact_fraction', 'force_episode_duration_mean', &
         'force_episode_duration_max']
      real(dp), allocatable :: force(:, :), values(:), errors(:), f(:)
      real(dp) :: expected(7), batch(7, batches), bound(7), largest
      integer :: c, j, b, contacts
      contacts = size(reported('contacts/impact_rate'))
      if (.not. compliant()) then
         do j = 1, 7
            values = reported('contacts/'//trim(names(j)))
            call t%check_true('contacts '//trim(names(j))//' 0 without springs', size(values) == contacts .and. &
                              all(abs(values) <= 0))
         end do
         return
      end if
      call read_real_2d(trim(file), '/contact/force', force, stat, errmsg)
      call t%check_true('read /contact/force', stat == 0 .and. size(force, 2) == last + 1, errmsg)
      if (stat /= 0 .or. size(force, 2) /= last + 1) return
      call t%check_true('compliant episodes in the window', count(abs(force(1, first + 2:)) > 0) > 100)
      do c = 1, contacts
         f = abs(force(c, :))   ! f(n + 1): after step n
         largest = maxval(f(first + 2:))
         call forces_over(f, first, last, expected)
         do b = 1, int(batches)
            call forces_over(f, first + (b - 1)*block, first + b*block, batch(:, b))
         end do
         associate (m => count(f(first + 2:) > 0))
            bound = [0.0_dp, 2*samples*eps*largest, 2*m*eps*largest, m*eps*expected(4), 0.0_dp, &
                     4*eps*expected(6), 4*eps*expected(7)]
         end associate
         do j = 1, 7
            values = reported('contacts/'//trim(names(j)))
            errors = reported('contacts/'//trim(names(j))//'_error')
            if (size(values) < c .or. size(errors) < c) then
               call t%check_true('contacts '//trim(names(j))//' present', .false.)
               cycle
            end if
            call close_to('contacts '//trim(names(j))//'('//integer_text(c)//')', values(c), expected(j), &
                          bound(j) + 2*eps*abs(expected(j)))
            call close_to('contacts '//trim(names(j))//'('//integer_text(c)//') error', errors(c), &
                          error_of(batch(j, :)), (bound(j) + 2*eps*maxval(abs(batch(j, :))))/sqrt(batches - 1.0_dp) &
                          + 4*batches*eps*error_of(batch(j, :)))
         end do
      end do
   end subroutine check_forces

   !> Force statistics of steps from+1 .. to (f(n + 1) = |force| after step n); the
   !! episodes that open there last until the first step without force, or to the end
   !! of the window (step last) when none comes.
   subroutine forces_over(f, from, to, values)
      real(dp), intent(in) :: f(0:)
      integer(int64), intent(in) :: from, to
      real(dp), intent(out) :: values(7)
      real(dp) :: steps, in_contact, episodes, total_steps, longest
      integer(int64) :: n, e
      associate (x => f(from + 1:to))
         steps = real(to - from, dp)
         in_contact = count(x > 0)
         values = 0
         values(1) = maxval(x)
         values(2) = sum(x)/steps
         if (in_contact > 0) values(3:4) = [sum(x, mask=x > 0)/in_contact, sqrt(sum(x**2, mask=x > 0)/in_contact)]
         values(5) = in_contact/steps
      end associate
      episodes = 0
      total_steps = 0
      longest = 0
      do n = from + 1, to
         ! an episode opens at step n: force after it, none after step n - 1 (none before step 1)
         if (f(n) <= 0) cycle
         if (n > 1) then
            if (f(n - 1) > 0) cycle
         end if
         e = n
         do while (e <= last)
            if (f(e) <= 0) exit
            e = e + 1
         end do
         episodes = episodes + 1
         total_steps = total_steps + (e - n)
         longest = max(longest, real(e - n, dp))
      end do
      if (episodes > 0) values(6:7) = [total_steps*dt/episodes, longest*dt]
   end subroutine forces_over

   !> The three largest local maxima of the amplitude spectrum of the tip displacement
   !! over the window (mean removed, periodic Hann window), by a direct DFT.
   subroutine check_spectrum()
      real(dp), allocatable :: amplitude(:), frequency(:), reported_f(:), reported_a(:)
      real(dp) :: x(samples), w(samples), c(samples), s(samples)
      real(dp) :: re, im, delta_a, width, left, middle, right, curvature, shift, f, a
      integer :: n, k, j, i, bins, found
      integer, allocatable :: peaks(:)
      logical, allocatable :: candidate(:)
      n = int(samples)
      x = tip_u(first + 2:last + 1)
      x = x - sum(x)/n
      bins = n/2 + 1
      allocate (amplitude(bins), frequency(bins))
      ! the window, and cos and sin of 2 pi r/n, r = j k mod n: every angle reduced exactly
      do j = 0, n - 1
         w(j + 1) = 0.5_dp*(1 - cos(2*pi*j/n))
         c(j + 1) = cos(2*pi*j/n)
         s(j + 1) = sin(2*pi*j/n)
      end do
      x = w*x
      do k = 0, bins - 1
         re = 0
         im = 0
         do j = 0, n - 1
            i = int(mod(int(j, int64)*k, int(n, int64))) + 1
            re = re + x(j + 1)*c(i)
            im = im - x(j + 1)*s(i)
         end do
         amplitude(k + 1) = sqrt(re**2 + im**2)/sum(w)
         if (k > 0 .and. 2*k /= n) amplitude(k + 1) = 2*amplitude(k + 1)
         frequency(k + 1) = k/(n*dt)
      end do
      width = 1/(n*dt)
      ! x holds w (x - mean): n products summed, times 2/sum(w) = 4/n
      delta_a = 4*n*eps*maxval(abs(x))
      allocate (candidate(bins))
      candidate = .false.
      do i = 2, bins
         if (amplitude(i) <= amplitude(i - 1)) cycle
         if (i < bins) then
            if (amplitude(i) < amplitude(i + 1)) cycle
         end if
         candidate(i) = .true.
      end do
      found = min(3, count(candidate))
      allocate (peaks(found))
      do j = 1, found
         peaks(j) = maxloc(amplitude, dim=1, mask=candidate)
         candidate(peaks(j)) = .false.
      end do
      call load('/statistics/spectrum/peak_frequency', reported_f)
      call load('/statistics/spectrum/peak_amplitude', reported_a)
      call t%check_true('three peaks', found == 3 .and. size(reported_f) == 3)
      if (found /= 3 .or. size(reported_f) /= 3) return
      do j = 1, found
         i = peaks(j)
         f = frequency(i)
         a = amplitude(i)
         curvature = -huge(1.0_dp)
         if (i < bins) then
            left = amplitude(i - 1)
            middle = amplitude(i)
            right = amplitude(i + 1)
            curvature = left - 2*middle + right
            if (curvature < 0) then
               shift = 0.5_dp*(left - right)/curvature
               f = frequency(i) + shift*width
               a = middle - 0.25_dp*(left - right)*shift
            end if
         end if
         call close_to('spectrum peak '//integer_text(j)//' frequency (Hz)', reported_f(j), f, &
                       3*delta_a/abs(curvature)*width + 4*eps*f)
         call close_to('spectrum peak '//integer_text(j)//' amplitude (m)', reported_a(j), a, &
                       2*delta_a + abs(left - right)*delta_a/abs(curvature))
      end do
   end subroutine check_spectrum

   !> The state at t_m = (2 pi m - phi_0)/Omega in (t_start, t_end], interpolated.
   subroutine check_poincare()
      real(dp), allocatable :: times(:), u(:, :), v(:, :)
      real(dp) :: omega, phase, t_m, weight, expected, amplitude, frequency
      character(len=:), allocatable :: choice
      integer(int64) :: m, n
      integer :: k, p, q
      ! the first harmonic load of base, point, distributed (&output poincare_load = 'auto')
      call read_attr_string(trim(file), '/', 'output.poincare_load', choice, stat, errmsg)
      call t%check_true('poincare_load auto', choice == 'auto', choice)
      omega = 0
      phase = 0
      call read_attr_real(trim(file), '/', 'load.base_acceleration', amplitude, stat, errmsg)
      call read_attr_real(trim(file), '/', 'load.base_frequency', frequency, stat, errmsg)
      if (abs(amplitude) > 0 .and. frequency > 0) omega = frequency
      if (omega <= 0) then
         call read_attr_real(trim(file), '/', 'load.point_force', amplitude, stat, errmsg)
         call read_attr_real(trim(file), '/', 'load.point_frequency', frequency, stat, errmsg)
         if (abs(amplitude) > 0 .and. frequency > 0) omega = frequency
      end if
      call t%check_true('a harmonic load', omega > 0)
      if (omega <= 0) return
      call load('/statistics/poincare/time', times)
      call read_real_2d(trim(file), '/statistics/poincare/displacement', u, stat, errmsg)
      call read_real_2d(trim(file), '/statistics/poincare/velocity', v, stat, errmsg)
      m = floor((omega*first*dt + phase)/(2*pi), int64) + 1
      k = 0
      do
         t_m = (2*pi*m - phase)/omega
         if (t_m > last*dt) exit
         if (t_m > first*dt) then
            k = k + 1
            if (k > size(times)) exit
            n = ceiling(t_m/dt, int64)
            if (n*dt < t_m) n = n + 1
            if ((n - 1)*dt >= t_m) n = n - 1
            weight = (t_m - (n - 1)*dt)/dt
            call close_to('poincare time '//integer_text(k), times(k), t_m, 2*eps*t_m)
            do q = 1, 2
               do p = 1, points
                  expected = observed(n - 1, p, q) + weight*(observed(n, p, q) - observed(n - 1, p, q))
                  if (q == 1) then
                     call close_to('poincare u '//integer_text(k), u(p, k), expected, &
                                   4*eps*maxval(abs(observed(:, p, q))))
                  else
                     call close_to('poincare v '//integer_text(k), v(p, k), expected, &
                                   4*eps*maxval(abs(observed(:, p, q))))
                  end if
               end do
            end do
         end if
         m = m + 1
      end do
      call t%check_true('poincare sample count', k == size(times) .and. k >= 4, &
                        integer_text(k)//' expected, '//integer_text(size(times))//' written')
   end subroutine check_poincare

   !> sqrt(sum (x - mean)^2 / (c (c - 1))).
   pure real(dp) function error_of(values)
      real(dp), intent(in) :: values(:)
      real(dp) :: mean
      integer :: c
      c = size(values)
      mean = sum(values)/c
      error_of = sqrt(sum((values - mean)**2)/(real(c, dp)*(c - 1)))
   end function error_of

   subroutine close_to(name, value, reference, tolerance)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value, reference, tolerance
      ! the room left, as every test reports it (largest |value - reference| / tolerance)
      if (tolerance > 0 .and. ieee_is_finite(value)) then
         if (abs(value - reference)/tolerance >= t%worst_ratio) then
            t%worst_ratio = abs(value - reference)/tolerance
            t%worst_check = name
         end if
      end if
      if (ieee_is_finite(value) .and. abs(value - reference) <= tolerance) then
         t%passed = t%passed + 1
      else
         call t%check_true(name, .false., 'value '//real_text(value)//', recomputed '//real_text(reference)// &
                           ', difference '//real_text(abs(value - reference))//', tolerance '//real_text(tolerance))
      end if
   end subroutine close_to
end program check_statistics
