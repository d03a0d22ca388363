!> Explicit interfaces of the LAPACK/BLAS routines on symmetric band matrices that
!! vibrobeam calls: in lower band storage the fall-back of `vibrobeam_band` for bandwidths
!! other than 3 and the oracle its kernels are tested against; the tridiagonal ones for the
!! curvature mass matrix of `vibrobeam_flexibility`; the generalized band eigensolver of the
!! dense modes path.
module vibrobeam_band_lapack
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: dpbtrf, dpbtrs, dsbmv, dpttrf, dpttrs, dsbgvx

   interface
      !> Cholesky factorization A = L L^T (UPLO = 'L'); info = k > 0: the leading minor of
      !! order k is not positive definite.
      subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: info
      end subroutine dpbtrf
      !> Solve A X = B with the factor of dpbtrf.
      subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, nrhs, ldab, ldb
         real(dp), intent(in) :: ab(ldab, *)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpbtrs
      !> y = alpha A x + beta y.
      subroutine dsbmv(uplo, n, k, alpha, a, lda, x, incx, beta, y, incy)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, k, lda, incx, incy
         real(dp), intent(in) :: alpha, beta
         real(dp), intent(in) :: a(lda, *), x(*)
         real(dp), intent(inout) :: y(*)
      end subroutine dsbmv
      !> L D L^T factorization of a symmetric positive definite tridiagonal matrix (diagonal
      !! d, off-diagonal e); info = k > 0: the leading minor of order k is not positive definite.
      subroutine dpttrf(n, d, e, info)
         import :: dp
         integer, intent(in) :: n
         real(dp), intent(inout) :: d(*), e(*)
         integer, intent(out) :: info
      end subroutine dpttrf
      !> Solve A X = B with the factor of dpttrf.
      subroutine dpttrs(n, nrhs, d, e, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, ldb
         real(dp), intent(in) :: d(*), e(*)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpttrs
      !> Selected eigenvalues (and vectors) of the band pencil A x = lambda B x, B positive
      !! definite (it forms an n x n transformation when vectors are asked).
      subroutine dsbgvx(jobz, range, uplo, n, ka, kb, ab, ldab, bb, ldbb, q, ldq, vl, vu, &
                        il, iu, abstol, m, w, z, ldz, work, iwork, ifail, info)
         import :: dp
         character, intent(in) :: jobz, range, uplo
         integer, intent(in) :: n, ka, kb, ldab, ldbb, ldq, il, iu, ldz
         real(dp), intent(inout) :: ab(ldab, *), bb(ldbb, *)
         real(dp), intent(out) :: q(ldq, *), w(*), z(ldz, *), work(*)
         real(dp), intent(in) :: vl, vu, abstol
         integer, intent(out) :: m, iwork(*), ifail(*), info
      end subroutine dsbgvx
   end interface
end module vibrobeam_band_lapack
