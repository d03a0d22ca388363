!> What a beam carries beyond a uniform bending stiffness and mass (theory §1, "Supports,
!! masses, sections, tension"): its end supports and end springs, intermediate supports,
!! point masses, piecewise-constant sections and an axial force, as `build_model` takes
!! them (positions on the nodes of the mesh, values in the model's units: N, kg, N m^2 and
!! kg/m, or per unit rho S when the beam is given by k2). The scene turns the input
!! (&beam, &supports, &masses, &sections, docs/input.md) into this.
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
      !> intermediate supports: the node (1..N-1) each acts at, its kind (support_pinned:
      !! deflection held; support_clamped: deflection and rotation held; support_spring:
      !! springs only) and its springs (N/m, N m/rad; they act with every kind)
      integer, allocatable :: support_node(:), support_kind(:)
      real(dp), allocatable :: support_stiffness(:), support_rotational_stiffness(:)
      !> point masses: position (m), mass (kg) and rotary inertia (kg m^2)
      real(dp), allocatable :: mass_position(:), mass_value(:), mass_rotary_inertia(:)
      !> rho S (kg/m) and EI (N m^2) of each element (N): a beam of sections; unallocated:
      !! uniform, the values given to `build_model`
      real(dp), allocatable :: element_rho_s(:), element_ei(:)
   contains
      procedure :: supports => structure_supports
      procedure :: masses => structure_masses
      procedure :: has_sections
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
      if (allocated(self%support_node)) structure_supports = size(self%support_node)
   end function structure_supports

   !> Number of point masses.
   pure integer function structure_masses(self)
      class(beam_structure), intent(in) :: self
      structure_masses = 0
      if (allocated(self%mass_position)) structure_masses = size(self%mass_position)
   end function structure_masses

   !> Are rho S and EI given element by element?
   pure logical function has_sections(self)
      class(beam_structure), intent(in) :: self
      has_sections = allocated(self%element_ei)
   end function has_sections
end module vibrobeam_structure
