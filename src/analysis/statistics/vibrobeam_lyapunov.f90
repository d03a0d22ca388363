!> The largest Lyapunov exponent of the discrete map, by Benettin's method on its tangent
!! map (docs/statistics.md, "Period, Lyapunov exponent and the 0-1 test"; G. Benettin,
!! L. Galgani, A. Giorgilli, J.-M. Strelcyn, Meccanica 15 (1980) 9-20).
!!
!! A perturbation w = (dU, dV) of the state goes through the derivative of every step of
!! the window (`linearise_step`: the time scheme's own tangent, the same as the period
!! map's monodromy, through the contact points the step held). Once per forcing period
!! (in the step where a Poincare sample falls) its energy norm ||w|| (`energy_norm` at the
!! forcing frequency) is taken, log ||w|| added to the sums and w scaled back to norm 1.
!! The exponent is the sum of the logarithms over the time they took, lambda (1/s), and
!! lambda T per forcing period T = 2 pi/Omega; its standard error is that of batch means
!! over blocks of periods (`vibrobeam_batch_blocks`, as the other statistics): each
!! block's sum over its duration is one batch value.
!!
!! w starts at the window's start as a velocity alone (dU = 0), of norm 1, its components
!! drawn from Philox4x32-10 at counter (j, 0, 0, 0) under the key of seed `vector_seed`
!! (uniform in [-1/2, 1/2)). Its component along the most unstable direction (about
!! 1/sqrt(J) in the norm of M) makes log ||w|| start lower than the aligned perturbation's
!! would: the first block of periods, where it aligns, is left out of the exponent
!! (`exponent`).
module vibrobeam_lyapunov
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_random, only: philox4x32, random_key
   use vibrobeam_state_record, only: state_record
   use vibrobeam_time_stepper, only: time_stepper, energy_norm
   use vibrobeam_stepper_factory, only: linearise_step
   use vibrobeam_batch_blocks, only: block_accumulator, standard_error
   implicit none
   private
   public :: lyapunov_tangent, vector_seed

   integer, parameter :: vector_seed = 1980   !! seed of the starting perturbation
   integer, parameter :: q_growth = 1, q_steps = 2   !! the sums of a block: log growth, steps

   type :: lyapunov_tangent
      logical :: active = .false.                   !! asked for (&output lyapunov)
      logical :: failed = .false.                   !! a step could not be linearised: the sums stopped there
      character(len=256) :: failure = ''
      real(dp) :: omega = 0                         !! forcing frequency (rad/s)
      real(dp) :: dt = 0
      integer(int64) :: steps_since = 0             !! steps since the last renormalisation
      real(dp), allocatable :: du(:, :), dv(:, :)   !! (unknowns, 1) the perturbation
      type(block_accumulator) :: blocks             !! one sample per period: its log growth and steps
   contains
      procedure :: init
      procedure :: restart
      procedure :: step
      procedure :: renormalise
      procedure :: exponent
      procedure :: save_state
      procedure :: restore_state
   end type lyapunov_tangent

contains

   !> A perturbation of the unknowns `stepper` steps, at forcing frequency `omega`; active
   !! only when `asked` (and omega > 0).
   subroutine init(self, asked, stepper, omega)
      class(lyapunov_tangent), intent(inout) :: self
      logical, intent(in) :: asked
      class(time_stepper), intent(in) :: stepper
      real(dp), intent(in) :: omega
      integer(int64) :: words(4)
      real(dp) :: norm
      integer :: j, unknowns
      self%active = asked .and. omega > 0
      self%omega = omega
      self%dt = stepper%dt
      if (.not. self%active) return
      unknowns = size(stepper%u)
      if (allocated(self%du)) deallocate (self%du, self%dv)
      allocate (self%du(unknowns, 1), self%dv(unknowns, 1))
      self%du = 0
      do j = 1, unknowns
         words = philox4x32([int(j, int64), 0_int64, 0_int64, 0_int64], random_key(vector_seed, 0_int64))
         self%dv(j, 1) = real(words(1), dp)/4294967296.0_dp - 0.5_dp
      end do
      norm = energy_norm(stepper%mass, stepper%stiffness, omega, self%du(:, 1), self%dv(:, 1))
      self%du = self%du/norm
      self%dv = self%dv/norm
      call self%restart()
   end subroutine init

   !> A new window: no sums (the perturbation goes on from where it is).
   subroutine restart(self)
      class(lyapunov_tangent), intent(inout) :: self
      self%steps_since = 0
      call self%blocks%init(2, 0, [real(dp) ::])
   end subroutine restart

   !> The perturbation through the step `stepper` just took.
   subroutine step(self, stepper)
      class(lyapunov_tangent), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      integer :: stat
      if (.not. self%active .or. self%failed) return
      call linearise_step(stepper, self%du, self%dv, stat, self%failure)
      if (stat /= 0) then
         self%failed = .true.
         return
      end if
      self%steps_since = self%steps_since + 1
   end subroutine step

   !> A forcing period ended in this step: log ||w|| into the sums, w back to norm 1 (the
   !! first interval of a window runs from its start to the first sample).
   subroutine renormalise(self, stepper)
      class(lyapunov_tangent), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      real(dp) :: norm
      if (.not. self%active .or. self%failed .or. self%steps_since == 0) return
      norm = energy_norm(stepper%mass, stepper%stiffness, self%omega, self%du(:, 1), self%dv(:, 1))
      if (.not. (norm > 0 .and. norm < huge(1.0_dp))) then
         self%failed = .true.
         self%failure = 'the perturbation vanished or overflowed'
         return
      end if
      call self%blocks%add(q_growth, log(norm))
      call self%blocks%add(q_steps, real(self%steps_since, dp))
      call self%blocks%close_sample()
      self%du = self%du/norm
      self%dv = self%dv/norm
      self%steps_since = 0
   end subroutine renormalise

   !> lambda (1/s) and its standard error, and the periods they cover (0: none, and
   !! lambda = 0). The first of the complete blocks (1/16 to 1/8 of the window's periods) is
   !! left out when there are at least 3: the perturbation aligns with the most unstable
   !! direction there (module documentation).
   subroutine exponent(self, lambda, error, periods)
      class(lyapunov_tangent), intent(in) :: self
      real(dp), intent(out) :: lambda, error
      integer(int64), intent(out) :: periods
      real(dp) :: growth, steps
      integer :: b, first
      lambda = 0
      error = 0
      periods = 0
      if (.not. self%active .or. self%blocks%samples < 1) return
      associate (blocks => self%blocks)
         first = 0
         if (blocks%complete >= 3) first = 1
         growth = blocks%total(q_growth) - sum(blocks%sums(q_growth, 0:first - 1))
         steps = blocks%total(q_steps) - sum(blocks%sums(q_steps, 0:first - 1))
         periods = blocks%samples - first*blocks%block_steps
         lambda = growth/(steps*self%dt)
         error = standard_error([(blocks%sums(q_growth, b)/(blocks%sums(q_steps, b)*self%dt), &
                                  b = first, blocks%complete - 1)])
      end associate
   end subroutine exponent

   subroutine save_state(self, record, prefix)
      class(lyapunov_tangent), intent(in) :: self
      type(state_record), intent(inout) :: record
      character(len=*), intent(in) :: prefix
      if (.not. self%active) return
      call record%put_int64s(prefix//'.counts', [self%steps_since, merge(1_int64, 0_int64, self%failed)])
      call record%put_reals(prefix//'.perturbation', [self%du(:, 1), self%dv(:, 1)])
      call self%blocks%save_state(record, prefix//'.blocks')
   end subroutine save_state

   !> Take the state back; a checkpoint without it (a run without &output lyapunov) leaves
   !! the perturbation at its start: the exponent then covers the continued run only.
   subroutine restore_state(self, record, prefix, stat, errmsg)
      class(lyapunov_tangent), intent(inout) :: self
      type(state_record), intent(in) :: record
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: counts(2)
      real(dp), allocatable :: perturbation(:)   ! (sized after the return: du is unallocated when inactive)
      stat = 0
      errmsg = ''
      if (.not. self%active .or. record%find(prefix//'.counts') == 0) return
      allocate (perturbation(2*size(self%du)))
      call record%get_int64s(prefix//'.counts', counts, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.perturbation', perturbation, stat, errmsg)
      if (stat == 0) call self%blocks%restore_state(record, prefix//'.blocks', stat, errmsg)
      if (stat /= 0) return
      self%steps_since = counts(1)
      self%failed = counts(2) == 1
      self%du(:, 1) = perturbation(1:size(self%du))
      self%dv(:, 1) = perturbation(size(self%du) + 1:)
   end subroutine restore_state
end module vibrobeam_lyapunov
