!> Unit test: the band mass and stiffness matrices of `build_model` equal a dense assembly
!! computed here independently (element matrices by 5-point Gauss quadrature of Hermite
!! shape functions written out below, not the closed-form matrices of the code), to round-off
!! relative to the largest entry; both are symmetric positive definite (LAPACK band and
!! dense Cholesky succeed); the band matrix-vector product and band solve agree with dense
!! LAPACK/BLAS to their round-off bounds. Each tolerance is derived beside its check, in
!! units of u = eps/2 and gamma_n = n u/(1 - n u) (`vibrobeam_roundoff_bounds`).
program test_band_assembly
   use vibrobeam_kinds, only: dp
   use vibrobeam_lapack, only: dgesv, dpotrf
   use vibrobeam_band, only: band_entry, band_matvec, band_factor, band_solve, band_cholesky
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_roundoff_bounds, only: gamma_n, abs_factor_times
   use vibrobeam_static_bounds, only: dense_inverse, permuted_lu_times
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   integer, parameter :: meshes(5) = [1, 2, 3, 7, 40]
   integer :: k
   do k = 1, size(meshes)
      call compare(meshes(k), 1.0_dp, 1.0_dp, 1.0_dp)
      call compare(meshes(k), 0.37_dp, 2.5_dp, 3.0e4_dp)
   end do
   call t%finish('test_band_assembly')

contains

   !> Hermite shape functions (order 0) and second derivatives on [0, h], written from
   !! their definition: cubic polynomials with unit nodal value or slope.
   subroutine shapes(s, h, n, d2n)
      real(dp), intent(in) :: s, h   ! s: physical coordinate in [0, h]
      real(dp), intent(out) :: n(4), d2n(4)
      real(dp) :: r
      r = s/h
      n(1) = (1 - r)**2*(1 + 2*r)
      n(2) = s*(1 - r)**2
      n(3) = r**2*(3 - 2*r)
      n(4) = s*r*(r - 1)
      d2n(1) = (12*r - 6)/h**2
      d2n(2) = (6*r - 4)/h
      d2n(3) = (6 - 12*r)/h**2
      d2n(4) = (6*r - 2)/h
   end subroutine shapes

   subroutine compare(elements, length, rho_s, ei)
      integer, intent(in) :: elements
      real(dp), intent(in) :: length, rho_s, ei
      ! 5-point Gauss-Legendre on [-1, 1]
      real(dp), parameter :: gp(5) = [-0.9061798459386640_dp, -0.5384693101056831_dp, 0.0_dp, &
                                      0.5384693101056831_dp, 0.9061798459386640_dp]
      real(dp), parameter :: gw(5) = [0.2369268850561891_dp, 0.4786286704993665_dp, 0.5688888888888889_dp, &
                                      0.4786286704993665_dp, 0.2369268850561891_dp]
      type(beam_model) :: model
      type(band_cholesky) :: chol
      real(dp), allocatable :: mass(:,:), stiffness(:,:), work(:,:), x(:), y(:), rhs(:,:), inverse(:,:), bound(:)
      integer, allocatable :: ipiv(:)
      real(dp) :: h, me(4, 4), ke(4, 4), n(4), d2n(4), scale_m, scale_k, err_m, err_k
      integer :: e, g, a, b, full, j, i, info, stat
      character(len=200) :: errmsg
      character(len=64) :: label
      write (label, '(a,i0,a,f0.2)') 'N=', elements, ' L=', length
      h = length/elements
      full = 2*(elements + 1)
      allocate (mass(full, full), stiffness(full, full), source=0.0_dp)
      do e = 1, elements
         me = 0
         ke = 0
         do g = 1, 5
            call shapes(0.5_dp*h*(gp(g) + 1), h, n, d2n)
            do b = 1, 4
               do a = 1, 4
                  me(a, b) = me(a, b) + 0.5_dp*h*gw(g)*rho_s*n(a)*n(b)
                  ke(a, b) = ke(a, b) + 0.5_dp*h*gw(g)*ei*d2n(a)*d2n(b)
               end do
            end do
         end do
         mass(2*e - 1:2*e + 2, 2*e - 1:2*e + 2) = mass(2*e - 1:2*e + 2, 2*e - 1:2*e + 2) + me
         stiffness(2*e - 1:2*e + 2, 2*e - 1:2*e + 2) = stiffness(2*e - 1:2*e + 2, 2*e - 1:2*e + 2) + ke
      end do
      ! clamp: drop w_0 and theta_0
      mass = mass(3:, 3:)
      stiffness = stiffness(3:, 3:)
      call build_model('hermite', elements, length, rho_s, ei, model, stat, errmsg)
      call t%check_true(trim(label)//' build_model', stat == 0, errmsg)
      call t%check_true(trim(label)//' unknowns = 2N', model%unknowns == 2*elements)
      allocate (work(model%unknowns, model%unknowns))
      scale_m = maxval(abs(mass))
      scale_k = maxval(abs(stiffness))
      err_m = 0
      err_k = 0
      do j = 1, model%unknowns
         do i = 1, model%unknowns
            err_m = max(err_m, abs(band_entry(model%mass, i, j) - mass(i, j)))
            err_k = max(err_k, abs(band_entry(model%stiffness, i, j) - stiffness(i, j)))
         end do
      end do
      ! Round-off of the dense side: r = s/h carries 4 roundings (the Gauss points are given
      ! to 16 digits), so a shape value is off by at most (max |dN/dr| = 1.5) x 4u + 4u =
      ! 10u of its scale and a second derivative by 12 x 4u + 3u < 9u of its largest value
      ! 6/h^2; a quadrature term adds 6 roundings and the sum over 5 points and 2 elements
      ! 10, each relative to sum |terms| <= sqrt(A_ii A_jj) <= max|A| (Cauchy-Schwarz over
      ! the quadrature). So an entry is off by at most (2 x 10 + 16)u = 36u of max|A|; the
      ! closed-form entries of the band matrix add gamma_5. Tolerance: 64u.
      call t%check_close(trim(label)//' max |M_band - M_dense|/max|M|', err_m/scale_m, 0.0_dp, 1.0_dp, &
                         64*epsilon(1.0_dp)/2)
      call t%check_close(trim(label)//' max |K_band - K_dense|/max|K|', err_k/scale_k, 0.0_dp, 1.0_dp, &
                         64*epsilon(1.0_dp)/2)
      ! positive definiteness: band Cholesky (LAPACK dpbtrf) and dense Cholesky (dpotrf)
      call band_factor(model%mass, chol, stat, errmsg)
      call t%check_true(trim(label)//' M band Cholesky', stat == 0, errmsg)
      call band_factor(model%stiffness, chol, stat, errmsg)
      call t%check_true(trim(label)//' K band Cholesky', stat == 0, errmsg)
      work = mass
      call dpotrf('L', model%unknowns, work, model%unknowns, info)
      call t%check_true(trim(label)//' M dense Cholesky', info == 0)
      work = stiffness
      call dpotrf('L', model%unknowns, work, model%unknowns, info)
      call t%check_true(trim(label)//' K dense Cholesky', info == 0)
      ! band products and solves against dense ones
      x = [(sin(1.3_dp*i) + 0.1_dp*i, i=1, model%unknowns)]
      allocate (y(model%unknowns))
      call band_matvec(model%stiffness, x, y)
      ! each row of both products is a sum of the same 7 nonzero products (the dense one adds
      ! exact zeros), in any order: the two differ by at most 2 gamma_7 (|K||x|)_i, plus the
      ! difference of the two matrices (<= 64u max|K|, above) times |x|
      call t%check_close(trim(label)//' K x band vs dense (largest difference / its bound)', &
                         maxval(abs(y - matmul(stiffness, x))/(2*gamma_n(7)*matmul(abs(stiffness), abs(x)) + &
                                64*epsilon(1.0_dp)/2*scale_k*sum(abs(x)))), 0.0_dp, 1.0_dp, 1.0_dp)
      rhs = reshape(x, [model%unknowns, 1])
      work = stiffness
      allocate (ipiv(model%unknowns))
      call dgesv(model%unknowns, 1, work, model%unknowns, ipiv, rhs, model%unknowns, info)
      y = x
      call band_solve(chol, y)
      ! forward errors of the two solves (first order): band Cholesky (K + dK) y = x with
      ! |dK| <= gamma_{3kd+4} |L||L^T| (Higham Thm 10.4, kd + 1 terms per inner product),
      ! dense LU with partial pivoting (K + dK) y = x with |dK| <= gamma_{3n} P^T|L||U|
      ! (Thm 9.4): |dy| <= |K^-1| |dK| |y|; plus the two matrices' difference (64u max|K|).
      ! cond(K) reaches 1e8 at N = 40: a norm bound (cond x u) would allow 1e-8, these
      ! componentwise bounds are 10 to 100 times smaller.
      inverse = dense_inverse(stiffness)
      bound = matmul(abs(inverse), gamma_n(3*model%stiffness%kd + 4)*abs_factor_times(chol, abs(y)) + &
                     gamma_n(3*model%unknowns)*permuted_lu_times(work, ipiv, abs(rhs(:, 1))) + &
                     64*epsilon(1.0_dp)/2*scale_k*sum(abs(y)))
      call t%check_close(trim(label)//' K^-1 x band vs dense (largest difference / its bound)', &
                         maxval(abs(y - rhs(:, 1))/bound), 0.0_dp, 1.0_dp, 1.0_dp)
   end subroutine compare

end program test_band_assembly
