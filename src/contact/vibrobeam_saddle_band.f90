!> The saddle-point system of a contact projection with a set F of constraints held as
!! equalities (theory §5):
!!
!!     [ W     -H_F^T ] [ x   ]   [ r_x ]
!!     [ -H_F   0     ] [ P_F ] = [ r_P ],
!!
!! W the symmetric positive definite band metric, H_F the constraint rows of the contact
!! points in F (any number of nonzeros per row within the band of W). The unknowns are
!! ordered so that each multiplier sits right after the last degree of freedom of its row:
!! the matrix then stays banded (half-bandwidth 4 for Hermite rows, 5 for B-spline rows) and
!! is factored by LAPACK dgbtrf (LU with partial pivoting) and solved by dgbtrs, O(J) per
!! factorization and per solve; no dense J x J or |F| x |F| matrix. The matrix depends only
!! on F, so the factors are kept and reused while F does not change.
module vibrobeam_saddle_band
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_linear_solver_failure
   use vibrobeam_lapack, only: dgbtrf, dgbtrs
   use vibrobeam_band, only: symmetric_band
   use vibrobeam_contact_set, only: contact_set
   implicit none
   private
   public :: saddle_factor

   !> LU factors of the ordered saddle-point matrix of one set F.
   type :: saddle_factor
      integer :: unknowns = 0                         !! J
      integer :: width = 0                            !! kl = ku of the ordered system
      integer, allocatable :: points(:)               !! contact points of F, in the caller's order
      integer, allocatable :: dof_position(:)         !! (J) row of each unknown
      integer, allocatable :: multiplier_position(:)  !! (|F|) row of each multiplier
      real(dp), allocatable :: lu(:,:)                !! dgbtrf factors, (3 width + 1, J + |F|)
      integer, allocatable :: pivots(:)
   contains
      procedure :: holds
      procedure :: factor
      procedure :: solve
      procedure :: forget
   end type saddle_factor


contains

   !> True when valid factors of exactly the set `points` (same order) are held.
   pure logical function holds(self, points)
      class(saddle_factor), intent(in) :: self
      integer, intent(in) :: points(:)
      holds = .false.
      if (.not. (allocated(self%points) .and. allocated(self%lu))) return
      if (size(self%points) /= size(points)) return
      holds = all(self%points == points)
   end function holds

   !> Drop the factors (the next solve of any set factors again).
   pure subroutine forget(self)
      class(saddle_factor), intent(inout) :: self
      if (allocated(self%points)) deallocate (self%points)
      if (allocated(self%lu)) deallocate (self%lu)
   end subroutine forget

   !> Order, assemble and LU-factor the saddle-point matrix of the contact points
   !! `points` (the set F) and keep the factors. stat = stat_linear_solver_failure when dgbtrf fails.
   subroutine factor(self, metric, contacts, points, stat, errmsg)
      class(saddle_factor), intent(inout) :: self
      type(symmetric_band), intent(in) :: metric     !! W
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: points(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: j, total, kd, i, k, a, width, position, col, row
      integer :: order(size(points)), anchors(size(points))
      stat = 0
      errmsg = ''
      j = metric%n
      kd = metric%kd
      total = j + size(points)
      call self%forget()
      self%unknowns = j
      if (allocated(self%dof_position)) deallocate (self%dof_position)
      if (allocated(self%multiplier_position)) deallocate (self%multiplier_position)
      if (allocated(self%pivots)) deallocate (self%pivots)
      allocate (self%dof_position(j), self%multiplier_position(size(points)))
      ! anchor of each constraint: the last degree of freedom of its row; order the set by
      ! anchor (insertion sort: a list ordered by node is already sorted)
      do k = 1, size(points)
         anchors(k) = maxval(contacts%dofs(:, points(k)))
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
         self%dof_position(i) = position
         do while (a <= size(order))
            if (anchors(order(a)) /= i) exit
            position = position + 1
            self%multiplier_position(order(a)) = position
            a = a + 1
         end do
      end do
      associate (dof_position => self%dof_position, multiplier_position => self%multiplier_position)
         ! bandwidth of the ordered system
         width = 0
         do i = 1, j
            do col = i, min(j, i + kd)
               width = max(width, abs(dof_position(col) - dof_position(i)))
            end do
         end do
         do k = 1, size(points)
            do a = 1, 4
               if (contacts%dofs(a, points(k)) /= 0) width = max(width, &
                  abs(multiplier_position(k) - dof_position(contacts%dofs(a, points(k)))))
            end do
         end do
         allocate (self%lu(3*width + 1, total), source=0.0_dp)
         allocate (self%pivots(total))
         ! W, read straight from its lower band storage (A(r,c) at lower(1 + r - c, c))
         do col = 1, j
            do row = col, min(j, col + kd)
               call put(dof_position(row), dof_position(col), metric%lower(1 + row - col, col))
               if (row /= col) call put(dof_position(col), dof_position(row), metric%lower(1 + row - col, col))
            end do
         end do
         do k = 1, size(points)
            do a = 1, 4
               col = contacts%dofs(a, points(k))
               if (col == 0) cycle
               call put(dof_position(col), multiplier_position(k), -contacts%weights(a, points(k)))
               call put(multiplier_position(k), dof_position(col), -contacts%weights(a, points(k)))
            end do
         end do
      end associate
      self%width = width
      call dgbtrf(total, total, width, width, self%lu, 3*width + 1, self%pivots, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'band saddle-point factorization (dgbtrf) failed: info = ', stat
         stat = stat_linear_solver_failure
         deallocate (self%lu)   ! no valid factors: the next call factors again
         return
      end if
      self%points = points
   contains
      subroutine put(r, c, value)
         integer, intent(in) :: r, c
         real(dp), intent(in) :: value
         self%lu(2*width + 1 + r - c, c) = self%lu(2*width + 1 + r - c, c) + value
      end subroutine put
   end subroutine factor

   !> Solve the factored system for the right-hand side (r_x, r_P): r_x (J) on the rows of
   !! W, r_P (|F|) on the constraint rows in the order of `points`. stat = stat_linear_solver_failure on failure.
   subroutine solve(self, rhs_dofs, rhs_multipliers, x, multipliers, stat, errmsg)
      class(saddle_factor), intent(in) :: self
      real(dp), intent(in) :: rhs_dofs(:), rhs_multipliers(:)
      real(dp), intent(out) :: x(:), multipliers(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: rhs(self%unknowns + size(self%points))
      integer :: total
      stat = 0
      errmsg = ''
      total = size(rhs)
      rhs(self%dof_position) = rhs_dofs
      rhs(self%multiplier_position) = rhs_multipliers
      call dgbtrs('N', total, self%width, self%width, 1, self%lu, 3*self%width + 1, self%pivots, rhs, total, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'band saddle-point solve (dgbtrs) failed: info = ', stat
         stat = stat_linear_solver_failure
         return
      end if
      x = rhs(self%dof_position)
      multipliers = rhs(self%multiplier_position)
   end subroutine solve
end module vibrobeam_saddle_band
