!> The amplitude spectra of a run's /spectrum (docs/output.md): the displacement at the tip
!! and at each observation point (&output points), sampled at the output times that are
!! multiples of `every`, each a streaming Welch estimate (`vibrobeam_welch`), so memory
!! does not grow with the run (one segment, 2^16 samples, per signal).
!!
!! /spectrum/frequency (Hz) and /spectrum/frequency_rad_s (rad/s, the same bins times
!! 2 pi), /spectrum/tip_amplitude (m), and with observation points
!! /spectrum/point_amplitude (bins x points, m, in the order of /points/x); a beam of two
!! planes has the spectra of the displacement in y and in z: tip_amplitude (bins, 2),
!! point_amplitude (bins, points, 2), y then z, each plane's own estimate; attributes
!! sampling_interval (s), bin_width (Hz), bin_width_rad_s (rad/s), segments (0: one
!! record), samples, point_samples (samples of the points' spectra), window. Everything is
!! created empty with the run's other datasets (before SWMR mode) and written at the end.
!!
!! The estimators' state goes into the checkpoint: the tip's under 'spectrum.*' (the names
!! of version 0.2.0), each point's under 'spectrum.point<k>.*' with the points' positions
!! 'spectrum.point_x'. A run continued from a checkpoint without them (an earlier version,
!! or other &output points) cannot give the points' spectra of the whole run: it leaves
!! /spectrum/point_amplitude empty (point_samples = 0). The z plane's estimators are
!! 'spectrum.tip_z.*' and 'spectrum.point<k>_z.*'.
module vibrobeam_run_spectra
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text, only: integer_text
   use vibrobeam_state_record, only: state_record
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_series
   use vibrobeam_welch, only: welch_estimator
   implicit none
   private
   public :: run_spectra

   type :: run_spectra
      type(welch_estimator) :: tip
      type(welch_estimator), allocatable :: points(:)   !! one per observation point
      integer :: planes = 1
      !> a beam of two planes: the tip's (1) and the points' estimators in z (none when planar)
      type(welch_estimator), allocatable :: tip_z(:), points_z(:)
      real(dp), allocatable :: point_x(:)               !! their positions (m)
      logical :: points_whole = .true.                  !! the points' estimators hold the whole run
      type(h5_series) :: frequency, frequency_rad_s, tip_amplitude, point_amplitude
   contains
      procedure :: init
      procedure :: create
      procedure :: add
      procedure :: finish
      procedure :: close
      procedure :: save_state
      procedure :: restore_state
   end type run_spectra

contains

   !> Spectra of signals sampled every `dt` seconds, at most `expected` samples in the run,
   !! at the tip and at the observation points `point_x` (m), in `planes` bending planes.
   subroutine init(self, dt, expected, point_x, planes)
      class(run_spectra), intent(inout) :: self
      real(dp), intent(in) :: dt, point_x(:)
      integer(int64), intent(in) :: expected
      integer, intent(in) :: planes
      integer :: p
      call self%tip%init(dt, expected)
      self%point_x = point_x
      self%planes = planes
      if (allocated(self%points)) deallocate (self%points, self%tip_z, self%points_z)
      allocate (self%points(size(point_x)), self%tip_z(planes - 1), self%points_z((planes - 1)*size(point_x)))
      do p = 1, size(point_x)
         call self%points(p)%init(dt, expected)
      end do
      do p = 1, size(self%points_z)
         call self%points_z(p)%init(dt, expected)
      end do
      if (planes == 2) call self%tip_z(1)%init(dt, expected)
      self%points_whole = .true.
   end subroutine init

   !> The attributes of /spectrum and its datasets, empty.
   subroutine create(self, writer, stat, errmsg)
      class(run_spectra), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call writer%attr_real('/spectrum', 'sampling_interval', self%tip%dt, stat, errmsg)
      if (stat == 0) call writer%attr_real('/spectrum', 'bin_width', 0.0_dp, stat, errmsg)
      if (stat == 0) call writer%attr_real('/spectrum', 'bin_width_rad_s', 0.0_dp, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/spectrum', 'segments', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/spectrum', 'samples', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/spectrum', 'point_samples', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_string('/spectrum', 'window', 'hann', stat, errmsg)
      if (stat == 0) call self%frequency%create(writer, '/spectrum/frequency', 1, 'Hz', stat, errmsg)
      if (stat == 0) call self%frequency_rad_s%create(writer, '/spectrum/frequency_rad_s', 1, 'rad/s', stat, errmsg)
      if (stat == 0) call self%tip_amplitude%create(writer, '/spectrum/tip_amplitude', self%planes, 'm', stat, errmsg, &
                                                    matrix=self%planes > 1)
      if (stat == 0 .and. size(self%points) > 0) &
         call self%point_amplitude%create(writer, '/spectrum/point_amplitude', self%planes*size(self%points), 'm', &
                                          stat, errmsg, matrix=.true., layers=self%planes)
   end subroutine create

   !> One sample: the tip's displacement and the observation points' (m); with two planes
   !! `z` the tip's and then the points' in z.
   subroutine add(self, tip, points, stat, errmsg, z)
      class(run_spectra), intent(inout) :: self
      real(dp), intent(in) :: tip, points(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), intent(in) :: z(:)
      integer :: p
      call self%tip%add(tip, stat, errmsg)
      do p = 1, size(self%points)
         if (stat /= 0) return
         call self%points(p)%add(points(p), stat, errmsg)
      end do
      if (stat /= 0 .or. self%planes == 1) return
      call self%tip_z(1)%add(z(1), stat, errmsg)
      do p = 1, size(self%points_z)
         if (stat /= 0) return
         call self%points_z(p)%add(z(1 + p), stat, errmsg)
      end do
   end subroutine add

   !> The spectra of every sample added, into the datasets of `create`.
   subroutine finish(self, writer, stat, errmsg)
      class(run_spectra), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: frequency(:), amplitude(:), tip(:, :), amplitudes(:, :, :)
      integer(int64) :: segments
      real(dp) :: width
      logical :: whole
      integer :: k
      call self%tip%spectrum(frequency, amplitude, segments, width, stat, errmsg)
      if (stat /= 0) then
         errmsg = 'tip spectrum: '//trim(errmsg)
         return
      end if
      ! (plane, bins) at the tip, (plane, point, bins) at the points: a row is y, z side by side
      allocate (tip(self%planes, size(frequency)), amplitudes(self%planes, size(self%points), size(frequency)), &
                source=0.0_dp)
      tip(1, :) = amplitude
      if (self%planes == 2) call plane_amplitudes(self%tip_z, 'the tip (z)', tip(2:2, :), whole)
      if (stat /= 0) return
      if (self%points_whole) call plane_amplitudes(self%points, 'observation point', amplitudes(1, :, :), self%points_whole)
      if (stat == 0 .and. self%points_whole .and. self%planes == 2) &
         call plane_amplitudes(self%points_z, 'observation point (z)', amplitudes(2, :, :), self%points_whole)
      if (stat /= 0) return
      call writer%rewrite_attr('/spectrum', 'bin_width', width, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/spectrum', 'bin_width_rad_s', 2*pi*width, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/spectrum', 'segments', segments, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/spectrum', 'samples', self%tip%samples, stat, errmsg)
      if (stat == 0 .and. size(self%points) > 0 .and. self%points_whole) &
         call writer%rewrite_attr('/spectrum', 'point_samples', self%points(1)%samples, stat, errmsg)
      if (stat /= 0) return
      ! (SWMR: the datasets were created empty with the others)
      do k = 1, size(frequency)
         call self%frequency%append(frequency(k:k), stat, errmsg)
         if (stat == 0) call self%frequency_rad_s%append([2*pi*frequency(k)], stat, errmsg)
         if (stat == 0) call self%tip_amplitude%append(tip(:, k), stat, errmsg)
         if (stat == 0 .and. size(self%points) > 0 .and. self%points_whole) &
            call self%point_amplitude%append(reshape(amplitudes(:, :, k), [size(amplitudes(:, :, k))]), stat, errmsg)
         if (stat /= 0) return
      end do
      call self%frequency%write(stat, errmsg)
      if (stat == 0) call self%frequency_rad_s%write(stat, errmsg)
      if (stat == 0) call self%tip_amplitude%write(stat, errmsg)
      if (stat == 0 .and. size(self%points) > 0) call self%point_amplitude%write(stat, errmsg)
   contains
      !> The amplitude spectrum of each estimator into values(estimator, bins); `whole`
      !! false (values left 0) when one has other bins than the tip's (a continued run whose
      !! checkpoint lacked it).
      subroutine plane_amplitudes(estimators, what, values, whole)
         type(welch_estimator), intent(inout) :: estimators(:)
         character(len=*), intent(in) :: what
         real(dp), intent(inout) :: values(:, :)
         logical, intent(out) :: whole
         real(dp), allocatable :: estimate_frequency(:), estimate(:)
         integer(int64) :: estimate_segments
         real(dp) :: estimate_width
         integer :: p
         whole = .true.
         do p = 1, size(estimators)
            call estimators(p)%spectrum(estimate_frequency, estimate, estimate_segments, estimate_width, stat, errmsg)
            if (stat /= 0) then
               errmsg = 'spectrum at '//what//' '//integer_text(p)//': '//trim(errmsg)
               return
            end if
            ! the same samples as the tip's, so the same bins
            whole = size(estimate) == size(frequency)
            if (.not. whole) return
            values(p, :) = estimate
         end do
      end subroutine plane_amplitudes
   end subroutine finish

   subroutine close(self)
      class(run_spectra), intent(inout) :: self
      call self%frequency%close()
      call self%frequency_rad_s%close()
      call self%tip_amplitude%close()
      call self%point_amplitude%close()
   end subroutine close

   !> Everything a continued run needs (module documentation).
   subroutine save_state(self, record)
      class(run_spectra), intent(in) :: self
      type(state_record), intent(inout) :: record
      integer :: p
      call self%tip%save_state(record)
      call record%put_reals('spectrum.point_x', self%point_x)
      do p = 1, size(self%points)
         call self%points(p)%save_state(record, 'spectrum.point'//integer_text(p))
      end do
      if (self%planes == 1) return
      call self%tip_z(1)%save_state(record, 'spectrum.tip_z')
      do p = 1, size(self%points_z)
         call self%points_z(p)%save_state(record, 'spectrum.point'//integer_text(p)//'_z')
      end do
   end subroutine save_state

   !> Take back what `save_state` put into `record`; the points' spectra only when the
   !! checkpoint holds them for the same points (module documentation).
   subroutine restore_state(self, record, stat, errmsg)
      class(run_spectra), intent(inout) :: self
      type(state_record), intent(in) :: record
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: saved_x(:)
      integer :: p, k
      call self%tip%restore_state(record, stat, errmsg)
      if (stat == 0 .and. self%planes == 2) call self%tip_z(1)%restore_state(record, stat, errmsg, 'spectrum.tip_z')
      if (stat /= 0 .or. size(self%points) == 0) return
      k = record%find('spectrum.point_x')
      self%points_whole = k > 0
      if (.not. self%points_whole) return
      allocate (saved_x, source=record%items(k)%reals)
      self%points_whole = size(saved_x) == size(self%point_x)
      if (self%points_whole) self%points_whole = all(abs(saved_x - self%point_x) <= 0)
      if (.not. self%points_whole) return
      do p = 1, size(self%points)
         call self%points(p)%restore_state(record, stat, errmsg, 'spectrum.point'//integer_text(p))
         if (stat /= 0) return
      end do
      do p = 1, size(self%points_z)
         call self%points_z(p)%restore_state(record, stat, errmsg, 'spectrum.point'//integer_text(p)//'_z')
         if (stat /= 0) return
      end do
   end subroutine restore_state
end module vibrobeam_run_spectra
