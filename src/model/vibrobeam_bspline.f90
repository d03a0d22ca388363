!> Cubic B-splines on a uniform open knot vector (theory §2, the paper's second family).
!!
!! Knots t_1..t_{N+7}: four at 0, the interior nodes h, 2h, ..., (N-1)h, four at L. The
!! N+3 basis functions B_1..B_{N+3} (B_i supported on [t_i, t_{i+4}]) are C^2 piecewise
!! cubics; on element e = [x_{e-1}, x_e] = [t_{e+3}, t_{e+4}] the nonzero ones are
!! B_e..B_{e+3}. Values and derivatives come from the Cox-de Boor recursion
!! (de Boor, A Practical Guide to Splines, 1978): degree-p functions from degree p-1 ones,
!! and B'_{i,p} = p B_{i,p-1}/(t_{i+p} - t_i) - p B_{i+1,p-1}/(t_{i+p+1} - t_{i+1}).
module vibrobeam_bspline
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: bspline_knots, bspline_shape

contains

   !> The open uniform knot vector of N elements on [0, L] (N + 7 knots).
   pure function bspline_knots(elements, length) result(t)
      integer, intent(in) :: elements
      real(dp), intent(in) :: length
      real(dp) :: t(elements + 7)
      integer :: k
      t(1:4) = 0
      do k = 1, elements - 1
         t(4 + k) = length*k/elements
      end do
      t(elements + 4:elements + 7) = length
   end function bspline_knots

   !> Derivative of order `order` (0, 1 or 2) at x of the four cubic B-splines B_e..B_{e+3}
   !! that are nonzero on element e, using the polynomial piece of that element (so x at
   !! either end of the element gives the one-sided limit from inside it).
   pure function bspline_shape(t, e, x, order) result(values)
      real(dp), intent(in) :: t(:)     !! knots (N + 7)
      integer, intent(in) :: e         !! element, 1..N
      real(dp), intent(in) :: x        !! position (m)
      integer, intent(in) :: order     !! 0, 1 or 2
      real(dp) :: values(4)
      ! table(i, p): B_{s-3+i-1, p}(x) for i = 1..4, the functions of degree p that can
      ! be nonzero on span s = e + 3 (entries with i < 4 - p are zero)
      real(dp) :: table(4, 0:3)
      integer :: s, p, i, index
      s = e + 3
      table = 0
      table(4, 0) = 1
      do p = 1, 3
         do i = 4 - p, 4
            index = s - 4 + i   ! basis index of table row i
            table(i, p) = weight_left(index, p)*table(i, p - 1)
         end do
         do i = 4 - p, 3
            index = s - 4 + i
            table(i, p) = table(i, p) + weight_right(index, p)*table(i + 1, p - 1)
         end do
      end do
      select case (order)
      case (0)
         values = table(:, 3)
      case (1)
         values = derivative(3, table(:, 2))
      case default
         values = derivative(3, derivative(2, table(:, 1)))
      end select
   contains
      !> (x - t_i)/(t_{i+p} - t_i), 0 when the knots coincide.
      pure real(dp) function weight_left(i, p)
         integer, intent(in) :: i, p
         weight_left = 0
         if (t(i + p) > t(i)) weight_left = (x - t(i))/(t(i + p) - t(i))
      end function weight_left
      !> (t_{i+p+1} - x)/(t_{i+p+1} - t_{i+1}), 0 when the knots coincide.
      pure real(dp) function weight_right(i, p)
         integer, intent(in) :: i, p
         weight_right = 0
         if (t(i + p + 1) > t(i + 1)) weight_right = (t(i + p + 1) - x)/(t(i + p + 1) - t(i + 1))
      end function weight_right
      !> Derivatives of the degree-p functions of rows 1..4 from (derivatives of) the
      !! degree p-1 ones `lower` on the same rows.
      pure function derivative(p, lower) result(d)
         integer, intent(in) :: p
         real(dp), intent(in) :: lower(4)
         real(dp) :: d(4)
         integer :: row, basis
         d = 0
         do row = 1, 4
            basis = s - 4 + row
            if (t(basis + p) > t(basis)) d(row) = d(row) + p*lower(row)/(t(basis + p) - t(basis))
         end do
         do row = 1, 3
            basis = s - 4 + row
            if (t(basis + p + 1) > t(basis + 1)) d(row) = d(row) - p*lower(row + 1)/(t(basis + p + 1) - t(basis + 1))
         end do
      end function derivative
   end function bspline_shape
end module vibrobeam_bspline
