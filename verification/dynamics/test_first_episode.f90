!> Self-convergence through the first contact episode of the two-stop looseness scene
!! (inputs/looseness_tip_stops.nml), the part of the self-convergence study that holds
!! (studies/convergence/REPORT.md, studies 5 and 6).
!!
!! The joint path of the study, level k: dt = 4e-5/2^k s, N = nint(16 2^(k/2)), k = 0..3,
!! against level 4 = (dt0/16, 4 N0), over [0, 4 ms]: the first contact episode of the
!! scene (upper stop, first impulse at 2.07 ms, last at 3.51 ms, about 60 rebounds at
!! dt = 1e-5 s) and 0.5 ms of free flight after it. Errors as in studies/convergence/self_convergence.f90:
!! tip (max in time), field (time-RMS at 11 points), energy at 4 ms.
!!
!! Passes when every run has exactly one impact event in the window with at least 10 steps
!! with an impulse (the episode is there), the tip and field errors decrease at every
!! level, and the observed order of the tip error from level 0 to level 3 is at least 0.5
!! in dt (measured: about 0.8; free flight alone gives 2). The energy
!! error at 4 ms is printed, not checked: the energy an episode dissipates does not
!! converge at these resolutions (studies/convergence/REPORT.md, "Resolved time steps", C).
!! usage: test_first_episode SCENE.nml
program test_first_episode
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_test_support, only: test_counter, read_test_scene
   use vibrobeam_convergence_runs, only: run_history, run_errors, simulate, compare, fail, sci, fixed, rate, &
                                         joint_dt, joint_elements
   implicit none

   real(dp), parameter :: window_end = 4e-3_dp     !! after the first contact episode (s)
   integer, parameter :: levels = 4                !! levels 0..3 against level 4
   real(dp), parameter :: least_order = 0.5_dp     !! observed order in dt, level 0 to 3

   type(scene_type) :: base
   type(run_history) :: runs(0:levels)
   type(run_errors) :: errors(0:levels - 1)
   type(test_counter) :: report
   character(len=4096) :: argument
   real(dp) :: order
   integer :: k, length

   if (command_argument_count() /= 1) call fail('usage: test_first_episode SCENE.nml')
   call get_command_argument(1, argument, length)
   base = read_test_scene(argument(1:length))
   do k = 0, levels
      call simulate(base, joint_dt(k), joint_elements(k), window_end, runs(k))
   end do
   write (output_unit, '(a)') 'errors against dt = '//sci(runs(levels)%dt)//' s, N = '// &
      integer_text(runs(levels)%elements)//' over [0, '//sci(window_end)//' s]', &
      ' level     dt (s)    N  events  impulses   tip (m)      field (m)    energy (J)'
   do k = 0, levels - 1
      errors(k) = compare(runs(k), runs(levels), window_end)
      write (output_unit, '(i6,es11.3,i5,i8,i10,3es13.4)') k, runs(k)%dt, runs(k)%elements, runs(k)%events, &
         runs(k)%impulse_steps, errors(k)%tip, errors(k)%field, errors(k)%energy
   end do
   ! the window must hold the contact episode, and only it: without it, free flight alone
   ! would pass the checks below (at order 2)
   do k = 0, levels
      call report%check_true('level '//integer_text(k)//' has one impact event in the window', &
                             runs(k)%events == 1, integer_text(runs(k)%events)//' events')
      call report%check_true('level '//integer_text(k)//' has at least 10 steps with an impulse', &
                             runs(k)%impulse_steps >= 10, integer_text(runs(k)%impulse_steps)//' steps')
   end do
   do k = 1, levels - 1
      call report%check_true('tip error decreases from level '//integer_text(k - 1)//' to '//integer_text(k), &
                             errors(k)%tip < errors(k - 1)%tip, sci(errors(k - 1)%tip)//' -> '//sci(errors(k)%tip))
      call report%check_true('field error decreases from level '//integer_text(k - 1)//' to '//integer_text(k), &
                             errors(k)%field < errors(k - 1)%field, &
                             sci(errors(k - 1)%field)//' -> '//sci(errors(k)%field))
   end do
   order = rate(errors(0)%tip, errors(levels - 1)%tip, runs(0)%dt, runs(levels - 1)%dt)
   call report%check_true('observed order of the tip error in dt, level 0 to 3, at least '//fixed(least_order, 1), &
                          order >= least_order, fixed(order, 2))
   call report%finish('test_first_episode')
end program test_first_episode
