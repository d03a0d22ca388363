!> Work-precision of the reduced model (issue 13, `&mesh reduction = 'craig-bampton'`):
!! error against the full model and time per step for several cut-offs, at N = 256
!! (studies/work_precision/REPORT.md, "The reduced model").
!!
!! A scene is run with the full model (J unknowns) and with the reduced model keeping
!! k = 0, 1, 2, ... fixed-interface modes and with the default cut-off. The statistics, over
!! the window [measure_from, t_end] of the scene:
!!  - RMS tip displacement (every step);
!!  - impact rate: impacts per second, an impact counted as the recorder counts it (an
!!    impulse at a point that had none in the previous step and approached its obstacle);
!!  - energy lost to impacts over the window (J), the stepper's `dissipated_impacts`;
!!  - the time of the first impact (s), reported beside the others;
!!  - episode rate: contact episodes per second, an episode being impacts separated by less
!!    than the recorder's default episode gap (0.05 of the period of mode 1): with a point
!!    stop and e < 1 the number of micro-bounces inside an episode depends on the highest
!!    modes of the mesh (docs/method.md, "What e means at a point stop"), the episodes do not.
!! Error of a statistic: |reduced - full| / |full| (the energy lost: relative to the
!! largest of that and 1e-6 of the beam's largest energy in the window, so that e = 1, where
!! nothing is lost, reads as round-off); "max error" is the largest of the three.
!! The statistics come from a first run (which also sums the energies); the time per step is
!! the median of three further runs.
!!
!! Cost: CPU time (`cpu_time`) of the stepping loop, the statistics included (a tip value
!! per step, for full and reduced alike), median of 3 runs; set-up (modes, factorization)
!! reported separately, once.
!!
!! The statistics of a rattling beam depend sensitively on its state (impacts make the
!! motion chaotic), so an error is only meaningful against the spread of the full model's
!! own statistics under a perturbation far below any modelling error: the row "full,
!! perturbed" runs the full model with every load and initial velocity scaled by
!! 1 + 1e-9. A reduced model whose errors are of the size of that row's is as close to the
!! full model as the statistics over this window can tell.
!!
!! Rows are named by one word (full, full-perturbed, full-N=..., k=..., default-cutoff), so
!! that the columns split on blanks.
!!
!! usage: work_precision_reduced SCENE.nml ELEMENTS MEASURE_FROM T_END OUTPUT.txt [full]
!! With `full` only the full model runs, at N, N/2 and 2N (its own mesh dependence).
program work_precision_reduced
   use vibrobeam_kinds, only: dp, output_unit, error_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_test_support, only: read_test_scene, prepare_test_scene
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_model, only: node_row
   use vibrobeam_recorder, only: default_episode_gap
   implicit none

   type :: statistics
      real(dp) :: rms_tip = 0, impact_rate = 0, energy_lost = 0, first_impact = -1
      real(dp) :: episode_rate = 0     !! contact episodes per second (1/s)
      real(dp) :: energy_scale = 0     !! largest kinetic + elastic energy in the window (J)
      real(dp) :: cpu_per_step = 0     !! s
      real(dp) :: setup_seconds = 0    !! s, modes and factorization
      integer :: unknowns = 0
      real(dp) :: highest_mode = 0     !! rad/s, highest fixed-interface mode kept
   end type statistics

   character(len=512) :: scene_file, argument, output_file
   type(scene_type) :: scene, perturbed_scene
   type(statistics) :: full, reduced
   integer, parameter :: mode_counts(*) = [0, 1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64]
   integer :: k, unit, elements
   real(dp) :: measure_from, t_end
   logical :: full_only

   full_only = command_argument_count() == 6
   if (command_argument_count() /= 5 .and. .not. full_only) then
      write (error_unit, '(a)') 'usage: work_precision_reduced SCENE.nml ELEMENTS MEASURE_FROM T_END OUTPUT.txt'
      error stop 2
   end if
   call get_command_argument(1, scene_file)
   call get_command_argument(2, argument)
   read (argument, *) elements
   call get_command_argument(3, argument)
   read (argument, *) measure_from
   call get_command_argument(4, argument)
   read (argument, *) t_end
   call get_command_argument(5, output_file)
   scene = read_test_scene(trim(scene_file))
   scene%mesh%elements = elements
   scene%output%measure_from = measure_from
   scene%time%t_end = t_end
   perturbed_scene = scene
   perturbed_scene%load%point_force = scene%load%point_force*(1 + 1e-9_dp)
   perturbed_scene%load%distributed = scene%load%distributed*(1 + 1e-9_dp)
   perturbed_scene%load%base_amplitude = scene%load%base_amplitude*(1 + 1e-9_dp)
   perturbed_scene%initial%velocity_amplitude = scene%initial%velocity_amplitude*(1 + 1e-9_dp)

   full = run(scene, 'none', -1)
   open (newunit=unit, file=trim(output_file), status='replace', action='write')
   call header(unit)
   call header(output_unit)
   call print_row(unit, 'full', full)
   call print_row(output_unit, 'full', full)
   reduced = run(perturbed_scene, 'none', -1)
   call print_row(unit, 'full-perturbed', reduced)
   call print_row(output_unit, 'full-perturbed', reduced)
   if (full_only) then
      ! the full model's own mesh dependence: N/2 and 2N against N
      do k = 1, 2
         scene%mesh%elements = merge(elements/2, 2*elements, k == 1)
         reduced = run(scene, 'none', -1)
         write (argument, '(a,i0)') 'full-N=', scene%mesh%elements
         call print_row(unit, trim(argument), reduced)
         call print_row(output_unit, trim(argument), reduced)
      end do
      close (unit)
      stop
   end if
   do k = 1, size(mode_counts)
      if (mode_counts(k) > 2*elements - 2) cycle
      reduced = run(scene, 'craig-bampton', mode_counts(k))
      write (argument, '(a,i0)') 'k=', mode_counts(k)
      call print_row(unit, trim(argument), reduced)
      call print_row(output_unit, trim(argument), reduced)
   end do
   reduced = run(scene, 'craig-bampton', -1)
   call print_row(unit, 'default-cutoff', reduced)
   call print_row(output_unit, 'default-cutoff', reduced)
   close (unit)

contains

   subroutine header(unit)
      integer, intent(in) :: unit
      write (unit, '(a)') '# scene '//trim(scene_file)//' with N = '//trim(real_text(real(elements, dp)))// &
         ', t_end = '//trim(real_text(t_end))//' s, window from t = '//trim(real_text(measure_from))//' s'
      write (unit, '(a)') '# model  r  highest_mode(rad/s)  rms_tip(m)  impact_rate(1/s)  energy_lost(J)  '// &
         'episode_rate(1/s)  first_impact(s)  err_rms  err_rate  err_energy  err_episodes  '// &
         'max_err(rms,rate,energy)  max_err(rms,energy,episodes)  us/step  speed-up  setup(s)'
   end subroutine header

   function real_text(x) result(text)
      real(dp), intent(in) :: x
      character(len=32) :: text
      write (text, '(g0.6)') x
   end function real_text

   subroutine print_row(unit, name, s)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      type(statistics), intent(in) :: s
      real(dp) :: errors(4)
      ! with e = 1 no energy is lost: the difference relative to the energy in the beam
      errors = [relative(s%rms_tip, full%rms_tip), relative(s%impact_rate, full%impact_rate), &
                abs(s%energy_lost - full%energy_lost)/max(abs(full%energy_lost), 1e-6_dp*full%energy_scale), &
                relative(s%episode_rate, full%episode_rate)]
      write (unit, '(a18,i6,es10.3,4es12.4,es11.4,6es9.2,f8.3,f7.1,f7.3)') name, s%unknowns, s%highest_mode, &
         s%rms_tip, s%impact_rate, s%energy_lost, s%episode_rate, s%first_impact, errors, maxval(errors(1:3)), &
         maxval(errors([1, 3, 4])), 1e6_dp*s%cpu_per_step, full%cpu_per_step/s%cpu_per_step, s%setup_seconds
   end subroutine print_row

   pure real(dp) function relative(value, reference)
      real(dp), intent(in) :: value, reference
      relative = abs(value - reference)/max(abs(reference), tiny(1.0_dp))
   end function relative

   !> One scene run four times (the statistics from the first, the median CPU time of the others).
   function run(base, reduction, modes) result(s)
      type(scene_type), intent(in) :: base
      character(len=*), intent(in) :: reduction
      integer, intent(in) :: modes
      type(statistics) :: s
      type(scene_type) :: scene
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      real(dp), allocatable :: tip_row(:)
      logical, allocatable :: in_contact(:), now(:)
      real(dp) :: times(0:3), start, finish, tip, sum_square, lost_start, setup_start, last_impulse, gap
      integer :: repetition, stat, n, steps, first, samples, impacts, c, j, dofs(4), a, episodes
      real(dp) :: weights(4)
      character(len=256) :: errmsg
      scene = base
      scene%mesh%reduction = reduction
      scene%mesh%reduction_modes = modes
      call cpu_time(setup_start)
      call prepare_test_scene(scene, prepared)
      call cpu_time(start)
      s%setup_seconds = start - setup_start
      steps = nint(scene%time%t_end/scene%time%dt)
      first = nint(scene%output%measure_from/scene%time%dt)
      ! the tip as a row of the stepper's unknowns
      call node_row(prepared%model, prepared%model%elements, dofs, weights)
      if (prepared%reduced) then
         allocate (tip_row(size(prepared%reduction%transform, 2)), source=0.0_dp)
         do a = 1, 4
            if (dofs(a) /= 0) tip_row = tip_row + weights(a)*prepared%reduction%transform(dofs(a), :)
         end do
         s%unknowns = size(tip_row)
         if (prepared%reduction%modes > 0) s%highest_mode = prepared%reduction%omega(prepared%reduction%modes)
      else
         allocate (tip_row(prepared%model%unknowns), source=0.0_dp)
         do a = 1, 4
            if (dofs(a) /= 0) tip_row(dofs(a)) = tip_row(dofs(a)) + weights(a)
         end do
         s%unknowns = prepared%model%unknowns
      end if
      do repetition = 0, 3
         if (allocated(stepper)) deallocate (stepper)
         call cpu_time(start)
         call new_stepper(scene, prepared, stepper, stat, errmsg)
         call cpu_time(finish)
         if (repetition == 0) s%setup_seconds = s%setup_seconds + finish - start
         if (stat /= 0) then
            write (error_unit, '(a)') 'work_precision_reduced: '//trim(errmsg)
            error stop 1
         end if
         in_contact = [(.false., c=1, stepper%contacts%count)]
         now = in_contact
         sum_square = 0
         samples = 0
         impacts = 0
         lost_start = 0
         episodes = 0
         last_impulse = -huge(1.0_dp)
         gap = default_episode_gap(prepared%model)
         s%first_impact = -1
         call cpu_time(start)
         do n = 1, steps
            call stepper%step(stat, errmsg)
            if (stat /= 0) then
               write (error_unit, '(a,i0,a)') 'work_precision_reduced: step ', n, ': '//trim(errmsg)
               error stop 1
            end if
            now = .false.
            do j = 1, stepper%report%active_count
               c = stepper%report%active(j)
               if (abs(stepper%report%impulse(j)) <= 0) cycle
               now(c) = .true.
               if (.not. in_contact(c) .and. stepper%report%approaching(j)) then
                  if (s%first_impact < 0) s%first_impact = stepper%t
                  if (n > first) impacts = impacts + 1
                  if (n > first .and. stepper%t - last_impulse > gap) episodes = episodes + 1
               end if
               last_impulse = stepper%t
            end do
            in_contact = now
            if (n == first) lost_start = stepper%energy%dissipated_impacts
            if (n > first) then
               tip = dot_product(tip_row, stepper%u)
               sum_square = sum_square + tip**2
               samples = samples + 1
               if (repetition == 0) s%energy_scale = max(s%energy_scale, stepper%kinetic_energy() + &
                                                         stepper%elastic_energy())
            end if
         end do
         call cpu_time(finish)
         times(repetition) = (finish - start)/steps   ! times(0), with the statistics, is not used
         if (repetition == 0) then
            s%rms_tip = sqrt(sum_square/max(samples, 1))
            s%impact_rate = impacts/((steps - first)*scene%time%dt)
            s%episode_rate = episodes/((steps - first)*scene%time%dt)
            s%energy_lost = stepper%energy%dissipated_impacts - lost_start
         end if
      end do
      s%cpu_per_step = times(1) + times(2) + times(3) - maxval(times(1:3)) - minval(times(1:3))
   end function run
end program work_precision_reduced
