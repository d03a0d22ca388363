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
!! Each mode is normalized to displacement 1 at a free end (the tip of a cantilever), else
!! at its largest nodal value.
!!
!! Other structures (any end supports and springs, intermediate supports, point masses,
!! sections, an axial force; docs/method.md, "Supports"): the same two paths on the pencil
!! shifted by s M (`mode_shift`: s = 0 unless the structure has rigid-body motions, whose
!! K is singular), K + s M factored by the band Cholesky where the double integration does
!! not apply; omega^2 is then always the Rayleigh quotient of the eigenvector from element
!! integrals (its error is second order in the eigenvector's), and the first
!! `rigid_motions` modes, whose eigenvalue is exactly 0, are reported as omega = 0. A
!! negative eigenvalue beyond them (an axial compression above the buckling load) is an
!! error.
module vibrobeam_modes
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure
   use vibrobeam_model, only: beam_model, build_model, nodal_displacement, energy_integrals, rigid_motions, &
      flexibility_applies
   use vibrobeam_structure, only: beam_structure
   use vibrobeam_band, only: band_combination, symmetric_band, band_matvec
   use vibrobeam_lanczos, only: lanczos_modes
   use vibrobeam_lapack, only: dsbgvx, dlamch
   implicit none
   private
   public :: compute_modes, dense_is_cheaper, mode_shift, reference_frequencies, normalize_modes

   !> Where dsbgvx is cheaper than Lanczos (measured, docs/method.md): up to this many
   !! unknowns, or for more than J/dense_fraction modes.
   integer, parameter :: dense_unknowns = 16, dense_fraction = 4
   !> Hermite elements of the model whose modes stand in for a closed form
   !! (`reference_frequencies`): relative error about (beta_n h)^4/1440, 1e-9 for mode 1
   !! of a cantilever and 2e-4 for its mode 10 (theory §7).
   integer, parameter :: reference_elements = 64

contains

   !> The shift s (rad^2/s^2) of the pencil (K + s M, M) the solvers use: 0 for a structure
   !! without rigid-body motion, else the scale EI/(rho S L^4) + |T|/(rho S L^2) of the
   !! lowest flexible eigenvalues (largest EI, smallest rho S of the sections), which makes
   !! K + s M positive definite without swamping them.
   pure real(dp) function mode_shift(model, rigid)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: rigid   !! rigid_motions(model)
      mode_shift = 0
      if (rigid == 0) return
      mode_shift = (maxval(model%element_ei)/model%length**4 + abs(model%structure%axial_force)/model%length**2)/ &
                   minval(model%element_rho_s)
   end function mode_shift

   !> The lowest natural frequencies (rad/s, ascending; the rigid-body motions at 0) of the
   !! beam of length L, mass rho S and stiffness EI with everything `structure` holds, as the
   !! frequency scale of advice, warnings and defaults that come before the run's own model
   !! (`vibrobeam --check`, the episode gap): the continuum's closed form
   !! (`boundary%natural_frequency`, theory §7) when the beam is uniform on two end supports
   !! without springs (`closed_form` true), else the modes of a model of
   !! `reference_elements` Hermite elements. stat /= 0 with errmsg when those fail.
   subroutine reference_frequencies(structure, length, rho_s, ei, omega, closed_form, stat, errmsg)
      type(beam_structure), intent(in) :: structure
      real(dp), intent(in) :: length, rho_s, ei   !! L (m), rho S (kg/m), EI (N m^2)
      real(dp), intent(out) :: omega(:)           !! the first size(omega) frequencies (rad/s)
      logical, intent(out) :: closed_form
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(beam_model) :: model
      real(dp), allocatable :: values(:), shapes(:,:), vectors(:,:)
      integer :: n
      stat = 0
      errmsg = ''
      closed_form = structure%has_closed_form()
      if (closed_form) then
         omega = [(structure%boundary%natural_frequency(n, length, ei/rho_s), n=1, size(omega))]
         return
      end if
      omega = 0
      call build_model('hermite', reference_elements, length, rho_s, ei, model, stat, errmsg, structure=structure)
      if (stat == 0) call compute_modes(model, min(size(omega), model%unknowns), values, shapes, vectors, stat, errmsg)
      if (stat /= 0) return
      omega(1:size(values)) = values
   end subroutine reference_frequencies

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
      integer :: n, k, rigid
      real(dp) :: bending, inertia, shift
      logical :: dense, refine
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
      ! the uniform cantilever keeps its exact paths; other structures are refined
      refine = .not. flexibility_applies(model)
      rigid = 0
      if (refine) rigid = rigid_motions(model)
      shift = mode_shift(model, rigid)
      if (dense) then
         call dense_modes(model, count, shift, vectors, stat, errmsg)
         if (stat /= 0) return
         ! omega^2 as the Rayleigh quotient of each eigenvector from element integrals: equal
         ! to the eigenvalue, but free of the eps * cond(K) error that dsbgvx's Cholesky of K
         ! leaves (measured: 1.6e-9 on omega_1 with 128 B-spline elements), since an
         ! O(delta) eigenvector error only changes the quotient by O(delta^2).
         do k = 1, count
            call energy_integrals(model, vectors(:, k), bending, inertia)
            omega(k) = sqrt(max(bending, 0.0_dp)/inertia)
            if (bending < 0) omega(k) = -sqrt(-bending/inertia)
         end do
      else
         ! The Ritz values need no such refinement (their operator is accurate), and would
         ! lose to it: the curvature summed by `energy_integrals` cancels to eps N^2
         ! (measured at N = 1e5: omega_1 off by 4e-8 with B-splines, against 1e-14 here).
         allocate (eigenvalues(count))
         call lanczos_modes(model, count, eigenvalues, vectors, stat, errmsg, shift=shift)
         if (stat /= 0) return
         if (refine) then
            do k = 1, count
               call energy_integrals(model, vectors(:, k), bending, inertia)
               eigenvalues(k) = bending/inertia
            end do
         end if
         omega = sign(sqrt(abs(eigenvalues)), eigenvalues)
      end if
      ! the rigid-body motions: eigenvalue 0 exactly (the structure says how many)
      omega(1:min(rigid, count)) = 0
      if (any(omega(min(rigid, count) + 1:) < 0)) then
         stat = stat_failure
         errmsg = 'the stiffness K is not positive: a mode has a negative eigenvalue omega^2 (an axial '// &
                  'compression beyond the buckling load?)'
         return
      end if
      if (rigid == 2 .and. count >= 2) call canonical_rigid_motions(model, vectors(:, 1:2))
      call normalize_modes(model, vectors, shapes, stat, errmsg)
   end subroutine compute_modes

   !> The mode shapes at the nodes of `vectors` (its columns scaled with them): 1 at a
   !! free end (the tip of a cantilever; the right end first), else, and for a mode
   !! (nearly) at rest there, 1 at its largest nodal value. stat = stat_failure for a mode zero at every
   !! node.
   subroutine normalize_modes(model, vectors, shapes, stat, errmsg)
      type(beam_model), intent(in) :: model
      real(dp), intent(inout) :: vectors(:,:)            !! (J, modes)
      real(dp), allocatable, intent(out) :: shapes(:,:)  !! (N+1, modes)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k, node
      real(dp) :: tip
      stat = 0
      errmsg = ''
      allocate (shapes(model%elements + 1, size(vectors, 2)))
      node = model%boundary%normalization_node(model%elements)
      do k = 1, size(vectors, 2)
         shapes(:, k) = nodal_displacement(model, vectors(:, k))
         if (node >= 0) then
            tip = shapes(node + 1, k)
         else
            tip = shapes(maxloc(abs(shapes(:, k)), dim=1), k)
         end if
         if (abs(tip) <= 1e-8_dp*maxval(abs(shapes(:, k)))) tip = shapes(maxloc(abs(shapes(:, k)), dim=1), k)
         if (abs(tip) <= tiny(tip)) then
            stat = stat_failure
            write (errmsg, '(a,i0,a)') 'mode ', k, ' has zero displacement at every node and cannot be normalized'
            return
         end if
         shapes(:, k) = shapes(:, k)/tip
         vectors(:, k) = vectors(:, k)/tip
      end do
   end subroutine normalize_modes

   !> Two rigid-body modes (any basis of the plane of u = a + b x the solver returned) as a
   !! translation (u = 1 up to scale) and the rotation about the centre of mass M-orthogonal
   !! to it: the translation is the combination whose end values agree, the rotation the
   !! other vector less its M-projection on the translation.
   subroutine canonical_rigid_motions(model, rigid)
      type(beam_model), intent(in) :: model
      real(dp), intent(inout) :: rigid(:,:)   !! (J, 2)
      real(dp) :: ends(2, 2), translation(size(rigid, 1)), rotation(size(rigid, 1)), m_translation(size(rigid, 1))
      real(dp) :: w(model%elements + 1)
      integer :: k
      do k = 1, 2
         w = nodal_displacement(model, rigid(:, k))
         ends(:, k) = [w(1), w(model%elements + 1)]
      end do
      translation = (ends(2, 2) - ends(1, 2))*rigid(:, 1) - (ends(2, 1) - ends(1, 1))*rigid(:, 2)
      call band_matvec(model%mass, translation, m_translation)
      k = maxloc(abs(ends(2, :) - ends(1, :)), dim=1)
      rotation = rigid(:, k) - dot_product(m_translation, rigid(:, k))/dot_product(m_translation, translation)*translation
      rigid(:, 1) = translation
      rigid(:, 2) = rotation
   end subroutine canonical_rigid_motions

   !> The eigenvectors of the `count` lowest modes (ascending) by LAPACK dsbgvx on the
   !! reversed pencil M phi = mu (K + s M) phi (module header). Needs a J x J work matrix.
   subroutine dense_modes(model, count, shift, vectors, stat, errmsg)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: count
      real(dp), intent(in) :: shift   !! s (rad^2/s^2)
      real(dp), intent(out) :: vectors(:,:)   !! (J, count)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: mass_band(:,:), stiffness_band(:,:), q(:,:), mu(:), work(:)
      type(symmetric_band) :: shifted
      integer, allocatable :: iwork(:), ifail(:)
      integer :: n, kd, found
      n = model%unknowns
      kd = model%mass%kd
      allocate (mass_band, source=model%mass%lower)
      if (shift > 0) then
         shifted = band_combination(1.0_dp, model%stiffness, shift, model%mass)
         allocate (stiffness_band, source=shifted%lower)
      else
         allocate (stiffness_band, source=model%stiffness%lower)
      end if
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
