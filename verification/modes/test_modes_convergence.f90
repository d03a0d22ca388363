!> Verification: natural frequencies of a cantilever (k2 = 1, L = 1) from the Hermite model
!! against the closed form omega_n = (beta_n L)^2 sqrt(k2)/L^2 with the beta_n L of theory §7
!! (quoted to 20 digits from scripts/cantilever_roots.py, so the reference is exact to the
!! rounding of a double, ~1e-16 relative; with the 11 digits quoted before, its error was
!! up to 1.3e-11 relative, 2.5 % of mode 1's error at N = 64).
!! Acceptance (issue 2): relative error of mode 1 below 1e-7 at N = 32; observed order of
!! convergence between 3.7 and 4.3 for modes 1-4, fitted by least squares on log(error)
!! against log(h) over the asymptotic range N >= 8 (at N = 4 mode 4 has less than one
!! element per half wave) and where the error exceeds 1e-9 (below that the round-off of the
!! computed frequencies, ~1e-13 relative, starts to bend the fit). Prints the table that
!! README quotes.
program test_modes_convergence
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_test_support, only: test_counter, fitted_order
   implicit none
   type(test_counter) :: t
   integer, parameter :: meshes(5) = [4, 8, 16, 32, 64], modes = 6
   real(dp), parameter :: beta_l(modes) = [1.8751040687119611664_dp, 4.6940911329741745764_dp, 7.8547574382376125649_dp, &
                                           10.995540734875466991_dp, 14.137168391046470581_dp, 17.278759532088236334_dp]
   real(dp), parameter :: floor_error = 1e-9_dp
   type(beam_model) :: model
   real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
   real(dp) :: error(size(meshes), modes), order
   integer :: k, n, stat
   character(len=200) :: errmsg
   character(len=48) :: label
   do k = 1, size(meshes)
      call build_model('hermite', meshes(k), 1.0_dp, 1.0_dp, 1.0_dp, model, stat, errmsg)
      call compute_modes(model, modes, omega, shapes, vectors, stat, errmsg)
      call t%check_true('compute_modes', stat == 0, errmsg)
      if (stat /= 0) call t%finish('test_modes_convergence')
      error(k, :) = abs(omega - beta_l**2)/beta_l**2
   end do
   write (output_unit, '(a)') 'relative error of omega_n (Hermite cubic, k2 = 1, L = 1)'
   write (output_unit, '(a6,6a11)') 'N', 'mode 1', 'mode 2', 'mode 3', 'mode 4', 'mode 5', 'mode 6'
   do k = 1, size(meshes)
      write (output_unit, '(i6,6es11.2)') meshes(k), error(k, :)
   end do
   call t%check_close('mode 1 relative error at N = 32', error(4, 1), 0.0_dp, 1.0_dp, 1e-7_dp)
   write (output_unit, '(a)', advance='no') 'observed order (least squares, N >= 8, error > 1e-9):'
   do n = 1, 4
      order = fitted_order(meshes, error(:, n), error(:, n) > floor_error .and. meshes >= 8)
      write (output_unit, '(f8.3)', advance='no') order
      write (label, '(a,i0)') 'convergence order of mode ', n
      call t%check_true(trim(label), order >= 3.7_dp .and. order <= 4.3_dp, 'outside [3.7, 4.3]')
   end do
   write (output_unit, *)
   call t%finish('test_modes_convergence')
end program test_modes_convergence
