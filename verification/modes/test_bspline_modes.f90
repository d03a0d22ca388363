!> Verification (issue 4): natural frequencies with cubic B-splines (k2 = 1, L = 1) against
!! the closed form of theory §7.
!! 1. Convergence: for a 4th-order problem and splines of degree p = 3, the eigenvalue
!!    error is O(h^(2(p-1))) = O(h^4) (Strang & Fix, An Analysis of the Finite Element
!!    Method, ch. 6); observed order of modes 1-4 fitted over N >= 16 where the error
!!    exceeds 1e-9: must lie in [3.7, 4.5].
!! 2. Per unknown: at equal numbers of unknowns J (Hermite N = J/2, B-splines N = J - 1),
!!    B-splines are more accurate than Hermite elements for each of the first 6 modes,
!!    for J = 16, 32, 64 (the reference roots are quoted to 20 digits, scripts/cantilever_roots.py).
!! Prints both tables (README, "Choosing a discretization").
program test_bspline_modes
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_test_support, only: test_counter, fitted_order
   implicit none
   type(test_counter) :: t
   integer, parameter :: modes = 6, meshes(6) = [4, 8, 16, 32, 64, 128], unknowns(3) = [16, 32, 64]
   real(dp), parameter :: beta_l(modes) = [1.8751040687119611664_dp, 4.6940911329741745764_dp, 7.8547574382376125649_dp, &
                                           10.995540734875466991_dp, 14.137168391046470581_dp, 17.278759532088236334_dp]
   real(dp) :: error(size(meshes), modes), hermite(modes), spline(modes), order
   integer :: k, n
   character(len=64) :: label
   write (output_unit, '(a)') 'relative error of omega_n, cubic B-splines (k2 = 1, L = 1)'
   write (output_unit, '(a6,a6,6a11)') 'N', 'J', 'mode 1', 'mode 2', 'mode 3', 'mode 4', 'mode 5', 'mode 6'
   do k = 1, size(meshes)
      error(k, :) = relative_errors('bspline', meshes(k))
      write (output_unit, '(2i6,6es11.2)') meshes(k), meshes(k) + 1, error(k, :)
   end do
   write (output_unit, '(a)', advance='no') 'observed order (least squares, N >= 16, error > 1e-9):'
   do n = 1, 4
      order = fitted_order(meshes, error(:, n), error(:, n) > 1e-9_dp .and. meshes >= 16)
      write (output_unit, '(f8.3)', advance='no') order
      write (label, '(a,i0)') 'B-spline convergence order of mode ', n
      call t%check_true(trim(label), order >= 3.7_dp .and. order <= 4.5_dp, 'outside [3.7, 4.5]')
   end do
   write (output_unit, *)
   write (output_unit, '(a)') 'equal number of unknowns J: relative error, Hermite / B-spline'
   write (output_unit, '(a4,6a22)') 'J', 'mode 1', 'mode 2', 'mode 3', 'mode 4', 'mode 5', 'mode 6'
   do k = 1, size(unknowns)
      hermite = relative_errors('hermite', unknowns(k)/2)
      spline = relative_errors('bspline', unknowns(k) - 1)
      write (output_unit, '(i4,6(es11.2,es11.2))') unknowns(k), (hermite(n), spline(n), n=1, modes)
      do n = 1, modes
         if (hermite(n) < 1e-11_dp) cycle
         write (label, '(a,i0,a,i0)') 'B-splines beat Hermite per unknown, J = ', unknowns(k), ', mode ', n
         call t%check_true(trim(label), spline(n) < hermite(n))
      end do
   end do
   call t%finish('test_bspline_modes')
contains
   function relative_errors(basis, elements) result(err)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp) :: err(modes)
      type(beam_model) :: model
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      integer :: stat
      character(len=200) :: errmsg
      call build_model(basis, elements, 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      call compute_modes(model, min(modes, model%unknowns), omega, shapes, vectors, stat, errmsg)
      if (stat /= 0) error stop 'compute_modes failed'
      err = huge(1.0_dp)
      err(1:size(omega)) = abs(omega - beta_l(1:size(omega))**2)/beta_l(1:size(omega))**2
   end function relative_errors

end program test_bspline_modes
