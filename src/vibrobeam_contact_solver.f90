!> The contact projection (SPEC §3 step 3, §4 and the static problem): for a metric W
!! (symmetric positive definite band matrix) and constraints k = 1..m on rows H_k of the
!! contact set, find
!!
!!     x = argmin 1/2 (x - x_free)^T W (x - x_free)   subject to   s_k (H_k x - b_k) >= 0,
!!
!! equivalently x = x_free + W^-1 sum_k H_k^T P_k with the complementarity conditions
!! 0 <= s_k P_k  _|_  s_k (H_k x - b_k) >= 0. P_k is the impulse (dynamics) or the force
!! (statics) the obstacle exerts on the beam at contact point c_k.
!!
!! Two regimes (issue 3), chosen from the number of contact points of the scene:
!! - 'delassus': the columns W^-1 H_c^T of every contact point are computed once per run
!!   (one band solve each) and cached; a step builds the small Delassus matrix
!!   A = S H W^-1 H^T S of its active points and solves LCP(A, q) with `solve_lcp`
!!   (block principal pivoting, Murty fallback). Cost O(J m) per step.
!! - 'band': the same block principal pivoting, but every trial set is solved through the
!!   sparse saddle-point system [W, -H_F^T; -H_F, 0] [x; P_F] = [W x_free; -b_F], whose
!!   unknowns are ordered so that each multiplier sits next to its last degree of
!!   freedom: the system stays banded (LAPACK dgbtrf/dgbtrs), cost O(J) per pivoting
!!   iteration, never a dense J x J or m x m matrix; the factors are reused while the set
!!   of held points does not change. Used when a longitudinal obstacle gives many contact
!!   points.
module vibrobeam_contact_solver
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_solve, band_matvec
   use vibrobeam_contact_points, only: contact_set, contact_value, no_bound
   use vibrobeam_lcp, only: solve_lcp
   implicit none
   private
   public :: contact_projector, regime_delassus, regime_band, delassus_limit

   integer, parameter :: regime_delassus = 1, regime_band = 2
   !> Largest number of contact points for which 'auto' caches the Delassus columns
   !! (measured, verification/benchmark: with every point active the band regime is
   !! already 1.3 times faster at 16 points and 4.7 times faster at 64; a scene with a
   !! few stops keeps the cached columns, which need no factorization per step).
   integer, parameter :: delassus_limit = 16
   !> Consecutive block pivots without progress before the single-pivot (Murty) rule.
   integer, parameter :: block_pivot_patience = 3

   !> What the projection needs about the scene, set up once per run.
   type :: contact_projector
      integer :: regime = regime_delassus
      integer :: unknowns = 0
      type(symmetric_band) :: metric              !! W
      type(band_cholesky) :: metric_factor        !! Cholesky factor of W
      type(contact_set) :: contacts
      real(dp), allocatable :: response(:,:)      !! (J, contacts) W^-1 H_c^T ('delassus')
      integer :: max_iterations = 0               !! 0: default of each regime
      ! 'band' regime: LU factors of the last trial set's saddle-point matrix, reused while
      ! the set of contact points held does not change
      integer, allocatable :: factored_points(:)          !! contact points of that set
      integer, allocatable :: factored_dof_position(:)    !! row of each unknown
      integer, allocatable :: factored_multiplier_position(:)   !! row of each multiplier
      real(dp), allocatable :: factored_lu(:,:)           !! dgbtrf factors
      integer, allocatable :: factored_pivots(:)
      integer :: factored_width = 0                       !! kl = ku of the ordered system
   contains
      procedure :: setup
      procedure :: project
      procedure :: project_admissible
   end type contact_projector

contains

   !> Prepare the projection for metric W (with its Cholesky factor) and the contact set.
   !! regime: 'auto' (Delassus up to `delassus_limit` contact points, band beyond),
   !! 'delassus' or 'band'.
   subroutine setup(self, metric, metric_factor, contacts, regime)
      class(contact_projector), intent(inout) :: self
      type(symmetric_band), intent(in) :: metric
      type(band_cholesky), intent(in) :: metric_factor
      type(contact_set), intent(in) :: contacts
      character(len=*), intent(in) :: regime
      integer :: c, a
      self%unknowns = metric%n
      self%metric = metric
      self%metric_factor = metric_factor
      self%contacts = contacts
      select case (regime)
      case ('delassus')
         self%regime = regime_delassus
      case ('band')
         self%regime = regime_band
      case default
         self%regime = merge(regime_delassus, regime_band, contacts%count <= delassus_limit)
      end select
      if (allocated(self%response)) deallocate (self%response)
      if (self%regime == regime_delassus) then
         allocate (self%response(metric%n, contacts%count), source=0.0_dp)
         do c = 1, contacts%count
            do a = 1, 4
               if (contacts%dofs(a, c) /= 0) self%response(contacts%dofs(a, c), c) = contacts%weights(a, c)
            end do
         end do
         do c = 1, contacts%count
            call band_solve(metric_factor, self%response(:, c))
         end do
      end if
   end subroutine setup

   !> Solve the projection for the constraints k = 1..m on contact points active(k) with
   !! signs s(k) (+1: from below, -1: from above) and offsets b(k).
   !! stat: 0 ok; 1 no convergence; 2 linear solver failure; 3 residual check failed.
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
      x = x_free
      impulse = 0
      iterations = 0
      stat = 0
      errmsg = ''
      if (size(active) == 0) return
      if (self%regime == regime_delassus) then
         call project_delassus(self, x_free, active, s, b, x, impulse, iterations, stat, errmsg)
      else
         call project_band(self, x_free, active, s, b, x, impulse, iterations, stat, errmsg)
      end if
   end subroutine project

   !> Projection onto the whole admissible set {lower(c) <= H_c x <= upper(c), every
   !! contact point c} (statics, SPEC §4's position projection). Each point may bound from
   !! below and above; the side that can be active is the one a solution violates, so we
   !! start from the points x_free violates and add (or switch the side of) every point a
   !! solution still violates, until none does. multiplier(c) = P_c, 0 off contact.
   subroutine project_admissible(self, x_free, x, multiplier, iterations, stat, errmsg)
      class(contact_projector), intent(inout) :: self
      real(dp), intent(in) :: x_free(:)
      real(dp), intent(out) :: x(:)
      real(dp), intent(out) :: multiplier(:)     !! (contacts%count)
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: value, scale
      real(dp), allocatable :: signs(:), offsets(:), impulse(:)
      integer, allocatable :: side(:), active(:)
      integer :: c, round, solver_iterations, m
      logical :: changed
      x = x_free
      multiplier = 0
      iterations = 0
      stat = 0
      errmsg = ''
      if (self%contacts%count == 0) return
      allocate (side(self%contacts%count), source=0)   ! +1 below, -1 above, 0 not a candidate
      ! violations are judged relative to the size of the free solution and of the levels
      scale = maxval(abs(x_free)) + tiny(1.0_dp)
      do c = 1, self%contacts%count
         if (self%contacts%lower(c) > -no_bound) scale = max(scale, abs(self%contacts%lower(c)))
         if (self%contacts%upper(c) < no_bound) scale = max(scale, abs(self%contacts%upper(c)))
      end do
      do round = 1, 2*self%contacts%count + 1
         changed = .false.
         do c = 1, self%contacts%count
            value = contact_value(self%contacts, c, x)
            if (value < self%contacts%lower(c) - 1e-12_dp*scale .and. side(c) /= 1) then
               side(c) = 1
               changed = .true.
            else if (value > self%contacts%upper(c) + 1e-12_dp*scale .and. side(c) /= -1) then
               side(c) = -1
               changed = .true.
            end if
         end do
         if (.not. changed) return
         active = pack([(c, c=1, self%contacts%count)], side /= 0)
         m = size(active)
         signs = real(side(active), dp)
         offsets = merge(self%contacts%lower(active), self%contacts%upper(active), side(active) == 1)
         if (allocated(impulse)) deallocate (impulse)
         allocate (impulse(m))
         call self%project(x_free, active, signs, offsets, x, impulse, solver_iterations, stat, errmsg)
         iterations = iterations + solver_iterations
         if (stat /= 0) return
         multiplier = 0
         multiplier(active) = impulse
      end do
      stat = 1
      errmsg = 'contact projection: the candidate contact set did not settle'
   end subroutine project_admissible


   subroutine project_delassus(self, x_free, active, s, b, x, impulse, iterations, stat, errmsg)
      type(contact_projector), intent(in) :: self
      real(dp), intent(in) :: x_free(:), s(:), b(:)
      integer, intent(in) :: active(:)
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: a(size(active), size(active)), q(size(active)), z(size(active)), w(size(active))
      integer :: k, l, m
      m = size(active)
      do l = 1, m
         do k = 1, m
            a(k, l) = s(k)*s(l)*contact_value(self%contacts, active(k), self%response(:, active(l)))
         end do
         q(l) = s(l)*(contact_value(self%contacts, active(l), x_free) - b(l))
      end do
      a = 0.5_dp*(a + transpose(a))   ! exact symmetry; the two triangles differ by round-off
      if (self%max_iterations > 0) then
         call solve_lcp(a, q, z, w, iterations, stat, errmsg, max_iterations=self%max_iterations)
      else
         call solve_lcp(a, q, z, w, iterations, stat, errmsg)
      end if
      if (stat == 4) stat = 2
      impulse = s*z
      x = x_free
      do l = 1, m
         if (z(l) > 0) x = x + impulse(l)*self%response(:, active(l))
      end do
   end subroutine project_delassus

   !> Block principal pivoting on the banded saddle-point system (see the module comment).
   subroutine project_band(self, x_free, active, s, b, x, impulse, iterations, stat, errmsg)
      type(contact_projector), intent(inout) :: self
      real(dp), intent(in) :: x_free(:), s(:), b(:)
      integer, intent(in) :: active(:)
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(out) :: iterations, stat
      character(len=*), intent(out) :: errmsg
      logical :: in_set(size(active)), infeasible(size(active))
      real(dp) :: gap(size(active)), w_x_free(size(x_free)), gap_scale, impulse_scale, slack
      integer :: m, k, count_infeasible, best, patience, limit
      m = size(active)
      call band_matvec(self%metric, x_free, w_x_free)
      do k = 1, m
         gap(k) = s(k)*(contact_value(self%contacts, active(k), x_free) - b(k))
      end do
      gap_scale = maxval(abs([(contact_value(self%contacts, active(k), x_free), k=1, m)])) + maxval(abs(b))
      gap_scale = max(gap_scale, tiny(1.0_dp))
      slack = max(1e-12_dp, 16*m*epsilon(1.0_dp))
      in_set = gap < 0
      limit = self%max_iterations
      if (limit <= 0) limit = max(100, 10*m)
      best = m + 1
      patience = block_pivot_patience
      iterations = 0
      do
         call solve_trial_set(self, w_x_free, active, b, in_set, x, impulse, stat, errmsg)
         if (stat /= 0) return
         impulse_scale = max(maxval(abs(impulse)), tiny(1.0_dp))
         do k = 1, m
            if (in_set(k)) then
               infeasible(k) = s(k)*impulse(k) < -slack*impulse_scale
            else
               gap(k) = s(k)*(contact_value(self%contacts, active(k), x) - b(k))
               infeasible(k) = gap(k) < -slack*gap_scale
            end if
         end do
         count_infeasible = count(infeasible)
         if (count_infeasible == 0) exit
         if (iterations >= limit) then
            stat = 1
            write (errmsg, '(a,i0,a,i0,a)') 'band contact solver did not converge in ', limit, &
               ' pivoting iterations (', count_infeasible, ' infeasible constraints left)'
            return
         end if
         iterations = iterations + 1
         if (count_infeasible < best) then
            best = count_infeasible
            patience = block_pivot_patience
         else
            patience = patience - 1
         end if
         if (patience > 0) then
            where (infeasible) in_set = .not. in_set
         else
            k = findloc(infeasible, .true., dim=1)   ! Murty: least infeasible index
            in_set(k) = .not. in_set(k)
         end if
      end do
      ! residual check: the constraints held as equalities must hold to the solve's accuracy
      ! (complementarity: P = 0 off the set by construction, gap = 0 on it)
      do k = 1, m
         if (.not. in_set(k)) cycle
         if (abs(contact_value(self%contacts, active(k), x) - b(k)) > 1e-8_dp*gap_scale) then
            stat = 3
            write (errmsg, '(a,i0,a,es10.3)') 'band contact solver: residual check failed at contact point ', &
               active(k), ', |H x - b| = ', abs(contact_value(self%contacts, active(k), x) - b(k))
            return
         end if
      end do
      ! clip the sign of round-off-sized impulses so that s P >= 0 holds exactly. x is kept
      ! from the saddle-point solve, which satisfies the active constraints to round-off;
      ! rebuilding it as x_free + W^-1 H^T P would not (measured: 1.5e-10 relative
      ! penetration in the static test at N = 64) and did not improve the energy balance.
      where (s*impulse < 0) impulse = 0
   end subroutine project_band

   !> Solve [W, -H_F^T; -H_F, 0] [x; P_F] = [W x_free; -b_F], P = 0 outside F, as one
   !! general band system (LAPACK dgbtrf/dgbtrs) with each multiplier ordered right after
   !! the last degree of freedom of its row. The matrix depends only on which contact
   !! points are in F, so its LU factors are kept and reused while F does not change (a
   !! persistent contact: one band back-substitution per step).
   subroutine solve_trial_set(self, w_x_free, active, b, in_set, x, impulse, stat, errmsg)
      type(contact_projector), intent(inout) :: self
      real(dp), intent(in) :: w_x_free(:), b(:)
      integer, intent(in) :: active(:)
      logical, intent(in) :: in_set(:)
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      interface
         subroutine dgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, rhs, ldb, info)
            import :: dp
            character, intent(in) :: trans
            integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
            real(dp), intent(in) :: ab(ldab, *)
            integer, intent(in) :: ipiv(*)
            real(dp), intent(inout) :: rhs(ldb, *)
            integer, intent(out) :: info
         end subroutine dgbtrs
      end interface
      integer, allocatable :: points(:)
      real(dp), allocatable :: rhs(:)
      integer :: i, k, n_set, total
      stat = 0
      errmsg = ''
      points = pack(active, in_set)
      if (.not. same_points(self%factored_points, points)) then
         call factor_trial_set(self, points, stat, errmsg)
         if (stat /= 0) return
      end if
      total = self%unknowns + size(points)
      allocate (rhs(total))
      do i = 1, self%unknowns
         rhs(self%factored_dof_position(i)) = w_x_free(i)
      end do
      n_set = 0
      do k = 1, size(active)
         if (.not. in_set(k)) cycle
         n_set = n_set + 1
         rhs(self%factored_multiplier_position(n_set)) = -b(k)
      end do
      call dgbtrs('N', total, self%factored_width, self%factored_width, 1, self%factored_lu, &
                  3*self%factored_width + 1, self%factored_pivots, rhs, total, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'band saddle-point solve (dgbtrs) failed: info = ', stat
         stat = 2
         return
      end if
      do i = 1, self%unknowns
         x(i) = rhs(self%factored_dof_position(i))
      end do
      impulse = 0
      n_set = 0
      do k = 1, size(active)
         if (.not. in_set(k)) cycle
         n_set = n_set + 1
         impulse(k) = rhs(self%factored_multiplier_position(n_set))
      end do
   contains
      pure logical function same_points(cached, wanted)
         integer, allocatable, intent(in) :: cached(:)
         integer, intent(in) :: wanted(:)
         same_points = .false.
         if (.not. allocated(cached)) return
         if (size(cached) /= size(wanted)) return
         same_points = all(cached == wanted)
      end function same_points
   end subroutine solve_trial_set

   !> Order, assemble and LU-factor (LAPACK dgbtrf) the saddle-point matrix of the contact
   !! points `points` (the set F, in the order of the active list), and keep the factors.
   subroutine factor_trial_set(self, points, stat, errmsg)
      type(contact_projector), intent(inout) :: self
      integer, intent(in) :: points(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      interface
         subroutine dgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
            import :: dp
            integer, intent(in) :: m, n, kl, ku, ldab
            real(dp), intent(inout) :: ab(ldab, *)
            integer, intent(out) :: ipiv(*), info
         end subroutine dgbtrf
      end interface
      integer :: j, total, kd, i, k, a, width, position, col, row
      integer :: order(size(points)), anchors(size(points))
      j = self%unknowns
      kd = self%metric%kd
      total = j + size(points)
      if (allocated(self%factored_points)) deallocate (self%factored_points)
      if (allocated(self%factored_dof_position)) deallocate (self%factored_dof_position)
      if (allocated(self%factored_multiplier_position)) deallocate (self%factored_multiplier_position)
      if (allocated(self%factored_lu)) deallocate (self%factored_lu)
      if (allocated(self%factored_pivots)) deallocate (self%factored_pivots)
      allocate (self%factored_dof_position(j), self%factored_multiplier_position(size(points)))
      ! anchor of each constraint: the last degree of freedom of its row; order the set by
      ! anchor (insertion sort: the active list is already ordered by node)
      do k = 1, size(points)
         anchors(k) = maxval(self%contacts%dofs(:, points(k)))
         order(k) = k
      end do
      do i = 2, size(order)
         k = order(i)
         a = i - 1
         do while (a >= 1)
            if (anchors(order(a)) <= anchors(k)) exit
            order(a + 1) = order(a)
            a = a - 1
         end do
         order(a + 1) = k
      end do
      position = 0
      a = 1
      do i = 1, j
         position = position + 1
         self%factored_dof_position(i) = position
         do while (a <= size(order))
            if (anchors(order(a)) /= i) exit
            position = position + 1
            self%factored_multiplier_position(order(a)) = position
            a = a + 1
         end do
      end do
      associate (dof_position => self%factored_dof_position, multiplier_position => self%factored_multiplier_position)
         ! bandwidth of the ordered system
         width = 0
         do i = 1, j
            do col = i, min(j, i + kd)
               width = max(width, abs(dof_position(col) - dof_position(i)))
            end do
         end do
         do k = 1, size(points)
            do a = 1, 4
               if (self%contacts%dofs(a, points(k)) /= 0) width = max(width, &
                  abs(multiplier_position(k) - dof_position(self%contacts%dofs(a, points(k)))))
            end do
         end do
         allocate (self%factored_lu(3*width + 1, total), source=0.0_dp)
         allocate (self%factored_pivots(total))
         ! W, read straight from its lower band storage (A(r,c) at lower(1 + r - c, c))
         do col = 1, j
            do row = col, min(j, col + kd)
               call put(dof_position(row), dof_position(col), self%metric%lower(1 + row - col, col))
               if (row /= col) call put(dof_position(col), dof_position(row), self%metric%lower(1 + row - col, col))
            end do
         end do
         do k = 1, size(points)
            do a = 1, 4
               col = self%contacts%dofs(a, points(k))
               if (col == 0) cycle
               call put(dof_position(col), multiplier_position(k), -self%contacts%weights(a, points(k)))
               call put(multiplier_position(k), dof_position(col), -self%contacts%weights(a, points(k)))
            end do
         end do
      end associate
      self%factored_width = width
      call dgbtrf(total, total, width, width, self%factored_lu, 3*width + 1, self%factored_pivots, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'band saddle-point factorization (dgbtrf) failed: info = ', stat
         stat = 2
         deallocate (self%factored_lu)   ! no valid factors: the next call refactors
         return
      end if
      self%factored_points = points
   contains
      subroutine put(r, c, value)
         integer, intent(in) :: r, c
         real(dp), intent(in) :: value
         self%factored_lu(2*width + 1 + r - c, c) = self%factored_lu(2*width + 1 + r - c, c) + value
      end subroutine put
   end subroutine factor_trial_set
end module vibrobeam_contact_solver
