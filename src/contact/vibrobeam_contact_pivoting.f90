!> The contact projection by principal pivoting (`&solver contact_method = 'pivoting'`,
!! vibrobeam 0.1; also the last-resort fall-back of the 'newton' method): block principal
!! pivoting (Júdice & Pires, Comput. Oper. Res. 21 (1994)) with Murty's least-index single
!! pivot as the safeguard (Murty, Opsearch 11 (1974)), on the LCP of theory §5 in the
!! variables lambda_k = s_k P_k with the Delassus matrix A = S H W^-1 H^T S:
!!
!! - 'delassus' regime: A is formed from the cached columns W^-1 H_c^T of the active
!!   points and the LCP is solved densely (`solve_lcp`);
!! - 'band' regime: every trial set is solved through the banded saddle-point system
!!   [W, -H_F^T; -H_F, 0] [x; P_F] = [W x_free; -b_F], O(J) per pivot.
!!
!! Finite in exact arithmetic, but each pivot costs a factorization and the number of
!! pivots grows with the number of contact points that change state (docs/method.md,
!! "The contact projection"). Kept as it was, for comparison: in the 'band' regime the
!! impulses of round-off size and the wrong sign are clipped after x is computed.
module vibrobeam_contact_pivoting
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_no_convergence, stat_invalid_argument, stat_linear_solver_failure, stat_residual_check_failed
   use vibrobeam_band, only: band_matvec
   use vibrobeam_contact_set, only: contact_value, no_bound
   use vibrobeam_contact_system, only: contact_system, solve_tally, regime_delassus
   use vibrobeam_lcp, only: solve_lcp
   implicit none
   private
   public :: pivot_project, pivot_admissible

   !> Consecutive block pivots without progress before the single-pivot (Murty) rule.
   integer, parameter :: block_pivot_patience = 3

contains

   !> Projection onto {s_k (H_k x - b_k) >= 0} for the points `active` (see module).
   !! stat: stat_ok; stat_no_convergence within max_iterations (0: the default of each
   !! regime); stat_linear_solver_failure; stat_residual_check_failed.
   subroutine pivot_project(system, x_free, active, s, b, max_iterations, x, impulse, iterations, tally, stat, errmsg)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: x_free(:), s(:), b(:)
      integer, intent(in) :: active(:), max_iterations
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(out) :: iterations, stat
      type(solve_tally), intent(inout) :: tally
      character(len=*), intent(out) :: errmsg
      x = x_free
      impulse = 0
      iterations = 0
      stat = 0
      errmsg = ''
      if (size(active) == 0) return
      if (system%regime == regime_delassus) then
         call pivot_delassus(system, x_free, active, s, b, max_iterations, x, impulse, iterations, tally, stat, errmsg)
      else
         call pivot_band(system, x_free, active, s, b, max_iterations, x, impulse, iterations, tally, stat, errmsg)
      end if
   end subroutine pivot_project

   !> Projection onto the whole admissible set {lower(c) <= H_c x <= upper(c)}: start from
   !! the points x_free violates and add (or switch the side of) every point a solution
   !! still violates, until none does. multiplier(c) = P_c, 0 off contact.
   subroutine pivot_admissible(system, x_free, max_iterations, x, multiplier, iterations, tally, stat, errmsg)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: x_free(:)
      integer, intent(in) :: max_iterations
      real(dp), intent(out) :: x(:)
      real(dp), intent(out) :: multiplier(:)     !! (contacts%count)
      integer, intent(out) :: iterations, stat
      type(solve_tally), intent(inout) :: tally
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
      associate (contacts => system%contacts)
         if (contacts%count == 0) return
         allocate (side(contacts%count), source=0)   ! +1 below, -1 above, 0 not a candidate
         ! violations are judged relative to the size of the free solution and of the levels
         scale = maxval(abs(x_free)) + tiny(1.0_dp)
         do c = 1, contacts%count
            if (contacts%lower(c) > -no_bound) scale = max(scale, abs(contacts%lower(c)))
            if (contacts%upper(c) < no_bound) scale = max(scale, abs(contacts%upper(c)))
         end do
         do round = 1, 2*contacts%count + 1
            changed = .false.
            do c = 1, contacts%count
               value = contact_value(contacts, c, x)
               if (value < contacts%lower(c) - 1e-12_dp*scale .and. side(c) /= 1) then
                  side(c) = 1
                  changed = .true.
               else if (value > contacts%upper(c) + 1e-12_dp*scale .and. side(c) /= -1) then
                  side(c) = -1
                  changed = .true.
               end if
            end do
            if (.not. changed) return
            active = pack([(c, c=1, contacts%count)], side /= 0)
            m = size(active)
            signs = real(side(active), dp)
            offsets = merge(contacts%lower(active), contacts%upper(active), side(active) == 1)
            if (allocated(impulse)) deallocate (impulse)
            allocate (impulse(m))
            call pivot_project(system, x_free, active, signs, offsets, max_iterations, x, impulse, solver_iterations, &
                               tally, stat, errmsg)
            iterations = iterations + solver_iterations
            if (stat /= 0) return
            multiplier = 0
            multiplier(active) = impulse
         end do
      end associate
      stat = stat_no_convergence
      errmsg = 'contact projection: the candidate contact set did not settle'
   end subroutine pivot_admissible

   subroutine pivot_delassus(system, x_free, active, s, b, max_iterations, x, impulse, iterations, tally, stat, errmsg)
      type(contact_system), intent(in) :: system
      real(dp), intent(in) :: x_free(:), s(:), b(:)
      integer, intent(in) :: active(:), max_iterations
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(out) :: iterations, stat
      type(solve_tally), intent(inout) :: tally
      character(len=*), intent(out) :: errmsg
      real(dp) :: a(size(active), size(active)), q(size(active)), z(size(active)), w(size(active))
      integer :: k, l, m
      m = size(active)
      do l = 1, m
         do k = 1, m
            a(k, l) = s(k)*s(l)*contact_value(system%contacts, active(k), system%response(:, active(l)))
         end do
         q(l) = s(l)*(contact_value(system%contacts, active(l), x_free) - b(l))
      end do
      a = 0.5_dp*(a + transpose(a))   ! exact symmetry; the two triangles differ by round-off
      if (max_iterations > 0) then
         call solve_lcp(a, q, z, w, iterations, stat, errmsg, max_iterations=max_iterations)
      else
         call solve_lcp(a, q, z, w, iterations, stat, errmsg)
      end if
      ! one dense Cholesky solve per pivot and the first trial set
      tally%linear_solves = tally%linear_solves + iterations + 1
      tally%factorizations = tally%factorizations + iterations + 1
      if (stat == stat_invalid_argument) stat = stat_linear_solver_failure
      impulse = s*z
      x = x_free
      do l = 1, m
         if (z(l) > 0) x = x + impulse(l)*system%response(:, active(l))
      end do
   end subroutine pivot_delassus

   !> Block principal pivoting on the banded saddle-point system (see the module comment).
   subroutine pivot_band(system, x_free, active, s, b, max_iterations, x, impulse, iterations, tally, stat, errmsg)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: x_free(:), s(:), b(:)
      integer, intent(in) :: active(:), max_iterations
      real(dp), intent(out) :: x(:), impulse(:)
      integer, intent(out) :: iterations, stat
      type(solve_tally), intent(inout) :: tally
      character(len=*), intent(out) :: errmsg
      logical :: in_set(size(active)), infeasible(size(active))
      real(dp) :: gap(size(active)), w_x_free(size(x_free)), gap_scale, impulse_scale, slack
      integer :: m, k, count_infeasible, best, patience, limit
      m = size(active)
      call band_matvec(system%metric, x_free, w_x_free)
      do k = 1, m
         gap(k) = s(k)*(contact_value(system%contacts, active(k), x_free) - b(k))
      end do
      gap_scale = maxval(abs([(contact_value(system%contacts, active(k), x_free), k=1, m)])) + maxval(abs(b))
      gap_scale = max(gap_scale, tiny(1.0_dp))
      slack = max(1e-12_dp, 16*m*epsilon(1.0_dp))
      in_set = gap < 0
      limit = max_iterations
      if (limit <= 0) limit = max(100, 10*m)
      best = m + 1
      patience = block_pivot_patience
      iterations = 0
      do
         call solve_trial_set(system, w_x_free, active, b, in_set, x, impulse, tally, stat, errmsg)
         if (stat /= 0) return
         impulse_scale = max(maxval(abs(impulse)), tiny(1.0_dp))
         do k = 1, m
            if (in_set(k)) then
               infeasible(k) = s(k)*impulse(k) < -slack*impulse_scale
            else
               gap(k) = s(k)*(contact_value(system%contacts, active(k), x) - b(k))
               infeasible(k) = gap(k) < -slack*gap_scale
            end if
         end do
         count_infeasible = count(infeasible)
         if (count_infeasible == 0) exit
         if (iterations >= limit) then
            stat = stat_no_convergence
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
      do k = 1, m
         if (.not. in_set(k)) cycle
         if (abs(contact_value(system%contacts, active(k), x) - b(k)) > 1e-8_dp*gap_scale) then
            stat = stat_residual_check_failed
            write (errmsg, '(a,i0,a,es10.3)') 'band contact solver: residual check failed at contact point ', &
               active(k), ', |H x - b| = ', abs(contact_value(system%contacts, active(k), x) - b(k))
            return
         end if
      end do
      ! clip the sign of round-off-sized impulses so that s P >= 0 holds (x is kept from
      ! the saddle-point solve: this is the inconsistency the 'newton' method removes)
      where (s*impulse < 0) impulse = 0
   end subroutine pivot_band

   !> Solve [W, -H_F^T; -H_F, 0] [x; P_F] = [W x_free; -b_F], P = 0 outside F.
   subroutine solve_trial_set(system, w_x_free, active, b, in_set, x, impulse, tally, stat, errmsg)
      type(contact_system), intent(inout) :: system
      real(dp), intent(in) :: w_x_free(:), b(:)
      integer, intent(in) :: active(:)
      logical, intent(in) :: in_set(:)
      real(dp), intent(out) :: x(:), impulse(:)
      type(solve_tally), intent(inout) :: tally
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, allocatable :: points(:)
      real(dp), allocatable :: held_impulse(:)
      points = pack(active, in_set)
      if (.not. system%saddle%holds(points)) then
         call system%saddle%factor(system%metric, system%contacts, points, stat, errmsg)
         tally%factorizations = tally%factorizations + 1
         if (stat /= 0) return
      end if
      tally%linear_solves = tally%linear_solves + 1
      allocate (held_impulse(size(points)))
      call system%saddle%solve(w_x_free, -pack(b, in_set), x, held_impulse, stat, errmsg)
      if (stat /= 0) return
      impulse = 0
      impulse = unpack(held_impulse, in_set, impulse)
   end subroutine solve_trial_set
end module vibrobeam_contact_pivoting
