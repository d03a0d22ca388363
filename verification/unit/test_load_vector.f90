!> Unit test: consistent load vectors. For U the Hermite interpolant of a cubic p(x) (exact:
!! Hermite cubics reproduce cubics), F(q)^T U = integral of q(x) p(x) dx, computed here in
!! closed form; the point-load vector at x_p gives F^T U = p(x_p).
!! Round-off (u = eps/2, gamma_n = n u/(1 - n u)): every Hermite shape function keeps one
!! sign on an element, so for a load of one sign the quadrature terms of each F_j share
!! its sign and F_j is off by at most gamma_20 |F_j| (4 Gauss terms per element, 2
!! elements, each term 12 roundings: the profile, the shape polynomial, the products); the
!! interpolant's entries x_i^p and p x_i^(p-1) by gamma_3; the dot product of J terms by
!! gamma_J: |F.U - exact| <= gamma_{J+23} sum |F_j U_j| + gamma_3 |exact| (the closed
!! forms L - h/2, L^3/3, L^5/5, x_p^3 round 3 times).
module load_profiles
   use vibrobeam_kinds, only: dp
   implicit none
   public
contains
   pure function one(x) result(v)
      real(dp), intent(in) :: x
      real(dp) :: v
      v = 1 + 0*x
   end function one
   pure function zero(x) result(v)
      real(dp), intent(in) :: x
      real(dp) :: v
      v = 0*x
   end function zero
   pure function linear(x) result(v)
      real(dp), intent(in) :: x
      real(dp) :: v
      v = x
   end function linear
   pure function x_squared(x) result(v)
      real(dp), intent(in) :: x
      real(dp) :: v
      v = x**2
   end function x_squared
   pure function two_x(x) result(v)
      real(dp), intent(in) :: x
      real(dp) :: v
      v = 2*x
   end function two_x
   pure function x_cubed(x) result(v)
      real(dp), intent(in) :: x
      real(dp) :: v
      v = x**3
   end function x_cubed
   pure function three_x_squared(x) result(v)
      real(dp), intent(in) :: x
      real(dp) :: v
      v = 3*x**2
   end function three_x_squared
end module load_profiles

program test_load_vector
   use vibrobeam_kinds, only: dp
   use vibrobeam_model, only: beam_model, build_model, load_vector, point_load_vector, interpolate_field
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter
   use load_profiles
   implicit none
   type(test_counter) :: t
   type(beam_model) :: model
   real(dp), allocatable :: f(:), ones(:), square(:), cube(:)
   real(dp) :: length, h
   integer :: stat, k, i
   integer, parameter :: meshes(4) = [1, 3, 16, 101]
   character(len=200) :: errmsg
   character(len=32) :: label
   length = 2.5_dp
   do k = 1, size(meshes)
      write (label, '(a,i0)') 'N=', meshes(k)
      call build_model('hermite', meshes(k), length, 1.0_dp, 1.0_dp, model, stat, errmsg)
      h = model%h
      ! u = 1 at every node but the clamped one: integral of q * (its interpolant)
      ones = interpolate_field(model, [(one(model%x(i)), i=1, size(model%x))], &
                               [(zero(model%x(i)), i=1, size(model%x))])
      square = interpolate_field(model, [(x_squared(model%x(i)), i=1, size(model%x))], &
                                 [(two_x(model%x(i)), i=1, size(model%x))])
      cube = interpolate_field(model, [(x_cubed(model%x(i)), i=1, size(model%x))], &
                               [(three_x_squared(model%x(i)), i=1, size(model%x))])
      f = load_vector(model, one)
      call check_dot(trim(label)//' uniform q=1: F.1 = L - h/2', f, ones, length - h/2)
      call check_dot(trim(label)//' uniform q=1: F.x^2 = L^3/3', f, square, length**3/3)
      f = load_vector(model, linear)
      call check_dot(trim(label)//' q=x: F.x^3 = L^5/5', f, cube, length**5/5)
      f = point_load_vector(model, 0.7_dp*length)
      call check_dot(trim(label)//' point load at 0.7L: F.x^3', f, cube, (0.7_dp*length)**3)
      f = point_load_vector(model, length)
      call check_dot(trim(label)//' point load at tip: F.x^2', f, square, length**2)
   end do
   call t%finish('test_load_vector')
contains
   !> F.U against its closed form, to the round-off bound of the module comment.
   subroutine check_dot(name, f, u, exact)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: f(:), u(:), exact
      call t%check_close(name, abs(dot_product(f, u) - exact), 0.0_dp, 1.0_dp, &
                         gamma_n(size(f) + 23)*sum(abs(f*u)) + gamma_n(3)*abs(exact))
   end subroutine check_dot
end program test_load_vector
