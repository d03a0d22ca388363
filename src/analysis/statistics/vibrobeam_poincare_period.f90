!> The period of the Poincare sequence of a run (docs/statistics.md, "Period, Lyapunov
!! exponent and the 0-1 test"): the smallest p in 1 .. max_period with
!! |x_{k+p,i} - x_{k,i}| <= tau_i for every component i (u, then v, at each observation
!! point) and every pair of samples k, k + p of the statistics window, or none.
!!
!! Streamed, with memory that does not grow with the window: the last max_period samples
!! in a ring, and for each p and component the largest difference seen so far,
!! d_{p,i} = max_k |x_{k+p,i} - x_{k,i}|. Every step of the window also updates each
!! component's largest magnitude s_i = max_n |y_i(t_n)| and largest change in one step
!! c_i = max_n |y_i(t_n) - y_i(t_{n-1})|, from which the tolerance is made at the end:
!!
!!   tau_i = 8 eps P s_i  + 2 eps N c_i  + (c_i when P = T/dt is not a whole number),
!!
!! P the steps per forcing period, N the window's last step (t_N = N dt). The first term is
!! the round-off of a period of P steps (eps of each step's state, times the steps: a state
!! that time marching repeats exactly repeats to it; measured 2e-14 relative for P = 1000,
!! docs/method.md). The second is the rounding of time: t_n = n dt and the loads' phase
!! Omega t_n carry a relative error of eps each, so the forcing a step sees is shifted by
!! up to 2 eps t_n, a shift that grows slowly along the run and that the response follows
!! (it is the same response, later or earlier by that much): a sample moves by the
!! response's change over that time, 2 eps n c_i at step n (measured 0.45 of it on a
!! linear beam after 2e6 steps, where without this term a periodic response read 'no
!! period' and the 0-1 test chaos: docs/statistics.md). The third is the
!! slip of the section: with P not whole, the sample falls at another place between two
!! steps every period, the forcing is sampled at other phases and impacts are rounded to
!! other steps, so even a periodic response moves its samples by up to what the response
!! moves in one step (measured 0.15 to 0.45 of it, docs/method.md).
!! A period p is tested only when the window holds at least 3 p samples (every sample of a
!! period is seen to come back twice).
module vibrobeam_poincare_period
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_state_record, only: state_record
   implicit none
   private
   public :: period_finder, max_period, whole_period_tolerance

   !> The longest period looked for (forcing periods).
   integer, parameter :: max_period = 64
   !> P = T/dt counts as whole within this relative distance (the rule of &analysis kind =
   !! 'periodic', a slip of 2 pi 1e-9 rad of the forcing per period).
   real(dp), parameter :: whole_period_tolerance = 1e-9_dp

   type :: period_finder
      integer :: values = 0                       !! components of a sample
      integer(int64) :: samples = 0               !! samples of the window so far
      logical :: stepped = .false.                !! `previous` holds the last step's values
      real(dp), allocatable :: ring(:, :)         !! (values, max_period) the latest samples
      real(dp), allocatable :: mismatch(:, :)     !! (values, max_period) d_{p,i}
      real(dp), allocatable :: largest(:)         !! (values) s_i
      real(dp), allocatable :: step_change(:)     !! (values) c_i
      real(dp), allocatable :: previous(:)        !! (values) the last step's values
   contains
      procedure :: init
      procedure :: start
      procedure :: observe_step
      procedure :: add_sample
      procedure :: tolerance
      procedure :: find
      procedure :: save_state
      procedure :: restore_state
   end type period_finder

contains

   !> Samples of `values` components.
   subroutine init(self, values)
      class(period_finder), intent(inout) :: self
      integer, intent(in) :: values
      self%values = values
      if (allocated(self%ring)) deallocate (self%ring, self%mismatch, self%largest, self%step_change, self%previous)
      allocate (self%ring(values, max_period), self%mismatch(values, max_period), self%largest(values), &
                self%step_change(values), self%previous(values))
      call self%start([real(dp) ::])
   end subroutine init

   !> A new window, starting at a state whose values are `values` (empty: not known).
   subroutine start(self, values)
      class(period_finder), intent(inout) :: self
      real(dp), intent(in) :: values(:)
      self%samples = 0
      self%ring = 0
      self%mismatch = 0
      self%largest = 0
      self%step_change = 0
      self%previous = 0
      self%stepped = size(values) == self%values
      if (self%stepped) then
         self%previous = values
         self%largest = abs(values)
      end if
   end subroutine start

   !> A step of the window ended with `values`.
   subroutine observe_step(self, values)
      class(period_finder), intent(inout) :: self
      real(dp), intent(in) :: values(:)
      integer :: i
      do i = 1, self%values
         if (self%stepped) self%step_change(i) = max(self%step_change(i), abs(values(i) - self%previous(i)))
         self%largest(i) = max(self%largest(i), abs(values(i)))
         self%previous(i) = values(i)
      end do
      self%stepped = .true.
   end subroutine observe_step

   !> The next sample of the sequence.
   subroutine add_sample(self, x)
      class(period_finder), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      integer :: p, slot
      do p = 1, int(min(int(max_period, int64), self%samples))
         slot = int(mod(self%samples - p, int(max_period, int64))) + 1
         self%mismatch(:, p) = max(self%mismatch(:, p), abs(x - self%ring(:, slot)))
      end do
      self%ring(:, int(mod(self%samples, int(max_period, int64))) + 1) = x
      self%samples = self%samples + 1
   end subroutine add_sample

   !> tau_i (module documentation) for `steps_per_period` = T/dt, the window ending at step
   !! `last_step` (N; none: 0, time's rounding left out).
   pure function tolerance(self, steps_per_period, last_step) result(tau)
      class(period_finder), intent(in) :: self
      real(dp), intent(in) :: steps_per_period
      integer(int64), intent(in), optional :: last_step
      real(dp) :: tau(self%values)
      tau = 8*epsilon(1.0_dp)*steps_per_period*self%largest
      if (present(last_step)) tau = tau + 2*epsilon(1.0_dp)*real(last_step, dp)*self%step_change
      if (abs(steps_per_period - anint(steps_per_period)) > whole_period_tolerance*steps_per_period) &
         tau = tau + self%step_change
   end function tolerance

   !> The period (-1: not determined, fewer than 3 samples; 0: none up to the longest
   !! period the window can show, min(max_period, samples/3)) and its mismatch,
   !! max_i d_{p,i}/tau_i (<= 1 for the period found; with none, that of the p that comes
   !! nearest, or 0 when no p could be tested).
   subroutine find(self, steps_per_period, period, mismatch, last_step)
      class(period_finder), intent(in) :: self
      real(dp), intent(in) :: steps_per_period
      integer(int64), intent(in), optional :: last_step   !! N, the window's last step (`tolerance`)
      integer, intent(out) :: period
      real(dp), intent(out) :: mismatch
      real(dp) :: tau(self%values), ratio
      integer :: p, longest
      period = -1
      mismatch = 0
      longest = int(min(int(max_period, int64), self%samples/3))
      if (longest < 1) return
      tau = self%tolerance(steps_per_period, last_step)
      period = 0
      mismatch = huge(1.0_dp)
      do p = 1, longest
         ratio = relative(self%mismatch(:, p), tau)
         if (ratio <= 1) then
            period = p
            mismatch = ratio
            return
         end if
         mismatch = min(mismatch, ratio)
      end do
   contains
      !> max_i d_i/tau_i, where tau_i = 0 counts only a d_i > 0 (as huge).
      pure real(dp) function relative(d, tau)
         real(dp), intent(in) :: d(:), tau(:)
         integer :: i
         relative = 0
         do i = 1, size(d)
            if (tau(i) > 0) then
               relative = max(relative, d(i)/tau(i))
            else if (d(i) > 0) then
               relative = huge(1.0_dp)
            end if
         end do
      end function relative
   end subroutine find

   subroutine save_state(self, record, prefix)
      class(period_finder), intent(in) :: self
      type(state_record), intent(inout) :: record
      character(len=*), intent(in) :: prefix
      call record%put_int64s(prefix//'.counts', [self%samples, merge(1_int64, 0_int64, self%stepped)])
      call record%put_reals(prefix//'.ring', reshape(self%ring, [size(self%ring)]))
      call record%put_reals(prefix//'.mismatch', reshape(self%mismatch, [size(self%mismatch)]))
      call record%put_reals(prefix//'.steps', [self%largest, self%step_change, self%previous])
   end subroutine save_state

   subroutine restore_state(self, record, prefix, stat, errmsg)
      class(period_finder), intent(inout) :: self
      type(state_record), intent(in) :: record
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: counts(2)
      real(dp) :: ring(size(self%ring)), mismatch(size(self%mismatch)), steps(3*self%values)
      call record%get_int64s(prefix//'.counts', counts, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.ring', ring, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.mismatch', mismatch, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.steps', steps, stat, errmsg)
      if (stat /= 0) return
      self%samples = counts(1)
      self%stepped = counts(2) == 1
      self%ring = reshape(ring, shape(self%ring))
      self%mismatch = reshape(mismatch, shape(self%mismatch))
      self%largest = steps(1:self%values)
      self%step_change = steps(self%values + 1:2*self%values)
      self%previous = steps(2*self%values + 1:)
   end subroutine restore_state
end module vibrobeam_poincare_period
