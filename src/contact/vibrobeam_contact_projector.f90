!> The contact projection (theory §3 step 3, §4 and the static problem): for a metric W
!! (symmetric positive definite band matrix) and the rows H_c of the contact points, find
!!
!!     x = argmin 1/2 (x - x_free)^T W (x - x_free)
!!
!! subject to s_k (H_k x - b_k) >= 0 on the active points (`project`: dynamics, one side
!! per point) or lower(c) <= H_c x <= upper(c) on every contact point (`project_admissible`:
!! statics and the position scheme), with x = x_free + W^-1 H^T P and the multipliers P
!! complementary to the constraints. P_c is the impulse (dynamics) or force (statics) of
!! the obstacle on the beam at contact point c, positive upwards.
!!
!! Two methods (`&solver contact_method`):
!! - 'newton' (default, `vibrobeam_contact_newton`): primal-dual active set from the
!!   previous projection's set, globalized by an interior-point method, exact finish; if
!!   it fails (it has not in any scene measured) principal pivoting runs instead and
!!   `used_fallback` says so;
!! - 'pivoting' (`vibrobeam_contact_pivoting`): block principal pivoting with Murty's
!!   fall-back, the method of vibrobeam 0.1, kept for comparison.
!! Two regimes for the linear algebra (`&solver contact_solver`, `vibrobeam_contact_system`):
!! 'delassus' (cached columns W^-1 H_c^T, for few contact points) and 'band' (band
!! factorizations, O(J) per solve whatever the number of points); 'auto' chooses
!! 'delassus' up to `delassus_limit` contact points.
!!
!! State kept between projections (the warm start; a restarted run must restore it to be
!! bitwise identical): `warm_side`. The cached factors in `system` depend only on the held
!! set and are recomputed identically when absent, so they need not be saved.
module vibrobeam_contact_projector
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky
   use vibrobeam_contact_set, only: contact_set, no_bound
   use vibrobeam_contact_system, only: contact_system, solve_tally, regime_delassus, regime_band
   use vibrobeam_contact_newton, only: newton_project, newton_report
   use vibrobeam_contact_pivoting, only: pivot_project, pivot_admissible
   implicit none
   private
   public :: contact_projector, regime_delassus, regime_band, delassus_limit, method_newton, method_pivoting
   public :: contact_method_code

   integer, parameter :: method_newton = 1, method_pivoting = 2
   !> Largest number of contact points for which 'auto' caches the Delassus columns
   !! (measured, studies/benchmark/REPORT.md).
   integer, parameter :: delassus_limit = 16
   !> Pivots of the fall-back per projection when `max_iterations` is 0: the pivoting's own
   !! default, max(100, 10 m), would let a projection of 10^5 points run for hours.
   integer, parameter :: fallback_pivot_limit = 500

   !> What the projection needs about the scene (set up once per run), its warm-start
   !! state, and what the last projection did.
   type :: contact_projector
      integer :: regime = regime_delassus          !! regime_delassus | regime_band
      integer :: method = method_newton            !! method_newton | method_pivoting
      integer :: unknowns = 0
      type(contact_system) :: system
      integer :: max_iterations = 0                !! pivoting iterations per solve; 0: default of each regime
      !> side held by each contact point at the end of the last projection (+1 its lower
      !! bound, -1 its upper bound, 0 free): the warm start of the next one
      integer, allocatable :: warm_side(:)
      ! what the last projection did
      integer :: iterations = 0                    !! active-set + interior-point iterations, or pivots
      integer :: linear_solves = 0                 !! linear solves (band or dense back-substitutions)
      integer :: factorizations = 0                !! new factorizations among them
      integer :: interior_iterations = 0           !! interior-point iterations ('newton')
      logical :: used_fallback = .false.           !! 'newton' failed and pivoting ran instead
   contains
      procedure :: setup
      procedure :: project
      procedure :: project_admissible
      procedure :: record_free
   end type contact_projector

contains

   !> The code of a `&solver contact_method` value ('newton' or 'pivoting'), 0 if unknown.
   pure integer function contact_method_code(name)
      character(len=*), intent(in) :: name
      select case (name)
      case ('newton')
         contact_method_code = method_newton
      case ('pivoting')
         contact_method_code = method_pivoting
      case default
         contact_method_code = 0
      end select
   end function contact_method_code

   !> Prepare the projection for metric W (with its Cholesky factor) and the contact set.
   !! regime: 'auto' (Delassus up to `delassus_limit` contact points, band beyond),
   !! 'delassus' or 'band'. method: 'newton' (default) or 'pivoting'.
   subroutine setup(self, metric, metric_factor, contacts, regime, method)
      class(contact_projector), intent(inout) :: self
      type(symmetric_band), intent(in) :: metric
      type(band_cholesky), intent(in) :: metric_factor
      type(contact_set), intent(in) :: contacts
      character(len=*), intent(in) :: regime
      character(len=*), intent(in), optional :: method
      self%unknowns = metric%n
      select case (regime)
      case ('delassus')
         self%regime = regime_delassus
      case ('band')
         self%regime = regime_band
      case default
         self%regime = merge(regime_delassus, regime_band, contacts%count <= delassus_limit)
      end select
      self%method = method_newton
      if (present(method)) then
         if (contact_method_code(method) /= 0) self%method = contact_method_code(method)
      end if
      call self%system%setup(metric, metric_factor, contacts, self%regime)
      if (allocated(self%warm_side)) deallocate (self%warm_side)
      allocate (self%warm_side(contacts%count), source=0)
   end subroutine setup

   !> Projection for the constraints k = 1..m on contact points active(k) with signs s(k)
   !! (+1: from below, -1: from above) and offsets b(k): s_k (H_k x - b_k) >= 0.
   !! stat: stat_ok; stat_no_convergence; stat_linear_solver_failure; stat_residual_check_failed
   !! (vibrobeam_status).
   subroutine project(self, x_free, active, s, b, x, impulse, iterations, stat, errmsg)
      class(contact_projector), intent(inout) :: self
      real(dp), intent(in) :: x_free(:)     !! (J) unconstrained solution
      integer, intent(in) :: active(:)      !! (m) contact point indices
      real(dp), intent(in) :: s(:)          !! (m) +1 or -1
      real(dp), intent(in) :: b(:)          !! (m) offsets
      real(dp), intent(out) :: x(:)         !! (J) projected solution
      real(dp), intent(out) :: impulse(:)   !! (m) P_k, s_k P_k >= 0
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      type(solve_tally) :: tally
      type(newton_report) :: report
      integer :: side(size(active))
      call start_report(self)
      stat = 0
      errmsg = ''
      if (self%method == method_newton) then
         side = self%warm_side(active)
         where (side /= nint(s)) side = 0
         call newton_project(self%system, x_free, active, merge(b, -no_bound, s > 0), merge(no_bound, b, s > 0), &
                             side, x, impulse, report, tally, stat, errmsg)
         call take_report(self, report)
      end if
      if (self%method == method_pivoting .or. stat /= 0) then
         self%used_fallback = self%method == method_newton
         call pivot_project(self%system, x_free, active, s, b, pivot_limit(self), x, impulse, iterations, tally, &
                            stat, errmsg)
         self%iterations = self%iterations + iterations
         side = nint(merge(s, 0.0_dp, abs(impulse) > 0))
      end if
      self%warm_side = 0
      self%warm_side(active) = side
      iterations = self%iterations
      self%linear_solves = tally%linear_solves
      self%factorizations = tally%factorizations
   end subroutine project

   !> What `project` records when no point is active (its projection is then x = x_free):
   !! the steppers call this instead, so a free-flight step allocates nothing.
   subroutine record_free(self)
      class(contact_projector), intent(inout) :: self
      call start_report(self)
      self%warm_side = 0
      self%linear_solves = 0
      self%factorizations = 0
   end subroutine record_free

   !> Projection onto the whole admissible set {lower(c) <= H_c x <= upper(c), every
   !! contact point c} (statics, theory §4's position projection). multiplier(c) = P_c,
   !! 0 off contact. stat as for `project`.
   subroutine project_admissible(self, x_free, x, multiplier, iterations, stat, errmsg, w_x_free)
      class(contact_projector), intent(inout) :: self
      real(dp), intent(in) :: x_free(:)
      !> W x_free when known exactly (statics: the load vector); else computed
      real(dp), intent(in), optional :: w_x_free(:)
      real(dp), intent(out) :: x(:)
      real(dp), intent(out) :: multiplier(:)     !! (contacts%count)
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      type(solve_tally) :: tally
      type(newton_report) :: report
      integer :: c
      call start_report(self)
      stat = 0
      errmsg = ''
      associate (contacts => self%system%contacts)
         if (self%method == method_newton) then
            call newton_project(self%system, x_free, [(c, c=1, contacts%count)], contacts%lower, contacts%upper, &
                                self%warm_side, x, multiplier, report, tally, stat, errmsg, w_x_free)
            call take_report(self, report)
         end if
         if (self%method == method_pivoting .or. stat /= 0) then
            self%used_fallback = self%method == method_newton
            call pivot_admissible(self%system, x_free, pivot_limit(self), x, multiplier, iterations, tally, stat, errmsg)
            self%iterations = self%iterations + iterations
            self%warm_side = 0
            where (multiplier > 0) self%warm_side = 1
            where (multiplier < 0) self%warm_side = -1
         end if
      end associate
      iterations = self%iterations
      self%linear_solves = tally%linear_solves
      self%factorizations = tally%factorizations
   end subroutine project_admissible

   !> Pivots allowed per projection: `max_iterations` (0: the pivoting's default), or for the
   !! fall-back of 'newton' fallback_pivot_limit when it is 0.
   pure integer function pivot_limit(self)
      type(contact_projector), intent(in) :: self
      pivot_limit = self%max_iterations
      if (self%method == method_newton .and. pivot_limit == 0) pivot_limit = fallback_pivot_limit
   end function pivot_limit

   subroutine start_report(self)
      type(contact_projector), intent(inout) :: self
      self%iterations = 0
      self%interior_iterations = 0
      self%used_fallback = .false.
   end subroutine start_report

   subroutine take_report(self, report)
      type(contact_projector), intent(inout) :: self
      type(newton_report), intent(in) :: report
      self%iterations = report%active_set_iterations + report%interior_iterations
      self%interior_iterations = report%interior_iterations
   end subroutine take_report
end module vibrobeam_contact_projector
