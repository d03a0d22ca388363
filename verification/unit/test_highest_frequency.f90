!> omega_max of the discrete model (vibrobeam_highest_frequency: bisection on the
!! definiteness of sigma M - K, decided by LAPACK dpbtrf) against independent references:
!! - one Hermite element: the 2 x 2 pencil solved in closed form (the quadratic
!!   det(K - lambda M) = 0 with the element matrices written here; omega_max = 34.8069
!!   sqrt(EI/(rho S L^4)), the classical one-element cantilever value);
!! - N = 1..16, both bases: LAPACK dsbgvx (band reduction, range 'I', the largest
!!   eigenvalue only) and dsygv on the dense matrices built here from the bands;
!! - N = 1e5 Hermite elements (J = 2e5): omega_max h^2/sqrt(k2) equals its value at
!!   N = 1e4 to 1e-6 (the top of the discrete spectrum tends to the maximum of the
!!   dispersion relation of the uniform mesh, with a relative shift O((pi/N)^2) = 1e-7 at
!!   N = 1e4), which also shows that O(J) memory and time suffice.
!! Tolerance against the solvers: the bisection stops at 2 eps; dpbtrf decides
!! definiteness with a backward error of about (kd + 1) eps per entry, amplified by the
!! conditioning of the diagonally scaled mass matrix (printed: below 30 for both bases)
!! and by J for the accumulation: 8 (kd + 1) J eps cond_scaled(M), at most 5e-11 here.
program test_highest_frequency
   use vibrobeam_kinds, only: dp
   use vibrobeam_lapack, only: dsbgvx, dsyev, dsygv
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_band, only: band_entry
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   type(beam_model) :: model
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   real(dp) :: omega, reference, a, b, c, tolerance, scaled_condition, coarse, fine
   integer :: n, basis, stat
   character(len=128) :: errmsg, label

   ! one Hermite element, EI = rho S = L = 1: K = [12 -6; -6 4], M = [156 -22; -22 4]/420
   a = (156*4 - 22**2)/420.0_dp**2
   b = (12*4 + 4*156 - 2*6*22)/420.0_dp
   c = 12*4 - 6**2
   reference = sqrt((b + sqrt(b**2 - 4*a*c))/(2*a))
   call build_model('hermite', 1, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
   call highest_frequency(model, omega, stat, errmsg)
   call t%check_true('one element: bisection succeeds', stat == 0, trim(errmsg))
   call t%check_close('one element: omega_max against the 2 x 2 closed form', omega, reference, 1e-13_dp)
   call t%check_close('one element: the classical value 34.8069', omega, 34.8069_dp, 1e-5_dp)

   do basis = 1, 2
      do n = 1, 16
         call build_model(bases(basis), n, 1.7_dp, 3.0_dp, 5.0_dp, model, stat, errmsg)
         call highest_frequency(model, omega, stat, errmsg)
         scaled_condition = mass_condition(model)
         tolerance = 2*epsilon(1.0_dp) + 8*(model%mass%kd + 1)*model%unknowns*epsilon(1.0_dp)*scaled_condition
         write (label, '(a,a,i0)') trim(bases(basis)), ' N = ', n
         call t%check_close(trim(label)//': omega_max against dsbgvx', omega, band_reference(model), tolerance)
         call t%check_close(trim(label)//': omega_max against dense dsygv', omega, dense_reference(model), tolerance)
         if (n == 16) write (*, '(a,es10.3,a,es10.3)') trim(label)//': condition of the scaled mass matrix ', &
            scaled_condition, ', tolerance ', tolerance
      end do
   end do

   ! O(J): N = 1e4 and 1e5 Hermite elements, omega_max h^2/sqrt(k2) (k2 = 1, L = 1)
   call build_model('hermite', 10000, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
   call highest_frequency(model, omega, stat, errmsg)
   coarse = omega*model%h**2
   call build_model('hermite', 100000, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
   call highest_frequency(model, omega, stat, errmsg)
   fine = omega*model%h**2
   write (*, '(a,f14.9,a,f14.9)') 'omega_max h^2: N = 1e4 ', coarse, ', N = 1e5 ', fine
   call t%check_close('N = 1e5: omega_max h^2 equals its value at N = 1e4', fine, coarse, 1e-6_dp)
   call t%finish('test_highest_frequency')

contains

   !> The largest eigenvalue of (K, M) by dsbgvx, as omega.
   function band_reference(model) result(omega)
      type(beam_model), intent(in) :: model
      real(dp) :: omega
      real(dp), allocatable :: stiffness(:,:), mass(:,:), w(:), work(:), q(:,:), z(:,:)
      integer, allocatable :: iwork(:), ifail(:)
      integer :: j, found, info
      j = model%unknowns
      allocate (stiffness, source=model%stiffness%lower)
      allocate (mass, source=model%mass%lower)
      allocate (w(j), work(7*j), iwork(5*j), ifail(j), q(1, 1), z(1, 1))
      call dsbgvx('N', 'I', 'L', j, model%stiffness%kd, model%mass%kd, stiffness, model%stiffness%kd + 1, mass, &
                  model%mass%kd + 1, q, 1, 0.0_dp, 0.0_dp, j, j, 0.0_dp, found, w, z, 1, work, iwork, ifail, info)
      omega = sqrt(w(1))
   end function band_reference

   !> The largest eigenvalue of (K, M) by dsygv on dense copies, as omega.
   function dense_reference(model) result(omega)
      type(beam_model), intent(in) :: model
      real(dp) :: omega
      real(dp), allocatable :: stiffness(:,:), mass(:,:), w(:), work(:)
      integer :: j, info
      call dense(model, stiffness, mass)
      j = model%unknowns
      allocate (w(j), work(64*j))
      call dsygv(1, 'N', 'L', j, stiffness, j, mass, j, w, work, size(work), info)
      omega = sqrt(w(j))
   end function dense_reference

   !> Condition number of D^-1/2 M D^-1/2, D = diag(M) (dense dsyev).
   function mass_condition(model) result(condition)
      type(beam_model), intent(in) :: model
      real(dp) :: condition
      real(dp), allocatable :: stiffness(:,:), mass(:,:), w(:), work(:)
      integer :: i, k, j, info
      call dense(model, stiffness, mass)
      j = model%unknowns
      do k = 1, j
         do i = 1, j
            mass(i, k) = mass(i, k)/sqrt(band_entry(model%mass, i, i)*band_entry(model%mass, k, k))
         end do
      end do
      allocate (w(j), work(64*j))
      call dsyev('N', 'L', j, mass, j, w, work, size(work), info)
      condition = w(j)/w(1)
   end function mass_condition

   subroutine dense(model, stiffness, mass)
      type(beam_model), intent(in) :: model
      real(dp), allocatable, intent(out) :: stiffness(:,:), mass(:,:)
      integer :: i, k, j
      j = model%unknowns
      allocate (stiffness(j, j), mass(j, j))
      do k = 1, j
         do i = 1, j
            stiffness(i, k) = band_entry(model%stiffness, i, k)
            mass(i, k) = band_entry(model%mass, i, k)
         end do
      end do
   end subroutine dense
end program test_highest_frequency
