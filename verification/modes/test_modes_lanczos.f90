!> The closed-form static solutions of test_modes_lanczos (a module, so that `ramp` can be
!! passed to load_vector without a trampoline on the stack).
module test_modes_lanczos_exact
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: ramp, deflection_ramp, slope_ramp, deflection_tip
contains

   !> The load q(x) = x.
   pure function ramp(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      value = x
   end function ramp

   !> Exact deflection and slope of the cantilever (EI = L = 1) under q(x) = x.
   pure function deflection_ramp(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      value = x**2/6 - x**3/12 + x**5/120
   end function deflection_ramp

   pure function slope_ramp(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      value = x/3 - x**2/4 + x**4/24
   end function slope_ramp

   !> Exact deflection under a tip force 1 and a tip moment 1/2 (EI = L = 1).
   pure function deflection_tip(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      value = x**2*(3 - x)/6 + x**2/4
   end function deflection_tip

end module test_modes_lanczos_exact

!> Verification (issue 13): natural modes at any size, by shift-invert Lanczos (ARPACK-NG)
!! with K^-1 applied by double integration of the curvature (`vibrobeam_flexibility`).
!! u = eps/2 below; N elements, J unknowns.
!!
!! 1. K^-1 f against closed-form static solutions (EI = L = 1), N = 1 ... 1e5:
!!    - Hermite, load q(x) = x: the Hermite solution equals the exact deflection
!!      x^2/6 - x^3/12 + x^5/120 and slope at every node (the beam's Green's function is
!!      piecewise cubic, so consistent loads give nodally exact answers);
!!    - both bases, tip force P = 1 and tip moment C = 1/2: the exact solution
!!      x^2 (3 - x)/6 + x^2/4 is a cubic, which both spaces contain.
!!    Tolerance (4N + 20) u relative: the loads here make every partial sum of the two
!!    moment recursions and of the two integrations one-signed, so each of the four sums
!!    of N terms is within gamma_N of its value; 20 u covers the 2 x 2 or tridiagonal
!!    curvature solve (condition number <= 3) and the nodal evaluation.
!! 2. The Lanczos and the dense (LAPACK dsbgvx) paths give the same 6 frequencies to
!!    1e-10 relative (the acceptance criterion of issue 13), N = 20, 50, 200, 500, both
!!    bases, and the same tip-normalized shapes within a first-order bound of the dense
!!    path's eigenvector error: its Cholesky of K leaves a backward error of about
!!    (kd+1) u lambda_max in the pencil (lambda_max the largest eigenvalue, computed here),
!!    which turns mode k by at most that over the gap, (kd+1) u lambda_max/(lambda_k g_k)
!!    with g_k = min(1 - lambda_k/lambda_(k+1), lambda_k/lambda_(k-1) - 1), in the M norm;
!!    4 sqrt(N) bounds the largest nodal value by the M norm (rho S = L = 1: a cubic p on
!!    an element of length h has max p^2 <= 16/h int p^2, from its Legendre expansion) and
!!    the tip value of a cantilever mode is twice its M norm. The Lanczos shapes, accurate to
!!    round-off (item 3), carry no error of that size. Measured: at most 0.005 of it; it
!!    catches a wrong mode, order or sign.
!! 3. At N = 1e4 and 1e5 (only Lanczos runs: dsbgvx would need 8 J^2 bytes), frequencies
!!    and tip-normalized shapes at the nodes equal the closed-form cantilever's: the
!!    discretization error is below 3.7e-6 (64/N)^4 < 3e-15 (README's N = 64 row, order 4),
!!    the round-off of K^-1 is (4N + 20) u as in 1 on these smooth modes, and ARPACK
!!    converges to eps: frequencies within (4N + 20) u + eps + 3e-15, shapes within
!!    ((4N + 20) u + eps)/0.45 + 3e-15 of max |shape| (0.45: the smallest relative gap
!!    1 - lambda_k/lambda_(k+1) of the first 6 cantilever eigenvalues).
!! 4. Asking Lanczos for J modes fails with a message; `dense_is_cheaper` takes the dense
!!    path below 17 unknowns and above J/4 modes.
program test_modes_lanczos
   use vibrobeam_kinds, only: dp
   use vibrobeam_model, only: beam_model, build_model, load_vector, point_load_vector, point_row, nodal_displacement
   use vibrobeam_flexibility, only: cantilever_flexibility
   use vibrobeam_modes, only: compute_modes, dense_is_cheaper
   use vibrobeam_cantilever_exact, only: cantilever_root, cantilever_mode_shape
   use vibrobeam_test_support, only: test_counter
   use vibrobeam_lapack, only: dsbgvx
   use test_modes_lanczos_exact, only: ramp, deflection_ramp, slope_ramp, deflection_tip
   implicit none
   real(dp), parameter :: u = epsilon(1.0_dp)/2
   integer, parameter :: modes = 6
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   integer, parameter :: static_meshes(6) = [1, 2, 3, 10, 1000, 100000]
   integer, parameter :: compared_meshes(4) = [20, 50, 200, 500]
   integer, parameter :: large_meshes(2) = [10000, 100000]
   type(test_counter) :: t
   integer :: b, k
   real(dp) :: largest_difference = 0, largest_shape_ratio = 0

   do b = 1, size(bases)
      do k = 1, size(static_meshes)
         call check_static(bases(b), static_meshes(k))
      end do
      do k = 1, size(compared_meshes)
         call compare_paths(bases(b), compared_meshes(k))
      end do
      do k = 1, size(large_meshes)
         call check_closed_form(bases(b), large_meshes(k))
      end do
   end do
   write (*, '(a,es10.2)') 'largest relative difference of frequencies, Lanczos - dense: ', largest_difference
   write (*, '(a,es10.2)') 'largest difference of shapes, Lanczos - dense, over its bound: ', largest_shape_ratio
   call check_requests()
   call t%finish('test_modes_lanczos')

contains

   subroutine check_static(basis, elements)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(beam_model) :: model
      type(cantilever_flexibility) :: flexibility
      real(dp), allocatable :: f(:), deflection(:)
      real(dp) :: exact(elements + 1)
      real(dp) :: weights(4), slope, tolerance
      integer :: dofs(4), stat, i, a
      character(len=200) :: errmsg
      character(len=80) :: label
      call build_model(basis, elements, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      call flexibility%setup(model, stat, errmsg)
      call t%check_true('flexibility setup', stat == 0, errmsg)
      tolerance = (4*elements + 20)*u
      if (basis == 'hermite') then
         f = load_vector(model, ramp)
         call flexibility%solve(f)
         exact(1:elements) = [(deflection_ramp(model%x(i)), i=2, elements + 1)]
         write (label, '(a,i0)') 'Hermite, q = x, nodal deflection, N = ', elements
         call t%check_close(trim(label), maxval(abs(f(1::2) - exact(1:elements)))/maxval(abs(exact(1:elements))), &
                            0.0_dp, 1.0_dp, tolerance)
         exact(1:elements) = [(slope_ramp(model%x(i)), i=2, elements + 1)]
         write (label, '(a,i0)') 'Hermite, q = x, nodal slope, N = ', elements
         call t%check_close(trim(label), maxval(abs(f(2::2) - exact(1:elements)))/maxval(abs(exact(1:elements))), &
                            0.0_dp, 1.0_dp, tolerance)
      end if
      ! tip force 1 and tip moment 1/2
      f = point_load_vector(model, 1.0_dp)
      call point_row(model, 1.0_dp, dofs, weights, order=1)
      do a = 1, 4
         if (dofs(a) /= 0) f(dofs(a)) = f(dofs(a)) + 0.5_dp*weights(a)
      end do
      call flexibility%solve(f)
      deflection = nodal_displacement(model, f)
      exact = [(deflection_tip(model%x(i)), i=1, elements + 1)]
      write (label, '(a,i0)') trim(basis)//', tip force and moment, nodal deflection, N = ', elements
      call t%check_close(trim(label), maxval(abs(deflection - exact))/maxval(abs(exact)), 0.0_dp, 1.0_dp, tolerance)
      slope = 0
      do a = 1, 4
         if (dofs(a) /= 0) slope = slope + weights(a)*f(dofs(a))
      end do
      write (label, '(a,i0)') trim(basis)//', tip force and moment, tip slope, N = ', elements
      call t%check_close(trim(label), slope, 1.0_dp, tolerance)
   end subroutine check_static

   subroutine compare_paths(basis, elements)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      type(beam_model) :: model
      real(dp), allocatable :: omega_lanczos(:), omega_dense(:), shapes_lanczos(:,:), shapes_dense(:,:), vectors(:,:)
      real(dp) :: highest, gap, tolerance
      integer :: stat, k
      character(len=200) :: errmsg
      character(len=80) :: label
      call build_model(basis, elements, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      call compute_modes(model, modes + 1, omega_lanczos, shapes_lanczos, vectors, stat, errmsg, 'lanczos')
      call t%check_true('Lanczos path', stat == 0, errmsg)
      call compute_modes(model, modes, omega_dense, shapes_dense, vectors, stat, errmsg, 'dense')
      call t%check_true('dense path', stat == 0, errmsg)
      if (stat /= 0) return
      highest = highest_eigenvalue(model)
      do k = 1, modes
         write (label, '(a,i0,a,i0)') trim(basis)//', N = ', elements, ', mode ', k
         call t%check_close(trim(label)//', omega, Lanczos against dense', omega_lanczos(k), omega_dense(k), 1e-10_dp)
         ! shapes: first-order bound of the dense eigenvector's error (header, item 2)
         gap = 1 - (omega_lanczos(k)/omega_lanczos(k + 1))**2
         if (k > 1) gap = min(gap, (omega_lanczos(k)/omega_lanczos(k - 1))**2 - 1)
         tolerance = 4*u*highest/omega_lanczos(k)**2/gap*4*sqrt(real(elements, dp))
         call t%check_close(trim(label)//', tip-normalized shape, Lanczos against dense', &
                            maxval(abs(shapes_lanczos(:, k) - shapes_dense(:, k))), 0.0_dp, 1.0_dp, tolerance)
         largest_shape_ratio = max(largest_shape_ratio, maxval(abs(shapes_lanczos(:, k) - shapes_dense(:, k)))/tolerance)
      end do
      largest_difference = max(largest_difference, maxval(abs(omega_lanczos(:modes) - omega_dense)/omega_dense))
   end subroutine compare_paths

   !> The largest eigenvalue of K phi = lambda M phi (LAPACK dsbgvx on the pencil (K, M),
   !! whose error is eps times that eigenvalue).
   function highest_eigenvalue(model) result(lambda)
      type(beam_model), intent(in) :: model
      real(dp) :: lambda
      real(dp) :: stiffness(4, model%unknowns), mass(4, model%unknowns), q(1, 1), w(model%unknowns), z(1, 1), &
                  work(7*model%unknowns)
      integer :: n, found, iwork(5*model%unknowns), ifail(model%unknowns), info
      n = model%unknowns
      stiffness = model%stiffness%lower
      mass = model%mass%lower
      call dsbgvx('N', 'I', 'L', n, 3, 3, stiffness, 4, mass, 4, q, 1, 0.0_dp, 0.0_dp, n, n, 0.0_dp, found, w, &
                  z, 1, work, iwork, ifail, info)
      if (info /= 0 .or. found /= 1) error stop 'dsbgvx failed on the highest eigenvalue'
      lambda = w(1)
   end function highest_eigenvalue

   subroutine check_closed_form(basis, elements)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), parameter :: discretization = 3e-15_dp, relative_gap = 0.45_dp
      type(beam_model) :: model
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      real(dp) :: roundoff, error
      integer :: stat, k, i
      character(len=200) :: errmsg
      character(len=80) :: label
      call build_model(basis, elements, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      call compute_modes(model, modes, omega, shapes, vectors, stat, errmsg)
      call t%check_true('compute_modes', stat == 0, errmsg)
      if (stat /= 0) return
      roundoff = (4*elements + 20)*u + epsilon(1.0_dp)
      do k = 1, modes
         write (label, '(a,i0,a,i0)') trim(basis)//', N = ', elements, ', mode ', k
         call t%check_close(trim(label)//', omega against the closed form', omega(k), cantilever_root(k)**2, &
                            roundoff + discretization)
         error = maxval([(abs(shapes(i, k) - cantilever_mode_shape(k, model%x(i), 1.0_dp, 0)), i=1, size(model%x))])
         call t%check_close(trim(label)//', shape against the closed form', error/maxval(abs(shapes(:, k))), &
                            0.0_dp, 1.0_dp, roundoff/relative_gap + discretization)
      end do
   end subroutine check_closed_form

   subroutine check_requests()
      type(beam_model) :: model
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      integer :: stat
      character(len=200) :: errmsg
      call build_model('hermite', 8, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      call compute_modes(model, 16, omega, shapes, vectors, stat, errmsg, 'lanczos')
      call t%check_true('Lanczos for all J modes fails', stat /= 0 .and. index(errmsg, 'outside [1, 15]') > 0, errmsg)
      call compute_modes(model, 16, omega, shapes, vectors, stat, errmsg)
      call t%check_true('all J modes: the dense path', stat == 0 .and. size(omega) == 16, errmsg)
      call t%check_true('dense below 17 unknowns', dense_is_cheaper(16, 1))
      call t%check_true('dense above J/4 modes', dense_is_cheaper(400, 101))
      call t%check_true('Lanczos for 100 modes of 400', .not. dense_is_cheaper(400, 100))
   end subroutine check_requests
end program test_modes_lanczos
