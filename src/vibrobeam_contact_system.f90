!> The linear algebra of the contact projection (theory §5): for the metric W (symmetric
!! positive definite band matrix, factored once per run) and the constraint rows H_c of the
!! contact points, three kernels that every contact method is built from. Each is O(J) with
!! LAPACK band routines (or O(J m) with cached columns in the 'delassus' regime):
!!
!! - `respond`:     x = x_free + W^-1 H^T P for given multipliers P (one back-substitution
!!                  with the factor of W, or a sum of cached columns W^-1 H_c^T);
!! - `solve_held`:  the projection with a set F of constraints held as equalities,
!!                  H_F x = t_F, W (x - x_free) = H_F^T P_F, P = 0 off F. Three ways:
!!                  'delassus': dense Cholesky of the Delassus block A_FF = H_F W^-1 H_F^T
!!                  from the cached columns; 'band' with unit rows (Hermite elements: H_c x
!!                  is one unknown): the held unknowns are fixed, and the principal
!!                  submatrix of W on the others (again a band matrix) is factored by dpbtrf;
!!                  'band' with general rows (B-splines): the banded saddle-point system
!!                  (`vibrobeam_saddle_band`) in increment form. The factors are kept while F
!!                  does not change.
!! - `factor_barrier` / `solve_barrier`: the interior-point system: for weights D_k >= 0,
!!                  dg = H (W + H^T D H)^-1 H^T rho = (A^-1 + D)^-1 rho, A = H W^-1 H^T; the
!!                  matrix W + H^T D H keeps the band of W (a row's nonzeros lie within it),
!!                  so dpbtrf/dpbtrs.
!!
!! Multipliers are signed: P_k >= 0 pushes H_k x up (a lower bound), P_k <= 0 down.
module vibrobeam_contact_system
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_solve, band_matvec, band_entry
   use vibrobeam_contact_points, only: contact_set, contact_value
   use vibrobeam_saddle_band, only: saddle_factor
   implicit none
   private
   public :: contact_system, solve_tally, regime_delassus, regime_band

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
      procedure :: respond
      procedure :: solve_held
      procedure :: factor_barrier
      procedure :: solve_barrier
   end type contact_system

   interface
      subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: info
      end subroutine dpbtrf
      subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, nrhs, ldab, ldb
         real(dp), intent(in) :: ab(ldab, *)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpbtrs
      subroutine dpotrf(uplo, n, a, lda, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, lda
         real(dp), intent(inout) :: a(lda, *)
         integer, intent(out) :: info
      end subroutine dpotrf
      subroutine dpotrs(uplo, n, nrhs, a, lda, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(in) :: a(lda, *)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpotrs
   end interface

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
         if (count(contacts%dofs(:, c) /= 0) /= 1 .or. contacts%weights(1, c) /= 1) self%unit_rows = .false.
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

   !> x = x_free + W^-1 sum_k H_{points(k)}^T multiplier(k).
   subroutine respond(self, x_free, points, multiplier, x, tally)
      class(contact_system), intent(in) :: self
      real(dp), intent(in) :: x_free(:), multiplier(:)
      integer, intent(in) :: points(:)
      real(dp), intent(out) :: x(:)
      type(solve_tally), intent(inout) :: tally
      integer :: k
      tally%linear_solves = tally%linear_solves + 1
      if (self%regime == regime_delassus) then
         x = x_free
         do k = 1, size(points)
            if (multiplier(k) /= 0) x = x + multiplier(k)*self%response(:, points(k))
         end do
      else
         x = 0
         call scatter_rows(self%contacts, points, multiplier, x)
         call band_solve(self%metric_factor, x)
         x = x_free + x
      end if
   end subroutine respond

   !> The projection with the constraints `held` held as equalities H_k x = target(k)
   !! (module comment): x and the multipliers (0 where not held). Every solve is followed
   !! by one step of iterative refinement with the same factors (residual of the increment
   !! form, correction applied); `error_estimate` = max_k |H_k correction| over all
   !! `points` estimates the remaining error of the values H_k x (it bounds it when
   !! cond eps < 1; the forward error of a band solve grows like the condition number of
   !! W, ~N^4 for a beam's stiffness). stat = 2 when a factorization fails.
   subroutine solve_held(self, x_free, points, held, target, x, multiplier, error_estimate, tally, stat, errmsg)
      class(contact_system), intent(inout) :: self
      real(dp), intent(in) :: x_free(:)
      integer, intent(in) :: points(:)
      logical, intent(in) :: held(:)
      real(dp), intent(in) :: target(:)
      real(dp), intent(out) :: x(:), multiplier(:)
      real(dp), intent(out) :: error_estimate
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, allocatable :: held_points(:)
      real(dp), allocatable :: held_target(:), held_multiplier(:), increment(:), correction(:), w_increment(:), &
                               correction_multiplier(:)
      integer :: k
      stat = 0
      errmsg = ''
      x = x_free
      multiplier = 0
      error_estimate = 0
      held_points = pack(points, held)
      if (size(held_points) == 0) return
      held_target = pack(target, held)
      allocate (held_multiplier(size(held_points)), increment(size(x_free)), correction(size(x_free)))
      ! constraint defects of x_free: the increment must close them
      do k = 1, size(held_points)
         held_target(k) = held_target(k) - contact_value(self%contacts, held_points(k), x_free)
      end do
      tally%linear_solves = tally%linear_solves + 2   ! the solve and its refinement
      if (self%regime == regime_delassus) then
         call solve_delassus(self, held_points, held_target, held_multiplier, correction, tally, stat, errmsg)
         if (stat /= 0) return
         do k = 1, size(held_points)
            x = x + held_multiplier(k)*self%response(:, held_points(k))
         end do
      else if (self%unit_rows) then
         call solve_reduced(self, held_points, held_target, increment, held_multiplier, correction, tally, stat, errmsg)
         if (stat /= 0) return
         x = x_free + increment
      else
         if (.not. self%saddle%holds(held_points)) then
            call self%saddle%factor(self%metric, self%contacts, held_points, stat, errmsg)
            tally%factorizations = tally%factorizations + 1
            if (stat /= 0) return
         end if
         ! [W, -H^T; -H, 0] [d; P] = [0; -(t - H x_free)], then the same system for the
         ! residual [-(W d - H^T P); H d - (t - H x_free)]
         allocate (w_increment(size(x_free)), correction_multiplier(size(held_points)))
         call self%saddle%solve([(0.0_dp, k=1, self%unknowns)], -held_target, increment, held_multiplier, &
                                stat, errmsg)
         if (stat /= 0) return
         call band_matvec(self%metric, increment, w_increment)
         correction = 0
         call scatter_rows(self%contacts, held_points, held_multiplier, correction)
         w_increment = correction - w_increment
         do k = 1, size(held_points)
            correction_multiplier(k) = contact_value(self%contacts, held_points(k), increment) - held_target(k)
         end do
         call self%saddle%solve(w_increment, correction_multiplier, correction, held_target, stat, errmsg)
         if (stat /= 0) return
         increment = increment + correction
         held_multiplier = held_multiplier + held_target   ! (held_target now holds the multipliers' correction)
         x = x_free + increment
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
         stat = 2
         return
      end if
      multiplier = multiplier + residual
      correction = 0
      do k = 1, n
         correction = correction + residual(k)*self%response(:, points(k))
      end do
   end subroutine solve_delassus

   !> Unit rows: the held unknowns j_k take x_free(j_k) + defect(k); the others solve
   !! W_RR d_R = -W_RH d_H with the band factor of the principal submatrix W_RR; the
   !! multipliers are P_k = (W d)_{j_k}, so that W d = H^T P holds row by row.
   subroutine solve_reduced(self, points, defect, increment, multiplier, correction, tally, stat, errmsg)
      type(contact_system), intent(inout) :: self
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: defect(:)
      real(dp), intent(out) :: increment(:), multiplier(:), correction(:)
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: reduced_rhs(:), w_increment(:)
      integer :: k, i, free_count, pass
      stat = 0
      errmsg = ''
      if (.not. same_list(self%reduced_points, points)) then
         call factor_reduced(self, points, stat, errmsg)
         tally%factorizations = tally%factorizations + 1
         if (stat /= 0) return
      end if
      increment = 0
      do k = 1, size(points)
         increment(self%contacts%dofs(1, points(k))) = defect(k)
      end do
      allocate (w_increment(size(increment)))
      free_count = count(self%reduced_index > 0)
      allocate (reduced_rhs(free_count))
      ! pass 1: W_RR d_R = -W_RH d_H; pass 2: the same for the residual -(W d)_R, added
      correction = 0
      do pass = 1, 2
         call band_matvec(self%metric, increment, w_increment)
         do i = 1, self%unknowns
            if (self%reduced_index(i) > 0) reduced_rhs(self%reduced_index(i)) = -w_increment(i)
         end do
         if (free_count > 0) call dpbtrs('L', free_count, self%reduced_kd, 1, self%reduced_factor, &
                                         self%reduced_kd + 1, reduced_rhs, free_count, stat)
         if (stat /= 0) then
            write (errmsg, '(a,i0)') 'reduced band solve (dpbtrs) failed: info = ', stat
            stat = 2
            return
         end if
         do i = 1, self%unknowns
            if (self%reduced_index(i) > 0) then
               if (pass == 2) correction(i) = reduced_rhs(self%reduced_index(i))
               increment(i) = increment(i) + reduced_rhs(self%reduced_index(i))
            end if
         end do
      end do
      call band_matvec(self%metric, increment, w_increment)
      do k = 1, size(points)
         multiplier(k) = w_increment(self%contacts%dofs(1, points(k)))
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
         stat = 2
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
         stat = 2
      end if
   end subroutine factor_barrier

   !> increment(k) = H_k (W + H^T D H)^-1 H^T rho with the factor of `factor_barrier`.
   subroutine solve_barrier(self, points, rho, increment, tally)
      class(contact_system), intent(in) :: self
      integer, intent(in) :: points(:)
      real(dp), intent(in) :: rho(:)
      real(dp), intent(out) :: increment(:)
      type(solve_tally), intent(inout) :: tally
      real(dp) :: v(self%unknowns)
      integer :: k, info
      tally%linear_solves = tally%linear_solves + 1
      v = 0
      call scatter_rows(self%contacts, points, rho, v)
      call dpbtrs('L', self%unknowns, self%barrier_kd, 1, self%barrier_factor, self%barrier_kd + 1, v, &
                  self%unknowns, info)
      do k = 1, size(points)
         increment(k) = contact_value(self%contacts, points(k), v)
      end do
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
