!> The statistics of an ensemble of realisations (docs/statistics.md, "Ensembles of
!! realisations"; docs/output.md, "Sweep file"): when an axis of a sweep is
!! `forces.realisation`, its points fall into groups, one per value of the other axis
!! (and per branch; one group for a 1-D ensemble), and each group gets, for every
!! statistic value of the layout, the mean over its R realisations that finished (status
!! ok) and the half-width of its 95 % interval,
!!
!!     x_mean = (1/R) sum_r x_r,   half_width = t_{0.975, R-1} s/sqrt(R),
!!     s^2 = (1/(R - 1)) sum_r (x_r - x_mean)^2,
!!
!! t Student's quantile (`vibrobeam_quantiles`); half_width = 0 when R < 2 (no interval).
!! The sums are Welford's running mean and sum of squared deviations, fed a point at a
!! time (`add`) as the sweep file is written: memory is two values per statistic and
!! group.
module vibrobeam_sweep_ensemble
   use vibrobeam_kinds, only: dp
   use vibrobeam_quantiles, only: student_quantile
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point
   implicit none
   private
   public :: sweep_ensemble, ensemble_parameter, ensemble_confidence

   character(len=*), parameter :: ensemble_parameter = 'forces.realisation'
   real(dp), parameter :: ensemble_confidence = 0.95_dp

   type :: sweep_ensemble
      integer :: axis = 0                          !! the realisations' axis (1, 2; 0: not an ensemble)
      integer :: groups = 0
      integer, allocatable :: group_of(:)          !! (points) the group of each point
      real(dp), allocatable :: other(:)            !! (groups) the other axis' value (0 for a 1-D ensemble)
      integer, allocatable :: direction(:)         !! (groups) the branch of the group
      integer, allocatable :: count(:)             !! (groups) R, the realisations added
      real(dp), allocatable :: mean(:, :)          !! (values, groups) running means
      real(dp), allocatable :: squares(:, :)       !! (values, groups) sums of squared deviations
   contains
      procedure :: init
      procedure :: add
      procedure :: half_width
   end type sweep_ensemble

contains

   !> The groups of the `points` of a sweep `settings` whose statistics have `values`
   !! values a point; axis = 0 (nothing to do) when neither axis is the realisation.
   subroutine init(self, settings, points, values)
      class(sweep_ensemble), intent(out) :: self
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer, intent(in) :: values
      real(dp), allocatable :: other(:)
      integer, allocatable :: direction(:)
      real(dp) :: key
      integer :: k, g
      self%axis = 0
      if (settings%axis(1)%parameter == ensemble_parameter) self%axis = 1
      if (settings%axis(2)%parameter == ensemble_parameter) self%axis = 2
      if (self%axis == 0) return
      allocate (self%group_of(size(points)), other(size(points)), direction(size(points)))
      self%groups = 0
      do k = 1, size(points)
         key = 0
         if (self%axis == 1 .and. len_trim(settings%axis(2)%parameter) > 0) key = points(k)%value(2)
         if (self%axis == 2) key = points(k)%value(1)
         g = 0
         ! the groups in the order of their first point (a few: one per value of the other axis)
         do g = self%groups, 1, -1
            if (same_value(other(g), key) .and. direction(g) == points(k)%direction) exit
         end do
         if (g == 0) then
            self%groups = self%groups + 1
            g = self%groups
            other(g) = key
            direction(g) = points(k)%direction
         end if
         self%group_of(k) = g
      end do
      self%other = other(1:self%groups)
      self%direction = direction(1:self%groups)
      allocate (self%count(self%groups), source=0)
      allocate (self%mean(values, self%groups), self%squares(values, self%groups), source=0.0_dp)
   contains
      logical function same_value(a, b)
         real(dp), intent(in) :: a, b
         same_value = .not. (a < b .or. a > b)
      end function same_value
   end subroutine init

   !> The statistics `x` of point k (a realisation that finished).
   subroutine add(self, k, x)
      class(sweep_ensemble), intent(inout) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: x(:)
      real(dp) :: delta(size(x))
      integer :: g
      g = self%group_of(k)
      self%count(g) = self%count(g) + 1
      delta = x - self%mean(:, g)
      self%mean(:, g) = self%mean(:, g) + delta/self%count(g)
      self%squares(:, g) = self%squares(:, g) + delta*(x - self%mean(:, g))
   end subroutine add

   !> The half-widths of the 95 % intervals of group g's means (0 when R < 2).
   function half_width(self, g) result(h)
      class(sweep_ensemble), intent(in) :: self
      integer, intent(in) :: g
      real(dp) :: h(size(self%mean, 1))
      integer :: r
      r = self%count(g)
      h = 0
      if (r < 2) return
      h = student_quantile(real(r - 1, dp), (1 + ensemble_confidence)/2)*sqrt(self%squares(:, g)/(r - 1))/sqrt(real(r, dp))
   end function half_width
end module vibrobeam_sweep_ensemble
