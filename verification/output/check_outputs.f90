!> What the dynamics outputs say they are (docs/output.md, docs/method.md "Impacts and
!! contact statistics"), each against a reference computed here independently of the
!! recorder.   usage: check_outputs MODE FILE.h5
!!
!! resting  (resting.nml): a beam that starts at rest on its tip stop logs no impact and
!!          no episode; its mean tip reaction is the static reaction of beam theory,
!!          R = 3EI(qL^4/(8EI) - g)/L^3 = 10.35 N, at every output after t = 0; the sum of
!!          reaction x interval equals the sum of /tip/impulse (same numbers, multiplied
!!          and divided: 4 eps per term) and R t_end; the tip is in contact the whole run;
!!          /energy/dissipated is the sum of its three parts and /energy/balance is
!!          total - work + dissipated; /run holds every attribute of docs/output.md.
!! episodes (episodes.nml): the episodes recomputed from /impacts with the rule (impacts
!!          at one point closer than the gap belong to one episode): same count, start
!!          times, impact counts and largest approach speeds (exact: the same numbers);
!!          each end lies between its last impact and the next episode's start; each total
!!          impulse has the sign of its impacts and is at least their sum (the steps of
!!          persistent contact push the same way); the default gap is 0.05 x 2 pi/omega_1
!!          with beta_1 L = 1.8751040687119611664 (published root of 1 + cos cosh = 0).
!! points   (points.nml): /points/displacement at t = 0 equals the Hermite interpolant of
!!          the exact static deflection u(x) = q x^2 (6L^2 - 4Lx + x^2)/(24 EI): u(x) -
!!          q/(24 EI) (x - x_i)^2 (x - x_i+1)^2 in element [x_i, x_i+1] (the Hermite element
!!          solution of a beam is exact at the nodes, u'''' = q/EI), to 1e-11 of max |u|
!!          (round-off of a static solve of condition ~1e3 at N = 4); nodal snapping would
!!          miss by 1e-2 of max |u|. /time holds t = n dt for n = 0, 3, ..., 21, 23 and
!!          /field/time for n = 0, 5, ..., 20, 23 (every = 3, field_every = 5, 23 steps).
program check_outputs
   use vibrobeam_kinds, only: dp, int64, pi, output_unit
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_real_2d, read_attr_real, read_attr_string
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_test_support, only: test_counter
   implicit none
   ! the steel cantilever of the scenes
   real(dp), parameter :: length = 0.5_dp, ei = 210e9_dp*1.6666666666666667e-9_dp, rho_s = 7850*2e-4_dp
   real(dp), parameter :: q = -100, gap_below = 1e-3_dp
   type(test_counter) :: t
   character(len=512) :: mode, file, errmsg
   integer :: stat
   ! the impacts and episodes of the 'episodes' mode
   real(dp), allocatable :: impact_time(:), impact_x(:), impact_impulse(:), before(:)
   real(dp), allocatable :: x(:), start(:), finish(:), impulse(:), approach(:), counts(:), still_open(:)
   integer :: groups

   call get_command_argument(1, mode)
   call get_command_argument(2, file)
   select case (trim(mode))
   case ('resting')
      call check_resting()
   case ('episodes')
      call check_episodes()
   case ('points')
      call check_points()
   case default
      call t%check_true('known mode', .false., 'usage: check_outputs resting|episodes|points FILE.h5')
   end select
   call t%finish('check_outputs '//trim(mode))

contains

   !> The 1-d dataset `path` of the file (empty when it cannot be read: a failed check).
   subroutine load(path, values)
      character(len=*), intent(in) :: path
      real(dp), allocatable, intent(out) :: values(:)
      call read_real_1d(trim(file), path, values, stat, errmsg)
      call t%check_true('read '//path, stat == 0, errmsg)
      if (stat /= 0) then
         if (allocated(values)) deallocate (values)
         allocate (values(0))
      end if
   end subroutine load

   subroutine check_resting()
      real(dp), allocatable :: time(:), reaction(:), impulse(:), fraction(:), total(:), work(:), dissipated(:), &
                               impacts(:), damping(:), numerical(:), balance(:)
      real(dp) :: r_static, sum_products, sum_impulses, bound, dt, value, t_end
      integer(int64) :: steps, count
      character(len=:), allocatable :: text
      type(h5_reader) :: h5
      integer :: k
      character(len=*), parameter :: counters(*) = [character(len=40) :: 'steps', 'start_step', &
         'contact_solver_iterations', 'contact_solver_iterations_max_per_step', 'contact_linear_solves', &
         'contact_linear_solves_max_per_step', 'contact_fallback_steps', 'flushed_step', 'flushed_outputs', &
         'flushed_field_outputs', 'flushed_impacts', 'flushed_episodes']
      r_static = 3*ei*(abs(q)*length**4/(8*ei) - gap_below)/length**3
      call load('/impacts/time', time)
      call t%check_true('no impact', size(time) == 0, integer_text(size(time))//' impacts logged')
      call load('/episodes/start', time)
      call t%check_true('no episode', size(time) == 0)
      call load('/time', time)
      call load('/tip/reaction', reaction)
      call load('/tip/impulse', impulse)
      call t%check_close('tip reaction at t = 0', reaction(1), 0.0_dp, 0.0_dp, 1.0_dp)
      ! the static reaction to the accuracy of the static solve (1e-8, verification/dynamics/test_static)
      call t%check_close('smallest mean tip reaction after t = 0 (N)', minval(reaction(2:)), r_static, 1e-8_dp)
      call t%check_close('largest mean tip reaction (N)', maxval(reaction(2:)), r_static, 1e-8_dp)
      sum_products = sum(reaction(2:)*(time(2:) - time(:size(time) - 1)))
      sum_impulses = sum(impulse)
      bound = 4*epsilon(1.0_dp)*sum(abs(impulse))
      call t%check_close('sum of reaction x interval = sum of tip impulses (N s)', sum_products, sum_impulses, &
                         bound/max(abs(sum_impulses), tiny(1.0_dp)))
      call read_attr_real(trim(file), '/', 'time.t_end', t_end, stat, errmsg)
      call t%check_close('sum of tip impulses = R t_end (N s)', sum_impulses, r_static*t_end, 1e-8_dp)
      call load('/contact/fraction', fraction)
      call read_attr_real(trim(file), '/', 'time.dt', dt, stat, errmsg)
      ! contact time is a sum of n dt, t_end the product n dt: n eps apart at most
      call t%check_close('contact fraction of the tip', fraction(1), 1.0_dp, size(time)*10*epsilon(1.0_dp))
      call load('/energy/total', total)
      call load('/energy/work', work)
      call load('/energy/dissipated', dissipated)
      call load('/energy/dissipated_impacts', impacts)
      call load('/energy/dissipated_damping', damping)
      call load('/energy/dissipated_numerical', numerical)
      call load('/energy/balance', balance)
      bound = epsilon(1.0_dp)*maxval(abs([total, work, dissipated]))
      call t%check_true('dissipated = impacts + damping + numerical', &
                        all(abs(dissipated - (impacts + damping + numerical)) <= 2*bound))
      call t%check_true('balance = total - work + dissipated', &
                        all(abs(balance - (total - work + dissipated)) <= 4*bound))
      call read_attr_string(trim(file), '/run', 'status', text, stat, errmsg)
      call t%check_true('/run status is ok', stat == 0 .and. text == 'ok', text)
      call read_attr_string(trim(file), '/run', 'run_id', text, stat, errmsg)
      call t%check_true('/run run_id is given', stat == 0 .and. len(text) > 16, text)
      call read_attr_real(trim(file), '/run', 'wall_seconds', value, stat, errmsg)
      call t%check_true('/run wall_seconds > 0', stat == 0 .and. value > 0)
      call h5%open(trim(file), stat, errmsg)
      do k = 1, size(counters)
         call h5%attr_int64('/run', trim(counters(k)), count, stat, errmsg)
         call t%check_true('/run '//trim(counters(k))//' >= 0', stat == 0 .and. count >= 0, errmsg)
      end do
      call h5%attr_int64('/run', 'steps', steps, stat, errmsg)
      call t%check_true('/run steps = t_end/dt', steps == nint(t_end/dt, int64), integer_text(int(steps)))
      call h5%attr_int64('/run', 'flushed_outputs', count, stat, errmsg)
      call t%check_true('/run flushed_outputs = rows of /time', count == size(time))
      call h5%close()
      write (output_unit, '(a)') 'resting beam: R = '//real_text(r_static)//' N, mean reactions '// &
         real_text(minval(reaction(2:)))//' .. '//real_text(maxval(reaction(2:)))//' N'
   end subroutine check_resting

   subroutine check_episodes()
      real(dp), allocatable :: points(:)
      integer, allocatable :: mine(:)
      real(dp) :: gap, expected_gap, omega_1
      integer :: p, i, j, first
      call load('/impacts/time', impact_time)
      call load('/impacts/x', impact_x)
      call load('/impacts/impulse', impact_impulse)
      call load('/impacts/velocity_before', before)
      call load('/episodes/x', x)
      call load('/episodes/start', start)
      call load('/episodes/end', finish)
      call load('/episodes/impulse', impulse)
      call load('/episodes/approach_speed', approach)
      call load('/episodes/impacts', counts)
      call load('/episodes/open_at_end', still_open)
      call read_attr_real(trim(file), '/episodes', 'gap', gap, stat, errmsg)
      omega_1 = 1.8751040687119611664_dp**2*sqrt(ei/rho_s)/length**2
      expected_gap = 0.05_dp*2*pi/omega_1
      call t%check_close('default episode gap 0.05 x 2 pi/omega_1 (s)', gap, expected_gap, 1e-12_dp)
      call t%check_true('more impacts than episodes (micro-bounces are grouped)', size(impact_time) > size(x))
      ! the contact points that saw impacts
      allocate (points(0))
      do i = 1, size(impact_x)
         if (.not. any(same(points, impact_x(i)))) points = [points, impact_x(i)]
      end do
      groups = 0
      do p = 1, size(points)
         mine = pack([(i, i=1, size(impact_x))], same(impact_x, points(p)))   ! in time order
         first = 1
         do j = 2, size(mine) + 1
            if (j <= size(mine)) then
               if (impact_time(mine(j)) - impact_time(mine(j - 1)) < gap) cycle
            end if
            call check_group(mine(first:j - 1), j <= size(mine))
            first = j
         end do
      end do
      call t%check_true('as many episodes recomputed as written', groups == size(x), integer_text(groups)// &
                        ' recomputed, '//integer_text(size(x))//' written')
      write (output_unit, '(a)') 'episodes: '//integer_text(size(impact_time))//' impacts in '// &
         integer_text(size(x))//' episodes, gap '//real_text(gap)//' s'
   end subroutine check_episodes

   !> Equal bit patterns.
   elemental logical function same_bits(a, b)
      real(dp), intent(in) :: a, b
      same_bits = transfer(a, 1_int64) == transfer(b, 1_int64)
   end function same_bits

      elemental logical function same(a, b)
         real(dp), intent(in) :: a, b
         same = abs(a - b) <= 0
      end function same
      !> The impacts `group` (of one point, consecutive ones closer than the gap) are an
      !! episode; `followed` when another impact of the point comes after them.
      subroutine check_group(group, followed)
         integer, intent(in) :: group(:)
         logical, intent(in) :: followed
         real(dp) :: next_start, total, fastest
         integer :: k, found
         groups = groups + 1
         found = 0
         do k = 1, size(x)
            if (same(x(k), impact_x(group(1))) .and. same(start(k), impact_time(group(1)))) found = k
         end do
         call t%check_true('an episode at x = '//real_text(impact_x(group(1)))//' m starts at '// &
                           real_text(impact_time(group(1)))//' s', found > 0)
         if (found == 0) return
         total = sum(impact_impulse(group))
         fastest = maxval(abs(before(group)))
         next_start = huge(1.0_dp)
         if (followed) next_start = minval(impact_time, mask=same(impact_x, impact_x(group(1))) .and. &
                                           impact_time > impact_time(group(size(group))))
         call t%check_true('episode at '//real_text(start(found))//' s: impacts', &
                           nint(counts(found)) == size(group), integer_text(nint(counts(found)))//' vs '// &
                           integer_text(size(group)))
         call t%check_true('episode at '//real_text(start(found))//' s: largest approach speed', &
                           same(approach(found), fastest), real_text(approach(found))//' vs '//real_text(fastest))
         call t%check_true('episode at '//real_text(start(found))//' s: end between its last impact and the next', &
                           finish(found) >= impact_time(group(size(group))) .and. finish(found) < next_start)
         call t%check_true('episode at '//real_text(start(found))//' s: impulse at least that of its impacts', &
                           impulse(found)*total > 0 .and. abs(impulse(found)) >= abs(total)*(1 - 1e-12_dp), &
                           real_text(impulse(found))//' vs '//real_text(total))
         call t%check_true('episode at '//real_text(start(found))//' s: open only if last', &
                           nint(still_open(found)) == 0 .or. .not. followed)
      end subroutine check_group

   subroutine check_points()
      real(dp), allocatable :: x(:), u(:, :), time(:), field_time(:), mesh(:)
      real(dp) :: exact, interpolant, h, left, scale, dt, worst
      integer :: p, element
      integer(int64), parameter :: output_steps(*) = [0, 3, 6, 9, 12, 15, 18, 21, 23]
      integer(int64), parameter :: field_steps(*) = [0, 5, 10, 15, 20, 23]
      call load('/points/x', x)
      call load('/mesh/x', mesh)
      call read_real_2d(trim(file), '/points/displacement', u, stat, errmsg)
      call t%check_true('read /points/displacement', stat == 0, errmsg)
      if (stat /= 0) return
      h = length/(size(mesh) - 1)
      scale = abs(q)*length**4/(8*ei)   ! tip deflection, the largest |u|
      worst = 0
      do p = 1, size(x)
         exact = q*x(p)**2*(6*length**2 - 4*length*x(p) + x(p)**2)/(24*ei)
         element = min(size(mesh) - 1, int(x(p)/h) + 1)
         left = (element - 1)*h
         interpolant = exact - q/(24*ei)*(x(p) - left)**2*(x(p) - left - h)**2
         call t%check_close('u at x = '//real_text(x(p))//' m (Hermite interpolant of the exact deflection)', &
                            u(p, 1), interpolant, 1e-11_dp, scale)
         worst = max(worst, abs(u(p, 1) - interpolant)/scale)
      end do
      call read_attr_real(trim(file), '/', 'time.dt', dt, stat, errmsg)
      call load('/time', time)
      call load('/field/time', field_time)
      call t%check_true('/time at n = 0, 3, ..., 21, 23 steps', size(time) == size(output_steps))
      if (size(time) == size(output_steps)) call t%check_true('/time = n dt', all(same_bits(time, output_steps*dt)))
      call t%check_true('/field/time at n = 0, 5, ..., 20, 23 steps', size(field_time) == size(field_steps))
      if (size(field_time) == size(field_steps)) call t%check_true('/field/time = n dt', &
                                                                  all(same_bits(field_time, field_steps*dt)))
      write (output_unit, '(a)') 'points: largest |u - Hermite interpolant of the exact u|/max|u| = '//real_text(worst)
   end subroutine check_points
end program check_outputs
