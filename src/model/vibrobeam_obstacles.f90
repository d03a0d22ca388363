!> The obstacles as the input gives them (&obstacles, docs/input.md): each a flat or
!! sloped surface below or above the beam over [x_from, x_to], rigid or compliant, every
!! variable declared once in `visit_obstacles` (`vibrobeam_schema_visitor`).
module vibrobeam_obstacles
   use vibrobeam_kinds, only: dp
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, keyword_length
   implicit none
   private
   public :: obstacle_type, max_obstacles, visit_obstacles

   integer, parameter :: max_obstacles = 32       !! most obstacles a scene may hold

   !> One obstacle of `&obstacles` (docs/input.md).
   type :: obstacle_type
      character(len=keyword_length) :: side = 'below'   !! 'below' (bounds u from below) | 'above'
      real(dp) :: x_from = 0, x_to = 0      !! extent along the beam (m)
      real(dp) :: level_from = 0, level_to = 0   !! surface height at x_from, x_to (m)
      !> 0: rigid (Newton's law, &impact); > 0: compliant stop with force stiffness p^exponent
      !! (N/m for a punctual obstacle, N/m per m of length for a longitudinal one; per unit
      !! rho S when the beam is given by k2), docs/theory.md section 8
      real(dp) :: stiffness = 0
      real(dp) :: exponent = 1                   !! 1 linear, 1.5 Hertz-like
      real(dp) :: damping = 0                    !! Hunt-Crossley alpha (s/m), compliant stops only
   end type obstacle_type

contains

   !> Every variable of &obstacles, once: `count`, then each obstacle's variables (element
   !! i of each array variable is obstacle i). The rows describe the variables even when
   !! there is no obstacle (element 0). The defaults that follow other inputs (x_from = L,
   !! x_to = x_from, level_to = level_from) and the variables required of each obstacle
   !! are the scene reader's.
   subroutine visit_obstacles(obstacles, count, visitor)
      type(obstacle_type), intent(inout) :: obstacles(:)
      integer, intent(inout) :: count            !! the obstacles given (size(obstacles) once read)
      class(schema_visitor), intent(inout) :: visitor
      type(obstacle_type) :: description
      integer :: i
      call visitor%variable(integer_row('obstacles', 'count', 0, max_obstacles, 'number of obstacles'), count)
      do i = 1, size(obstacles)
         call visit_one(obstacles(i), i)
      end do
      if (size(obstacles) == 0) call visit_one(description, 0)
   contains
      subroutine visit_one(o, i)
         type(obstacle_type), intent(inout) :: o
         integer, intent(in) :: i                  !! the obstacle (0: a description only)
         integer, parameter :: n = max_obstacles
         call visitor%variable(keyword_row('obstacles', 'side', 'below|above', keyword_length, &
                                           'below: bounds u from below (g1); above: from above (g2)', n, i), o%side)
         call visitor%variable(real_row('obstacles', 'x_from', 'm', 0.0_dp, 1e6_dp, &
                                        'start of the obstacle along the beam', n, i), o%x_from)
         call visitor%variable(real_row('obstacles', 'x_to', 'm', 0.0_dp, 1e6_dp, &
                                        'end of the obstacle (x_from: a punctual obstacle)', n, i), o%x_to)
         call visitor%variable(real_row('obstacles', 'level_from', 'm', -1e6_dp, 1e6_dp, &
                                        'height of the obstacle surface at x_from', n, i), o%level_from)
         call visitor%variable(real_row('obstacles', 'level_to', 'm', -1e6_dp, 1e6_dp, &
                                        'height of the obstacle surface at x_to (linear in between)', n, i), o%level_to)
         call visitor%variable(real_row('obstacles', 'stiffness', 'N/m', 0.0_dp, 1e30_dp, &
                                        '0: a rigid stop; > 0: a compliant stop of force stiffness p^exponent', n, i), &
                               o%stiffness)
         call visitor%variable(real_row('obstacles', 'exponent', '', 1.0_dp, 3.0_dp, &
                                        'exponent of the compliant stop''s force (1 linear, 1.5 Hertz-like)', n, i), &
                               o%exponent)
         call visitor%variable(real_row('obstacles', 'damping', 's/m', 0.0_dp, 1e6_dp, &
                                        'Hunt-Crossley contact damping of a compliant stop', n, i), o%damping)
      end subroutine visit_one
   end subroutine visit_obstacles
end module vibrobeam_obstacles
