!> Damping per mode (issue 18, item 6; &beam modal_damping, modal_damping_ratios): the free
!! decay of each of the first K modes at its ratio, with Rayleigh damping beside it, both
!! schemes, against each scheme's own exact per-step recurrence written here.
!!
!! The scene: a normalized cantilever (L = 1, k2 = 1, N = 16, Hermite and B-splines),
!! Rayleigh a = 0.1 1/s, b = 1e-4 s, modal_damping = 0.02 for every resolved mode, and
!! modal_damping_ratios(1) = 0.05, (3) = 0.1. Released at rest in its discrete mode k
!! (M-normalized, `compute_modes`), U stays q_n phi_k (C, M and K are all diagonal in the
!! modes: C phi_k = (a + b omega_k^2 + c_k) M phi_k for k <= K, (a + b omega_k^2) M phi_k
!! beyond), and q_n follows the scheme's scalar recurrence with c_R = a + b omega^2 implicit
!! and c_m = 2 zeta omega - c_R explicit (theory §3, §4; docs/method.md, "Damping per mode"):
!! - velocity scheme (theta = 1/2): (1 + theta^2 dt^2 omega^2 + theta dt c_R) (p' - p) =
!!   dt (-omega^2 (q + theta dt p) - (c_R + c_m) p), q' = q + dt (theta p' + (1 - theta) p);
!! - position scheme: (q' - 2q + q-)/dt^2 + c_R (q' - q-)/(2 dt) + omega^2 (theta q' +
!!   (1 - 2 theta) q + theta q-) + c_m (q - q-)/dt = 0, q- of the start = q (1 - (omega dt)^2/2).
!! The reference iterates these scalar recurrences (independent of the library's vector
!! code); the check: max |U_n - q_n phi_k| over the run against 4 (eigen residual + n eps
!! cond(W)) of q_0 (test_support_dynamics.f90). Also printed: the effective ratio of each
!! mode from the recurrence's per-step factor |lambda| = exp(-zeta_eff omega_eff dt),
!! omega_eff = arg(lambda)/dt, against zeta_k (first order in omega dt, the explicit part),
!! and a mode above K decaying by the Rayleigh part alone (c_m = 0) is checked the same way.
program test_modal_damping
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_band, only: band_matvec
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_test_support, only: test_counter, prepare_test_scene
   implicit none
   type(test_counter) :: t
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   character(len=8), parameter :: schemes(2) = [character(len=8) :: 'velocity', 'position']
   real(dp), parameter :: a = 0.1_dp, b = 1e-4_dp, every = 0.02_dp
   integer :: i, j
   do i = 1, 2
      do j = 1, 2
         call decay(bases(i), schemes(j))
      end do
   end do
   call t%finish('test_modal_damping')

contains

   subroutine decay(basis, scheme)
      character(len=*), intent(in) :: basis, scheme
      type(scene_type) :: scene
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:), mass_phi(:), residual(:)
      real(dp) :: zeta, c_r, c_m, q, q_old, p, q_new, p_new, worst, omega_max, condition, residual_size, tolerance
      real(dp) :: modulus, angle, zeta_eff
      integer :: k, n, stat, kept
      integer, parameter :: steps = 600
      character(len=512) :: errmsg
      character(len=:), allocatable :: label
      scene%beam%length = 1
      scene%beam%k2 = 1
      scene%beam%rayleigh_mass = a
      scene%beam%rayleigh_stiffness = b
      scene%beam%modal_damping = every
      scene%beam%modal_damping_ratios(1) = 0.05_dp
      scene%beam%modal_damping_ratios(3) = 0.1_dp
      scene%mesh%basis = basis
      scene%mesh%elements = 16
      scene%time%scheme = scheme
      scene%time%dt = 2e-3_dp
      scene%time%t_end = steps*scene%time%dt
      allocate (scene%obstacles(0))
      call prepare_test_scene(scene, prepared)
      kept = size(prepared%modal_rates)
      call compute_modes(prepared%model, kept + 1, omega, shapes, vectors, stat, errmsg)
      call t%check_true(basis//' '//scheme//': modes', stat == 0, trim(errmsg))
      if (stat /= 0) return
      call highest_frequency(prepared%model, omega_max, stat, errmsg)
      allocate (mass_phi(prepared%model%unknowns), residual(prepared%model%unknowns))
      write (*, '(a,i0,a,es10.3,a)') basis//' '//scheme//': ', kept, ' modes with a ratio of their own (omega_K dt = ', &
         omega(kept)*scene%time%dt, ')'
      do k = 1, kept + 1
         label = basis//' '//scheme//' mode '//integer_text(k)
         ! M-normalized mode, its eigen residual
         call band_matvec(prepared%model%mass, vectors(:, k), mass_phi)
         vectors(:, k) = vectors(:, k)/sqrt(dot_product(vectors(:, k), mass_phi))
         call band_matvec(prepared%model%stiffness, vectors(:, k), residual)
         call band_matvec(prepared%model%mass, vectors(:, k), mass_phi)
         residual_size = maxval(abs(residual - omega(k)**2*mass_phi))/maxval(abs(residual))
         zeta = every
         if (k == 1) zeta = 0.05_dp
         if (k == 3) zeta = 0.1_dp
         c_r = a + b*omega(k)**2
         c_m = 0
         if (k <= kept) c_m = 2*zeta*omega(k) - c_r
         prepared%start%u = vectors(:, k)
         prepared%start%v = 0
         call new_stepper(scene, prepared, stepper, stat, errmsg)
         call t%check_true(label//': stepper', stat == 0, trim(errmsg))
         if (stat /= 0) return
         q = 1
         p = 0
         q_old = 1 - (omega(k)*scene%time%dt)**2/2
         worst = 0
         do n = 1, steps
            call stepper%step(stat, errmsg)
            if (stat /= 0) exit
            associate (dt => scene%time%dt, w => omega(k))
               if (scheme == 'velocity') then
                  p_new = p + dt*(-w**2*(q + 0.5_dp*dt*p) - (c_r + c_m)*p)/(1 + (0.5_dp*dt*w)**2 + 0.5_dp*dt*c_r)
                  q = q + dt*(0.5_dp*p_new + 0.5_dp*p)
                  p = p_new
               else
                  ! (1/dt^2 + c_r/(2 dt) + w^2/2) q' = (2/dt^2) q - (1/dt^2 - c_r/(2 dt) + w^2/2) q-
                  !                                   - c_m (q - q-)/dt   (theta = 1/2)
                  q_new = (2*q/dt**2 - (1/dt**2 - c_r/(2*dt) + w**2/2)*q_old - c_m*(q - q_old)/dt)/ &
                          (1/dt**2 + c_r/(2*dt) + w**2/2)
                  q_old = q
                  q = q_new
               end if
            end associate
            worst = max(worst, maxval(abs(stepper%u - q*vectors(:, k))))
         end do
         call t%check_true(label//': steps', stat == 0, trim(errmsg))
         if (scheme == 'velocity') then
            condition = 1 + (0.5_dp*scene%time%dt*omega_max)**2
         else
            condition = (1 + 0.5_dp*(scene%time%dt*omega_max)**2)/sin(acos(1/(1 + (omega(k)*scene%time%dt)**2/2)))
         end if
         tolerance = 4*(residual_size + steps*epsilon(1.0_dp)*condition)*maxval(abs(vectors(:, k)))
         call per_step_factor(scheme, omega(k), scene%time%dt, c_r, c_m, modulus, angle)
         zeta_eff = -log(modulus)/angle
         write (*, '(a,a,f8.5,a,f8.5,a,es10.3,a,es10.3)') label, ': zeta ', merge(zeta, c_r/(2*omega(k)), k <= kept), &
            ', effective ', zeta_eff, ', largest deviation from the recurrence ', worst, ', tolerance ', tolerance
         call t%check_close(label//': U_n against the scheme''s recurrence', worst, 0.0_dp, 1.0_dp, tolerance)
      end do
   end subroutine decay

   !> |lambda| and arg(lambda) of the scheme's per-step factor for one mode (the complex
   !! root of the 2 x 2 recurrence).
   subroutine per_step_factor(scheme, w, dt, c_r, c_m, modulus, angle)
      character(len=*), intent(in) :: scheme
      real(dp), intent(in) :: w, dt, c_r, c_m
      real(dp), intent(out) :: modulus, angle
      real(dp) :: m(2, 2), d, tr, det, disc
      if (scheme == 'velocity') then
         ! (q, p) -> (q', p'): p' = p + dt(-w^2 q - (w^2 dt/2 + c_r + c_m) p)/d, q' = q + dt (p + p')/2
         d = 1 + (0.5_dp*dt*w)**2 + 0.5_dp*dt*c_r
         m(2, 1) = -dt*w**2/d
         m(2, 2) = 1 - dt*(0.5_dp*dt*w**2 + c_r + c_m)/d
         m(1, 1) = 1 + 0.5_dp*dt*m(2, 1)
         m(1, 2) = 0.5_dp*dt*(1 + m(2, 2))
      else
         ! (q, q-) -> (q', q)
         d = 1/dt**2 + c_r/(2*dt) + w**2/2
         m(1, 1) = (2/dt**2 - c_m/dt)/d
         m(1, 2) = (-(1/dt**2 - c_r/(2*dt) + w**2/2) + c_m/dt)/d
         m(2, 1) = 1
         m(2, 2) = 0
      end if
      tr = m(1, 1) + m(2, 2)
      det = m(1, 1)*m(2, 2) - m(1, 2)*m(2, 1)
      disc = det - tr**2/4
      modulus = sqrt(det)
      angle = atan2(sqrt(max(disc, 0.0_dp)), tr/2)
   end subroutine per_step_factor
end program test_modal_damping
