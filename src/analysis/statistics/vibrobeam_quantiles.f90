!> Quantiles of the chi-square and Student's t distributions, for confidence intervals
!! (docs/statistics.md: the band of a random load's measured density, the intervals of an
!! ensemble's means): bisection on the distribution functions, which come from the
!! regularized incomplete gamma and beta functions (their series and continued fractions,
!! evaluated by the modified Lentz method; Abramowitz & Stegun 6.5.29, 6.5.31, 26.5.8).
module vibrobeam_quantiles
   use vibrobeam_kinds, only: dp
   implicit none
   private
   public :: chi_square_quantile, student_quantile

   real(dp), parameter :: eps = epsilon(1.0_dp), small = tiny(1.0_dp)/epsilon(1.0_dp)

contains

   !> The quantile x of the chi-square distribution with nu > 0 degrees of freedom:
   !! P(chi2_nu <= x) = p, 0 < p < 1, by bisection on the regularized incomplete gamma
   !! function P(nu/2, x/2) to a relative 1e-13.
   real(dp) function chi_square_quantile(nu, p) result(x)
      real(dp), intent(in) :: nu, p
      real(dp) :: low, high
      integer :: i
      low = 0
      high = max(1.0_dp, 2*nu)
      do while (gamma_p(nu/2, high/2) < p)
         low = high
         high = 2*high
      end do
      do i = 1, 200
         x = (low + high)/2
         if (gamma_p(nu/2, x/2) < p) then
            low = x
         else
            high = x
         end if
         if (high - low <= 1e-13_dp*high) exit
      end do
      x = (low + high)/2
   end function chi_square_quantile

   !> The regularized lower incomplete gamma function P(a, x), a > 0, x >= 0: its series
   !! for x < a + 1, else 1 - Q(a, x) from Legendre's continued fraction (modified Lentz).
   real(dp) function gamma_p(a, x) result(p)
      real(dp), intent(in) :: a, x
      real(dp) :: term, total, prefactor, b, c, d, h, an, delta
      integer :: i
      if (x <= 0) then
         p = 0
         return
      end if
      prefactor = exp(-x + a*log(x) - log_gamma(a))
      if (x < a + 1) then
         term = 1/a
         total = term
         do i = 1, 10000
            term = term*x/(a + i)
            total = total + term
            if (abs(term) < abs(total)*eps) exit
         end do
         p = total*prefactor
      else
         b = x + 1 - a
         c = 1/small
         d = 1/b
         h = d
         do i = 1, 10000
            an = -i*(i - a)
            b = b + 2
            d = an*d + b
            if (abs(d) < small) d = small
            c = b + an/c
            if (abs(c) < small) c = small
            d = 1/d
            delta = d*c
            h = h*delta
            if (abs(delta - 1) < eps) exit
         end do
         p = 1 - prefactor*h
      end if
   end function gamma_p

   !> The quantile t of Student's t distribution with nu > 0 degrees of freedom,
   !! P(T <= t) = p, 1/2 <= p < 1, by bisection on P(T > t) = I_{nu/(nu + t^2)}(nu/2, 1/2)/2
   !! to a relative 1e-13.
   real(dp) function student_quantile(nu, p) result(t)
      real(dp), intent(in) :: nu, p
      real(dp) :: low, high
      integer :: i
      low = 0
      high = 1
      do while (upper_tail(high) > 1 - p)
         low = high
         high = 2*high
      end do
      do i = 1, 200
         t = (low + high)/2
         if (upper_tail(t) > 1 - p) then
            low = t
         else
            high = t
         end if
         if (high - low <= 1e-13_dp*high) exit
      end do
      t = (low + high)/2
   contains
      real(dp) function upper_tail(x)
         real(dp), intent(in) :: x
         upper_tail = beta_i(nu/(nu + x*x), nu/2, 0.5_dp)/2
      end function upper_tail
   end function student_quantile

   !> The regularized incomplete beta function I_x(a, b), a, b > 0, 0 <= x <= 1: its
   !! continued fraction at x for x < (a + 1)/(a + b + 2), else 1 - I_{1-x}(b, a) from the
   !! fraction at 1 - x (where it converges fast).
   real(dp) function beta_i(x, a, b) result(value)
      real(dp), intent(in) :: x, a, b
      real(dp) :: front
      if (x <= 0) then
         value = 0
         return
      end if
      if (x >= 1) then
         value = 1
         return
      end if
      front = exp(a*log(x) + b*log(1 - x) - (log_gamma(a) + log_gamma(b) - log_gamma(a + b)))
      if (x < (a + 1)/(a + b + 2)) then
         value = front*beta_fraction(x, a, b)/a
      else
         value = 1 - front*beta_fraction(1 - x, b, a)/b
      end if
   end function beta_i

   !> The continued fraction of I_x(a, b) (modified Lentz).
   real(dp) function beta_fraction(x, a, b) result(h)
      real(dp), intent(in) :: x, a, b
      real(dp) :: c, d, aa, delta
      integer :: m
      c = 1
      d = 1 - (a + b)*x/(a + 1)
      if (abs(d) < small) d = small
      d = 1/d
      h = d
      do m = 1, 10000
         aa = m*(b - m)*x/((a + 2*m - 1)*(a + 2*m))
         d = 1 + aa*d
         if (abs(d) < small) d = small
         c = 1 + aa/c
         if (abs(c) < small) c = small
         d = 1/d
         h = h*d*c
         aa = -(a + m)*(a + b + m)*x/((a + 2*m)*(a + 2*m + 1))
         d = 1 + aa*d
         if (abs(d) < small) d = small
         c = 1 + aa/c
         if (abs(c) < small) c = small
         d = 1/d
         delta = d*c
         h = h*delta
         if (abs(delta - 1) < eps) exit
      end do
   end function beta_fraction
end module vibrobeam_quantiles
