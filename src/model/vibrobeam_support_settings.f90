!> Intermediate supports (&supports) and point masses (&masses) as the input gives them
!! (docs/input.md), each variable declared once in `visit_supports` and `visit_masses`
!! (`vibrobeam_schema_visitor`), element by element like &obstacles; the scene turns them
!! into the model's `beam_structure` (`vibrobeam_scene_structure`).
!!
!! Both counts are optional rows: a scene that gives neither group lists neither (its
!! results keep the attributes of earlier versions); read, they default to 0.
module vibrobeam_support_settings
   use vibrobeam_kinds, only: dp
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, keyword_length
   use vibrobeam_structure, only: beam_structure, support_kind_names, support_kind_code
   use vibrobeam_beam_settings, only: beam_settings
   implicit none
   private
   public :: support_settings, mass_settings, visit_supports, visit_masses, max_supports, max_masses
   public :: structure_from

   integer, parameter :: max_supports = 64   !! most intermediate supports a scene may hold
   integer, parameter :: max_masses = 64     !! most point masses a scene may hold

   !> One intermediate support of &supports.
   type :: support_settings
      real(dp) :: x = 0                                   !! position (m), in (0, L): required
      character(len=keyword_length) :: kind = 'pinned'    !! 'pinned' | 'clamped' | 'spring'
      real(dp) :: stiffness = 0                           !! translational spring (N/m)
      real(dp) :: rotational_stiffness = 0                !! rotational spring (N m/rad)
   end type support_settings

   !> One point mass of &masses.
   type :: mass_settings
      real(dp) :: x = 0                    !! position (m), in [0, L]: required
      real(dp) :: mass = 0                 !! m (kg)
      real(dp) :: rotary_inertia = 0       !! J (kg m^2)
   end type mass_settings

contains

   !> Every variable of &supports, once: `count`, then each support's variables (element
   !! i of each array variable is support i; element 0 only describes them). `count` is
   !! unset_integer when the group was not given.
   subroutine visit_supports(supports, count, visitor)
      type(support_settings), intent(inout) :: supports(:)
      integer, intent(inout) :: count
      class(schema_visitor), intent(inout) :: visitor
      type(support_settings) :: description
      integer :: i
      call visitor%variable(integer_row('supports', 'count', 0, max_supports, 'number of intermediate supports', &
                                        optional=.true.), count)
      do i = 1, size(supports)
         call visit_one(supports(i), i)
      end do
      if (size(supports) == 0) call visit_one(description, 0)
   contains
      subroutine visit_one(s, i)
         type(support_settings), intent(inout) :: s
         integer, intent(in) :: i
         integer, parameter :: n = max_supports
         call visitor%variable(real_row('supports', 'x', 'm', 0.0_dp, 1e6_dp, &
                                        'position of the support (on its nearest node)', n, i), s%x)
         call visitor%variable(keyword_row('supports', 'kind', support_kind_names, keyword_length, &
                                           'pinned: deflection held; clamped: deflection and rotation; spring: springs only', &
                                           n, i), s%kind)
         call visitor%variable(real_row('supports', 'stiffness', 'N/m', 0.0_dp, 1e30_dp, &
                                        'translational spring of the support', n, i), s%stiffness)
         call visitor%variable(real_row('supports', 'rotational_stiffness', 'N m/rad', 0.0_dp, 1e30_dp, &
                                        'rotational spring of the support', n, i), s%rotational_stiffness)
      end subroutine visit_one
   end subroutine visit_supports

   !> Every variable of &masses, once, like `visit_supports`.
   subroutine visit_masses(masses, count, visitor)
      type(mass_settings), intent(inout) :: masses(:)
      integer, intent(inout) :: count
      class(schema_visitor), intent(inout) :: visitor
      type(mass_settings) :: description
      integer :: i
      call visitor%variable(integer_row('masses', 'count', 0, max_masses, 'number of point masses', optional=.true.), &
                            count)
      do i = 1, size(masses)
         call visit_one(masses(i), i)
      end do
      if (size(masses) == 0) call visit_one(description, 0)
   contains
      subroutine visit_one(m, i)
         type(mass_settings), intent(inout) :: m
         integer, intent(in) :: i
         integer, parameter :: n = max_masses
         call visitor%variable(real_row('masses', 'x', 'm', 0.0_dp, 1e6_dp, 'position of the point mass', n, i), m%x)
         call visitor%variable(real_row('masses', 'mass', 'kg', 0.0_dp, 1e15_dp, &
                                        'mass m of the point mass (per unit rho S, in m, when the beam is given by k2)', &
                                        n, i), m%mass)
         call visitor%variable(real_row('masses', 'rotary_inertia', 'kg m^2', 0.0_dp, 1e15_dp, &
                                        'rotary inertia J of the point mass (its rotation with the beam''s slope)', n, i), &
                               m%rotary_inertia)
      end subroutine visit_one
   end subroutine visit_masses

   !> The structure `build_model` takes (`vibrobeam_structure`) from &beam's supports,
   !! springs, axial force and sections (&sections), &supports and &masses as given.
   pure function structure_from(beam, supports, masses) result(structure)
      type(beam_settings), intent(in) :: beam
      type(support_settings), intent(in) :: supports(:)
      type(mass_settings), intent(in) :: masses(:)
      type(beam_structure) :: structure
      integer :: i
      structure%boundary = beam%supports()
      structure%axial_force = beam%tension()
      if (beam%sectioned()) then
         allocate (structure%section_end(size(beam%sections)), structure%section_rho_s(size(beam%sections)), &
                   structure%section_ei(size(beam%sections)))
         structure%section_end(:) = beam%sections%x_to
         structure%section_rho_s(:) = beam%sections%rho_s()
         structure%section_ei(:) = beam%sections%ei()
      end if
      allocate (structure%support_x(size(supports)), structure%support_kind(size(supports)), &
                structure%support_stiffness(size(supports)), structure%support_rotational_stiffness(size(supports)))
      do i = 1, size(supports)
         structure%support_x(i) = supports(i)%x
         structure%support_kind(i) = support_kind_code(supports(i)%kind)
         structure%support_stiffness(i) = supports(i)%stiffness
         structure%support_rotational_stiffness(i) = supports(i)%rotational_stiffness
      end do
      allocate (structure%mass_position(size(masses)), structure%mass_value(size(masses)), &
                structure%mass_rotary_inertia(size(masses)))
      do i = 1, size(masses)
         structure%mass_position(i) = masses(i)%x
         structure%mass_value(i) = masses(i)%mass
         structure%mass_rotary_inertia(i) = masses(i)%rotary_inertia
      end do
   end function structure_from
end module vibrobeam_support_settings
