!> A consumer of the installed library: builds the Hermite model of a cantilever under a
!! uniform load q, solves K u = f with the library's band solver and compares the tip
!! deflection and rotation with the closed forms u(L) = q L^4/(8 EI), u'(L) = q L^3/(6 EI)
!! (theory §7). Hermite cubic elements reproduce the exact solution at the nodes of a
!! one-dimensional problem with consistent loads (P. Tong, Exact solution of certain
!! problems by finite-element method, AIAA Journal 7 (1969) 178-180), so the only error is
!! the round-off of the solve.
!! usage: static_tip VERSION   (the version the package must report)
program static_tip
   use vibrobeam_kinds, only: dp
   use vibrobeam_version, only: version_string
   use vibrobeam_model, only: beam_model, build_model, load_vector, unit_profile
   use vibrobeam_band, only: band_cholesky, band_factor, band_solve, band_entry
   implicit none
   integer, parameter :: elements = 8
   real(dp), parameter :: length = 0.5_dp, ei = 350.0_dp, q = -100.0_dp   ! m, N m^2, N/m
   type(beam_model) :: model
   type(band_cholesky) :: factor
   real(dp), allocatable :: u(:), column(:)
   real(dp) :: norm_k, norm_inverse, condition, tolerance, exact(2), computed(2), error(2)
   character(len=32) :: expected_version
   character(len=256) :: errmsg
   integer :: stat, i, j

   call get_command_argument(1, expected_version)
   if (version_string /= trim(expected_version)) then
      print '(4a)', 'FAIL: the library reports version ', version_string, ', expected ', trim(expected_version)
      error stop 1
   end if
   call build_model('hermite', elements, length, 1.0_dp, ei, model, stat, errmsg)
   if (stat /= 0) call fail('build_model: '//trim(errmsg))
   call band_factor(model%stiffness, factor, stat, errmsg)
   if (stat /= 0) call fail('band_factor: '//trim(errmsg))
   u = q*load_vector(model, unit_profile)
   call band_solve(factor, u)

   ! The tolerance: a backward-stable band solve gives a relative error of at most about
   ! (2 kd + 1) eps kappa_1(K) (Higham, Accuracy and Stability of Numerical Algorithms,
   ! 2nd ed., section 10.1), kd = 3, with kappa_1 = ||K||_1 ||K^-1||_1 computed here from
   ! the columns of K^-1 (J band solves); a factor 10 for the load vector's round-off.
   norm_k = 0
   norm_inverse = 0
   allocate (column(model%unknowns))
   do j = 1, model%unknowns
      norm_k = max(norm_k, sum([(abs(band_entry(model%stiffness, i, j)), i=1, model%unknowns)]))
      column = 0
      column(j) = 1
      call band_solve(factor, column)
      norm_inverse = max(norm_inverse, sum(abs(column)))
   end do
   condition = norm_k*norm_inverse
   tolerance = 10*(2*3 + 1)*epsilon(1.0_dp)*condition

   exact = [q*length**4/(8*ei), q*length**3/(6*ei)]
   computed = u(model%unknowns - 1:model%unknowns)   ! (w_N, theta_N): the tip
   error = abs(computed - exact)/abs(exact)
   print '(a, a)', 'vibrobeam ', version_string
   print '(a, es23.15, a, es23.15, a, es9.2)', 'tip deflection ', computed(1), ' m, exact ', exact(1), &
      ', relative error ', error(1)
   print '(a, es23.15, a, es23.15, a, es9.2)', 'tip rotation   ', computed(2), ' rad, exact ', exact(2), &
      ', relative error ', error(2)
   print '(a, es9.2, a, es9.2, a)', 'tolerance ', tolerance, ' (kappa_1(K) = ', condition, ')'
   if (any(error > tolerance)) call fail('the tip differs from the closed form by more than the tolerance')
   print '(a)', 'PASS'

contains

   subroutine fail(message)
      character(len=*), intent(in) :: message
      print '(2a)', 'FAIL: ', message
      error stop 1
   end subroutine fail
end program static_tip
