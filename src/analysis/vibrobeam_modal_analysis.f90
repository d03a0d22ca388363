!> A modes run from start to published result (&analysis kind = 'modes'): the natural
!! frequencies and mode shapes of the discrete beam (`vibrobeam_modes`), and with
!! `contact_modes` those of the beam held at every contact point (`contact_modes`), written
!! to the result file and published (docs/output.md, "Natural modes"), and the frequencies
!! as the run prints them (`frequencies_text`).
module vibrobeam_modal_analysis
   use vibrobeam_status, only: stat_ok, outcome_interrupted
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_reduction, only: contact_modes
   use vibrobeam_result_files, only: result_files, run_summary, run_outcome
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_text, only: integer_text, significant_text
   implicit none
   private
   public :: run_modal, frequencies_text, printed_digits

   !> Significant digits of the frequencies a modes run prints: 9, a rounding of 5e-9
   !! relative at most, below the discretization error of every mode but the first of a
   !! fine mesh (mode 1 of the steel cantilever at N = 64 is within 5e-10 of the closed
   !! form, mode 2 within 2e-8; README), so the digits shown show that error.
   integer, parameter :: printed_digits = 9

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
      real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:), contact_omega(:), contact_shapes(:,:)
      type(result_files) :: files
      type(progress_meter) :: meter
      type(run_summary) :: summary
      call meter%init(scene%output%progress)
      call compute_modes(prepared%model, scene%analysis%modes, omega, shapes, vectors, stat, errmsg)
      if (stat /= stat_ok) return
      if (scene%analysis%contact_modes) then
         ! the beam held at every contact point (as many modes as asked, or as it has)
         call contact_modes(prepared%model, prepared%contacts, &
                            min(scene%analysis%modes, prepared%model%unknowns - prepared%contacts%count), &
                            contact_omega, contact_shapes, stat, errmsg)
         if (stat /= stat_ok) return
      end if
      call files%open(scene, prepared%model, stat, errmsg)
      if (stat == stat_ok) call files%write_modes(omega, shapes, stat, errmsg)
      if (stat == stat_ok .and. scene%analysis%contact_modes) &
         call files%write_modes(contact_omega, contact_shapes, stat, errmsg, '/contact_modes')
      summary%wall_seconds = meter%elapsed()
      if (interrupt_requested()) summary%status = outcome_interrupted
      call files%finish(summary, meter, outcome%text_skipped, stat, errmsg)
      if (stat /= stat_ok) return
      outcome%status = summary%status
      outcome%wall_seconds = summary%wall_seconds
      outcome%run_id = files%run_id
      call move_alloc(omega, outcome%omega)
   end subroutine run_modal

   !> One line per mode, '  mode 1: omega = 209.988357 rad/s, f = 33.4206641 Hz', as --check
   !! lists the closed-form frequencies; omega in rad/s (ascending).
   function frequencies_text(omega) result(text)
      real(dp), intent(in) :: omega(:)
      character(len=:), allocatable :: text
      integer :: n
      text = ''
      do n = 1, size(omega)
         text = text//'  mode '//integer_text(n)//': omega = '//significant_text(omega(n), printed_digits)// &
                ' rad/s, f = '//significant_text(omega(n)/(2*pi), printed_digits)//' Hz'//new_line('a')
      end do
   end function frequencies_text
end module vibrobeam_modal_analysis
