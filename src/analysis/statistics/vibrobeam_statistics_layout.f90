!> The statistics of a run as named vectors (docs/statistics.md): which statistics there
!! are, their unit, their length and where they sit in the flat vector of values that the
!! statistics module computes, the result file stores under /statistics and the sweep
!! file under /sweep/statistics (one row per sweep point).
!!
!! Groups and lengths: 'points' (the tip, then each &output points x), 'contacts' (the
!! contact points), 'obstacles' (each obstacle of &obstacles), 'beam' (all contact points
!! together; 1; the contact points also have the force statistics of the compliant
!! stops), 'energy' (1), 'spectrum' (the `peak_count` largest peaks), 'poincare' (1: the
!! period of the Poincare sequence, the 0-1 test and the Lyapunov exponent,
!! `vibrobeam_poincare_diagnostics`) and, for a beam of two planes with obstacles, 'wear'
!! (the points of its obstacles: `vibrobeam_support_wear`'s quantities, the wear volume
!! rate where a wear_coefficient is given) and the energy's 'power_friction' (with
!! friction). Every statistic has a standard error beside it (`<name>_error`) except the
!! spectrum's and the 'poincare' group's, where only the Lyapunov exponent has one.
!! A sweep of periodic analyses has the one group 'periodic' instead (`init_periodic`).
!! A beam of two planes has the 'points' statistics in y and z: 2 values per point, the
!! plane fastest (`layers` = 2: (1 + points, 2) as h5py shows it), the planar y values
!! of point p at offset + 2 (p - 1) + 1; and the 'spectrum' peaks likewise, (peaks, 2).
module vibrobeam_statistics_layout
   implicit none
   private
   public :: statistics_layout, statistic_entry, peak_count
   public :: group_points, group_contacts, group_obstacles, group_beam, group_energy, group_spectrum, group_poincare
   public :: group_wear, group_periodic, wear_quantities, wear_names, wear_units, periodic_names

   integer, parameter :: peak_count = 3   !! dominant response frequencies reported
   integer, parameter :: group_points = 1, group_contacts = 2, group_obstacles = 3, group_beam = 4, &
                         group_energy = 5, group_spectrum = 6, group_poincare = 7, group_wear = 8, group_periodic = 9
   character(len=*), parameter :: group_names(9) = [character(len=9) :: 'points', 'contacts', 'obstacles', &
                                                    'beam', 'energy', 'spectrum', 'poincare', 'wear', 'periodic']
   !> What a sweep of periodic analyses keeps of each point (`init_periodic`; docs/output.md,
   !! "Sweep file"): of its orbit, or of its branch's first orbit, the period, the largest
   !! modulus of its Floquet multipliers and the Newton iterations; the points and the
   !! bifurcations of its branch (0 without a continuation); the time steps it took.
   character(len=*), parameter :: periodic_names(6) = [character(len=32) :: 'period', 'largest_multiplier', &
      'newton_iterations', 'branch_points', 'bifurcations', 'steps']
   character(len=*), parameter :: periodic_units(6) = [character(len=8) :: 's', '1', '1', '1', '1', '1']
   !> The wear quantities of each point of a beam of two planes' obstacles
   !! (`vibrobeam_support_wear`; the last only where a wear_coefficient is given).
   integer, parameter :: wear_quantities = 7
   character(len=*), parameter :: wear_names(wear_quantities) = [character(len=20) :: 'work_rate', 'mean_force', &
      'rms_force', 'contact_fraction', 'sliding_fraction', 'impact_rate', 'wear_volume_rate']
   character(len=*), parameter :: wear_units(wear_quantities) = [character(len=8) :: 'W', 'N', 'N', '1', '1', &
      '1/s', 'm^3/s']

   !> One statistic: a vector of `length` values.
   type :: statistic_entry
      character(len=32) :: name = ''    !! e.g. 'displacement_rms'
      character(len=8) :: unit = ''
      integer :: group = 0              !! group_points, ...
      integer :: length = 0
      integer :: offset = 0             !! values(offset + 1 : offset + length)
      integer :: layers = 1             !! 2: a value in y and in z per point, the plane fastest
      logical :: has_error = .true.
   end type statistic_entry

   !> Every statistic of a scene with the given numbers of observation points, contact
   !! points and obstacles (and, for a beam of two planes, its obstacles' points, whether
   !! a wear coefficient is given, whether friction acts and its `planes`).
   type :: statistics_layout
      integer :: observation_points = 0, contact_points = 0, obstacles = 0
      integer :: wear_points = 0                  !! points of a beam of two planes' obstacles (0: none)
      logical :: wear_volume = .false.            !! some wear_coefficient given: wear_volume_rate
      logical :: friction = .false.               !! Coulomb friction acts: energy/power_friction
      integer :: planes = 1                       !! 2: the 'points' statistics in y and z
      integer :: size = 0                         !! length of the flat vector
      !> the points are periodic analyses (`init_periodic`): the one group 'periodic'
      logical :: periodic = .false.
      type(statistic_entry), allocatable :: entries(:)
   contains
      procedure :: init
      procedure :: init_periodic
      procedure :: find
      procedure :: path
      procedure :: one_value
   end type statistics_layout

   !> Statistics of the observation points (m for displacement, m/s for velocity).
   character(len=*), parameter :: point_names(8) = [character(len=32) :: 'displacement_mean', &
      'displacement_rms', 'displacement_min', 'displacement_max', 'velocity_mean', 'velocity_rms', &
      'velocity_min', 'velocity_max']
   !> Contact statistics of each contact point, each obstacle and the beam.
   character(len=*), parameter :: contact_names(7) = [character(len=32) :: 'impact_rate', 'episode_rate', &
      'episode_impulse_mean', 'episode_impulse_max', 'episode_impulse_rms', 'contact_fraction', 'contact_force']
   character(len=*), parameter :: contact_units(7) = [character(len=8) :: '1/s', '1/s', 'N s', 'N s', 'N s', '1', 'N']
   !> Force statistics of the compliant stops at each contact point (0 where no spring acts).
   character(len=*), parameter :: force_names(7) = [character(len=32) :: 'force_peak', 'force_mean', &
      'force_contact_mean', 'force_contact_rms', 'force_contact_fraction', 'force_episode_duration_mean', &
      'force_episode_duration_max']
   character(len=*), parameter :: force_units(7) = [character(len=8) :: 'N', 'N', 'N', 'N', '1', 's', 's']
   !> The Poincare sequence's diagnostics (docs/statistics.md, "Period, Lyapunov exponent and
   !! the 0-1 test"), one value each; only the Lyapunov exponent has a standard error.
   character(len=*), parameter :: poincare_names(7) = [character(len=32) :: 'period', 'period_mismatch', &
      'zero_one_k', 'zero_one_lags', 'lyapunov_exponent', 'lyapunov_exponent_per_period', 'lyapunov_periods']
   character(len=*), parameter :: poincare_units(7) = [character(len=8) :: '1', '1', '1', '1', '1/s', '1', '1']
   character(len=*), parameter :: energy_names(8) = [character(len=32) :: 'power_input', 'power_impacts', &
      'power_damping', 'power_numerical', 'power_contact_damping', 'power_dissipated', 'power_stored', &
      'balance_residual']

contains

   subroutine init(self, observation_points, contact_points, obstacles, wear_points, wear_volume, friction, planes)
      class(statistics_layout), intent(inout) :: self
      integer, intent(in) :: observation_points, contact_points, obstacles
      integer, intent(in), optional :: wear_points, planes
      logical, intent(in), optional :: wear_volume, friction
      integer :: k, group, lengths(3)
      self%observation_points = observation_points
      self%contact_points = contact_points
      self%obstacles = obstacles
      self%periodic = .false.
      self%wear_points = 0
      if (present(wear_points)) self%wear_points = wear_points
      self%wear_volume = .false.
      if (present(wear_volume)) self%wear_volume = wear_volume .and. self%wear_points > 0
      self%friction = .false.
      if (present(friction)) self%friction = friction
      self%planes = 1
      if (present(planes)) self%planes = planes
      self%size = 0
      if (allocated(self%entries)) deallocate (self%entries)
      allocate (self%entries(0))
      do k = 1, size(point_names)
         call add(point_names(k), merge('m  ', 'm/s', k <= 4), group_points, self%planes*observation_points, .true.)
         self%entries(k)%layers = self%planes
      end do
      lengths = [contact_points, obstacles, 1]
      do group = group_contacts, group_beam
         do k = 1, size(contact_names)
            call add(contact_names(k), contact_units(k), group, lengths(group - group_contacts + 1), .true.)
         end do
      end do
      do k = 1, size(force_names)
         call add(force_names(k), force_units(k), group_contacts, contact_points, .true.)
      end do
      do k = 1, size(energy_names)
         call add(energy_names(k), 'W', group_energy, 1, .true.)
      end do
      ! with two planes each peak in y and in z (of the tip displacement in each plane)
      call add('peak_frequency', 'Hz', group_spectrum, self%planes*peak_count, .false.)
      call add('peak_amplitude', 'm', group_spectrum, self%planes*peak_count, .false.)
      call add('peak_frequency_rad_s', 'rad/s', group_spectrum, self%planes*peak_count, .false.)   ! 2 pi peak_frequency
      self%entries(size(self%entries) - 2:)%layers = self%planes
      do k = 1, size(poincare_names)
         call add(poincare_names(k), poincare_units(k), group_poincare, 1, index(poincare_names(k), 'lyapunov_exponent') == 1)
      end do
      ! a beam of two planes: after the planar entries, so a planar layout is unchanged
      if (self%friction) call add('power_friction', 'W', group_energy, 1, .true.)
      if (self%wear_points > 0) then
         do k = 1, wear_quantities
            if (k < wear_quantities .or. self%wear_volume) &
               call add(wear_names(k), wear_units(k), group_wear, self%wear_points, .true.)
         end do
      end if
   contains
      subroutine add(name, unit, group, length, has_error)
         character(len=*), intent(in) :: name, unit
         integer, intent(in) :: group, length
         logical, intent(in) :: has_error
         type(statistic_entry) :: item
         item%name = name
         item%unit = unit
         item%group = group
         item%length = length
         item%offset = self%size
         item%has_error = has_error
         self%entries = [self%entries, item]
         self%size = self%size + length
      end subroutine add
   end subroutine init

   !> The layout of a sweep of periodic analyses: the group 'periodic' (`periodic_names`),
   !! one value each, without standard errors.
   subroutine init_periodic(self)
      class(statistics_layout), intent(inout) :: self
      integer :: k
      self%observation_points = 0
      self%contact_points = 0
      self%obstacles = 0
      self%wear_points = 0
      self%wear_volume = .false.
      self%friction = .false.
      self%planes = 1
      self%periodic = .true.
      if (allocated(self%entries)) deallocate (self%entries)
      allocate (self%entries(size(periodic_names)))
      do k = 1, size(periodic_names)
         self%entries(k) = statistic_entry(periodic_names(k), periodic_units(k), group_periodic, 1, k - 1, 1, .false.)
      end do
      self%size = size(periodic_names)
   end subroutine init_periodic

   !> Index of the statistic `name` of `group`, 0 when there is none.
   pure integer function find(self, group, name)
      class(statistics_layout), intent(in) :: self
      integer, intent(in) :: group
      character(len=*), intent(in) :: name
      integer :: k
      find = 0
      do k = 1, size(self%entries)
         if (self%entries(k)%group == group .and. self%entries(k)%name == name) then
            find = k
            return
         end if
      end do
   end function find

   !> Entry k is one value per run (its group is 'beam', 'energy', 'poincare' or 'periodic'): a sweep
   !! file holds it as a vector over the points, not a matrix.
   pure logical function one_value(self, k)
      class(statistics_layout), intent(in) :: self
      integer, intent(in) :: k
      one_value = any(self%entries(k)%group == [group_beam, group_energy, group_poincare, group_periodic])
   end function one_value

   !> 'group/name' of entry k (e.g. 'points/displacement_rms'), '_error' appended when
   !! `error`; the caller prefixes '/statistics/' or '/sweep/statistics/'.
   pure function path(self, k, error) result(text)
      class(statistics_layout), intent(in) :: self
      integer, intent(in) :: k
      logical, intent(in) :: error
      character(len=:), allocatable :: text
      text = trim(group_names(self%entries(k)%group))//'/'//trim(self%entries(k)%name)
      if (error) text = text//'_error'
   end function path
end module vibrobeam_statistics_layout
