!> The lowest eigenpairs of K phi = lambda M phi by shift-invert Lanczos: ARPACK-NG's
!! implicitly restarted Lanczos (dsaupd, then dseupd for the vectors) in its mode 3 with
!! shift 0, OP = K^-1 M, B = M, driven by reverse communication. K^-1 is applied by
!! `vibrobeam_flexibility` (double integration of the curvature: accurate at any N, where a
!! Cholesky solve with K is not), M by the band product.
!!
!! The eigenvalues of OP are 1/lambda: the wanted lowest lambda are the largest in
!! magnitude and separate fast (for a beam lambda_k grows like k^4). Memory: the ncv
!! Lanczos vectors, J x ncv with ncv = max(2 count + 1, 20) capped at J, plus O(J); time
!! O(J ncv^2) beside the operator. No J x J array (docs/method.md, "Natural modes";
!! Lehoucq, Sorensen & Yang, ARPACK Users' Guide, SIAM 1998, ch. 4).
module vibrobeam_lanczos
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_status, only: stat_failure, stat_invalid_argument
   use vibrobeam_band, only: band_matvec
   use vibrobeam_model, only: beam_model
   use vibrobeam_flexibility, only: cantilever_flexibility
   implicit none
   private
   public :: lanczos_modes

   integer, parameter :: max_restarts = 300   !! ARPACK's iparam(3)

   interface
      subroutine dsaupd(ido, bmat, n, which, nev, tol, resid, ncv, v, ldv, iparam, ipntr, workd, workl, &
                        lworkl, info)
         import :: dp
         integer, intent(inout) :: ido, info
         character(len=1), intent(in) :: bmat
         character(len=2), intent(in) :: which
         integer, intent(in) :: n, nev, ncv, ldv, lworkl
         real(dp), intent(inout) :: tol   !! a tol <= 0 is replaced by machine precision
         real(dp), intent(inout) :: resid(n), v(ldv, ncv), workd(3*n), workl(lworkl)
         integer, intent(inout) :: iparam(11), ipntr(11)
      end subroutine dsaupd
      subroutine dseupd(rvec, howmny, select, d, z, ldz, sigma, bmat, n, which, nev, tol, resid, ncv, v, &
                        ldv, iparam, ipntr, workd, workl, lworkl, info)
         import :: dp
         logical, intent(in) :: rvec
         character(len=1), intent(in) :: howmny, bmat
         character(len=2), intent(in) :: which
         logical, intent(inout) :: select(ncv)
         integer, intent(in) :: ldz, n, nev, ncv, ldv, lworkl
         real(dp), intent(in) :: sigma, tol
         real(dp), intent(out) :: d(nev), z(ldz, nev)
         real(dp), intent(inout) :: resid(n), v(ldv, ncv), workd(3*n), workl(lworkl)
         integer, intent(inout) :: iparam(11), ipntr(11), info
      end subroutine dseupd
   end interface

contains

   !> The number of Lanczos vectors ARPACK keeps for `count` eigenpairs of an n x n
   !! pencil: twice the count plus one, at least 20 (ARPACK's advice, ncv >= 2 nev), at
   !! most n. ARPACK needs count < ncv <= n, so it applies only for count < n.
   pure function lanczos_basis_size(n, count) result(ncv)
      integer, intent(in) :: n, count
      integer :: ncv
      ncv = min(n, max(2*count + 1, 20))
   end function lanczos_basis_size

   !> The `count` lowest eigenvalues lambda (ascending) of K phi = lambda M phi of the
   !! clamped-free beam, with their M-orthonormal eigenvectors. stat /= 0 with errmsg if
   !! count is not in [1, J-1] or on any ARPACK error.
   !!
   !! With `held_dofs`, `held_weights` and `constraint_modes` the modes are those of the beam
   !! with the m displacements H_c U (rows of 4 unknowns and weights) held at 0, the
   !! fixed-interface modes of Craig-Bampton (`vibrobeam_reduction`): the operator becomes
   !! the constrained flexibility (I - Psi H) K^-1, Psi = K^-1 H^T (H K^-1 H^T)^-1 the
   !! constraint modes. It is M-symmetric (K^-1 - K^-1 H^T S^-1 H K^-1 is symmetric), its
   !! range is {H U = 0}, and its m zero eigenvalues are the smallest, never wanted.
   subroutine lanczos_modes(model, count, eigenvalues, vectors, stat, errmsg, held_dofs, held_weights, &
                            constraint_modes)
      type(beam_model), intent(in) :: model
      integer, intent(in) :: count                   !! 1 <= count <= J - 1
      real(dp), intent(out) :: eigenvalues(:)        !! (count) lambda (rad^2/s^2), ascending
      real(dp), intent(out) :: vectors(:,:)          !! (J, count), phi^T M phi = 1
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: held_dofs(:,:)           !! (4, m) unknowns of each held row (0: none)
      real(dp), intent(in), optional :: held_weights(:,:)       !! (4, m) its weights
      real(dp), intent(in), optional :: constraint_modes(:,:)   !! (J, m) Psi
      type(cantilever_flexibility) :: flexibility
      real(dp), allocatable :: lanczos_vectors(:,:), workd(:), workl(:), resid(:)
      logical, allocatable :: select(:)
      integer :: n, ncv, ido, info, iparam(11), ipntr(11), i
      real(dp) :: tolerance
      n = model%unknowns
      stat = 0
      errmsg = ''
      if (count < 1 .or. count >= n) then
         stat = stat_invalid_argument
         write (errmsg, '(a,i0,a,i0,a)') 'Lanczos: number of modes ', count, ' is outside [1, ', n - 1, ']'
         return
      end if
      call flexibility%setup(model, stat, errmsg)
      if (stat /= 0) return
      ncv = lanczos_basis_size(n, count)
      ! ARPACK's work length ncv (ncv + 8) is a default integer
      if (int(ncv, int64)*(ncv + 8) > huge(ncv)) then
         stat = stat_invalid_argument
         write (errmsg, '(a,i0,a)') 'Lanczos: ', count, ' modes need a work array longer than ARPACK can index'
         return
      end if
      allocate (lanczos_vectors(n, ncv), workd(3*n), workl(ncv*(ncv + 8)), resid(n), select(ncv), stat=stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0,a,i0,a)') 'Lanczos: cannot allocate ', 8*int(n, int64)*ncv/2**20, &
            ' MB for ', ncv, ' Lanczos vectors'
         return
      end if
      ! A fixed starting vector (info = 1), so that a run repeats exactly: a Weyl sequence,
      ! with components along every eigenvector (ARPACK's default draws a random one).
      resid = [(modulo(i*0.6180339887498949_dp, 1.0_dp) - 0.5_dp, i=1, n)]
      info = 1
      iparam = 0
      iparam(1) = 1              ! exact shifts
      iparam(3) = max_restarts
      iparam(4) = 1              ! block size
      iparam(7) = 3              ! shift-invert mode
      ido = 0
      ! 0: ARPACK's default, machine precision on each Ritz value (dsaupd writes it back)
      tolerance = 0
      ! ARPACK keeps the state of an iteration in SAVEd variables: one iteration at a time
      ! in the process (a sweep's points prepare their reduced models on several threads)
      !$omp critical (vibrobeam_arpack)
      call iterate()
      !$omp end critical (vibrobeam_arpack)

   contains

      !> dsaupd's reverse-communication loop, then dseupd for the eigenpairs.
      subroutine iterate()
         do
            call dsaupd(ido, 'G', n, 'LM', count, tolerance, resid, ncv, lanczos_vectors, n, iparam, ipntr, &
                        workd, workl, size(workl), info)
            if (ido == 99) exit
            call apply_operator(model, flexibility, ido, ipntr, workd, stat, errmsg, held_dofs, held_weights, &
                                constraint_modes)
            if (stat /= 0) return
         end do
         if (info /= 0 .or. iparam(5) < count) then
            stat = stat_failure
            errmsg = 'Lanczos: '//arpack_message('dsaupd', info, iparam(5), count, ncv)
            return
         end if
         call dseupd(.true., 'A', select, eigenvalues, vectors, n, 0.0_dp, 'G', n, 'LM', count, tolerance, resid, &
                     ncv, lanczos_vectors, n, iparam, ipntr, workd, workl, size(workl), info)
         if (info /= 0) then
            stat = stat_failure
            errmsg = 'Lanczos: '//arpack_message('dseupd', info, iparam(5), count, ncv)
         end if
      end subroutine iterate
   end subroutine lanczos_modes

   !> One request of ARPACK's reverse communication (`ido`, mode 3): the operand starts
   !! at workd(ipntr(1)), the result goes to workd(ipntr(2)), and M times the operand is at
   !! workd(ipntr(3)) when ido = 1. OP = K^-1 M, held displacements put back to 0 with
   !! `constraint_modes` (`hold`); B = M. stat = stat_failure on an unexpected request.
   subroutine apply_operator(model, flexibility, ido, ipntr, workd, stat, errmsg, held_dofs, held_weights, &
                             constraint_modes)
      type(beam_model), intent(in) :: model
      type(cantilever_flexibility), intent(inout) :: flexibility
      integer, intent(in) :: ido, ipntr(11)
      real(dp), intent(inout) :: workd(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: held_dofs(:,:)
      real(dp), intent(in), optional :: held_weights(:,:), constraint_modes(:,:)
      integer :: n
      n = model%unknowns
      stat = 0
      errmsg = ''
      ! (ipntr(3) is set for ido = 1 only: its section is formed there)
      associate (x => workd(ipntr(1):ipntr(1) + n - 1), y => workd(ipntr(2):ipntr(2) + n - 1))
         select case (ido)
         case (-1)   ! y = K^-1 M x (the start: M x not yet known)
            call band_matvec(model%mass, x, y)
            call flexibility%solve(y)
            if (present(constraint_modes)) call hold(y, held_dofs, held_weights, constraint_modes)
         case (1)    ! y = K^-1 M x, with M x given
            y = workd(ipntr(3):ipntr(3) + n - 1)
            call flexibility%solve(y)
            if (present(constraint_modes)) call hold(y, held_dofs, held_weights, constraint_modes)
         case (2)    ! y = M x
            call band_matvec(model%mass, x, y)
         case default
            stat = stat_failure
            write (errmsg, '(a,i0)') 'Lanczos: ARPACK dsaupd made an unexpected request, ido = ', ido
         end select
      end associate
   end subroutine apply_operator

   !> y := y - Psi (H y): the static response with the held displacements (rows of 4
   !! unknowns `held_dofs` and weights `held_weights`) put back to 0.
   subroutine hold(y, held_dofs, held_weights, constraint_modes)
      real(dp), intent(inout) :: y(:)
      integer, intent(in) :: held_dofs(:,:)
      real(dp), intent(in) :: held_weights(:,:), constraint_modes(:,:)
      real(dp) :: held(size(constraint_modes, 2))
      integer :: c, a
      real(dp) :: value
      do c = 1, size(constraint_modes, 2)
         value = 0
         do a = 1, 4
            if (held_dofs(a, c) /= 0) value = value + held_weights(a, c)*y(held_dofs(a, c))
         end do
         held(c) = value
      end do
      do c = 1, size(constraint_modes, 2)
         y = y - held(c)*constraint_modes(:, c)
      end do
   end subroutine hold

   !> What an ARPACK info (dsaupd / dseupd, ARPACK-NG 3.8 documentation) means.
   function arpack_message(routine, info, converged, count, ncv) result(message)
      character(len=*), intent(in) :: routine
      integer, intent(in) :: info, converged, count, ncv
      character(len=:), allocatable :: message
      character(len=200) :: text
      character(len=300) :: buffer
      select case (info)
      case (0)
         write (text, '(a,i0,a,i0,a)') 'only ', converged, ' of ', count, ' eigenvalues converged'
      case (1)
         write (text, '(a,i0,a,i0,a,i0,a)') 'the maximum of ', max_restarts, ' restarts was reached with ', &
            converged, ' of ', count, ' eigenvalues converged'
      case (3)
         write (text, '(a,i0,a)') 'no shift could be applied in a restart (', ncv, ' Lanczos vectors)'
      case (-1, -2, -3, -4, -5, -6, -7, -10, -11, -12, -13, -15, -16)
         write (text, '(a,i0,a,i0,a,i0,a)') 'invalid argument (info = ', info, ', count ', count, ', ', ncv, &
            ' Lanczos vectors)'
      case (-8)
         text = 'the tridiagonal eigenvalue solver (dsteqr) failed'
      case (-9)
         text = 'the starting vector is zero'
      case (-14)
         text = 'no eigenvalue reached the required accuracy'
      case (-17)
         text = 'dseupd counted a different number of converged eigenvalues than dsaupd'
      case (-9999)
         write (text, '(a,i0,a)') 'no Lanczos factorization could be built (size reached ', converged, ')'
      case default
         write (text, '(a,i0)') 'unknown error, info = ', info
      end select
      write (buffer, '(a,i0,a)') 'ARPACK '//routine//' (info = ', info, '): '//trim(text)
      message = trim(buffer)
   end function arpack_message
end module vibrobeam_lanczos
