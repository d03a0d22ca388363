!> A modes run from start to published result (&analysis kind = 'modes'): the natural
!! frequencies and mode shapes of the discrete beam (`vibrobeam_modes`), written to the
!! result file and published (docs/output.md, "Natural modes").
module vibrobeam_modal_analysis
   use vibrobeam_status, only: stat_ok, outcome_interrupted
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_result_files, only: result_files, run_summary, run_outcome
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: run_modal

contains

   !> Compute the modes of `prepared%model` and publish them. stat /= 0 (with errmsg) when
   !! they cannot be computed or written (nothing is published, earlier results stay);
   !! an interruption is reported in `outcome%status` ('interrupted').
   subroutine run_modal(scene, prepared, outcome, stat, errmsg)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:)
      type(result_files) :: files
      type(progress_meter) :: meter
      type(run_summary) :: summary
      call meter%init(scene%output%progress)
      call compute_modes(prepared%model, scene%analysis%modes, omega, shapes, vectors, stat, errmsg)
      if (stat /= stat_ok) return
      call files%open(scene, prepared%model, stat, errmsg)
      if (stat == stat_ok) call files%write_modes(omega, shapes, stat, errmsg)
      summary%wall_seconds = meter%elapsed()
      if (interrupt_requested()) summary%status = outcome_interrupted
      call files%finish(summary, meter, outcome%text_skipped, stat, errmsg)
      if (stat /= stat_ok) return
      outcome%status = summary%status
      outcome%wall_seconds = summary%wall_seconds
      outcome%run_id = files%run_id
      call move_alloc(omega, outcome%omega)
   end subroutine run_modal
end module vibrobeam_modal_analysis
