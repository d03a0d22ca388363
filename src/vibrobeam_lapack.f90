!> Explicit interfaces of the LAPACK routines the contact projection and its tests call
!! (Reference-LAPACK argument conventions), declared once.
module vibrobeam_lapack
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: dpbtrf, dpbtrs, dpbcon, dpotrf, dpotrs, dgbtrf, dgbtrs, dgesv

   interface
      !> Cholesky factorization of a symmetric positive definite band matrix.
      subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: info
      end subroutine dpbtrf
      !> Solve with the factor of dpbtrf.
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
      !> Dense LU solve.
      subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
   end interface
end module vibrobeam_lapack
