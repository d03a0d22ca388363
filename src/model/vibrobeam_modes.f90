!> Natural modes of the discrete beam: K phi = omega^2 M phi (theory §2).
!!
!! Two solvers (docs/method.md, "Natural modes"):
!! - shift-invert Lanczos (`vibrobeam_lanczos`, ARPACK-NG) with K^-1 applied by double
!!   integration of the curvature (`vibrobeam_flexibility`): memory and time O(J) per
!!   mode, accurate at any N. omega^2 is the Ritz value, i.e. the inverse of the Rayleigh
!!   quotient of K^-1 in the M inner product, computed without differentiating the mode;
!! - LAPACK dsbgvx, which forms a dense J x J transformation (8 J^2 bytes), kept where it
!!   is cheaper or the only one that applies (`dense_is_cheaper`: few unknowns, or more
!!   than J/4 modes). It is given the pencil the other way round, M phi = mu K phi with
!!   mu = 1/omega^2, and asked for the largest mu, so that its error, of order eps times
!!   the largest eigenvalue, stays small on the low modes; what its Cholesky of K still
!!   leaves (eps cond(K)) is removed by taking omega^2 as the Rayleigh quotient of each
!!   eigenvector summed element by element (`energy_integrals`).
!! Each mode is normalized to tip displacement 1.
module vibrobeam_modes
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure
   use vibrobeam_model, only: beam_model, nodal_displacement, energy_integrals
   use vibrobeam_lanczos, only: lanczos_modes
   use vibrobeam_lapack, only: dsbgvx, dlamch
   implicit none
   private
   public :: compute_modes, dense_is_cheaper

   !> Where dsbgvx is cheaper than Lanczos (measured, docs/method.md): up to this many
   !! unknowns, or for more than J/dense_fraction modes.
   integer, parameter :: dense_unknowns = 16, dense_fraction = 4


contains

   !> Whether LAPACK's dense path is cheaper than Lanczos for `count` modes of J unknowns
   !! (the rule measured in docs/method.md, "Natural modes"), or the only one that applies
   !! (ARPACK needs count < J).
   pure function dense_is_cheaper(unknowns, count) result(dense)
      integer, intent(in) :: unknowns, count
      logical :: dense
      dense = unknowns <= dense_unknowns .or. count > unknowns/dense_fraction
   end function dense_is_cheaper

   !> The `count` lowest natural angular frequencies (rad/s, ascending) and their mode
   !! shapes at the nodes (node 0 included), each normalized to tip displacement 1. Also
   !! returns the unknowns of each mode (columns of `vectors`, same normalization).
   !! `method` forces a path for tests and benchmarks: 'lanczos' or 'dense' (default:
   !! the cheaper, `dense_is_cheaper`).
   subroutine compute_modes(model, count, omega, shapes, vectors, stat, errmsg, method)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: count                     !! 1 <= count <= J
      real(dp), allocatable, intent(out) :: omega(:)   !! (count)
      real(dp), allocatable, intent(out) :: shapes(:,:)   !! (N+1, count)
      real(dp), allocatable, intent(out) :: vectors(:,:)  !! (J, count)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), intent(in), optional :: method  !! 'lanczos' | 'dense'
      real(dp), allocatable :: eigenvalues(:)
      integer :: n, k, node
      real(dp) :: tip, bending, inertia
      logical :: dense
      stat = 0
      errmsg = ''
      n = model%unknowns
      if (count < 1 .or. count > n) then
         stat = stat_failure
         write (errmsg, '(a,i0,a,i0,a)') 'number of modes ', count, ' is outside [1, ', n, ']'
         return
      end if
      dense = dense_is_cheaper(n, count)
      if (present(method)) dense = method == 'dense'
      allocate (vectors(n, count), omega(count), stat=stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0,a,i0,a)') 'cannot allocate ', 8*int(n, int64)*count/2**20, ' MB for ', count, ' modes'
         return
      end if
      if (dense) then
         call dense_modes(model, count, vectors, stat, errmsg)
         if (stat /= 0) return
         ! omega^2 as the Rayleigh quotient of each eigenvector from element integrals: equal
         ! to the eigenvalue, but free of the eps * cond(K) error that dsbgvx's Cholesky of K
         ! leaves (measured: 1.6e-9 on omega_1 with 128 B-spline elements), since an
         ! O(delta) eigenvector error only changes the quotient by O(delta^2).
         do k = 1, count
            call energy_integrals(model, vectors(:, k), bending, inertia)
            omega(k) = sqrt(bending/inertia)
         end do
      else
         ! The Ritz values need no such refinement (their operator is accurate), and would
         ! lose to it: the curvature summed by `energy_integrals` cancels to eps N^2
         ! (measured at N = 1e5: omega_1 off by 4e-8 with B-splines, against 1e-14 here).
         allocate (eigenvalues(count))
         call lanczos_modes(model, count, eigenvalues, vectors, stat, errmsg)
         if (stat /= 0) return
         omega = sqrt(eigenvalues)
      end if
      allocate (shapes(model%elements + 1, count))
      node = model%boundary%normalization_node(model%elements)
      do k = 1, count
         shapes(:, k) = nodal_displacement(model, vectors(:, k))
         ! scaled to 1 at a free end (the tip of a cantilever), else at its largest value
         if (node >= 0) then
            tip = shapes(node + 1, k)
         else
            tip = shapes(maxloc(abs(shapes(:, k)), dim=1), k)
         end if
         if (abs(tip) <= tiny(tip)) then
            stat = stat_failure
            write (errmsg, '(a,i0,a)') 'mode ', k, ' has zero displacement at its free end and cannot be normalized'
            return
         end if
         shapes(:, k) = shapes(:, k)/tip
         vectors(:, k) = vectors(:, k)/tip
      end do
   end subroutine compute_modes

   !> The eigenvectors of the `count` lowest modes (ascending) by LAPACK dsbgvx on the
   !! reversed pencil (module header). Needs a J x J work matrix.
   subroutine dense_modes(model, count, vectors, stat, errmsg)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: count
      real(dp), intent(out) :: vectors(:,:)   !! (J, count)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: mass_band(:,:), stiffness_band(:,:), q(:,:), mu(:), work(:)
      integer, allocatable :: iwork(:), ifail(:)
      integer :: n, kd, found
      n = model%unknowns
      kd = model%mass%kd
      allocate (mass_band, source=model%mass%lower)
      allocate (stiffness_band, source=model%stiffness%lower)
      allocate (q(n, n), mu(n), work(7*n), iwork(5*n), ifail(n), stat=stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0,a)') 'dsbgvx: cannot allocate its J x J work matrix (', 8*int(n, int64)**2/2**20, ' MB)'
         return
      end if
      call dsbgvx('V', 'I', 'L', n, kd, model%stiffness%kd, mass_band, kd + 1, stiffness_band, &
                  model%stiffness%kd + 1, q, n, 0.0_dp, 0.0_dp, n - count + 1, n, &
                  2*dlamch('S'), found, mu, vectors, n, work, iwork, ifail, stat)
      if (stat /= 0 .or. found /= count) then
         write (errmsg, '(a,i0,a,i0,a,i0)') 'eigenvalue solver dsbgvx failed: info = ', stat, &
            ', found ', found, ' of ', count
         stat = stat_failure
         return
      end if
      errmsg = ''
      ! mu ascends, so omega = 1/sqrt(mu) descends: reverse.
      vectors = vectors(:, count:1:-1)
   end subroutine dense_modes
end module vibrobeam_modes
