!> Unit test of the closed-form references (SPEC §6): the roots of 1 + cos b cosh b = 0
!! and tan b = tanh b against the published values quoted in SPEC §6, and the mode shapes
!! against their boundary conditions (clamped at 0, free at L), tip value 1, the beam
!! equation phi'''' = beta^4 phi (checked by a central difference of phi''') and
!! orthogonality (Gauss quadrature written here).
program test_cantilever_exact
   use vibrobeam_kinds, only: dp
   use vibrobeam_cantilever_exact, only: cantilever_root, pinned_tip_root, cantilever_mode_shape
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: spec_roots(6) = [1.8751040687_dp, 4.6940911330_dp, 7.8547574382_dp, &
                                           10.9955407349_dp, 14.1371683910_dp, 17.2787595321_dp]
   real(dp), parameter :: spec_pinned(3) = [3.9266023120_dp, 7.0685827456_dp, 10.2101761228_dp]
   real(dp), parameter :: length = 1.7_dp
   real(dp) :: beta, step, d4, x, overlap
   integer :: n, i, m
   character(len=40) :: label
   do n = 1, 6
      write (label, '(a,i0)') 'cantilever root ', n
      call t%check_close(trim(label), cantilever_root(n), spec_roots(n), 1e-10_dp)
   end do
   ! beyond the table, roots approach (2n-1) pi/2
   call t%check_close('cantilever root 30 ~ (2n-1)pi/2', cantilever_root(30), 59*acos(-1.0_dp)/2, 1e-12_dp)
   do n = 1, 3
      write (label, '(a,i0)') 'pinned-tip root ', n
      call t%check_close(trim(label), pinned_tip_root(n), spec_pinned(n), 1e-10_dp)
   end do
   do n = 1, 12
      beta = cantilever_root(n)/length
      write (label, '(a,i0)') 'mode ', n
      call t%check_close(trim(label)//' phi(0)', cantilever_mode_shape(n, 0.0_dp, length, 0), 0.0_dp, 1.0_dp, 1e-12_dp)
      call t%check_close(trim(label)//' phi''(0)', cantilever_mode_shape(n, 0.0_dp, length, 1), 0.0_dp, 1.0_dp, &
                         1e-12_dp*beta)
      call t%check_close(trim(label)//' phi(L)', cantilever_mode_shape(n, length, length, 0), 1.0_dp, 1e-14_dp)
      call t%check_close(trim(label)//' phi''''(L)', cantilever_mode_shape(n, length, length, 2), 0.0_dp, 1.0_dp, &
                         1e-11_dp*beta**2)
      call t%check_close(trim(label)//' phi''''''(L)', cantilever_mode_shape(n, length, length, 3), 0.0_dp, 1.0_dp, &
                         1e-11_dp*beta**3)
      x = 0.37_dp*length
      step = 1e-3_dp/beta
      d4 = (cantilever_mode_shape(n, x + step, length, 3) - cantilever_mode_shape(n, x - step, length, 3))/(2*step)
      call t%check_close(trim(label)//' phi'''''''' = beta^4 phi', d4, beta**4*cantilever_mode_shape(n, x, length, 0), &
                         1e-5_dp, beta**4)
   end do
   do n = 1, 4
      do m = n + 1, 5
         overlap = 0
         do i = 1, 400   ! midpoint rule, 400 cells: error ~1e-6 of the norm
            x = (i - 0.5_dp)*length/400
            overlap = overlap + cantilever_mode_shape(n, x, length, 0)*cantilever_mode_shape(m, x, length, 0)*length/400
         end do
         write (label, '(a,i0,a,i0)') 'orthogonality of modes ', n, ' and ', m
         call t%check_close(trim(label), overlap, 0.0_dp, 1.0_dp, 1e-4_dp*length)
      end do
   end do
   call t%finish('test_cantilever_exact')
end program test_cantilever_exact
