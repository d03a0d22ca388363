!> The periodic analysis a scene of &analysis kind = 'periodic' asks for, in one place for
!! the program and for a sweep's points (docs/method.md): a continued branch (&periodic
!! parameter given, `run_continuation`), an autonomous orbit (&periodic autonomous,
!! `run_autonomous`) or a forced orbit (`run_periodic`), each published as the scene's
!! result file.
module vibrobeam_periodic_run
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_result_files, only: run_outcome
   use vibrobeam_periodic_analysis, only: run_periodic
   use vibrobeam_autonomous_orbit, only: run_autonomous
   use vibrobeam_branch_output, only: run_continuation
   use vibrobeam_continuation_axis, only: continues
   implicit none
   private
   public :: run_periodic_kind

contains

   !> Run the scene's periodic analysis on `prepared` and publish its result; stat and
   !! outcome as the analysis run says (stat /= 0: nothing could be written).
   subroutine run_periodic_kind(scene, prepared, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      if (continues(scene)) then
         call run_continuation(scene, prepared, outcome, stat, errmsg)
      else if (scene%periodic%autonomous) then
         call run_autonomous(scene, prepared, outcome, stat, errmsg)
      else
         call run_periodic(scene, prepared, outcome, stat, errmsg)
      end if
   end subroutine run_periodic_kind
end module vibrobeam_periodic_run
