!> How time is stepped, as the input gives it: &time (the scheme, its step and parameters)
!! and &impact (Newton's law at the rigid stops), each variable declared once in
!! `visit_time` and `visit_impact` (`vibrobeam_schema_visitor`; docs/input.md). The
!! schemes allowed are the factory's (`scheme_names`).
module vibrobeam_time_settings
   use vibrobeam_kinds, only: dp
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, keyword_row, keyword_length
   use vibrobeam_stepper_factory, only: scheme_names
   implicit none
   private
   public :: time_settings, impact_settings, visit_time, visit_impact

   !> &time.
   type :: time_settings
      real(dp) :: t_end = 1                    !! simulated time (s)
      real(dp) :: dt = 1e-4_dp                 !! time step (s)
      character(len=keyword_length) :: scheme = 'velocity'
      real(dp) :: theta = 0.5_dp, gamma = 0.5_dp
      !> force of a compliant stop over a step: 'gradient' (discrete gradient of its potential,
      !! conserves energy) or 'mean' (theta-weighted mean of the end forces, Newmark's rule)
      character(len=keyword_length) :: compliant_rule = 'gradient'
   end type time_settings

   !> &impact.
   type :: impact_settings
      real(dp) :: restitution = 1
      character(len=keyword_length) :: separating_points = 'elastic'   !! restitution of active points moving away
   end type impact_settings

contains

   !> Every variable of &impact, once (docs/input.md, "&impact").
   subroutine visit_impact(impact, visitor)
      type(impact_settings), intent(inout) :: impact
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(real_row('impact', 'restitution', '', 0.0_dp, 1.0_dp, &
                                     'Newton restitution coefficient e (1 elastic, 0 plastic)'), impact%restitution)
      call visitor%variable(keyword_row('impact', 'separating_points', 'elastic|restitution', keyword_length, &
                                        'restitution of an active point already moving away: 1 or e'), &
                            impact%separating_points)
   end subroutine visit_impact

   !> Every variable of &time, once (docs/input.md, "&time").
   subroutine visit_time(time, visitor)
      type(time_settings), intent(inout) :: time
      class(schema_visitor), intent(inout) :: visitor
      call visitor%variable(real_row('time', 't_end', 's', 1e-15_dp, 1e12_dp, 'simulated time'), time%t_end)
      call visitor%variable(real_row('time', 'dt', 's', 1e-18_dp, 1e12_dp, 'time step'), time%dt)
      call visitor%variable(keyword_row('time', 'scheme', scheme_names(), keyword_length, &
                                        'velocity-based scheme or the position-based Paoli-Schatzman scheme'), &
                            time%scheme)
      call visitor%variable(real_row('time', 'theta', '', 0.5_dp, 1.0_dp, 'theta of the theta-method'), time%theta)
      call visitor%variable(real_row('time', 'gamma', '', 0.0_dp, 1.0_dp, &
                                     'contact activation at U + gamma dt V (velocity scheme)'), time%gamma)
      call visitor%variable(keyword_row('time', 'compliant_rule', 'gradient|mean', keyword_length, &
                                        'force of a compliant stop over a step: discrete gradient or theta-mean'), &
                            time%compliant_rule)
   end subroutine visit_time
end module vibrobeam_time_settings
