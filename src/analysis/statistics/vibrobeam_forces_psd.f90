!> The spectra of a run's random loads (docs/output.md, "/forces"; docs/statistics.md,
!! "The measured density of a random load"): for each load of &forces with
!! signal = 'random', the target one-sided density S and the density of the signal the
!! run generated, measured by Welch's method with its 95 % confidence band, and what lets
!! a user regenerate the signal exactly.
!!
!! The samples are y_n (channel 1 of the load: its only channel, or the first point of a
!! coherent field), n = 1 .. N the run's steps (t_n = n dt), taken from the signal's own
!! block (`random_signal%sample`: the bits the steppers use). They feed a streaming Welch
!! estimate (`vibrobeam_welch`) whose segments are n_s samples overlapping by half,
!! periodic Hann window: n_s = L/8, L the filter's taps (the filter resolves the
!! narrowest feature of S with 8 of its bins 1/(L dt): the estimate with one), at least
!! 256 (`segment_samples`). Memory is one segment per load, whatever the run's length. A
!! run of fewer than n_s samples is transformed whole. The measured density of bin k (f_k = k/(n_s dt), n_s the segment's
!! samples) is, from Welch's amplitudes a_k (`welch_density`),
!!
!!     P_k = a_k^2 n_s dt / 3   (0 < f_k < Nyquist),   P_k = 2 a_k^2 n_s dt / 3   (f = 0, Nyquist),
!!
!! (the periodic Hann window: sum w = n_s/2, sum w^2 = 3 n_s/8, P = 2 |X|^2 dt/sum w^2).
!! Its equivalent degrees of freedom are nu = 2 K^2/(K + 2 (K - 1) c^2) for K segments,
!! c = 1/6 the correlation of two Hann segments overlapping by half (Welch 1967, eq. 11;
!! `welch_degrees_of_freedom`), nu = 2 for one record, half of it at 0 and at the Nyquist
!! frequency; the 95 % band is [nu P/chi2_nu(0.975), nu P/chi2_nu(0.025)]
!! (`chi_square_quantile`). The bins are written up to twice the highest frequency of S
!! (at most the Nyquist frequency), where the measured density must be small.
!!
!! The recipe of the signal (attributes seed, realisation, stream, taps, sample_step,
!! noise_origin and the dataset filter_taps) and, for a run of at most
!! `signal_samples_max` steps, the samples themselves (/forces/load_<i>/signal).
!! The estimators' state and the samples kept go into the checkpoint
!! ('forces_psd.load<i>.*').
module vibrobeam_forces_psd
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: integer_text
   use vibrobeam_state_record, only: state_record
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_series
   use vibrobeam_welch, only: welch_estimator
   use vibrobeam_quantiles, only: chi_square_quantile
   use vibrobeam_schema_visitor, only: unset_integer
   use vibrobeam_force_settings, only: forces_settings
   use vibrobeam_forces, only: force_set
   use vibrobeam_random_signal, only: random_signal
   implicit none
   private
   public :: forces_psd, welch_degrees_of_freedom, welch_density, signal_samples_max, &
             psd_confidence, psd_reach

   !> a run of at most this many steps keeps the samples of its random loads (/forces/load_<i>/signal)
   integer(int64), parameter :: signal_samples_max = 2_int64**16
   real(dp), parameter :: psd_confidence = 0.95_dp   !! of the band psd_lower .. psd_upper
   real(dp), parameter :: psd_reach = 2              !! bins up to psd_reach times the highest frequency of S
   integer, parameter :: least_segment_samples = 2**8   !! the shortest Welch segment

   !> One random load's estimator and datasets.
   type :: load_psd
      integer :: load = 0                         !! its number in &forces
      type(random_signal) :: signal               !! a copy of the load's channel 1 (its own block)
      type(welch_estimator) :: welch
      real(dp), allocatable :: samples(:)         !! (N) y_1 .. y_N when N <= signal_samples_max, else (0)
      real(dp), allocatable :: values(:)          !! (channels) work space
      character(len=:), allocatable :: kind, unit
      integer(int64) :: seed = 0, realisation = 1
      type(h5_series) :: frequency, target, measured, lower, upper, record
   end type load_psd

   type :: forces_psd
      type(load_psd), allocatable :: loads(:)     !! (random loads)
   contains
      procedure :: init
      procedure :: add
      procedure :: create
      procedure :: finish
      procedure :: close
      procedure :: save_state
      procedure :: restore_state
   end type forces_psd

contains

   !> The random loads of `forces` (built from `settings`), in a run of `last_step` steps.
   subroutine init(self, settings, forces, last_step)
      class(forces_psd), intent(inout) :: self
      type(forces_settings), intent(in) :: settings
      type(force_set), intent(in) :: forces
      integer(int64), intent(in) :: last_step
      integer :: i, r
      r = 0
      if (allocated(self%loads)) deallocate (self%loads)
      allocate (self%loads(count(settings%load(1:forces%count)%signal == 'random')))
      do i = 1, forces%count
         if (settings%load(i)%signal /= 'random') cycle
         r = r + 1
         associate (l => self%loads(r))
            l%load = i
            ! channel 1 alone: a coherent field's other points would cost their blocks again
            l%signal = forces%random_of(i)
            l%signal = l%signal%first_channel()
            allocate (l%values(l%signal%channels))
            call l%welch%init(l%signal%step, last_step, segment_samples(l%signal%taps))
            allocate (l%samples(merge(last_step, 0_int64, last_step <= signal_samples_max)), source=0.0_dp)
            l%kind = trim(settings%load(i)%kind)
            select case (l%kind)
            case ('distributed')
               l%unit = 'N/m'
            case ('base')
               l%unit = 'm/s^2'
            case default
               l%unit = 'N'
            end select
            l%seed = i
            if (settings%load(i)%seed /= unset_integer) l%seed = settings%load(i)%seed
            l%realisation = int(settings%realisation, int64)
         end associate
      end do
   end subroutine init

   !> The samples of a Welch segment for a filter of `taps` taps: taps/8, one bin per
   !! narrowest feature of S (the filter resolves it with 8), at least
   !! `least_segment_samples`. It does not depend on the run's length, so a continued run
   !! goes on with the segments of the run it continues.
   pure integer function segment_samples(taps)
      integer, intent(in) :: taps
      segment_samples = max(least_segment_samples, taps/8)
   end function segment_samples

   !> Sample `step` (t = step dt) of every random load into its estimator.
   subroutine add(self, step, stat, errmsg)
      class(forces_psd), intent(inout) :: self
      integer(int64), intent(in) :: step
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: r
      stat = 0
      errmsg = ''
      do r = 1, size(self%loads)
         associate (l => self%loads(r))
            call l%signal%sample(step, l%values)
            call l%welch%add(l%values(1), stat, errmsg)
            if (stat /= 0) return
            if (step >= 1 .and. step <= size(l%samples)) l%samples(step) = l%values(1)
         end associate
      end do
   end subroutine add

   !> /forces/load_<i>: the recipe's attributes and the filter's taps, the spectra's
   !! datasets empty (before SWMR mode; written by `finish`).
   subroutine create(self, writer, stat, errmsg)
      class(forces_psd), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: group, density_unit
      integer :: r
      stat = 0
      errmsg = ''
      do r = 1, size(self%loads)
         associate (l => self%loads(r), s => self%loads(r)%signal)
            group = '/forces/load_'//integer_text(l%load)
            density_unit = l%unit//'^2/Hz'
            if (index(l%unit, '/') > 0) density_unit = '('//l%unit//')^2/Hz'
            call writer%attr_string(group, 'kind', l%kind, stat, errmsg)
            if (stat == 0) call writer%attr_string(group, 'unit', l%unit, stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'seed', l%seed, stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'realisation', l%realisation, stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'stream', s%stream(1), stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'taps', int(s%taps, int64), stat, errmsg)
            if (stat == 0) call writer%attr_real(group, 'sample_step', s%step, stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'first_sample', 1_int64, stat, errmsg)
            if (stat == 0) call writer%attr_real(group, 'rms_target', s%target_rms, stat, errmsg)
            if (stat == 0) call writer%attr_real(group, 'rms_filter', s%rms, stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'segment_samples', int(l%welch%segment, int64), stat, errmsg)
            if (stat == 0) call writer%attr_string(group, 'window', 'hann', stat, errmsg)
            if (stat == 0) call writer%attr_real(group, 'confidence', psd_confidence, stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'samples', 0_int64, stat, errmsg)
            if (stat == 0) call writer%attr_int64(group, 'segments', 0_int64, stat, errmsg)
            if (stat == 0) call writer%attr_real(group, 'degrees_of_freedom', 0.0_dp, stat, errmsg)
            if (stat == 0) call writer%attr_real(group, 'bin_width', 0.0_dp, stat, errmsg)
            if (stat == 0) call writer%write_real_1d(group//'/filter_taps', s%taps_values, '1', stat, errmsg)
            if (stat == 0) call l%frequency%create(writer, group//'/frequency', 1, 'Hz', stat, errmsg)
            if (stat == 0) call l%target%create(writer, group//'/psd_target', 1, density_unit, stat, errmsg)
            if (stat == 0) call l%measured%create(writer, group//'/psd_measured', 1, density_unit, stat, errmsg)
            if (stat == 0) call l%lower%create(writer, group//'/psd_lower', 1, density_unit, stat, errmsg)
            if (stat == 0) call l%upper%create(writer, group//'/psd_upper', 1, density_unit, stat, errmsg)
            if (stat == 0 .and. size(l%samples) > 0) &
               call l%record%create(writer, group//'/signal', 1, l%unit, stat, errmsg)
         end associate
         if (stat /= 0) return
      end do
   end subroutine create

   !> The spectra of every sample added, and the samples kept, into the datasets of `create`.
   subroutine finish(self, writer, stat, errmsg)
      class(forces_psd), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: frequency(:), amplitude(:)
      real(dp) :: width, nu, nu_k, density
      integer(int64) :: segments, n, k
      character(len=:), allocatable :: group
      integer :: r
      stat = 0
      errmsg = ''
      do r = 1, size(self%loads)
         associate (l => self%loads(r))
            group = '/forces/load_'//integer_text(l%load)
            call l%welch%spectrum(frequency, amplitude, segments, width, stat, errmsg)
            if (stat /= 0) then
               errmsg = 'spectrum of random load '//integer_text(l%load)//': '//trim(errmsg)
               return
            end if
            nu = welch_degrees_of_freedom(segments)
            if (stat == 0) call writer%rewrite_attr(group, 'samples', l%welch%samples, stat, errmsg)
            if (stat == 0) call writer%rewrite_attr(group, 'segments', segments, stat, errmsg)
            if (stat == 0) call writer%rewrite_attr(group, 'degrees_of_freedom', nu, stat, errmsg)
            if (stat == 0) call writer%rewrite_attr(group, 'bin_width', width, stat, errmsg)
            if (stat /= 0) return
            n = 0
            if (width > 0) n = nint(1/(width*l%signal%step), int64)
            do k = 0, size(frequency, kind=int64) - 1
               if (frequency(k + 1) > psd_reach*l%signal%highest) exit
               ! the bins at 0 and at the Nyquist frequency have half the degrees of freedom
               nu_k = nu
               if (k == 0 .or. 2*k == n) nu_k = nu/2
               density = welch_density(amplitude(k + 1), width, k == 0 .or. 2*k == n)
               call l%frequency%append(frequency(k + 1:k + 1), stat, errmsg)
               if (stat == 0) call l%target%append([l%signal%density%at(frequency(k + 1))], stat, errmsg)
               if (stat == 0) call l%measured%append([density], stat, errmsg)
               if (stat == 0) call l%lower%append([nu_k*density/chi_square_quantile(nu_k, (1 + psd_confidence)/2)], &
                                                  stat, errmsg)
               if (stat == 0) call l%upper%append([nu_k*density/chi_square_quantile(nu_k, (1 - psd_confidence)/2)], &
                                                  stat, errmsg)
               if (stat /= 0) return
            end do
            do k = 1, min(size(l%samples, kind=int64), l%welch%samples)
               call l%record%append(l%samples(k:k), stat, errmsg)
               if (stat /= 0) return
            end do
            call l%frequency%write(stat, errmsg)
            if (stat == 0) call l%target%write(stat, errmsg)
            if (stat == 0) call l%measured%write(stat, errmsg)
            if (stat == 0) call l%lower%write(stat, errmsg)
            if (stat == 0) call l%upper%write(stat, errmsg)
            if (stat == 0 .and. size(l%samples) > 0) call l%record%write(stat, errmsg)
         end associate
         if (stat /= 0) return
      end do
   end subroutine finish

   subroutine close(self)
      class(forces_psd), intent(inout) :: self
      integer :: r
      do r = 1, size(self%loads)
         call self%loads(r)%frequency%close()
         call self%loads(r)%target%close()
         call self%loads(r)%measured%close()
         call self%loads(r)%lower%close()
         call self%loads(r)%upper%close()
         call self%loads(r)%record%close()
      end do
   end subroutine close

   !> Everything a continued run needs (module documentation).
   subroutine save_state(self, record)
      class(forces_psd), intent(in) :: self
      type(state_record), intent(inout) :: record
      integer :: r
      do r = 1, size(self%loads)
         associate (l => self%loads(r), name => 'forces_psd.load'//integer_text(self%loads(r)%load))
            call l%welch%save_state(record, name)
            call record%put_reals(name//'.signal', l%samples)
         end associate
      end do
   end subroutine save_state

   !> Take back what `save_state` put into `record`.
   subroutine restore_state(self, record, stat, errmsg)
      class(forces_psd), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: r, k
      stat = 0
      errmsg = ''
      do r = 1, size(self%loads)
         associate (l => self%loads(r), name => 'forces_psd.load'//integer_text(self%loads(r)%load))
            call l%welch%restore_state(record, stat, errmsg, name)
            if (stat /= 0) return
            k = record%find(name//'.signal')
            if (k == 0) then
               stat = stat_failure
               errmsg = 'the checkpoint has no '''//name//'.signal'''
               return
            end if
            call restore_samples(l, record%items(k)%reals)
         end associate
         if (stat /= 0) return
      end do
   end subroutine restore_state

   !> The samples a checkpoint kept (`saved`): none when it kept none after some steps (a
   !! run of more than `signal_samples_max` steps), else those that fit.
   subroutine restore_samples(l, saved)
      type(load_psd), intent(inout) :: l
      real(dp), intent(in) :: saved(:)
      integer :: n
      if (size(saved) == 0 .and. l%welch%samples > 0) then
         deallocate (l%samples)
         allocate (l%samples(0))
      else
         n = min(size(saved), size(l%samples))
         l%samples(1:n) = saved(1:n)
      end if
   end subroutine restore_samples

   !> The one-sided density (unit^2/Hz) of a bin whose Welch amplitude (periodic Hann
   !! window) is `amplitude`, with bin width `width` (Hz): a^2/(3 width), twice that at
   !! 0 and at the Nyquist frequency (`at_end`; module documentation).
   elemental real(dp) function welch_density(amplitude, width, at_end)
      real(dp), intent(in) :: amplitude, width
      logical, intent(in) :: at_end
      welch_density = amplitude**2/(3*width)
      if (at_end) welch_density = 2*welch_density
   end function welch_density

   !> The equivalent degrees of freedom of a Welch estimate over `segments` periodic Hann
   !! segments overlapping by half, 2 K^2/(K + 2 (K - 1)/36) (Welch 1967, eq. 11, with the
   !! segments' correlation c = 1/6); 2 for one record transformed whole (segments = 0).
   elemental real(dp) function welch_degrees_of_freedom(segments) result(nu)
      integer(int64), intent(in) :: segments
      real(dp) :: k
      k = real(max(segments, 1_int64), dp)
      nu = 2*k**2/(k + 2*(k - 1)/36)
   end function welch_degrees_of_freedom

end module vibrobeam_forces_psd
