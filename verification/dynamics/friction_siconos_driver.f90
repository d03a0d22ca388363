!> The vibrobeam side of the friction comparison with Siconos (issue 21;
!! check_friction_siconos.py beside this file): steps a scene of a beam of two planes on
!! one flat stop with friction and writes
!! - MODEL_FILE: line 1 "J kd tip", then the lower bands of M and K column by column
!!   (kd + 1 numbers a line; the z plane's are the same: inertia_z is not given), the
!!   point load vector of a unit force (J), the initial U and V (2J each), then one line
!!   "force shares(1) shares(2) level side mu e dt steps";
!! - HISTORY_FILE: per step "t y_tip z_tip v_y v_z p r_T" (p, r_T the stop's normal and
!!   tangential impulses of the step, 0 when not held).
!! Numbers in es25.17 (round trip).
!!    usage: friction_siconos_driver SCENE.nml MODEL_FILE HISTORY_FILE
program friction_siconos_driver
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene
   implicit none
   type(scene_type) :: scene
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: stepper
   character(len=512) :: path, model_file, history_file, errmsg
   integer :: unit, j, n, steps, stat, tip
   real(dp) :: p, r_t
   call get_command_argument(1, path)
   call get_command_argument(2, model_file)
   call get_command_argument(3, history_file)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call new_stepper(scene, prepared, stepper, stat, errmsg)
   if (stat /= 0) error stop 'new_stepper failed'
   steps = nint(scene%time%t_end/scene%time%dt)
   tip = stepper%holes%circles%dof(1)
   associate (model => prepared%model)
      open (newunit=unit, file=trim(model_file), status='replace', action='write')
      write (unit, '(i0,1x,i0,1x,i0)') model%unknowns, model%mass%kd, tip
      do j = 1, model%unknowns
         write (unit, '(*(es25.17))') model%mass%lower(:, j)
      end do
      do j = 1, model%unknowns
         write (unit, '(*(es25.17))') model%stiffness%lower(:, j)
      end do
      write (unit, '(es25.17)') prepared%loads%point
      write (unit, '(es25.17)') prepared%start%u
      write (unit, '(es25.17)') prepared%start%v
      write (unit, '(8(es25.17,1x),i0)') scene%load%point_force, prepared%loads%shares, scene%obstacles(1)%level_from, &
         merge(1.0_dp, -1.0_dp, scene%obstacles(1)%side == 'below'), scene%obstacles(1)%friction, &
         scene%impact%restitution, scene%time%dt, steps
      close (unit)
   end associate
   open (newunit=unit, file=trim(history_file), status='replace', action='write')
   j = prepared%model%unknowns
   do n = 1, steps
      call stepper%step(stat, errmsg)
      if (stat /= 0) then
         write (*, '(a)') trim(errmsg)
         error stop 'step failed'
      end if
      p = 0
      r_t = 0
      if (stepper%report%circle_count > 0) then
         p = stepper%report%circle_impulse(1)
         r_t = stepper%report%circle_friction(1)
      end if
      write (unit, '(*(es25.17))') stepper%t, stepper%u(tip), stepper%u(j + tip), stepper%v(tip), stepper%v(j + tip), &
         p, r_t
   end do
   close (unit)
end program friction_siconos_driver
