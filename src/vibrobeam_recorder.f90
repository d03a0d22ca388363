!> Histories of a dynamics run and their output (INTERFACE.md "Output", SPEC §5).
!!
!! Recorded at every output time (t = 0, every `every` steps, and the last step): time,
!! tip displacement, velocity and mean contact force at the tip over the output interval,
!! energies, largest penetration, and the displacement field. Recorded at every step: new
!! impacts (a contact point approaching its obstacle that receives an impulse after a step
!! without one; an impulse on a point already moving away holds it, it is not an impact),
!! the time each contact point spends in contact, and the largest penetration of the run.
module vibrobeam_recorder
   use vibrobeam_kinds, only: dp
   use vibrobeam_model, only: beam_model, nodal_displacement
   use vibrobeam_contact_points, only: contact_value
   use vibrobeam_stepper, only: time_stepper
   use vibrobeam_results, only: result_files
   use vibrobeam_spectrum, only: amplitude_spectrum, bin_width
   implicit none
   private
   public :: dynamics_recorder

   type :: growing_table
      integer :: rows = 0
      real(dp), allocatable :: values(:,:)   !! (columns, capacity)
   end type growing_table

   type :: dynamics_recorder
      integer :: tip_contact = 0                    !! contact point at the tip, 0 if none
      real(dp) :: tip_impulse = 0                   !! tip impulse since the last output (N s)
      real(dp) :: last_output_time = 0
      real(dp) :: max_penetration = 0               !! over every step (m)
      real(dp) :: max_penetration_time = 0
      integer :: iterations_total = 0, iterations_max = 0
      type(growing_table) :: series                 !! one row per output time
      type(growing_table) :: field                  !! (N+1) per output time
      type(growing_table) :: impacts                !! time, x, impulse, v before, v after
      logical, allocatable :: in_contact(:)         !! contact point had an impulse last step
      real(dp), allocatable :: contact_time(:)      !! time spent in contact per point (s)
   contains
      procedure :: init => recorder_init
      procedure :: after_step
      procedure :: sample
      procedure :: write => recorder_write
   end type dynamics_recorder

   integer, parameter :: series_columns = 12
   ! columns of `series`
   integer, parameter :: c_time = 1, c_tip_u = 2, c_tip_v = 3, c_tip_force = 4, c_kinetic = 5, &
                         c_elastic = 6, c_work = 7, c_dissipated = 8, c_impacts = 9, c_damping = 10, &
                         c_total = 11, c_penetration = 12

contains

   subroutine append(table, row)
      type(growing_table), intent(inout) :: table
      real(dp), intent(in) :: row(:)
      real(dp), allocatable :: bigger(:,:)
      if (.not. allocated(table%values)) allocate (table%values(size(row), 64))
      if (table%rows == size(table%values, 2)) then
         allocate (bigger(size(row), 2*table%rows))
         bigger(:, 1:table%rows) = table%values(:, 1:table%rows)
         call move_alloc(bigger, table%values)
      end if
      table%rows = table%rows + 1
      table%values(:, table%rows) = row
   end subroutine append

   subroutine recorder_init(self, stepper, model)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(beam_model), intent(in) :: model
      integer :: c
      allocate (self%in_contact(stepper%contacts%count), source=.false.)
      allocate (self%contact_time(stepper%contacts%count), source=0.0_dp)
      self%tip_contact = 0
      do c = 1, stepper%contacts%count
         if (stepper%contacts%node(c) == model%elements) self%tip_contact = c
      end do
      self%max_penetration = penetration(stepper)
   end subroutine recorder_init

   !> Largest penetration of the current positions into an obstacle (m, >= 0).
   pure function penetration(stepper) result(depth)
      class(time_stepper), intent(in) :: stepper
      real(dp) :: depth, u
      integer :: c
      depth = 0
      do c = 1, stepper%contacts%count
         u = contact_value(stepper%contacts, c, stepper%u)
         depth = max(depth, stepper%contacts%lower(c) - u, u - stepper%contacts%upper(c))
      end do
   end function penetration

   !> Bookkeeping after every step: impacts, contact time, penetration, iterations.
   subroutine after_step(self, stepper)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      logical :: now(size(self%in_contact))
      real(dp) :: depth
      integer :: k, c
      now = .false.
      do k = 1, stepper%active_count
         c = stepper%active(k)
         if (abs(stepper%impulse(k)) <= 0) cycle
         now(c) = .true.
         if (.not. self%in_contact(c) .and. stepper%approaching(k)) call append(self%impacts, &
                                                   [stepper%impulse_time, stepper%contacts%x(c), &
                                                   stepper%impulse(k), stepper%velocity_before(k), stepper%velocity_after(k)])
         if (c == self%tip_contact) self%tip_impulse = self%tip_impulse + stepper%impulse(k)
      end do
      where (now) self%contact_time = self%contact_time + stepper%dt
      self%in_contact = now
      depth = penetration(stepper)
      if (depth > self%max_penetration) then
         self%max_penetration = depth
         self%max_penetration_time = stepper%t
      end if
      self%iterations_total = self%iterations_total + stepper%iterations
      self%iterations_max = max(self%iterations_max, stepper%iterations)
   end subroutine after_step

   !> Record the state at an output time.
   subroutine sample(self, stepper, model)
      class(dynamics_recorder), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(beam_model), intent(in) :: model
      real(dp) :: row(series_columns), nodes(model%elements + 1), nodal_velocity(model%elements + 1)
      real(dp) :: interval
      nodes = nodal_displacement(model, stepper%u)
      nodal_velocity = nodal_displacement(model, stepper%v)
      interval = stepper%t - self%last_output_time
      row(c_time) = stepper%t
      row(c_tip_u) = nodes(model%elements + 1)
      row(c_tip_v) = nodal_velocity(model%elements + 1)
      row(c_tip_force) = 0
      if (interval > 0) row(c_tip_force) = self%tip_impulse/interval
      row(c_kinetic) = stepper%kinetic_energy()
      row(c_elastic) = stepper%elastic_energy()
      row(c_work) = stepper%work
      row(c_impacts) = stepper%dissipated_impacts
      row(c_damping) = stepper%dissipated_damping
      row(c_dissipated) = stepper%dissipated_impacts + stepper%dissipated_damping
      row(c_total) = row(c_kinetic) + row(c_elastic)
      row(c_penetration) = penetration(stepper)
      call append(self%series, row)
      call append(self%field, nodes)
      self%tip_impulse = 0
      self%last_output_time = stepper%t
   end subroutine sample

   !> Write every history into the result files (HDF5 datasets and .dat files).
   subroutine recorder_write(self, files, model, stepper, stat, errmsg)
      class(dynamics_recorder), intent(in) :: self
      type(result_files), intent(inout) :: files
      type(beam_model), intent(in) :: model
      class(time_stepper), intent(in) :: stepper
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: n, unit, i, k
      real(dp), allocatable :: s(:,:), impacts(:,:)
      real(dp), allocatable :: frequency(:), tip_amplitude(:)
      integer :: uniform, spectrum_stat
      real(dp) :: interval
      character(len=256) :: spectrum_message
      n = self%series%rows
      allocate (s, source=self%series%values(:, 1:n))
      allocate (impacts(5, self%impacts%rows))
      if (self%impacts%rows > 0) impacts(:, :) = self%impacts%values(:, 1:self%impacts%rows)
      call files%h5%write_real_1d('/time', s(c_time, :), 's', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/tip/displacement', s(c_tip_u, :), 'm', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/tip/velocity', s(c_tip_v, :), 'm/s', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/tip/reaction', s(c_tip_force, :), 'N', stat, errmsg)
      if (stat == 0) call files%h5%write_real_2d('/field/displacement', self%field%values(:, 1:n), 'm', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/kinetic', s(c_kinetic, :), 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/elastic', s(c_elastic, :), 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/work', s(c_work, :), 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/dissipated', s(c_dissipated, :), 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/dissipated_impacts', s(c_impacts, :), 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/dissipated_damping', s(c_damping, :), 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/total', s(c_total, :), 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/energy/balance', s(c_total, :) - s(c_work, :) + s(c_dissipated, :), &
                                                 'J', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/impacts/time', impacts(1, :), 's', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/impacts/x', impacts(2, :), 'm', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/impacts/impulse', impacts(3, :), 'N s', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/impacts/velocity_before', impacts(4, :), 'm/s', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/impacts/velocity_after', impacts(5, :), 'm/s', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/contact/penetration', s(c_penetration, :), 'm', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/contact/x', stepper%contacts%x, 'm', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/contact/fraction', self%contact_time/max(stepper%t, tiny(1.0_dp)), &
                                                 '1', stat, errmsg)
      if (stat == 0) call files%h5%attr_real('/contact', 'max_penetration', self%max_penetration, stat, errmsg)
      if (stat == 0) call files%h5%attr_real('/contact', 'max_penetration_time', self%max_penetration_time, stat, errmsg)
      if (stat /= 0) return
      ! Spectrum of the tip displacement (SPEC §5) over the uniformly spaced output times
      ! t = 0, every*dt, ...: the last row (end of run / last good state) is dropped when its
      ! interval differs from the others. Fewer than 2 samples: an empty spectrum.
      uniform = n
      interval = 0
      if (n >= 2) interval = s(c_time, 2) - s(c_time, 1)
      if (n >= 3) then
         if (abs((s(c_time, n) - s(c_time, n - 1)) - interval) > 1e-9_dp*interval) uniform = n - 1
      end if
      call amplitude_spectrum(s(c_tip_u, 1:uniform), interval, frequency, tip_amplitude, spectrum_stat, &
                              spectrum_message, window='hann')
      call files%h5%write_real_1d('/spectrum/frequency', frequency, 'Hz', stat, errmsg)
      if (stat == 0) call files%h5%write_real_1d('/spectrum/tip_amplitude', tip_amplitude, 'm', stat, errmsg)
      if (stat == 0 .and. uniform >= 2) &
         call files%h5%attr_real('/spectrum', 'bin_width', bin_width(uniform, interval), stat, errmsg)
      if (stat == 0) call files%h5%attr_real('/spectrum', 'sampling_interval', interval, stat, errmsg)
      if (stat == 0) call files%h5%attr_string('/spectrum', 'window', 'hann', stat, errmsg)
      if (stat /= 0) return
      call files%open_text('spectrum', 'frequency (Hz)  amplitude of the tip displacement (m): single-sided, '// &
                           'mean removed, Hann window', unit, stat, errmsg)
      if (stat /= 0) return
      if (unit /= -1) then
         do i = 1, size(frequency)
            write (unit, '(*(es24.15))') frequency(i), tip_amplitude(i)
         end do
      end if
      call files%open_text('tip', 't (s)  u_tip (m)  v_tip (m/s)  mean tip contact force over the output interval (N)', &
                           unit, stat, errmsg)
      if (stat /= 0) return
      if (unit /= -1) then
         do i = 1, n
            write (unit, '(*(es24.15))') s([c_time, c_tip_u, c_tip_v, c_tip_force], i)
         end do
      end if
      call files%open_text('energy', 't (s)  kinetic  elastic  work of loads  dissipated (impacts + damping)  '// &
                           'dissipated by impacts  by damping  total = kinetic + elastic  balance = total - work + '// &
                           'dissipated (J)  penetration (m)', unit, stat, errmsg)
      if (stat /= 0) return
      if (unit /= -1) then
         do i = 1, n
            write (unit, '(*(es24.15))') s([c_time, c_kinetic, c_elastic, c_work, c_dissipated, c_impacts, c_damping, &
                                            c_total], i), s(c_total, i) - s(c_work, i) + s(c_dissipated, i), &
               s(c_penetration, i)
         end do
      end if
      call files%open_text('impacts', 't (s)  x (m)  impulse (N s)  velocity before (m/s)  velocity after (m/s)', &
                           unit, stat, errmsg)
      if (stat /= 0) return
      if (unit /= -1) then
         do i = 1, size(impacts, 2)
            write (unit, '(*(es24.15))') impacts(:, i)
         end do
      end if
      call files%open_text('field', 'x (m)  t (s)  u (m); one block per output time (gnuplot splot/pm3d)', &
                           unit, stat, errmsg)
      if (stat /= 0) return
      if (unit /= -1) then
         do i = 1, n
            do k = 1, model%elements + 1
               write (unit, '(*(es16.7))') model%x(k), s(c_time, i), self%field%values(k, i)
            end do
            write (unit, '(a)') ''
         end do
      end if
      call files%open_text('obstacles', 'x (m)  lower bound g1 (m)  upper bound g2 (m) at each contact point '// &
                           '(+-1e30: no obstacle on that side)', unit, stat, errmsg)
      if (stat /= 0 .or. unit == -1) return
      do k = 1, stepper%contacts%count
         write (unit, '(*(es24.15))') stepper%contacts%x(k), max(-1e30_dp, stepper%contacts%lower(k)), &
            min(1e30_dp, stepper%contacts%upper(k))
      end do
   end subroutine recorder_write
end module vibrobeam_recorder
