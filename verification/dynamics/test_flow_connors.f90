!> The fluid-elastic force of &flow against Connors' formula (docs/theory.md section 10):
!! the linear growth rate of mode 1 of a free tube changes sign at Connors' critical
!! velocity U_c = K f d sqrt(2 pi zeta m/(rho d^2)) within 1 %.
!!
!! The scene (flow_connors.nml, no obstacle) is stepped from mode 1's velocity at flow
!! velocities U = U_c (0.90, 0.95, 1.05, 1.10), U_c from the formula computed here: f
!! and the mode from the mesh's M and K by dense LAPACK (dsygv, not the library's modal
!! solver), zeta = a/(2 omega) + b omega/2 of the Rayleigh damping, m = rho S. The growth
!! rate sigma(U) is the slope of ln A(t), A^2 = q'^2 + omega^2 q^2 with q = phi^T M U the
!! modal coordinate, fitted by least squares over the last 3 s of 4 s (the first second
!! lets the other modes, excited by the continuum mode shape's interpolation, decay).
!! sigma is linear in U^2 (sigma = omega (zeta_f(U) - zeta), zeta_f proportional to U^2):
!! its zero, from the straight line through the four (U^2, sigma) by least squares, must
!! be U_c within 1 %; so must that of a tube in cross-flow over [0.4, 0.8] m only, whose
!! U_c is the formula's divided by sqrt(J), J the share of the mode's kinetic energy in
!! the span, computed here by Simpson's rule on 64 sub-intervals per element.
program test_flow_connors
   use vibrobeam_kinds, only: dp, pi, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_model, only: point_row
   use vibrobeam_band, only: band_to_dense
   use vibrobeam_lapack, only: dsygv
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   real(dp), parameter :: factors(4) = [0.90_dp, 0.95_dp, 1.05_dp, 1.10_dp]
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   character(len=512) :: path
   real(dp), allocatable :: mass(:, :), stiffness(:, :), phi(:), m_phi(:)
   real(dp) :: omega, zeta, critical, share
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call first_mode()
   zeta = scene%beam%rayleigh_mass/(2*omega) + scene%beam%rayleigh_stiffness*omega/2
   critical = scene%flow%connors_constant*(omega/(2*pi))*scene%flow%diameter* &
              sqrt(2*pi*zeta*scene%beam%rho_s()/(scene%flow%density*scene%flow%diameter**2))
   write (output_unit, '(a,f10.5,a,es11.4,a,f9.5,a)') 'mode 1: f = ', omega/(2*pi), ' Hz, zeta = ', zeta, &
      ', Connors U_c = ', critical, ' m/s'
   call check_threshold('whole span', critical)
   ! the span [0.4, 0.8] m: U_c / sqrt(J)
   scene%flow%x_from = 0.4_dp
   scene%flow%x_to = 0.8_dp
   share = span_share(0.4_dp, 0.8_dp)
   write (output_unit, '(a,f9.6)') 'span [0.4, 0.8] m: share of mode 1''s kinetic energy J = ', share
   call check_threshold('span [0.4, 0.8] m', critical/sqrt(share))
   call t%finish('test_flow_connors')

contains

   !> omega_1 and phi_1 (M-normalized) of the mesh's M, K by dense LAPACK.
   subroutine first_mode()
      real(dp), allocatable :: a(:, :), b(:, :), w(:), work(:)
      integer :: n, info
      mass = band_to_dense(prepared%model%mass)
      stiffness = band_to_dense(prepared%model%stiffness)
      n = size(mass, 1)
      allocate (a(n, n), b(n, n), w(n), work(64*n))   ! allocated first: gfortran 12 -Wmaybe-uninitialized
      a = stiffness
      b = mass
      call dsygv(1, 'V', 'L', n, a, n, b, n, w, work, size(work), info)
      if (info /= 0) error stop 'test_flow_connors: dsygv failed'
      omega = sqrt(w(1))
      phi = a(:, 1)          ! dsygv normalizes phi^T M phi = 1
      m_phi = matmul(mass, phi)
   end subroutine first_mode

   !> The zero of sigma(U) from runs at U = U_ref * factors against U_ref (within 1 %).
   subroutine check_threshold(name, reference)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: reference
      real(dp) :: u2(size(factors)), sigma(size(factors)), slope, intercept, zero
      integer :: k
      do k = 1, size(factors)
         scene%flow%velocity = reference*factors(k)
         u2(k) = scene%flow%velocity**2
         sigma(k) = growth_rate()
         write (output_unit, '(a,f9.5,a,es12.4,a)') '   U = ', scene%flow%velocity, ' m/s: growth rate ', sigma(k), ' 1/s'
      end do
      slope = (size(u2)*sum(u2*sigma) - sum(u2)*sum(sigma))/(size(u2)*sum(u2**2) - sum(u2)**2)
      intercept = (sum(sigma) - slope*sum(u2))/size(u2)
      zero = sqrt(-intercept/slope)
      write (output_unit, '(a,f9.5,a,f9.5,a,es10.3)') '   growth rate 0 at U = ', zero, ' m/s; the formula ', &
         reference, ' m/s; relative difference ', zero/reference - 1
      call t%check_close(name//': the growth rate changes sign at Connors'' velocity', zero, reference, 1e-2_dp)
      call t%check_true(name//': decaying below, growing above', all(sigma(1:2) < 0) .and. all(sigma(3:4) > 0))
   end subroutine check_threshold

   !> The slope of ln A over the last 3 s of a 4 s run from mode 1's velocity.
   real(dp) function growth_rate()
      class(time_stepper), allocatable :: stepper
      integer :: n, steps, stat, count
      character(len=512) :: errmsg
      real(dp) :: q, q_dot, ln_a, time, sum_t, sum_y, sum_ty, sum_tt
      call prepare_test_scene(scene, prepared)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) error stop 'test_flow_connors: no stepper'
      steps = nint(scene%time%t_end/scene%time%dt)
      sum_t = 0
      sum_y = 0
      sum_ty = 0
      sum_tt = 0
      count = 0
      do n = 1, steps
         call stepper%step(stat, errmsg)
         if (stat /= 0) error stop 'test_flow_connors: a step failed'
         time = stepper%t
         if (time < 1) cycle
         q = dot_product(m_phi, stepper%u)
         q_dot = dot_product(m_phi, stepper%v)
         ln_a = 0.5_dp*log(q_dot**2 + omega**2*q**2)
         sum_t = sum_t + time
         sum_y = sum_y + ln_a
         sum_ty = sum_ty + time*ln_a
         sum_tt = sum_tt + time**2
         count = count + 1
      end do
      growth_rate = (count*sum_ty - sum_t*sum_y)/(count*sum_tt - sum_t**2)
   end function growth_rate

   !> The share of rho S phi_1^2 in [a, b] (Simpson's rule, 64 sub-intervals per element).
   real(dp) function span_share(a, b)
      real(dp), intent(in) :: a, b
      real(dp) :: inside, whole
      inside = integral(a, b)
      whole = integral(0.0_dp, scene%beam%length)
      span_share = inside/whole
   end function span_share

   real(dp) function integral(a, b)
      real(dp), intent(in) :: a, b
      integer, parameter :: parts = 64
      real(dp) :: h, x, weights(4), value
      integer :: e, k, j, dofs(4)
      integral = 0
      do e = 1, prepared%model%elements
         if (prepared%model%x(e + 1) <= a .or. prepared%model%x(e) >= b) cycle
         h = (prepared%model%x(e + 1) - prepared%model%x(e))/parts
         do k = 0, parts
            x = prepared%model%x(e) + k*h
            x = min(max(x, prepared%model%x(e) + 1e-12_dp*h), prepared%model%x(e + 1) - 1e-12_dp*h)
            call point_row(prepared%model, x, dofs, weights)
            value = 0
            do j = 1, 4
               if (dofs(j) /= 0) value = value + weights(j)*phi(dofs(j))
            end do
            integral = integral + h/3*merge(1, merge(4, 2, mod(k, 2) == 1), k == 0 .or. k == parts)* &
                       scene%beam%rho_s()*value**2
         end do
      end do
   end function integral
end program test_flow_connors
