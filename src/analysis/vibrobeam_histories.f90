!> The datasets of a dynamics result (docs/output.md): the histories sampled at every
!! output time (time, tip, energies, penetration, observation points, compliant stops'
!! energies and forces), the field snapshots and the impacts, streamed while the run goes
!! on (`vibrobeam_hdf5_series`), and what is written at its end (contact fractions, largest
!! penetration, impact count, the compliant stops' peak forces; the spectra are
!! `vibrobeam_run_spectra`'s). The recorder (`vibrobeam_recorder`) decides what goes in;
!! this module owns the layout: names, units, creation before the file enters SWMR mode,
!! buffers and closing.
module vibrobeam_histories
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_contact_set, only: contact_set
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_series, h5_array
   implicit none
   private
   public :: run_histories, history_paths, history_count
   public :: h_time, h_tip_u, h_tip_v, h_tip_reaction, h_tip_impulse, h_kinetic, h_elastic, h_total, h_work, &
             h_dissipated, h_impacts, h_damping, h_numerical, h_balance, h_penetration

   !> The histories sampled at every output time, in the order of a sample row.
   integer, parameter :: history_count = 15
   integer, parameter :: h_time = 1, h_tip_u = 2, h_tip_v = 3, h_tip_reaction = 4, h_tip_impulse = 5, &
                         h_kinetic = 6, h_elastic = 7, h_total = 8, h_work = 9, h_dissipated = 10, &
                         h_impacts = 11, h_damping = 12, h_numerical = 13, h_balance = 14, h_penetration = 15
   character(len=*), parameter :: history_paths(history_count) = [character(len=40) :: '/time', &
      '/tip/displacement', '/tip/velocity', '/tip/reaction', '/tip/impulse', '/energy/kinetic', &
      '/energy/elastic', '/energy/total', '/energy/work', '/energy/dissipated', '/energy/dissipated_impacts', &
      '/energy/dissipated_damping', '/energy/dissipated_numerical', '/energy/balance', '/contact/penetration']
   character(len=*), parameter :: history_units(history_count) = [character(len=8) :: 's', 'm', 'm/s', 'N', &
      'N s', 'J', 'J', 'J', 'J', 'J', 'J', 'J', 'J', 'J', 'm']
   !> Columns of /impacts.
   character(len=*), parameter :: impact_paths(5) = [character(len=32) :: '/impacts/time', '/impacts/x', &
      '/impacts/impulse', '/impacts/velocity_before', '/impacts/velocity_after']
   character(len=*), parameter :: impact_units(5) = [character(len=8) :: 's', 'm', 'N s', 'm/s', 'm/s']

   !> The datasets of one result file.
   type :: run_histories
      logical :: points = .false.                   !! the scene has observation points
      logical :: compliant = .false.                !! the scene has compliant stops
      !> bending planes: with 2, /tip/displacement and /tip/velocity have two columns (y, z)
      integer :: planes = 1
      !> friction at circular holes: /energy/dissipated_friction (created only then)
      logical :: friction = .false.
      type(h5_series) :: friction_series
      type(h5_series) :: histories(history_count), point_u, point_v, field_time, field, impact_columns(5)
      type(h5_array) :: fraction
      ! compliant stops: created only when the scene has springs
      type(h5_series) :: contact_potential, contact_damping, contact_force
      type(h5_array) :: peak_force_array
   contains
      procedure :: create
      procedure :: create_compliant
      procedure :: append_sample
      procedure :: append_impact
      procedure :: append_field
      procedure :: write
      procedure :: write_compliant
      procedure :: rows
      procedure :: finish
   end type run_histories

contains

   !> Create every dataset and attribute of the histories (before the file enters SWMR
   !! mode): `point_x` the observation points (m), `contacts` the contact points, `nodes`
   !! the field's node count, `planes` the bending planes (1, or 2: the tip's, the points'
   !! and the field's deflection histories in y and z).
   subroutine create(self, writer, point_x, contacts, nodes, compliant, planes, friction, stat, errmsg)
      class(run_histories), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      real(dp), intent(in) :: point_x(:)
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: nodes
      logical, intent(in) :: compliant
      integer, intent(in) :: planes
      logical, intent(in) :: friction   !! the scene has friction (at circular holes)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      self%points = size(point_x) > 0
      self%compliant = compliant
      self%planes = planes
      self%friction = friction
      do k = 1, history_count
         if (planes == 2 .and. (k == h_tip_u .or. k == h_tip_v)) then
            call self%histories(k)%create(writer, trim(history_paths(k)), 2, trim(history_units(k)), stat, errmsg, &
                                          matrix=.true.)
         else
            call self%histories(k)%create(writer, trim(history_paths(k)), 1, trim(history_units(k)), stat, errmsg)
         end if
         if (stat /= 0) return
      end do
      do k = 1, 5
         call self%impact_columns(k)%create(writer, trim(impact_paths(k)), 1, trim(impact_units(k)), stat, errmsg)
         if (stat /= 0) return
      end do
      if (friction) then
         call self%friction_series%create(writer, '/energy/dissipated_friction', 1, 'J', stat, errmsg)
         if (stat /= 0) return
      end if
      call self%field_time%create(writer, '/field/time', 1, 's', stat, errmsg)
      ! (snapshots, nodes), with two planes (snapshots, nodes, 2): y, z
      if (stat == 0) call self%field%create(writer, '/field/displacement', planes*nodes, 'm', stat, errmsg, &
                                            matrix=.true., layers=planes)
      if (stat == 0 .and. self%points) then
         call writer%write_real_1d('/points/x', point_x, 'm', stat, errmsg)
         ! (outputs, points), with two planes (outputs, points, 2): y, z
         if (stat == 0) call self%point_u%create(writer, '/points/displacement', planes*size(point_x), 'm', &
                                                 stat, errmsg, matrix=.true., layers=planes)
         if (stat == 0) call self%point_v%create(writer, '/points/velocity', planes*size(point_x), 'm/s', &
                                                 stat, errmsg, matrix=.true., layers=planes)
      end if
      if (stat == 0) call writer%write_real_1d('/contact/x', contacts%x, 'm', stat, errmsg)
      if (stat == 0) call writer%write_real_1d('/contact/lower', contacts%lower, 'm', stat, errmsg)
      if (stat == 0) call writer%write_real_1d('/contact/upper', contacts%upper, 'm', stat, errmsg)
      if (stat == 0) call self%fraction%create(writer, '/contact/fraction', contacts%count, .false., stat, errmsg)
      if (stat == 0) call writer%attr_string('/contact/fraction', 'unit', '1', stat, errmsg)
      if (stat == 0) call writer%attr_real('/contact', 'max_penetration', 0.0_dp, stat, errmsg)
      if (stat == 0) call writer%attr_real('/contact', 'max_penetration_time', 0.0_dp, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/impacts', 'count', 0_int64, stat, errmsg)
   end subroutine create

   !> The compliant stops' datasets, created after the episodes' (the order of the file).
   subroutine create_compliant(self, writer, contacts, stat, errmsg)
      class(run_histories), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      type(contact_set), intent(in) :: contacts
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%contact_potential%create(writer, '/energy/contact_potential', 1, 'J', stat, errmsg)
      if (stat == 0) call self%contact_damping%create(writer, '/energy/dissipated_contact_damping', 1, 'J', &
                                                      stat, errmsg)
      if (stat == 0) call self%contact_force%create(writer, '/contact/force', contacts%count, 'N', stat, errmsg, &
                                                    matrix=.true.)
      if (stat == 0) call self%peak_force_array%create(writer, '/contact/peak_force', contacts%count, .false., &
                                                       stat, errmsg)
      if (stat == 0) call writer%attr_string('/contact/peak_force', 'unit', 'N', stat, errmsg)
   end subroutine create_compliant

   !> One history row (`row`, indexed by h_*, the tip's deflection in y), the tip's
   !! deflection and velocity in z (`tip_z`, read with two planes), the energy friction
   !! took (with friction), the observation
   !! points' u and v, and with compliant stops their stored energy, damping dissipation
   !! and forces.
   subroutine append_sample(self, row, tip_z, friction, point_u, point_v, point_uz, point_vz, potential, &
                            contact_damping, contact_force, stat, errmsg)
      class(run_histories), intent(inout) :: self
      real(dp), intent(in) :: row(history_count), tip_z(2), point_u(:), point_v(:)
      real(dp), intent(in) :: point_uz(:), point_vz(:)   !! a beam of two planes: u and v in z at the points
      real(dp), intent(in) :: friction   !! the energy friction has taken (J)
      real(dp), intent(in) :: potential, contact_damping, contact_force(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      stat = 0
      errmsg = ''
      if (self%compliant) then
         call self%contact_potential%append([potential], stat, errmsg)
         if (stat == 0) call self%contact_damping%append([contact_damping], stat, errmsg)
         if (stat == 0) call self%contact_force%append(contact_force, stat, errmsg)
         if (stat /= 0) return
      end if
      do k = 1, history_count
         if (self%planes == 2 .and. k == h_tip_u) then
            call self%histories(k)%append([row(k), tip_z(1)], stat, errmsg)
         else if (self%planes == 2 .and. k == h_tip_v) then
            call self%histories(k)%append([row(k), tip_z(2)], stat, errmsg)
         else
            call self%histories(k)%append(row(k:k), stat, errmsg)
         end if
         if (stat /= 0) return
      end do
      if (self%friction) then
         call self%friction_series%append([friction], stat, errmsg)
         if (stat /= 0) return
      end if
      if (self%points .and. self%planes == 2) then   ! (points, 2): y and z of each point side by side
         call self%point_u%append(side_by_side([point_u, point_uz]), stat, errmsg)
         if (stat == 0) call self%point_v%append(side_by_side([point_v, point_vz]), stat, errmsg)
      else if (self%points) then
         call self%point_u%append(point_u, stat, errmsg)
         if (stat == 0) call self%point_v%append(point_v, stat, errmsg)
      end if
   end subroutine append_sample

   !> One impact: [time (s), x (m), impulse (N s), velocity before, after (m/s)].
   subroutine append_impact(self, row, stat, errmsg)
      class(run_histories), intent(inout) :: self
      real(dp), intent(in) :: row(5)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: column
      do column = 1, 5
         call self%impact_columns(column)%append(row(column:column), stat, errmsg)
         if (stat /= 0) return
      end do
   end subroutine append_impact

   !> One field snapshot at time t: the displacement at the nodes (a beam of two planes:
   !! at each node in y, then at each in z).
   subroutine append_field(self, t, nodal, stat, errmsg)
      class(run_histories), intent(inout) :: self
      real(dp), intent(in) :: t, nodal(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%field_time%append([t], stat, errmsg)
      if (stat /= 0) return
      if (self%planes == 2) then
         call self%field%append(side_by_side(nodal), stat, errmsg)
      else
         call self%field%append(nodal, stat, errmsg)
      end if
   end subroutine append_field

   !> The values of a row of a 3-d series of two layers (`h5_series` `layers`), y and z of
   !! each point side by side, from `stacked`: every y value, then every z value.
   pure function side_by_side(stacked) result(row)
      real(dp), intent(in) :: stacked(:)
      real(dp) :: row(size(stacked))
      row = reshape(transpose(reshape(stacked, [size(stacked)/2, 2])), [size(stacked)])
   end function side_by_side

   !> Buffered rows to the file.
   subroutine write(self, stat, errmsg)
      class(run_histories), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      do k = 1, history_count
         call self%histories(k)%write(stat, errmsg)
         if (stat /= 0) return
      end do
      do k = 1, 5
         call self%impact_columns(k)%write(stat, errmsg)
         if (stat /= 0) return
      end do
      call self%field_time%write(stat, errmsg)
      if (stat == 0) call self%field%write(stat, errmsg)
      if (stat == 0 .and. self%points) call self%point_u%write(stat, errmsg)
      if (stat == 0 .and. self%points) call self%point_v%write(stat, errmsg)
      if (stat == 0 .and. self%friction) call self%friction_series%write(stat, errmsg)
   end subroutine write

   !> Buffered rows of the compliant stops' datasets to the file (after the episodes').
   subroutine write_compliant(self, stat, errmsg)
      class(run_histories), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.not. self%compliant) return
      call self%contact_potential%write(stat, errmsg)
      if (stat == 0) call self%contact_damping%write(stat, errmsg)
      if (stat == 0) call self%contact_force%write(stat, errmsg)
   end subroutine write_compliant

   !> Rows so far: [outputs, field snapshots, impacts].
   function rows(self) result(counts)
      class(run_histories), intent(in) :: self
      integer(int64) :: counts(3)
      counts = [self%histories(1)%rows(), self%field_time%rows(), self%impact_columns(1)%rows()]
   end function rows

   !> End of the run: the contact fractions, largest penetration and impact count, the
   !! compliant stops' peak forces; the datasets are closed.
   subroutine finish(self, writer, fraction, max_penetration, max_penetration_time, impacts, peak_force, stat, errmsg)
      class(run_histories), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      real(dp), intent(in) :: fraction(:), max_penetration, max_penetration_time, peak_force(:)
      integer(int64), intent(in) :: impacts
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      call self%fraction%write_reals(fraction, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/contact', 'max_penetration', max_penetration, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/contact', 'max_penetration_time', max_penetration_time, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/impacts', 'count', impacts, stat, errmsg)
      if (stat == 0 .and. self%compliant) call self%peak_force_array%write_reals(peak_force, stat, errmsg)
      if (stat /= 0) return
      do k = 1, history_count
         call self%histories(k)%close()
      end do
      do k = 1, 5
         call self%impact_columns(k)%close()
      end do
      call self%field_time%close()
      call self%field%close()
      call self%point_u%close()
      call self%point_v%close()
      if (self%friction) call self%friction_series%close()
      call self%fraction%close()
      if (self%compliant) then
         call self%contact_potential%close()
         call self%contact_damping%close()
         call self%contact_force%close()
         call self%peak_force_array%close()
      end if
   end subroutine finish
end module vibrobeam_histories
