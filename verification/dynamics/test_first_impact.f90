!> Verification (issue 3, "First impact" and "Penetration"): mode-1 initial velocity toward
!! a tip obstacle at gap g = 0.05 (verification/dynamics/first_impact.nml).
!! - The first step with an impulse ends within 2 dt of the closed-form time
!!   t* = asin(g omega_1/v0)/omega_1, for dt = 1e-3, 5e-4, 2.5e-4, 1.25e-4.
!! - The largest penetration during this impact episode (0.1 s from the first impulse: the
!!   tip bounces a few times on the stop, every other step, before it leaves) is below
!!   dt |v_impact|: the activation
!!   rule lets the point travel (1 - gamma) dt |v| into the obstacle before the impulse,
!!   and Newton's law constrains V^{n+1} + e V^n, not V^{n+1}, so while the prediction
!!   stays inside, a point already moving out may be drawn back by the rest of the beam
!!   for another fraction of a step (docs/method.md).
!! - With dt = t*/(m + 1/4), m = 50, 100, 200, 400, the obstacle is crossed at the same
!!   fraction of a step for every dt (a fixed impact): the penetration then decreases at
!!   least linearly over the three largest dt, exponent >= 0.9 (the fourth is printed).
!!   (With arbitrary dt the crossing phase, and so the penetration between 0 and the
!!   bound, varies from one dt to the next.)
!! The scene's &time scheme is used: with 'position' the impulse time is t_n, where the
!! centred scheme applies its reaction, and the penetration bound is 2 dt |v_impact|.
program test_first_impact
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_cantilever_exact, only: cantilever_frequency
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   character(len=512) :: path, errmsg
   real(dp), parameter :: plain_steps(4) = [1e-3_dp, 5e-4_dp, 2.5e-4_dp, 1.25e-4_dp]
   real(dp), parameter :: steps_per_t_star(4) = [50.25_dp, 100.25_dp, 200.25_dp, 400.25_dp]
   real(dp) :: omega1, gap, t_star, t_impact, depth(size(plain_steps)), v_impact, bound, slope, steps(4)
   class(time_stepper), allocatable :: stepper
   integer :: k, stat, n
   character(len=64) :: label
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   omega1 = cantilever_frequency(1, scene%beam%length, scene%beam%k2)
   gap = -scene%obstacles(1)%level_from
   t_star = asin(gap*omega1/abs(scene%initial%velocity_amplitude))/omega1
   write (output_unit, '(a,es20.12)') 'closed-form first impact time t* = ', t_star
   call measure(plain_steps)
   steps = t_star/steps_per_t_star
   call measure(steps)
   slope = log(max(depth(1), tiny(1.0_dp))/max(depth(3), tiny(1.0_dp)))/log(steps(1)/steps(3))
   write (output_unit, '(a,f7.3)') 'fixed impact: fitted exponent of penetration against dt: ', slope
   call t%check_true('penetration decreases at least linearly in dt (exponent >= 0.9)', slope >= 0.9_dp)
   call t%finish('test_first_impact')
contains
   subroutine measure(steps)
   real(dp), intent(in) :: steps(:)
   write (output_unit, '(a)') '     dt       t_impact    (t_impact - t*)/dt   max penetration   bound'
   do k = 1, size(steps)
      scene%time%dt = steps(k)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      t_impact = -1
      depth(k) = 0
      v_impact = 0
      do n = 1, nint(scene%time%t_end/scene%time%dt)
         call stepper%step(stat, errmsg)
         if (stat /= 0) error stop 'step failed'
         if (t_impact < 0 .and. stepper%report%active_count > 0) then
            if (abs(stepper%report%impulse(1)) > 0) then
               t_impact = stepper%report%impulse_time
               v_impact = abs(stepper%report%velocity_before(1))
            end if
         end if
         depth(k) = max(depth(k), prepared%contacts%lower(1) - contact_value(prepared%contacts, 1, stepper%u))
         if (t_impact > 0 .and. stepper%t > t_impact + 0.1_dp) exit   ! the first impact episode is over
      end do
      bound = scene%time%dt*v_impact
      ! position scheme: U^{n+1} = (1 + e) Z - e U^{n-1} may reflect a point up to dt |v|
      ! inside (one degree of freedom: exactly dt |v| at most), and the beam's elastic
      ! response adds to it (measured: 1.1 dt |v|); allow 2 dt |v|
      if (scene%time%scheme == 'position') bound = 2*bound
      write (output_unit, '(es10.3, es14.6, f12.3, 2es16.4)') scene%time%dt, t_impact, (t_impact - t_star)/scene%time%dt, &
         depth(k), bound
      write (label, '(a,es9.2)') 'first impact time, dt =', scene%time%dt
      call t%check_close(trim(label), abs(t_impact - t_star), 0.0_dp, 1.0_dp, 2*scene%time%dt)
      write (label, '(a,es9.2)') 'penetration within the bound, dt =', scene%time%dt
      ! round-off: depth = g1 - H U (H U a sum of at most 3 products, then a subtraction)
      ! is off by gamma_4 (|g1| + |H U|) <= gamma_4 2|g1|; the bound dt |v| by gamma_5
      call t%check_true(trim(label), depth(k) <= bound*(1 + gamma_n(5)) + 2*gamma_n(4)*abs(prepared%contacts%lower(1)))
   end do
   end subroutine measure
end program test_first_impact
