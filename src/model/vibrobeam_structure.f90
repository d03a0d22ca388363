!> What a beam carries beyond a uniform bending stiffness and mass (theory §1, "Supports",
!! "Point masses", "Sections" and "Axial force"): its end supports and end springs,
!! intermediate supports, point masses, piecewise-constant sections and an axial force, as
!! `build_model` takes them (positions in m, independent of the mesh: `build_model` puts
!! each intermediate support and each section end on its nearest node; values in the
!! model's units: N, kg, N m^2 and kg/m, or per unit rho S when the beam is given by k2).
!! The scene turns the input (&beam, &supports, &masses, &sections, docs/input.md) into
!! this.
module vibrobeam_structure
   use vibrobeam_kinds, only: dp
   use vibrobeam_boundary, only: boundary_conditions
   implicit none
   private
   public :: beam_structure, support_pinned, support_clamped, support_spring, support_kind_names, support_kind_code

   integer, parameter :: support_pinned = 1, support_clamped = 2, support_spring = 3
   character(len=*), parameter :: support_kind_names = 'pinned|clamped|spring'

   !> Everything of the beam beyond EI and rho S of &beam; the defaults are today's
   !! uniform clamped-free beam without tension.
   type :: beam_structure
      type(boundary_conditions) :: boundary            !! end supports and end springs
      real(dp) :: axial_force = 0                      !! T (N), positive in tension
      !> intermediate supports: where each acts (m, in (0, L); on its nearest node), its kind
      !! (support_pinned: deflection held; support_clamped: deflection and rotation held;
      !! support_spring: springs only) and its springs (N/m, N m/rad; they act with every kind)
      real(dp), allocatable :: support_x(:)
      integer, allocatable :: support_kind(:)
      real(dp), allocatable :: support_stiffness(:), support_rotational_stiffness(:)
      !> point masses: position (m), mass (kg) and rotary inertia (kg m^2)
      real(dp), allocatable :: mass_position(:), mass_value(:), mass_rotary_inertia(:)
      !> sections of piecewise-constant rho S (kg/m) and EI (N m^2): section i ends at
      !! section_end(i) (m, increasing, the last at L; `build_model` moves each end to its
      !! nearest node) and begins where section i - 1 ends (at 0 for the first); unallocated
      !! or empty: uniform, the values given to `build_model`
      real(dp), allocatable :: section_end(:), section_rho_s(:), section_ei(:)
   contains
      procedure :: supports => structure_supports
      procedure :: masses => structure_masses
      procedure :: has_sections
      procedure :: sections => structure_sections
      procedure :: section_nodes
      procedure :: element_properties
      procedure :: rigid_motions => structure_rigid_motions
      procedure :: held_count => structure_held_count
      procedure :: has_closed_form => structure_has_closed_form
   end type beam_structure

contains

   !> The code of an intermediate support's kind ('pinned', ...); 0 for another name.
   pure integer function support_kind_code(text)
      character(len=*), intent(in) :: text
      select case (trim(text))
      case ('pinned')
         support_kind_code = support_pinned
      case ('clamped')
         support_kind_code = support_clamped
      case ('spring')
         support_kind_code = support_spring
      case default
         support_kind_code = 0
      end select
   end function support_kind_code

   !> Number of intermediate supports.
   pure integer function structure_supports(self)
      class(beam_structure), intent(in) :: self
      structure_supports = 0
      if (allocated(self%support_x)) structure_supports = size(self%support_x)
   end function structure_supports

   !> Number of point masses.
   pure integer function structure_masses(self)
      class(beam_structure), intent(in) :: self
      structure_masses = 0
      if (allocated(self%mass_position)) structure_masses = size(self%mass_position)
   end function structure_masses

   !> How many rigid-body motions u = a + b x the structure leaves free (0, 1 or 2; theory
   !! §1, "Supports"): each held deflection and translational spring (ends, intermediate
   !! supports) removes the combination a + b x that vanishes at its position, each held
   !! rotation or rotational spring removes b, and so does a tensile axial force (its
   !! energy T int u'^2 = T b^2 L). K is singular exactly when this is positive.
   pure integer function structure_rigid_motions(self, length)
      class(beam_structure), intent(in) :: self
      real(dp), intent(in) :: length   !! L (m)
      real(dp) :: positions(2*self%supports() + 2)
      logical :: slope
      integer :: s, held
      held = 0
      associate (b => self%boundary)
         slope = b%holds_rotation(1) .or. b%holds_rotation(2) .or. b%left_rotational_spring > 0 .or. &
                 b%right_rotational_spring > 0 .or. self%axial_force > 0
         if (b%holds_deflection(1) .or. b%left_spring > 0) then
            held = held + 1
            positions(held) = 0
         end if
         if (b%holds_deflection(2) .or. b%right_spring > 0) then
            held = held + 1
            positions(held) = length
         end if
      end associate
      do s = 1, self%supports()
         if (self%support_kind(s) /= support_spring .or. self%support_stiffness(s) > 0) then
            held = held + 1
            positions(held) = self%support_x(s)
         end if
         if (self%support_kind(s) == support_clamped .or. self%support_rotational_stiffness(s) > 0) slope = .true.
      end do
      ! the values held at two distinct points, or at one point and the slope, fix a and b
      if (held > 0) then
         if (any(abs(positions(1:held) - positions(1)) > 0) .or. slope) then
            structure_rigid_motions = 0
         else
            structure_rigid_motions = 1
         end if
      else
         structure_rigid_motions = merge(1, 2, slope)
      end if
   end function structure_rigid_motions

   !> How many conditions the supports impose on the displacement (a held deflection or
   !! rotation each, ends and intermediate supports): the mesh's unknowns are its degrees
   !! of freedom less these, in both bases (two supports on one node count twice).
   pure integer function structure_held_count(self)
      class(beam_structure), intent(in) :: self
      integer :: s
      structure_held_count = self%boundary%held_count()
      do s = 1, self%supports()
         if (self%support_kind(s) == support_pinned) structure_held_count = structure_held_count + 1
         if (self%support_kind(s) == support_clamped) structure_held_count = structure_held_count + 2
      end do
   end function structure_held_count

   !> Are the natural frequencies known in closed form (theory §7): a uniform beam on two
   !! end supports, without springs, intermediate supports, point masses or axial force?
   pure logical function structure_has_closed_form(self)
      class(beam_structure), intent(in) :: self
      structure_has_closed_form = self%boundary%has_closed_form() .and. self%supports() == 0 .and. &
                                  self%masses() == 0 .and. .not. self%has_sections() .and. &
                                  .not. abs(self%axial_force) > 0
   end function structure_has_closed_form

   !> Are rho S and EI given section by section?
   pure logical function has_sections(self)
      class(beam_structure), intent(in) :: self
      has_sections = self%sections() > 0
   end function has_sections

   !> The node (0..N) where each section ends on a mesh of N elements of [0, L]: the one
   !! nearest its end, the last section's at N (its end is L). Section i spans the elements
   !! section_nodes(i - 1) + 1 .. section_nodes(i) (none when the two ends share a node).
   pure function section_nodes(self, elements, length) result(nodes)
      class(beam_structure), intent(in) :: self
      integer, intent(in) :: elements   !! N
      real(dp), intent(in) :: length    !! L (m)
      integer :: nodes(self%sections())
      integer :: i
      do i = 1, self%sections()
         nodes(i) = min(elements, max(0, nint(self%section_end(i)/length*elements)))
      end do
      if (self%sections() > 0) nodes(self%sections()) = elements
   end function section_nodes

   !> rho S (kg/m) and EI (N m^2) of each of N elements of [0, L]: section i on the
   !! elements between the nodes nearest its ends (`section_nodes`); `rho_s` and `ei` on
   !! every element of a beam without sections.
   pure subroutine element_properties(self, elements, length, rho_s, ei, element_rho_s, element_ei)
      class(beam_structure), intent(in) :: self
      integer, intent(in) :: elements                   !! N
      real(dp), intent(in) :: length, rho_s, ei         !! L (m), the uniform beam's rho S and EI
      real(dp), allocatable, intent(out) :: element_rho_s(:), element_ei(:)   !! (N)
      integer :: nodes(self%sections()), i, first
      allocate (element_rho_s(elements), source=rho_s)
      allocate (element_ei(elements), source=ei)
      nodes = self%section_nodes(elements, length)
      first = 1
      do i = 1, size(nodes)
         element_rho_s(first:nodes(i)) = self%section_rho_s(i)
         element_ei(first:nodes(i)) = self%section_ei(i)
         first = max(first, nodes(i) + 1)
      end do
   end subroutine element_properties

   !> Number of sections (0: a uniform beam).
   pure integer function structure_sections(self)
      class(beam_structure), intent(in) :: self
      structure_sections = 0
      if (allocated(self%section_end)) structure_sections = size(self%section_end)
   end function structure_sections
end module vibrobeam_structure
