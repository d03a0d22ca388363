!> What the position scheme records (docs/method.md, "The position-based scheme": work,
!! impulses, impact times), checked step by step against the scheme's own equation
!!   M (U^{n+1} - 2U^n + U^{n-1})/dt^2 + C (U^{n+1} - U^{n-1})/(2 dt)
!!     + K (theta U^{n+1} + (1 - 2 theta) U^n + theta U^{n-1}) = F^n + H^T r^n
!! on a forced, damped scene rattling between two tip stops (forced_damped.nml, run with
!! scheme = 'position'; Hermite elements, so H_c picks one unknown):
!! 1. a recorded impulse is r^n dt, r^n the reaction the equation needs at the point;
!! 2. it is stamped at t_n, the centre of the scheme's stencil (the step goes t_n -> t_{n+1});
!! 3. the velocities before and after are H(U^n - U^{n-1})/dt and H(U^{n+1} - U^n)/dt;
!! 4. the work of the loads grows by F^n.(U^{n+1} - U^{n-1})/2 per step, and the energies
!!    the stepper reports after the step are those of t_{n+1/2}: v = (U^{n+1} - U^n)/dt.
!! Round-off allowances: r^n recomputed here from the three positions cancels like the
!! step itself; its error is bounded row by row by the residual bound of the step
!! (`energy_ledger%residual`, vibrobeam_roundoff_bounds) plus the rounding of this
!! recomputation, gamma_{2kd+6} of the same magnitudes, over dt^2. The work: the stepper
!! adds 1/2 F.(U^{n+1} - U^{n-1}) (gamma_{J+4}) to its sum (u |W|), compared here (u |W|).
program test_position_records
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_band, only: band_matvec
   use vibrobeam_contact_set, only: contact_value
   use vibrobeam_roundoff_bounds, only: energy_ledger, gamma_n, abs_band_times
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: stepper
   type(energy_ledger) :: ledger
   character(len=512) :: path, errmsg
   real(dp), allocatable :: u_old(:), u_older(:), force(:), mu(:), ku(:), cu(:), equation(:), magnitude(:), stride(:)
   real(dp) :: t_before, work_before, reaction, bound, worst_impulse, worst_work, velocity
   integer :: n, stat, k, c, dof, impulses
   logical :: stamped_at_t_n
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   scene%time%scheme = 'position'
   call prepare_test_scene(scene, prepared)
   call new_stepper(scene, prepared, stepper, stat, errmsg)
   call ledger%start(stepper)
   worst_impulse = 0
   worst_work = 0
   impulses = 0
   stamped_at_t_n = .true.
   associate (dt => scene%time%dt, theta => scene%time%theta)
      do n = 1, nint(scene%time%t_end/scene%time%dt)
         call ledger%before_step(stepper)
         u_old = ledger%u_before
         u_older = ledger%u_before_previous
         t_before = stepper%t
         work_before = stepper%energy%work
         force = prepared%loads%at(t_before)
         call stepper%step(stat, errmsg)
         if (stat /= 0) error stop 'step failed'
         call ledger%after_step(stepper)
         ! the scheme's equation times dt^2, left side minus dt^2 F^n: dt^2 H^T r^n
         allocate (mu(size(u_old)), ku(size(u_old)), cu(size(u_old)))
         call band_matvec(stepper%mass, stepper%u - 2*u_old + u_older, mu)
         call band_matvec(stepper%stiffness, theta*stepper%u + (1 - 2*theta)*u_old + theta*u_older, ku)
         cu = stepper%damping_times(stepper%u - u_older)
         equation = mu + 0.5_dp*dt*cu + dt**2*(ku - force)
         magnitude = abs_band_times(stepper%mass, abs(stepper%u) + 2*abs(u_old) + abs(u_older)) &
                     + 0.5_dp*dt*(stepper%rayleigh_mass*abs_band_times(stepper%mass, abs(stepper%u) + abs(u_older)) &
                                  + stepper%rayleigh_stiffness*abs_band_times(stepper%stiffness, abs(stepper%u) + abs(u_older))) &
                     + dt**2*(abs_band_times(stepper%stiffness, theta*abs(stepper%u) + abs(1 - 2*theta)*abs(u_old) + &
                                             theta*abs(u_older)) + abs(force))
         deallocate (mu, ku, cu)
         do k = 1, stepper%report%active_count
            c = stepper%report%active(k)
            dof = prepared%contacts%dofs(1, c)   ! Hermite: H_c U = U(dof)
            reaction = equation(dof)/dt**2
            bound = (ledger%residual(dof) + gamma_n(2*stepper%stiffness%kd + 6)*magnitude(dof))/dt**2*dt
            worst_impulse = max(worst_impulse, abs(stepper%report%impulse(k) - reaction*dt)/bound)
            impulses = impulses + 1
            stamped_at_t_n = stamped_at_t_n .and. abs(stepper%report%impulse_time - t_before) <= 0
            velocity = (contact_value(prepared%contacts, c, u_old) - contact_value(prepared%contacts, c, u_older))/dt
            call t%check_true('velocity before = H(U^n - U^{n-1})/dt', abs(stepper%report%velocity_before(k) - velocity) <= 0)
            velocity = (contact_value(prepared%contacts, c, stepper%u) - contact_value(prepared%contacts, c, u_old))/dt
            call t%check_true('velocity after = H(U^{n+1} - U^n)/dt', abs(stepper%report%velocity_after(k) - velocity) <= 0)
         end do
         ! no impulse where the equation needs none
         if (stepper%report%active_count == 0) then
            dof = prepared%contacts%dofs(1, 1)
            worst_impulse = max(worst_impulse, abs(equation(dof))/(ledger%residual(dof) + &
                                gamma_n(2*stepper%stiffness%kd + 6)*magnitude(dof)))
         end if
         stride = stepper%u - u_older
         worst_work = max(worst_work, abs(stepper%energy%work - work_before - 0.5_dp*dot_product(force, stride))/ &
                          (gamma_n(size(stride) + 4)*0.5_dp*dot_product(abs(force), abs(stride)) + &
                           gamma_n(2)*abs(stepper%energy%work) + tiny(1.0_dp)))
         call t%check_true('the stepper reports v = (U^{n+1} - U^n)/dt', all(abs(stepper%v - (stepper%u - u_old)/dt) <= 0))
      end do
   end associate
   write (output_unit, '(a,i0,a,es10.3,a,es10.3)') 'steps with an impulse: ', impulses, &
      '; largest |impulse - r^n dt| / its round-off bound ', worst_impulse, '; work increment / bound ', worst_work
   call t%check_true('impulses happen', impulses > 0)
   call t%check_close('impulse = r^n dt (largest difference / its round-off bound)', worst_impulse, 0.0_dp, 1.0_dp, 1.0_dp)
   call t%check_true('impulses are stamped at t_n', stamped_at_t_n)
   call t%check_close('work increment = F^n.(U^{n+1} - U^{n-1})/2 (largest difference / its bound)', worst_work, &
                      0.0_dp, 1.0_dp, 1.0_dp)
   call t%finish('test_position_records')
end program test_position_records
