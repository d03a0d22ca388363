!> Streaming amplitude spectrum of a uniformly sampled signal: Welch's method (P. D.
!! Welch, "The use of fast Fourier transform for the estimation of power spectra", IEEE
!! Trans. Audio Electroacoust. 15 (1967) 70-73), with memory bounded by one segment.
!!
!! Samples arrive one at a time (`add`). A record of n <= `welch_segment` = 2^16 samples is
!! transformed as a whole at the end: the result is exactly `amplitude_spectrum` of the
!! record (mean removed, periodic Hann window, single-sided amplitudes; see
!! `vibrobeam_spectrum`). A longer record is cut into segments of 2^16 samples that
!! overlap by half (a new segment every 2^15 samples); each segment gets the same
!! treatment (its own mean removed, Hann window), and the amplitudes are averaged in
!! power: a_k = sqrt(mean over segments of a_k(segment)^2), so a steady sine on a bin
!! still reads its amplitude. The samples after the last complete segment (fewer than
!! 2^15) are not used. Bin width 1/(n dt) for one record, 1/(2^16 dt) for segments.
!!
!! An estimator may be given another segment length n_s (a power of two, `init`'s
!! `segment`; the random loads' spectra use the filter's length): everything above holds
!! with 2^16 replaced by n_s.
!!
!! Memory: one buffer of at most 2^16 samples and 2^15 + 1 power sums. The estimator's
!! state goes into a checkpoint (`save_state`), so a continued run gives the spectrum of
!! the whole run.
module vibrobeam_welch
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_spectrum, only: amplitude_spectrum, bin_width
   use vibrobeam_state_record, only: state_record
   implicit none
   private
   public :: welch_estimator, welch_segment

   !> Samples per segment (and the longest record transformed whole).
   integer, parameter :: welch_segment = 2**16

   type :: welch_estimator
      real(dp) :: dt = 0                     !! sampling interval (s)
      integer :: segment = welch_segment     !! samples per segment (a power of two)
      integer :: filled = 0                  !! samples in the buffer
      integer(int64) :: samples = 0          !! samples added since the start of the run
      integer(int64) :: segments = 0         !! segments transformed
      real(dp), allocatable :: buffer(:)     !! (capacity) the latest samples
      real(dp), allocatable :: power(:)      !! (segment/2 + 1) sums of a_k^2, or (0)
   contains
      procedure :: init
      procedure :: add
      procedure :: spectrum
      procedure :: save_state
      procedure :: restore_state
   end type welch_estimator

contains

   !> Start with sampling interval `dt`; `expected` samples at most in the whole run size
   !! the buffer (min(expected, segment)); `segment` samples per segment (a power of two
   !! >= 2; default `welch_segment`).
   subroutine init(self, dt, expected, segment)
      class(welch_estimator), intent(inout) :: self
      real(dp), intent(in) :: dt
      integer(int64), intent(in) :: expected
      integer, intent(in), optional :: segment
      self%dt = dt
      self%segment = welch_segment
      if (present(segment)) self%segment = segment
      self%filled = 0
      self%samples = 0
      self%segments = 0
      if (allocated(self%buffer)) deallocate (self%buffer)
      if (allocated(self%power)) deallocate (self%power)
      allocate (self%buffer(int(max(2_int64, min(expected, int(self%segment, int64))))), source=0.0_dp)
      call size_power(self)
   end subroutine init

   !> Power sums exist once segments can occur (a full-size buffer).
   subroutine size_power(self)
      type(welch_estimator), intent(inout) :: self
      if (allocated(self%power)) deallocate (self%power)
      if (size(self%buffer) == self%segment) then
         allocate (self%power(self%segment/2 + 1), source=0.0_dp)
      else
         allocate (self%power(0))
      end if
   end subroutine size_power

   !> Add the next sample. stat /= 0 only when a segment's transform fails.
   subroutine add(self, sample, stat, errmsg)
      class(welch_estimator), intent(inout) :: self
      real(dp), intent(in) :: sample
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: bigger(:)
      stat = 0
      errmsg = ''
      if (self%filled == size(self%buffer)) then
         if (size(self%buffer) < self%segment) then
            ! more samples than expected (a longer continued run): grow up to one segment
            allocate (bigger(min(self%segment, 2*size(self%buffer))), source=0.0_dp)
            bigger(1:self%filled) = self%buffer(1:self%filled)
            call move_alloc(bigger, self%buffer)
            call size_power(self)
         else
            call transform_segment(self, stat, errmsg)
            if (stat /= 0) return
            self%buffer(1:self%segment/2) = self%buffer(self%segment/2 + 1:self%segment)
            self%filled = self%segment/2
         end if
      end if
      self%filled = self%filled + 1
      self%buffer(self%filled) = sample
      self%samples = self%samples + 1
   end subroutine add

   !> Add the amplitudes of the full buffer, squared, to the power sums.
   subroutine transform_segment(self, stat, errmsg)
      type(welch_estimator), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: frequency(:), amplitude(:)
      call amplitude_spectrum(self%buffer, self%dt, frequency, amplitude, stat, errmsg, window='hann')
      if (stat /= 0) return
      self%power = self%power + amplitude**2
      self%segments = self%segments + 1
   end subroutine transform_segment

   !> The spectrum of every sample added so far (module documentation). `segments` is 0
   !! for a record transformed whole; `width` is the bin width (Hz). Fewer than 2 samples
   !! give empty arrays.
   subroutine spectrum(self, frequency, amplitude, segments, width, stat, errmsg)
      class(welch_estimator), intent(inout) :: self
      real(dp), allocatable, intent(out) :: frequency(:), amplitude(:)
      integer(int64), intent(out) :: segments
      real(dp), intent(out) :: width
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      stat = 0
      errmsg = ''
      segments = self%segments
      width = 0
      if (self%segments == 0) then
         if (self%filled < 2) then
            allocate (frequency(0), amplitude(0))
            return
         end if
         call amplitude_spectrum(self%buffer(1:self%filled), self%dt, frequency, amplitude, stat, errmsg, &
                                 window='hann')
         width = bin_width(self%filled, self%dt)
         return
      end if
      if (self%filled == self%segment) then
         ! the last segment is complete: count it (once; the buffer then starts the next)
         call transform_segment(self, stat, errmsg)
         if (stat /= 0) return
         self%buffer(1:self%segment/2) = self%buffer(self%segment/2 + 1:self%segment)
         self%filled = self%segment/2
      end if
      segments = self%segments
      width = bin_width(self%segment, self%dt)
      allocate (frequency(self%segment/2 + 1), amplitude(self%segment/2 + 1))
      do k = 0, self%segment/2
         frequency(k + 1) = k*width
      end do
      amplitude = sqrt(self%power/self%segments)
   end subroutine spectrum

   !> The estimator's state (sizes fixed for a run: see `init`), under names starting with
   !! `prefix` (default 'spectrum': the recorder's whole-run spectrum).
   subroutine save_state(self, record, prefix)
      class(welch_estimator), intent(in) :: self
      type(state_record), intent(inout) :: record
      character(len=*), intent(in), optional :: prefix
      character(len=:), allocatable :: name
      name = 'spectrum'
      if (present(prefix)) name = prefix
      call record%put_int64s(name//'.counts', [int(self%filled, int64), self%samples, self%segments])
      call record%put_reals(name//'.buffer', self%buffer)
      call record%put_reals(name//'.power', self%power)
   end subroutine save_state

   !> Take back a saved state; the buffer keeps at least its present size (`init`).
   subroutine restore_state(self, record, stat, errmsg, prefix)
      class(welch_estimator), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), intent(in), optional :: prefix
      integer(int64) :: counts(3)
      integer :: k, saved
      character(len=:), allocatable :: name
      name = 'spectrum'
      if (present(prefix)) name = prefix
      call record%get_int64s(name//'.counts', counts, stat, errmsg)
      if (stat /= 0) return
      k = record%find(name//'.buffer')
      if (k == 0) then
         stat = stat_failure
         errmsg = 'the checkpoint has no '''//name//'.buffer'''
         return
      end if
      saved = size(record%items(k)%reals)
      if (counts(1) > saved .or. saved > self%segment) then
         stat = stat_failure
         errmsg = 'the checkpoint''s spectrum state is inconsistent'
         return
      end if
      if (saved > size(self%buffer)) then
         deallocate (self%buffer)
         allocate (self%buffer(saved), source=0.0_dp)
         call size_power(self)
      end if
      self%filled = int(counts(1))
      self%samples = counts(2)
      self%segments = counts(3)
      self%buffer(1:self%filled) = record%items(k)%reals(1:self%filled)
      if (self%segments > 0) call record%get_reals(name//'.power', self%power, stat, errmsg)
   end subroutine restore_state
end module vibrobeam_welch
