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
!! Standard errors: the window cut into `batches` equal batches of steps, each quantity
!! computed per batch, the standard deviation of the batch values over sqrt(batches)
!! (independent batches: a window long against the motion's correlation time).
module vibrobeam_support_wear
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_circle_set, only: circle_set
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_array
   use vibrobeam_statistics_layout, only: wear_quantities, wear_names, wear_units, group_wear
   use vibrobeam_statistics, only: statistics_result
   implicit none
   private
   public :: support_wear

   integer, parameter :: batch_count = 16

   type :: support_wear
      logical :: active = .false.                  !! the scene has such points
      integer :: points = 0
      integer(int64) :: first_step = 1, last_step = 0   !! the window's first and last steps
      integer :: batches = batch_count
      real(dp) :: dt = 0
      real(dp), allocatable :: coefficient(:)      !! (points) Archard's K (m^3/(N m)); < 0: not given
      !> (points, batches) sums over each batch: P |v_t|, P, P^2/dt, held steps, sliding
      !! steps, impacts
      real(dp), allocatable :: work(:, :), impulse(:, :), square(:, :), held(:, :), sliding(:, :), impacts(:, :)
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
      procedure :: result
      procedure :: into_statistics
   end type support_wear

contains

   !> For the points of the stepper's obstacles (`stepper%holes%circles`, at its start,
   !! with the initial velocity `v0`), a window from step first_step to last_step; each
   !! point's `coefficient`, Archard's K of its obstacle (< 0: not given). A point on its
   !! wall (within `tolerance`) and not moving into it is in contact from t = 0, so its
   !! first impulse is not an impact.
   subroutine init(self, stepper, v0, tolerance, first_step, last_step, coefficient)
      class(support_wear), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: v0(:), tolerance
      integer(int64), intent(in) :: first_step, last_step
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
      call self%begin_window(first_step, last_step)
   end subroutine init

   !> The window from the state of step `first_step` (n0) to that of `last_step` (N): the
   !! steps n0 + 1 .. N, as the statistics' window (`vibrobeam_statistics`), its tallies
   !! empty (a sweep measures window after window); the points' contact state carries on.
   subroutine begin_window(self, first_step, last_step)
      class(support_wear), intent(inout) :: self
      integer(int64), intent(in) :: first_step, last_step
      self%first_step = first_step + 1
      self%last_step = last_step
      self%batches = int(max(1_int64, min(int(batch_count, int64), last_step - self%first_step + 1)))
      if (allocated(self%work)) deallocate (self%work, self%impulse, self%square, self%held, self%sliding, self%impacts)
      allocate (self%work(self%points, self%batches), self%impulse(self%points, self%batches), &
                self%square(self%points, self%batches), self%held(self%points, self%batches), &
                self%sliding(self%points, self%batches), self%impacts(self%points, self%batches), source=0.0_dp)
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
   end subroutine observe_step

   !> Batch of step n (0: outside the window).
   pure integer function batch_of(self, n)
      class(support_wear), intent(in) :: self
      integer(int64), intent(in) :: n
      batch_of = 0
      if (n < self%first_step .or. n > self%last_step) return
      batch_of = 1 + int((n - self%first_step)*self%batches/(self%last_step - self%first_step + 1))
   end function batch_of

   !> Step n's contact at point k: normal impulse `impulse` (N s, > 0 held), tangential
   !! velocity `slip` (m/s, at V^{n+theta}), `sliding` whether it slid.
   subroutine observe(self, n, k, impulse, slip, sliding)
      class(support_wear), intent(inout) :: self
      integer(int64), intent(in) :: n
      integer, intent(in) :: k
      real(dp), intent(in) :: impulse, slip
      logical, intent(in) :: sliding
      integer :: b
      b = batch_of(self, n)
      if (b == 0 .or. impulse <= 0) return
      self%work(k, b) = self%work(k, b) + impulse*abs(slip)
      self%impulse(k, b) = self%impulse(k, b) + impulse
      self%square(k, b) = self%square(k, b) + impulse**2/self%dt
      self%held(k, b) = self%held(k, b) + 1
      if (sliding) self%sliding(k, b) = self%sliding(k, b) + 1
   end subroutine observe

   !> An impact at point k in step n.
   subroutine count_impact(self, n, k)
      class(support_wear), intent(inout) :: self
      integer(int64), intent(in) :: n
      integer, intent(in) :: k
      integer :: b
      b = batch_of(self, n)
      if (b > 0) self%impacts(k, b) = self%impacts(k, b) + 1
   end subroutine count_impact

   !> The quantities of the module documentation (points, wear_quantities) over the whole
   !! window and their standard errors; the wear volume rate is 0 where no coefficient is
   !! given.
   subroutine result(self, value, error)
      class(support_wear), intent(in) :: self
      real(dp), intent(out) :: value(:, :), error(:, :)   !! (points, wear_quantities)
      real(dp) :: per_batch(self%batches), length(self%batches), window
      integer :: k, q, b
      integer(int64) :: steps
      steps = self%last_step - self%first_step + 1
      value = 0
      error = 0
      if (steps < 1 .or. self%points == 0) return   ! no window
      do b = 1, self%batches   ! the steps of batch b
         length(b) = real(count_steps(b), dp)*self%dt
      end do
      window = real(steps, dp)*self%dt
      do k = 1, self%points
         do q = 1, wear_quantities
            do b = 1, self%batches
               per_batch(b) = quantity(q, k, [b], length(b))
            end do
            value(k, q) = quantity(q, k, [(b, b=1, self%batches)], window)
            error(k, q) = 0
            if (self%batches > 1) error(k, q) = sqrt(sum((per_batch - sum(per_batch)/self%batches)**2)/ &
                                                     (self%batches - 1)/self%batches)
         end do
      end do
   contains
      !> Quantity q of point k over the batches `in` of total length `time` (s).
      pure real(dp) function quantity(q, k, in, time)
         integer, intent(in) :: q, k, in(:)
         real(dp), intent(in) :: time
         select case (q)
         case (1)
            quantity = sum(self%work(k, in))/time
         case (2)
            quantity = sum(self%impulse(k, in))/time
         case (3)
            quantity = sqrt(sum(self%square(k, in))/time)
         case (4)
            quantity = sum(self%held(k, in))*self%dt/time
         case (5)
            quantity = sum(self%sliding(k, in))*self%dt/time
         case (6)
            quantity = sum(self%impacts(k, in))/time
         case default
            quantity = max(0.0_dp, self%coefficient(k))*sum(self%work(k, in))/time
         end select
      end function quantity
      !> Steps of batch b: n - first_step in [ceil((b - 1) N/B), ceil(b N/B) - 1].
      pure integer(int64) function count_steps(b)
         integer, intent(in) :: b
         count_steps = ceiling_ratio(b*steps, self%batches) - ceiling_ratio((b - 1)*steps, self%batches)
      end function count_steps
      pure integer(int64) function ceiling_ratio(a, d)
         integer(int64), intent(in) :: a
         integer, intent(in) :: d
         ceiling_ratio = (a + d - 1)/d
      end function ceiling_ratio
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
end module vibrobeam_support_wear
