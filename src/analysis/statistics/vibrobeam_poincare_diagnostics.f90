!> What the Poincare sequence of a run says about its dynamics (docs/statistics.md,
!! "Period, Lyapunov exponent and the 0-1 test"): its period (`vibrobeam_poincare_period`),
!! the 0-1 test for chaos (`vibrobeam_zero_one`) and, when &output lyapunov asks for it,
!! the largest Lyapunov exponent of the discrete map (`vibrobeam_lyapunov`). Fed by the
!! statistics after every step of the window, with the samples that fell in it; the
!! values fill the 'poincare' group of the statistics' layout.
!!
!! The sequence is x_k = (u at each observation point, then v at each) at the k-th
!! sample; the 0-1 test takes phi_k = the sum of the displacements of x_k (the tip's alone
!! without &output points). A sequence of period 1 (every sample the same to the period
!! finder's tolerance, velocities included) is constant to what the scheme resolves: its
!! K is 0, a regular sequence (the test would otherwise read the round-off, or the slip of
!! the section, as noise).
module vibrobeam_poincare_diagnostics
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_state_record, only: state_record
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_statistics_layout, only: statistics_layout, group_poincare
   use vibrobeam_poincare_period, only: period_finder
   use vibrobeam_zero_one, only: zero_one_test
   use vibrobeam_lyapunov, only: lyapunov_tangent
   implicit none
   private
   public :: poincare_diagnostics

   type :: poincare_diagnostics
      logical :: section = .false.             !! the run has a Poincare section (a harmonic load)
      integer :: points = 0                    !! observation points
      real(dp) :: omega = 0, dt = 0
      integer(int64) :: last_step = 0          !! the last step observed (t = last_step dt)
      type(period_finder) :: period
      type(zero_one_test) :: zero_one
      type(lyapunov_tangent) :: lyapunov
   contains
      procedure :: init
      procedure :: start
      procedure :: observe_step
      procedure :: fill
      procedure :: save_state
      procedure :: restore_state
   end type poincare_diagnostics

contains

   !> For `points` observation points and the forcing frequency `omega` (0: no section,
   !! nothing is computed); `lyapunov`: &output lyapunov, on the unknowns `stepper` steps.
   subroutine init(self, points, omega, lyapunov, stepper)
      class(poincare_diagnostics), intent(inout) :: self
      integer, intent(in) :: points
      real(dp), intent(in) :: omega
      logical, intent(in) :: lyapunov
      class(time_stepper), intent(in) :: stepper
      self%section = omega > 0
      self%points = points
      self%omega = omega
      self%dt = stepper%dt
      call self%period%init(2*points)
      call self%zero_one%init()
      call self%lyapunov%init(lyapunov, stepper, omega)
   end subroutine init

   !> A window starts at a state whose observed values are `values` (2 points).
   subroutine start(self, values)
      class(poincare_diagnostics), intent(inout) :: self
      real(dp), intent(in) :: values(:)
      call self%period%start(values)
      call self%zero_one%restart()
      call self%lyapunov%restart()
   end subroutine start

   !> A step of the window: `stepper` took it and ended with the observed `values`;
   !! samples(:, 1:found) fell in it.
   subroutine observe_step(self, stepper, values, found, samples)
      class(poincare_diagnostics), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: values(:), samples(:, :)
      integer, intent(in) :: found
      integer :: k
      if (.not. self%section) return
      self%last_step = stepper%steps
      call self%lyapunov%step(stepper)
      if (found > 0) call self%lyapunov%renormalise(stepper)
      call self%period%observe_step(values)
      do k = 1, found
         call self%period%add_sample(samples(:, k))
         call self%zero_one%add(sum(samples(1:self%points, k)))
      end do
   end subroutine observe_step

   !> The group 'poincare' of `values` (and `errors`), laid out by `layout`.
   subroutine fill(self, layout, values, errors)
      class(poincare_diagnostics), intent(in) :: self
      type(statistics_layout), intent(in) :: layout
      real(dp), intent(inout) :: values(:), errors(:)
      real(dp) :: steps_per_period, mismatch, k, lambda, error
      integer :: period, lags
      integer(int64) :: periods
      if (.not. self%section) then
         values(at('period')) = -1
         return
      end if
      steps_per_period = 2*pi/(self%omega*self%dt)
      call self%period%find(steps_per_period, period, mismatch, self%last_step)
      values(at('period')) = period
      values(at('period_mismatch')) = mismatch
      call self%zero_one%result(k, lags)
      if (period == 1) k = 0
      values(at('zero_one_k')) = k
      values(at('zero_one_lags')) = lags
      call self%lyapunov%exponent(lambda, error, periods)
      values(at('lyapunov_exponent')) = lambda
      errors(at('lyapunov_exponent')) = error
      values(at('lyapunov_exponent_per_period')) = lambda*2*pi/self%omega
      errors(at('lyapunov_exponent_per_period')) = error*2*pi/self%omega
      values(at('lyapunov_periods')) = real(periods, dp)
   contains
      integer function at(name)
         character(len=*), intent(in) :: name
         at = layout%entries(layout%find(group_poincare, name))%offset + 1
      end function at
   end subroutine fill

   subroutine save_state(self, record, prefix)
      class(poincare_diagnostics), intent(in) :: self
      type(state_record), intent(inout) :: record
      character(len=*), intent(in) :: prefix
      if (.not. self%section) return
      call self%period%save_state(record, prefix//'.period')
      call self%zero_one%save_state(record, prefix//'.zero_one')
      call self%lyapunov%save_state(record, prefix//'.lyapunov')
   end subroutine save_state

   !> Take the state back; a checkpoint without it (written by version 0.2.0 or earlier) leaves the
   !! diagnostics to start at the checkpoint.
   subroutine restore_state(self, record, prefix, stat, errmsg)
      class(poincare_diagnostics), intent(inout) :: self
      type(state_record), intent(in) :: record
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.not. self%section .or. record%find(prefix//'.period.counts') == 0) return
      call self%period%restore_state(record, prefix//'.period', stat, errmsg)
      if (stat == 0) call self%zero_one%restore_state(record, prefix//'.zero_one', stat, errmsg)
      if (stat == 0) call self%lyapunov%restore_state(record, prefix//'.lyapunov', stat, errmsg)
   end subroutine restore_state
end module vibrobeam_poincare_diagnostics
