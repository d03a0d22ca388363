!> Verification of the discrete energy E^n = 1/2 V^T M V + 1/2 U^T K U (SPEC §3, issue 3).
!!
!! usage: test_energy SCENE.nml conserve STEPS
!!   e = 1, theta = 1/2, no load: |E^n/E^0 - 1| < 1e-10 at every step over STEPS steps,
!!   and at least 200 impacts (a new contact after a step without one).
!! usage: test_energy SCENE.nml dissipate DT [DT ...]
!!   e < 1, no load: E^{n+1} <= E^n + 1e-12 E^0 at every step, for every dt given (the
!!   scene's own settings otherwise), with the default treatment of separating points; the
!!   same run with the plain law of SPEC §3 (&impact separating_points = 'restitution')
!!   is reported beside it (largest energy increase), not asserted.
!! usage: test_energy SCENE.nml measure DT [DT ...]
!!   any scheme, e < 1: the same table; asserts only that the run ends with less energy
!!   than it started with (the position scheme's one-step rises are reported, SPEC §4).
!! With the position scheme and e = 0, 'dissipate' also asserts zero penetration.
!! usage: test_energy SCENE.nml converge DT [DT ...]
!!   e = 1 with the position scheme, whose energy is not conserved through impacts: over
!!   t_end, max |E^n/E^0 - 1| must decrease as dt decreases (the scheme converges to the
!!   energy-conserving solution, Dumont & Paoli 2006).
program test_energy
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_setup, only: prepared_scene, start_time_stepper
   use vibrobeam_stepper, only: time_stepper
   use vibrobeam_contact_points, only: contact_value
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene
   type(prepared_scene) :: prepared
   character(len=512) :: path, mode, argument
   real(dp) :: drift, rise, penetration, previous
   integer :: impacts, steps, k
   call get_command_argument(1, path)
   call get_command_argument(2, mode)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   if (mode == 'conserve') then
      call get_command_argument(3, argument)
      read (argument, *) steps
      call run(scene, steps, drift, rise, impacts, penetration)
      write (output_unit, '(a,i0,a,i0,a,es10.3,a,es10.3)') 'steps ', steps, ', impacts ', impacts, &
         ', max |E/E0 - 1| = ', drift, ', max penetration ', penetration
      call t%check_close('max |E^n/E^0 - 1| with e = 1', drift, 0.0_dp, 1.0_dp, 1e-10_dp)
      call t%check_true('at least 200 impacts', impacts >= 200)
   else if (mode == 'converge') then
      write (output_unit, '(a)') '     dt     steps  impacts  max |E^n/E^0 - 1|  max penetration'
      previous = huge(1.0_dp)
      do k = 3, command_argument_count()
         call get_command_argument(k, argument)
         read (argument, *) scene%dt
         steps = nint(scene%t_end/scene%dt)
         call run(scene, steps, drift, rise, impacts, penetration)
         write (output_unit, '(es10.3,i8,i8,es16.3,es16.3)') scene%dt, steps, impacts, drift, penetration
         write (argument, '(a,es9.2)') 'energy error decreases with dt, dt =', scene%dt
         call t%check_true(trim(argument), drift < previous)
         previous = drift
      end do
   else
      write (output_unit, '(a)') '     dt     steps  impacts  max (E^{n+1}-E^n)/E^0  E_end/E0   penetration/dt' // &
         '   plain SPEC law: max rise'
      do k = 3, command_argument_count()
         call get_command_argument(k, argument)
         read (argument, *) scene%dt
         steps = nint(scene%t_end/scene%dt)
         scene%separating_points = 'restitution'
         call run(scene, steps, drift, rise, impacts, penetration)
         write (argument, '(es11.3)') rise
         scene%separating_points = 'elastic'
         call run(scene, steps, drift, rise, impacts, penetration)
         write (output_unit, '(es10.3,i8,i8,es16.3,f12.6,es14.3,a)') scene%dt, steps, impacts, rise, 1 - drift, &
            penetration/scene%dt, '   '//trim(argument)
         if (mode == 'dissipate') then
            call t%check_close('largest energy increase in one step / E0', max(rise, 0.0_dp), 0.0_dp, 1.0_dp, 1e-12_dp)
         else
            call t%check_true('the run ends with less energy than it started with', drift > 0)
         end if
         call t%check_true('some impacts happen', impacts > 0)
         ! SPEC §4: with e = 0 every position of the position scheme is admissible
         if (scene%scheme == 'position' .and. scene%restitution <= 0) &
            call t%check_close('penetration of the position scheme with e = 0', penetration, 0.0_dp, 1.0_dp, &
                               1e-12_dp*maxval(abs([scene%obstacles%level_from, scene%obstacles%level_to])))
      end do
   end if
   call t%finish('test_energy')

contains

   !> Run `steps` steps; drift = max |E^n/E^0 - 1| (for 'dissipate': 1 - E_end/E0),
   !! rise = max (E^{n+1} - E^n)/E^0, impacts = new contacts, penetration = largest.
   subroutine run(scene, steps, drift, rise, impacts, penetration)
      type(scene_type), intent(in) :: scene
      integer, intent(in) :: steps
      real(dp), intent(out) :: drift, rise, penetration
      integer, intent(out) :: impacts
      class(time_stepper), allocatable :: stepper
      real(dp) :: e0, e_old, e_new, u
      logical :: touching(prepared%contacts%count), now(prepared%contacts%count)
      integer :: n, stat, k, c
      character(len=512) :: errmsg
      call start_time_stepper(scene, prepared, stepper, stat, errmsg)
      e0 = stepper%kinetic_energy() + stepper%elastic_energy()
      e_old = e0
      drift = 0
      rise = -huge(1.0_dp)
      impacts = 0
      penetration = 0
      touching = .false.
      do n = 1, steps
         call stepper%step(stat, errmsg)
         if (stat /= 0) then
            write (output_unit, '(a)') trim(errmsg)
            error stop 'step failed'
         end if
         e_new = stepper%kinetic_energy() + stepper%elastic_energy()
         drift = max(drift, abs(e_new/e0 - 1))
         rise = max(rise, (e_new - e_old)/e0)
         e_old = e_new
         now = .false.
         do k = 1, stepper%active_count
            if (abs(stepper%impulse(k)) > 0) now(stepper%active(k)) = .true.
         end do
         impacts = impacts + count(now .and. .not. touching)
         touching = now
         do c = 1, prepared%contacts%count
            u = contact_value(prepared%contacts, c, stepper%u)
            penetration = max(penetration, prepared%contacts%lower(c) - u, u - prepared%contacts%upper(c))
         end do
      end do
      if (mode == 'dissipate' .or. mode == 'measure') drift = 1 - e_new/e0
   end subroutine run
end program test_energy
