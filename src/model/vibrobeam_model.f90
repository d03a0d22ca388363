!> The discrete beam model (theory §2): mesh, unknowns, banded mass and stiffness matrices,
!! load vectors and the map from unknowns to the displacement at a point.
!!
!! Two bases, both with M and K of 3 sub-diagonals kept in LAPACK band storage
!! (`vibrobeam_band`):
!! - 'hermite': Hermite cubic elements, degrees of freedom (w_0, theta_0, ..., w_N, theta_N);
!! - 'bspline': cubic B-splines on the open uniform knot vector (`vibrobeam_bspline`),
!!   degrees of freedom the coefficients c_1..c_{N+3}. The displacement at a node is a
!!   combination of 3 coefficients.
!! The supports (`vibrobeam_boundary`, `vibrobeam_structure`) hold some of them or tie them
!! to others (`vibrobeam_dof_map`); the others are the unknowns, in order. For the
!! clamped-free beam: (w_1, theta_1, ..., w_N, theta_N), J = 2N, or c_3..c_{N+3}, J = N + 1
!! (the clamp u(0) = u_x(0) = 0 sets c_1 = c_2 = 0). Beyond the uniform beam (theory §1,
!! "Supports, masses, sections, tension"): element-wise rho S and EI, the geometric
!! stiffness T int u' w' of an axial force, point masses (m u w + J u' w' in M) and springs
!! (k u w, k_r u' w' in K) at points, each integrated exactly.
module vibrobeam_model
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_band, only: symmetric_band, band_allocate, band_add
   use vibrobeam_hermite, only: hermite_shape, hermite_element_mass, hermite_element_stiffness, hermite_element_tension
   use vibrobeam_bspline, only: bspline_knots, bspline_shape
   use vibrobeam_lapack, only: dgbsv, poison_failed_solve
   use vibrobeam_boundary, only: boundary_conditions
   use vibrobeam_structure, only: beam_structure
   use vibrobeam_dof_map, only: dof_map, build_dof_map
   implicit none
   private
   public :: beam_model, build_model, point_row, node_row, nodal_displacement
   public :: load_vector, point_load_vector, interpolate_field, space_profile, unit_profile, energy_integrals
   public :: add_inertial_excess
   public :: rigid_motions, flexibility_applies, gauss_points, gauss_weights

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
      !> supports, masses, sections and axial force (`vibrobeam_structure`; its boundary is `boundary`)
      type(beam_structure) :: structure
      logical :: hermite = .true.            !! the basis is 'hermite' (else 'bspline')
      !> unknown of each degree of freedom of the basis (module header), 0 where a support
      !! holds it, -1 where it is a combination of others (`terms`)
      integer, allocatable :: unknown_of(:)
      type(dof_map) :: terms                 !! the combinations of B-spline supports (`vibrobeam_dof_map`)
      logical, allocatable :: deflection_held(:)   !! (0:N) u(x_i) = 0 held by a support
      integer, allocatable :: support_node(:)      !! the node (1..N-1) of each intermediate support (nearest its x)
      logical :: uniform = .true.            !! rho S and EI the same in every element
      real(dp), allocatable :: element_rho_s(:), element_ei(:)   !! (N) rho S (kg/m) and EI (N m^2) of each element
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
   !! `boundary` (clamped-free when absent), or with everything `structure` describes
   !! (`vibrobeam_structure`; its boundary, unless `boundary` is given too).
   subroutine build_model(basis, elements, length, rho_s, ei, model, stat, errmsg, boundary, structure)
      character(len=*), intent(in) :: basis  !! 'hermite' | 'bspline'
      integer, intent(in) :: elements        !! N >= 1
      real(dp), intent(in) :: length         !! L > 0 (m)
      real(dp), intent(in) :: rho_s          !! rho S > 0 (kg/m)
      real(dp), intent(in) :: ei             !! E I >= 0 (N m^2)
      type(beam_model), intent(out) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(boundary_conditions), intent(in), optional :: boundary
      type(beam_structure), intent(in), optional :: structure
      real(dp) :: element_mass(4, 4), element_stiffness(4, 4), n(4), d1n(4), d2n(4), x, w, transform(4, 4), tension
      integer :: e, a, b, dofs(4), i, g
      logical :: mapped
      stat = 0
      errmsg = ''
      model%basis = basis
      if (present(structure)) model%structure = structure
      if (present(boundary)) model%structure%boundary = boundary
      model%boundary = model%structure%boundary
      model%elements = elements
      model%length = length
      model%h = length/elements
      model%rho_s = rho_s
      model%ei = ei
      model%x = [(length*i/elements, i=0, elements)]
      ! a beam whose sections all agree is uniform, with their rho S and EI (the fast paths
      ! then apply); otherwise rho_s and ei stay the values given (scales, the scene's
      ! length-weighted means)
      call model%structure%element_properties(elements, length, rho_s, ei, model%element_rho_s, model%element_ei)
      model%uniform = all(abs(model%element_rho_s - model%element_rho_s(1)) <= 0) .and. &
                      all(abs(model%element_ei - model%element_ei(1)) <= 0)
      if (model%uniform) then
         model%rho_s = model%element_rho_s(1)
         model%ei = model%element_ei(1)
      end if
      tension = model%structure%axial_force
      select case (basis)
      case ('hermite')
         model%hermite = .true.
         allocate (model%knots(0))
      case ('bspline')
         model%hermite = .false.
         model%knots = bspline_knots(elements, length)
      case default
         stat = stat_failure
         errmsg = 'basis '''//trim(basis)//''' is not available'
         return
      end select
      model%support_node = [(min(elements - 1, max(1, nint(model%structure%support_x(i)/model%h))), &
                             i=1, model%structure%supports())]
      call build_dof_map(model%hermite, elements, model%knots, model%structure, model%support_node, model%terms, stat, &
                         errmsg)
      if (stat /= 0) return
      call check_point_moments(model, stat, errmsg)
      if (stat /= 0) return
      model%unknown_of = model%terms%unknown_of
      model%unknowns = model%terms%unknowns
      allocate (model%deflection_held(0:elements))
      model%deflection_held(:) = model%terms%deflection_held
      call band_allocate(model%mass, model%unknowns, bandwidth)
      call band_allocate(model%stiffness, model%unknowns, bandwidth)
      do e = 1, elements
         if (model%hermite) then
            element_mass = model%element_rho_s(e)*hermite_element_mass(model%h)
            element_stiffness = model%element_ei(e)*hermite_element_stiffness(model%h)
            if (abs(tension) > 0) element_stiffness = element_stiffness + tension*hermite_element_tension(model%h)
         else
            ! Gauss quadrature, exact for the degree-6, degree-4 and degree-2 integrands
            element_mass = 0
            element_stiffness = 0
            d1n = 0
            do g = 1, 4
               x = model%x(e) + gauss_points(g)*model%h
               w = gauss_weights(g)*model%h
               n = bspline_shape(model%knots, e, x, 0)
               d2n = bspline_shape(model%knots, e, x, 2)
               if (abs(tension) > 0) d1n = bspline_shape(model%knots, e, x, 1)
               do b = 1, 4
                  element_mass(:, b) = element_mass(:, b) + w*model%element_rho_s(e)*n*n(b)
                  element_stiffness(:, b) = element_stiffness(:, b) + w*model%element_ei(e)*d2n*d2n(b)
                  if (abs(tension) > 0) element_stiffness(:, b) = element_stiffness(:, b) + w*tension*d1n*d1n(b)
               end do
            end do
         end if
         call element_map(model, e, dofs, transform, mapped)
         if (mapped) then
            element_mass = matmul(transform, matmul(element_mass, transpose(transform)))
            element_stiffness = matmul(transform, matmul(element_stiffness, transpose(transform)))
            call assemble_mapped(dofs, element_mass, element_stiffness)
            cycle
         end if
         do b = 1, 4
            do a = b, 4
               if (dofs(a) == 0 .or. dofs(b) == 0) cycle
               call band_add(model%mass, dofs(a), dofs(b), element_mass(a, b))
               call band_add(model%stiffness, dofs(a), dofs(b), element_stiffness(a, b))
            end do
         end do
      end do
      call add_point_terms(model)
   contains
      !> A mapped element's matrices over its distinct unknowns, in any order: the lower
      !! triangle of the band once per pair.
      subroutine assemble_mapped(dofs, element_mass, element_stiffness)
         integer, intent(in) :: dofs(4)
         real(dp), intent(in) :: element_mass(4, 4), element_stiffness(4, 4)
         integer :: a, b
         do b = 1, 4
            do a = 1, 4
               if (dofs(a) == 0 .or. dofs(b) == 0 .or. dofs(a) < dofs(b)) cycle
               call band_add(model%mass, dofs(a), dofs(b), element_mass(a, b))
               call band_add(model%stiffness, dofs(a), dofs(b), element_stiffness(a, b))
            end do
         end do
      end subroutine assemble_mapped
   end subroutine build_model

   !> B-splines refuse a point moment inside the beam (a rotational spring of a support,
   !! the rotary inertia of a mass away from the ends) and a jump of EI between sections:
   !! each makes u'' jump at its point, which a C^2 spline cannot follow (the frequencies
   !! then converge like h, not h^4; measured: 3.6e-3 at N = 32 for a rotational spring
   !! support, 4.1e-3 at N = 40 for EI stepping by 4, theory §2). Hermite elements are C^1
   !! and take it; a step of rho S alone leaves u'' continuous and B-splines take it.
   !! stat = stat_failure with a message naming the input.
   subroutine check_point_moments(model, stat, errmsg)
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k
      character(len=*), parameter :: why = ' makes u'''' jump at its point, which &mesh basis = ''bspline'' '// &
                                           '(C^2 splines) cannot follow; use basis = ''hermite'''
      stat = 0
      errmsg = ''
      if (model%hermite) return
      associate (st => model%structure)
         do k = 1, st%sections() - 1
            if (abs(st%section_ei(k + 1) - st%section_ei(k)) > 0) then
               stat = stat_failure
               errmsg = '&sections youngs_modulus and inertia of sections '//integer_text(k)//' and '// &
                        integer_text(k + 1)//': their EI differ ('//real_text(st%section_ei(k))//' and '// &
                        real_text(st%section_ei(k + 1))//' N m^2); a jump of EI at x_to('//integer_text(k)//')'//why
               return
            end if
         end do
         do k = 1, st%supports()
            if (st%support_rotational_stiffness(k) > 0) then
               stat = stat_failure
               errmsg = '&supports rotational_stiffness('//integer_text(k)//') = '// &
                        real_text(st%support_rotational_stiffness(k))//' N m/rad: a rotational spring inside the beam'//why
               return
            end if
         end do
         do k = 1, st%masses()
            if (st%mass_rotary_inertia(k) > 0 .and. st%mass_position(k) > 0 .and. st%mass_position(k) < model%length) then
               stat = stat_failure
               errmsg = '&masses rotary_inertia('//integer_text(k)//') = '//real_text(st%mass_rotary_inertia(k))// &
                        ' kg m^2 of a mass inside the beam (x = '//real_text(st%mass_position(k))//' m)'//why
               return
            end if
         end do
      end associate
   end subroutine check_point_moments

   !> The point terms of the structure (theory §1, "Supports, masses, sections, tension"):
   !! end springs and the springs of intermediate supports in K (k u(x) w(x) and
   !! k_r u'(x) w'(x)), point masses in M (m u w + J u' w'). Each is a product of two rows
   !! of `point_row`, on one element: the band keeps its width.
   subroutine add_point_terms(model)
      type(beam_model), intent(inout) :: model
      integer :: s, k
      associate (b => model%boundary, st => model%structure)
         call add_rows(model%stiffness, 0.0_dp, b%left_spring, b%left_rotational_spring)
         call add_rows(model%stiffness, model%length, b%right_spring, b%right_rotational_spring)
         do s = 1, st%supports()
            call add_rows(model%stiffness, model%x(model%support_node(s) + 1), st%support_stiffness(s), &
                          st%support_rotational_stiffness(s))
         end do
         do k = 1, st%masses()
            call add_rows(model%mass, st%mass_position(k), st%mass_value(k), st%mass_rotary_inertia(k))
         end do
      end associate
   contains
      subroutine add_rows(matrix, x, value_weight, slope_weight)
         type(symmetric_band), intent(inout) :: matrix
         real(dp), intent(in) :: x, value_weight, slope_weight
         integer :: dofs(4), a, c, order
         real(dp) :: weights(4), factor
         do order = 0, 1
            factor = merge(value_weight, slope_weight, order == 0)
            if (.not. factor > 0) cycle
            call point_row(model, x, dofs, weights, order)
            do c = 1, 4
               do a = 1, 4
                  if (dofs(a) == 0 .or. dofs(c) == 0 .or. dofs(a) < dofs(c)) cycle
                  call band_add(matrix, dofs(a), dofs(c), factor*weights(a)*weights(c))
               end do
            end do
         end do
      end subroutine add_rows
   end subroutine add_point_terms

   !> How many rigid-body motions the model's structure leaves free (0, 1 or 2;
   !! `beam_structure%rigid_motions`). K is singular exactly when this is positive.
   pure integer function rigid_motions(model)
      type(beam_model), intent(in) :: model
      rigid_motions = model%structure%rigid_motions(model%length)
   end function rigid_motions

   !> Does the flexibility by double integration from the clamp (`vibrobeam_flexibility`)
   !! apply: a uniform beam clamped at x = 0 and free at L, without end springs,
   !! intermediate supports or axial force (point masses change M only)? Otherwise K^-1 is a
   !! band Cholesky solve (docs/method.md, "Supports").
   pure logical function flexibility_applies(model)
      type(beam_model), intent(in) :: model
      flexibility_applies = model%boundary%is_clamped_free() .and. model%uniform .and. &
                            model%structure%supports() == 0 .and. .not. abs(model%structure%axial_force) > 0
   end function flexibility_applies

   !> Unknowns of element e (1..N) in the order of its shape functions: 0 marks a degree
   !! of freedom a support holds, -1 one that is a combination of others (`element_map`).
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

   !> The distinct unknowns `dofs` of element e and how its shape functions map to them:
   !! function s is sum_a transform(a, s) U(dofs(a)). `mapped` is false, and `transform`
   !! the identity with dofs = `element_dofs`, unless a degree of freedom of the element is
   !! a combination (B-spline supports, `vibrobeam_dof_map`).
   pure subroutine element_map(model, e, dofs, transform, mapped)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: e
      integer, intent(out) :: dofs(4)
      real(dp), intent(out) :: transform(4, 4)
      logical, intent(out) :: mapped
      integer :: s, t, k, used, unknown, a
      real(dp) :: weight
      dofs = element_dofs(model, e)
      transform = 0
      mapped = any(dofs < 0)
      if (.not. mapped) then
         do s = 1, 4
            transform(s, s) = 1
         end do
         return
      end if
      dofs = 0
      used = 0
      do s = 1, 4
         k = e - 1 + s   ! B_(e-1+s): Hermite supports hold whole unknowns, never combine them
         do t = 1, 2
            ! the terms of degree of freedom k: itself, or its combination
            if (model%unknown_of(k) > 0) then
               if (t == 2) exit
               unknown = model%unknown_of(k)
               weight = 1
            else if (model%unknown_of(k) < 0) then
               unknown = model%terms%term_unknown(t, k)
               weight = model%terms%term_weight(t, k)
            else
               exit
            end if
            if (unknown <= 0) cycle
            a = findloc(dofs(1:used), unknown, dim=1)
            if (a == 0) then
               used = used + 1
               dofs(used) = unknown
               a = used
            end if
            transform(a, s) = transform(a, s) + weight
         end do
      end do
   end subroutine element_map

   !> The derivative of order `order` at x of the functions of element e, as weights of
   !! its distinct unknowns `dofs` (`element_map`; 0: no unknown).
   pure subroutine element_functions(model, e, x, order, dofs, weights)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: e, order
      real(dp), intent(in) :: x
      integer, intent(out) :: dofs(4)
      real(dp), intent(out) :: weights(4)
      real(dp) :: transform(4, 4)
      logical :: mapped
      call element_map(model, e, dofs, transform, mapped)
      weights = element_shape(model, e, x, order)
      if (mapped) weights = matmul(transform, weights)
   end subroutine element_functions

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
   !! where a dof of 0 (held by a support) contributes nothing. `order` 1 or 2 gives u_x, u_xx.
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
      call element_functions(model, e, x, derivative, dofs, weights)
      where (dofs == 0) weights = 0
   end subroutine point_row

   !> The displacement at node i (0..N) as a combination of unknowns, like `point_row`
   !! but exact at the node: for Hermite elements u_h(x_i) = w_i is an unknown itself
   !! (theory §2); for B-splines it is the value of the element ending at x_i (the first
   !! element at x_0). A node whose
   !! deflection a support holds has no weight.
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
         ! the element ending at the node (the first one at x = 0)
         call element_functions(model, max(node, 1), model%x(node + 1), 0, dofs, weights)
         where (dofs == 0 .or. abs(weights) < epsilon(1.0_dp)) weights = 0
         if (model%deflection_held(node)) weights = 0
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
      if (model%unknown_of(1) > 0) w(1) = u(model%unknown_of(1))
      do i = 1, model%elements
         call node_row(model, i, dofs, weights)
         w(i + 1) = 0
         do a = 1, 4
            if (dofs(a) /= 0) w(i + 1) = w(i + 1) + weights(a)*u(dofs(a))
         end do
      end do
   end function nodal_displacement

   !> The integrals 1/2 U^T K U (bending 1/2 int EI (u_h'')^2, tension 1/2 int T (u_h')^2 and
   !! the springs' 1/2 k u^2, 1/2 k_r u'^2) and 1/2 U^T M U (1/2 int rho S u_h^2 and the point
   !! masses' 1/2 m u^2 + 1/2 J u'^2), summed element by element by Gauss quadrature (exact
   !! for cubic elements) and point by point. Sums of non-negative terms (with T >= 0): full
   !! relative accuracy even when K is ill-conditioned, unlike the product U^T (K U), which
   !! cancels for smooth U.
   pure subroutine energy_integrals(model, u, bending, inertia)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: u(:)          !! (J) unknowns
      real(dp), intent(out) :: bending      !! 1/2 U^T K U
      real(dp), intent(out) :: inertia      !! 1/2 U^T M U
      integer :: e, g, dofs(4), s, k
      real(dp) :: x, local(4), curvature, value, slope, transform(4, 4)
      logical :: mapped
      bending = 0
      inertia = 0
      do e = 1, model%elements
         call element_map(model, e, dofs, transform, mapped)
         local = 0
         where (dofs /= 0) local = u(max(dofs, 1))
         if (mapped) local = matmul(local, transform)   ! the coefficients of the element's functions
         do g = 1, 4
            x = model%x(e) + gauss_points(g)*model%h
            curvature = dot_product(element_shape(model, e, x, 2), local)
            value = dot_product(element_shape(model, e, x, 0), local)
            bending = bending + 0.5_dp*gauss_weights(g)*model%h*model%element_ei(e)*curvature**2
            inertia = inertia + 0.5_dp*gauss_weights(g)*model%h*model%element_rho_s(e)*value**2
            if (abs(model%structure%axial_force) > 0) then
               slope = dot_product(element_shape(model, e, x, 1), local)
               bending = bending + 0.5_dp*gauss_weights(g)*model%h*model%structure%axial_force*slope**2
            end if
         end do
      end do
      associate (b => model%boundary, st => model%structure)
         bending = bending + point_energy(0.0_dp, b%left_spring, b%left_rotational_spring) + &
                   point_energy(model%length, b%right_spring, b%right_rotational_spring)
         do s = 1, st%supports()
            bending = bending + point_energy(model%x(model%support_node(s) + 1), st%support_stiffness(s), &
                                             st%support_rotational_stiffness(s))
         end do
         do k = 1, st%masses()
            inertia = inertia + point_energy(st%mass_position(k), st%mass_value(k), st%mass_rotary_inertia(k))
         end do
      end associate
   contains
      !> 1/2 value_weight u(x)^2 + 1/2 slope_weight u'(x)^2.
      pure real(dp) function point_energy(x, value_weight, slope_weight)
         real(dp), intent(in) :: x, value_weight, slope_weight
         integer :: dofs(4), order, a
         real(dp) :: weights(4), factor, v
         point_energy = 0
         do order = 0, 1
            factor = merge(value_weight, slope_weight, order == 0)
            if (.not. factor > 0) cycle
            call point_row(model, x, dofs, weights, order)
            v = 0
            do a = 1, 4
               if (dofs(a) /= 0) v = v + weights(a)*u(dofs(a))
            end do
            point_energy = point_energy + 0.5_dp*factor*v**2
         end do
      end function point_energy
   end subroutine energy_integrals

   !> Consistent load vector F_j = integral over (0, L) of profile(x) phi_j(x) dx, by
   !! 4-point Gauss quadrature per element (exact for profiles of degree <= 4); with
   !! `x_from` and `x_to` (m) the integral over that segment only, the rule then applied to
   !! the part of each element inside it (an element the segment covers whole takes the
   !! same points as without a segment, so a segment [0, L] gives the same bits); with
   !! `element_factor` (N) the profile times factor(e) on element e.
   function load_vector(model, profile, x_from, x_to, element_factor) result(f)
      type(beam_model), intent(in) :: model
      procedure(space_profile) :: profile
      real(dp), intent(in), optional :: x_from, x_to
      real(dp), intent(in), optional :: element_factor(:)
      real(dp) :: f(model%unknowns)
      integer :: e, g, dofs(4), a
      real(dp) :: n(4), x, start, width
      f = 0
      do e = 1, model%elements
         if (present(element_factor)) then
            if (.not. abs(element_factor(e)) > 0) cycle
         end if
         start = model%x(e)
         width = model%h
         if (present(x_from) .and. present(x_to)) then
            if (x_to <= model%x(e) .or. x_from >= model%x(e + 1)) cycle
            if (x_from > model%x(e) .or. x_to < model%x(e + 1)) then   ! the element's part in the segment
               start = max(x_from, model%x(e))
               width = min(x_to, model%x(e + 1)) - start
            end if
         end if
         do g = 1, 4
            x = start + gauss_points(g)*width
            call element_functions(model, e, x, 0, dofs, n)
            if (present(element_factor)) n = element_factor(e)*n
            do a = 1, 4
               if (dofs(a) /= 0) f(dofs(a)) = f(dofs(a)) + gauss_weights(g)*width*profile(x)*n(a)
            end do
         end do
      end do
   end function load_vector

   !> vector += the base excitation's inertial load beyond that of a uniform rho_s (theory
   !! §1, "Base excitation"; per unit of the support's acceleration and of rho_s): each point
   !! mass's m_k/rho_s phi(x_k), then on a beam of sections int (rho S(x)/rho_s - 1) phi dx.
   !! With the uniform load vector (`unit_profile`) it makes int rho S phi/rho_s + the masses.
   subroutine add_inertial_excess(model, rho_s, vector)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rho_s          !! the load's rho S (kg/m)
      real(dp), intent(inout) :: vector(:)   !! (J)
      integer :: k
      do k = 1, model%structure%masses()
         vector = vector + model%structure%mass_value(k)/rho_s*point_load_vector(model, model%structure%mass_position(k))
      end do
      if (any(abs(model%element_rho_s - rho_s) > 0)) &
         vector = vector + load_vector(model, unit_profile, element_factor=model%element_rho_s/rho_s - 1)
   end subroutine add_inertial_excess

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

   !> Unknowns of a field given by its value and slope at the nodes x_0..x_N (index
   !! 1..N+1). Hermite: the interpolant w_i = value(i), theta_i = slope(i) where the node's
   !! unknowns exist (a support holds the others). B-splines: the spline through the values
   !! at every node whose deflection no support holds, with the slope at each end whose
   !! rotation the end leaves free (the complete cubic spline of the free data: one
   !! condition per unknown; on the clamped-free beam N + 1, the clamp giving u = u_x = 0 at
   !! x = 0), solved as a band system; its rows in the order of x keep the band. Both
   !! reproduce a cubic polynomial that satisfies the supports exactly. NaN when the
   !! conditions do not match the unknowns (a tied support the conditions do not describe).
   function interpolate_field(model, value, slope) result(u)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: value(:)   !! (N + 1) u(x_i), i = 0..N (m)
      real(dp), intent(in) :: slope(:)   !! (N + 1) u_x(x_i)
      real(dp) :: u(model%unknowns)
      integer, parameter :: kl = 3, ku = 3
      real(dp) :: ab(2*kl + ku + 1, model%unknowns), weights(4)
      integer :: ipiv(model%unknowns), i, dofs(4), info, n, row
      logical :: fits
      if (model%hermite) then
         u = 0
         do i = 0, model%elements
            if (model%unknown_of(2*i + 1) > 0) u(model%unknown_of(2*i + 1)) = value(i + 1)
            if (model%unknown_of(2*i + 2) > 0) u(model%unknown_of(2*i + 2)) = slope(i + 1)
         end do
         return
      end if
      n = model%unknowns
      ab = 0
      row = 0
      fits = .true.
      if (.not. model%boundary%holds_rotation(1)) then   ! u_x(0) = slope(0)
         call point_row(model, 0.0_dp, dofs, weights, order=1)
         call add_row(slope(1))
      end if
      do i = 0, model%elements                            ! u_h(x_i) = value(i)
         if (model%deflection_held(i)) cycle
         call node_row(model, i, dofs, weights)
         call add_row(value(i + 1))
      end do
      if (.not. model%boundary%holds_rotation(2)) then   ! u_x(L) = slope(N)
         call point_row(model, model%length, dofs, weights, order=1)
         call add_row(slope(model%elements + 1))
      end if
      if (.not. fits .or. row /= n) then
         info = -1
      else
         call dgbsv(n, kl, ku, 1, ab, 2*kl + ku + 1, ipiv, u, n, info)
      end if
      call poison_failed_solve(info, u)   ! nonsingular for distinct nodes (Schoenberg-Whitney)
   contains
      !> The next row: weights at the unknowns dofs, right-hand side `rhs`.
      subroutine add_row(rhs)
         real(dp), intent(in) :: rhs
         integer :: a
         row = row + 1
         if (row > n) then
            fits = .false.
            return
         end if
         u(row) = rhs
         do a = 1, 4
            if (dofs(a) == 0) cycle
            if (abs(row - dofs(a)) > min(kl, ku)) then
               fits = .false.
               cycle
            end if
            ab(kl + ku + 1 + row - dofs(a), dofs(a)) = ab(kl + ku + 1 + row - dofs(a), dofs(a)) + weights(a)
         end do
      end subroutine add_row
   end function interpolate_field
end module vibrobeam_model
