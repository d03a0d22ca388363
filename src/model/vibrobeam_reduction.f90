!> The reduced model of `&mesh reduction = 'craig-bampton'` (docs/method.md, "The reduced
!! model"; Craig & Bampton, AIAA J. 6(7), 1968, 1313-1319).
!!
!! The unknowns U (J of them) are replaced by r = m + k reduced coordinates q = (y, eta),
!! U = T q with T = [Psi, Phi]:
!! - y_c = H_c U, the displacement at contact point c (the boundary unknowns), and Psi the
!!   static constraint modes: Psi(:, c) is the static response to y_c = 1 with the other
!!   contact displacements held at 0 and no other load, Psi = K^-1 H^T S^-1 with
!!   S = H K^-1 H^T (m x m), so that H Psi = I. For Hermite elements H_c picks the unknown
!!   w_i, and this is the classical definition (interior rows of K Psi zero); for B-splines
!!   it is the same with the constraint H_c U = 1 in place of a held unknown;
!! - eta the amplitudes of the k lowest fixed-interface modes Phi: K phi = omega^2 M phi
!!   with H phi = 0, M-orthonormal, up to a cut-off frequency (or a given count).
!! Since H T = [I, 0], the contact conditions act exactly on the reduced coordinates y:
!! the reduced contact rows are identity rows. The reduced matrices are
!!   K_r = T^T K T = diag(S^-1, omega_1^2 .. omega_k^2)
!! (Psi^T K Psi = S^-1 H K^-1 H^T S^-1 = S^-1 and Psi^T K Phi = S^-1 H Phi = 0: taken from
!! these identities rather than from products with K, whose condition number ~N^4 would
!! cancel), M_r = T^T M T (a product with the well-conditioned M), C_r = a M_r + b K_r
!! (Rayleigh damping projects to Rayleigh damping), F_r = T^T F.
!!
!! K^-1 is applied by the double integration of `vibrobeam_flexibility` (accurate at any N;
!! for other structures than the uniform cantilever the band Cholesky of
!! `vibrobeam_stiffness_inverse`, which needs a K without rigid-body motion),
!! and the fixed-interface modes come from the shift-invert Lanczos of `vibrobeam_lanczos`
!! with the constrained flexibility (I - Psi H) K^-1 as operator: the held displacements
!! are imposed exactly, without renumbering the band and without the loss of accuracy of a
!! penalty (a penalty p would leave O(K/p) errors or add cond ~ p/lambda_1). Where Lanczos
!! does not apply or costs more (few unknowns, many modes) a dense path takes the
!! null space of H by a QR factorization and solves the projected pencil with dsygv.
!!
!! The reduced M_r and K_r are dense (r x r) and are stored as symmetric band matrices
!! with kd = r - 1, so the steppers, the contact solver and the recorder use them as they
!! are (band kernels other than kd = 3 go to LAPACK).
module vibrobeam_reduction
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_invalid_argument
   use vibrobeam_band, only: band_allocate, band_matvec, band_to_dense
   use vibrobeam_model, only: beam_model, energy_integrals, rigid_motions
   use vibrobeam_contact_set, only: contact_set, contact_value
   use vibrobeam_loads, only: load_set
   use vibrobeam_stiffness_inverse, only: stiffness_inverse
   use vibrobeam_lanczos, only: lanczos_modes
   use vibrobeam_modes, only: dense_is_cheaper, normalize_modes
   use vibrobeam_lapack, only: dpotrf, dpotri, dgeqrf, dormqr, dsygv
   implicit none
   private
   public :: reduced_basis, build_reduction, reduce_model, reduce_contacts, reduce_loads, reduce_state
   public :: default_reduction_frequency, frequency_error_limit, contact_modes

   !> Relative frequency error of the trapezoidal rule that sets the default cut-off: the
   !! velocity scheme with theta = 1/2 steps a mode of frequency omega at
   !! (2/dt) atan(omega dt/2) = omega (1 - (omega dt)^2/12 + ...), so the full model already
   !! misrepresents by more than 1 % every mode with omega dt > sqrt(12 x 0.01) = 0.346.
   real(dp), parameter :: frequency_error_limit = 0.01_dp

   !> What maps reduced coordinates to the unknowns of the full model.
   type :: reduced_basis
      integer :: boundary = 0                 !! m, contact points (boundary unknowns y)
      integer :: modes = 0                    !! k, fixed-interface modes kept
      real(dp) :: cutoff = 0                  !! cut-off frequency (rad/s); 0 when set by a count
      real(dp), allocatable :: omega(:)       !! (k) fixed-interface frequencies (rad/s)
      real(dp), allocatable :: stiffness(:)   !! (m*m) S^-1, the boundary block of K_r (N/m)
      real(dp), allocatable :: transform(:,:) !! (J, r) T = [Psi, Phi]
   contains
      procedure :: expand
   end type reduced_basis

contains

   !> The default cut-off (rad/s): the largest of 10 times the highest forcing frequency and
   !! sqrt(12 frequency_error_limit)/dt, above which the full model's own time step already
   !! puts more than 1 % of error on a mode's frequency (docs/input.md, &mesh).
   pure function default_reduction_frequency(dt, forcing) result(cutoff)
      real(dp), intent(in) :: dt           !! time step (s)
      real(dp), intent(in) :: forcing(:)   !! forcing frequencies of the scene (rad/s)
      real(dp) :: cutoff
      cutoff = sqrt(12*frequency_error_limit)/dt
      if (size(forcing) > 0) cutoff = max(cutoff, 10*maxval(forcing))
   end function default_reduction_frequency

   !> Constraint modes at the contact points and fixed-interface modes up to `cutoff`
   !! (rad/s), or exactly `count` of them when count >= 0. stat /= 0 with errmsg on a
   !! failure of the eigenvalue solver or an allocation.
   subroutine build_reduction(model, contacts, cutoff, count, basis, stat, errmsg)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: cutoff      !! rad/s (used when count < 0)
      integer, intent(in) :: count        !! number of modes, or < 0: all below the cut-off
      type(reduced_basis), intent(out) :: basis
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(stiffness_inverse) :: flexibility
      real(dp), allocatable :: flexible(:,:), schur(:,:), eigenvalues(:), vectors(:,:)
      integer :: n, m, c, d, available, trial, k
      stat = 0
      errmsg = ''
      n = model%unknowns
      m = contacts%count
      basis%boundary = m
      if (count < 0) basis%cutoff = cutoff
      ! constraint modes: G = K^-1 H^T, S = H G, Psi = G S^-1
      call flexibility%setup(model, stat, errmsg)
      if (stat /= 0) return
      allocate (flexible(n, m), schur(m, m))
      do c = 1, m
         flexible(:, c) = 0
         do d = 1, 4
            if (contacts%dofs(d, c) /= 0) flexible(contacts%dofs(d, c), c) = contacts%weights(d, c)
         end do
         call flexibility%solve(flexible(:, c))
      end do
      do c = 1, m
         do d = 1, m
            schur(d, c) = contact_value(contacts, d, flexible(:, c))
         end do
      end do
      schur = 0.5_dp*(schur + transpose(schur))
      if (m > 0) then
         call dpotrf('L', m, schur, m, stat)
         if (stat == 0) call dpotri('L', m, schur, m, stat)
         if (stat /= 0) then
            errmsg = 'reduction: the contact points'' flexibility H K^-1 H^T is singular (two points on one node?)'
            return
         end if
      end if
      do c = 1, m
         schur(c, c + 1:) = schur(c + 1:, c)
      end do
      basis%stiffness = reshape(schur, [m*m])
      available = n - m
      allocate (basis%transform(n, m))
      if (m > 0) basis%transform = matmul(flexible, schur)
      ! fixed-interface modes: a count, or enough to pass the cut-off (doubled until one is above)
      if (count >= 0) then
         trial = min(count, available)
      else
         trial = min(available, max(4, 2*free_modes_below(model, cutoff) + 2))
      end if
      do
         if (trial == 0) then
            allocate (eigenvalues(0), vectors(n, 0))
            exit
         end if
         call fixed_interface_modes(model, contacts, basis%transform(:, 1:m), trial, eigenvalues, vectors, &
                                    stat, errmsg)
         if (stat /= 0) return
         if (count >= 0 .or. trial == available) exit
         if (sqrt(max(eigenvalues(trial), 0.0_dp)) > cutoff) exit
         trial = min(available, 2*trial)
      end do
      if (count >= 0) then
         k = trial
      else
         k = count_below(eigenvalues, cutoff)
      end if
      basis%modes = k
      basis%omega = sqrt(max(eigenvalues(1:k), 0.0_dp))
      basis%transform = reshape([basis%transform, vectors(:, 1:k)], [n, m + k])
   end subroutine build_reduction

   pure integer function count_below(eigenvalues, cutoff)
      real(dp), intent(in) :: eigenvalues(:), cutoff
      count_below = count(eigenvalues <= cutoff**2)
   end function count_below

   !> How many modes of the continuous clamped-free beam lie below omega (rad/s):
   !! beta_k L ~ (k - 1/2) pi, omega_k = beta_k^2 sqrt(EI/rho S). A first guess only.
   pure integer function free_modes_below(model, omega)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: omega
      real(dp), parameter :: pi = acos(-1.0_dp)
      free_modes_below = int(min(1e8_dp, sqrt(omega/sqrt(model%ei/model%rho_s))*model%length/pi + 0.5_dp))
   end function free_modes_below

   !> The modes in contact (docs/theory.md §7, "Modes in contact"; &analysis contact_modes):
   !! the `count` lowest natural modes of the beam with every contact point held at its
   !! obstacle (H phi = 0), the fixed-interface modes of the reduced model, as frequencies
   !! (rad/s, each the Rayleigh quotient of its eigenvector from element integrals, as
   !! `compute_modes` does) and shapes at the nodes scaled like the free modes
   !! (`normalize_modes`). count <= J - m. A beam with rigid-body motions (singular K,
   !! which the constraint modes need) takes the dense path.
   subroutine contact_modes(model, contacts, count, omega, shapes, stat, errmsg)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: count
      real(dp), allocatable, intent(out) :: omega(:), shapes(:,:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(reduced_basis) :: basis
      real(dp), allocatable :: eigenvalues(:), vectors(:,:)
      real(dp) :: bending, inertia
      integer :: k, n, m
      n = model%unknowns
      m = contacts%count
      if (count < 1 .or. count > n - m) then
         stat = stat_invalid_argument
         write (errmsg, '(a,i0,a,i0,a)') 'contact modes: ', count, ' modes asked, the beam held at its contact points '// &
            'has ', n - m, ' (J - m)'
         return
      end if
      if (rigid_motions(model) > 0 .or. m == 0) then
         allocate (eigenvalues(count), vectors(n, count))
         call dense_fixed_interface_modes(model, contacts, count, eigenvalues, vectors, stat, errmsg)
      else
         call build_reduction(model, contacts, 0.0_dp, 0, basis, stat, errmsg)   ! the constraint modes only
         if (stat == 0) call fixed_interface_modes(model, contacts, basis%transform(:, 1:m), count, eigenvalues, &
                                                   vectors, stat, errmsg)
      end if
      if (stat /= 0) return
      allocate (omega(count))
      do k = 1, count
         call energy_integrals(model, vectors(:, k), bending, inertia)
         omega(k) = sqrt(max(bending, 0.0_dp)/inertia)
      end do
      call normalize_modes(model, vectors, shapes, stat, errmsg)
   end subroutine contact_modes

   !> The `count` lowest modes with H phi = 0, M-orthonormal, ascending eigenvalues.
   subroutine fixed_interface_modes(model, contacts, constraint_modes, count, eigenvalues, vectors, stat, errmsg)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      real(dp), intent(in) :: constraint_modes(:,:)
      integer, intent(in) :: count
      real(dp), allocatable, intent(out) :: eigenvalues(:), vectors(:,:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: n, m
      n = model%unknowns
      m = contacts%count
      allocate (eigenvalues(count), vectors(n, count))
      if (dense_is_cheaper(n - m, count) .or. count >= n - m - 1) then
         call dense_fixed_interface_modes(model, contacts, count, eigenvalues, vectors, stat, errmsg)
      else if (m == 0) then
         call lanczos_modes(model, count, eigenvalues, vectors, stat, errmsg)
      else
         call lanczos_modes(model, count, eigenvalues, vectors, stat, errmsg, contacts%dofs, contacts%weights, &
                            constraint_modes)
      end if
   end subroutine fixed_interface_modes

   !> Dense path: Q = [Q_1, Q_2] from the QR factorization of H^T (J x m), Q_2 spans
   !! {H U = 0}; the pencil (Q_2^T K Q_2, Q_2^T M Q_2) by dsygv; phi = Q_2 x.
   subroutine dense_fixed_interface_modes(model, contacts, count, eigenvalues, vectors, stat, errmsg)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      integer, intent(in) :: count
      real(dp), intent(out) :: eigenvalues(:), vectors(:,:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: rows(:,:), tau(:), stiffness(:,:), mass(:,:), lambda(:), work(:), embedded(:,:)
      integer :: n, m, c, d, lwork
      n = model%unknowns
      m = contacts%count
      lwork = 64*n
      allocate (rows(n, max(m, 1)), tau(max(m, 1)), work(lwork), lambda(n - m))
      rows = 0
      do c = 1, m
         do d = 1, 4
            if (contacts%dofs(d, c) /= 0) rows(contacts%dofs(d, c), c) = contacts%weights(d, c)
         end do
      end do
      stiffness = band_to_dense(model%stiffness)
      mass = band_to_dense(model%mass)
      if (m > 0) then
         call dgeqrf(n, m, rows, n, tau, work, lwork, stat)
         if (stat == 0) call dormqr('L', 'T', n, n, m, rows, n, tau, stiffness, n, work, lwork, stat)
         if (stat == 0) call dormqr('R', 'N', n, n, m, rows, n, tau, stiffness, n, work, lwork, stat)
         if (stat == 0) call dormqr('L', 'T', n, n, m, rows, n, tau, mass, n, work, lwork, stat)
         if (stat == 0) call dormqr('R', 'N', n, n, m, rows, n, tau, mass, n, work, lwork, stat)
         if (stat /= 0) then
            write (errmsg, '(a,i0)') 'reduction: QR of the contact rows failed, info = ', stat
            return
         end if
      end if
      stiffness = stiffness(m + 1:, m + 1:)
      mass = mass(m + 1:, m + 1:)
      call dsygv(1, 'V', 'L', n - m, stiffness, n - m, mass, n - m, lambda, work, lwork, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'reduction: dsygv failed on the fixed-interface modes, info = ', stat
         return
      end if
      eigenvalues = lambda(1:count)
      allocate (embedded(n, count), source=0.0_dp)
      embedded(m + 1:, :) = stiffness(:, 1:count)   ! dsygv's B-orthonormal eigenvectors
      if (m > 0) call dormqr('L', 'N', n, count, m, rows, n, tau, embedded, n, work, lwork, stat)
      vectors = embedded
   end subroutine dense_fixed_interface_modes

   !> The reduced model: M_r = T^T M T and K_r = diag(S^-1, omega^2), dense r x r, in band
   !! storage with kd = r - 1. Everything else (length, beam data) as in the full model.
   subroutine reduce_model(model, basis, reduced)
      type(beam_model), intent(in) :: model
      type(reduced_basis), intent(in) :: basis
      type(beam_model), intent(out) :: reduced
      real(dp), allocatable :: mass_times(:,:)
      integer :: r, m, i, j
      m = basis%boundary
      r = m + basis%modes
      reduced%basis = 'reduced'
      reduced%elements = model%elements
      reduced%unknowns = r
      reduced%length = model%length
      reduced%h = model%h
      reduced%rho_s = model%rho_s
      reduced%ei = model%ei
      reduced%x = model%x
      allocate (mass_times(model%unknowns, r))
      do j = 1, r
         call band_matvec(model%mass, basis%transform(:, j), mass_times(:, j))
      end do
      call band_allocate(reduced%mass, r, max(r - 1, 0))
      call band_allocate(reduced%stiffness, r, max(r - 1, 0))
      do j = 1, r
         do i = j, r
            reduced%mass%lower(1 + i - j, j) = 0.5_dp*(dot_product(basis%transform(:, i), mass_times(:, j)) + &
                                                       dot_product(basis%transform(:, j), mass_times(:, i)))
         end do
      end do
      do j = 1, m
         do i = j, m
            reduced%stiffness%lower(1 + i - j, j) = basis%stiffness(i + (j - 1)*m)
         end do
      end do
      do j = 1, basis%modes
         reduced%stiffness%lower(1, m + j) = basis%omega(j)**2
      end do
   end subroutine reduce_model

   !> The contact points on the reduced coordinates: point c is y_c, an identity row.
   pure subroutine reduce_contacts(contacts, reduced)
      type(contact_set), intent(in) :: contacts
      type(contact_set), intent(out) :: reduced
      integer :: c
      reduced = contacts
      reduced%dofs = 0
      reduced%weights = 0
      do c = 1, contacts%count
         reduced%dofs(1, c) = c
         reduced%weights(1, c) = 1
      end do
   end subroutine reduce_contacts

   !> The loads on the reduced coordinates: F_r(t) = T^T F(t) (the load vectors projected).
   subroutine reduce_loads(loads, basis, reduced)
      type(load_set), intent(in) :: loads
      type(reduced_basis), intent(in) :: basis
      type(load_set), intent(out) :: reduced
      reduced = loads
      reduced%uniform = matmul(loads%uniform, basis%transform)
      reduced%point = matmul(loads%point, basis%transform)
      reduced%mass_points = matmul(loads%mass_points, basis%transform)
      call reduced%forces%project(basis%transform)
      call reduced%flow%project(basis%transform)
   end subroutine reduce_loads

   !> Reduced coordinates of a state U of the full model: y = H U exactly (so a state on its
   !! obstacles stays on them) and eta = Phi^T M (U - Psi y), the M-orthogonal projection
   !! of the rest on the modes kept.
   function reduce_state(model, contacts, basis, u) result(q)
      type(beam_model), intent(in) :: model
      type(contact_set), intent(in) :: contacts
      type(reduced_basis), intent(in) :: basis
      real(dp), intent(in) :: u(:)   !! (J)
      real(dp) :: q(basis%boundary + basis%modes)
      real(dp) :: rest(size(u)), mass_rest(size(u))
      integer :: c, m
      m = basis%boundary
      rest = u
      do c = 1, m
         q(c) = contact_value(contacts, c, u)
         rest = rest - q(c)*basis%transform(:, c)
      end do
      call band_matvec(model%mass, rest, mass_rest)
      if (basis%modes > 0) q(m + 1:) = matmul(mass_rest, basis%transform(:, m + 1:))
   end function reduce_state

   !> U = T q: the unknowns of the full model (for output only).
   function expand(self, q) result(u)
      class(reduced_basis), intent(in) :: self
      real(dp), intent(in) :: q(:)   !! (r)
      real(dp) :: u(size(self%transform, 1))
      u = matmul(self%transform, q)
   end function expand
end module vibrobeam_reduction
