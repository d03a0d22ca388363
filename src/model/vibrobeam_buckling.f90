!> Whether an axial compression leaves the beam stable, and its buckling load (theory §1,
!! "Axial force"; docs/input.md, "&beam" axial_force).
!!
!! A compression T < 0 adds T int u'^2 < 0 to the strain energy: K = K_b + T K_g (K_b of
!! bending and springs, K_g = int phi_i' phi_j' the geometric stiffness) stays positive
!! definite up to the buckling load P = min u^T K_b u / u^T K_g u and becomes indefinite
!! beyond it, where every analysis would follow an exponential growth that the linear
!! model cannot describe. `check_compression` refuses it on the scene's own mesh: the
!! Cholesky factorization of K fails exactly when K is not (numerically) positive definite.
!! A structure with rigid-body motions (K_b singular) is checked on the motions' complement:
!! a free rotation u = b (x - x_p) has energy T b^2 L < 0 under any compression (buckling
!! load 0); a free translation u = a has none (K_g u = 0), and K is positive semi-definite
!! exactly when it is positive definite on {u(0) = 0}, which holding the left end's
!! deflection gives.
!!
!! `buckling_load` computes P on `buckling_elements` Hermite elements as the largest
!! eigenvalue mu of the band pencil K_g v = mu K_b v (LAPACK dsbgvx; P = 1/mu), the discrete
!! value converging like h^4 from above (Rayleigh-Ritz): 8.1e-9 relative for the pinned-
!! pinned beam's pi^2 EI/L^2 at 64 elements.
module vibrobeam_buckling
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_band, only: symmetric_band, band_cholesky, band_factor, band_combination
   use vibrobeam_lapack, only: dsbgvx, dlamch
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_structure, only: beam_structure
   use vibrobeam_boundary, only: end_free, end_pinned, end_sliding, end_clamped
   implicit none
   private
   public :: check_compression, buckling_load, buckling_elements

   !> Hermite elements of the model whose buckling load a message gives.
   integer, parameter :: buckling_elements = 64

contains

   !> stat = stat_failure with a message naming &beam axial_force and the buckling load
   !! when the compression of `structure` (axial_force < 0) makes K of the mesh (basis, N
   !! elements of [0, L], the uniform rho S and EI or the structure's sections) indefinite
   !! (module documentation); stat = 0 otherwise and for T >= 0.
   subroutine check_compression(basis, elements, length, rho_s, ei, structure, stat, errmsg)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), intent(in) :: length, rho_s, ei   !! L (m), rho S (kg/m), EI (N m^2)
      type(beam_structure), intent(in) :: structure
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(beam_structure) :: held
      type(beam_model) :: model
      type(band_cholesky) :: factor
      real(dp) :: load
      character(len=256) :: detail
      character(len=:), allocatable :: force
      stat = 0
      errmsg = ''
      if (.not. structure%axial_force < 0) return
      force = '&beam axial_force = '//real_text(structure%axial_force)//' N'
      call stable_part(structure, length, held, stat)
      if (stat /= 0) then
         errmsg = force//' compresses a beam whose supports leave it free to rotate (a rigid-body motion '// &
                  'u = b (x - x_p), whose energy T b^2 L is negative under any compression: buckling load 0); '// &
                  'hold its rotation or a second point, or give axial_force >= 0'
         return
      end if
      call build_model(basis, elements, length, rho_s, ei, model, stat, errmsg, structure=held)
      if (stat /= 0) return
      call band_factor(model%stiffness, factor, stat, detail)
      if (stat == 0) return
      call buckling_load(held, length, rho_s, ei, load, stat, detail)
      if (stat /= 0) then
         stat = stat_failure
         errmsg = force//' is beyond the buckling load of this beam: its stiffness K is not positive definite '// &
                  '(the Cholesky factorization fails); give a smaller compression'
         return
      end if
      stat = stat_failure
      errmsg = force//' is beyond the buckling load of this beam, P = '//real_text(load)//' N (computed with '// &
               integer_text(buckling_elements)//' Hermite elements; pinned-pinned: pi^2 EI/L^2): its stiffness '// &
               'K = K_bending + T K_geometric is not positive definite (the Cholesky factorization fails); give '// &
               'axial_force > -P'
   end subroutine check_compression

   !> The structure whose K is positive definite exactly when that of `structure` is
   !! positive semi-definite with its rigid-body motions only (module documentation): the
   !! structure itself without rigid-body motion, or with its left end's deflection held
   !! when a translation is the only one; stat = stat_failure when a rotation is free.
   pure subroutine stable_part(structure, length, held, stat)
      type(beam_structure), intent(in) :: structure
      real(dp), intent(in) :: length
      type(beam_structure), intent(out) :: held
      integer, intent(out) :: stat
      type(beam_structure) :: bent, pulled
      integer :: rigid
      stat = 0
      held = structure
      bent = structure
      bent%axial_force = 0
      pulled = structure
      pulled%axial_force = 1   ! a tension removes the rotation, and only it
      rigid = bent%rigid_motions(length)
      if (rigid == 0) return
      if (pulled%rigid_motions(length) < rigid) then
         stat = stat_failure
         return
      end if
      ! a translation alone: no deflection is held, so the left end is free or sliding
      if (held%boundary%left == end_free) held%boundary%left = end_pinned
      if (held%boundary%left == end_sliding) held%boundary%left = end_clamped
   end subroutine stable_part

   !> The buckling load P (N; per unit rho S with k2) of the structure under compression
   !! (its axial force ignored; no rigid-body motion), on `buckling_elements` Hermite
   !! elements: 1/mu, mu the largest eigenvalue of K_g v = mu K_b v; huge when no
   !! compression buckles it. stat /= 0 with errmsg when the model or dsbgvx fails.
   subroutine buckling_load(structure, length, rho_s, ei, load, stat, errmsg)
      type(beam_structure), intent(in) :: structure
      real(dp), intent(in) :: length, rho_s, ei
      real(dp), intent(out) :: load
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(beam_structure) :: bent, pulled
      type(beam_model) :: bending, tensioned
      type(symmetric_band) :: geometric
      real(dp), allocatable :: mu(:), work(:)
      integer, allocatable :: iwork(:), ifail(:)
      real(dp) :: scale, q(1, 1), z(1, 1)
      integer :: n, found
      load = huge(1.0_dp)
      bent = structure
      bent%axial_force = 0
      call build_model('hermite', buckling_elements, length, rho_s, ei, bending, stat, errmsg, structure=bent)
      if (stat /= 0) return
      ! K_g scaled to the bending's EI/L^2, as the difference of two models: its rounding,
      ! eps EI N^2/L^2 against EI/L^2, stays near eps N^2
      scale = maxval(bending%element_ei)/length**2
      pulled = bent
      pulled%axial_force = scale
      call build_model('hermite', buckling_elements, length, rho_s, ei, tensioned, stat, errmsg, structure=pulled)
      if (stat /= 0) return
      geometric = band_combination(1.0_dp, tensioned%stiffness, -1.0_dp, bending%stiffness)
      n = bending%unknowns
      allocate (mu(n), work(7*n), iwork(5*n), ifail(n))
      call dsbgvx('N', 'I', 'L', n, geometric%kd, bending%stiffness%kd, geometric%lower, geometric%kd + 1, &
                  bending%stiffness%lower, bending%stiffness%kd + 1, q, 1, 0.0_dp, 0.0_dp, n, n, &
                  2*dlamch('S'), found, mu, z, 1, work, iwork, ifail, stat)
      if (stat /= 0 .or. found /= 1) then
         stat = stat_failure
         errmsg = 'the buckling load: the eigenvalue solver dsbgvx failed'
         return
      end if
      errmsg = ''
      if (mu(1) > 0) load = scale/mu(1)
   end subroutine buckling_load
end module vibrobeam_buckling
