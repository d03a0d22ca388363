!> A continuation from start to published result (&analysis kind = 'periodic' with
!! &periodic parameter; docs/method.md, "Continuation of periodic orbits"; docs/output.md,
!! "Continued branch"): the branch of `continue_branch` written to /periodic/branch and
!! /periodic/branch/bifurcations, and with &periodic switch_branch the branch of twice the
!! period (`switch_branch`) to /periodic/branch_2 beside it, published at once like every
!! result (a temporary file renamed when complete); a branch that ended early is published
!! too, marked 'failed' with the reason in /periodic failure.
module vibrobeam_branch_output
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_ok, outcome_ok, outcome_interrupted
   use vibrobeam_text, only: integer_text
   use vibrobeam_branch_switch, only: switched_branch, switch_branch
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_continuation, only: continuation_branch, continue_branch, bifurcation_names
   use vibrobeam_branch_point, only: is_stable
   use vibrobeam_backbone, only: continue_backbone
   use vibrobeam_result_files, only: result_files, run_summary, run_outcome
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   implicit none
   private
   public :: run_continuation

contains

   !> Continue the orbit of the prepared scene and publish the branch. stat /= 0 (errmsg)
   !! when the continuation input is invalid, a problem cannot be built or the result
   !! cannot be written (nothing is published, earlier results stay).
   subroutine run_continuation(scene, prepared, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(continuation_branch) :: branch
      type(progress_meter) :: meter
      type(result_files) :: files
      type(run_summary) :: summary
      type(switched_branch) :: second
      call meter%init(scene%output%progress)
      if (scene%periodic%autonomous) then
         call continue_backbone(scene, prepared, branch, stat, errmsg, meter)
      else
         call continue_branch(scene, prepared, branch, stat, errmsg)
      end if
      if (stat /= 0) return
      if (scene%periodic%switch_branch .and. branch%status == outcome_ok) then
         call switch_branch(scene, branch, second, stat, errmsg)
         if (stat /= 0) return
         if (second%switched .and. second%branch%status /= outcome_ok) then
            branch%status = second%branch%status
            branch%failure = 'the branch of twice the period: '//trim(second%branch%failure)
         end if
         branch%steps_taken = branch%steps_taken + second%branch%steps_taken
      end if
      call files%open(scene, prepared%model, stat, errmsg)
      if (stat == stat_ok) call write_branch(files, '/periodic/branch', branch, stat, errmsg)
      if (stat == stat_ok .and. second%switched) call write_switched(files, second, stat, errmsg)
      if (stat == stat_ok .and. len_trim(second%note) > 0) &
         call files%h5%attr_string('/periodic', 'switch_branch', trim(second%note), stat, errmsg)
      if (stat == stat_ok) call write_cost(files, branch, stat, errmsg)
      summary%status = branch%status
      summary%steps = branch%steps_taken
      summary%wall_seconds = meter%elapsed()
      if (interrupt_requested()) summary%status = outcome_interrupted
      call files%finish(summary, meter, outcome%text_skipped, stat, errmsg)
      if (stat /= stat_ok) return
      outcome%status = summary%status
      outcome%failure = branch%failure
      outcome%wall_seconds = summary%wall_seconds
      outcome%run_id = files%run_id
      outcome%steps = branch%steps_taken
      outcome%branch_points = size(branch%points)
      outcome%bifurcations = size(branch%bifurcations)
      if (size(branch%points) > 0) then   ! its first orbit's, as a single orbit's run says
         outcome%period = branch%points(1)%period
         outcome%newton_iterations = branch%first_iterations
         if (size(branch%points(1)%multipliers, 2) > 0) outcome%largest_multiplier = &
            hypot(branch%points(1)%multipliers(1, 1), branch%points(1)%multipliers(2, 1))
      end if
   end subroutine run_continuation

   !> /periodic/branch_2 (docs/output.md, "Continued branch"): the branch of twice the
   !! period as /periodic/branch, and where it came from.
   subroutine write_switched(files, second, stat, errmsg)
      type(result_files), intent(inout) :: files
      type(switched_branch), intent(in) :: second
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), parameter :: group = '/periodic/branch_2'
      call write_branch(files, group, second%branch, stat, errmsg)
      if (stat == 0) call files%h5%attr_int(group, 'period_multiple', second%period_multiple, stat, errmsg)
      if (stat == 0) call files%h5%attr_real(group, 'doubling', second%doubling, stat, errmsg)
      if (stat == 0) call files%h5%attr_real(group, 'start', second%start, stat, errmsg)
      if (stat == 0) call files%h5%attr_real(group, 'move', second%move, stat, errmsg)
      if (stat == 0) call files%h5%attr_int(group, 'towards_points', second%towards_points, stat, errmsg)
      if (stat == 0) call files%h5%attr_int64(group, 'steps_taken', second%branch%steps_taken, stat, errmsg)
   end subroutine write_switched

   !> /periodic: what the continuation cost and how it ended.
   subroutine write_cost(files, branch, stat, errmsg)
      type(result_files), intent(inout) :: files
      type(continuation_branch), intent(in) :: branch
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call files%h5%attr_string('/periodic', 'monodromy', trim(branch%monodromy), stat, errmsg)
      if (stat == 0) call files%h5%attr_int64('/periodic', 'steps_taken', branch%steps_taken, stat, errmsg)
      if (stat == 0) call files%h5%attr_int64('/periodic', 'orbit_steps', branch%orbit_steps, stat, errmsg)
      if (stat == 0) call files%h5%attr_int('/periodic', 'first_newton_iterations', branch%first_iterations, stat, &
                                            errmsg)
      if (stat == 0 .and. len_trim(branch%failure) > 0) &
         call files%h5%attr_string('/periodic', 'failure', trim(branch%failure), stat, errmsg)
   end subroutine write_cost

   !> `group` (one value per point) and group/bifurcations (docs/output.md, "Continued
   !! branch") of `branch`.
   subroutine write_branch(files, group, branch, stat, errmsg)
      type(result_files), intent(inout) :: files
      character(len=*), intent(in) :: group
      type(continuation_branch), intent(in) :: branch
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: found
      integer :: k
      stat = 0
      errmsg = ''
      found = group//'/bifurcations'
      associate (points => branch%points, bifurcations => branch%bifurcations)
         call files%h5%write_real_1d(group//'/parameter', points%parameter, trim(branch%axis%unit), stat, errmsg)
         if (stat == 0) call files%h5%attr_string(group, 'parameter', trim(branch%axis%parameter), stat, errmsg)
         if (stat == 0) call files%h5%write_real_1d(group//'/amplitude', points%amplitude, 'm', stat, errmsg)
         if (stat == 0) call files%h5%write_real_1d(group//'/period', points%period, 's', stat, errmsg)
         if (stat == 0) call files%h5%write_int_1d(group//'/stable', merge(1, 0, is_stable(points)), stat, errmsg)
         if (stat == 0 .and. branch%backbone) &
            call files%h5%write_real_1d(group//'/stable_margin', points%stable_margin, '1', stat, errmsg)
         if (stat == 0) call files%h5%write_real_1d(group//'/largest_multiplier', [(largest(k), k=1, size(points))], &
                                                    '1', stat, errmsg)
         if (stat == 0) call files%h5%write_real_2d(group//'/floquet_multipliers', multiplier_table(), '1', stat, &
                                                    errmsg, layers=2)
         if (stat == 0) call files%h5%write_int_1d(group//'/newton_iterations', points%iterations, stat, errmsg)
         ! (a scene without obstacles has no clearance: huge at every point, not written)
         if (stat == 0 .and. any(points%minimum_gap < huge(1.0_dp))) &
            call files%h5%write_real_1d(group//'/minimum_gap', points%minimum_gap, 'm', stat, errmsg)
         if (stat == 0) call files%h5%write_int_1d(found//'/kind', bifurcations%kind, stat, errmsg)
         if (stat == 0) call files%h5%attr_string(found, 'kinds', kinds_text(), stat, errmsg)
         if (stat == 0) call files%h5%write_real_1d(found//'/parameter', bifurcations%parameter, &
                                                    trim(branch%axis%unit), stat, errmsg)
         if (stat == 0) call files%h5%write_real_1d(found//'/amplitude', bifurcations%amplitude, 'm', stat, errmsg)
         if (stat == 0) call files%h5%write_int_1d(found//'/index', bifurcations%index, stat, errmsg)
         if (stat == 0) call files%h5%write_int_1d(found//'/located', merge(1, 0, bifurcations%located), stat, errmsg)
      end associate
   contains
      !> '1 fold, 2 period-doubling, 3 neimark-sacker, 4 grazing'.
      function kinds_text() result(text)
         character(len=:), allocatable :: text
         text = '1 '//trim(bifurcation_names(1))
         do k = 2, size(bifurcation_names)
            text = text//', '//integer_text(k)//' '//trim(bifurcation_names(k))
         end do
      end function kinds_text

      !> Every point's multipliers, a column each: (2 x 2 J, points), so that h5py sees
      !! (points, 2 J, 2), the last dimension the real and imaginary parts.
      function multiplier_table() result(table)
         real(dp), allocatable :: table(:, :)
         integer :: count
         count = 0
         if (size(branch%points) > 0) count = size(branch%points(1)%multipliers)
         allocate (table(count, size(branch%points)))
         do k = 1, size(branch%points)
            table(:, k) = reshape(branch%points(k)%multipliers, [count])
         end do
      end function multiplier_table

      !> The largest modulus of point k's multipliers.
      real(dp) function largest(k)
         integer, intent(in) :: k
         largest = hypot(branch%points(k)%multipliers(1, 1), branch%points(k)%multipliers(2, 1))
      end function largest
   end subroutine write_branch
end module vibrobeam_branch_output
