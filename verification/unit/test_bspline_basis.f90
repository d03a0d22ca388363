!> Unit test of the cubic B-spline basis (`vibrobeam_bspline`) and of the B-spline model:
!! - partition of unity: the four nonzero B-splines of an element sum to 1 and their first
!!   and second derivatives sum to 0, at points inside every element (N = 1, 2, 3, 7);
!! - C^2 continuity: value, slope and curvature of a random spline agree from both sides of
!!   every interior node to 1e-12;
!! - derivatives: the first and second derivatives equal central differences of the
!!   values (h-relative step 1e-4, tolerance 1e-6);
!! - the clamp: with the model's unknowns, u(0) = u_x(0) = 0 for any coefficients;
!! - cubic reproduction: the spline interpolating a cubic with u(0) = u_x(0) = 0
!!   (x^2 (3 - x), built by `interpolate_field`) equals it everywhere (1e-12).
program test_bspline_basis
   use vibrobeam_kinds, only: dp
   use vibrobeam_bspline, only: bspline_knots, bspline_shape
   use vibrobeam_model, only: beam_model, build_model, point_row, interpolate_field
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
      real(dp) :: knots(elements + 7), h, x, step, left(3), right(3), value, exact
      real(dp), allocatable :: u(:), coefficients(:)
      type(beam_model) :: model
      integer :: e, i, order, stat, dofs(4)
      real(dp) :: weights(4), d(4)
      character(len=200) :: errmsg
      character(len=48) :: label
      write (label, '(a,i0)') 'N = ', elements
      knots = bspline_knots(elements, length)
      h = length/elements
      do e = 1, elements
         do i = 1, 5
            x = (e - 1)*h + h*(i - 0.5_dp)/5
            call t%check_close(trim(label)//' partition of unity', sum(bspline_shape(knots, e, x, 0)), 1.0_dp, 1e-14_dp)
            call t%check_close(trim(label)//' derivatives of unity', sum(bspline_shape(knots, e, x, 1)), 0.0_dp, &
                               1.0_dp, 1e-12_dp/h)
            call t%check_close(trim(label)//' curvatures of unity', sum(bspline_shape(knots, e, x, 2)), 0.0_dp, &
                               1.0_dp, 1e-10_dp/h**2)
            step = 1e-4_dp*h
            d = (bspline_shape(knots, e, x + step, 0) - bspline_shape(knots, e, x - step, 0))/(2*step)
            call t%check_close(trim(label)//' first derivative vs difference', &
                               maxval(abs(d - bspline_shape(knots, e, x, 1))), 0.0_dp, 1.0_dp, 1e-6_dp/h)
            d = (bspline_shape(knots, e, x + step, 1) - bspline_shape(knots, e, x - step, 1))/(2*step)
            call t%check_close(trim(label)//' second derivative vs difference', &
                               maxval(abs(d - bspline_shape(knots, e, x, 2))), 0.0_dp, 1.0_dp, 1e-6_dp/h**2)
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
         call t%check_close(trim(label)//' clamp', value, 0.0_dp, 1.0_dp, 1e-13_dp)
      end do
      ! C^2 at interior nodes: the element on the left against the one on the right
      do e = 1, elements - 1
         x = e*h
         do order = 0, 2
            left(order + 1) = evaluate(model, e, x, order, coefficients)
            right(order + 1) = evaluate(model, e + 1, x, order, coefficients)
         end do
         call t%check_close(trim(label)//' C2 continuity', maxval(abs(left - right)), 0.0_dp, 1.0_dp, &
                            1e-12_dp*max(1.0_dp, maxval(abs(left))))
      end do
      ! cubic reproduction through interpolate_field: p(x) = x^2 (3 - x), p(0) = p'(0) = 0
      u = interpolate_field(model, [(cubic(model%x(i + 1), 0), i=1, elements)], [(cubic(model%x(i + 1), 1), i=1, elements)])
      do i = 0, 20
         x = length*i/20
         call point_row(model, x, dofs, weights)
         value = 0
         do e = 1, 4
            if (dofs(e) /= 0) value = value + weights(e)*u(dofs(e))
         end do
         exact = cubic(x, 0)
         call t%check_close(trim(label)//' cubic reproduction', value, exact, 1.0_dp, 1e-12_dp*max(1.0_dp, abs(exact)))
      end do
   end subroutine check_mesh

   pure real(dp) function cubic(x, order)
      real(dp), intent(in) :: x
      integer, intent(in) :: order
      if (order == 0) then
         cubic = x**2*(3 - x)
      else
         cubic = 6*x - 3*x**2
      end if
   end function cubic

   !> Derivative `order` at x of the spline with unknowns `c`, using element e's piece.
   function evaluate(model, e, x, order, c) result(value)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: e, order
      real(dp), intent(in) :: x, c(:)
      real(dp) :: value, n(4)
      integer :: a, basis
      n = bspline_shape(model%knots, e, x, order)
      value = 0
      do a = 1, 4
         basis = e + a - 1 - 2     ! unknown index = basis index - 2 (c_1 = c_2 = 0: clamp)
         if (basis >= 1) value = value + n(a)*c(basis)
      end do
   end function evaluate
end program test_bspline_basis
