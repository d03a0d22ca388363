!> Impacts, forces, sliding and wear at the points of the obstacles of a beam of two planes
!! (circles and levels; docs/statistics.md, "Wear at the supports"), over the statistics
!! window (&output measure_from to the end), each with a standard error from batch means.
!!
!! Per point, from each step n in the window that the wall held (normal impulse P_n > 0,
!! rigid walls; the force f dt of a compliant one), the step's tangential velocity
!! v_t = t.V^{n+theta} at the point (t the tangent of the step's normal) and its length dt:
!! - normal work rate (wear work rate) W' = (1/T) sum_n P_n |v_t| (W): the impulse form of
!!   (1/T) int F_n |v_t| dt, F_n = P_n/dt over the step;
!! - mean normal force (1/T) sum_n P_n and RMS normal force sqrt((1/T) sum_n P_n^2/dt) (N);
!! - contact fraction (held steps) dt/T, sliding fraction (held steps whose point
!!   slides: friction at its bound, |r_T| >= mu p (1 - 1e-9) at a rigid wall and
!!   |phi| >= mu f (1 - 1e-9) at a compliant one, or no friction) dt/T;
!! - impact rate: impacts (an impulse after a free step, towards the wall) per second;
!! - Archard's wear volume rate K W' (m^3/s) where the obstacle's wear_coefficient K is
!!   given.
!! Standard errors: batch means over the blocks of the run's statistics
!! (`vibrobeam_batch_blocks`: 8 to 15 complete blocks of 2^m steps, the same blocks as
!! every other statistic of the window), each quantity computed per complete block, the
!! standard error of the mean of the block values (independent blocks: a window long
!! against the motion's correlation time). The blocks depend only on the steps observed,
!! not on where the window will end, so a run continued from its checkpoint
!! (`save_state`, `restore_state`) reaches the uninterrupted run's numbers bit for bit.
module vibrobeam_support_wear
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_circle_set, only: circle_set
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_array
   use vibrobeam_batch_blocks, only: block_accumulator, standard_error
   use vibrobeam_state_record, only: state_record
   use vibrobeam_statistics_layout, only: wear_quantities, wear_names, wear_units, group_wear
   use vibrobeam_statistics, only: statistics_result
   implicit none
   private
   public :: support_wear

   !> the sums kept per point, in this order: P |v_t|, P, P^2/dt, held steps, sliding
   !! steps, impacts (sum s of point k is the blocks' quantity sums_per_point (k - 1) + s)
   integer, parameter :: s_work = 1, s_impulse = 2, s_square = 3, s_held = 4, s_sliding = 5, s_impacts = 6, &
                         sums_per_point = 6

   type :: support_wear
      logical :: active = .false.                  !! the scene has such points
      integer :: points = 0
      integer(int64) :: window_start = 0          !! n0: the window holds the steps n > n0
      real(dp) :: dt = 0
      real(dp), allocatable :: coefficient(:)      !! (points) Archard's K (m^3/(N m)); < 0: not given
      type(block_accumulator) :: blocks            !! the sums of every point over the window's blocks
      !> each point received an impulse in the last step (or rested on its wall at t = 0):
      !! the next impulse there is not an impact
      logical, allocatable :: in_contact(:)
      type(h5_array) :: arrays(2, wear_quantities)   !! /wear/NAME and /wear/NAME_error
      logical :: volume = .false.                  !! some coefficient given: wear_volume_rate written
   contains
      procedure :: create_datasets
      procedure :: write
      procedure :: init
      procedure :: begin_window
      procedure :: observe_step
      procedure :: observe
      procedure :: count_impact
      procedure :: close_step
      procedure :: result
      procedure :: into_statistics
      procedure :: save_state
      procedure :: restore_state
   end type support_wear

contains

   !> For the points of the stepper's obstacles (`stepper%holes%circles`, at its start,
   !! with the initial velocity `v0`), a window after the state of step `first_step`;
   !! each point's `coefficient`, Archard's K of its obstacle (< 0: not given). A point on
   !! its wall (within `tolerance`) and not moving into it is in contact from t = 0, so its
   !! first impulse is not an impact.
   subroutine init(self, stepper, v0, tolerance, first_step, coefficient)
      class(support_wear), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: v0(:), tolerance
      integer(int64), intent(in) :: first_step
      real(dp), intent(in) :: coefficient(:)
      integer :: c
      associate (circles => stepper%holes%circles)
         self%points = circles%count
         self%active = circles%count > 0
         allocate (self%in_contact(circles%count))
         self%in_contact = .false.
         do c = 1, circles%count
            ! (the normal only on the wall: a circle's is undefined at its centre)
            if (circles%gap_at(c, circles%position(c, stepper%u)) > tolerance) cycle
            self%in_contact(c) = dot_product(circles%normal_at(c, circles%position(c, stepper%u)), &
                                             circles%position(c, v0)) >= 0
         end do
      end associate
      self%dt = stepper%dt
      self%coefficient = coefficient
      self%volume = any(coefficient >= 0)
      call self%begin_window(first_step)
   end subroutine init

   !> The window from the state of step `first_step` (n0): the steps n0 + 1, n0 + 2, ...,
   !! as the statistics' window (`vibrobeam_statistics`), its tallies empty (a sweep
   !! measures window after window); the points' contact state carries on.
   subroutine begin_window(self, first_step)
      class(support_wear), intent(inout) :: self
      integer(int64), intent(in) :: first_step
      real(dp) :: no_levels(0)
      self%window_start = first_step
      call self%blocks%init(sums_per_point*self%points, 0, no_levels)
   end subroutine begin_window

   !> The last step of `stepper` at its points: each held point's impulse, tangential
   !! velocity t.V^{n+theta} and sliding (the friction at its bound, or no friction), each
   !! compliant wall's force over the step along its direction; `new(1:count)`
   !! the entries of the step report (k of report%circle_*) that are impacts: an impulse at
   !! a point that received none in the previous step, moving towards its wall.
   subroutine observe_step(self, stepper, new, count)
      class(support_wear), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      integer, intent(out) :: new(:), count
      logical :: held(self%points)
      real(dp) :: tangent(2), slip, impulse, mu
      integer :: k, point
      count = 0
      held = .false.
      associate (circles => stepper%holes%circles, r => stepper%report, holes => stepper%holes)
         do k = 1, r%circle_count
            if (r%circle_impulse(k) <= 0) cycle
            point = r%circle_active(k)
            held(point) = .true.
            tangent = [-r%circle_normal(2, k), r%circle_normal(1, k)]
            slip = stepper%theta*dot_product(tangent, circles%position(point, stepper%v)) + &
                   (1 - stepper%theta)*r%circle_tangential_before(k)
            mu = circles%friction(point)
            call self%observe(stepper%steps, point, r%circle_impulse(k), slip, &
                              mu <= 0 .or. abs(r%circle_friction(k)) >= mu*r%circle_impulse(k)*(1 - 1e-9_dp))
            if (self%in_contact(point) .or. r%circle_before(k) > 0) cycle
            count = count + 1
            new(count) = k
            call self%count_impact(stepper%steps, point)
         end do
         ! compliant walls: the force over the step along its direction; a point slides when
         ! its wall is frictionless or its friction force is at the bound mu f
         if (circles%compliant) then
            do point = 1, circles%count
               impulse = holes%f(point)*stepper%dt
               if (impulse <= 0) cycle
               held(point) = .true.
               tangent = [holes%force(2, point), -holes%force(1, point)]/norm2(holes%force(:, point))
               slip = dot_product(tangent, stepper%theta*circles%position(point, stepper%v) + &
                                  (1 - stepper%theta)*holes%start_velocity(:, point))
               mu = circles%friction(point)
               call self%observe(stepper%steps, point, impulse, slip, &
                                 mu <= 0 .or. abs(holes%friction_force(point)) >= mu*holes%f(point)*(1 - 1e-9_dp))
            end do
         end if
      end associate
      self%in_contact = held
      call self%close_step(stepper%steps)
   end subroutine observe_step

   !> Step n is in the window.
   pure logical function in_window(self, n)
      class(support_wear), intent(in) :: self
      integer(int64), intent(in) :: n
      in_window = n > self%window_start
   end function in_window

   !> Step n is observed: in the window, it closes its sample of the blocks.
   subroutine close_step(self, n)
      class(support_wear), intent(inout) :: self
      integer(int64), intent(in) :: n
      if (in_window(self, n)) call self%blocks%close_sample()
   end subroutine close_step

   !> Step n's contact at point k: normal impulse `impulse` (N s, > 0 held), tangential
   !! velocity `slip` (m/s, at V^{n+theta}), `sliding` whether it slid.
   subroutine observe(self, n, k, impulse, slip, sliding)
      class(support_wear), intent(inout) :: self
      integer(int64), intent(in) :: n
      integer, intent(in) :: k
      real(dp), intent(in) :: impulse, slip
      logical, intent(in) :: sliding
      integer :: q
      if (.not. in_window(self, n) .or. impulse <= 0) return
      q = sums_per_point*(k - 1)
      call self%blocks%add(q + s_work, impulse*abs(slip))
      call self%blocks%add(q + s_impulse, impulse)
      call self%blocks%add(q + s_square, impulse**2/self%dt)
      call self%blocks%add(q + s_held, 1.0_dp)
      if (sliding) call self%blocks%add(q + s_sliding, 1.0_dp)
   end subroutine observe

   !> An impact at point k in step n.
   subroutine count_impact(self, n, k)
      class(support_wear), intent(inout) :: self
      integer(int64), intent(in) :: n
      integer, intent(in) :: k
      if (in_window(self, n)) call self%blocks%add(sums_per_point*(k - 1) + s_impacts, 1.0_dp)
   end subroutine count_impact

   !> The quantities of the module documentation (points, wear_quantities) over the whole
   !! window and their standard errors (batch means over the complete blocks); the wear
   !! volume rate is 0 where no coefficient is given.
   subroutine result(self, value, error)
      class(support_wear), intent(in) :: self
      real(dp), intent(out) :: value(:, :), error(:, :)   !! (points, wear_quantities)
      real(dp) :: per_block(self%blocks%complete), whole(sums_per_point), window, block_length
      integer :: k, q, b
      value = 0
      error = 0
      if (self%blocks%samples < 1 .or. self%points == 0) return   ! no window
      window = real(self%blocks%samples, dp)*self%dt
      block_length = real(self%blocks%block_steps, dp)*self%dt
      do k = 1, self%points
         whole = [(self%blocks%total(sums_per_point*(k - 1) + q), q = 1, sums_per_point)]
         do q = 1, wear_quantities
            value(k, q) = quantity(q, k, whole, window)
            do b = 1, self%blocks%complete
               per_block(b) = quantity(q, k, self%blocks%sums(sums_per_point*(k - 1) + 1:sums_per_point*k, b - 1), &
                                       block_length)
            end do
            error(k, q) = standard_error(per_block)
         end do
      end do
   contains
      !> Quantity q of point k from its sums over a time `time` (s).
      pure real(dp) function quantity(q, k, sums, time)
         integer, intent(in) :: q, k
         real(dp), intent(in) :: sums(:), time
         select case (q)
         case (1)
            quantity = sums(s_work)/time
         case (2)
            quantity = sums(s_impulse)/time
         case (3)
            quantity = sqrt(sums(s_square)/time)
         case (4)
            quantity = sums(s_held)*self%dt/time
         case (5)
            quantity = sums(s_sliding)*self%dt/time
         case (6)
            quantity = sums(s_impacts)/time
         case default
            quantity = max(0.0_dp, self%coefficient(k))*sums(s_work)/time
         end select
      end function quantity
   end subroutine result

   !> The quantities and their standard errors into the 'wear' group of `outcome` (the
   !! statistics of the same window, whose layout has that group: the sweep file and
   !! /statistics hold them there).
   subroutine into_statistics(self, outcome)
      class(support_wear), intent(in) :: self
      type(statistics_result), intent(inout) :: outcome
      real(dp) :: value(self%points, wear_quantities), error(self%points, wear_quantities)
      integer :: q, e
      call self%result(value, error)
      do q = 1, wear_quantities
         e = outcome%layout%find(group_wear, wear_names(q))
         if (e == 0) cycle   ! the wear volume rate without a coefficient
         associate (first => outcome%layout%entries(e)%offset + 1, last => outcome%layout%entries(e)%offset + self%points)
            outcome%values(first:last) = value(:, q)
            outcome%errors(first:last) = error(:, q)
         end associate
      end do
   end subroutine into_statistics

   !> /wear/x (m) and /wear/obstacle (the obstacles' indices) of the points, and room for
   !! each quantity and its standard error, /wear/NAME and /wear/NAME_error (created before
   !! the file enters SWMR mode; written by `write` at the end).
   subroutine create_datasets(self, writer, circles, stat, errmsg)
      class(support_wear), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      type(circle_set), intent(in) :: circles
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: q, e
      character(len=*), parameter :: suffix(2) = [character(len=6) :: '', '_error']
      stat = 0
      errmsg = ''
      if (.not. self%active) return
      call writer%write_real_1d('/wear/x', circles%x, 'm', stat, errmsg)
      if (stat == 0) call writer%write_real_1d('/wear/obstacle', real(circles%obstacle, dp), '1', stat, errmsg)
      do q = 1, wear_quantities
         if (q == wear_quantities .and. .not. self%volume) exit
         do e = 1, 2
            if (stat /= 0) return
            call self%arrays(e, q)%create(writer, '/wear/'//trim(wear_names(q))//trim(suffix(e)), self%points, &
                                          .false., stat, errmsg)
            if (stat == 0) call writer%attr_string('/wear/'//trim(wear_names(q))//trim(suffix(e)), 'unit', &
                                                   trim(wear_units(q)), stat, errmsg)
         end do
      end do
   end subroutine create_datasets

   !> The quantities and their standard errors into /wear (end of the run).
   subroutine write(self, stat, errmsg)
      class(support_wear), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: value(self%points, wear_quantities), error(self%points, wear_quantities)
      integer :: q
      stat = 0
      errmsg = ''
      if (.not. self%active) return
      call self%result(value, error)
      do q = 1, wear_quantities
         if (q == wear_quantities .and. .not. self%volume) exit
         call self%arrays(1, q)%write_reals(value(:, q), stat, errmsg)
         if (stat == 0) call self%arrays(2, q)%write_reals(error(:, q), stat, errmsg)
         call self%arrays(1, q)%close()
         call self%arrays(2, q)%close()
         if (stat /= 0) return
      end do
   end subroutine write

   !> Put what a continued run needs into `record` (docs/output.md, "Checkpoint and
   !! restart"): the window's start, each point's contact state and the blocks' sums.
   subroutine save_state(self, record)
      class(support_wear), intent(in) :: self
      type(state_record), intent(inout) :: record
      if (.not. self%active) return
      call record%put_int64s('wear.window_start', [self%window_start])
      call record%put_logicals('wear.in_contact', self%in_contact)
      call self%blocks%save_state(record, 'wear.blocks')
   end subroutine save_state

   !> Take back what `save_state` put into `record` (the observer is `init`ed for the
   !! same points).
   subroutine restore_state(self, record, stat, errmsg)
      class(support_wear), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: start(1)
      stat = 0
      errmsg = ''
      if (.not. self%active) return
      call record%get_int64s('wear.window_start', start, stat, errmsg)
      if (stat == 0) call record%get_logicals('wear.in_contact', self%in_contact, stat, errmsg)
      if (stat == 0) call self%blocks%restore_state(record, 'wear.blocks', stat, errmsg)
      if (stat == 0) self%window_start = start(1)
   end subroutine restore_state
end module vibrobeam_support_wear
