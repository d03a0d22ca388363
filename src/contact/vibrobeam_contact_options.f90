!> How the contact problems are solved, as the input gives it (&solver, docs/input.md),
!! each variable declared once in `visit_solver` (`vibrobeam_schema_visitor`).
module vibrobeam_contact_options
   use vibrobeam_kinds, only: dp
   use vibrobeam_schema_visitor, only: schema_visitor, integer_row, keyword_row, real_row, keyword_length
   implicit none
   private
   public :: contact_options, visit_solver

   !> &solver.
   type :: contact_options
      character(len=keyword_length) :: contact_solver = 'auto'     !! 'auto' | 'delassus' | 'band'
      character(len=keyword_length) :: contact_method = 'newton'   !! 'newton' | 'pivoting'
      integer :: contact_max_iterations = 0                        !! pivots per projection; 0: the default
      !> statics: the largest derived round-off bound of a nodal displacement accepted (m);
      !! 0: any (docs/method.md, "Statics")
      real(dp) :: static_tolerance = 0
   end type contact_options

contains

   !> Every variable of &solver, once (docs/input.md, "&solver").
   subroutine visit_solver(solver, visitor)
      type(contact_options), intent(inout) :: solver
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(keyword_row('solver', 'contact_solver', 'auto|delassus|band', keyword_length, &
                                        'linear algebra of the contact projection: Delassus blocks or band solves'), &
                            solver%contact_solver)
      call visitor%variable(keyword_row('solver', 'contact_method', 'newton|pivoting', keyword_length, &
                                        'contact projection: active set with interior point, or principal pivoting'), &
                            solver%contact_method)
      call visitor%variable(integer_row('solver', 'contact_max_iterations', 0, huge(1), &
                                        'pivots allowed per projection (0: the default)'), solver%contact_max_iterations)
      call visitor%variable(real_row('solver', 'static_tolerance', 'm', 0.0_dp, 1e6_dp, &
                                     'largest round-off bound of a static displacement accepted (0: any)'), &
                            solver%static_tolerance)
   end subroutine visit_solver
end module vibrobeam_contact_options
