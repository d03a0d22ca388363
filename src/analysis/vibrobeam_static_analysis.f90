!> A static run from start to published result (&analysis kind = 'static'): the
!! equilibrium against the obstacles under the loads at t = 0 (`vibrobeam_static`), with
!! its reactions and accuracy, written to the result file and published (docs/output.md,
!! "Static equilibrium"). A solve that fails (no settled active set, or an answer that
!! fails its a-posteriori check) still publishes its last iterate, marked 'failed', with
!! the reason in /static failure.
module vibrobeam_static_analysis
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_ok, message_length, outcome_failed, outcome_interrupted
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_static, only: solve_static, static_report
   use vibrobeam_result_files, only: result_files, run_summary, run_outcome
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   implicit none
   private
   public :: run_equilibrium

contains

   !> Solve for the equilibrium of the prepared scene and publish it. stat /= 0 (with
   !! errmsg) when the result cannot be written (nothing is published, earlier results
   !! stay); a failed solve is `outcome%status` = 'failed' with the reason in
   !! `outcome%failure`, its last iterate published.
   subroutine run_equilibrium(scene, prepared, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: u(:), reaction(:)
      type(result_files) :: files
      type(progress_meter) :: meter
      type(run_summary) :: summary
      type(static_report) :: report
      integer :: iterations, solve_stat
      character(len=message_length) :: solve_message
      associate (model => prepared%model, contacts => prepared%contacts, loads => prepared%loads)
         call meter%init(scene%output%progress)
         allocate (u(model%unknowns), reaction(contacts%count))
         call solve_static(model, contacts, loads%at(0.0_dp), u, reaction, iterations, solve_stat, solve_message, &
                           scene%solver%contact_max_iterations, report, scene%solver%static_tolerance)
         if (solve_stat /= stat_ok) summary%status = outcome_failed
         call files%open(scene, model, stat, errmsg)
         if (stat == stat_ok) call files%write_static(nodal_displacement(model, u), contacts%x, reaction, stat, errmsg)
         if (stat == stat_ok) call files%write_static_accuracy(report%error_estimate, report%error_bound, &
                                                               report%position_bound, report%iterations, &
                                                               trim(solve_message), stat, errmsg)
         summary%wall_seconds = meter%elapsed()
         summary%iterations_total = iterations
         summary%iterations_max = iterations
         if (interrupt_requested()) summary%status = outcome_interrupted
         call files%finish(summary, meter, outcome%text_skipped, stat, errmsg)
         if (stat /= stat_ok) return
         outcome%status = summary%status
         outcome%wall_seconds = summary%wall_seconds
         outcome%run_id = files%run_id
         if (solve_stat /= stat_ok) outcome%failure = solve_message
         outcome%in_contact = count(abs(reaction) > 0)
         outcome%position_bound = report%position_bound
      end associate
   end subroutine run_equilibrium
end module vibrobeam_static_analysis
