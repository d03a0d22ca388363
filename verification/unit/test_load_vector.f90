!> Unit test: consistent load vectors. For U the Hermite interpolant of a cubic p(x) (exact:
!! Hermite cubics reproduce cubics), F(q)^T U = integral of q(x) p(x) dx, computed here in
!! closed form; the point-load vector at x_p gives F^T U = p(x_p).
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
      ones = interpolate_field(model, [(one(model%x(i)), i=2, size(model%x))], &
                               [(zero(model%x(i)), i=2, size(model%x))])
      square = interpolate_field(model, [(x_squared(model%x(i)), i=2, size(model%x))], &
                                 [(two_x(model%x(i)), i=2, size(model%x))])
      cube = interpolate_field(model, [(x_cubed(model%x(i)), i=2, size(model%x))], &
                               [(three_x_squared(model%x(i)), i=2, size(model%x))])
      f = load_vector(model, one)
      call t%check_close(trim(label)//' uniform q=1: F.1 = L - h/2', dot_product(f, ones), length - h/2, 1e-14_dp)
      call t%check_close(trim(label)//' uniform q=1: F.x^2 = L^3/3', dot_product(f, square), length**3/3, 1e-14_dp)
      f = load_vector(model, linear)
      call t%check_close(trim(label)//' q=x: F.x^3 = L^5/5', dot_product(f, cube), length**5/5, 1e-14_dp)
      f = point_load_vector(model, 0.7_dp*length)
      call t%check_close(trim(label)//' point load at 0.7L: F.x^3', dot_product(f, cube), (0.7_dp*length)**3, 1e-13_dp)
      f = point_load_vector(model, length)
      call t%check_close(trim(label)//' point load at tip: F.x^2', dot_product(f, square), length**2, 1e-14_dp)
   end do
   call t%finish('test_load_vector')
end program test_load_vector
