!> The sections of a non-uniform beam as the input gives them (&sections, docs/input.md):
!! piecewise-constant Young's modulus, density, area and inertia, section i from the end
!! of section i - 1 (x = 0 for the first) to x_to(i), the last at L. Each variable is
!! declared once in `visit_sections`, element by element like &supports; the beam keeps
!! them (`beam_settings%sections`) and the scene turns them into the model's sections
!! (`beam_structure`, theory §1, "Sections"). `check_sections` holds the rules between
!! them and the beam.
!!
!! The count is an optional row: a scene without &sections does not list it (its results
!! keep the attributes of earlier versions); read, it defaults to 0.
module vibrobeam_section_settings
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row
   implicit none
   private
   public :: section_settings, visit_sections, check_sections, max_sections, section_end_tolerance

   integer, parameter :: max_sections = 64   !! most sections a beam may have
   !> The last section's end must be L to this fraction of L.
   real(dp), parameter :: section_end_tolerance = 1e-9_dp

   !> One section of &sections: where it ends and its four data (required, each of them).
   type :: section_settings
      real(dp) :: x_to = 0                 !! end of the section (m)
      real(dp) :: youngs_modulus = 0       !! E (Pa)
      real(dp) :: density = 0              !! rho (kg/m^3)
      real(dp) :: area = 0                 !! S (m^2)
      real(dp) :: inertia = 0              !! I (m^4)
   contains
      procedure :: rho_s => section_rho_s  !! mass per unit length (kg/m)
      procedure :: ei => section_ei        !! bending stiffness (N m^2)
   end type section_settings

contains

   !> Every variable of &sections, once: `count`, then each section's variables (element i
   !! of each array variable is section i; element 0 only describes them). `count` is
   !! unset_integer when the group was not given. The ranges are those of &beam's data.
   subroutine visit_sections(sections, count, visitor)
      type(section_settings), intent(inout) :: sections(:)
      integer, intent(inout) :: count
      class(schema_visitor), intent(inout) :: visitor
      type(section_settings) :: description
      integer :: i
      call visitor%variable(integer_row('sections', 'count', 0, max_sections, &
                                        'number of sections of a non-uniform beam', optional=.true.), count)
      do i = 1, size(sections)
         call visit_one(sections(i), i)
      end do
      if (size(sections) == 0) call visit_one(description, 0)
   contains
      subroutine visit_one(s, i)
         type(section_settings), intent(inout) :: s
         integer, intent(in) :: i
         integer, parameter :: n = max_sections
         call visitor%variable(real_row('sections', 'x_to', 'm', 0.0_dp, 1e6_dp, &
                                        'end of the section (on its nearest node; the last at L)', n, i), s%x_to)
         call visitor%variable(real_row('sections', 'youngs_modulus', 'Pa', 1.0_dp, 1e13_dp, &
                                        'Young''s modulus E of the section', n, i), s%youngs_modulus)
         call visitor%variable(real_row('sections', 'density', 'kg/m^3', 1e-2_dp, 1e6_dp, 'density rho of the section', &
                                        n, i), s%density)
         call visitor%variable(real_row('sections', 'area', 'm^2', 1e-20_dp, 1e4_dp, 'cross-section area S of the section', &
                                        n, i), s%area)
         call visitor%variable(real_row('sections', 'inertia', 'm^4', 1e-42_dp, 1e8_dp, &
                                        'second moment of area I of the section', n, i), s%inertia)
      end subroutine visit_one
   end subroutine visit_sections

   !> rho S (kg/m).
   elemental real(dp) function section_rho_s(self)
      class(section_settings), intent(in) :: self
      section_rho_s = self%density*self%area
   end function section_rho_s

   !> E I (N m^2).
   elemental real(dp) function section_ei(self)
      class(section_settings), intent(in) :: self
      section_ei = self%youngs_modulus*self%inertia
   end function section_ei

   !> The rules between the sections and the beam (docs/input.md, "&sections"): the ends
   !! increasing, inside (0, L], the last at L (to `section_end_tolerance` L); on a mesh of
   !! N elements each section keeps at least one element once its ends move to their
   !! nearest nodes. stat = stat_failure and a message naming the variable otherwise.
   subroutine check_sections(sections, length, elements, stat, errmsg)
      type(section_settings), intent(in) :: sections(:)
      real(dp), intent(in) :: length      !! L (m)
      integer, intent(in) :: elements     !! N
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i, n, node, previous
      real(dp) :: start
      character(len=:), allocatable :: item
      stat = 0
      errmsg = ''
      n = size(sections)
      if (n == 0) return
      stat = stat_failure
      previous = 0
      start = 0
      do i = 1, n
         item = '('//integer_text(i)//')'
         associate (x => sections(i)%x_to)
            if (.not. x > start) then
               if (i == 1) then
                  errmsg = '&sections x_to'//item//' = '//real_text(x)//' m: a section ends after x = 0'
               else
                  errmsg = '&sections x_to'//item//' = '//real_text(x)//' m is not after x_to('//integer_text(i - 1)// &
                           ') = '//real_text(start)//' m: give the section ends in increasing order'
               end if
               return
            end if
            if (i < n .and. x >= length) then
               errmsg = '&sections x_to'//item//' = '//real_text(x)//' m reaches the end of the beam (length = '// &
                        real_text(length)//' m) before the last section (count = '//integer_text(n)//'): the '// &
                        'last section ends at L; give count = '//integer_text(i)//', or ends inside the beam'
               return
            end if
            if (i == n .and. abs(x - length) > section_end_tolerance*length) then
               errmsg = '&sections x_to'//item//' = '//real_text(x)//' m: the last section must end at the end of '// &
                        'the beam, &beam length = '//real_text(length)//' m (the sections cover the whole beam)'
               return
            end if
            node = min(elements, nint(x/length*elements))
            if (i == n) node = elements
            if (node <= previous) then
               errmsg = '&sections x_to'//item//' = '//real_text(x)//' m and the section''s start '// &
                        real_text(start)//' m move to the same node x = '// &
                        real_text(node*length/elements)//' m of &mesh elements = '//integer_text(elements)// &
                        ': the section has no element; refine the mesh or merge the sections'
               return
            end if
            previous = node
            start = x
         end associate
      end do
      stat = 0
      errmsg = ''
   end subroutine check_sections
end module vibrobeam_section_settings
