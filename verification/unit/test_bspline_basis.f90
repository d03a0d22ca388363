!> Unit test of the cubic B-spline basis (`vibrobeam_bspline`) and of the B-spline model:
!! - partition of unity: the four nonzero B-splines of an element sum to 1 and their first
!!   and second derivatives sum to 0, at points inside every element (N = 1, 2, 3, 7);
!! - C^2 continuity: value, slope and curvature of a random spline agree from both sides of
!!   every interior node;
!! - derivatives: the first and second derivatives equal central differences of the
!!   values (h-relative step 1e-4);
!! - the clamp: with the model's unknowns, u(0) = u_x(0) = 0 for any coefficients;
!! - cubic reproduction: the spline interpolating a cubic with u(0) = u_x(0) = 0
!!   (x^2 (3 - x), built by `interpolate_field`) equals it everywhere;
!! - `&initial velocity = 'uniform'` (docs/method.md, initial data): never above the
!!   amplitude A, nondecreasing from the clamp, equal to A with zero slope from x = 2h on,
!!   3/4 A at x = h.
!! Every tolerance is a round-off (or truncation) bound derived beside its check, in units
!! of u = eps/2 and gamma_n = n u/(1 - n u) (`vibrobeam_roundoff_bounds`). Cox-de Boor
!! computes a cubic B-spline value in 3 levels of at most 6 roundings each (two differences
!! x - t, one knot difference, one division, two products and a sum): gamma_18 relative,
!! and all values are >= 0; a derivative adds the 3 roundings of its own level (gamma_21).
program test_bspline_basis
   use vibrobeam_kinds, only: dp
   use vibrobeam_lapack, only: dgetrf
   use vibrobeam_bspline, only: bspline_knots, bspline_shape
   use vibrobeam_model, only: beam_model, build_model, point_row, node_row, interpolate_field
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_static_bounds, only: dense_inverse, permuted_lu_times
   use vibrobeam_scene, only: scene_type
   use vibrobeam_initial_state, only: initial_velocity
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   integer, parameter :: meshes(4) = [1, 2, 3, 7]
   integer :: k
   do k = 1, size(meshes)
      call check_mesh(meshes(k))
   end do
   call t%finish('test_bspline_basis')
contains
   subroutine check_mesh(elements)
      integer, intent(in) :: elements
      real(dp), parameter :: length = 1.3_dp
      real(dp) :: knots(elements + 7), h, x, step, left(3), right(3), value, exact, bound(3), third, magnitude
      real(dp), allocatable :: u(:), coefficients(:), collocation(:, :), factors(:, :), inverse(:, :), coefficient_error(:)
      integer, allocatable :: pivots(:)
      type(beam_model) :: model
      integer :: e, i, order, stat, dofs(4), n, info, j
      real(dp) :: weights(4), d(4)
      character(len=200) :: errmsg
      character(len=48) :: label
      write (label, '(a,i0)') 'N = ', elements
      knots = bspline_knots(elements, length)
      h = length/elements
      do e = 1, elements
         do i = 1, 5
            x = (e - 1)*h + h*(i - 0.5_dp)/5
            ! values >= 0 with gamma_18 each, summed: gamma_21
            call t%check_close(trim(label)//' partition of unity', sum(bspline_shape(knots, e, x, 0)), 1.0_dp, &
                               gamma_n(21))
            ! derivatives of both signs, gamma_21 each, summed: gamma_24 times the sum of |.|
            call t%check_close(trim(label)//' derivatives of unity', sum(bspline_shape(knots, e, x, 1)), 0.0_dp, &
                               1.0_dp, gamma_n(24)*sum(abs(bspline_shape(knots, e, x, 1))))
            call t%check_close(trim(label)//' curvatures of unity', sum(bspline_shape(knots, e, x, 2)), 0.0_dp, &
                               1.0_dp, gamma_n(24)*sum(abs(bspline_shape(knots, e, x, 2))))
            ! a cubic's central difference is exact up to step^2/6 N''' (N''' is constant on
            ! the element; measured here as the exact central difference of the linear N''),
            ! plus the rounding of the two values divided by 2 step
            step = 1e-4_dp*h
            d = (bspline_shape(knots, e, x + step, 0) - bspline_shape(knots, e, x - step, 0))/(2*step)
            third = maxval(abs(bspline_shape(knots, e, x + step, 2) - bspline_shape(knots, e, x - step, 2)))/(2*step)
            call t%check_close(trim(label)//' first derivative vs difference', &
                               maxval(abs(d - bspline_shape(knots, e, x, 1))), 0.0_dp, 1.0_dp, &
                               step**2/6*third*(1 + gamma_n(30)) + gamma_n(21)/step + gamma_n(21)*maxval(abs(d)))
            ! N' is quadratic: its central difference is exact, only rounding is left
            d = (bspline_shape(knots, e, x + step, 1) - bspline_shape(knots, e, x - step, 1))/(2*step)
            magnitude = maxval(abs(bspline_shape(knots, e, x + step, 1))) + maxval(abs(bspline_shape(knots, e, x - step, 1)))
            call t%check_close(trim(label)//' second derivative vs difference', &
                               maxval(abs(d - bspline_shape(knots, e, x, 2))), 0.0_dp, 1.0_dp, &
                               gamma_n(24)*magnitude/(2*step) + gamma_n(24)*maxval(abs(d)))
         end do
      end do
      call build_model('bspline', elements, length, 1.0_dp, 1.0_dp, model, stat, errmsg)
      call t%check_true(trim(label)//' build_model', stat == 0, errmsg)
      allocate (coefficients(model%unknowns))
      coefficients = [(sin(1.7_dp*i) + 0.3_dp, i=1, model%unknowns)]
      ! clamp
      do order = 0, 1
         call point_row(model, 0.0_dp, dofs, weights, order)
         value = 0
         do i = 1, 4
            if (dofs(i) /= 0) value = value + weights(i)*coefficients(dofs(i))
         end do
         ! 4 products of gamma_21-accurate weights: gamma_25 times the sum of |terms|
         call t%check_close(trim(label)//' clamp', value, 0.0_dp, 1.0_dp, &
                            gamma_n(25)*sum(abs(weights)*abs(coefficients(max(dofs, 1))), mask=dofs /= 0))
      end do
      ! C^2 at interior nodes: the element on the left against the one on the right; each
      ! side a sum of 4 products of gamma_21-accurate basis values: gamma_25 sum |terms|
      do e = 1, elements - 1
         x = e*h
         do order = 0, 2
            left(order + 1) = evaluate(model, e, x, order, coefficients)
            right(order + 1) = evaluate(model, e + 1, x, order, coefficients)
            bound(order + 1) = gamma_n(25)*(evaluate(model, e, x, order, coefficients, absolute=.true.) + &
                                            evaluate(model, e + 1, x, order, coefficients, absolute=.true.))
         end do
         call t%check_close(trim(label)//' C2 continuity (largest difference / its bound)', &
                            maxval(abs(left - right)/bound), 0.0_dp, 1.0_dp, 1.0_dp)
      end do
      ! cubic reproduction through interpolate_field: p(x) = x^2 (3 - x), p(0) = p'(0) = 0.
      ! The coefficients solve A c = b (N node values and the tip slope) by banded Gaussian
      ! elimination with partial pivoting (LAPACK dgbsv): (A + dA) c = b + db with
      ! |dA| <= gamma_{3n} P^T|L||U| (Higham, Thm 9.4; the band has the dense pivots, so
      ! the factors of a dense dgetrf of A are the same) and |db| <= gamma_4 |b| (the
      ! cubic's values), so |dc| <= |A^-1| (gamma_{3n} P^T|L||U||c| + gamma_4 |b|); each
      ! value then adds sum |w_a| |dc_a| and the rounding of the sum, gamma_25 sum |w_a c_a|.
      u = interpolate_field(model, [(cubic(model%x(i + 1), 0), i=0, elements)], [(cubic(model%x(i + 1), 1), i=0, elements)])
      n = model%unknowns
      allocate (collocation(n, n), source=0.0_dp)
      do i = 1, elements
         call node_row(model, i, dofs, weights)
         do j = 1, 4
            if (dofs(j) /= 0) collocation(i, dofs(j)) = weights(j)
         end do
      end do
      call point_row(model, model%length, dofs, weights, order=1)
      do j = 1, 4
         if (dofs(j) /= 0) collocation(n, dofs(j)) = weights(j)
      end do
      factors = collocation
      allocate (pivots(n))
      call dgetrf(n, n, factors, n, pivots, info)
      inverse = dense_inverse(collocation)
      coefficient_error = matmul(abs(inverse), gamma_n(3*n)*permuted_lu_times(factors, pivots, abs(u)) + &
                                 gamma_n(4)*abs([(cubic(model%x(i + 1), 0), i=1, elements), cubic(model%length, 1)]))
      do i = 0, 20
         x = length*i/20
         call point_row(model, x, dofs, weights)
         value = 0
         do e = 1, 4
            if (dofs(e) /= 0) value = value + weights(e)*u(dofs(e))
         end do
         exact = cubic(x, 0)
         call t%check_close(trim(label)//' cubic reproduction', abs(value - exact), 0.0_dp, 1.0_dp, &
                            sum(abs(weights)*coefficient_error(max(dofs, 1)), mask=dofs /= 0) + &
                            gamma_n(25)*sum(abs(weights*u(max(dofs, 1))), mask=dofs /= 0) + gamma_n(4)*abs(exact))
      end do
      call uniform_velocity(model, label)
   end subroutine check_mesh

   !> The B-spline 'uniform' initial velocity: a monotone ramp over two elements, then A.
   !! Values are sums of 4 products of gamma_21-accurate basis values with coefficients A:
   !! gamma_25 A (partition of unity); slopes gamma_28 sum |B'_a| A.
   subroutine uniform_velocity(model, label)
      type(beam_model), intent(in) :: model
      character(len=*), intent(in) :: label
      real(dp), parameter :: amplitude = 0.7_dp
      type(scene_type) :: scene
      real(dp) :: v(model%unknowns)
      real(dp) :: x, value, previous, weights(4)
      integer :: i, dofs(4)
      scene%initial%velocity = 'uniform'
      scene%initial%velocity_amplitude = amplitude
      v = initial_velocity(scene%initial, model)
      previous = 0
      do i = 0, 400
         x = model%length*i/400
         call point_row(model, x, dofs, weights)
         value = sum(weights*v(max(dofs, 1)), mask=dofs /= 0)
         call t%check_close(label//' uniform velocity: not above the amplitude', max(value - amplitude, 0.0_dp), &
                            0.0_dp, 1.0_dp, gamma_n(25)*amplitude)
         call t%check_close(label//' uniform velocity: nondecreasing', max(previous - value, 0.0_dp), 0.0_dp, 1.0_dp, &
                            2*gamma_n(25)*amplitude)
         previous = value
         if (x >= 2*model%h) then
            call t%check_close(label//' uniform velocity: A from x = 2h on', value, amplitude, gamma_n(25))
            call point_row(model, x, dofs, weights, order=1)
            call t%check_close(label//' uniform velocity: zero slope from x = 2h on', &
                               sum(weights*v(max(dofs, 1)), mask=dofs /= 0), 0.0_dp, 1.0_dp, &
                               gamma_n(28)*sum(abs(weights))*amplitude)
         end if
      end do
      if (model%elements >= 2) then
         call point_row(model, model%h, dofs, weights)
         call t%check_close(label//' uniform velocity: 3/4 A at x = h', sum(weights*v(max(dofs, 1)), mask=dofs /= 0), &
                            0.75_dp*amplitude, gamma_n(25))
      end if
   end subroutine uniform_velocity

   pure real(dp) function cubic(x, order)
      real(dp), intent(in) :: x
      integer, intent(in) :: order
      if (order == 0) then
         cubic = x**2*(3 - x)
      else
         cubic = 6*x - 3*x**2
      end if
   end function cubic

   !> Derivative `order` at x of the spline with unknowns `c`, using element e's piece
   !! (with `absolute`: the sum of the |terms| instead).
   function evaluate(model, e, x, order, c, absolute) result(value)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: e, order
      real(dp), intent(in) :: x, c(:)
      logical, intent(in), optional :: absolute
      real(dp) :: value, n(4)
      integer :: a, basis
      n = bspline_shape(model%knots, e, x, order)
      value = 0
      do a = 1, 4
         basis = e + a - 1 - 2     ! unknown index = basis index - 2 (c_1 = c_2 = 0: clamp)
         if (basis < 1) cycle
         if (present(absolute)) then
            value = value + abs(n(a)*c(basis))
         else
            value = value + n(a)*c(basis)
         end if
      end do
   end function evaluate

end program test_bspline_basis
