!> The discrete beam model (SPEC §2): mesh, unknowns, banded mass and stiffness matrices,
!! load vectors and the map from unknowns to the displacement at a point.
!!
!! Hermite cubic elements: the unknowns are (w_1, theta_1, ..., w_N, theta_N) (node 0 is
!! clamped and carries no unknown), so M and K have 3 sub-diagonals. Every matrix is kept
!! in LAPACK band storage (`vibrobeam_band`).
module vibrobeam_model
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_allocate, band_add
   use vibrobeam_hermite, only: hermite_shape, hermite_element_mass, hermite_element_stiffness
   implicit none
   private
   public :: beam_model, build_model, element_dofs, point_row, node_row, nodal_displacement
   public :: load_vector, point_load_vector, interpolate_field, space_profile

   integer, parameter :: bandwidth = 3   !! sub-diagonals of M and K for both bases

   !> 4-point Gauss-Legendre rule on [0, 1] (exact for polynomials of degree 7, hence for
   !! every Hermite mass and stiffness integrand and for loads that are cubic in x).
   real(dp), parameter :: gauss_points(4) = 0.5_dp + 0.5_dp*[-0.861136311594052575_dp, &
      -0.339981043584856265_dp, 0.339981043584856265_dp, 0.861136311594052575_dp]
   real(dp), parameter :: gauss_weights(4) = 0.5_dp*[0.347854845137453857_dp, &
      0.652145154862546143_dp, 0.652145154862546143_dp, 0.347854845137453857_dp]

   !> What the discretized beam is.
   type :: beam_model
      character(len=16) :: basis = 'hermite'  !! 'hermite'
      integer :: elements = 0      !! N
      integer :: unknowns = 0      !! J = 2N for Hermite elements
      real(dp) :: length = 0       !! L (m)
      real(dp) :: h = 0            !! element length L/N (m)
      real(dp) :: rho_s = 1        !! mass per unit length rho S (kg/m)
      real(dp) :: ei = 1           !! bending stiffness E I (N m^2)
      real(dp), allocatable :: x(:)          !! node positions x_0..x_N (m), index 1..N+1
      type(symmetric_band) :: mass           !! M, (J x J, 3 sub-diagonals)
      type(symmetric_band) :: stiffness      !! K, (J x J, 3 sub-diagonals)
   end type beam_model

   abstract interface
      !> A load's distribution along the beam (dimensionless factor of the amplitude).
      pure function space_profile(x) result(value)
         import :: dp
         real(dp), intent(in) :: x
         real(dp) :: value
      end function space_profile
   end interface

contains

   !> Assemble the model of a clamped-free beam of `elements` Hermite elements.
   subroutine build_model(basis, elements, length, rho_s, ei, model, stat, errmsg)
      character(len=*), intent(in) :: basis  !! 'hermite'
      integer, intent(in) :: elements        !! N >= 1
      real(dp), intent(in) :: length         !! L > 0 (m)
      real(dp), intent(in) :: rho_s          !! rho S > 0 (kg/m)
      real(dp), intent(in) :: ei             !! E I > 0 (N m^2)
      type(beam_model), intent(out) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: element_mass(4, 4), element_stiffness(4, 4)
      integer :: e, a, b, dofs(4), i
      stat = 0
      errmsg = ''
      if (basis /= 'hermite') then
         stat = 1
         errmsg = 'basis '''//trim(basis)//''' is not available'
         return
      end if
      model%basis = basis
      model%elements = elements
      model%unknowns = 2*elements
      model%length = length
      model%h = length/elements
      model%rho_s = rho_s
      model%ei = ei
      model%x = [(length*i/elements, i=0, elements)]
      call band_allocate(model%mass, model%unknowns, bandwidth)
      call band_allocate(model%stiffness, model%unknowns, bandwidth)
      element_mass = rho_s*hermite_element_mass(model%h)
      element_stiffness = ei*hermite_element_stiffness(model%h)
      do e = 1, elements
         dofs = element_dofs(e)
         do b = 1, 4
            do a = b, 4
               if (dofs(a) == 0 .or. dofs(b) == 0) cycle
               call band_add(model%mass, dofs(a), dofs(b), element_mass(a, b))
               call band_add(model%stiffness, dofs(a), dofs(b), element_stiffness(a, b))
            end do
         end do
      end do
   end subroutine build_model

   !> Global unknowns of element e (1..N) in the order of `hermite_shape`; 0 marks a
   !! clamped degree of freedom (node 0), which has no unknown.
   pure function element_dofs(e) result(dofs)
      integer, intent(in) :: e
      integer :: dofs(4)
      dofs = [2*e - 3, 2*e - 2, 2*e - 1, 2*e]
      if (e == 1) dofs(1:2) = 0
   end function element_dofs

   !> The displacement at x as a combination of unknowns: u_h(x) = sum(weights * U(dofs)),
   !! where a dof of 0 (clamped) contributes nothing. `order` 1 or 2 gives u_x, u_xx.
   pure subroutine point_row(model, x, dofs, weights, order)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: x             !! position in [0, L] (m)
      integer, intent(out) :: dofs(4)
      real(dp), intent(out) :: weights(4)
      integer, intent(in), optional :: order
      integer :: e, derivative
      derivative = 0
      if (present(order)) derivative = order
      e = min(model%elements, max(1, floor(x/model%h) + 1))
      dofs = element_dofs(e)
      weights = hermite_shape((x - model%x(e))/model%h, model%h, derivative)
      where (dofs == 0) weights = 0
   end subroutine point_row

   !> The displacement at node i (1..N) as a combination of unknowns, like `point_row`
   !! but exact: for Hermite elements u_h(x_i) = w_i is an unknown itself (SPEC §2).
   pure subroutine node_row(node, dofs, weights)
      integer, intent(in) :: node
      integer, intent(out) :: dofs(4)
      real(dp), intent(out) :: weights(4)
      dofs = [2*node - 1, 0, 0, 0]
      weights = [1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
   end subroutine node_row

   !> Displacement at the N+1 nodes (node 0 included, where it is 0) from the unknowns.
   pure function nodal_displacement(model, u) result(w)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: u(:)   !! (J) unknowns
      real(dp) :: w(model%elements + 1)
      w(1) = 0
      w(2:) = u(1:model%unknowns:2)
   end function nodal_displacement

   !> Consistent load vector F_j = integral over (0, L) of profile(x) phi_j(x) dx, by
   !! 4-point Gauss quadrature per element (exact for profiles of degree <= 4).
   function load_vector(model, profile) result(f)
      type(beam_model), intent(in) :: model
      procedure(space_profile) :: profile
      real(dp) :: f(model%unknowns)
      integer :: e, g, dofs(4), a
      real(dp) :: n(4), x
      f = 0
      do e = 1, model%elements
         dofs = element_dofs(e)
         do g = 1, 4
            x = model%x(e) + gauss_points(g)*model%h
            n = hermite_shape(gauss_points(g), model%h, 0)
            do a = 1, 4
               if (dofs(a) /= 0) f(dofs(a)) = f(dofs(a)) + gauss_weights(g)*model%h*profile(x)*n(a)
            end do
         end do
      end do
   end function load_vector

   !> Load vector of a unit point force at x (the virtual work of the force: the row of
   !! `point_row`).
   pure function point_load_vector(model, x) result(f)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: x
      real(dp) :: f(model%unknowns)
      integer :: dofs(4), a
      real(dp) :: weights(4)
      f = 0
      call point_row(model, x, dofs, weights)
      do a = 1, 4
         if (dofs(a) /= 0) f(dofs(a)) = f(dofs(a)) + weights(a)
      end do
   end function point_load_vector

   !> Unknowns of the Hermite interpolant of a field given by its value and slope at the
   !! nodes x_1..x_N: w_i = value(i), theta_i = slope(i).
   pure function interpolate_field(model, value, slope) result(u)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: value(:)   !! (N) u(x_i), i = 1..N (m)
      real(dp), intent(in) :: slope(:)   !! (N) u_x(x_i)
      real(dp) :: u(model%unknowns)
      u(1::2) = value
      u(2::2) = slope
   end function interpolate_field
end module vibrobeam_model
