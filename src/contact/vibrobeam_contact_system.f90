!> The linear algebra of the contact projection (theory §5): for the metric W (symmetric
!! positive definite band matrix, factored once per run) and the constraint rows H_c of the
!! contact points, the kernels every contact method is built from, each O(J) with LAPACK
!! band routines (or O(J m) with cached columns in the 'delassus' regime):
!!
!! - `solve_held`: the projection with a set F of constraints held as equalities,
!!   H_F x = t_F, W x - b = H_F^T P_F, P = 0 off F, where b = W x_free. Three ways:
!!   'delassus': dense Cholesky of the Delassus block A_FF = H_F W^-1 H_F^T from the
!!   cached columns (x = x_free + sum_k P_k W^-1 H_k^T); 'band' with unit rows (Hermite
!!   elements: H_c x is one unknown): the held unknowns take their targets, and the
!!   principal submatrix W_RR on the others (again a band matrix) is factored by dpbtrf,
!!   W_RR x_R = b_R - W_RH t; 'band' with general rows (B-splines): the banded
!!   saddle-point system (`vibrobeam_saddle_band`). The factors are kept while F does not
!!   change. Every solve is refined once (below).
!! - `factor_barrier` / `solve_barrier`: the interior-point system W + H^T D H for
!!   weights D_k >= 0 (dpbtrf/dpbtrs): a row's nonzeros lie within the band of W, so the
!!   matrix keeps it.
!!
!! The band kernels take b = W x_free rather than x_free and evaluate every residual by a
!! product with W: a band solve with W loses accuracy like its condition number (~N^4 for
!! a beam's stiffness, so that K^-1 F is wrong in the second digit for a static cantilever
!! of 10^4 Hermite elements), while the products stay exact to round-off, and the held
!! problem W_RR x_R = b_R - W_RH t is far better conditioned than W when the held points
!! pin the beam.
!!
!! Multipliers are signed: P_k >= 0 pushes H_k x up (a lower bound), P_k <= 0 down.
module vibrobeam_contact_system
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_linear_solver_failure
   use vibrobeam_lapack, only: dpbtrf, dpbtrs, dpotrf, dpotrs, poison_failed_solve
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_solve, band_matvec, band_entry
   use vibrobeam_contact_set, only: contact_set, contact_value
   use vibrobeam_saddle_band, only: saddle_factor
   implicit none
   private
   public :: contact_system, solve_tally, regime_delassus, regime_band, scatter_rows

   integer, parameter :: regime_delassus = 1, regime_band = 2

   !> What the kernels did in one projection.
   type :: solve_tally
      integer :: linear_solves = 0     !! solves (back-substitutions, new or reused factors)
      integer :: factorizations = 0    !! new factorizations among them
   end type solve_tally

   !> The metric, the contact rows and the kernels' cached factors.
   type :: contact_system
      integer :: regime = regime_band
      integer :: unknowns = 0
      logical :: unit_rows = .false.            !! every row is one unknown with weight 1
      type(symmetric_band) :: metric            !! W
      type(band_cholesky) :: metric_factor      !! its Cholesky factor
      type(contact_set) :: contacts
      real(dp), allocatable :: response(:,:)    !! (J, contacts) W^-1 H_c^T ('delassus')
      real(dp), allocatable :: row_stiffness(:) !! H_c W H_c^T of each contact point
      ! factors of the last held set (they depend only on the set; results do not depend
      ! on whether they are reused or computed again)
      type(saddle_factor) :: saddle             !! general rows
      integer, allocatable :: reduced_points(:) !! held points of `reduced_factor` (unit rows)
      integer, allocatable :: reduced_index(:)  !! (J) row of each unknown in it, 0 if held
      real(dp), allocatable :: reduced_factor(:,:)   !! dpbtrf factor of W on the free unknowns
      integer :: reduced_kd = 0
      real(dp), allocatable :: barrier_factor(:,:)   !! dpbtrf factor of W + H^T D H
      integer :: barrier_kd = 0
   contains
      procedure :: setup => setup_system
      procedure :: solve_held
      procedure :: factor_barrier
      procedure :: solve_barrier
   end type contact_system


contains

   !> Take the metric W with its Cholesky factor and the contact rows; in the 'delassus'
   !! regime compute the columns W^-1 H_c^T of every contact point (one band solve each).
   subroutine setup_system(self, metric, metric_factor, contacts, regime)
      class(contact_system), intent(inout) :: self
      type(symmetric_band), intent(in) :: metric
      type(band_cholesky), intent(in) :: metric_factor
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: regime      !! regime_delassus | regime_band
      integer :: c, a, b, spread
      self%unknowns = metric%n
      self%metric = metric
      self%metric_factor = metric_factor
      self%contacts = contacts
      self%regime = regime
      self%unit_rows = .true.
      spread = 0
      do c = 1, contacts%count
         if (count(contacts%dofs(:, c) /= 0) /= 1 .or. abs(contacts%weights(1, c) - 1) > 0) self%unit_rows = .false.
         spread = max(spread, maxval(contacts%dofs(:, c)) - minval(contacts%dofs(:, c), contacts%dofs(:, c) /= 0))
      end do
      self%barrier_kd = max(metric%kd, spread)
      if (allocated(self%row_stiffness)) deallocate (self%row_stiffness)
      allocate (self%row_stiffness(contacts%count), source=0.0_dp)
      do c = 1, contacts%count
         do a = 1, 4
            if (contacts%dofs(a, c) == 0) cycle
            do b = 1, 4
               if (contacts%dofs(b, c) == 0) cycle
               self%row_stiffness(c) = self%row_stiffness(c) + contacts%weights(a, c)*contacts%weights(b, c)* &
                                       band_entry(metric, contacts%dofs(a, c), contacts%dofs(b, c))
            end do
         end do
      end do
      call self%saddle%forget()
      if (allocated(self%reduced_points)) deallocate (self%reduced_points)
      if (allocated(self%response)) deallocate (self%response)
      if (regime == regime_delassus) then
         allocate (self%response(metric%n, contacts%count), source=0.0_dp)
         do c = 1, contacts%count
            do a = 1, 4
               if (contacts%dofs(a, c) /= 0) self%response(contacts%dofs(a, c), c) = contacts%weights(a, c)
            end do
            call band_solve(metric_factor, self%response(:, c))
         end do
      end if
   end subroutine setup_system

   !> The projection with the constraints `held` held as equalities H_k x = target(k)
   !! (module comment): x and the multipliers (0 where not held). Every solve is followed
   !! by one step of iterative refinement with the same factors (the residual of the held
   !! problem computed by products with W, the correction applied); `error_estimate` =
   !! max_k |H_k correction| over all `points` estimates the remaining error of the values
   !! H_k x (it bounds it while cond eps < 1). stat = stat_linear_solver_failure when a factorization fails.
   subroutine solve_held(self, x_free, w_x_free, points, held, target, x, multiplier, error_estimate, tally, &
                         stat, errmsg)
      class(contact_system), intent(inout) :: self
      real(dp), intent(in) :: x_free(:)
      real(dp), intent(in) :: w_x_free(:)   !! b = W x_free
      integer, intent(in) :: points(:)
      logical, intent(in) :: held(:)
      real(dp), intent(in) :: target(:)
      real(dp), intent(out) :: x(:), multiplier(:)
      real(dp), intent(out) :: error_estimate
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, allocatable :: held_points(:)
      real(dp), allocatable :: held_target(:), held_multiplier(:), correction(:), residual(:), &
                               residual_multiplier(:), correction_multiplier(:)
      integer :: k
      stat = 0
      errmsg = ''
      x = x_free
      multiplier = 0
      error_estimate = 0
      held_points = pack(points, held)
      if (size(held_points) == 0) return
      held_target = pack(target, held)
      allocate (held_multiplier(size(held_points)), correction(size(x_free)))
      tally%linear_solves = tally%linear_solves + 2   ! the solve and its refinement
      if (self%regime == regime_delassus) then
         do k = 1, size(held_points)
            held_target(k) = held_target(k) - contact_value(self%contacts, held_points(k), x_free)
         end do
         call solve_delassus(self, held_points, held_target, held_multiplier, correction, tally, stat, errmsg)
         if (stat /= 0) return
         do k = 1, size(held_points)
            x = x + held_multiplier(k)*self%response(:, held_points(k))
         end do
      else if (self%unit_rows) then
         call solve_reduced(self, w_x_free, held_points, held_target, x, held_multiplier, correction, tally, stat, errmsg)
         if (stat /= 0) return
      else
         if (.not. self%saddle%holds(held_points)) then
            call self%saddle%factor(self%metric, self%contacts, held_points, stat, errmsg)
            tally%factorizations = tally%factorizations + 1
            if (stat /= 0) return
         end if
         ! [W, -H^T; -H, 0] [x; P] = [b; -t], then the same system for the residual
         ! [b - W x + H^T P; H x - t], the correction added
         allocate (residual(size(x_free)), residual_multiplier(size(held_points)), &
                   correction_multiplier(size(held_points)))
         call self%saddle%solve(w_x_free, -held_target, x, held_multiplier, stat, errmsg)
         if (stat /= 0) return
         call band_matvec(self%metric, x, residual)
         correction = 0
         call scatter_rows(self%contacts, held_points, held_multiplier, correction)
         residual = w_x_free - residual + correction
         do k = 1, size(held_points)
            residual_multiplier(k) = contact_value(self%contacts, held_points(k), x) - held_target(k)
         end do
         call self%saddle%solve(residual, residual_multiplier, correction, correction_multiplier, stat, errmsg)
         if (stat /= 0) return
         x = x + correction
         held_multiplier = held_multiplier + correction_multiplier
      end if
      do k = 1, size(points)
         error_estimate = max(error_estimate, abs(contact_value(self%contacts, points(k), correction)))
      end do
      multiplier = unpack(held_multiplier, held, multiplier)
   end subroutine solve_held

   !> A_FF P = defect by dense Cholesky of the Delassus block from the cached columns,
   !! one refinement step; correction = the change of x that the refinement made.
   subroutine solve_delassus(self, points, defect, multiplier, correction, tally, stat, errmsg)
      type(contact_system), intent(in) :: self
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: defect(:)
      real(dp), intent(out) :: multiplier(:), correction(:)
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: a(size(points), size(points)), delassus(size(points), size(points)), residual(size(points))
      integer :: k, l, n
      n = size(points)
      do l = 1, n
         do k = 1, n
            a(k, l) = contact_value(self%contacts, points(k), self%response(:, points(l)))
         end do
      end do
      a = 0.5_dp*(a + transpose(a))   ! exact symmetry; the two triangles differ by round-off
      delassus = a
      multiplier = defect
      tally%factorizations = tally%factorizations + 1
      call dpotrf('L', n, a, n, stat)
      if (stat == 0) call dpotrs('L', n, 1, a, n, multiplier, n, stat)
      if (stat == 0) then
         residual = defect - matmul(delassus, multiplier)
         call dpotrs('L', n, 1, a, n, residual, n, stat)
      end if
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'Delassus block factorization (dpotrf) failed: info = ', stat
         stat = stat_linear_solver_failure
         return
      end if
      multiplier = multiplier + residual
      correction = 0
      do k = 1, n
         correction = correction + residual(k)*self%response(:, points(k))
      end do
   end subroutine solve_delassus

   !> Unit rows: the held unknowns j_k take target(k); the others solve
   !! W_RR x_R = b_R - W_RH x_H with the band factor of the principal submatrix W_RR, then
   !! once more for the residual b_R - (W x)_R (refinement, `correction`); the multipliers
   !! are P_k = (W x - b)_{j_k}, so that W x - b = H^T P holds row by row.
   subroutine solve_reduced(self, w_x_free, points, target, x, multiplier, correction, tally, stat, errmsg)
      type(contact_system), intent(inout) :: self
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: w_x_free(:), target(:)
      real(dp), intent(out) :: x(:), multiplier(:), correction(:)
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: reduced_rhs(:), w_x(:)
      integer :: k, i, free_count, pass
      stat = 0
      errmsg = ''
      if (.not. same_list(self%reduced_points, points)) then
         call factor_reduced(self, points, stat, errmsg)
         tally%factorizations = tally%factorizations + 1
         if (stat /= 0) return
      end if
      x = 0
      do k = 1, size(points)
         x(self%contacts%dofs(1, points(k))) = target(k)
      end do
      allocate (w_x(size(x)))
      free_count = count(self%reduced_index > 0)
      allocate (reduced_rhs(free_count))
      correction = 0
      do pass = 1, 2
         call band_matvec(self%metric, x, w_x)
         do i = 1, self%unknowns
            if (self%reduced_index(i) > 0) reduced_rhs(self%reduced_index(i)) = w_x_free(i) - w_x(i)
         end do
         if (free_count > 0) call dpbtrs('L', free_count, self%reduced_kd, 1, self%reduced_factor, &
                                         self%reduced_kd + 1, reduced_rhs, free_count, stat)
         if (stat /= 0) then
            write (errmsg, '(a,i0)') 'reduced band solve (dpbtrs) failed: info = ', stat
            stat = stat_linear_solver_failure
            return
         end if
         do i = 1, self%unknowns
            if (self%reduced_index(i) > 0) then
               if (pass == 2) correction(i) = reduced_rhs(self%reduced_index(i))
               x(i) = x(i) + reduced_rhs(self%reduced_index(i))
            end if
         end do
      end do
      call band_matvec(self%metric, x, w_x)
      do k = 1, size(points)
         multiplier(k) = w_x(self%contacts%dofs(1, points(k))) - w_x_free(self%contacts%dofs(1, points(k)))
      end do
   end subroutine solve_reduced

   !> Band Cholesky factor of W on the unknowns not held by `points` (unit rows).
   subroutine factor_reduced(self, points, stat, errmsg)
      type(contact_system), intent(inout) :: self
      integer, intent(in) :: points(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i, j, k, free_count, kd
      if (allocated(self%reduced_points)) deallocate (self%reduced_points)
      if (allocated(self%reduced_factor)) deallocate (self%reduced_factor)
      if (allocated(self%reduced_index)) deallocate (self%reduced_index)
      allocate (self%reduced_index(self%unknowns), source=1)
      do k = 1, size(points)
         self%reduced_index(self%contacts%dofs(1, points(k))) = 0
      end do
      free_count = 0
      do i = 1, self%unknowns
         if (self%reduced_index(i) == 0) cycle
         free_count = free_count + 1
         self%reduced_index(i) = free_count
      end do
      kd = self%metric%kd
      ! removing unknowns can only narrow the band
      self%reduced_kd = 0
      do j = 1, self%unknowns
         if (self%reduced_index(j) == 0) cycle
         do i = j + 1, min(self%unknowns, j + kd)
            if (self%reduced_index(i) > 0) self%reduced_kd = max(self%reduced_kd, self%reduced_index(i) - self%reduced_index(j))
         end do
      end do
      allocate (self%reduced_factor(self%reduced_kd + 1, free_count), source=0.0_dp)
      do j = 1, self%unknowns
         if (self%reduced_index(j) == 0) cycle
         do i = j, min(self%unknowns, j + kd)
            if (self%reduced_index(i) == 0) cycle
            self%reduced_factor(1 + self%reduced_index(i) - self%reduced_index(j), self%reduced_index(j)) = &
               self%metric%lower(1 + i - j, j)
         end do
      end do
      stat = 0
      errmsg = ''
      if (free_count > 0) call dpbtrf('L', free_count, self%reduced_kd, self%reduced_factor, self%reduced_kd + 1, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'reduced band factorization (dpbtrf) failed: info = ', stat
         stat = stat_linear_solver_failure
         deallocate (self%reduced_factor)
         return
      end if
      self%reduced_points = points
   end subroutine factor_reduced

   !> Factor W + sum_k weight(k) H_k^T H_k (weights >= 0) for `solve_barrier`.
   subroutine factor_barrier(self, points, weight, tally, stat, errmsg)
      class(contact_system), intent(inout) :: self
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: weight(:)
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k, a, b, ra, rb, kd
      kd = self%barrier_kd
      if (allocated(self%barrier_factor)) deallocate (self%barrier_factor)
      allocate (self%barrier_factor(kd + 1, self%unknowns), source=0.0_dp)
      self%barrier_factor(1:self%metric%kd + 1, :) = self%metric%lower
      do k = 1, size(points)
         if (weight(k) <= 0) cycle
         associate (dofs => self%contacts%dofs(:, points(k)), weights => self%contacts%weights(:, points(k)))
            do a = 1, 4
               if (dofs(a) == 0) cycle
               do b = 1, 4
                  if (dofs(b) == 0 .or. dofs(b) < dofs(a)) cycle
                  ra = dofs(a)
                  rb = dofs(b)
                  self%barrier_factor(1 + rb - ra, ra) = self%barrier_factor(1 + rb - ra, ra) + weight(k)*weights(a)*weights(b)
               end do
            end do
         end associate
      end do
      tally%factorizations = tally%factorizations + 1
      errmsg = ''
      call dpbtrf('L', self%unknowns, kd, self%barrier_factor, kd + 1, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'interior-point band factorization (dpbtrf) failed: info = ', stat
         stat = stat_linear_solver_failure
      end if
   end subroutine factor_barrier

   !> Overwrite v with (W + H^T D H)^-1 v, the factor of `factor_barrier`.
   subroutine solve_barrier(self, v, tally)
      class(contact_system), intent(in) :: self
      real(dp), intent(inout) :: v(:)
      type(solve_tally), intent(inout) :: tally
      integer :: info
      tally%linear_solves = tally%linear_solves + 1
      call dpbtrs('L', self%unknowns, self%barrier_kd, 1, self%barrier_factor, self%barrier_kd + 1, v, &
                  self%unknowns, info)
      call poison_failed_solve(info, v)
   end subroutine solve_barrier

   !> v = v + sum_k H_{points(k)}^T value(k).
   pure subroutine scatter_rows(contacts, points, value, v)
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: value(:)
      real(dp), intent(inout) :: v(:)
      integer :: k, a
      do k = 1, size(points)
         do a = 1, 4
            if (contacts%dofs(a, points(k)) /= 0) v(contacts%dofs(a, points(k))) = &
               v(contacts%dofs(a, points(k))) + contacts%weights(a, points(k))*value(k)
         end do
      end do
   end subroutine scatter_rows

   pure logical function same_list(cached, wanted)
      integer, allocatable, intent(in) :: cached(:)
      integer, intent(in) :: wanted(:)
      same_list = .false.
      if (.not. allocated(cached)) return
      if (size(cached) /= size(wanted)) return
      same_list = all(cached == wanted)
   end function same_list
end module vibrobeam_contact_system
