!> The natural frequencies of the structure a scene describes (`structure_of`), which the
!! checks, warnings and advice use before a run has its own model (`scene_frequencies`),
!! and the warnings for intermediate supports and section ends off the nodes.
module vibrobeam_scene_structure
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type, structure_of
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_model, only: beam_model
   use vibrobeam_modes, only: reference_frequencies
   implicit none
   private
   public :: scene_frequencies, off_node_warnings

contains

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

   !> One line per intermediate support, and per section end, that is not on a node of
   !! `model` (further than 1e-9 h): it acts at its nearest node (docs/input.md, "&supports",
   !! "&sections"; the last section's end is L, a node).
   function off_node_warnings(scene, model) result(text)
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      character(len=:), allocatable :: text
      integer :: i
      integer, allocatable :: nodes(:)
      text = ''
      if (allocated(scene%supports)) then
         do i = 1, size(scene%supports)
            if (abs(model%x(model%support_node(i) + 1) - scene%supports(i)%x) <= 1e-9_dp*model%h) cycle
            text = text//'&supports x('//integer_text(i)//') = '//real_text(scene%supports(i)%x)// &
                   ' m is not on a node; the support acts at the nearest node x = '// &
                   real_text(model%x(model%support_node(i) + 1))//' m'//new_line('a')
         end do
      end if
      nodes = model%structure%section_nodes(model%elements, model%length)
      do i = 1, size(nodes) - 1
         if (abs(model%x(nodes(i) + 1) - scene%beam%sections(i)%x_to) <= 1e-9_dp*model%h) cycle
         text = text//'&sections x_to('//integer_text(i)//') = '//real_text(scene%beam%sections(i)%x_to)// &
                ' m is not on a node; the section ends at the nearest node x = '//real_text(model%x(nodes(i) + 1))// &
                ' m'//new_line('a')
      end do
   end function off_node_warnings
end module vibrobeam_scene_structure
