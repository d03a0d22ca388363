!> Stationary Gaussian random signals with a given one-sided power spectral density
!! (docs/theory.md section 9, "Random loads"; docs/method.md, "Random signals").
!!
!! A signal is white noise shaped by a filter: sample n (t_n = n tau, tau the time step
!! of the run) is
!!
!!     y_n = sum_{k=0}^{L-1} h_k xi_{n-k},
!!
!! with xi_m independent N(0, 1) deviates (`vibrobeam_random`: deviate m of a stream is a
!! function of the seed, the realisation, the stream and m alone) and h the L taps of a
!! linear-phase filter whose gain follows sqrt(S(f)/(2 tau)). Its one-sided density is
!! exactly S_y(f) = 2 tau |G(f)|^2, G(f) = sum_k h_k exp(-2 pi i f k tau), a smooth function
!! equal to S up to the filter's resolution 1/(L tau) (`design`), and its variance is
!! exactly sum_k h_k^2. Unlike a sum of sinusoids on a frequency grid, the density has no
!! comb: a lightly damped resonance between two grid lines is excited as the target says.
!!
!! FFT synthesis (FFTW, r2c/c2r): the taps come from S by one inverse transform of size L
!! (frequency sampling at f_j = j/(L tau), Hann window); the signal is made in blocks of L
!! samples, block b holding n = b L .. (b + 1) L - 1, by overlap-save: the 2L deviates
!! n = (b - 1) L .. (b + 1) L - 1, one forward transform of size 2L, a product with the
!! taps' transform, one inverse transform, whose last L values are the linear convolution.
!! A block is a pure function of (seed, realisation, stream, b): a run continued from any
!! step recomputes the block it is in and goes on with the same bits, and no state is
!! carried from block to block but the noise a following block shares (it is a function of
!! its index: kept only to draw each deviate once). Memory: the block and its noise per
!! channel (2 L values, in the copy of the signal that is evaluated) and the taps and their
!! transform (3 L values).
!! The plans use FFTW_ESTIMATE (no timing) and FFTW_UNALIGNED (no SIMD codelets, whose
!! choice depends on the processor), so the bits depend on the FFTW library, not on the
!! machine, thread or process.
!!
!! Several channels (the points of a distributed load with spatial coherence) carry
!! q_1 = eta_1, q_k = rho_k q_{k-1} + sqrt(1 - rho_k^2) eta_k, with eta_k independent
!! signals of the same density (streams 0, 1, ...) and rho_k = exp(-(x_k - x_{k-1})/l):
!! every channel has the density S and the coherence of channels j, k is
!! exp(-|x_j - x_k|/l) at every frequency (the exponential correlation is Markov in x).
module vibrobeam_random_signal
   use, intrinsic :: iso_c_binding
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure
   use vibrobeam_random, only: gaussian_pair, portable_exp, portable_sin_pi
   use vibrobeam_table_file, only: linear_table
   implicit none
   private
   public :: spectrum_shape, random_signal, filter_taps, min_taps, max_taps

   include 'fftw3.f03'

   integer, parameter :: min_taps = 2**8      !! fewest filter taps L
   integer, parameter :: max_taps = 2**20     !! most filter taps L (8 MB per channel and block)
   !> filter resolution: L tau >= resolution_factor / (the narrowest feature of S, Hz)
   real(dp), parameter :: resolution_factor = 8
   !> deviate m of a stream is used for noise sample n = m - noise_origin (n >= -2^21 >= -2 L)
   integer(int64), parameter :: noise_origin = 2_int64**21
   !> a time within this fraction of a step of t_n takes sample n itself, not an interpolation
   real(dp), parameter :: on_grid = 1e-6_dp

   !> A one-sided power spectral density S(f) (unit^2/Hz, f in Hz): `level` over
   !! [band_from, band_to] (band-limited white), or, when `tabulated`, the table (f, S),
   !! linear between its points and 0 outside them.
   type :: spectrum_shape
      real(dp) :: level = 0, band_from = 0, band_to = 0
      logical :: tabulated = .false.
      type(linear_table) :: table
   contains
      procedure :: at => spectrum_at
      procedure :: highest => spectrum_highest
      procedure :: narrowest => spectrum_narrowest
      procedure :: variance => spectrum_variance
      procedure :: integral => spectrum_integral
   end type spectrum_shape

   type :: random_signal
      real(dp) :: step = 0                          !! tau, the sample step (s)
      integer :: taps = 0                           !! L
      integer(int64) :: key(2) = 0                  !! of the seed and realisation (`random_key`)
      integer :: channels = 0
      integer(int64), allocatable :: stream(:)      !! (channels) stream of each channel's eta
      real(dp), allocatable :: carried(:), fresh(:) !! (channels) rho_k and sqrt(1 - rho_k^2)
      real(dp), allocatable :: taps_values(:)       !! (L) the filter's taps h_0 .. h_{L-1}
      complex(dp), allocatable :: response(:)       !! (L + 1) transform of the taps padded to 2L
      real(dp) :: rms = 0                           !! root mean square of every channel, sqrt(sum h^2)
      real(dp) :: highest = 0                       !! the highest frequency where S is not 0 (Hz)
      real(dp) :: target_rms = 0                    !! sqrt of the integral of S, what the density asks
      type(spectrum_shape) :: density               !! S, the target density (the result file's psd_target)
      integer(int64) :: block_index = -huge(1_int64)   !! the block in `block` (none yet)
      !> (L, channels) samples b L .. (b + 1) L - 1 of block b = block_index (allocated when
      !! the signal is first evaluated)
      real(dp), allocatable :: block(:, :)
      !> (L, channels) the white noise of the block's samples, the first half of the next
      !! block's (`fill_block`)
      real(dp), allocatable :: tail(:, :)
   contains
      procedure :: design
      procedure :: values => signal_values
      procedure :: values_uncached => signal_values_uncached
      procedure :: sample => signal_sample
      procedure :: first_channel
      procedure :: fill_block
      procedure :: applied_density
   end type random_signal

contains

   !> S(f) (unit^2/Hz).
   elemental real(dp) function spectrum_at(self, f)
      class(spectrum_shape), intent(in) :: self
      real(dp), intent(in) :: f   !! frequency (Hz)
      if (self%tabulated) then
         spectrum_at = self%table%at(f)
      else
         spectrum_at = 0
         if (f >= self%band_from .and. f <= self%band_to) spectrum_at = self%level
      end if
   end function spectrum_at

   !> The highest frequency where S may be non-zero (Hz).
   pure real(dp) function spectrum_highest(self)
      class(spectrum_shape), intent(in) :: self
      if (self%tabulated) then
         spectrum_highest = self%table%x(size(self%table%x))
      else
         spectrum_highest = self%band_to
      end if
   end function spectrum_highest

   !> The narrowest feature of S (Hz), which the filter must resolve: the band's width and
   !! its distance from 0; a table's smallest spacing.
   pure real(dp) function spectrum_narrowest(self)
      class(spectrum_shape), intent(in) :: self
      if (self%tabulated) then
         associate (x => self%table%x)
            spectrum_narrowest = minval(x(2:) - x(:size(x) - 1))
         end associate
      else
         spectrum_narrowest = self%band_to - self%band_from
         if (self%band_from > 0) spectrum_narrowest = min(spectrum_narrowest, self%band_from)
      end if
   end function spectrum_narrowest

   !> The integral of S over f (unit^2): the variance of a signal with this density.
   pure real(dp) function spectrum_variance(self)
      class(spectrum_shape), intent(in) :: self
      integer :: n
      if (self%tabulated) then
         associate (x => self%table%x, y => self%table%y)
            n = size(x)
            spectrum_variance = 0.5_dp*sum((x(2:) - x(:n - 1))*(y(2:) + y(:n - 1)))
         end associate
      else
         spectrum_variance = self%level*(self%band_to - self%band_from)
      end if
   end function spectrum_variance

   !> The integral of S over [a, b] (unit^2), exact (S is piecewise linear).
   pure real(dp) function spectrum_integral(self, a, b)
      class(spectrum_shape), intent(in) :: self
      real(dp), intent(in) :: a, b   !! Hz, a <= b
      real(dp) :: lo, hi
      integer :: k
      spectrum_integral = 0
      if (.not. self%tabulated) then
         spectrum_integral = self%level*max(0.0_dp, min(b, self%band_to) - max(a, self%band_from))
         return
      end if
      do k = 1, size(self%table%x) - 1
         lo = max(a, self%table%x(k))
         hi = min(b, self%table%x(k + 1))
         ! S is linear on the clipped piece: its mean is the mean of its end values
         if (hi > lo) spectrum_integral = spectrum_integral + 0.5_dp*(hi - lo)*(self%at(lo) + self%at(hi))
      end do
   end function spectrum_integral

   !> The number of taps L for a density and a sample step (s): the smallest power of two in
   !! [min_taps, max_taps] with L tau >= 8 / (the narrowest feature of S).
   pure integer function filter_taps(shape, step)
      type(spectrum_shape), intent(in) :: shape
      real(dp), intent(in) :: step
      real(dp) :: needed
      needed = resolution_factor/(max(shape%narrowest(), tiny(1.0_dp))*step)
      filter_taps = min_taps
      do while (filter_taps < max_taps .and. real(filter_taps, dp) < needed)
         filter_taps = 2*filter_taps
      end do
   end function filter_taps

   !> Set up a signal of density `shape`, sample step `step` (s), key `key`: the taps of its
   !! filter (module documentation) and its channels at `positions` (m, increasing; one
   !! channel when absent) with the correlation length `correlation_length` (m; 0: fully
   !! correlated, one channel). stat = stat_failure when FFTW cannot plan.
   subroutine design(self, shape, step, key, stat, errmsg, positions, correlation_length)
      class(random_signal), intent(out) :: self
      type(spectrum_shape), intent(in) :: shape
      real(dp), intent(in) :: step
      integer(int64), intent(in) :: key(2)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), intent(in), optional :: positions(:), correlation_length
      real(c_double), pointer :: taps(:), padded(:)
      complex(c_double_complex), pointer :: gains(:), transform(:)
      type(c_ptr) :: taps_memory, padded_memory, gains_memory, transform_memory, inverse, forward
      real(dp) :: low, high
      integer :: l, j, k
      stat = 0
      errmsg = ''
      self%step = step
      self%key = key
      self%highest = shape%highest()
      self%target_rms = sqrt(shape%variance())
      self%density = shape
      self%taps = filter_taps(shape, step)
      l = self%taps
      self%channels = 1
      if (present(positions)) self%channels = size(positions)
      allocate (self%stream(self%channels), self%carried(self%channels), self%fresh(self%channels))
      self%stream = [(int(k - 1, int64), k=1, self%channels)]
      self%carried = 0
      self%fresh = 1
      if (present(positions) .and. present(correlation_length)) then
         do k = 2, self%channels
            self%carried(k) = portable_exp(-(positions(k) - positions(k - 1))/correlation_length)
            self%fresh(k) = sqrt(1 - self%carried(k)**2)
         end do
      end if
      taps_memory = fftw_alloc_real(int(l, c_size_t))
      gains_memory = fftw_alloc_complex(int(l/2 + 1, c_size_t))
      padded_memory = fftw_alloc_real(int(2*l, c_size_t))
      transform_memory = fftw_alloc_complex(int(l + 1, c_size_t))
      call c_f_pointer(taps_memory, taps, [l])
      call c_f_pointer(gains_memory, gains, [l/2 + 1])
      call c_f_pointer(padded_memory, padded, [2*l])
      call c_f_pointer(transform_memory, transform, [l + 1])
      ! the planner is not thread-safe (FFTW manual, "Thread safety"): one thread at a time
      !$omp critical (vibrobeam_fftw_planner)
      inverse = fftw_plan_dft_c2r_1d(int(l, c_int), gains, taps, ior(FFTW_ESTIMATE, FFTW_UNALIGNED))
      forward = fftw_plan_dft_r2c_1d(int(2*l, c_int), padded, transform, ior(FFTW_ESTIMATE, FFTW_UNALIGNED))
      !$omp end critical (vibrobeam_fftw_planner)
      if (c_associated(inverse) .and. c_associated(forward)) then
         ! frequency sampling: zero-phase gains sqrt(S_j/(2 tau)) at f_j = j/(L tau), S_j the
         ! mean of S over the bin [f_j - df/2, f_j + df/2] within [0, 1/(2 tau)] (df = 1/(L tau)):
         ! the variance sum_j of the bins' powers is then the integral of S, edges included
         do j = 0, l/2
            low = max(0.0_dp, (j - 0.5_dp)/(l*step))
            high = min(0.5_dp/step, (j + 0.5_dp)/(l*step))
            gains(j + 1) = cmplx(sqrt(shape%integral(low, high)/(high - low)/(2*step)), 0.0_dp, c_double_complex)
         end do
         call fftw_execute_dft_c2r(inverse, gains, taps)
         ! centred on L/2 (linear phase, causal), Hann window, 1/L of the unnormalized inverse
         do k = 0, l - 1
            padded(k + 1) = portable_sin_pi(real(k, dp)/l)**2*taps(modulo(k - l/2, l) + 1)/l
         end do
         padded(l + 1:) = 0
         self%taps_values = real(padded(1:l), dp)
         self%rms = sqrt(sum(self%taps_values**2))
         call fftw_execute_dft_r2c(forward, padded, transform)
         self%response = cmplx(transform, kind=dp)
      else
         stat = stat_failure
         write (errmsg, '(a,i0)') 'random signal: FFTW could not plan the transforms of size ', 2*l
      end if
      !$omp critical (vibrobeam_fftw_planner)
      if (c_associated(inverse)) call fftw_destroy_plan(inverse)
      if (c_associated(forward)) call fftw_destroy_plan(forward)
      !$omp end critical (vibrobeam_fftw_planner)
      call fftw_free(taps_memory)
      call fftw_free(gains_memory)
      call fftw_free(padded_memory)
      call fftw_free(transform_memory)
   end subroutine design

   !> The one-sided power spectral density the signal has, 2 tau |G(f)|^2 with
   !! G(f) = sum_k h_k exp(-2 pi i f k tau) (unit^2/Hz; module documentation): what a
   !! sampled record of it has, exactly, at f in [0, 1/(2 tau)] (Hz).
   elemental real(dp) function applied_density(self, f)
      class(random_signal), intent(in) :: self
      real(dp), intent(in) :: f
      real(dp), parameter :: two_pi = 2*acos(-1.0_dp)
      complex(dp) :: g
      integer :: k
      g = 0
      do k = 0, self%taps - 1
         g = g + self%taps_values(k + 1)*exp(cmplx(0.0_dp, -two_pi*f*k*self%step, dp))
      end do
      applied_density = 2*self%step*abs(g)**2
   end function applied_density

   !> Block b (samples b L .. (b + 1) L - 1 of every channel) into self%block, block_index =
   !! b. The 2L deviates of noise samples (b - 1) L .. (b + 1) L - 1 are pure functions of
   !! their index; when b follows the block kept, the first L of them are those the last
   !! block drew second (kept in `tail`), so a run draws each deviate once.
   subroutine fill_block(self, b)
      class(random_signal), intent(inout) :: self
      integer(int64), intent(in) :: b
      real(c_double), pointer :: noise(:)
      complex(c_double_complex), pointer :: transform(:)
      type(c_ptr) :: noise_memory, transform_memory, forward, inverse
      integer(int64) :: first_pair
      logical :: follows
      integer :: l, c, k
      l = self%taps
      if (.not. allocated(self%block)) allocate (self%block(l, self%channels), self%tail(l, self%channels))
      follows = b == self%block_index + 1
      noise_memory = fftw_alloc_real(int(2*l, c_size_t))
      transform_memory = fftw_alloc_complex(int(l + 1, c_size_t))
      call c_f_pointer(noise_memory, noise, [2*l])
      call c_f_pointer(transform_memory, transform, [l + 1])
      !$omp critical (vibrobeam_fftw_planner)
      forward = fftw_plan_dft_r2c_1d(int(2*l, c_int), noise, transform, ior(FFTW_ESTIMATE, FFTW_UNALIGNED))
      inverse = fftw_plan_dft_c2r_1d(int(2*l, c_int), transform, noise, ior(FFTW_ESTIMATE, FFTW_UNALIGNED))
      !$omp end critical (vibrobeam_fftw_planner)
      ! deviate m = n + noise_origin of noise sample n; (b - 1) L + noise_origin is even (L
      ! is a power of two >= 256), so the noise takes whole pairs: pair k of the block holds
      ! deviates first + 2k, first + 2k + 1
      first_pair = ((b - 1)*l + noise_origin)/2
      do c = 1, self%channels
         if (follows) then
            noise(1:l) = self%tail(:, c)
         else
            do k = 0, l/2 - 1
               noise(2*k + 1:2*k + 2) = gaussian_pair(self%key, self%stream(c), first_pair + k)
            end do
         end if
         do k = l/2, l - 1
            noise(2*k + 1:2*k + 2) = gaussian_pair(self%key, self%stream(c), first_pair + k)
         end do
         self%tail(:, c) = noise(l + 1:2*l)
         call fftw_execute_dft_r2c(forward, noise, transform)
         transform = transform*self%response
         call fftw_execute_dft_c2r(inverse, transform, noise)
         self%block(:, c) = noise(l + 1:2*l)/(2*l)
      end do
      !$omp critical (vibrobeam_fftw_planner)
      call fftw_destroy_plan(forward)
      call fftw_destroy_plan(inverse)
      !$omp end critical (vibrobeam_fftw_planner)
      call fftw_free(noise_memory)
      call fftw_free(transform_memory)
      do c = 2, self%channels
         self%block(:, c) = self%carried(c)*self%block(:, c - 1) + self%fresh(c)*self%block(:, c)
      end do
      self%block_index = b
   end subroutine fill_block

   !> The value of every channel at time t (s), from the block kept (computed when t is in
   !! another one): sample n when t is t_n to within 1e-6 of a step, else linear between
   !! the samples around t.
   subroutine signal_values(self, t, values)
      class(random_signal), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(out) :: values(:)   !! (channels)
      integer(int64) :: n
      real(dp) :: r, a
      r = max(t, 0.0_dp)/self%step
      n = nint(r, int64)
      if (abs(r - n) <= on_grid) then
         call take(n, values)
      else
         n = floor(r, int64)
         a = r - n
         call take(n, values)
         values = (1 - a)*values
         call add(n + 1, a)
      end if
   contains
      subroutine take(sample, out)
         integer(int64), intent(in) :: sample
         real(dp), intent(out) :: out(:)
         call make_current(sample/self%taps)
         out = self%block(sample - self%block_index*self%taps + 1, :)
      end subroutine take
      subroutine add(sample, weight)
         integer(int64), intent(in) :: sample
         real(dp), intent(in) :: weight
         call make_current(sample/self%taps)
         values = values + weight*self%block(sample - self%block_index*self%taps + 1, :)
      end subroutine add
      subroutine make_current(b)
         integer(int64), intent(in) :: b
         ! the block is allocated at its first use: the copies of a signal made before a run
         ! (the problem's, the system's) keep none
         if (b /= self%block_index) call self%fill_block(b)
      end subroutine make_current
   end subroutine signal_values

   !> Sample n >= 0 of every channel (y_n, at t_n = n tau), from the block kept (computed
   !! when n is in another one): the values `values` gives at t_n.
   subroutine signal_sample(self, n, values)
      class(random_signal), intent(inout) :: self
      integer(int64), intent(in) :: n
      real(dp), intent(out) :: values(:)   !! (channels)
      if (n/self%taps /= self%block_index) call self%fill_block(n/self%taps)
      values = self%block(n - self%block_index*self%taps + 1, :)
   end subroutine signal_sample

   !> The signal of channel 1 alone (q_1 = eta_1, stream 0: the same bits as channel 1 of
   !! this signal, at 1/channels of its cost), no block kept.
   function first_channel(self) result(single)
      class(random_signal), intent(in) :: self
      type(random_signal) :: single
      single%step = self%step
      single%taps = self%taps
      single%key = self%key
      single%channels = 1
      single%stream = self%stream(1:1)
      single%carried = [0.0_dp]
      single%fresh = [1.0_dp]
      single%taps_values = self%taps_values
      single%response = self%response
      single%rms = self%rms
      single%highest = self%highest
      single%target_rms = self%target_rms
      single%density = self%density
   end function first_channel

   !> `values` without keeping a block (for a caller that cannot change the signal): the
   !! same bits, at the cost of computing the block of t.
   subroutine signal_values_uncached(self, t, values)
      class(random_signal), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp), intent(out) :: values(:)
      type(random_signal) :: copy
      copy = self
      call copy%values(t, values)
   end subroutine signal_values_uncached
end module vibrobeam_random_signal
