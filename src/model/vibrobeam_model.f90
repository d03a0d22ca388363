!> The discrete beam model (theory §2): mesh, unknowns, banded mass and stiffness matrices,
!! load vectors and the map from unknowns to the displacement at a point.
!!
!! Two bases, both with M and K of 3 sub-diagonals kept in LAPACK band storage
!! (`vibrobeam_band`):
!! - 'hermite': Hermite cubic elements, degrees of freedom (w_0, theta_0, ..., w_N, theta_N);
!! - 'bspline': cubic B-splines on the open uniform knot vector (`vibrobeam_bspline`),
!!   degrees of freedom the coefficients c_1..c_{N+3}. The displacement at a node is a
!!   combination of 3 coefficients.
!! The supports (`vibrobeam_boundary`) hold some of them; the others are the unknowns, in
!! order. For the clamped-free beam: (w_1, theta_1, ..., w_N, theta_N), J = 2N, or
!! c_3..c_{N+3}, J = N + 1 (the clamp u(0) = u_x(0) = 0 sets c_1 = c_2 = 0).
module vibrobeam_model
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: symmetric_band, band_allocate, band_add
   use vibrobeam_hermite, only: hermite_shape, hermite_element_mass, hermite_element_stiffness
   use vibrobeam_bspline, only: bspline_knots, bspline_shape
   use vibrobeam_lapack, only: dgbsv, poison_failed_solve
   use vibrobeam_boundary, only: boundary_conditions
   implicit none
   private
   public :: beam_model, build_model, point_row, node_row, nodal_displacement
   public :: load_vector, point_load_vector, interpolate_field, space_profile, unit_profile, energy_integrals
   public :: gauss_points, gauss_weights

   integer, parameter :: bandwidth = 3   !! sub-diagonals of M and K for both bases

   !> 4-point Gauss-Legendre rule on [0, 1] (exact for polynomials of degree 7, hence for
   !! every mass and stiffness integrand of cubic elements and for loads cubic in x).
   real(dp), parameter :: gauss_points(4) = 0.5_dp + 0.5_dp*[-0.861136311594052575_dp, &
      -0.339981043584856265_dp, 0.339981043584856265_dp, 0.861136311594052575_dp]
   real(dp), parameter :: gauss_weights(4) = 0.5_dp*[0.347854845137453857_dp, &
      0.652145154862546143_dp, 0.652145154862546143_dp, 0.347854845137453857_dp]

   !> What the discretized beam is.
   type :: beam_model
      character(len=16) :: basis = 'hermite'  !! 'hermite' | 'bspline'
      integer :: elements = 0      !! N
      integer :: unknowns = 0      !! J = 2N (Hermite), N + 1 (B-splines)
      real(dp) :: length = 0       !! L (m)
      real(dp) :: h = 0            !! element length L/N (m)
      real(dp) :: rho_s = 1        !! mass per unit length rho S (kg/m)
      real(dp) :: ei = 1           !! bending stiffness E I (N m^2)
      real(dp), allocatable :: x(:)          !! node positions x_0..x_N (m), index 1..N+1
      real(dp), allocatable :: knots(:)      !! B-spline knots (N + 7), B-splines only
      type(symmetric_band) :: mass           !! M, (J x J, 3 sub-diagonals)
      type(symmetric_band) :: stiffness      !! K, (J x J, 3 sub-diagonals)
      type(boundary_conditions) :: boundary  !! the supports at the ends
      logical :: hermite = .true.            !! the basis is 'hermite' (else 'bspline')
      !> unknown of each degree of freedom of the basis (module header), 0 where a support holds it
      integer, allocatable :: unknown_of(:)
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

   !> Assemble the model of a beam of N elements of the given basis, on the supports
   !! `boundary` (clamped-free when absent).
   subroutine build_model(basis, elements, length, rho_s, ei, model, stat, errmsg, boundary)
      character(len=*), intent(in) :: basis  !! 'hermite' | 'bspline'
      integer, intent(in) :: elements        !! N >= 1
      real(dp), intent(in) :: length         !! L > 0 (m)
      real(dp), intent(in) :: rho_s          !! rho S > 0 (kg/m)
      real(dp), intent(in) :: ei             !! E I > 0 (N m^2)
      type(beam_model), intent(out) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(boundary_conditions), intent(in), optional :: boundary
      real(dp) :: element_mass(4, 4), element_stiffness(4, 4), n(4), d2n(4), x, w
      integer :: e, a, b, dofs(4), i, g
      logical, allocatable :: held(:)
      logical :: expressible
      stat = 0
      errmsg = ''
      model%basis = basis
      if (present(boundary)) model%boundary = boundary
      model%elements = elements
      model%length = length
      model%h = length/elements
      model%rho_s = rho_s
      model%ei = ei
      model%x = [(length*i/elements, i=0, elements)]
      select case (basis)
      case ('hermite')
         model%hermite = .true.
      case ('bspline')
         model%hermite = .false.
         model%knots = bspline_knots(elements, length)
      case default
         stat = stat_failure
         errmsg = 'basis '''//trim(basis)//''' is not available'
         return
      end select
      call model%boundary%basis_dof_held(model%hermite, elements, held, expressible)
      if (.not. expressible) then
         stat = stat_failure
         errmsg = 'the '//model%boundary%name()//' supports cannot be expressed in the '''//trim(basis)//''' basis'
         return
      end if
      allocate (model%unknown_of(size(held)), source=0)
      model%unknowns = 0
      do i = 1, size(held)
         if (held(i)) cycle
         model%unknowns = model%unknowns + 1
         model%unknown_of(i) = model%unknowns
      end do
      call band_allocate(model%mass, model%unknowns, bandwidth)
      call band_allocate(model%stiffness, model%unknowns, bandwidth)
      do e = 1, elements
         if (model%hermite) then
            element_mass = rho_s*hermite_element_mass(model%h)
            element_stiffness = ei*hermite_element_stiffness(model%h)
         else
            ! Gauss quadrature, exact for the degree-6 and degree-2 integrands
            element_mass = 0
            element_stiffness = 0
            do g = 1, 4
               x = model%x(e) + gauss_points(g)*model%h
               w = gauss_weights(g)*model%h
               n = bspline_shape(model%knots, e, x, 0)
               d2n = bspline_shape(model%knots, e, x, 2)
               do b = 1, 4
                  element_mass(:, b) = element_mass(:, b) + w*rho_s*n*n(b)
                  element_stiffness(:, b) = element_stiffness(:, b) + w*ei*d2n*d2n(b)
               end do
            end do
         end if
         dofs = element_dofs(model, e)
         do b = 1, 4
            do a = b, 4
               if (dofs(a) == 0 .or. dofs(b) == 0) cycle
               call band_add(model%mass, dofs(a), dofs(b), element_mass(a, b))
               call band_add(model%stiffness, dofs(a), dofs(b), element_stiffness(a, b))
            end do
         end do
      end do
   end subroutine build_model

   !> Global unknowns of element e (1..N) in the order of the element's shape functions;
   !! 0 marks a degree of freedom a support holds, which has no unknown.
   pure function element_dofs(model, e) result(dofs)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: e
      integer :: dofs(4)
      if (model%hermite) then
         dofs = model%unknown_of(2*e - 1:2*e + 2)   ! (w, theta) of nodes e - 1 and e
      else
         dofs = model%unknown_of(e:e + 3)           ! B_e..B_{e+3}
      end if
   end function element_dofs

   !> Shape functions of element e at x (derivative of order `order`).
   pure function element_shape(model, e, x, order) result(n)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: e, order
      real(dp), intent(in) :: x
      real(dp) :: n(4)
      if (model%hermite) then
         n = hermite_shape((x - model%x(e))/model%h, model%h, order)
      else
         n = bspline_shape(model%knots, e, x, order)
      end if
   end function element_shape

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
      dofs = element_dofs(model, e)
      weights = element_shape(model, e, x, derivative)
      where (dofs == 0) weights = 0
   end subroutine point_row

   !> The displacement at node i (1..N) as a combination of unknowns, like `point_row`
   !! but exact at the node: for Hermite elements u_h(x_i) = w_i is an unknown itself
   !! (theory §2); for B-splines it is the value of the element ending at x_i.
   pure subroutine node_row(model, node, dofs, weights)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: node
      integer, intent(out) :: dofs(4)
      real(dp), intent(out) :: weights(4)
      if (model%hermite) then
         dofs = [model%unknown_of(2*node + 1), 0, 0, 0]   ! w of the node
         weights = [1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
         if (dofs(1) == 0) weights(1) = 0
      else
         dofs = element_dofs(model, node)
         weights = bspline_shape(model%knots, node, model%x(node + 1), 0)
         where (dofs == 0 .or. abs(weights) < epsilon(1.0_dp)) weights = 0
         where (abs(weights) <= 0) dofs = 0
      end if
   end subroutine node_row

   !> Displacement at the N+1 nodes x_0..x_N from the unknowns (0 where a support holds it).
   pure function nodal_displacement(model, u) result(w)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: u(:)   !! (J) unknowns
      real(dp) :: w(model%elements + 1)
      integer :: i, a, dofs(4)
      real(dp) :: weights(4)
      if (model%hermite) then
         do i = 0, model%elements
            w(i + 1) = 0
            if (model%unknown_of(2*i + 1) /= 0) w(i + 1) = u(model%unknown_of(2*i + 1))
         end do
         return
      end if
      w(1) = 0   ! u(0) = c_1
      if (model%unknown_of(1) /= 0) w(1) = u(model%unknown_of(1))
      do i = 1, model%elements
         call node_row(model, i, dofs, weights)
         w(i + 1) = 0
         do a = 1, 4
            if (dofs(a) /= 0) w(i + 1) = w(i + 1) + weights(a)*u(dofs(a))
         end do
      end do
   end function nodal_displacement

   !> The integrals 1/2 int EI (u_h'')^2 dx = 1/2 U^T K U and 1/2 int rho S u_h^2 dx =
   !! 1/2 U^T M U, summed element by element by Gauss quadrature (exact for cubic
   !! elements). Sums of non-negative terms: full relative accuracy even when K is
   !! ill-conditioned, unlike the product U^T (K U), which cancels for smooth U.
   pure subroutine energy_integrals(model, u, bending, inertia)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: u(:)          !! (J) unknowns
      real(dp), intent(out) :: bending      !! 1/2 U^T K U
      real(dp), intent(out) :: inertia      !! 1/2 U^T M U
      integer :: e, g, dofs(4)
      real(dp) :: x, local(4), curvature, value
      bending = 0
      inertia = 0
      do e = 1, model%elements
         dofs = element_dofs(model, e)
         local = 0
         where (dofs /= 0) local = u(max(dofs, 1))
         do g = 1, 4
            x = model%x(e) + gauss_points(g)*model%h
            curvature = dot_product(element_shape(model, e, x, 2), local)
            value = dot_product(element_shape(model, e, x, 0), local)
            bending = bending + 0.5_dp*gauss_weights(g)*model%h*model%ei*curvature**2
            inertia = inertia + 0.5_dp*gauss_weights(g)*model%h*model%rho_s*value**2
         end do
      end do
   end subroutine energy_integrals

   !> Consistent load vector F_j = integral over (0, L) of profile(x) phi_j(x) dx, by
   !! 4-point Gauss quadrature per element (exact for profiles of degree <= 4); with
   !! `x_from` and `x_to` (m) the integral over that segment only, the rule then applied to
   !! the part of each element inside it (an element the segment covers whole takes the
   !! same points as without a segment, so a segment [0, L] gives the same bits).
   function load_vector(model, profile, x_from, x_to) result(f)
      type(beam_model), intent(in) :: model
      procedure(space_profile) :: profile
      real(dp), intent(in), optional :: x_from, x_to
      real(dp) :: f(model%unknowns)
      integer :: e, g, dofs(4), a
      real(dp) :: n(4), x, start, width
      f = 0
      do e = 1, model%elements
         start = model%x(e)
         width = model%h
         if (present(x_from) .and. present(x_to)) then
            if (x_to <= model%x(e) .or. x_from >= model%x(e + 1)) cycle
            if (x_from > model%x(e) .or. x_to < model%x(e + 1)) then   ! the element's part in the segment
               start = max(x_from, model%x(e))
               width = min(x_to, model%x(e + 1)) - start
            end if
         end if
         dofs = element_dofs(model, e)
         do g = 1, 4
            x = start + gauss_points(g)*width
            n = element_shape(model, e, x, 0)
            do a = 1, 4
               if (dofs(a) /= 0) f(dofs(a)) = f(dofs(a)) + gauss_weights(g)*width*profile(x)*n(a)
            end do
         end do
      end do
   end function load_vector

   !> The profile of a uniform load: 1 along the whole beam.
   pure function unit_profile(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      value = 1 + 0*x
   end function unit_profile

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

   !> Unknowns of a field given by its value and slope at the nodes x_1..x_N, for the
   !! clamped-free beam (the caller checks `model%boundary%is_clamped_free()`).
   !! Hermite: the interpolant w_i = value(i), theta_i = slope(i). B-splines: the spline
   !! through value(1..N) at the nodes with slope(N) at the tip (N + 1 conditions for the
   !! N + 1 unknowns; the clamp gives u = u_x = 0 at x = 0), solved as a band system.
   function interpolate_field(model, value, slope) result(u)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: value(:)   !! (N) u(x_i), i = 1..N (m)
      real(dp), intent(in) :: slope(:)   !! (N) u_x(x_i)
      real(dp) :: u(model%unknowns)
      integer, parameter :: kl = 3, ku = 3
      real(dp) :: ab(2*kl + ku + 1, model%unknowns), weights(4)
      integer :: ipiv(model%unknowns), i, a, dofs(4), info, n
      if (model%hermite) then
         u(1::2) = value
         u(2::2) = slope
         return
      end if
      n = model%unknowns
      ab = 0
      do i = 1, model%elements          ! row i: u_h(x_i) = value(i)
         call node_row(model, i, dofs, weights)
         do a = 1, 4
            if (dofs(a) /= 0) ab(kl + ku + 1 + i - dofs(a), dofs(a)) = weights(a)
         end do
      end do
      call point_row(model, model%length, dofs, weights, order=1)   ! row N+1: u_x(L) = slope(N)
      do a = 1, 4
         if (dofs(a) /= 0) ab(kl + ku + 1 + n - dofs(a), dofs(a)) = weights(a)
      end do
      u(1:model%elements) = value
      u(n) = slope(model%elements)
      call dgbsv(n, kl, ku, 1, ab, 2*kl + ku + 1, ipiv, u, n, info)
      call poison_failed_solve(info, u)   ! nonsingular for distinct nodes (Schoenberg-Whitney)
   end function interpolate_field
end module vibrobeam_model
