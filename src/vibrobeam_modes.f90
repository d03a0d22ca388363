!> Natural modes of the discrete beam: K phi = omega^2 M phi (SPEC §2, §5).
!!
!! Solved with LAPACK dsbgvx on the band matrices. We pass the pencil the other way round,
!! M phi = mu K phi with mu = 1/omega^2, and ask for the largest mu: dsbgvx's error on an
!! eigenvalue is of order eps times the largest one, so the low modes users want keep full
!! relative accuracy instead of losing the condition number of K (about 1e9 at N = 64).
module vibrobeam_modes
   use vibrobeam_kinds, only: dp
   use vibrobeam_model, only: beam_model, nodal_displacement, energy_integrals
   implicit none
   private
   public :: compute_modes

   interface
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
      function dlamch(cmach) result(value)
         import :: dp
         character, intent(in) :: cmach
         real(dp) :: value
      end function dlamch
   end interface

contains

   !> The `count` lowest natural angular frequencies (rad/s, ascending) and their mode
   !! shapes at the nodes (node 0 included), each normalized to tip displacement 1. Also
   !! returns the unknowns of each mode (columns of `vectors`, same normalization).
   subroutine compute_modes(model, count, omega, shapes, vectors, stat, errmsg)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: count                     !! 1 <= count <= J
      real(dp), allocatable, intent(out) :: omega(:)   !! (count)
      real(dp), allocatable, intent(out) :: shapes(:,:)   !! (N+1, count)
      real(dp), allocatable, intent(out) :: vectors(:,:)  !! (J, count)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: mass_band(:,:), stiffness_band(:,:), q(:,:), mu(:), work(:)
      integer, allocatable :: iwork(:), ifail(:)
      integer :: n, kd, found, k
      real(dp) :: tip, bending, inertia
      stat = 0
      errmsg = ''
      n = model%unknowns
      kd = model%mass%kd
      if (count < 1 .or. count > n) then
         stat = 1
         write (errmsg, '(a,i0,a,i0,a)') 'number of modes ', count, ' is outside [1, ', n, ']'
         return
      end if
      allocate (mass_band, source=model%mass%lower)
      allocate (stiffness_band, source=model%stiffness%lower)
      allocate (q(n, n), mu(n), vectors(n, count), work(7*n), iwork(5*n), ifail(n))
      call dsbgvx('V', 'I', 'L', n, kd, model%stiffness%kd, mass_band, kd + 1, stiffness_band, &
                  model%stiffness%kd + 1, q, n, 0.0_dp, 0.0_dp, n - count + 1, n, &
                  2*dlamch('S'), found, mu, vectors, n, work, iwork, ifail, stat)
      if (stat /= 0 .or. found /= count) then
         write (errmsg, '(a,i0,a,i0,a,i0)') 'eigenvalue solver dsbgvx failed: info = ', stat, &
            ', found ', found, ' of ', count
         if (stat == 0) stat = 1
         return
      end if
      ! mu ascends, so omega = 1/sqrt(mu) descends: reverse both.
      vectors = vectors(:, count:1:-1)
      ! Each omega^2 is then taken as the Rayleigh quotient of its eigenvector, computed
      ! from element integrals (`energy_integrals`): equal to the eigenvalue, but free of
      ! the eps * cond(K) error that dsbgvx's Cholesky of K leaves (measured: 1.6e-9 on
      ! omega_1 with 128 B-spline elements), since an O(delta) eigenvector error only
      ! changes the quotient by O(delta^2).
      allocate (omega(count))
      do k = 1, count
         call energy_integrals(model, vectors(:, k), bending, inertia)
         omega(k) = sqrt(bending/inertia)
      end do
      allocate (shapes(model%elements + 1, count))
      do k = 1, count
         shapes(:, k) = nodal_displacement(model, vectors(:, k))
         tip = shapes(model%elements + 1, k)
         if (abs(tip) <= tiny(tip)) then
            stat = 1
            write (errmsg, '(a,i0,a)') 'mode ', k, ' has zero tip displacement and cannot be normalized'
            return
         end if
         shapes(:, k) = shapes(:, k)/tip
         vectors(:, k) = vectors(:, k)/tip
      end do
   end subroutine compute_modes
end module vibrobeam_modes
