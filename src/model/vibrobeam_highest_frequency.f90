!> The highest natural frequency of the discrete beam, omega_max = sqrt(lambda_max) of
!! K phi = lambda M phi (theory §2), in O(J) memory and O(J) time per step of a bisection.
!!
!! LAPACK's band eigensolvers (dsbgvx with jobz = 'N', range = 'I') need O(J) memory but
!! O(J^2) time (the reduction of the band pencil to tridiagonal form): 15 s at N = 16000
!! Hermite elements, about ten minutes at N = 1e5. Instead we use that sigma M - K is
!! positive definite exactly when sigma > lambda_max (M is positive definite), and ask
!! LAPACK's band Cholesky factorization dpbtrf which is the case: a bisection on sigma
!! with one O(J kd^2) factorization per step. The decision is that of a backward stable
!! factorization: wrong only when sigma lies within a few eps of lambda_max, relative to
!! the scale of the diagonally scaled pencil, so omega_max comes out to about 1e-13
!! relative; verification/unit/test_highest_frequency.f90 compares it with dsbgvx and a
!! dense eigensolver.
module vibrobeam_highest_frequency
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp
   use vibrobeam_band, only: band_cholesky, band_combination, band_factor
   use vibrobeam_model, only: beam_model
   implicit none
   private
   public :: highest_frequency

contains

   !> omega_max (rad/s) of the model's pencil (K, M). stat /= 0 only if no bracket is
   !! found (not expected for a valid model).
   subroutine highest_frequency(model, omega_max, stat, errmsg)
      type(beam_model), intent(in) :: model
      real(dp), intent(out) :: omega_max
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: low, high, middle
      integer :: iteration
      integer, parameter :: max_iterations = 400
      omega_max = 0
      stat = 0
      errmsg = ''
      ! a bracket [low, high] with sigma M - K indefinite at low and definite at high,
      ! from the scale k2/h^4 of the element eigenvalues, by halving and doubling
      high = model%ei/(model%rho_s*model%h**4)
      low = high
      do iteration = 1, max_iterations
         if (above_spectrum(high)) exit
         low = high
         high = 2*high
      end do
      do iteration = 1, max_iterations
         if (.not. above_spectrum(low)) exit
         high = low
         low = low/2
      end do
      if (above_spectrum(low) .or. .not. above_spectrum(high)) then
         stat = stat_failure
         errmsg = 'highest frequency: no bracket of the largest eigenvalue found'
         return
      end if
      ! bisection to the resolution of double precision
      do iteration = 1, max_iterations
         middle = low + (high - low)/2
         if (middle <= low .or. middle >= high) exit
         if (high - low <= 2*epsilon(high)*high) exit
         if (above_spectrum(middle)) then
            high = middle
         else
            low = middle
         end if
      end do
      omega_max = sqrt(high)
   contains
      !> Is sigma M - K positive definite, i.e. sigma > lambda_max?
      logical function above_spectrum(sigma)
         real(dp), intent(in) :: sigma
         type(band_cholesky) :: factor
         integer :: info
         character(len=128) :: message
         call band_factor(band_combination(sigma, model%mass, -1.0_dp, model%stiffness), factor, info, message)
         above_spectrum = info == 0
      end function above_spectrum
   end subroutine highest_frequency
end module vibrobeam_highest_frequency
