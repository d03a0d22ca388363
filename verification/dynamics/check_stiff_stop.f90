!> A very stiff compliant stop that the run resolves conserves the energy to the accuracy
!! docs/theory.md section 8 ("Accuracy") states (issue 23 item 4: a stop of 1e30 N/m
!! multiplied the energy by 10.9 in 0.1 s with status 'ok', and one of 1e27 N/m raised it
!! by 13 to 21 %).   usage: check_stiff_stop RESULT.h5 INPUT.nml
!!
!! The scene (INPUT.nml): undamped springs at the tip only, the 'gradient' rule, theta =
!! 1/2, no load, no damping, no rigid obstacle, every step written (&output every = 1).
!! Then E = kinetic + elastic + sum_j Phi_j (/energy/total) is conserved by the scheme in
!! exact arithmetic, and in floating point the run guarantees (or stops with exit 3):
!!  - the work of the force residual Newton's method leaves is at most sqrt(eps) of the
!!    energy scale max(|E|, |W|, |D|) (the run's own check, `unresolved_fraction`);
!!  - the stored energy is evaluated from the positions, each penetration
!!    p = s (g - u_tip) with an error of at most gamma_6 (2|g| + |u^n| + |u^{n+1}| +
!!    dt |v^n| + dt |v^{n+1}|) (g and U^n enter the step's penetrations, U^{n+1} the
!!    booked one; the velocities through U^{n+1} = U^n + dt V^{n+1/2}), which moves the
!!    energy identity of a step by at most that times the force, f^n + f^{n+1} bounding
!!    both the rule's force (a mean of f over [p^n, p^{n+1}]) and the end force (the
!!    forces of /contact/force, written at every step), plus the rounding of the
!!    potential's two evaluations gamma_8 (Phi^n + Phi^{n+1}).
!! The check: |E^n - E^0| <= sqrt(eps) scale + sum_{k<=n} b_k at every step, b_k the step's
!! terms above (summed linearly: the worst case, no statistical model). Before issue 23 the
!! same run of a 1e27 N/m stop gained 21 % of E^0 in 0.02 s, 30 times this bound.
program check_stiff_stop
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_real_2d, read_attr_string
   use vibrobeam_time_stepper, only: unresolved_fraction
   use vibrobeam_test_support, only: test_counter, read_test_scene
   use vibrobeam_roundoff_bounds, only: gamma_n
   implicit none
   type(test_counter) :: t
   character(len=4096) :: file, input
   character(len=512) :: errmsg
   character(len=:), allocatable :: status
   type(scene_type) :: scene
   real(dp), allocatable :: total(:), potential(:), work(:), dissipated(:), tip_u(:), tip_v(:), force(:, :)
   real(dp) :: level, scale, bound, ratio, drift, worst_bound
   integer :: stat, n, k

   call get_command_argument(1, file)
   call get_command_argument(2, input)
   scene = read_test_scene(trim(input))
   level = 0
   do k = 1, size(scene%obstacles)
      if (scene%obstacles(k)%stiffness <= 0 .or. scene%obstacles(k)%damping > 0 .or. &
          scene%obstacles(k)%x_from < scene%beam%length) error stop 'check_stiff_stop: undamped tip springs only'
      level = max(level, abs(scene%obstacles(k)%level_from))
   end do
   if (scene%output%every /= 1 .or. scene%time%compliant_rule /= 'gradient' .or. abs(scene%time%theta - 0.5_dp) > 0) &
      error stop 'check_stiff_stop: every = 1, the gradient rule and theta = 1/2'

   call read_attr_string(trim(file), '/run', 'status', status, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/total', total, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/contact_potential', potential, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/work', work, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/energy/dissipated', dissipated, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/tip/displacement', tip_u, stat, errmsg)
   if (stat == 0) call read_real_1d(trim(file), '/tip/velocity', tip_v, stat, errmsg)
   if (stat == 0) call read_real_2d(trim(file), '/contact/force', force, stat, errmsg)
   call t%check_true('read the result', stat == 0, errmsg)
   if (stat /= 0) call t%finish('check_stiff_stop')
   call t%check_true('/run status is ok', status == 'ok', 'status = '//status)
   call t%check_true('every step written', size(total) == nint(scene%time%t_end/scene%time%dt) + 1 .and. &
                     size(force, 2) == size(total))
   call t%check_true('the stops are hit', maxval(abs(force)) > 0)
   if (size(force, 2) /= size(total)) call t%finish('check_stiff_stop')

   scale = max(maxval(abs(total)), maxval(abs(work)), maxval(abs(dissipated)))
   bound = unresolved_fraction*scale
   ratio = 0
   drift = 0
   worst_bound = bound
   do n = 2, size(total)
      bound = bound + gamma_n(6)*(sum(abs(force(:, n))) + sum(abs(force(:, n - 1))))* &
              (2*level + abs(tip_u(n)) + abs(tip_u(n - 1)) + scene%time%dt*(abs(tip_v(n)) + abs(tip_v(n - 1)))) &
              + gamma_n(8)*(potential(n) + potential(n - 1))
      drift = max(drift, abs(total(n) - total(1)))
      if (abs(total(n) - total(1))/bound > ratio) then
         ratio = abs(total(n) - total(1))/bound
         worst_bound = bound
      end if
   end do
   write (output_unit, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3,a)') 'E^0 = ', total(1), ' J, largest |E^n - E^0| = ', &
      drift, ' J; largest |E^n - E^0|/bound_n ', ratio, ' (bound there ', worst_bound, ' J)'
   call t%check_close('|E^n - E^0| / its stated bound, largest over the steps', ratio, 0.0_dp, 1.0_dp, 1.0_dp)
   call t%finish('check_stiff_stop')
end program check_stiff_stop
