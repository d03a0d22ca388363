!> Statistics of a dynamics run over a window (docs/statistics.md): fed by the recorder
!! after every step, O(1) memory per observed quantity, its state in the checkpoint.
!!
!! The window starts at step n0, the first step with n0 dt >= measure_from (to 1e-9 dt,
!! so a measure_from computed as a multiple of dt lands on its step), and ends at the
!! run's last step N. Its samples are the steps n0+1 .. N (K = N - n0 of them, T = K dt):
!! the state after each of these steps and what happened in it (impulses, impacts).
!! Contact episodes (/episodes) count in the window when they open in one of its steps;
!! they are added when they close, or at the end of the window when still open.
!! Sub-windows for standard errors: `vibrobeam_batch_blocks`. Which statistics:
!! `vibrobeam_statistics_layout`.
module vibrobeam_statistics
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_state_record, only: state_record
   use vibrobeam_step_observer, only: step_observer, step_events
   use vibrobeam_batch_blocks, only: block_accumulator, standard_error
   use vibrobeam_poincare, only: poincare_sampler
   use vibrobeam_poincare_diagnostics, only: poincare_diagnostics
   use vibrobeam_welch, only: welch_estimator
   use vibrobeam_spectrum, only: interpolated_peaks
   use vibrobeam_contact_fill, only: fill, fill_force, f_force, f_force_square, f_steps, f_episodes, f_episode_steps, &
      per_force, x_force, x_episode_steps, per_force_extreme
   use vibrobeam_statistics_layout, only: statistics_layout, peak_count, group_points, group_contacts, &
      group_obstacles, group_beam, group_energy, group_spectrum, group_poincare
   implicit none
   private
   public :: run_statistics, statistics_result, window_first_step, first_value

   !> Levels recorded at block boundaries: the running sums of the stepper and the balance.
   integer, parameter :: level_work = 1, level_impacts = 2, level_damping = 3, level_numerical = 4, &
                         level_contact_damping = 5, level_total = 6, level_balance = 7, level_count = 7, &
                         level_friction = 8   ! only with friction (after the planar levels)
   !> Sum quantities per contact target (a contact point, an obstacle or the beam).
   integer, parameter :: s_impacts = 1, s_episodes = 2, s_impulse = 3, s_impulse_square = 4, s_contact_steps = 5, &
                         s_force = 6, per_target = 6

   !> What the statistics of a window are (docs/statistics.md).
   type :: statistics_result
      logical :: present = .false.                !! a window with at least one step
      type(statistics_layout) :: layout
      real(dp), allocatable :: values(:)          !! (layout%size)
      real(dp), allocatable :: errors(:)          !! (layout%size) standard errors; 0 where none
      integer(int64) :: first_step = 0            !! n0
      integer(int64) :: steps = 0                 !! K
      integer(int64) :: block_steps = 1           !! L
      integer :: batches = 0                      !! complete blocks c
      real(dp) :: window_start = 0, window_end = 0   !! n0 dt, N dt (s)
      real(dp) :: bin_width = 0                   !! of the tip spectrum (Hz)
      integer(int64) :: poincare_total = 0        !! Poincare samples in the window
      real(dp), allocatable :: poincare_time(:)   !! the latest ones (kept_samples at most)
      real(dp), allocatable :: poincare_values(:, :)  !! (2 points, samples): u at each point, then v
   end type statistics_result

   type, extends(step_observer) :: run_statistics
      logical :: active = .false.                 !! the run has a window
      logical :: started = .false.                !! the window has begun (step n0 seen)
      integer(int64) :: first_step = 0            !! n0
      real(dp) :: dt = 0
      integer :: points = 0, contacts = 0, obstacles = 0
      integer :: planes = 1                       !! 2: the points' statistics in z too (events%observed_z)
      integer, allocatable :: lower_obstacle(:), upper_obstacle(:)
      type(statistics_layout) :: layout
      type(block_accumulator) :: blocks
      type(poincare_sampler) :: poincare
      type(poincare_diagnostics) :: diagnostics   !! period, 0-1 test, Lyapunov exponent of the samples
      type(welch_estimator) :: spectrum, spectrum_z   !! the tip's displacement, in z with two planes
      !> (contact points) sample offset at which the open episode there opened; -1: none in the window
      integer(int64), allocatable :: episode_offset(:)
      !> (contact points) the compliant stops push there (force /= 0 after the last step)
      logical, allocatable :: force_touching(:)
      !> (contact points) sample offset at which the compliant episode there opened; -1: none in the window
      integer(int64), allocatable :: force_offset(:)
      ! the Poincare samples of the last step (the recorder streams them)
      integer :: poincare_found = 0
      real(dp), allocatable :: sample_times(:), sample_values(:, :)
      integer(int64) :: expected_samples = 0
   contains
      procedure :: init
      procedure :: begin_window
      procedure :: observe_start
      procedure :: observe_step
      procedure :: result
      procedure :: save_state
      procedure :: restore_state
   end type run_statistics

contains

   !> The value of statistic `name` of `group` in `outcome` (its first, for a vector).
   pure real(dp) function first_value(outcome, group, name)
      type(statistics_result), intent(in) :: outcome
      integer, intent(in) :: group
      character(len=*), intent(in) :: name
      first_value = outcome%values(outcome%layout%entries(outcome%layout%find(group, name))%offset + 1)
   end function first_value

   !> n0: the first step with n0 dt >= measure_from (module documentation).
   pure function window_first_step(measure_from, dt) result(step)
      real(dp), intent(in) :: measure_from, dt
      integer(int64) :: step
      step = max(0_int64, ceiling(measure_from/dt - 1e-9_dp, int64))
   end function window_first_step

   !> Statistics from step `first_step` to `last_step` (none when first_step >= last_step)
   !! of `points` observation points, the contact points with their obstacles, and
   !! Poincare samples at phase 0 of the forcing omega t + phase (omega = 0: none), with
   !! their diagnostics (the Lyapunov exponent when `lyapunov`, on the unknowns of `stepper`);
   !! for a beam of two planes with obstacles, the layout's 'wear' group (`wear_points`,
   !! `wear_volume`: filled by the recorder from `vibrobeam_support_wear`) and, with
   !! `friction` (the scene gives a friction coefficient, 0 too: the layout of every point
   !! of a sweep over it is the same), the power friction takes; `planes` = 2: the points'
   !! statistics in y and z.
   subroutine init(self, first_step, last_step, dt, points, lower_obstacle, upper_obstacle, obstacles, omega, phase, &
                   lyapunov, stepper, wear_points, wear_volume, friction, planes)
      class(run_statistics), intent(inout) :: self
      integer(int64), intent(in) :: first_step, last_step
      real(dp), intent(in) :: dt, omega, phase
      integer, intent(in) :: points, obstacles
      integer, intent(in) :: lower_obstacle(:), upper_obstacle(:)
      logical, intent(in) :: lyapunov
      class(time_stepper), intent(in) :: stepper
      integer, intent(in), optional :: wear_points, planes
      logical, intent(in), optional :: wear_volume, friction
      integer :: capacity
      self%active = first_step < last_step
      self%dt = dt
      self%points = points
      self%contacts = size(lower_obstacle)
      self%obstacles = obstacles
      self%lower_obstacle = lower_obstacle
      self%upper_obstacle = upper_obstacle
      self%planes = 1
      if (present(planes)) self%planes = planes
      call self%layout%init(points, self%contacts, obstacles, wear_points, wear_volume, friction, self%planes)
      allocate (self%episode_offset(self%contacts), self%force_offset(self%contacts), source=-1_int64)
      allocate (self%force_touching(self%contacts), source=.false.)
      call self%poincare%init(omega, phase, dt, 2*points)
      call self%diagnostics%init(points, omega, lyapunov, stepper)
      capacity = 1
      if (omega > 0) capacity = int(min(1e6_dp, dt*omega/(8*atan(1.0_dp)))) + 2
      allocate (self%sample_times(capacity), self%sample_values(2*points, capacity))
      self%expected_samples = max(1_int64, last_step - first_step)
      ! every item of the checkpoint exists from the start, with its size for the run
      call self%blocks%init(sum_count(self), extreme_count(self), &
                            spread(0.0_dp, 1, level_count + merge(1, 0, self%layout%friction)))
      call self%begin_window(first_step)
   end subroutine init

   !> Begin a new window at step `first_step` (sweeps measure window after window);
   !! nothing is accumulated until that step has been observed.
   subroutine begin_window(self, first_step)
      class(run_statistics), intent(inout) :: self
      integer(int64), intent(in) :: first_step
      self%first_step = first_step
      self%started = .false.
      self%episode_offset = -1
      self%force_offset = -1
      call self%spectrum%init(self%dt, self%expected_samples)
      if (self%planes == 2) call self%spectrum_z%init(self%dt, self%expected_samples)
   end subroutine begin_window

   !> The run's starting state (t = 0, or a checkpoint): the window starts here when n0 is
   !! this step. `observed` (points, 2): u and v at the observation points.
   subroutine observe_start(self, stepper, observed)
      class(run_statistics), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: observed(:, :)
      if (self%active .and. .not. self%started .and. stepper%steps == self%first_step) &
         call start(self, stepper, observed)
   end subroutine observe_start

   !> Levels at the window's start, the state for Poincare interpolation, empty blocks.
   subroutine start(self, stepper, observed)
      type(run_statistics), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: observed(:, :)
      call self%blocks%init(sum_count(self), extreme_count(self), levels_of(stepper, self%layout%friction))
      call self%poincare%start(stepper%t, reshape(observed, [2*self%points]))
      call self%diagnostics%start(reshape(observed, [2*self%points]))
      self%started = .true.
   end subroutine start

   !> Contact targets: each contact point, each obstacle, the beam.
   pure integer function targets(self)
      type(run_statistics), intent(in) :: self
      targets = self%contacts + self%obstacles + 1
   end function targets

   !> Sum quantities: 4 per observation point, per_target per contact target, per_force
   !! per contact point, then (a beam of two planes) 4 per observation point in z.
   pure integer function sum_count(self)
      type(run_statistics), intent(in) :: self
      sum_count = 4*self%points*self%planes + per_target*targets(self) + per_force*self%contacts
   end function sum_count

   !> Extreme quantities: u and v per observation point, |I| per target, per_force_extreme
   !! per contact point, then (a beam of two planes) u and v per observation point in z.
   pure integer function extreme_count(self)
      type(run_statistics), intent(in) :: self
      extreme_count = 2*self%points*self%planes + targets(self) + per_force_extreme*self%contacts
   end function extreme_count

   !> The sums of observation point p in `plane` (1: y, 2: z) follow this index: u, u^2, v, v^2.
   pure integer function point_sum(self, p, plane)
      type(run_statistics), intent(in) :: self
      integer, intent(in) :: p, plane
      point_sum = 4*(p - 1)
      if (plane == 2) point_sum = point_sum + 4*self%points + per_target*targets(self) + per_force*self%contacts
   end function point_sum

   !> The extremes of observation point p in `plane` follow this index: u, v.
   pure integer function point_extreme(self, p, plane)
      type(run_statistics), intent(in) :: self
      integer, intent(in) :: p, plane
      point_extreme = 2*(p - 1)
      if (plane == 2) point_extreme = point_extreme + 2*self%points + targets(self) + per_force_extreme*self%contacts
   end function point_extreme

   !> Index of force sum quantity q of contact point c.
   pure integer function force_sum(self, c, q)
      type(run_statistics), intent(in) :: self
      integer, intent(in) :: c, q
      force_sum = 4*self%points + per_target*targets(self) + per_force*(c - 1) + q
   end function force_sum

   !> Index of force extreme quantity q of contact point c.
   pure integer function force_extreme(self, c, q)
      type(run_statistics), intent(in) :: self
      integer, intent(in) :: c, q
      force_extreme = 2*self%points + targets(self) + per_force_extreme*(c - 1) + q
   end function force_extreme

   !> Work, impact, damping, numerical and contact damping sums of the stepper, the total
   !! energy (with the compliant stops' potential) and the balance total - work +
   !! dissipated, as /energy writes them (docs/theory.md section 8, "Energy"), and with
   !! `friction` the energy Coulomb friction took (a beam of two planes; in the balance).
   function levels_of(stepper, friction) result(levels)
      class(time_stepper), intent(in) :: stepper
      logical, intent(in) :: friction
      real(dp) :: levels(level_count + merge(1, 0, friction)), total, dissipated
      total = stepper%kinetic_energy() + stepper%elastic_energy()
      dissipated = stepper%energy%dissipated_impacts + stepper%energy%dissipated_damping + stepper%energy%dissipated_numerical
      if (friction) dissipated = dissipated + stepper%energy%dissipated_friction
      if (stepper%contacts%springs%count > 0 .or. stepper%holes%circles%compliant) then
         total = total + stepper%contact_potential()
         dissipated = dissipated + stepper%energy%dissipated_contact_damping
      end if
      levels(1:level_count) = [stepper%energy%work, stepper%energy%dissipated_impacts, &
                               stepper%energy%dissipated_damping, stepper%energy%dissipated_numerical, &
                               stepper%energy%dissipated_contact_damping, total, total - stepper%energy%work + dissipated]
      if (friction) levels(level_friction) = stepper%energy%dissipated_friction
   end function levels_of

   !> After every step: the recorder's events carry the impacts, the episodes that opened
   !! and closed, and the observed values (module documentation).
   subroutine observe_step(self, stepper, events, stat, errmsg)
      class(run_statistics), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(step_events), intent(inout) :: events
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical :: touched(targets(self))
      real(dp) :: values(2*self%points)   !! u, then v, at each observation point
      integer(int64) :: offset
      real(dp) :: impulse, force
      integer :: k, c, p, obstacle, beam
      stat = 0
      errmsg = ''
      self%poincare_found = 0
      if (.not. self%active) return
      if (.not. self%started .and. stepper%steps == self%first_step) call start(self, stepper, events%observed)
      offset = -1
      if (self%started .and. stepper%steps > self%first_step) offset = stepper%steps - self%first_step - 1
      beam = targets(self)
      ! episodes that closed in this step count where they opened; those that opened start
      do k = 1, events%closed_count
         c = events%closed_point(k)
         if (self%episode_offset(c) >= 0) call add_episode(self, c, events%closed_impulse(k))
         self%episode_offset(c) = -1
      end do
      do c = 1, self%contacts
         if (events%opened(c)) self%episode_offset(c) = offset
      end do
      call force_episodes()
      if (offset < 0) return
      associate (blocks => self%blocks)
         do p = 1, self%points
            call point_sums(p, 1, events%observed(p, :))
            if (self%planes == 2) call point_sums(p, 2, events%observed_z(p, :))
         end do
         touched = .false.
         do k = 1, stepper%report%active_count
            impulse = stepper%report%impulse(k)
            if (abs(impulse) <= 0) cycle
            c = stepper%report%active(k)
            obstacle = obstacle_of(self, c, impulse)
            call contact_sum(c, s_force, abs(impulse))
            if (events%impact(k)) call contact_sum(c, s_impacts, 1.0_dp)
            call touch(c, obstacle)
         end do
         do c = 1, self%contacts
            force = abs(stepper%report%contact_force(c))
            call blocks%extreme(force_extreme(self, c, x_force), force)
            if (force <= 0) cycle
            call blocks%add(force_sum(self, c, f_force), force)
            call blocks%add(force_sum(self, c, f_force_square), force**2)
            call blocks%add(force_sum(self, c, f_steps), 1.0_dp)
            ! in contact with a compliant stop too (contact_fraction counts every kind of stop)
            call touch(c, obstacle_of(self, c, stepper%report%contact_force(c)))
         end do
         do k = 1, size(touched)
            if (touched(k)) call blocks%add(target_sum(self, k, s_contact_steps), 1.0_dp)
         end do
      end associate
      values = reshape(events%observed, [2*self%points])
      call self%poincare%sample_step(stepper%steps, values, self%poincare_found, self%sample_times, self%sample_values)
      call self%diagnostics%observe_step(stepper, values, self%poincare_found, self%sample_values)
      call self%spectrum%add(events%observed(1, 1), stat, errmsg)
      if (stat == 0 .and. self%planes == 2) call self%spectrum_z%add(events%observed_z(1, 1), stat, errmsg)
      ! the levels (an energy evaluation) only where a block ends
      if (self%blocks%completes_block()) then
         call self%blocks%close_sample(levels_of(stepper, self%layout%friction))
      else
         call self%blocks%close_sample()
      end if
   contains
      !> u, u^2, v, v^2 and the extremes of u and v at observation point p in `plane`.
      subroutine point_sums(p, plane, observed)
         integer, intent(in) :: p, plane
         real(dp), intent(in) :: observed(2)
         integer :: j
         do j = 1, 2
            call self%blocks%add(point_sum(self, p, plane) + 2*j - 1, observed(j))
            call self%blocks%add(point_sum(self, p, plane) + 2*j, observed(j)**2)
            call self%blocks%extreme(point_extreme(self, p, plane) + j, observed(j))
         end do
      end subroutine point_sums

      !> Compliant episodes (docs/statistics.md): one opens where the force becomes nonzero
      !! and closes at the first step without force; it counts when it opened in the window.
      subroutine force_episodes()
         integer :: point
         do point = 1, self%contacts
            if (abs(stepper%report%contact_force(point)) > 0) then
               if (.not. self%force_touching(point)) self%force_offset(point) = offset
               self%force_touching(point) = .true.
            else
               if (self%force_touching(point) .and. self%force_offset(point) >= 0) &
                  call add_force_episode(self, point, offset - self%force_offset(point))
               self%force_touching(point) = .false.
               self%force_offset(point) = -1
            end if
         end do
      end subroutine force_episodes

      !> Contact point `point` is in contact in this step, pushed by obstacle `by` (0: none):
      !! so are that obstacle and the beam.
      subroutine touch(point, by)
         integer, intent(in) :: point, by
         touched(point) = .true.
         touched(beam) = .true.
         if (by > 0) touched(self%contacts + by) = .true.
      end subroutine touch

      !> Add `value` to sum quantity `q` of contact point c, of its obstacle and of the beam.
      subroutine contact_sum(point, q, value)
         integer, intent(in) :: point, q
         real(dp), intent(in) :: value
         call self%blocks%add(target_sum(self, point, q), value)
         if (obstacle > 0) call self%blocks%add(target_sum(self, self%contacts + obstacle, q), value)
         call self%blocks%add(target_sum(self, beam, q), value)
      end subroutine contact_sum
   end subroutine observe_step

   !> Index of sum quantity q of contact target t.
   pure integer function target_sum(self, t, q)
      type(run_statistics), intent(in) :: self
      integer, intent(in) :: t, q
      target_sum = 4*self%points + per_target*(t - 1) + q
   end function target_sum

   !> The obstacle that gives an impulse at contact point c (upwards: the one below), 0 if none.
   pure integer function obstacle_of(self, c, impulse)
      type(run_statistics), intent(in) :: self
      integer, intent(in) :: c
      real(dp), intent(in) :: impulse
      if (impulse > 0) then
         obstacle_of = self%lower_obstacle(c)
      else
         obstacle_of = self%upper_obstacle(c)
      end if
   end function obstacle_of

   !> A finished episode of total impulse `impulse` at contact point c, opened at
   !! episode_offset(c): counted in the block it opened in, at c, at the obstacle its
   !! impulse comes from, and for the beam.
   subroutine add_episode(self, c, impulse)
      type(run_statistics), intent(inout) :: self
      integer, intent(in) :: c
      real(dp), intent(in) :: impulse
      integer :: block, t, obstacle, k
      integer :: list(3), count
      block = self%blocks%block_of(self%episode_offset(c))
      obstacle = obstacle_of(self, c, impulse)
      list = [c, targets(self), 0]
      count = 2
      if (obstacle > 0) then
         count = 3
         list(3) = self%contacts + obstacle
      end if
      do k = 1, count
         t = list(k)
         call self%blocks%add(target_sum(self, t, s_episodes), 1.0_dp, block)
         call self%blocks%add(target_sum(self, t, s_impulse), abs(impulse), block)
         call self%blocks%add(target_sum(self, t, s_impulse_square), impulse**2, block)
         call self%blocks%extreme(2*self%points + t, abs(impulse), block)
      end do
   end subroutine add_episode

   !> A compliant episode of `steps` steps at contact point c, opened at force_offset(c):
   !! counted in the block it opened in.
   subroutine add_force_episode(self, c, steps)
      type(run_statistics), intent(inout) :: self
      integer, intent(in) :: c
      integer(int64), intent(in) :: steps
      integer :: block
      block = self%blocks%block_of(self%force_offset(c))
      call self%blocks%add(force_sum(self, c, f_episodes), 1.0_dp, block)
      call self%blocks%add(force_sum(self, c, f_episode_steps), real(steps, dp), block)
      call self%blocks%extreme(force_extreme(self, c, x_episode_steps), real(steps, dp), block)
   end subroutine add_force_episode

   !> The statistics of the window so far, ending at the stepper's present step: the
   !! episodes still open (`open`, `open_impulse` per contact point, from the episode
   !! tracker) count with their impulse so far. The observer itself is not changed.
   function result(self, stepper, open, open_impulse) result(outcome)
      class(run_statistics), intent(in) :: self
      class(time_stepper), intent(in) :: stepper
      logical, intent(in) :: open(:)
      real(dp), intent(in) :: open_impulse(:)
      type(statistics_result) :: outcome
      type(run_statistics) :: copy
      real(dp), allocatable :: batch(:, :), frequency(:), amplitude(:)
      real(dp) :: levels_end(level_count + merge(1, 0, self%layout%friction)), duration, block_duration, width_z
      integer :: c, k, e, b, batches, stat
      integer(int64) :: segments
      character(len=256) :: errmsg
      outcome%layout = self%layout
      allocate (outcome%values(self%layout%size), outcome%errors(self%layout%size), source=0.0_dp)
      allocate (outcome%poincare_time(0), outcome%poincare_values(2*self%points, 0))
      outcome%first_step = self%first_step
      outcome%window_start = self%first_step*self%dt
      outcome%values(self%layout%entries(self%layout%find(group_poincare, 'period'))%offset + 1) = -1
      if (.not. (self%active .and. self%started)) return
      if (self%blocks%samples < 1) return
      select type (self)
      type is (run_statistics)
         copy = self
      end select
      do c = 1, self%contacts
         if (open(c) .and. copy%episode_offset(c) >= 0) call add_episode(copy, c, open_impulse(c))
         if (copy%force_touching(c) .and. copy%force_offset(c) >= 0) &
            call add_force_episode(copy, c, copy%blocks%samples - copy%force_offset(c))
      end do
      associate (blocks => copy%blocks)
         outcome%present = .true.
         outcome%steps = blocks%samples
         outcome%block_steps = blocks%block_steps
         batches = blocks%complete
         outcome%batches = batches
         outcome%window_end = stepper%t
         duration = blocks%samples*self%dt
         block_duration = blocks%block_steps*self%dt
         levels_end = levels_of(stepper, self%layout%friction)
         allocate (batch(self%layout%size, batches), source=0.0_dp)
         ! observation points
         do k = 1, self%points
            do c = 1, self%planes
               call point_statistics(k, c, 1, 0)
               call point_statistics(k, c, 2, 4)
            end do
         end do
         ! contact points, obstacles, beam
         do k = 1, targets(self)
            call contact_statistics(k)
         end do
         do k = 1, self%contacts
            call force_statistics(k)
         end do
         ! energy
         e = self%layout%entries(self%layout%find(group_energy, 'power_input'))%offset
         call powers(e + 1, levels_end(level_work) - blocks%levels(level_work, 0), &
                     [(blocks%levels(level_work, b + 1) - blocks%levels(level_work, b), b = 0, batches - 1)])
         call powers(e + 2, levels_end(level_impacts) - blocks%levels(level_impacts, 0), &
                     [(blocks%levels(level_impacts, b + 1) - blocks%levels(level_impacts, b), b = 0, batches - 1)])
         call powers(e + 3, levels_end(level_damping) - blocks%levels(level_damping, 0), &
                     [(blocks%levels(level_damping, b + 1) - blocks%levels(level_damping, b), b = 0, batches - 1)])
         call powers(e + 4, levels_end(level_numerical) - blocks%levels(level_numerical, 0), &
                     [(blocks%levels(level_numerical, b + 1) - blocks%levels(level_numerical, b), b = 0, batches - 1)])
         call powers(e + 5, levels_end(level_contact_damping) - blocks%levels(level_contact_damping, 0), &
                     [(blocks%levels(level_contact_damping, b + 1) - blocks%levels(level_contact_damping, b), &
                       b = 0, batches - 1)])
         outcome%values(e + 6) = sum(outcome%values(e + 2:e + 5))
         batch(e + 6, :) = batch(e + 2, :) + batch(e + 3, :) + batch(e + 4, :) + batch(e + 5, :)
         call powers(e + 7, levels_end(level_total) - blocks%levels(level_total, 0), &
                     [(blocks%levels(level_total, b + 1) - blocks%levels(level_total, b), b = 0, batches - 1)])
         call powers(e + 8, levels_end(level_balance) - blocks%levels(level_balance, 0), &
                     [(blocks%levels(level_balance, b + 1) - blocks%levels(level_balance, b), b = 0, batches - 1)])
         if (self%layout%friction) then   ! the power friction takes, also in the power dissipated
            e = self%layout%entries(self%layout%find(group_energy, 'power_friction'))%offset
            call powers(e + 1, levels_end(level_friction) - blocks%levels(level_friction, 0), &
                        [(blocks%levels(level_friction, b + 1) - blocks%levels(level_friction, b), b = 0, batches - 1)])
            associate (dissipated => self%layout%entries(self%layout%find(group_energy, 'power_dissipated'))%offset + 1)
               outcome%values(dissipated) = outcome%values(dissipated) + outcome%values(e + 1)
               batch(dissipated, :) = batch(dissipated, :) + batch(e + 1, :)
            end associate
         end if
      end associate
      do k = 1, self%layout%size
         outcome%errors(k) = standard_error(batch(k, :))
      end do
      ! dominant frequencies of the tip displacement (in each plane: the same samples, bins)
      call copy%spectrum%spectrum(frequency, amplitude, segments, outcome%bin_width, stat, errmsg)
      if (stat == 0) call peaks(frequency, amplitude, 1)
      if (stat == 0 .and. self%planes == 2) call copy%spectrum_z%spectrum(frequency, amplitude, segments, &
                                                                         width_z, stat, errmsg)
      if (stat == 0 .and. self%planes == 2) call peaks(frequency, amplitude, 2)
      outcome%poincare_total = self%poincare%taken
      call self%diagnostics%fill(self%layout, outcome%values, outcome%errors)
      call self%poincare%kept(outcome%poincare_time, outcome%poincare_values)
   contains
      !> Mean, RMS, min, max of quantity `which` (1: u, 2: v) at point p in `plane` into
      !! the entries from `first` on ('displacement_*' when first = 0, 'velocity_*' when 4).
      subroutine point_statistics(p, plane, which, first)
         integer, intent(in) :: p, plane, which, first
         integer :: sum_q, extreme_q, o(4), j
         sum_q = point_sum(self, p, plane) + 2*(which - 1) + 1
         extreme_q = point_extreme(self, p, plane) + which
         do j = 1, 4
            o(j) = self%layout%entries(first + j)%offset + self%planes*(p - 1) + plane
         end do
         associate (blocks => copy%blocks)
            outcome%values(o(1)) = blocks%total(sum_q)/blocks%samples
            outcome%values(o(2)) = sqrt(blocks%total(sum_q + 1)/blocks%samples)
            outcome%values(o(3)) = blocks%lowest(extreme_q)
            outcome%values(o(4)) = blocks%highest(extreme_q)
            do b = 1, batches
               batch(o(1), b) = blocks%sums(sum_q, b - 1)/blocks%block_steps
               batch(o(2), b) = sqrt(blocks%sums(sum_q + 1, b - 1)/blocks%block_steps)
               batch(o(3), b) = blocks%lows(extreme_q, b - 1)
               batch(o(4), b) = blocks%highs(extreme_q, b - 1)
            end do
         end associate
      end subroutine point_statistics

      !> The seven contact statistics of target t (a contact point, an obstacle, the beam).
      subroutine contact_statistics(t)
         integer, intent(in) :: t
         integer :: group, index, o(7), j, first
         real(dp) :: episodes
         if (t <= self%contacts) then
            group = group_contacts
            index = t
         else if (t <= self%contacts + self%obstacles) then
            group = group_obstacles
            index = t - self%contacts
         else
            group = group_beam
            index = 1
         end if
         first = self%layout%find(group, 'impact_rate')
         do j = 1, 7
            o(j) = self%layout%entries(first + j - 1)%offset + index
         end do
         associate (blocks => copy%blocks)
            episodes = blocks%total(target_sum(self, t, s_episodes))
            call fill(outcome%values, o, blocks%total(target_sum(self, t, s_impacts)), episodes, &
                      blocks%total(target_sum(self, t, s_impulse)), blocks%total(target_sum(self, t, s_impulse_square)), &
                      blocks%highest(2*self%points + t), blocks%total(target_sum(self, t, s_contact_steps)), &
                      blocks%total(target_sum(self, t, s_force)), real(blocks%samples, dp), duration)
            do b = 1, batches
               call fill(batch(:, b), o, blocks%sums(target_sum(self, t, s_impacts), b - 1), &
                         blocks%sums(target_sum(self, t, s_episodes), b - 1), &
                         blocks%sums(target_sum(self, t, s_impulse), b - 1), &
                         blocks%sums(target_sum(self, t, s_impulse_square), b - 1), &
                         blocks%highs(2*self%points + t, b - 1), &
                         blocks%sums(target_sum(self, t, s_contact_steps), b - 1), &
                         blocks%sums(target_sum(self, t, s_force), b - 1), real(blocks%block_steps, dp), block_duration)
            end do
         end associate
      end subroutine contact_statistics

      !> The force statistics of the compliant stops at contact point c.
      subroutine force_statistics(c)
         integer, intent(in) :: c
         integer :: o(7), j, first
         first = self%layout%find(group_contacts, 'force_peak')
         do j = 1, 7
            o(j) = self%layout%entries(first + j - 1)%offset + c
         end do
         associate (blocks => copy%blocks)
            call fill_force(outcome%values, o, [(blocks%total(force_sum(self, c, j)), j = 1, per_force)], &
                            [(blocks%highest(force_extreme(self, c, j)), j = 1, per_force_extreme)], &
                            real(blocks%samples, dp), self%dt)
            do b = 1, batches
               call fill_force(batch(:, b), o, [(blocks%sums(force_sum(self, c, j), b - 1), j = 1, per_force)], &
                               [(blocks%highs(force_extreme(self, c, j), b - 1), j = 1, per_force_extreme)], &
                               real(blocks%block_steps, dp), self%dt)
            end do
         end associate
      end subroutine force_statistics

      !> Power = change/duration into entry `at`, and each block's.
      subroutine powers(at, change, block_changes)
         integer, intent(in) :: at
         real(dp), intent(in) :: change, block_changes(:)
         outcome%values(at) = change/duration
         batch(at, :) = block_changes/block_duration
      end subroutine powers

      !> The three largest local maxima of the spectrum (`interpolated_peaks`), also in rad/s,
      !! of `plane` (the layout's entries hold each peak's y, z side by side with two planes).
      subroutine peaks(frequency, amplitude, plane)
         real(dp), intent(in) :: frequency(:), amplitude(:)
         integer, intent(in) :: plane
         integer :: f_at, a_at, w_at, n
         n = self%planes
         f_at = self%layout%entries(self%layout%find(group_spectrum, 'peak_frequency'))%offset + plane
         a_at = self%layout%entries(self%layout%find(group_spectrum, 'peak_amplitude'))%offset + plane
         w_at = self%layout%entries(self%layout%find(group_spectrum, 'peak_frequency_rad_s'))%offset + plane
         call interpolated_peaks(frequency, amplitude, outcome%bin_width, outcome%values(f_at:f_at + n*(peak_count - 1):n), &
                                 outcome%values(a_at:a_at + n*(peak_count - 1):n))
         outcome%values(w_at:w_at + n*(peak_count - 1):n) = 2*pi*outcome%values(f_at:f_at + n*(peak_count - 1):n)
      end subroutine peaks
   end function result

   !> Everything a continued run needs (docs/output.md, "Checkpoint and restart").
   subroutine save_state(self, record)
      class(run_statistics), intent(in) :: self
      type(state_record), intent(inout) :: record
      if (.not. self%active) return
      call record%put_int64s('statistics.layout', [self%first_step, int(self%points, int64), &
                                                   int(self%contacts, int64), int(self%obstacles, int64), &
                                                   merge(1_int64, 0_int64, self%started)])
      call record%put_int64s('statistics.episode_offset', self%episode_offset)
      call record%put_int64s('statistics.force_offset', self%force_offset)
      call record%put_int64s('statistics.force_touching', merge(1_int64, 0_int64, self%force_touching))
      if (self%planes > 1) call record%put_int64s('statistics.planes', [int(self%planes, int64)])
      call self%blocks%save_state(record, 'statistics.blocks')
      call self%poincare%save_state(record, 'statistics.poincare')
      call self%diagnostics%save_state(record, 'statistics.diagnostics')
      call self%spectrum%save_state(record, 'statistics.spectrum')
      if (self%planes > 1) call self%spectrum_z%save_state(record, 'statistics.spectrum_z')
   end subroutine save_state

   !> Take the state back. A checkpoint of another window (another measure_from, other
   !! points, contact points, obstacles or planes) or of a run without statistics is not
   !! restored: `restored` is then false and the window starts afresh.
   subroutine restore_state(self, record, stat, errmsg)
      class(run_statistics), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: layout(5), touching(self%contacts)
      stat = 0
      errmsg = ''
      if (.not. self%active .or. record%find('statistics.layout') == 0) return
      call record%get_int64s('statistics.layout', layout, stat, errmsg)
      if (stat /= 0) return
      if (any(layout(1:4) /= [self%first_step, int(self%points, int64), int(self%contacts, int64), &
                              int(self%obstacles, int64)])) return
      if ((record%find('statistics.planes') > 0) .neqv. (self%planes > 1)) return
      call record%get_int64s('statistics.episode_offset', self%episode_offset, stat, errmsg)
      if (stat == 0 .and. record%find('statistics.force_offset') > 0) then
         call record%get_int64s('statistics.force_offset', self%force_offset, stat, errmsg)
         if (stat == 0) call record%get_int64s('statistics.force_touching', touching, stat, errmsg)
         if (stat == 0) self%force_touching = touching == 1
      end if
      if (stat /= 0 .or. layout(5) == 0) return
      self%started = .true.
      call self%blocks%restore_state(record, 'statistics.blocks', stat, errmsg)
      if (stat == 0) call self%poincare%restore_state(record, 'statistics.poincare', stat, errmsg)
      if (stat == 0) call self%diagnostics%restore_state(record, 'statistics.diagnostics', stat, errmsg)
      if (stat == 0) call self%spectrum%restore_state(record, stat, errmsg, 'statistics.spectrum')
      if (stat == 0 .and. self%planes > 1) call self%spectrum_z%restore_state(record, stat, errmsg, 'statistics.spectrum_z')
   end subroutine restore_state
end module vibrobeam_statistics
