!> Portable, counter-based random numbers for the random loads (docs/method.md, "Random
!! signals"; docs/theory.md section 9).
!!
!! The generator is Philox4x32-10 of J. K. Salmon, M. A. Moraes, R. O. Dror and D. E. Shaw,
!! "Parallel random numbers: as easy as 1, 2, 3", Proc. SC11 (2011), doi:10.1145/2063384.2063405:
!! a keyed bijection of a 128-bit counter, ten rounds of two 32 x 32 -> 64-bit products and
!! exclusive ors. Its output for a counter depends on nothing else: no state is carried from
!! one number to the next, so the k-th number of a stream is computed directly, in any
!! order, on any thread or process, and a run continued from any step reproduces it. It is
!! written here with 64-bit integers that hold 32-bit words and never overflow (a product
!! is split into 16-bit halves), so it is exact on every machine and compiler; the test
!! `unit.test_random` checks the published known-answer vectors of Random123.
!!
!! Normal deviates come in pairs from Marsaglia's polar method (G. Marsaglia, T. A. Bray,
!! SIAM Review 6 (1964) 260-264): x, y uniform in [-1, 1) from one Philox block, accepted
!! when 0 < s = x^2 + y^2 < 1, giving x f and y f with f = sqrt(-2 ln s / s). Pair number k
!! of a stream tries the counters (k, attempt 0), (k, attempt 1), ... until one is
!! accepted (probability pi/4 each), so every pair is a function of (key, stream, k) alone.
!! The logarithm is `portable_log`, written with +, -, *, / only (libm's log may differ in
!! the last bit between libraries and processors: glibc picks a variant with fused
!! multiply-adds on processors that have them); with sqrt, these are correctly rounded by
!! IEEE 754, and this file is compiled without contraction into fused multiply-adds
!! (src/core/CMakeLists.txt), so the deviates are the same bits everywhere. For the same
!! reason the filter of a random signal takes its window and its spatial correlation from
!! `portable_sin_pi` and `portable_exp` (`vibrobeam_random_signal`).
module vibrobeam_random
   use vibrobeam_kinds, only: dp, int64
   implicit none
   private
   public :: philox4x32, gaussian_pair, portable_log, portable_exp, portable_sin_pi, random_key

   integer(int64), parameter :: mask32 = 4294967295_int64        !! 2^32 - 1
   integer(int64), parameter :: mask16 = 65535_int64
   ! the round multipliers and key increments of Philox4x32 [Salmon et al. 2011, section 4.1]
   integer(int64), parameter :: multiplier(2) = [int(z'D2511F53', int64), int(z'CD9E8D57', int64)]
   integer(int64), parameter :: key_step(2) = [int(z'9E3779B9', int64), int(z'BB67AE85', int64)]
   !> second key word of vibrobeam's streams ('vibr' in ASCII): the first is the seed
   integer(int64), parameter :: domain_tag = int(z'76696272', int64)
   !> attempts of the polar method before giving up on a pair (each fails with probability
   !! 1 - pi/4 = 0.215: 200 failures in a row have probability 1e-133)
   integer, parameter :: max_attempts = 200

contains

   !> The key of a seed and a realisation (non-negative integers): (seed mod 2^32, the
   !! domain tag + realisation mod 2^32). Distinct (seed, realisation) pairs give
   !! distinct keys, hence independent streams.
   pure function random_key(seed, realisation) result(key)
      integer, intent(in) :: seed
      integer(int64), intent(in) :: realisation
      integer(int64) :: key(2)
      key = [iand(int(seed, int64), mask32), iand(domain_tag + realisation, mask32)]
   end function random_key

   !> Philox4x32-10: four 32-bit words (held in 64-bit integers, each in [0, 2^32)) from a
   !! counter of four words and a key of two.
   pure function philox4x32(counter, key) result(words)
      integer(int64), intent(in) :: counter(4), key(2)
      integer(int64) :: words(4)
      integer(int64) :: k(2), hi(2), lo(2)
      integer :: round
      words = iand(counter, mask32)
      k = iand(key, mask32)
      do round = 1, 10
         if (round > 1) k = iand(k + key_step, mask32)
         call multiply_32(multiplier(1), words(1), hi(1), lo(1))
         call multiply_32(multiplier(2), words(3), hi(2), lo(2))
         words = [ieor(ieor(hi(2), words(2)), k(1)), lo(2), ieor(ieor(hi(1), words(4)), k(2)), lo(1)]
      end do
   end function philox4x32

   !> The high and low 32-bit words of the 64-bit product a b of two 32-bit words, without
   !! overflowing a signed 64-bit integer: b = b1 2^16 + b0, a b0 and a b1 < 2^48.
   pure subroutine multiply_32(a, b, high, low)
      integer(int64), intent(in) :: a, b
      integer(int64), intent(out) :: high, low
      integer(int64) :: low_part, high_part, sum
      low_part = a*iand(b, mask16)
      high_part = a*ishft(b, -16)
      ! a b = low_part + high_part 2^16 = sum + (high_part >> 16) 2^32
      sum = low_part + ishft(iand(high_part, mask16), 16)
      low = iand(sum, mask32)
      high = ishft(high_part, -16) + ishft(sum, -32)
   end subroutine multiply_32

   !> Pair number `index` (>= 0) of normal deviates N(0, 1) of stream `stream` (in
   !! [0, 2^32)) under `key` (module documentation: the polar method on Philox blocks with
   !! counter (index mod 2^32, index / 2^32, attempt, stream)).
   pure function gaussian_pair(key, stream, index) result(z)
      integer(int64), intent(in) :: key(2), stream, index
      real(dp) :: z(2)
      integer(int64) :: words(4)
      real(dp) :: x, y, s
      integer :: attempt
      z = 0
      do attempt = 0, max_attempts - 1
         words = philox4x32([iand(index, mask32), ishft(index, -32), int(attempt, int64), stream], key)
         x = symmetric_uniform(words(1), words(2))
         y = symmetric_uniform(words(3), words(4))
         s = x*x + y*y
         if (s > 0 .and. s < 1) then
            z = [x, y]*sqrt(-2*portable_log(s)/s)
            return
         end if
      end do
   end function gaussian_pair

   !> A uniform number in [-1, 1) on the grid 2^-52 from two 32-bit words: the 53-bit
   !! integer k = a 2^21 + (b >> 11), then (k - 2^52) 2^-52 (both steps exact).
   pure real(dp) function symmetric_uniform(a, b)
      integer(int64), intent(in) :: a, b
      integer(int64) :: k
      k = ishft(a, 21) + ishft(b, -11)
      symmetric_uniform = real(k - 2_int64**52, dp)*2.0_dp**(-52)
   end function symmetric_uniform

   !> ln x for a positive normal x with +, -, *, / only (module documentation): x = m 2^e
   !! with m in [1/sqrt 2, sqrt 2), ln m = 2 atanh(t), t = (m - 1)/(m + 1), |t| <= 0.172,
   !! by its series to t^25 (the next term is below 2e-21), and e ln 2 in two parts (the
   !! high part has 32 trailing zero bits, so e ln2_hi is exact for |e| < 2^20). Within a few
   !! units in the last place of ln x (`unit.test_random` bounds it against the intrinsic).
   elemental real(dp) function portable_log(x)
      real(dp), intent(in) :: x
      real(dp), parameter :: ln2_hi = 6.93147180369123816490e-01_dp, ln2_lo = 1.90821492927058770002e-10_dp
      real(dp), parameter :: half_sqrt2 = 0.70710678118654752440_dp
      real(dp) :: m, t, t2, series
      integer :: e, k
      e = exponent(x)
      m = fraction(x)             ! x = m 2^e, m in [1/2, 1)
      if (m < half_sqrt2) then
         m = 2*m
         e = e - 1
      end if
      t = (m - 1)/(m + 1)
      t2 = t*t
      series = 0
      do k = 12, 1, -1            ! sum_{k>=1} t^(2k) / (2k + 1), by Horner's rule
         series = t2*(1/real(2*k + 1, dp) + series)
      end do
      portable_log = e*ln2_hi + (e*ln2_lo + 2*(t + t*series))
   end function portable_log

   !> exp(x) with +, -, *, / only (module documentation): x = k ln 2 + r, k = nint(x/ln 2),
   !! |r| <= 0.35 (ln 2 in two parts as in `portable_log`, k ln2_hi exact), exp(r) by its
   !! Taylor series to r^17 by Horner's rule (the next term is below 3e-23), times 2^k
   !! exactly (`scale`). 0 below -745 (below the smallest subnormal number), and within a
   !! few units in the last place otherwise (`unit.test_random`). For x <= 709.
   elemental real(dp) function portable_exp(x)
      real(dp), intent(in) :: x
      real(dp), parameter :: ln2_hi = 6.93147180369123816490e-01_dp, ln2_lo = 1.90821492927058770002e-10_dp
      real(dp) :: r, series
      integer :: k, n
      if (x < -745) then
         portable_exp = 0
         return
      end if
      k = nint(x/(ln2_hi + ln2_lo))
      r = (x - k*ln2_hi) - k*ln2_lo
      series = 1
      do n = 17, 1, -1
         series = 1 + r*series/n
      end do
      portable_exp = scale(series, k)
   end function portable_exp

   !> sin(pi x) for x in [0, 1] with +, -, *, / only (module documentation): by symmetry
   !! sin(pi y), y = min(x, 1 - x) in [0, 1/2] (1 - x exact there), a = pi y in [0, pi/2],
   !! by its Taylor series to a^25 (the next term is below 3e-23). Within a few units in the
   !! last place (`unit.test_random`).
   elemental real(dp) function portable_sin_pi(x)
      real(dp), intent(in) :: x
      real(dp), parameter :: pi = 3.14159265358979323846_dp
      real(dp) :: a, a2, series
      integer :: n
      a = pi*min(x, 1 - x)
      a2 = a*a
      series = 1
      do n = 12, 1, -1            ! sin a = a (1 - a^2/(2 3) (1 - a^2/(4 5) (1 - ...)))
         series = 1 - a2*series/real((2*n)*(2*n + 1), dp)
      end do
      portable_sin_pi = a*series
   end function portable_sin_pi
end module vibrobeam_random
