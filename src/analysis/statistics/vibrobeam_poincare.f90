!> Poincare samples of a forced response (docs/statistics.md, "Poincare samples"): the
!! state at the observation points at a fixed phase of the forcing, once per period.
!!
!! The forcing's phase is psi(t) = Omega t + phi_0 (Omega in rad/s). Sample m is taken at
!! t_m = (2 pi m - phi_0)/Omega, the instants where psi is a whole multiple of 2 pi, for
!! every t_m in the window (t_start, t_end]. The state at t_m is interpolated linearly
!! between the two time steps around it, t_{n-1} < t_m <= t_n:
!! y(t_m) = y_{n-1} + (t_m - t_{n-1})/dt (y_n - y_{n-1}), t_n = n dt.
!!
!! Every sample is handed back to the caller (`sample_step` returns how many fell in the
!! step), and the last `kept_samples` are also kept in a ring buffer (the sweep file
!! keeps those), so memory does not grow with the window.
module vibrobeam_poincare
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_state_record, only: state_record
   implicit none
   private
   public :: poincare_sampler, kept_samples

   !> Samples kept for the sweep file (the latest ones of the window).
   integer, parameter :: kept_samples = 256

   type :: poincare_sampler
      real(dp) :: omega = 0                 !! forcing frequency (rad/s); 0: no samples
      real(dp) :: phase = 0                 !! phi_0 (rad)
      real(dp) :: dt = 0
      integer(int64) :: next = 0            !! m of the next sample
      integer(int64) :: taken = 0           !! samples taken in the window
      real(dp), allocatable :: previous(:)  !! (values) y_{n-1}
      !> ring buffer of the latest samples: time and values (values, kept_samples)
      real(dp), allocatable :: ring_time(:), ring_values(:, :)
   contains
      procedure :: init
      procedure :: start
      procedure :: sample_step
      procedure :: kept
      procedure :: save_state
      procedure :: restore_state
   end type poincare_sampler

contains

   !> Samples of `values` quantities at phase 0 of the forcing Omega t + phi_0 (omega = 0:
   !! no samples); `dt` is the time step (s).
   subroutine init(self, omega, phase, dt, values)
      class(poincare_sampler), intent(inout) :: self
      real(dp), intent(in) :: omega, phase, dt
      integer, intent(in) :: values
      self%omega = omega
      self%phase = phase
      self%dt = dt
      self%next = 0
      self%taken = 0
      if (allocated(self%previous)) deallocate (self%previous, self%ring_time, self%ring_values)
      allocate (self%previous(values), source=0.0_dp)
      allocate (self%ring_time(kept_samples), source=0.0_dp)
      allocate (self%ring_values(values, kept_samples), source=0.0_dp)
   end subroutine init

   !> The window starts at t_start with the state `values` there: the first sample is the
   !! first t_m > t_start.
   subroutine start(self, t_start, values)
      class(poincare_sampler), intent(inout) :: self
      real(dp), intent(in) :: t_start, values(:)
      self%previous = values
      self%taken = 0
      if (self%omega <= 0) return
      self%next = floor((self%omega*t_start + self%phase)/(2*pi), int64) + 1
      ! t_m > t_start even where the floor sits on a rounding boundary
      do while (sample_time(self, self%next) <= t_start)
         self%next = self%next + 1
      end do
   end subroutine start

   !> t_m = (2 pi m - phi_0)/Omega.
   pure real(dp) function sample_time(self, m)
      type(poincare_sampler), intent(in) :: self
      integer(int64), intent(in) :: m
      sample_time = (2*pi*m - self%phase)/self%omega
   end function sample_time

   !> Step n, from t_{n-1} = (n - 1) dt to t_n = n dt, ended with `values`: `found`
   !! samples fell in it, at times(1:found) with values(:, 1:found) (at most
   !! `size(times)`; room for a step of any length is dt Omega/(2 pi) + 1 samples).
   subroutine sample_step(self, n, values, found, times, samples)
      class(poincare_sampler), intent(inout) :: self
      integer(int64), intent(in) :: n
      real(dp), intent(in) :: values(:)
      integer, intent(out) :: found
      real(dp), intent(out) :: times(:), samples(:, :)
      real(dp) :: t_m, t_n, t_previous, weight
      integer :: slot
      found = 0
      if (self%omega > 0) then
         t_n = n*self%dt
         t_previous = (n - 1)*self%dt
         do
            t_m = sample_time(self, self%next)
            if (t_m > t_n .or. found == size(times)) exit
            weight = (t_m - t_previous)/self%dt
            found = found + 1
            times(found) = t_m
            samples(:, found) = self%previous + weight*(values - self%previous)
            self%next = self%next + 1
            slot = int(mod(self%taken, int(kept_samples, int64))) + 1
            self%ring_time(slot) = t_m
            self%ring_values(:, slot) = samples(:, found)
            self%taken = self%taken + 1
         end do
      end if
      self%previous = values
   end subroutine sample_step

   !> The kept samples in time order: times(k), values(:, k).
   subroutine kept(self, times, values)
      class(poincare_sampler), intent(in) :: self
      real(dp), allocatable, intent(out) :: times(:), values(:, :)
      integer :: count, first, k, slot
      count = int(min(self%taken, int(kept_samples, int64)))
      allocate (times(count), values(size(self%previous), count))
      first = int(mod(self%taken - count, int(kept_samples, int64)))
      do k = 1, count
         slot = mod(first + k - 1, kept_samples) + 1
         times(k) = self%ring_time(slot)
         values(:, k) = self%ring_values(:, slot)
      end do
   end subroutine kept

   subroutine save_state(self, record, prefix)
      class(poincare_sampler), intent(in) :: self
      type(state_record), intent(inout) :: record
      character(len=*), intent(in) :: prefix
      call record%put_int64s(prefix//'.counts', [self%next, self%taken])
      call record%put_reals(prefix//'.previous', self%previous)
      call record%put_reals(prefix//'.ring_time', self%ring_time)
      call record%put_reals(prefix//'.ring_values', reshape(self%ring_values, [size(self%ring_values)]))
   end subroutine save_state

   subroutine restore_state(self, record, prefix, stat, errmsg)
      class(poincare_sampler), intent(inout) :: self
      type(state_record), intent(in) :: record
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: counts(2)
      real(dp) :: flat(size(self%ring_values))
      call record%get_int64s(prefix//'.counts', counts, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.previous', self%previous, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.ring_time', self%ring_time, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.ring_values', flat, stat, errmsg)
      if (stat /= 0) return
      self%next = counts(1)
      self%taken = counts(2)
      self%ring_values = reshape(flat, shape(self%ring_values))
   end subroutine restore_state
end module vibrobeam_poincare
