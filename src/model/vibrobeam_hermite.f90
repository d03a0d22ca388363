!> Hermite cubic beam element (theory §2): shape functions and element matrices.
!!
!! On an element [x_e, x_e + h] with local coordinate xi = (x - x_e)/h in [0, 1], the four
!! degrees of freedom are (w_left, theta_left, w_right, theta_right), w the displacement
!! and theta = u_x the rotation at the element's end nodes.
module vibrobeam_hermite
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: hermite_shape, hermite_element_mass, hermite_element_stiffness, hermite_element_tension

contains

   !> Derivative of order `order` (0, 1 or 2) with respect to x of the four Hermite shape
   !! functions at local coordinate xi on an element of length h.
   pure function hermite_shape(xi, h, order) result(n)
      real(dp), intent(in) :: xi   !! local coordinate in [0, 1]
      real(dp), intent(in) :: h    !! element length (m)
      integer, intent(in) :: order !! 0, 1 or 2
      real(dp) :: n(4)
      select case (order)
      case (0)
         n = [1 - 3*xi**2 + 2*xi**3, h*(xi - 2*xi**2 + xi**3), 3*xi**2 - 2*xi**3, h*(xi**3 - xi**2)]
      case (1)
         n = [(6*xi**2 - 6*xi)/h, 1 - 4*xi + 3*xi**2, (6*xi - 6*xi**2)/h, 3*xi**2 - 2*xi]
      case default
         n = [(12*xi - 6)/h**2, (6*xi - 4)/h, (6 - 12*xi)/h**2, (6*xi - 2)/h]
      end select
   end function hermite_shape

   !> Consistent element mass matrix for rho S = 1 (theory §2): h/420 [156 22h 54 -13h; ...].
   pure function hermite_element_mass(h) result(m)
      real(dp), intent(in) :: h   !! element length (m)
      real(dp) :: m(4, 4)
      m = reshape([156*h, 22*h**2, 54*h, -13*h**2, &
                   22*h**2, 4*h**3, 13*h**2, -3*h**3, &
                   54*h, 13*h**2, 156*h, -22*h**2, &
                   -13*h**2, -3*h**3, -22*h**2, 4*h**3], [4, 4])/420.0_dp
   end function hermite_element_mass

   !> Element stiffness matrix for E I = 1 (theory §2): 1/h^3 [12 6h -12 6h; ...].
   pure function hermite_element_stiffness(h) result(k)
      real(dp), intent(in) :: h   !! element length (m)
      real(dp) :: k(4, 4)
      k = reshape([12.0_dp, 6*h, -12.0_dp, 6*h, &
                   6*h, 4*h**2, -6*h, 2*h**2, &
                   -12.0_dp, -6*h, 12.0_dp, -6*h, &
                   6*h, 2*h**2, -6*h, 4*h**2], [4, 4])/h**3
   end function hermite_element_stiffness

   !> Geometric stiffness of an axial force T = 1 (theory §1, "Supports, masses, sections,
   !! tension"): int N_a' N_b' dx over the element, exact: 1/(30 h) [36 3h -36 3h;
   !! 3h 4h^2 -3h -h^2; -36 -3h 36 -3h; 3h -h^2 -3h 4h^2].
   pure function hermite_element_tension(h) result(k)
      real(dp), intent(in) :: h   !! element length (m)
      real(dp) :: k(4, 4)
      k = reshape([36.0_dp, 3*h, -36.0_dp, 3*h, &
                   3*h, 4*h**2, -3*h, -h**2, &
                   -36.0_dp, -3*h, 36.0_dp, -3*h, &
                   3*h, -h**2, -3*h, 4*h**2], [4, 4])/(30*h)
   end function hermite_element_tension
end module vibrobeam_hermite
