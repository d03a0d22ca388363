!> The 0-1 test for chaos of Gottwald and Melbourne, correlation method (G. A. Gottwald,
!! I. Melbourne, Proc. R. Soc. A 460 (2004) 603-611; "On the implementation of the 0-1
!! test for chaos", SIAM J. Appl. Dyn. Syst. 8 (2009) 129-145), on a scalar sequence
!! phi_1, phi_2, ... (docs/statistics.md, "Period, Lyapunov exponent and the 0-1 test").
!!
!! For a frequency c, p_c(n) + i q_c(n) = sum_{j<=n} phi_j e^{ijc}; the mean square
!! displacement over a lag n is M_c(n) = mean over j of |z_c(j + n) - z_c(j)|^2, the
!! modified one D_c(n) = M_c(n) - (E phi)^2 (1 - cos nc)/(1 - cos c), and
!! K_c = corr(n, D_c(n)) over n = 1 .. n_cut; K is the median of K_c over `frequencies`
!! values of c in (pi/5, 4 pi/5): near 0 for a regular sequence (D_c bounded), near 1 for
!! a chaotic one (D_c grows linearly).
!!
!! Streamed: z_c(J) - z_c(J - n) = sum_{m<n} phi_{J-m} e^{i(J-m)c}, whose modulus is that
!! of sum_{m<n} phi_{J-m} e^{-imc}: each new sample J adds |.|^2 for n = 1 .. max_lag to
!! sums(c, n) from the last max_lag samples alone. Memory and a checkpoint of
!! frequencies x max_lag sums and max_lag samples, whatever the length of the sequence:
!! the limit N -> infinity of Gottwald and Melbourne's M_c(n) at each fixed lag. At the
!! end n_cut = min(max_lag, N/10) (their N/10); K needs N >= min_samples.
!!
!! The samples enter less the first one (phi_j - phi_1): K does not change with a constant
!! shift of phi, and a level far above the fluctuations no longer cancels in D_c.
!!
!! The frequencies are drawn once, the same for every run: c_k = pi/5 + (3 pi/5) u_k, u_k
!! the first word of Philox4x32-10 (`vibrobeam_random`) at counter (k, 0, 0, 0) with the
!! key of seed `frequency_seed`, over 2^32.
module vibrobeam_zero_one
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_random, only: philox4x32, random_key
   use vibrobeam_sorting, only: median
   use vibrobeam_state_record, only: state_record
   implicit none
   private
   public :: zero_one_test, frequencies, max_lag, min_samples, frequency_seed

   integer, parameter :: frequencies = 100      !! values of c (Gottwald and Melbourne's 100)
   integer, parameter :: max_lag = 100          !! the longest lag n_cut
   integer, parameter :: min_samples = 100      !! shortest sequence tested: n_cut >= 10
   integer, parameter :: frequency_seed = 2004  !! seed of the frequencies c

   type :: zero_one_test
      integer(int64) :: samples = 0              !! N so far
      real(dp) :: first = 0                      !! phi_1
      real(dp) :: total = 0                      !! sum of phi_j - phi_1
      real(dp) :: c(frequencies) = 0             !! the frequencies c_k
      real(dp), allocatable :: cosines(:, :), sines(:, :)   !! (frequencies, 0:max_lag-1) cos(mc), -sin(mc)
      real(dp), allocatable :: latest(:)         !! (0:max_lag-1) the last max_lag samples, less phi_1
      real(dp), allocatable :: sums(:, :)        !! (frequencies, max_lag) sums of |z_c(J) - z_c(J-n)|^2
   contains
      procedure :: init
      procedure :: restart
      procedure :: add
      procedure :: result => zero_one_result
      procedure :: save_state
      procedure :: restore_state
   end type zero_one_test

contains

   !> An empty sequence, its frequencies drawn.
   subroutine init(self)
      class(zero_one_test), intent(inout) :: self
      integer(int64) :: words(4)
      integer :: k, m
      do k = 1, frequencies
         words = philox4x32([int(k, int64), 0_int64, 0_int64, 0_int64], random_key(frequency_seed, 0_int64))
         self%c(k) = pi/5 + (3*pi/5)*(real(words(1), dp)/4294967296.0_dp)
      end do
      if (allocated(self%sums)) deallocate (self%cosines, self%sines, self%latest, self%sums)
      allocate (self%cosines(frequencies, 0:max_lag - 1), self%sines(frequencies, 0:max_lag - 1))
      do m = 0, max_lag - 1
         self%cosines(:, m) = cos(m*self%c)
         self%sines(:, m) = -sin(m*self%c)
      end do
      allocate (self%latest(0:max_lag - 1), self%sums(frequencies, max_lag))
      call clear(self)
   end subroutine init

   !> No samples: a new window.
   subroutine restart(self)
      class(zero_one_test), intent(inout) :: self
      call clear(self)
   end subroutine restart

   !> No samples.
   subroutine clear(self)
      type(zero_one_test), intent(inout) :: self
      self%samples = 0
      self%first = 0
      self%total = 0
      self%latest = 0
      self%sums = 0
   end subroutine clear

   !> The next value of the sequence.
   subroutine add(self, phi)
      class(zero_one_test), intent(inout) :: self
      real(dp), intent(in) :: phi
      real(dp) :: shifted, p(frequencies), q(frequencies)
      integer :: n, slot
      if (self%samples == 0) self%first = phi
      shifted = phi - self%first
      self%samples = self%samples + 1
      self%total = self%total + shifted
      slot = int(mod(self%samples, int(max_lag, int64)))
      self%latest(slot) = shifted
      p = 0
      q = 0
      ! lag n: the samples J, J - 1, ..., J - n + 1 (m = 0 .. n - 1)
      do n = 1, int(min(int(max_lag, int64), self%samples))
         associate (value => self%latest(modulo(slot - (n - 1), max_lag)))
            p = p + value*self%cosines(:, n - 1)
            q = q + value*self%sines(:, n - 1)
         end associate
         self%sums(:, n) = self%sums(:, n) + (p**2 + q**2)
      end do
   end subroutine add

   !> K and the lags it used (n_cut; 0 and K = 0 with fewer than min_samples samples).
   subroutine zero_one_result(self, k, lags)
      class(zero_one_test), intent(in) :: self
      real(dp), intent(out) :: k
      integer, intent(out) :: lags
      real(dp) :: correlation(frequencies), d(max_lag), mean, lag_mean, lag_spread
      integer :: j, n
      k = 0
      lags = 0
      if (self%samples < min_samples) return
      lags = int(min(int(max_lag, int64), self%samples/10))
      mean = self%total/self%samples
      lag_mean = 0.5_dp*(lags + 1)
      lag_spread = sqrt(sum([((n - lag_mean)**2, n = 1, lags)]))
      do j = 1, frequencies
         do n = 1, lags
            d(n) = self%sums(j, n)/real(self%samples - n + 1, dp) - mean**2*(1 - cos(n*self%c(j)))/(1 - cos(self%c(j)))
         end do
         associate (centred => d(1:lags) - sum(d(1:lags))/lags)
            if (sum(centred**2) > 0) then
               correlation(j) = sum([((n - lag_mean)*centred(n), n = 1, lags)])/(lag_spread*sqrt(sum(centred**2)))
            else
               correlation(j) = 0
            end if
         end associate
      end do
      k = median(correlation)
   end subroutine zero_one_result

   subroutine save_state(self, record, prefix)
      class(zero_one_test), intent(in) :: self
      type(state_record), intent(inout) :: record
      character(len=*), intent(in) :: prefix
      call record%put_int64s(prefix//'.samples', [self%samples])
      call record%put_reals(prefix//'.moments', [self%first, self%total])
      call record%put_reals(prefix//'.latest', self%latest)
      call record%put_reals(prefix//'.sums', reshape(self%sums, [size(self%sums)]))
   end subroutine save_state

   subroutine restore_state(self, record, prefix, stat, errmsg)
      class(zero_one_test), intent(inout) :: self
      type(state_record), intent(in) :: record
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: samples(1)
      real(dp) :: moments(2), sums(size(self%sums))
      call record%get_int64s(prefix//'.samples', samples, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.moments', moments, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.latest', self%latest, stat, errmsg)
      if (stat == 0) call record%get_reals(prefix//'.sums', sums, stat, errmsg)
      if (stat /= 0) return
      self%samples = samples(1)
      self%first = moments(1)
      self%total = moments(2)
      self%sums = reshape(sums, shape(self%sums))
   end subroutine restore_state
end module vibrobeam_zero_one
