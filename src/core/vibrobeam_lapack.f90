!> Explicit interfaces of every LAPACK and BLAS routine vibrobeam calls (Reference-LAPACK
!! argument conventions), declared once: the symmetric band routines (the fall-back of
!! `vibrobeam_band` for bandwidths other than 3 and the oracle its kernels are tested
!! against), the generalized band eigensolver of the dense modes path, the tridiagonal
!! routines of `vibrobeam_flexibility`, the dense and general band routines of the contact
!! projection and of the B-spline interpolation, the general eigensolver of the Floquet
!! multipliers, and those the tests use as references.
!! Every caller checks `info`.
module vibrobeam_lapack
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: poison_failed_solve
   public :: dpbtrf, dpbtrs, dpbcon, dpbrfs, dsbmv, dgemv, dsbgvx, dpttrf, dpttrs
   public :: dpotrf, dpotrs, dpotri, dgbtrf, dgbtrs, dgbsv, dgesv, dlamch, dgeqrf, dormqr, dsygv, dgeev
   public :: dgels   ! the autonomous orbit's Gauss-Newton steps (an overdetermined consistent system)
   public :: dger   ! the rank-one update of vibrobeam_lemke's tableau
   public :: dgetrf, dorgqr, dsyev, dgeevx, zgesv   ! the tests' dense references

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
      !> Reciprocal condition number (1-norm) estimate from the factor of dpbtrf.
      subroutine dpbcon(uplo, n, kd, ab, ldab, anorm, rcond, work, iwork, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, ldab
         real(dp), intent(in) :: ab(ldab, *), anorm
         real(dp), intent(out) :: rcond, work(*)
         integer, intent(out) :: iwork(*), info
      end subroutine dpbcon
      !> Iterative refinement of the solutions X of A X = B (dpbtrf's factor AFB of A), with a
      !! bound FERR of each solution's forward error (relative, max norm) and its
      !! componentwise backward error BERR.
      subroutine dpbrfs(uplo, n, kd, nrhs, ab, ldab, afb, ldafb, b, ldb, x, ldx, ferr, berr, work, iwork, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, nrhs, ldab, ldafb, ldb, ldx
         real(dp), intent(in) :: ab(ldab, *), afb(ldafb, *), b(ldb, *)
         real(dp), intent(inout) :: x(ldx, *)
         real(dp), intent(out) :: ferr(*), berr(*), work(*)
         integer, intent(out) :: iwork(*), info
      end subroutine dpbrfs
      !> y = alpha A x + beta y.
      subroutine dsbmv(uplo, n, k, alpha, a, lda, x, incx, beta, y, incy)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, k, lda, incx, incy
         real(dp), intent(in) :: alpha, beta
         real(dp), intent(in) :: a(lda, *), x(*)
         real(dp), intent(inout) :: y(*)
      end subroutine dsbmv
      !> y = alpha op(A) x + beta y, op(A) = A ('N') or A^T ('T'), A m x n.
      subroutine dgemv(trans, m, n, alpha, a, lda, x, incx, beta, y, incy)
         import :: dp
         character, intent(in) :: trans
         integer, intent(in) :: m, n, lda, incx, incy
         real(dp), intent(in) :: alpha, beta
         real(dp), intent(in) :: a(lda, *), x(*)
         real(dp), intent(inout) :: y(*)
      end subroutine dgemv
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
      !> Dense Cholesky factorization.
      subroutine dpotrf(uplo, n, a, lda, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, lda
         real(dp), intent(inout) :: a(lda, *)
         integer, intent(out) :: info
      end subroutine dpotrf
      !> Solve with the factor of dpotrf.
      subroutine dpotrs(uplo, n, nrhs, a, lda, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(in) :: a(lda, *)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpotrs
      !> LU factorization of a general band matrix with partial pivoting.
      subroutine dgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
         import :: dp
         integer, intent(in) :: m, n, kl, ku, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgbtrf
      !> Solve with the factors of dgbtrf.
      subroutine dgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, rhs, ldb, info)
         import :: dp
         character, intent(in) :: trans
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(dp), intent(in) :: ab(ldab, *)
         integer, intent(in) :: ipiv(*)
         real(dp), intent(inout) :: rhs(ldb, *)
         integer, intent(out) :: info
      end subroutine dgbtrs
      !> Solve a general band system A X = B by LU with partial pivoting (dgbtrf + dgbtrs);
      !! info = k > 0: U(k, k) is exactly zero, A is singular.
      subroutine dgbsv(n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(dp), intent(inout) :: ab(ldab, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgbsv
      !> Rank-one update A = A + alpha x y^T (BLAS 2).
      subroutine dger(m, n, alpha, x, incx, y, incy, a, lda)
         import :: dp
         integer, intent(in) :: m, n, incx, incy, lda
         real(dp), intent(in) :: alpha, x(*), y(*)
         real(dp), intent(inout) :: a(lda, *)
      end subroutine dger
      !> Dense LU solve.
      subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
      !> Least squares by QR: min ||b - A x|| for a full-rank m x n A, m >= n (trans 'N');
      !! x in b(1:n).
      subroutine dgels(trans, m, n, nrhs, a, lda, b, ldb, work, lwork, info)
         import :: dp
         character, intent(in) :: trans
         integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         real(dp), intent(out) :: work(*)
         integer, intent(out) :: info
      end subroutine dgels
      !> Eigenvalues (and optionally eigenvectors) of a general real matrix: the Floquet
      !! multipliers of a periodic orbit (its monodromy) and the tests' references.
      subroutine dgeev(jobvl, jobvr, n, a, lda, wr, wi, vl, ldvl, vr, ldvr, work, lwork, info)
         import :: dp
         character, intent(in) :: jobvl, jobvr
         integer, intent(in) :: n, lda, ldvl, ldvr, lwork
         real(dp), intent(inout) :: a(lda, *)
         real(dp), intent(out) :: wr(*), wi(*), vl(ldvl, *), vr(ldvr, *), work(*)
         integer, intent(out) :: info
      end subroutine dgeev
      !> Eigenvalues of a general real matrix with the reciprocal condition number of each
      !! (tests: the round-off bound of an eigenvalue).
      subroutine dgeevx(balanc, jobvl, jobvr, sense, n, a, lda, wr, wi, vl, ldvl, vr, ldvr, ilo, ihi, scale, abnrm, &
                        rconde, rcondv, work, lwork, iwork, info)
         import :: dp
         character, intent(in) :: balanc, jobvl, jobvr, sense
         integer, intent(in) :: n, lda, ldvl, ldvr, lwork
         real(dp), intent(inout) :: a(lda, *)
         real(dp), intent(out) :: wr(*), wi(*), vl(ldvl, *), vr(ldvr, *), scale(*), abnrm, rconde(*), rcondv(*), &
                                  work(*)
         integer, intent(out) :: ilo, ihi, iwork(*), info
      end subroutine dgeevx
      !> Dense complex LU solve (tests: a harmonic steady state).
      subroutine zgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, lda, ldb
         complex(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine zgesv
      !> LU factorization of a general matrix with partial pivoting (tests).
      subroutine dgetrf(m, n, a, lda, ipiv, info)
         import :: dp
         integer, intent(in) :: m, n, lda
         real(dp), intent(inout) :: a(lda, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgetrf
      !> Inverse of a symmetric positive definite matrix from its dpotrf factor.
      subroutine dpotri(uplo, n, a, lda, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, lda
         real(dp), intent(inout) :: a(lda, *)
         integer, intent(out) :: info
      end subroutine dpotri
      !> QR factorization of a dense matrix (Householder reflectors).
      subroutine dgeqrf(m, n, a, lda, tau, work, lwork, info)
         import :: dp
         integer, intent(in) :: m, n, lda, lwork
         real(dp), intent(inout) :: a(lda, *)
         real(dp), intent(out) :: tau(*), work(*)
         integer, intent(out) :: info
      end subroutine dgeqrf
      !> The orthogonal factor Q of dgeqrf (tests).
      subroutine dorgqr(m, n, k, a, lda, tau, work, lwork, info)
         import :: dp
         integer, intent(in) :: m, n, k, lda, lwork
         real(dp), intent(inout) :: a(lda, *)
         real(dp), intent(in) :: tau(*)
         real(dp), intent(out) :: work(*)
         integer, intent(out) :: info
      end subroutine dorgqr
      !> Eigenvalues (and vectors) of a dense symmetric matrix (tests).
      subroutine dsyev(jobz, uplo, n, a, lda, w, work, lwork, info)
         import :: dp
         character, intent(in) :: jobz, uplo
         integer, intent(in) :: n, lda, lwork
         real(dp), intent(inout) :: a(lda, *)
         real(dp), intent(out) :: w(*), work(*)
         integer, intent(out) :: info
      end subroutine dsyev
      !> C := Q C, Q^T C, C Q or C Q^T with the Q of dgeqrf.
      subroutine dormqr(side, trans, m, n, k, a, lda, tau, c, ldc, work, lwork, info)
         import :: dp
         character, intent(in) :: side, trans
         integer, intent(in) :: m, n, k, lda, ldc, lwork
         real(dp), intent(in) :: a(lda, *), tau(*)
         real(dp), intent(inout) :: c(ldc, *)
         real(dp), intent(out) :: work(*)
         integer, intent(out) :: info
      end subroutine dormqr
      !> Dense symmetric-definite generalized eigenproblem A x = lambda B x.
      subroutine dsygv(itype, jobz, uplo, n, a, lda, b, ldb, w, work, lwork, info)
         import :: dp
         integer, intent(in) :: itype, n, lda, ldb, lwork
         character, intent(in) :: jobz, uplo
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         real(dp), intent(out) :: w(*), work(*)
         integer, intent(out) :: info
      end subroutine dsygv
      !> Machine parameters ('S': the safe minimum, 1/huge not overflowing).
      function dlamch(cmach) result(value)
         import :: dp
         character, intent(in) :: cmach
         real(dp) :: value
      end function dlamch
   end interface

contains

   !> For the solves that return no stat (a band or tridiagonal solve inside a time step,
   !! where the factor was checked when it was made): a nonzero `info` from the LAPACK solve
   !! (only possible for invalid arguments) turns the whole result into NaN, which the
   !! callers' finiteness checks report (stat_not_finite, exit status 3), instead of a
   !! plausible wrong answer.
   pure subroutine poison_failed_solve(info, x)
      integer, intent(in) :: info       !! LAPACK's info of the solve
      real(dp), intent(inout) :: x(:)   !! the solution
      if (info /= 0) x = ieee_value(1.0_dp, ieee_quiet_nan)
   end subroutine poison_failed_solve
end module vibrobeam_lapack
