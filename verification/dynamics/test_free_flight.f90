!> Verification (issue 3, "Free flight"): with no obstacle touched, the velocity-based
!! stepper (theta = 1/2) against
!! (1) the exact solution of the semi-discrete system M U'' + K U = 0, by modal
!!     superposition with the discrete eigenpairs (LAPACK dsbgvx through compute_modes):
!!     the error at t = 2 must decrease like dt^2: order between dt = 1/400 and 1/3200 in
!!     [1.9, 2.1] (coarser steps are pre-asymptotic for mode 2: omega_2 dt > 0.05);
!! (2) the closed-form continuum solution u = v0 phi_1(x) sin(omega_1 t)/omega_1 for
!!     mode-1 velocity data (theory §7), at N = 32 and a small dt, within the spatial error
!!     (relative error of omega_1 at N = 32 is 8e-9, so 1e-6 relative at the tip).
program test_free_flight
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_band, only: band_matvec
   use vibrobeam_cantilever_exact, only: cantilever_frequency, cantilever_mode_shape
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   character(len=512) :: path
   real(dp), parameter :: steps_per_unit(4) = [400.0_dp, 800.0_dp, 1600.0_dp, 3200.0_dp]
   real(dp) :: error(size(steps_per_unit)), order, exact_tip, omega1, tip
   real(dp), allocatable :: u_exact(:), u(:)
   integer :: k
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   allocate (u_exact, source=modal_solution(prepared, scene%time%t_end))
   write (output_unit, '(a)') '    dt         max|U - U_exact|/max|U_exact| at t = 2'
   do k = 1, size(steps_per_unit)
      scene%time%dt = 1/steps_per_unit(k)
      u = run(scene, prepared)
      error(k) = maxval(abs(u - u_exact))/maxval(abs(u_exact))
      write (output_unit, '(es10.3, es14.4)') scene%time%dt, error(k)
   end do
   order = log(error(1)/error(size(error)))/log(steps_per_unit(size(error))/steps_per_unit(1))
   write (output_unit, '(a,f7.4)') 'observed order in dt: ', order
   call t%check_true('order of the time error in [1.9, 2.1]', order >= 1.9_dp .and. order <= 2.1_dp)
   call t%check_close('error at dt = 1/3200 (semi-discrete exact)', error(size(error)), 0.0_dp, 1.0_dp, 2e-6_dp)

   ! (2) continuum closed form, mode-1 velocity data only, N = 32
   scene%mesh%elements = 32
   scene%initial%displacement = 'zero'
   scene%time%t_end = 1.0_dp
   scene%time%dt = 1e-4_dp
   call prepare_test_scene(scene, prepared)
   u = run(scene, prepared)
   tip = u(prepared%model%unknowns - 1)
   omega1 = cantilever_frequency(1, scene%beam%length, scene%beam%k2)
   exact_tip = scene%initial%velocity_amplitude*sin(omega1*scene%time%t_end)/omega1
   write (output_unit, '(a,es22.14,a,es22.14)') 'tip at t = 1: vibrobeam ', tip, ', closed form ', exact_tip
   ! tolerance: theta-method phase error (omega dt)^2/12 omega t ~ 1.3e-7 plus spatial 1e-6
   call t%check_close('tip displacement vs continuum closed form', tip, exact_tip, 2e-6_dp)
   call t%check_close('tip slope vs continuum closed form', u(prepared%model%unknowns), &
                      scene%initial%velocity_amplitude*cantilever_mode_shape(1, scene%beam%length, scene%beam%length, 1)* &
                      sin(omega1*scene%time%t_end)/omega1, 2e-6_dp)
   call t%finish('test_free_flight')

contains

   function run(scene, prepared) result(u)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      real(dp), allocatable :: u(:)
      class(time_stepper), allocatable :: stepper
      integer :: n, stat
      character(len=512) :: errmsg
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      do n = 1, nint(scene%time%t_end/scene%time%dt)
         call stepper%step(stat, errmsg)
         if (stat /= 0) error stop 'step failed'
         if (stepper%report%active_count > 0) error stop 'an obstacle was touched in free flight'
      end do
      u = stepper%u
   end function run

   !> U(t) = sum_k phi_k (a_k cos(omega_k t) + b_k/omega_k sin(omega_k t)), with
   !! M-normalized eigenvectors phi_k, a = Phi^T M U0, b = Phi^T M V0.
   function modal_solution(prepared, time) result(u)
      type(run_problem), intent(in) :: prepared
      real(dp), intent(in) :: time
      real(dp), allocatable :: u(:), omega(:), shapes(:,:), vectors(:,:)
      real(dp) :: m_phi(prepared%model%unknowns), norm
      integer :: k, stat
      character(len=256) :: errmsg
      call compute_modes(prepared%model, prepared%model%unknowns, omega, shapes, vectors, stat, errmsg)
      if (stat /= 0) error stop 'compute_modes failed'
      allocate (u(prepared%model%unknowns), source=0.0_dp)
      do k = 1, size(omega)
         call band_matvec(prepared%model%mass, vectors(:, k), m_phi)
         norm = dot_product(vectors(:, k), m_phi)
         u = u + vectors(:, k)*(dot_product(m_phi, prepared%u0)*cos(omega(k)*time) + &
                                dot_product(m_phi, prepared%v0)*sin(omega(k)*time)/omega(k))/norm
      end do
   end function modal_solution
end program test_free_flight
