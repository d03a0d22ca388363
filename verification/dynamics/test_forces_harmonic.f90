!> Verification of &forces with harmonic and table signals (docs/theory.md section 9):
!! (1) the scene forces_harmonic.nml (a point force and a segment load of &forces, the
!!     support's acceleration, a constant tip force and the point force of &load) in its
!!     steady state against the superposition of harmonic responses, computed here with
!!     load vectors integrated independently (Simpson's rule on each element's part of the
!!     segment, exact for a uniform load on cubics; a point force's is phi_j(x) itself,
!!     `point_load_vector`) and dense complex solves
!!     (`vibrobeam_linear_response`):
!!     - at the scheme's own discrete frequencies s(omega) (theta-method): the same
!!       numbers up to round-off. The transient is below exp(-2 * 25) of the response; the
!!       round-off of a step is at most about eps kappa(W) of the response, and the
!!       damping forgets it within 1/(2 dt) steps: tolerance 20 eps kappa(W)/(2 dt)
!!       (kappa(W) computed here);
!!     - at s = i omega (the semi-discrete system): within the theta-method's frequency
!!       error (omega dt)^2/12, times 10 for the response's sensitivity to frequency in
!!       this damped scene (|d ln H/d ln omega| < 3 for damping ratios above 0.1);
!! (2) a table that samples load 1's harmonic every 0.02 s against that harmonic: the
!!     linear interpolation of a sinusoid errs by at most (omega delta)^2/8 of its
!!     amplitude; the responses differ by at most twice that of the response (the
!!     error's images above the forcing frequency are filtered by the beam), and by more
!!     than 1e-3 of it (the table is the signal used); after the table's end the load is
!!     0 ('zero') or its last value ('hold');
!! (3) a load of &forces equal to one of &load gives:
!!     - a point force: the same bits (the same load vector, and A cos(Omega t + 0) times
!!       it is the same product);
!!     - a uniform load over the whole beam: the same bits (`load_vector` over [0, L] takes
!!       the points of the whole-beam rule);
!!     - base excitation (&load: support motion A sin(Omega t); &forces: its acceleration
!!       A Omega^2 cos(Omega t + pi/2)): round-off only. cos(Omega t + pi/2) is not -sin(Omega t)
!!       to the bit: the rounded phase sum errs by eps (Omega t + 2), the two library
!!       functions and the products by a few eps more, so the loads differ by at most
!!       delta = eps (Omega t_end + 8) of their amplitude; the responses by at most delta
!!       times the largest gain of the tip max_w |H(w)| over the gain at Omega (computed
!!       here, the difference may have any frequency), times 10 for the accumulation
!!       over the damping's memory.
program test_forces_harmonic
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_model, only: beam_model, point_row, node_row, point_load_vector
   use vibrobeam_band, only: symmetric_band, band_combination
   use vibrobeam_linear_response, only: dense_transfer, theta_frequency, simpson_load_vector
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, band_condition, same_bits
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, single
   type(run_problem) :: prepared
   character(len=512) :: path
   real(dp), allocatable :: times(:), tip(:), tip_harmonic(:), tip_table(:), f(:)
   real(dp) :: exact_discrete, exact_continuous, scale, kappa, tolerance, difference, bound, delta
   integer :: k, tip_dofs(4), unit
   real(dp) :: tip_weights(4)
   complex(dp), allocatable :: load(:, :)
   real(dp), allocatable :: omega(:)
   type(symmetric_band) :: w

   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call node_row(prepared%model, prepared%model%elements, tip_dofs, tip_weights)
   call run(scene, prepared, times, tip)

   ! the loads as complex amplitudes F e^{i phi} at their frequencies, integrated here
   associate (model => prepared%model, l => scene%beam%length)
      allocate (load(model%unknowns, 5), omega(5))
      load(:, 1) = 0.7_dp*exp(cmplx(0.0_dp, 0.4_dp, dp))*point_load_vector(model, 0.6_dp)
      omega(1) = 3
      load(:, 2) = -1.3_dp*exp(cmplx(0.0_dp, -1.0_dp, dp))*simpson_load_vector(model, 0.2_dp, 0.7_dp)
      omega(2) = 11
      load(:, 3) = -scene%beam%rho_s()*0.5_dp*simpson_load_vector(model, 0.0_dp, l)   ! -rho S a(t)
      omega(3) = 25
      load(:, 4) = 0.2_dp*point_load_vector(model, l)
      omega(4) = 0
      load(:, 5) = 0.3_dp*point_load_vector(model, 0.5_dp)
      omega(5) = 7
   end associate
   w = band_combination(1 + scene%time%theta*scene%time%dt*scene%beam%rayleigh_mass, prepared%model%mass, &
                        (scene%time%theta*scene%time%dt)**2 + scene%time%theta*scene%time%dt*scene%beam%rayleigh_stiffness, &
                        prepared%model%stiffness)
   kappa = band_condition(w)
   tolerance = 20*epsilon(1.0_dp)*kappa/(2*scene%time%dt)
   write (output_unit, '(a,es10.3,a,es10.3)') 'kappa(W) = ', kappa, ', round-off tolerance ', tolerance
   scale = maxval(abs(tip))
   do k = 1, size(times), 97
      exact_discrete = response(times(k), .true.)
      exact_continuous = response(times(k), .false.)
      call t%check_close('tip against the discrete steady state', tip(k), exact_discrete, tolerance, scale=scale)
      call t%check_close('tip against the semi-discrete steady state', tip(k), exact_continuous, &
                         10*(25*scene%time%dt)**2/12, scale=scale)
   end do
   write (output_unit, '(a,es12.4,a)') 'largest tip displacement ', scale, ' m'

   ! (2) load 1 alone, harmonic, then as a table sampled every delta
   single = scene
   single%forces%load = scene%forces%load(1:1)
   single%load%point_force = 0
   call prepare_test_scene(single, prepared)
   call run(single, prepared, times, tip_harmonic)
   delta = 0.02_dp
   open (newunit=unit, file='forces_harmonic_table.dat', status='replace', action='write')
   write (unit, '(a)') '# t (s), force (N): 0.7 cos(3 t + 0.4) every 0.02 s'
   do k = 0, nint(scene%time%t_end/delta)
      write (unit, '(es24.16e3, 1x, es24.16e3)') k*delta, 0.7_dp*cos(3*k*delta + 0.4_dp)
   end do
   close (unit)
   single%forces%load(1)%signal = 'table'
   single%forces%load(1)%table = 'forces_harmonic_table.dat'
   single%forces%load(1)%amplitude = 1
   call prepare_test_scene(single, prepared)
   call run(single, prepared, times, tip_table)
   difference = maxval(abs(tip_table - tip_harmonic))
   bound = 2*(3*delta)**2/8*maxval(abs(tip_harmonic))
   write (output_unit, '(a,es10.3,a,es10.3)') 'table against harmonic: largest difference ', difference, &
      ' m, bound ', bound
   call t%check_true('table reproduces the harmonic to the interpolation error', difference <= bound)
   call t%check_true('table differs from the harmonic (it is the signal used)', difference > 1e-3_dp*bound)
   ! after the table's end: 0, or the last value held
   f = prepared%loads%at(scene%time%t_end + 1)
   call t%check_true('table_end = ''zero'': no load after the table', all(same_bits(abs(f), 0.0_dp)))
   single%forces%load(1)%table_end = 'hold'
   call prepare_test_scene(single, prepared)
   f = prepared%loads%at(scene%time%t_end + 1)
   call t%check_close('table_end = ''hold'': the last value', dot_product(f, point_load_vector(prepared%model, 0.6_dp))/ &
                      dot_product(point_load_vector(prepared%model, 0.6_dp), point_load_vector(prepared%model, 0.6_dp)), &
                      0.7_dp*cos(3*scene%time%t_end + 0.4_dp), 1e-12_dp)

   ! (3) &forces against &load
   call same_as_load('point')
   call same_as_load('distributed')
   call same_as_load('base')
   call t%finish('test_forces_harmonic')

contains

   !> A scene loaded by one load of &load, and by the same load as a load of &forces.
   subroutine same_as_load(kind)
      character(len=*), intent(in) :: kind
      type(scene_type) :: by_load, by_forces
      real(dp), allocatable :: tip_load(:), tip_forces(:)
      real(dp) :: omega_b, gain_ratio, delta, tolerance, w
      integer :: j
      by_load = scene
      by_load%load%point_force = 0
      deallocate (by_load%forces%load)
      allocate (by_load%forces%load(0))
      by_forces = by_load
      deallocate (by_forces%forces%load)
      allocate (by_forces%forces%load(1))
      by_forces%forces%load(1)%kind = kind
      select case (kind)
      case ('point')
         by_load%load%point_force = 0.3_dp
         by_load%load%point_position = 0.5_dp
         by_load%load%point_frequency = 7
         by_forces%forces%load(1)%position = 0.5_dp
         by_forces%forces%load(1)%amplitude = 0.3_dp
         by_forces%forces%load(1)%frequency = 7
      case ('distributed')
         by_load%load%distributed = 0.8_dp
         by_load%load%distributed_frequency = 11
         by_load%load%distributed_phase = -1
         by_forces%forces%load(1)%amplitude = 0.8_dp
         by_forces%forces%load(1)%frequency = 11
         by_forces%forces%load(1)%phase = -1
      case ('base')
         omega_b = 25
         by_load%load%base_acceleration = 0.5_dp
         by_load%load%base_frequency = omega_b
         by_forces%forces%load(1)%amplitude = 0.5_dp
         by_forces%forces%load(1)%frequency = omega_b
         by_forces%forces%load(1)%phase = acos(-1.0_dp)/2
      end select
      call prepare_test_scene(by_load, prepared)
      call run(by_load, prepared, times, tip_load)
      call prepare_test_scene(by_forces, prepared)
      call run(by_forces, prepared, times, tip_forces)
      if (kind /= 'base') then
         call t%check_true('&forces '//kind//' = &load: the same bits', all(same_bits(tip_forces, tip_load)))
         return
      end if
      ! the gain of the tip to a uniform load: largest over a fine grid against the gain at Omega_b
      gain_ratio = 0
      do j = 0, 4000
         w = j*0.25_dp
         gain_ratio = max(gain_ratio, uniform_gain(w))
      end do
      gain_ratio = gain_ratio/uniform_gain(omega_b)
      delta = epsilon(1.0_dp)*(omega_b*scene%time%t_end + 8)
      tolerance = 10*delta*gain_ratio
      write (output_unit, '(a,es10.3,a,es10.3,a,es10.3)') '&forces base = &load base: largest difference ', &
         maxval(abs(tip_forces - tip_load))/maxval(abs(tip_load)), ' of the response, tolerance ', tolerance, &
         ', gain ratio ', gain_ratio
      call t%check_close('&forces base = &load base to round-off', maxval(abs(tip_forces - tip_load)), 0.0_dp, &
                         tolerance, scale=maxval(abs(tip_load)))
   end subroutine same_as_load

   !> |H(w)| of the tip to a uniform unit load (semi-discrete system).
   real(dp) function uniform_gain(w)
      real(dp), intent(in) :: w
      complex(dp) :: x(prepared%model%unknowns)
      integer :: a
      complex(dp) :: tip_value
      associate (model => prepared%model)
         x = dense_transfer(model%mass, model%stiffness, scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, &
                            cmplx(0.0_dp, w, dp), cmplx(simpson_load_vector(model, 0.0_dp, scene%beam%length), 0.0_dp, dp))
         tip_value = 0
         do a = 1, 4
            if (tip_dofs(a) /= 0) tip_value = tip_value + tip_weights(a)*x(tip_dofs(a))
         end do
      end associate
      uniform_gain = abs(tip_value)
   end function uniform_gain

   !> Tip displacement at every step of the last 5 s.
   subroutine run(scene, prepared, times, tip)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      real(dp), allocatable, intent(out) :: times(:), tip(:)
      class(time_stepper), allocatable :: stepper
      integer :: n, steps, first, stat, a
      character(len=512) :: errmsg
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      steps = nint(scene%time%t_end/scene%time%dt)
      first = steps - nint(5/scene%time%dt)
      allocate (times(steps - first + 1), tip(steps - first + 1))
      do n = 1, steps
         call stepper%step(stat, errmsg)
         if (stat /= 0) error stop 'step failed'
         if (n < first) cycle
         times(n - first + 1) = stepper%t
         tip(n - first + 1) = 0
         do a = 1, 4
            if (tip_dofs(a) /= 0) tip(n - first + 1) = tip(n - first + 1) + tip_weights(a)*stepper%u(tip_dofs(a))
         end do
      end do
   end subroutine run

   !> The steady tip displacement at t: sum_k Re(H(s_k) F_k e^{i omega_k t}).
   real(dp) function response(time, discrete)
      real(dp), intent(in) :: time
      logical, intent(in) :: discrete
      complex(dp) :: s
      complex(dp) :: x(prepared%model%unknowns)
      integer :: j, a
      response = 0
      associate (model => prepared%model)
         do j = 1, size(omega)
            if (discrete) then
               s = theta_frequency(omega(j), scene%time%dt, scene%time%theta)
            else
               s = cmplx(0.0_dp, omega(j), dp)
            end if
            x = dense_transfer(model%mass, model%stiffness, scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, s, &
                               load(:, j))
            do a = 1, 4
               if (tip_dofs(a) /= 0) response = response + tip_weights(a)*real(x(tip_dofs(a))* &
                                                                              exp(cmplx(0.0_dp, omega(j)*time, dp)), dp)
            end do
         end do
      end associate
   end function response
end program test_forces_harmonic
