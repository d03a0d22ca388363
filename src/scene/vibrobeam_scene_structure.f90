!> The structure a scene describes, as the model takes it (`vibrobeam_structure`): the end
!! supports and springs of &beam (docs/input.md, "&beam"); and the natural frequencies of
!! that structure which the checks, warnings and advice use before a run has its own model
!! (`scene_frequencies`).
module vibrobeam_scene_structure
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type
   use vibrobeam_structure, only: beam_structure
   use vibrobeam_modes, only: reference_frequencies
   implicit none
   private
   public :: structure_of, scene_frequencies

contains

   !> What `build_model` takes of the scene beyond the uniform beam: its supports.
   pure function structure_of(scene) result(structure)
      type(scene_type), intent(in) :: scene
      type(beam_structure) :: structure
      structure%boundary = scene%beam%supports()
   end function structure_of

   !> The first size(omega) natural frequencies (rad/s, ascending, rigid-body motions at 0)
   !! of the scene's beam without its obstacles (`reference_frequencies`: the continuum's
   !! closed form where there is one, `closed_form`), and `first`, the first flexible one
   !! (index of the first omega > 0; 0 when there is none among them or they cannot be
   !! computed, then omega = 0).
   subroutine scene_frequencies(scene, omega, first, closed_form)
      type(scene_type), intent(in) :: scene
      real(dp), intent(out) :: omega(:)
      integer, intent(out) :: first
      logical, intent(out), optional :: closed_form
      logical :: exact
      integer :: stat
      character(len=256) :: errmsg
      call reference_frequencies(structure_of(scene), scene%beam%length, scene%beam%rho_s(), scene%beam%ei(), omega, &
                                 exact, stat, errmsg)
      if (stat /= 0) omega = 0
      if (present(closed_form)) closed_form = exact
      first = findloc(omega > 0, .true., dim=1)
   end subroutine scene_frequencies
end module vibrobeam_scene_structure
