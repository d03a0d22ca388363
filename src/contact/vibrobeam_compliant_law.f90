!> Compliant stops: the force law of one spring and its treatment over a time step
!! (docs/theory.md, section "8. Compliant stops").
!!
!! A spring j acts at contact point c_j from one side s_j (+1 below, -1 above) with level
!! g_j. Its penetration is p = s_j (g_j - H_c U) (> 0 inside the stop), its force on the
!! beam s_j f H_c^T with
!!
!!     f(p, pdot) = k p_+^a max(0, 1 + 3/2 alpha pdot)       (Hunt and Crossley 1975)
!!
!! and its stored energy Phi(p) = k p_+^(a+1) / (a + 1). The force vanishes at separation
!! (p <= 0) and never pulls (f >= 0). Over a step from p0 to p1 the elastic part is taken
!! either as the discrete gradient (Phi(p1) - Phi(p0)) / (p1 - p0) ('gradient': its work
!! is exactly Phi(p1) - Phi(p0), so a stop without damping conserves the discrete energy)
!! or as theta f(p1) + (1 - theta) f(p0) ('mean': Newmark's average acceleration for
!! theta = 1/2, the rule of code_aster's DYNA_NON_LINE). The damping factor uses
!! pdot = (p1 - p0) / dt in both.
module vibrobeam_compliant_law
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: spring_set, end_force, elastic_force, elastic_slope, stop_potential, step_force, rule_gradient, rule_mean, &
             rule_code

   integer, parameter :: rule_gradient = 1, rule_mean = 2

   !> The springs of a scene (one per compliant obstacle and covered node).
   type :: spring_set
      integer :: count = 0
      integer, allocatable :: point(:)        !! contact point index
      real(dp), allocatable :: sign(:)        !! +1 below (pushes up), -1 above
      real(dp), allocatable :: level(:)       !! g_j (m)
      real(dp), allocatable :: stiffness(:)   !! k_j lumped at the node (N/m^a; per unit rho S with k2)
      real(dp), allocatable :: exponent(:)    !! a_j >= 1
      real(dp), allocatable :: damping(:)     !! Hunt-Crossley alpha_j (s/m)
   end type spring_set

contains

   !> The code of a `&time compliant_rule` value, 0 if unknown.
   pure integer function rule_code(name)
      character(len=*), intent(in) :: name
      select case (name)
      case ('gradient')
         rule_code = rule_gradient
      case ('mean')
         rule_code = rule_mean
      case default
         rule_code = 0
      end select
   end function rule_code

   !> The force at the end of a step, k p1_+^a max(0, 1 + 3/2 alpha (p1 - p0)/dt) (N): what
   !! /contact/force reports.
   elemental real(dp) function end_force(k, a, alpha, dt, p0, p1)
      real(dp), intent(in) :: k, a, alpha, dt, p0, p1
      end_force = elastic_force(k, a, p1)
      if (alpha > 0) end_force = end_force*max(0.0_dp, 1 + 1.5_dp*alpha*(p1 - p0)/dt)
   end function end_force

   !> k p_+^a (N).
   elemental real(dp) function elastic_force(k, a, p)
      real(dp), intent(in) :: k, a, p
      elastic_force = 0
      if (p > 0) elastic_force = k*p**a
   end function elastic_force

   !> d/dp k p_+^a (N/m).
   elemental real(dp) function elastic_slope(k, a, p)
      real(dp), intent(in) :: k, a, p
      elastic_slope = 0
      if (p > 0) then
         if (abs(a - 1) > 0) then
            elastic_slope = k*a*p**(a - 1)
         else
            elastic_slope = k
         end if
      end if
   end function elastic_slope

   !> Phi(p) = k p_+^(a+1) / (a+1) (J).
   elemental real(dp) function stop_potential(k, a, p)
      real(dp), intent(in) :: k, a, p
      stop_potential = 0
      if (p > 0) stop_potential = k*p**(a + 1)/(a + 1)
   end function stop_potential

   !> The force of one spring over a step from p0 to p1 (f), its derivative with respect
   !! to p1 (slope, for Newton's method), and its elastic part alone (elastic), so that
   !! (f - elastic)(p1 - p0) >= 0 is the energy the contact damping takes; with
   !! `start_slope`, also its derivative with respect to p0 (the tangent of a step,
   !! `velocity_stepper%tangent`).
   pure subroutine step_force(rule, k, a, alpha, theta, dt, p0, p1, f, slope, elastic, start_slope)
      integer, intent(in) :: rule
      real(dp), intent(in) :: k, a, alpha, theta, dt, p0, p1
      real(dp), intent(out) :: f, slope, elastic
      real(dp), intent(out), optional :: start_slope
      real(dp) :: dp_, elastic_slope_, start_derivative, factor, scale
      ! below this relative separation of p0 and p1 the discrete gradient is replaced by the
      ! midpoint force, whose difference from it is a(a-1) k p^(a-1) dp^2 / 24: at 1e-5
      ! relative it is below 1e-11 of the force, while the quotient's cancellation would
      ! cost eps/1e-5 ~ 2e-11 of it (either way the energy error dp*df is round-off level)
      real(dp), parameter :: close = 1e-5_dp
      dp_ = p1 - p0
      select case (rule)
      case (rule_mean)
         elastic = theta*elastic_force(k, a, p1) + (1 - theta)*elastic_force(k, a, p0)
         elastic_slope_ = theta*elastic_slope(k, a, p1)
         start_derivative = (1 - theta)*elastic_slope(k, a, p0)
      case default
         scale = max(abs(p0), abs(p1))
         if (abs(dp_) > close*scale) then
            elastic = (stop_potential(k, a, p1) - stop_potential(k, a, p0))/dp_
            elastic_slope_ = (elastic_force(k, a, p1) - elastic)/dp_
            start_derivative = (elastic - elastic_force(k, a, p0))/dp_
         else
            elastic = elastic_force(k, a, 0.5_dp*(p0 + p1))
            elastic_slope_ = 0.5_dp*elastic_slope(k, a, 0.5_dp*(p0 + p1))
            start_derivative = elastic_slope_
         end if
      end select
      if (alpha > 0) then
         factor = 1 + 1.5_dp*alpha*dp_/dt
         if (factor > 0) then
            f = elastic*factor
            slope = elastic_slope_*factor + elastic*1.5_dp*alpha/dt
            start_derivative = start_derivative*factor - elastic*1.5_dp*alpha/dt
         else
            f = 0
            slope = 0
            start_derivative = 0
         end if
      else
         f = elastic
         slope = elastic_slope_
      end if
      if (present(start_slope)) start_slope = start_derivative
   end subroutine step_force
end module vibrobeam_compliant_law
