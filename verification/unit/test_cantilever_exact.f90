!> Unit test of the closed-form references (SPEC §6): the roots of 1 + cos b cosh b = 0
!! and tan b = tanh b against the published values quoted in SPEC §6, and the mode shapes
!! against their boundary conditions (clamped at 0, free at L), tip value 1, the beam
!! equation phi'''' = beta^4 phi (checked by a central difference of phi''') and
!! orthogonality (midpoint rule written here).
!! Tolerances (u = eps/2, gamma_n = n u/(1 - n u)), derived beside each check: the
!! published roots carry 10 decimals (5e-11); Newton's method ends within a few roundings
!! of the root (gamma_8 relative). A shape value is a sum of 4 terms of size <= 2 whose
!! arguments a = beta x <= B = beta L are rounded (an absolute error of gamma_8 B in sin,
!! cos), divided by the classical tip value 2: off by at most (3 gamma_8 B + 2 gamma_10)
!! beta^k for the k-th derivative.
program test_cantilever_exact
   use vibrobeam_kinds, only: dp
   use vibrobeam_cantilever_exact, only: cantilever_root, pinned_tip_root, cantilever_mode_shape
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: spec_roots(6) = [1.8751040687_dp, 4.6940911330_dp, 7.8547574382_dp, &
                                           10.9955407349_dp, 14.1371683910_dp, 17.2787595321_dp]
   real(dp), parameter :: spec_pinned(3) = [3.9266023120_dp, 7.0685827456_dp, 10.2101761228_dp]
   real(dp), parameter :: length = 1.7_dp
   real(dp) :: beta, step, d4, x, overlap, shape_error, truncation, cell
   integer :: n, i, m
   character(len=40) :: label
   do n = 1, 6
      write (label, '(a,i0)') 'cantilever root ', n
      call t%check_close(trim(label), abs(cantilever_root(n) - spec_roots(n)), 0.0_dp, 1.0_dp, &
                         0.5e-10_dp + gamma_n(8)*spec_roots(n))
   end do
   ! beyond the table, roots approach (2n-1) pi/2: b_30 - 59 pi/2 ~ 2 exp(-59 pi/2) < 1e-40,
   ! so only the rounding of the root and of 59 pi/2 is left
   call t%check_close('cantilever root 30 ~ (2n-1)pi/2', abs(cantilever_root(30) - 59*acos(-1.0_dp)/2), 0.0_dp, &
                      1.0_dp, gamma_n(8)*59*acos(-1.0_dp)/2)
   do n = 1, 3
      write (label, '(a,i0)') 'pinned-tip root ', n
      call t%check_close(trim(label), abs(pinned_tip_root(n) - spec_pinned(n)), 0.0_dp, 1.0_dp, &
                         0.5e-10_dp + gamma_n(8)*spec_pinned(n))
   end do
   do n = 1, 12
      beta = cantilever_root(n)/length
      write (label, '(a,i0)') 'mode ', n
      shape_error = 3*gamma_n(8)*beta*length + 2*gamma_n(10)   ! of phi^(k)/beta^k
      ! at x = 0 the terms are exactly 1, 0, -1, 0 (value) and -1, d, 0, s = 1 - d (slope)
      call t%check_close(trim(label)//' phi(0)', cantilever_mode_shape(n, 0.0_dp, length, 0), 0.0_dp, 1.0_dp, &
                         gamma_n(4))
      call t%check_close(trim(label)//' phi''(0)', cantilever_mode_shape(n, 0.0_dp, length, 1), 0.0_dp, 1.0_dp, &
                         gamma_n(8)*beta)
      ! the tip value is divided by itself
      call t%check_close(trim(label)//' phi(L)', cantilever_mode_shape(n, length, length, 0), 1.0_dp, gamma_n(1))
      call t%check_close(trim(label)//' phi''''(L)', cantilever_mode_shape(n, length, length, 2), 0.0_dp, 1.0_dp, &
                         shape_error*beta**2)
      call t%check_close(trim(label)//' phi''''''(L)', cantilever_mode_shape(n, length, length, 3), 0.0_dp, 1.0_dp, &
                         shape_error*beta**3)
      ! central difference of phi''': truncation step^2/6 |phi^(6)| <= step^2/6 2.25 beta^6
      ! (the four terms of phi^(k)/beta^k, each at most 1 or 1.5, over the classical tip
      ! value 2), and the rounding of the two values divided by 2 step
      x = 0.37_dp*length
      step = 1e-3_dp/beta
      d4 = (cantilever_mode_shape(n, x + step, length, 3) - cantilever_mode_shape(n, x - step, length, 3))/(2*step)
      truncation = step**2/6*2.25_dp*beta**6
      call t%check_close(trim(label)//' phi'''''''' = beta^4 phi', abs(d4 - beta**4*cantilever_mode_shape(n, x, length, 0)), &
                         0.0_dp, 1.0_dp, truncation + shape_error*beta**3/step + shape_error*beta**4)
   end do
   do n = 1, 4
      do m = n + 1, 5
         overlap = 0
         cell = length/400
         do i = 1, 400
            x = (i - 0.5_dp)*cell
            overlap = overlap + cantilever_mode_shape(n, x, length, 0)*cantilever_mode_shape(m, x, length, 0)*cell
         end do
         ! midpoint rule: error = cell^2/24 (f'(L) - f'(0)) + O(cell^4) for f = phi_n phi_m,
         ! f'(0) = 0 and f'(L) = phi_n'(L) + phi_m'(L) (tip values 1); twice that allowed
         write (label, '(a,i0,a,i0)') 'orthogonality of modes ', n, ' and ', m
         call t%check_close(trim(label), overlap, 0.0_dp, 1.0_dp, 2*cell**2/24* &
                            abs(cantilever_mode_shape(n, length, length, 1) + cantilever_mode_shape(m, length, length, 1)))
      end do
   end do
   call t%finish('test_cantilever_exact')
end program test_cantilever_exact
