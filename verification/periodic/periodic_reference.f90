!> What the periodic-orbit tests share (verification/periodic): dense linear algebra on
!! the energy norm of a state x = (U, V), ||x||^2 = x^T G x with G = diag(K + Omega^2 M, M)
!! (the norm `period_map` measures residuals in), written here from the dense M and K so
!! that the tests' bounds do not rest on the code under test.
module vibrobeam_periodic_reference
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_problem, only: run_problem
   use vibrobeam_lapack, only: dgesv, dpotrf, dgeevx, zgesv, dsygv
   use vibrobeam_scene, only: scene_type
   use vibrobeam_continuation, only: continuation_branch, continue_branch
   use vibrobeam_test_support, only: test_counter
   use vibrobeam_period_map, only: difference_fraction
   implicit none
   private
   public :: identity, solve_dense, energy_gram, energy_norm, cancellation, fixed_point_condition
   public :: amplification_matrix, eigenvalues_with_conditions, harmonic_steady_state, matrix_power
   public :: continue_test_branch, check_multipliers, fluid_elastic_damping, modal_damping_excess

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

   !> matrix^power by repeated squaring.
   function matrix_power(matrix, exponent) result(out)
      real(dp), intent(in) :: matrix(:, :)
      integer(int64), intent(in) :: exponent
      real(dp) :: out(size(matrix, 1), size(matrix, 2)), base(size(matrix, 1), size(matrix, 2))
      integer(int64) :: e
      out = identity(size(matrix, 1))
      base = matrix
      e = exponent
      do while (e > 0)
         if (mod(e, 2_int64) == 1) out = matmul(out, base)
         base = matmul(base, base)
         e = e/2
      end do
   end function matrix_power

   !> The harmonic steady state of the velocity scheme without contact under F(t) =
   !! Re(F^ e^{i Omega t}), F^ = F(0) - i F(T/4) (the loads of `prepared`), from the dense
   !! M, K, C = damping and W = M + theta dt C + theta^2 dt^2 K: its solution is
   !! Re((U^, V^) z^n), z = e^{i Omega dt}, with
   !!   (z - 1) W V^ = dt (F^ (theta z + 1 - theta) - K U^ - (C + theta dt K) V^),
   !!   (z - 1) U^ = dt (theta z + 1 - theta) V^,
   !! a complex linear system solved with LAPACK zgesv; `state` = (U^, V^). `info` /= 0:
   !! zgesv found it singular. `explicit` (optional): a damping taken at V^n outside W, as
   !! the scheme takes the fluid-elastic force and damping per mode, -E V^n on the right
   !! (C + theta dt K becomes C + E + theta dt K there).
   subroutine harmonic_steady_state(prepared, mass, stiffness, damping, dt, theta, omega, state, info, explicit)
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: mass(:, :), stiffness(:, :), damping(:, :), dt, theta, omega
      real(dp), intent(in), optional :: explicit(:, :)
      complex(dp), allocatable, intent(out) :: state(:)
      integer, intent(out) :: info
      complex(dp), allocatable :: system(:, :), rhs(:, :)
      complex(dp) :: z, g
      integer, allocatable :: pivots(:)
      real(dp), parameter :: pi = acos(-1.0_dp)
      integer :: n, m, j
      n = size(mass, 1)
      m = 2*n
      z = exp(cmplx(0.0_dp, omega*dt, dp))
      g = theta*z + (1 - theta)
      allocate (system(m, m), rhs(m, 1), pivots(m))
      system = 0
      system(1:n, 1:n) = dt*stiffness
      system(1:n, n + 1:) = (z - 1)*(mass + theta*dt*damping + theta**2*dt**2*stiffness) + &
                            dt*(damping + theta*dt*stiffness)
      if (present(explicit)) system(1:n, n + 1:) = system(1:n, n + 1:) + dt*explicit
      rhs(1:n, 1) = dt*g*cmplx(prepared%system%loads%at(0.0_dp), -prepared%system%loads%at(2*pi/omega/4), dp)
      do j = 1, n
         system(n + j, j) = z - 1
         system(n + j, n + j) = -dt*g
      end do
      rhs(n + 1:, 1) = 0
      call zgesv(m, 1, system, m, pivots, rhs, m, info)
      state = rhs(:, 1)
   end subroutine harmonic_steady_state

   !> The one-step amplification matrix A of the velocity scheme without contact,
   !! (U', V') = A (U, V) + load terms: W (V' - V) = -dt (C V + K (U + theta dt V)),
   !! U' = U + dt (theta V' + (1 - theta) V), W = M + theta dt C + theta^2 dt^2 K, from the
   !! dense M, K and C = damping of the stepped system; `explicit` (optional) a damping E
   !! taken at V^n outside W (-dt (C + E) V on the right; `harmonic_steady_state`).
   function amplification_matrix(mass, stiffness, damping, dt, theta, explicit) result(a)
      real(dp), intent(in) :: mass(:, :), stiffness(:, :), damping(:, :), dt, theta
      real(dp), intent(in), optional :: explicit(:, :)
      real(dp) :: a(2*size(mass, 1), 2*size(mass, 1))
      real(dp) :: work(size(mass, 1), 2*size(mass, 1)), eye(size(mass, 1), size(mass, 1))
      integer :: n
      n = size(mass, 1)
      eye = identity(n)
      work(:, 1:n) = stiffness
      work(:, n + 1:) = damping + theta*dt*stiffness
      if (present(explicit)) work(:, n + 1:) = work(:, n + 1:) + explicit
      call solve_dense(mass + theta*dt*damping + theta**2*dt**2*stiffness, work)
      a(n + 1:, 1:n) = -dt*work(:, 1:n)
      a(n + 1:, n + 1:) = eye - dt*work(:, n + 1:)
      a(1:n, 1:n) = eye + theta*dt*a(n + 1:, 1:n)
      a(1:n, n + 1:) = theta*dt*a(n + 1:, n + 1:) + (1 - theta)*dt*eye
   end function amplification_matrix

   !> Eigenvalues of `matrix`, the reciprocal condition number of each and the right
   !! eigenvectors (LAPACK dgeevx; a complex pair as the real and imaginary parts of its
   !! first vector in two columns).
   subroutine eigenvalues_with_conditions(matrix, wr, wi, rconde, vr)
      real(dp), intent(in) :: matrix(:, :)
      real(dp), intent(out) :: wr(:), wi(:), rconde(:), vr(:, :)
      real(dp) :: copy(size(matrix, 1), size(matrix, 1)), vl(size(matrix, 1), size(matrix, 1)), &
                  scale(size(matrix, 1)), rcondv(size(matrix, 1)), abnrm, query(1)
      real(dp), allocatable :: space(:)
      integer :: iwork(2*size(matrix, 1)), ilo, ihi, status, size1
      size1 = size(matrix, 1)
      copy = matrix
      call dgeevx('N', 'V', 'V', 'E', size1, copy, size1, wr, wi, vl, size1, vr, size1, ilo, ihi, scale, abnrm, &
                  rconde, rcondv, query, -1, iwork, status)
      allocate (space(int(query(1))))
      call dgeevx('N', 'V', 'V', 'E', size1, copy, size1, wr, wi, vl, size1, vr, size1, ilo, ihi, scale, abnrm, &
                  rconde, rcondv, space, size(space), iwork, status)
      if (status /= 0) error stop 'dgeevx failed'
   end subroutine eigenvalues_with_conditions

   !> The fluid-elastic force of &flow as an explicit damping E = -sum_n g_n (M phi_n)(M phi_n)^T
   !! (docs/theory.md §10: F_f = -E V), from the dense M, K (LAPACK dsygv: the modes with
   !! phi^T M phi = 1, so g_n = 2 zeta_f,n omega_n) and Connors' formula zeta_f,n = rho
   !! U^2/(2 pi K^2 m f_n^2), for the flow over the whole span (J_n = 1) of a beam of mass
   !! per length `mass_per_length` and the lowest `modes` modes: written here from the
   !! formula, not from `vibrobeam_flow`.
   function fluid_elastic_damping(mass, stiffness, velocity, fluid_density, connors, mass_per_length, modes) &
      result(explicit)
      real(dp), intent(in) :: mass(:, :), stiffness(:, :), velocity, fluid_density, connors, mass_per_length
      integer, intent(in) :: modes
      real(dp) :: explicit(size(mass, 1), size(mass, 1))
      real(dp) :: omega(size(mass, 1)), rates(modes)
      real(dp), allocatable :: shapes(:, :)
      real(dp), parameter :: pi = acos(-1.0_dp)
      call dense_modes(mass, stiffness, shapes, omega)
      associate (zeta_f => fluid_density*velocity**2/(2*pi*connors**2*mass_per_length*(omega(1:modes)/(2*pi))**2))
         rates = -2*zeta_f*omega(1:modes)
      end associate
      explicit = modal_sum(mass, shapes, rates)
   end function fluid_elastic_damping

   !> The damping per mode of `&beam modal_damping_ratios` as the scheme takes it, at V^n
   !! beside the Rayleigh damping: mode k (of the first size(ratios), phi^T M phi = 1 from
   !! LAPACK dsygv on the dense M, K) gets the excess rate c_k = 2 zeta_k omega_k - a -
   !! b omega_k^2 over Rayleigh's, so E = sum_k c_k (M phi_k)(M phi_k)^T (docs/method.md,
   !! "Damping per mode"); written from the formula, not from `vibrobeam_modal_damping`.
   function modal_damping_excess(mass, stiffness, ratios, rayleigh_mass, rayleigh_stiffness) result(explicit)
      real(dp), intent(in) :: mass(:, :), stiffness(:, :), ratios(:), rayleigh_mass, rayleigh_stiffness
      real(dp) :: explicit(size(mass, 1), size(mass, 1))
      real(dp) :: omega(size(mass, 1))
      real(dp), allocatable :: shapes(:, :)
      call dense_modes(mass, stiffness, shapes, omega)
      associate (w => omega(1:size(ratios)))
         explicit = modal_sum(mass, shapes, 2*ratios*w - rayleigh_mass - rayleigh_stiffness*w**2)
      end associate
   end function modal_damping_excess

   !> The modes of the dense (K, M) by LAPACK dsygv (phi^T M phi = 1, ascending) and their
   !! angular frequencies omega_k (rad/s).
   subroutine dense_modes(mass, stiffness, shapes, omega)
      real(dp), intent(in) :: mass(:, :), stiffness(:, :)
      real(dp), allocatable, intent(out) :: shapes(:, :)
      real(dp), intent(out) :: omega(:)
      real(dp) :: b(size(mass, 1), size(mass, 1)), query(1)
      real(dp), allocatable :: space(:)
      integer :: n, info
      n = size(mass, 1)
      shapes = stiffness
      b = mass
      call dsygv(1, 'V', 'L', n, shapes, n, b, n, omega, query, -1, info)
      allocate (space(int(query(1))))
      call dsygv(1, 'V', 'L', n, shapes, n, b, n, omega, space, size(space), info)
      if (info /= 0) error stop 'dsygv failed'
      omega = sqrt(max(omega, 0.0_dp))   ! (a rigid-body mode: 0, not a rounding below it)
   end subroutine dense_modes

   !> sum_k rates(k) (M phi_k)(M phi_k)^T over the first size(rates) modes `shapes`.
   function modal_sum(mass, shapes, rates) result(explicit)
      real(dp), intent(in) :: mass(:, :), shapes(:, :), rates(:)
      real(dp) :: explicit(size(mass, 1), size(mass, 1))
      real(dp) :: y(size(mass, 1))
      integer :: k, j
      explicit = 0
      do k = 1, size(rates)
         y = matmul(mass, shapes(:, k))
         do j = 1, size(y)
            explicit(:, j) = explicit(:, j) + rates(k)*y*y(j)
         end do
      end do
   end function modal_sum

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

   !> The branch of `scene` (`continue_branch`) for the continuation tests: it must run
   !! (else the test `program` ends, failed) and reach its end without failure; prints
   !! its number of points, its span in the parameter and its steps.
   subroutine continue_test_branch(t, program, scene, prepared, branch)
      type(test_counter), intent(inout) :: t
      character(len=*), intent(in) :: program
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(continuation_branch), intent(out) :: branch
      integer :: stat
      character(len=512) :: errmsg
      call continue_branch(scene, prepared, branch, stat, errmsg)
      call t%check_true('continue_branch runs', stat == 0, trim(errmsg))
      if (stat /= 0) call t%finish(program)
      call t%check_true('the branch reached its end without failure', len_trim(branch%failure) == 0, &
                        trim(branch%failure))
      write (*, '(a,i0,3a,f0.3,a,f0.3,3a,i0,a)') 'branch: ', size(branch%points), ' points, ', &
         trim(branch%axis%parameter), ' from ', branch%points(1)%parameter, ' to ', &
         branch%points(size(branch%points))%parameter, ' ', trim(branch%axis%unit), ', ', branch%steps_taken, ' steps'
   end subroutine continue_test_branch
   !> Check the Floquet multipliers `multipliers` (2, 2 J: real, imaginary) of an orbit of
   !! `steps` steps against lambda_k^steps, lambda_k the eigenvalues of the one-step
   !! amplification matrix `a` (LAPACK dgeevx), each to the round-off bound derived below;
   !! `monodromy` says how they were computed ('linearised' or 'differences'), `noise` is
   !! the period map's relative noise in the energy norm of `gram`. Returns the largest
   !! error over its bound.
   real(dp) function check_multipliers(t, multipliers, a, steps, monodromy, noise, gram) result(worst)
      type(test_counter), intent(inout) :: t
      real(dp), intent(in) :: multipliers(:, :), a(:, :), noise, gram(:, :)
      integer(int64), intent(in) :: steps
      character(len=*), intent(in) :: monodromy
      real(dp), allocatable :: wr(:), wi(:), rconde(:), vectors(:, :)
      complex(dp), allocatable :: mu_ref(:)
      logical, allocatable :: used(:)
      real(dp) :: distance, lambda_power, bound
      integer :: k, j, m
      m = size(a, 1)
      allocate (wr(m), wi(m), rconde(m), vectors(m, m))
      call eigenvalues_with_conditions(a, wr, wi, rconde, vectors)
      allocate (mu_ref(m))   ! (first: gfortran's -Wmaybe-uninitialized does not follow a reallocation)
      mu_ref = cmplx(wr, wi, dp)**steps
      call t%check_true('as many multipliers as unknowns of the map (2 J)', size(multipliers, 2) == m)
      ! Bounds, to first order (a factor 4 beside them): an error E of a matrix moves its
      ! eigenvalue by |y^H E x|/|y^H x| <= ||E x||/s_k (x, y right and left eigenvectors,
      ! s_k = rconde, LAPACK's reciprocal condition number). The reference lambda_k^P:
      ! dgeevx's backward error eps ||A||_F, times P |lambda_k|^(P-1). The monodromy, P
      ! tangent steps applied to the eigenvector x_k: each step's componentwise round-off
      ! (8 eps, as the map's noise) of a vector of size |lambda_k|^j, carried to the end by
      ! A^(P-1-j), adds to y^H E x a term lambda_k^(P-1) 8 eps rho(x_k), so P of them; and
      ! dgeev on the monodromy its backward error eps ||M||_F (M in the energy coordinates,
      ! where the steps are contractions: ||M||_F <= sqrt(2 J)). By finite differences
      ! (&periodic monodromy = 'differences') each column is a difference quotient whose
      ! numerator carries the map's noise: ||E|| <= noise/difference_fraction instead.
      allocate (used(m), source=.false.)
      worst = 0
      do k = 1, min(m, size(multipliers, 2))
         j = minloc(abs(cmplx(multipliers(1, k), multipliers(2, k), dp) - mu_ref), mask=.not. used, dim=1)
         used(j) = .true.
         distance = abs(cmplx(multipliers(1, k), multipliers(2, k), dp) - mu_ref(j))
         lambda_power = abs(cmplx(wr(j), wi(j), dp))**(steps - 1)
         bound = epsilon(1.0_dp)*steps*sqrt(sum(a**2))*lambda_power + epsilon(1.0_dp)*sqrt(real(m, dp))
         if (monodromy == 'differences') then
            bound = bound + noise/difference_fraction
         else
            bound = bound + 8*epsilon(1.0_dp)*steps*lambda_power*pair_cancellation(j)
         end if
         bound = 4*bound/rconde(j)
         worst = max(worst, distance/bound)
         call t%check_close('Floquet multiplier against lambda^P', distance, 0.0_dp, bound, scale=1.0_dp)
      end do
   contains
      !> rho of eigenvector j of dgeevx's `vectors` (a complex pair is stored as its real and
      !! imaginary parts in columns j, j + 1): the larger of its parts' rho.
      real(dp) function pair_cancellation(j)
         integer, intent(in) :: j
         integer :: first
         first = j
         if (wi(j) < 0) first = j - 1
         pair_cancellation = cancellation(gram, vectors(:, first))
         if (abs(wi(j)) > 0) pair_cancellation = max(pair_cancellation, cancellation(gram, vectors(:, first + 1)))
      end function pair_cancellation
   end function check_multipliers
end module vibrobeam_periodic_reference
