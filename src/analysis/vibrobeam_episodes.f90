!> Contact episodes (docs/method.md, "Impacts and contact statistics"): the raw impacts
!! of one contact point grouped into the bounces of one contact.
!!
!! Rule: impacts at one contact point that follow each other by less than `gap` seconds
!! belong to one episode. An episode opens at an impact; every impulse the point receives
!! from then on (the impacts and the steps of persistent contact between and after them)
!! belongs to it; it closes at the first step without an impulse at that point once `gap`
!! has passed since its last impact. Per episode: the point's x, start (time of its first
!! impact), end (time of its last impulse), total impulse (N s), largest approach speed
!! (the largest |velocity before| of its impacts, m/s) and its number of impacts. An
!! episode still open when the run ends is written as it stands with `open_at_end` = 1; a
!! continued run carries it on (its checkpoint holds the open episodes) and writes it
!! again when it closes. Attributes of /episodes: `gap` (s) and `closed` (episodes closed
!! during the run, the rows with open_at_end = 0).
!!
!! At a contact point with compliant stops (docs/theory.md section 8) an episode is a
!! contiguous interval of nonzero stop force: it opens at the first step whose end-of-step
!! force is nonzero (start = that time, approach_speed = |u_t| of the point then, impacts =
!! 1) and closes at the first step without force (no `gap` merging: the force itself shows
!! when the contact lasts); its impulse is sum dt f. Its duration end - start is the
!! contact duration (to one step). The rigid rule above groups the separate impulses of a
!! rigid stop's micro-impacts into what a compliant stop shows as one interval of force.
module vibrobeam_episodes
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_series
   use vibrobeam_state_record, only: state_record
   use vibrobeam_step_observer, only: step_observer, step_events
   use vibrobeam_contact_set, only: contact_value
   implicit none
   private
   public :: episode_tracker, episode_columns

   !> Columns of /episodes: x, start, end, impulse, approach_speed, impacts, open_at_end.
   integer, parameter :: episode_columns = 7

   type, extends(step_observer) :: episode_tracker
      real(dp) :: gap = 0                          !! impacts closer than this: one episode (s)
      real(dp), allocatable :: x(:)                !! (contact points) position (m)
      logical, allocatable :: open(:)              !! an episode is open at the point
      logical, allocatable :: touched(:)           !! work space of `observe_step`: an impulse this step
      real(dp), allocatable :: start(:), last_impulse(:), last_impact(:), impulse(:), approach(:)
      integer(int64), allocatable :: impacts(:)
      integer(int64) :: written = 0                !! episodes closed (rows of /episodes)
      logical :: write_rows = .true.               !! append rows to /episodes (false: count only)
      ! what the last step did: episodes closed (point, total impulse) and opened
      integer :: closed_count = 0
      integer, allocatable :: closed_point(:)
      real(dp), allocatable :: closed_impulse(:)
      logical, allocatable :: opened(:)
      type(h5_series) :: series(episode_columns)
   contains
      procedure :: init
      procedure :: observe_step
      procedure :: create_datasets
      procedure :: write_buffers
      procedure :: finish
      procedure :: save_state
      procedure :: restore_state
      procedure :: rows
   end type episode_tracker

   character(len=*), parameter :: names(episode_columns) = [character(len=32) :: 'x', 'start', 'end', &
      'impulse', 'approach_speed', 'impacts', 'open_at_end']
   character(len=*), parameter :: units(episode_columns) = [character(len=8) :: 'm', 's', 's', 'N s', &
      'm/s', '1', '1']

contains

   !> Start with no episode open at the points `x` (m); `gap` (s) as in the rule. With
   !! `write_rows` false nothing goes to a file (a sweep's statistics need only the
   !! grouping).
   subroutine init(self, x, gap, write_rows)
      class(episode_tracker), intent(inout) :: self
      real(dp), intent(in) :: x(:), gap
      logical, intent(in), optional :: write_rows
      integer :: n
      n = size(x)
      self%gap = gap
      self%x = x
      if (present(write_rows)) self%write_rows = write_rows
      allocate (self%closed_point(n), self%closed_impulse(n), self%opened(n))
      self%closed_count = 0
      self%opened = .false.
      allocate (self%open(n), self%touched(n), source=.false.)
      allocate (self%start(n), self%last_impulse(n), self%last_impact(n), self%impulse(n), self%approach(n), &
                source=0.0_dp)
      allocate (self%impacts(n), source=0_int64)
      self%written = 0
   end subroutine init

   subroutine create_datasets(self, writer, stat, errmsg)
      class(episode_tracker), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      do k = 1, episode_columns
         call self%series(k)%create(writer, '/episodes/'//trim(names(k)), 1, trim(units(k)), stat, errmsg, &
                                    integers=k >= 6)
         if (stat /= 0) return
      end do
      call writer%attr_real('/episodes', 'gap', self%gap, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/episodes', 'closed', 0_int64, stat, errmsg)
   end subroutine create_datasets

   !> Open, extend and close episodes after a step (module documentation).
   subroutine observe_step(self, stepper, events, stat, errmsg)
      class(episode_tracker), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(step_events), intent(inout) :: events
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: t
      integer :: k, c
      stat = 0
      errmsg = ''
      t = stepper%report%impulse_time
      associate (touched => self%touched)
      touched = .false.
      self%closed_count = 0
      self%opened = .false.
      do k = 1, stepper%report%active_count
         c = stepper%report%active(k)
         if (abs(stepper%report%impulse(k)) <= 0) cycle
         touched(c) = .true.
         if (events%impact(k)) then
            if (self%open(c) .and. t - self%last_impact(c) >= self%gap) then
               call close_episode(c, .false.)
               if (stat /= 0) return
            end if
            if (.not. self%open(c)) then
               self%open(c) = .true.
               self%opened(c) = .true.
               self%start(c) = t
               self%impulse(c) = 0
               self%approach(c) = 0
               self%impacts(c) = 0
            end if
            self%impacts(c) = self%impacts(c) + 1
            self%last_impact(c) = t
            self%approach(c) = max(self%approach(c), abs(stepper%report%velocity_before(k)))
         end if
         if (self%open(c)) then
            self%impulse(c) = self%impulse(c) + stepper%report%impulse(k)
            self%last_impulse(c) = t
         end if
      end do
      ! compliant stops: episodes are contiguous intervals of nonzero force
      do k = 1, stepper%contacts%springs%count
         c = stepper%contacts%springs%point(k)
         if (touched(c)) cycle   ! a rigid impulse this step, or a point seen already
         if (abs(stepper%report%contact_force(c)) > 0) then
            touched(c) = .true.
            if (.not. self%open(c)) then
               self%open(c) = .true.
               ! the run statistics count the episode from here, like a rigid one
               self%opened(c) = .true.
               self%start(c) = t
               self%impulse(c) = 0
               self%approach(c) = abs(contact_value(stepper%contacts, c, stepper%v))
               self%impacts(c) = 1
            end if
            self%impulse(c) = self%impulse(c) + stepper%dt*stepper%report%contact_force(c)
            self%last_impulse(c) = t
            self%last_impact(c) = t
         else if (self%open(c)) then
            touched(c) = .true.
            call close_episode(c, .false.)
            if (stat /= 0) return
         end if
      end do
      do c = 1, size(self%open)
         if (self%open(c) .and. .not. touched(c) .and. t - self%last_impact(c) >= self%gap) then
            call close_episode(c, .false.)
            if (stat /= 0) return
         end if
      end do
      end associate
      ! what the episodes decided, for the observers after them (the statistics)
      events%closed_count = self%closed_count
      events%closed_point = self%closed_point
      events%closed_impulse = self%closed_impulse
      events%opened = self%opened
   contains
      subroutine close_episode(point, still_open)
         integer, intent(in) :: point
         logical, intent(in) :: still_open
         call append_row(self, point, still_open, stat, errmsg)
         self%open(point) = .false.
         self%closed_count = self%closed_count + 1
         self%closed_point(self%closed_count) = point
         self%closed_impulse(self%closed_count) = self%impulse(point)
      end subroutine close_episode
   end subroutine observe_step

   !> One row of /episodes for the episode at `point`.
   subroutine append_row(self, point, still_open, stat, errmsg)
      type(episode_tracker), intent(inout) :: self
      integer, intent(in) :: point
      logical, intent(in) :: still_open
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: row(episode_columns)
      integer :: k
      stat = 0
      errmsg = ''
      if (.not. still_open) self%written = self%written + 1
      if (.not. self%write_rows) return
      row = [self%x(point), self%start(point), self%last_impulse(point), self%impulse(point), &
             self%approach(point), real(self%impacts(point), dp), merge(1.0_dp, 0.0_dp, still_open)]
      do k = 1, episode_columns
         call self%series(k)%append(row(k:k), stat, errmsg)
         if (stat /= 0) return
      end do
   end subroutine append_row

   subroutine write_buffers(self, stat, errmsg)
      class(episode_tracker), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      stat = 0
      errmsg = ''
      if (.not. self%write_rows) return
      do k = 1, episode_columns
         call self%series(k)%write(stat, errmsg)
         if (stat /= 0) return
      end do
   end subroutine write_buffers

   !> Write the episodes still open (marked open_at_end), ordered by point, and every
   !! buffered row.
   subroutine finish(self, writer, stat, errmsg)
      class(episode_tracker), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: c, k
      stat = 0
      errmsg = ''
      do c = 1, size(self%open)
         if (.not. self%open(c)) cycle
         call append_row(self, c, .true., stat, errmsg)
         if (stat /= 0) return
      end do
      call self%write_buffers(stat, errmsg)
      do k = 1, episode_columns
         call self%series(k)%close()
      end do
      if (stat == 0) call writer%rewrite_attr('/episodes', 'closed', self%written, stat, errmsg)
   end subroutine finish

   !> Rows of /episodes so far (closed episodes, and at the end the open ones).
   function rows(self) result(count)
      class(episode_tracker), intent(in) :: self
      integer(int64) :: count
      count = self%series(1)%rows()
   end function rows

   subroutine save_state(self, record)
      class(episode_tracker), intent(in) :: self
      type(state_record), intent(inout) :: record
      call record%put_logicals('episodes.open', self%open)
      call record%put_reals('episodes.start', self%start)
      call record%put_reals('episodes.last_impulse', self%last_impulse)
      call record%put_reals('episodes.last_impact', self%last_impact)
      call record%put_reals('episodes.impulse', self%impulse)
      call record%put_reals('episodes.approach', self%approach)
      call record%put_int64s('episodes.impacts', self%impacts)
   end subroutine save_state

   subroutine restore_state(self, record, stat, errmsg)
      class(episode_tracker), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call record%get_logicals('episodes.open', self%open, stat, errmsg)
      if (stat == 0) call record%get_reals('episodes.start', self%start, stat, errmsg)
      if (stat == 0) call record%get_reals('episodes.last_impulse', self%last_impulse, stat, errmsg)
      if (stat == 0) call record%get_reals('episodes.last_impact', self%last_impact, stat, errmsg)
      if (stat == 0) call record%get_reals('episodes.impulse', self%impulse, stat, errmsg)
      if (stat == 0) call record%get_reals('episodes.approach', self%approach, stat, errmsg)
      if (stat == 0) call record%get_int64s('episodes.impacts', self%impacts, stat, errmsg)
   end subroutine restore_state
end module vibrobeam_episodes
