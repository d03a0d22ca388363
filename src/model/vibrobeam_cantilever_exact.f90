!> Closed-form free vibration of uniform Euler-Bernoulli beams (theory §7).
!!
!! Used for initial data in a natural mode and as the independent reference of the
!! verification tests. The frequency equation of a beam clamped at 0 and free at L is
!! `1 + cos(b) cosh(b) = 0`, b = beta L; a beam clamped at 0 and pinned at L (held by a
!! tip obstacle) has `tan(b) = tanh(b)`. The other pairs of end supports (Blevins,
!! "Formulas for natural frequency and mode shape", 1979, table 8-1; theory §7) have
!! `1 - cos(b) cosh(b) = 0` (clamped-clamped, free-free), `sin(b) = 0` (pinned-pinned,
!! sliding-sliding), `tan(b) + tanh(b) = 0` (clamped-sliding, sliding-free) and
!! `cos(b) = 0` (sliding-pinned); the last two have the roots n pi and (n - 1/2) pi, the
!! others are solved here by Newton's method on an overflow-free form (`newton_root`).
module vibrobeam_cantilever_exact
   use vibrobeam_kinds, only: dp, pi
   implicit none
   private
   public :: cantilever_root, pinned_tip_root, cantilever_frequency, cantilever_mode_shape
   public :: clamped_clamped_root, clamped_sliding_root

   !> The frequency equations `newton_root` solves.
   integer, parameter :: clamped_free = 1, clamped_pinned = 2, clamped_clamped = 3, clamped_sliding = 4

contains

   !> n-th positive root b of 1 + cos(b) cosh(b) = 0 (n >= 1), by Newton's method on the
   !! overflow-free form f(b) = cos(b) + 1/cosh(b).
   pure function cantilever_root(n) result(b)
      integer, intent(in) :: n   !! mode number, n >= 1
      real(dp) :: b
      b = (2*n - 1)*pi/2
      if (n == 1) b = 1.875_dp
      b = newton_root(clamped_free, b)
   end function cantilever_root

   !> n-th positive root b of tan(b) = tanh(b) (clamped-pinned and pinned-free beams), by
   !! Newton's method on f(b) = sin(b) - cos(b) tanh(b), from (n + 1/4) pi.
   pure function pinned_tip_root(n) result(b)
      integer, intent(in) :: n   !! mode number, n >= 1
      real(dp) :: b
      b = newton_root(clamped_pinned, (4*n + 1)*pi/4)
   end function pinned_tip_root

   !> n-th positive root b of 1 - cos(b) cosh(b) = 0 (clamped-clamped and free-free beams),
   !! by Newton's method on f(b) = cos(b) - 1/cosh(b), from (n + 1/2) pi (the roots approach
   !! it like 2 exp(-b): 4.7300, 7.8532, ...).
   pure function clamped_clamped_root(n) result(b)
      integer, intent(in) :: n   !! mode number, n >= 1
      real(dp) :: b
      b = newton_root(clamped_clamped, (2*n + 1)*pi/2)
   end function clamped_clamped_root

   !> n-th positive root b of tan(b) + tanh(b) = 0 (clamped-sliding and sliding-free beams),
   !! by Newton's method on f(b) = sin(b) + cos(b) tanh(b), from (n - 1/4) pi (2.3650,
   !! 5.4978, ...).
   pure function clamped_sliding_root(n) result(b)
      integer, intent(in) :: n   !! mode number, n >= 1
      real(dp) :: b
      b = newton_root(clamped_sliding, (4*n - 1)*pi/4)
   end function clamped_sliding_root

   !> Newton's method on the overflow-free form f of frequency equation `equation` from b,
   !! until the step is within 4 eps of the root.
   pure function newton_root(equation, start) result(b)
      integer, intent(in) :: equation
      real(dp), intent(in) :: start
      real(dp) :: b
      real(dp) :: f, df
      integer :: iteration
      b = start
      do iteration = 1, 50
         select case (equation)
         case (clamped_free)
            f = cos(b) + 1.0_dp/cosh(b)
            df = -sin(b) - tanh(b)/cosh(b)
         case (clamped_pinned)
            f = sin(b) - cos(b)*tanh(b)
            df = cos(b) + sin(b)*tanh(b) - cos(b)/cosh(b)**2
         case (clamped_clamped)
            f = cos(b) - 1.0_dp/cosh(b)
            df = -sin(b) + tanh(b)/cosh(b)
         case default
            f = sin(b) + cos(b)*tanh(b)
            df = cos(b) - sin(b)*tanh(b) + cos(b)/cosh(b)**2
         end select
         b = b - f/df
         if (abs(f/df) <= 4*epsilon(b)*b) exit
      end do
   end function newton_root

   !> Natural angular frequency (rad/s) of mode n of a cantilever of length `length` (m)
   !! with k2 = EI/(rho S) (m^4/s^2): omega_n = (beta_n L)^2 sqrt(k2)/L^2.
   pure function cantilever_frequency(n, length, k2) result(omega)
      integer, intent(in) :: n
      real(dp), intent(in) :: length, k2
      real(dp) :: omega
      omega = cantilever_root(n)**2*sqrt(k2)/length**2
   end function cantilever_frequency

   !> Derivative of order `order` (0..3) with respect to x of the n-th cantilever mode
   !! shape at x, normalized so that the shape equals 1 at the tip x = L.
   !!
   !! The classical form cosh(a) - cos(a) - s (sinh(a) - sin(a)), a = beta x, loses all
   !! digits for high modes (cosh and s sinh cancel); we write s = 1 - d with
   !! d = (sin(B) - cos(B) - exp(-B))/(sinh(B) + sin(B)), B = beta L, so that
   !! cosh(a) - s sinh(a) = exp(-a) + d sinh(a) is evaluated without cancellation.
   pure function cantilever_mode_shape(n, x, length, order) result(value)
      integer, intent(in) :: n        !! mode number, n >= 1
      real(dp), intent(in) :: x       !! position (m), 0 <= x <= length
      real(dp), intent(in) :: length  !! beam length (m)
      integer, intent(in) :: order    !! derivative order, 0..3
      real(dp) :: value
      real(dp) :: beta
      beta = cantilever_root(n)/length
      value = unnormalized(beta*x, order)*beta**order/unnormalized(beta*length, 0)
   contains
      pure function unnormalized(a, derivative) result(phi)
         real(dp), intent(in) :: a
         integer, intent(in) :: derivative
         real(dp) :: phi, big_b, d, s
         big_b = beta*length
         d = (sin(big_b) - cos(big_b) - exp(-big_b))/(sinh(big_b) + sin(big_b))
         s = 1.0_dp - d
         select case (derivative)
         case (0)
            phi = exp(-a) + d*sinh(a) - cos(a) + s*sin(a)
         case (1)
            phi = -exp(-a) + d*cosh(a) + sin(a) + s*cos(a)
         case (2)
            phi = exp(-a) + d*sinh(a) + cos(a) - s*sin(a)
         case default
            phi = -exp(-a) + d*cosh(a) - sin(a) - s*cos(a)
         end select
      end function unnormalized
   end function cantilever_mode_shape
end module vibrobeam_cantilever_exact
