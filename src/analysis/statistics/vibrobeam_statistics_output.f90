!> /statistics of a result file (docs/output.md, docs/statistics.md): created with the
!! other datasets (before the file enters SWMR mode), the Poincare samples streamed while
!! the run goes on, every other statistic written at the end.
!!
!! Layout: /statistics/<group>/<name> and <name>_error for every statistic of
!! `vibrobeam_statistics_layout` (a beam of two planes' points statistics: (1 + points, 2),
!! y then z, as h5py shows them); /statistics/points/x (the tip, then &output points),
!! /statistics/contacts/x, lower_obstacle, upper_obstacle (`statistics_points`, also the
!! sweep file's), /statistics/wear/x and obstacle (a beam of two planes' obstacles' points,
!! only when it has such points); /statistics/poincare/time,
!! displacement, velocity (samples x observation points). Attributes of /statistics:
!! measure_from, window_start, window_end (s), window_steps, batches, batch_steps;
!! poincare_load, poincare_frequency (rad/s) and poincare_frequency_hz (Hz),
!! poincare_phase (rad); /statistics/spectrum bin_width (Hz) and bin_width_rad_s (rad/s).
module vibrobeam_statistics_output
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_series, h5_array
   use vibrobeam_statistics_layout, only: statistics_layout
   use vibrobeam_statistics, only: statistics_result
   implicit none
   private
   public :: statistics_datasets, statistics_points

   type :: statistics_datasets
      logical :: created = .false.
      type(statistics_layout) :: layout
      type(h5_array), allocatable :: values(:), errors(:)   !! (entries)
      type(h5_series) :: poincare_time, poincare_u, poincare_v
   contains
      procedure :: create
      procedure :: append_poincare
      procedure :: write_buffers
      procedure :: rows
      procedure :: finish
   end type statistics_datasets

contains

   !> Create every dataset and attribute of /statistics (values written at `finish`).
   subroutine create(self, writer, layout, point_x, contact_x, lower_obstacle, upper_obstacle, wear_x, wear_obstacle, &
                     measure_from, forcing, omega, phase, stat, errmsg)
      class(statistics_datasets), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      type(statistics_layout), intent(in) :: layout
      real(dp), intent(in) :: point_x(:), contact_x(:), measure_from, omega, phase
      integer, intent(in) :: lower_obstacle(:), upper_obstacle(:)
      real(dp), intent(in), optional :: wear_x(:)          !! absent (or unallocated): a planar beam
      integer, intent(in), optional :: wear_obstacle(:)
      character(len=*), intent(in) :: forcing
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      self%layout = layout
      allocate (self%values(size(layout%entries)), self%errors(size(layout%entries)))
      call statistics_points(writer, '/statistics', point_x, contact_x, lower_obstacle, upper_obstacle, wear_x, &
                             wear_obstacle, stat, errmsg)
      do k = 1, size(layout%entries)
         if (stat /= 0) return
         associate (item => layout%entries(k))
            call self%values(k)%create(writer, '/statistics/'//layout%path(k, .false.), item%length, .false., &
                                       stat, errmsg, item%layers)
            if (stat == 0) call writer%attr_string('/statistics/'//layout%path(k, .false.), 'unit', trim(item%unit), &
                                                   stat, errmsg)
            if (stat /= 0 .or. .not. item%has_error) cycle
            call self%errors(k)%create(writer, '/statistics/'//layout%path(k, .true.), item%length, .false., &
                                       stat, errmsg, item%layers)
            if (stat == 0) call writer%attr_string('/statistics/'//layout%path(k, .true.), 'unit', trim(item%unit), &
                                                   stat, errmsg)
         end associate
      end do
      if (stat == 0) call self%poincare_time%create(writer, '/statistics/poincare/time', 1, 's', stat, errmsg)
      if (stat == 0) call self%poincare_u%create(writer, '/statistics/poincare/displacement', size(point_x), 'm', &
                                                 stat, errmsg, matrix=.true.)
      if (stat == 0) call self%poincare_v%create(writer, '/statistics/poincare/velocity', size(point_x), 'm/s', &
                                                 stat, errmsg, matrix=.true.)
      if (stat == 0) call writer%attr_real('/statistics', 'measure_from', measure_from, stat, errmsg)
      if (stat == 0) call writer%attr_real('/statistics', 'window_start', 0.0_dp, stat, errmsg)
      if (stat == 0) call writer%attr_real('/statistics', 'window_end', 0.0_dp, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/statistics', 'window_steps', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/statistics', 'batches', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/statistics', 'batch_steps', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_string('/statistics', 'poincare_load', forcing, stat, errmsg)
      if (stat == 0) call writer%attr_real('/statistics', 'poincare_frequency', omega, stat, errmsg)
      if (stat == 0) call writer%attr_real('/statistics', 'poincare_frequency_hz', omega/(2*pi), stat, errmsg)
      if (stat == 0) call writer%attr_real('/statistics', 'poincare_phase', phase, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/statistics/poincare', 'samples', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_real('/statistics/spectrum', 'bin_width', 0.0_dp, stat, errmsg)
      if (stat == 0) call writer%attr_real('/statistics/spectrum', 'bin_width_rad_s', 0.0_dp, stat, errmsg)
      self%created = stat == 0
   end subroutine create

   !> Where the statistics were taken, under `prefix` ('/statistics', '/sweep/statistics'):
   !! points/x (m), contacts/x (m), lower_obstacle and upper_obstacle, and, where a beam of
   !! two planes has obstacles' points (`wear_x` present, an unallocated actual argument
   !! is absent), wear/x (m) and wear/obstacle (each point's obstacle).
   subroutine statistics_points(writer, prefix, point_x, contact_x, lower_obstacle, upper_obstacle, wear_x, &
                                wear_obstacle, stat, errmsg)
      type(h5_writer), intent(inout) :: writer
      character(len=*), intent(in) :: prefix
      real(dp), intent(in) :: point_x(:), contact_x(:)
      integer, intent(in) :: lower_obstacle(:), upper_obstacle(:)
      real(dp), intent(in), optional :: wear_x(:)
      integer, intent(in), optional :: wear_obstacle(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call writer%write_real_1d(prefix//'/points/x', point_x, 'm', stat, errmsg)
      if (stat == 0) call writer%write_real_1d(prefix//'/contacts/x', contact_x, 'm', stat, errmsg)
      if (stat == 0) call writer%write_int_1d(prefix//'/contacts/lower_obstacle', lower_obstacle, stat=stat, errmsg=errmsg)
      if (stat == 0) call writer%write_int_1d(prefix//'/contacts/upper_obstacle', upper_obstacle, stat=stat, errmsg=errmsg)
      if (.not. (present(wear_x) .and. present(wear_obstacle))) return
      if (size(wear_x) == 0) return
      if (stat == 0) call writer%write_real_1d(prefix//'/wear/x', wear_x, 'm', stat, errmsg)
      if (stat == 0) call writer%write_int_1d(prefix//'/wear/obstacle', wear_obstacle, stat=stat, errmsg=errmsg)
   end subroutine statistics_points

   !> Stream Poincare samples: times(k), values(:, k) = u at each point, then v.
   subroutine append_poincare(self, times, values, stat, errmsg)
      class(statistics_datasets), intent(inout) :: self
      real(dp), intent(in) :: times(:), values(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k, points
      stat = 0
      errmsg = ''
      points = size(values, 1)/2
      do k = 1, size(times)
         call self%poincare_time%append(times(k:k), stat, errmsg)
         if (stat == 0) call self%poincare_u%append(values(1:points, k), stat, errmsg)
         if (stat == 0) call self%poincare_v%append(values(points + 1:, k), stat, errmsg)
         if (stat /= 0) return
      end do
   end subroutine append_poincare

   subroutine write_buffers(self, stat, errmsg)
      class(statistics_datasets), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.not. self%created) return
      call self%poincare_time%write(stat, errmsg)
      if (stat == 0) call self%poincare_u%write(stat, errmsg)
      if (stat == 0) call self%poincare_v%write(stat, errmsg)
   end subroutine write_buffers

   !> Poincare samples so far.
   integer(int64) function rows(self)
      class(statistics_datasets), intent(in) :: self
      rows = self%poincare_time%rows()
   end function rows

   !> Write the statistics of the window and close every dataset.
   subroutine finish(self, writer, outcome, stat, errmsg)
      class(statistics_datasets), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      type(statistics_result), intent(in) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k, first, last
      stat = 0
      errmsg = ''
      if (.not. self%created) return
      call self%write_buffers(stat, errmsg)
      do k = 1, size(self%layout%entries)
         if (stat /= 0) exit
         first = self%layout%entries(k)%offset + 1
         last = self%layout%entries(k)%offset + self%layout%entries(k)%length
         call self%values(k)%write_reals(outcome%values(first:last), stat, errmsg)
         if (stat == 0 .and. self%layout%entries(k)%has_error) &
            call self%errors(k)%write_reals(outcome%errors(first:last), stat, errmsg)
      end do
      if (stat == 0) call writer%rewrite_attr('/statistics', 'window_start', outcome%window_start, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/statistics', 'window_end', outcome%window_end, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/statistics', 'window_steps', outcome%steps, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/statistics', 'batches', int(outcome%batches, int64), stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/statistics', 'batch_steps', outcome%block_steps, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/statistics/poincare', 'samples', outcome%poincare_total, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/statistics/spectrum', 'bin_width', outcome%bin_width, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/statistics/spectrum', 'bin_width_rad_s', 2*pi*outcome%bin_width, stat, &
                                              errmsg)
      do k = 1, size(self%layout%entries)
         call self%values(k)%close()
         call self%errors(k)%close()
      end do
      call self%poincare_time%close()
      call self%poincare_u%close()
      call self%poincare_v%close()
      self%created = .false.
   end subroutine finish
end module vibrobeam_statistics_output
