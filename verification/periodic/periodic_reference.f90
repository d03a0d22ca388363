!> What the periodic-orbit tests share (verification/periodic): dense linear algebra on
!! the energy norm of a state x = (U, V), ||x||^2 = x^T G x with G = diag(K + Omega^2 M, M)
!! (the norm `period_map` measures residuals in), written here from the dense M and K so
!! that the tests' bounds do not rest on the code under test.
module vibrobeam_periodic_reference
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_problem, only: run_problem
   use vibrobeam_lapack, only: dgesv, dpotrf
   implicit none
   private
   public :: identity, solve_dense, energy_gram, energy_norm, cancellation, fixed_point_condition

contains

   pure function identity(size) result(matrix)
      integer, intent(in) :: size
      real(dp) :: matrix(size, size)
      integer :: i
      matrix = 0
      do i = 1, size
         matrix(i, i) = 1
      end do
   end function identity

   !> Overwrite b with matrix^-1 b (dense LU, LAPACK dgesv); stops the test when singular.
   subroutine solve_dense(matrix, b)
      real(dp), intent(in) :: matrix(:, :)
      real(dp), intent(inout) :: b(:, :)
      real(dp) :: copy(size(matrix, 1), size(matrix, 2))
      integer :: ipiv(size(matrix, 1)), status
      copy = matrix
      call dgesv(size(copy, 1), size(b, 2), copy, size(copy, 1), ipiv, b, size(b, 1), status)
      if (status /= 0) error stop 'dgesv: singular matrix'
   end subroutine solve_dense

   !> G = diag(K + omega^2 M, M) of the stepped system, dense (2 unknowns square).
   function energy_gram(prepared, omega) result(gram)
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: omega
      real(dp), allocatable :: gram(:, :)
      integer :: n
      n = prepared%system%model%unknowns
      allocate (gram(2*n, 2*n), source=0.0_dp)
      gram(n + 1:, n + 1:) = band_to_dense(prepared%system%model%mass)
      gram(1:n, 1:n) = band_to_dense(prepared%system%model%stiffness) + omega**2*gram(n + 1:, n + 1:)
   end function energy_gram

   !> sqrt(x^T G x).
   real(dp) function energy_norm(gram, x)
      real(dp), intent(in) :: gram(:, :), x(:)
      energy_norm = sqrt(dot_product(x, matmul(gram, x)))
   end function energy_norm

   !> rho(x) = sqrt(x^T diag(G) x / x^T G x): how much the energy norm weighs errors of
   !! the unknowns, each relative to itself, against the norm of x (the cancellation
   !! between neighbouring unknowns that x^T K x hides).
   real(dp) function cancellation(gram, x)
      real(dp), intent(in) :: gram(:, :), x(:)
      integer :: i
      cancellation = 0
      do i = 1, size(x)
         cancellation = cancellation + gram(i, i)*x(i)**2
      end do
      cancellation = sqrt(cancellation)/energy_norm(gram, x)
   end function cancellation

   !> ||(I - M)^-1|| in the energy norm (Frobenius, an upper bound of the 2-norm) of a
   !! period map's monodromy M (original coordinates): how far a residual r of the map
   !! can put a state from its fixed point on the same affine piece, ||x - x*|| <=
   !! ||(I - M)^-1|| ||r||. In the coordinates y = L^T x (G = L L^T) the matrix is
   !! L^T M L^-T.
   real(dp) function fixed_point_condition(gram, monodromy)
      real(dp), intent(in) :: gram(:, :), monodromy(:, :)
      real(dp) :: chol(size(gram, 1), size(gram, 1)), scaled(size(gram, 1), size(gram, 1)), &
                  work(size(gram, 1), size(gram, 1))
      integer :: info, j, m
      m = size(gram, 1)
      chol = gram
      call dpotrf('L', m, chol, m, info)
      if (info /= 0) error stop 'dpotrf: the Gram matrix is not positive definite'
      do j = 2, m
         chol(1:j - 1, j) = 0
      end do
      scaled = matmul(transpose(chol), monodromy)
      work = transpose(scaled)
      call solve_dense(chol, work)          ! L^-1 (L^T M)^T = (L^T M L^-T)^T
      scaled = identity(m) - transpose(work)
      work = identity(m)
      call solve_dense(scaled, work)
      fixed_point_condition = sqrt(sum(work**2))
   end function fixed_point_condition
end module vibrobeam_periodic_reference
