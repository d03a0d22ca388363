!> (K + s M)^-1 applied to a vector, for the shift-invert Lanczos of the natural modes and
!! the constraint modes of the reduced model (docs/method.md, "Natural modes" and
!! "Supports").
!!
!! For the uniform clamped-free beam (`flexibility_applies`) and s = 0, K^-1 is the double
!! integration of `vibrobeam_flexibility`: accurate at any N. Every other structure (other
!! end supports, end springs, intermediate supports, sections, an axial force) has no such
!! integration here, and K + s M is factored by the band Cholesky of `vibrobeam_band`: its
!! solves err by about eps cond(K + s M), cond growing like N^4, which the callers account
!! for (the Rayleigh quotient of each computed mode, docs/method.md). A structure with
!! rigid-body motions (K singular) needs s > 0: K + s M is then positive definite and has
!! the same eigenvectors, with eigenvalues lambda + s.
module vibrobeam_stiffness_inverse
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_numerical_failure
   use vibrobeam_band, only: band_cholesky, band_combination, band_factor, band_solve
   use vibrobeam_model, only: beam_model, flexibility_applies
   use vibrobeam_flexibility, only: cantilever_flexibility
   implicit none
   private
   public :: stiffness_inverse

   type :: stiffness_inverse
      logical :: integrate = .false.             !! by double integration (else the band Cholesky)
      real(dp) :: shift = 0                      !! s (rad^2/s^2)
      type(cantilever_flexibility) :: flexibility
      type(band_cholesky) :: factor              !! of K + s M
   contains
      procedure :: setup
      procedure :: solve
   end type stiffness_inverse

contains

   !> Prepare (K + shift M)^-1 for the model (shift >= 0; default 0). stat =
   !! stat_numerical_failure with a message when K + s M cannot be factored: a structure
   !! with rigid-body motion and s = 0, an axial compression beyond buckling, or a mesh so
   !! fine that the band Cholesky meets a non-positive pivot in round-off.
   subroutine setup(self, model, stat, errmsg, shift)
      class(stiffness_inverse), intent(out) :: self
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), intent(in), optional :: shift
      character(len=256) :: detail
      if (present(shift)) self%shift = shift
      self%integrate = flexibility_applies(model) .and. .not. self%shift > 0
      if (self%integrate) then
         call self%flexibility%setup(model, stat, errmsg)
         return
      end if
      call band_factor(band_combination(1.0_dp, model%stiffness, self%shift, model%mass), self%factor, stat, detail)
      errmsg = ''
      if (stat /= 0) then
         stat = stat_numerical_failure
         write (errmsg, '(a,es10.3,a)') 'the stiffness K + s M (s = ', self%shift, ') of the '// &
            model%boundary%name()//' beam is not positive definite: '//trim(detail)// &
            ' (a rigid-body motion, an axial compression beyond buckling, or round-off at this N)'
      end if
   end subroutine setup

   !> x := (K + s M)^-1 x.
   subroutine solve(self, x)
      class(stiffness_inverse), intent(inout) :: self
      real(dp), intent(inout) :: x(:)   !! (J)
      if (self%integrate) then
         call self%flexibility%solve(x)
      else
         call band_solve(self%factor, x)
      end if
   end subroutine solve
end module vibrobeam_stiffness_inverse
