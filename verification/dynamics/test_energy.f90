!> Verification of the discrete energy identities (docs/method.md "Energies"; theory §6).
!!
!! Every round-off allowance is the bound of `vibrobeam_roundoff_bounds`, computed from the
!! run itself: the evaluation error of each energy (its conditioning |x|^T|A||x| against
!! x^T A x), b_k for each step, and for a whole run the two evaluations plus
!! min(sum b_k, 6 sqrt(sum b_k^2)). Each check prints the largest ratio value/bound, which
!! must stay below 1 on any conforming BLAS; a broken identity moves the energy by orders
!! of magnitude more (the plain law of theory §3 by 1e-3 to 4e-2 E0 in one step).
!!
!! usage: test_energy SCENE.nml conserve STEPS
!!   e = 1, theta = 1/2, no load: |E^n - E^0| <= drift bound + the round-off of the
!!   impacts' complementarity, at every step, and at least 200 impacts.
!! usage: test_energy SCENE.nml dissipate DT [DT ...]
!!   e < 1, no load: E^{n+1} <= E^n + (one-step bound) at every step, for every dt given
!!   (the scene's own settings otherwise), with the default treatment of separating points;
!!   the balance closes step by step and the impacts' share never goes below zero. The same
!!   run with the plain law of theory §3 (&impact separating_points = 'restitution') is
!!   reported beside it (largest energy increase), not asserted.
!! usage: test_energy SCENE.nml measure DT [DT ...]
!!   any scheme, e < 1: the same table; asserts that the balance closes step by step, that
!!   the run ends with less energy than it started with, and for the position scheme the
!!   documented bound of its energy gains (docs/method.md, "The position-based scheme"):
!!   the impulses of one step add energy in some steps, never more than a third of the
!!   energy before that step (the largest gain measured, 0.32 with e = 0.8;
!!   over the bundled scenes 0.22).
!! With the position scheme and e = 0, 'dissipate' also asserts that no position enters an
!! obstacle by more than the round-off of the projection.
!! usage: test_energy SCENE.nml converge DT [DT ...]
!!   e = 1 with the position scheme, whose energy is not conserved through impacts: over
!!   t_end, max |E^n/E^0 - 1| must decrease as dt decreases (the scheme converges to the
!!   energy-conserving solution, Dumont & Paoli 2006); the balance closes at every step.
!! usage: test_energy SCENE.nml gains DT [DT ...]
!!   the scene run with scheme = 'position' at its own e: prints the largest energy the
!!   impulses of one step add, relative to the energy before that step (the table of
!!   docs/method.md, "The position-based scheme"); asserts only the balance.
!! usage: test_energy SCENE.nml theta THETA [THETA ...]
!!   the velocity scheme with each theta: E - W + D_impacts + D_damping + D_numerical is
!!   constant to the drift bound at every step; the impacts' increment is >= 0 (to its
!!   round-off) at every step; the theta-method's increment is >= 0 in every step without
!!   impulses, its running sum >= 0 at every step, and it is exactly 0 for theta = 1/2.
program test_energy
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_contact_set, only: contact_value, no_bound
   use vibrobeam_roundoff_bounds, only: energy_ledger, stepper_balance
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none

   !> What one run measured; every *_ratio is the largest value/bound over the run.
   type :: run_record
      real(dp) :: drift = 0          !! max |E^n/E^0 - 1| ('dissipate', 'measure': 1 - E_end/E0)
      real(dp) :: rise = 0           !! max (E^{n+1} - E^n)/E^0
      real(dp) :: gain = 0           !! max energy the impulses add in one step / E^n
      real(dp) :: rise_ratio = 0     !! max (E^{n+1} - E^n)/(one-step bound + impacts' round-off)
      real(dp) :: conserve_ratio = 0 !! max |E^n - E^0|/(drift bound + sum of impacts' round-off)
      real(dp) :: conserve_bound = 0 !! that bound/E0 at the end of the run
      real(dp) :: step_ratio = 0     !! max |B^{n+1} - B^n|/one-step bound
      real(dp) :: drift_ratio = 0    !! max |B^n - B^0|/drift bound
      real(dp) :: drift_bound = 0    !! the drift bound at the end, relative to the energy scale
      real(dp) :: impacts_ratio = 0  !! max (-increment of dissipated_impacts)/its round-off
      real(dp) :: numerical_ratio = 0   !! max (-increment of dissipated_numerical)/its round-off, steps without impulses
      real(dp) :: numerical_lowest = 0  !! min increment of dissipated_numerical / E0 (any step)
      real(dp) :: numerical_running = 0 !! min running dissipated_numerical / E0
      real(dp) :: numerical_end = 0     !! dissipated_numerical at the end / E0
      real(dp) :: penetration = 0       !! largest penetration (m)
      real(dp) :: penetration_ratio = 0 !! max penetration / its bound (position scheme, e = 0)
      integer :: impacts = 0            !! new contacts
   end type run_record

   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   type(run_record) :: r, plain
   character(len=512) :: path, mode, argument
   real(dp) :: previous
   integer :: steps, k
   call get_command_argument(1, path)
   call get_command_argument(2, mode)
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   select case (mode)
   case ('conserve')
      call get_command_argument(3, argument)
      read (argument, *) steps
      r = run(scene, steps)
      write (output_unit, '(a,i0,a,i0,a,es10.3,a,es10.3,a,es10.3,a,es10.3)') 'steps ', steps, ', impacts ', &
         r%impacts, ', max |E/E0 - 1| = ', r%drift, ' (bound ', r%conserve_bound, ', largest ratio ', &
         r%conserve_ratio, '), max penetration ', r%penetration
      call t%check_close('max |E^n - E^0| / its round-off bound, e = 1', r%conserve_ratio, 0.0_dp, 1.0_dp, 1.0_dp)
      call check_balance(r)
      call t%check_true('at least 200 impacts', r%impacts >= 200)
   case ('converge')
      write (output_unit, '(a)') '     dt     steps  impacts  max |E^n/E^0 - 1|  max penetration  balance/bound'
      previous = huge(1.0_dp)
      do k = 3, command_argument_count()
         call get_command_argument(k, argument)
         read (argument, *) scene%time%dt
         steps = nint(scene%time%t_end/scene%time%dt)
         r = run(scene, steps)
         write (output_unit, '(es10.3,i8,i8,es16.3,es16.3,es16.3)') scene%time%dt, steps, r%impacts, r%drift, &
            r%penetration, r%drift_ratio
         write (argument, '(a,es9.2)') 'energy error decreases with dt, dt =', scene%time%dt
         call t%check_true(trim(argument), r%drift < previous)
         call check_balance(r)
         previous = r%drift
      end do
   case ('theta')
      write (output_unit, '(a)') ' theta  impacts   D_impacts/E  D_numerical/E  lowest step of D_num/E' // &
         '  lowest running D_num/E  drift/bound  impacts/bound  D_num(no impulse)/bound   (E: largest energy of the run)'
      do k = 3, command_argument_count()
         call get_command_argument(k, argument)
         read (argument, *) scene%time%theta
         steps = nint(scene%time%t_end/scene%time%dt)
         r = run(scene, steps)
         write (output_unit, '(f6.3,i9,2es14.4,2es25.3,3es14.3)') scene%time%theta, r%impacts, r%drift, r%numerical_end, &
            r%numerical_lowest, r%numerical_running, r%drift_ratio, r%impacts_ratio, r%numerical_ratio
         call check_balance(r)
         write (argument, '(a,f5.3)') 'theta = ', scene%time%theta
         call t%check_close('increment of dissipated_impacts >= -round-off, '//trim(argument), max(r%impacts_ratio, 0.0_dp), &
                            0.0_dp, 1.0_dp, 1.0_dp)
         call t%check_close('increment of dissipated_numerical >= -round-off without impulses, '//trim(argument), &
                            max(r%numerical_ratio, 0.0_dp), 0.0_dp, 1.0_dp, 1.0_dp)
         call t%check_true('running dissipated_numerical >= 0, '//trim(argument), r%numerical_running >= 0)
         if (abs(scene%time%theta - 0.5_dp) <= 0) call t%check_true('dissipated_numerical = 0 for theta = 1/2', &
                                                               abs(r%numerical_end) + abs(r%numerical_lowest) <= 0)
         if (scene%time%theta > 0.5_dp) call t%check_true('dissipated_numerical > 0 for theta > 1/2, '//trim(argument), &
                                                     r%numerical_end > 0)
      end do
   case ('gains')
      scene%time%scheme = 'position'
      write (output_unit, '(a)') '     dt      e    largest one-step gain of the impulses / E before the step'
      do k = 3, command_argument_count()
         call get_command_argument(k, argument)
         read (argument, *) scene%time%dt
         r = run(scene, nint(scene%time%t_end/scene%time%dt))
         write (output_unit, '(es10.3,f6.2,f12.4)') scene%time%dt, scene%impact%restitution, r%gain
         call check_balance(r)
      end do
   case ('dissipate', 'measure')
      write (output_unit, '(a)') '     dt     steps  impacts  max (E^{n+1}-E^n)/E^0  rise/bound  E_end/E0  penetration/dt' // &
         '  plain law: max rise   max impulse gain/E^n'
      do k = 3, command_argument_count()
         call get_command_argument(k, argument)
         read (argument, *) scene%time%dt
         steps = nint(scene%time%t_end/scene%time%dt)
         scene%impact%separating_points = 'restitution'
         plain = run(scene, steps, bounds=.false.)   ! reported only: no round-off bounds needed
         scene%impact%separating_points = 'elastic'
         r = run(scene, steps)
         write (output_unit, '(es10.3,i8,i8,es16.3,es12.3,f12.6,es14.3,es14.3,f16.4)') scene%time%dt, steps, r%impacts, r%rise, &
            r%rise_ratio, 1 - r%drift, r%penetration/scene%time%dt, plain%rise, r%gain
         call check_balance(r)
         if (mode == 'dissipate') then
            call t%check_close('largest energy increase in one step / its round-off bound', max(r%rise_ratio, 0.0_dp), &
                               0.0_dp, 1.0_dp, 1.0_dp)
            call t%check_close('increment of dissipated_impacts >= -round-off', max(r%impacts_ratio, 0.0_dp), &
                               0.0_dp, 1.0_dp, 1.0_dp)
         else
            call t%check_true('the run ends with less energy than it started with', r%drift > 0)
            if (scene%time%scheme == 'position') then
               call t%check_true('the impulses add energy in some step (the position scheme)', r%gain > 0)
               call t%check_close('largest energy the impulses add in one step / the energy before it, '// &
                                  'documented bound 1/3', r%gain, 0.0_dp, 1.0_dp, 1.0_dp/3)
            end if
         end if
         call t%check_true('some impacts happen', r%impacts > 0)
         ! theory §4: with e = 0 every position of the position scheme is admissible
         if (scene%time%scheme == 'position' .and. scene%impact%restitution <= 0) &
            call t%check_close('penetration of the position scheme with e = 0 / its round-off bound', &
                               r%penetration_ratio, 0.0_dp, 1.0_dp, 1.0_dp)
      end do
   case default
      error stop 'test_energy: unknown mode'
   end select
   call t%finish('test_energy')

contains

   !> The balance checks every mode makes: step by step and over the run.
   subroutine check_balance(r)
      type(run_record), intent(in) :: r
      call t%check_close('|change of E - W + D in one step| / its round-off bound', r%step_ratio, 0.0_dp, 1.0_dp, 1.0_dp)
      call t%check_close('|E - W + D - its initial value| / the drift bound', r%drift_ratio, 0.0_dp, 1.0_dp, 1.0_dp)
   end subroutine check_balance

   !> Run `steps` steps with the round-off ledger (unless `bounds` is false) and record
   !! what the checks need.
   function run(scene, steps, bounds) result(r)
      type(scene_type), intent(in) :: scene
      integer, intent(in) :: steps
      logical, intent(in), optional :: bounds
      type(run_record) :: r
      logical :: with_bounds
      class(time_stepper), allocatable :: stepper
      type(energy_ledger) :: ledger
      real(dp) :: e0, e_old, e_new, u, b0, b_old, b_new, bound, impacts_total, scale, increment
      logical :: touching(prepared%contacts%count), now(prepared%contacts%count)
      integer :: n, stat, k, c
      character(len=512) :: errmsg
      with_bounds = .true.
      if (present(bounds)) with_bounds = bounds
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      call ledger%start(stepper)
      e0 = stepper%kinetic_energy() + stepper%elastic_energy()
      e_old = e0
      b0 = stepper_balance(stepper)
      b_old = b0
      scale = abs(e0)
      r%rise = -huge(1.0_dp)
      r%rise_ratio = -huge(1.0_dp)
      r%impacts_ratio = -huge(1.0_dp)
      r%numerical_ratio = -huge(1.0_dp)
      r%numerical_lowest = huge(1.0_dp)
      impacts_total = 0
      touching = .false.
      do n = 1, steps
         if (.not. with_bounds) then
            call stepper%step(stat, errmsg)
            if (stat /= 0) error stop 'step failed'
            e_new = stepper%kinetic_energy() + stepper%elastic_energy()
            r%rise = max(r%rise, (e_new - e_old)/e0)
            e_old = e_new
            cycle
         end if
         call ledger%before_step(stepper)
         call stepper%step(stat, errmsg)
         if (stat /= 0) then
            write (output_unit, '(a)') trim(errmsg)
            error stop 'step failed'
         end if
         call ledger%after_step(stepper)
         e_new = stepper%kinetic_energy() + stepper%elastic_energy()
         b_new = stepper_balance(stepper)
         scale = max(scale, abs(e_new), abs(stepper%energy%work))
         if (e0 > 0) r%drift = max(r%drift, abs(e_new/e0 - 1))
         if (e0 > 0) r%rise = max(r%rise, (e_new - e_old)/e0)
         ! the energy may rise by the balance's round-off and by the impacts' (below 0)
         bound = ledger%one_step() + ledger%impacts
         r%rise_ratio = max(r%rise_ratio, (e_new - e_old)/bound)
         impacts_total = impacts_total + ledger%impacts
         r%conserve_ratio = max(r%conserve_ratio, abs(e_new - e0)/(ledger%drift() + impacts_total))
         r%step_ratio = max(r%step_ratio, abs(b_new - b_old)/ledger%one_step())
         r%drift_ratio = max(r%drift_ratio, abs(b_new - b0)/ledger%drift())
         r%impacts_ratio = max(r%impacts_ratio, -(stepper%energy%dissipated_impacts - ledger%impacts_before)/ &
                               max(ledger%impacts, tiny(1.0_dp)))
         if (e_old > 0) r%gain = max(r%gain, -(stepper%energy%dissipated_impacts - ledger%impacts_before)/e_old)
         increment = stepper%energy%dissipated_numerical - ledger%numerical_before
         r%numerical_lowest = min(r%numerical_lowest, increment)
         r%numerical_running = min(r%numerical_running, stepper%energy%dissipated_numerical)
         if (all(abs(stepper%report%impulse(1:stepper%report%active_count)) <= 0)) &
            r%numerical_ratio = max(r%numerical_ratio, -increment/max(ledger%numerical, tiny(1.0_dp)))
         e_old = e_new
         b_old = b_new
         now = .false.
         do k = 1, stepper%report%active_count
            if (abs(stepper%report%impulse(k)) > 0) now(stepper%report%active(k)) = .true.
         end do
         r%impacts = r%impacts + count(now .and. .not. touching)
         touching = now
         do c = 1, prepared%contacts%count
            u = contact_value(prepared%contacts, c, stepper%u)
            r%penetration = max(r%penetration, prepared%contacts%lower(c) - u, u - prepared%contacts%upper(c))
            if (ledger%penetration <= 0) cycle   ! the position scheme's bound only
            if (prepared%contacts%lower(c) > -no_bound) r%penetration_ratio = max(r%penetration_ratio, &
               (prepared%contacts%lower(c) - u)/ledger%penetration)
            if (prepared%contacts%upper(c) < no_bound) r%penetration_ratio = max(r%penetration_ratio, &
               (u - prepared%contacts%upper(c))/ledger%penetration)
         end do
      end do
      if (.not. with_bounds) return   ! only the largest rise was wanted
      if (e0 > 0) r%conserve_bound = (ledger%drift() + impacts_total)/e0
      r%drift_bound = ledger%drift()/scale
      ! energies of the 'theta' table relative to the largest energy of the run (E0 may be 0)
      r%numerical_end = stepper%energy%dissipated_numerical/scale
      r%numerical_lowest = r%numerical_lowest/scale
      r%numerical_running = r%numerical_running/scale
      if ((mode == 'dissipate' .or. mode == 'measure') .and. e0 > 0) r%drift = 1 - e_new/e0
      if (mode == 'theta') r%drift = stepper%energy%dissipated_impacts/scale
   end function run
end program test_energy
