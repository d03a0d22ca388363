!> The portable random numbers (src/core/vibrobeam_random.f90) against independent
!! references:
!! - Philox4x32-10 against the known-answer vectors published with Random123 (Salmon et
!!   al., SC11, 2011; its tests/kat_vectors: counter, key, output in hexadecimal);
!! - portable_log against the intrinsic log: both are within a few units in the last
!!   place (ulp) of ln x; the bound 16 eps |ln x| (plus 16 eps for |ln x| < 1, where the
!!   error is relative to the series' leading term t) leaves room for the intrinsic's
!!   own ulp and the few roundings of the series (t: 2 roundings; the Horner sum of 12
!!   terms with |t^2| < 0.03: its relative error is below 2 eps; the final sum: 2);
!! - portable_exp against the intrinsic exp over [-700, 700] (normal numbers), and
!!   portable_sin_pi against sin(pi min(x, 1 - x)) over [0, 1] (well conditioned: the
!!   argument in [0, pi/2]), within 16 eps of the value (a few ulp of each, as for the
!!   logarithm: the series' roundings and the intrinsic's own);
!! - the normal deviates: mean, variance and fourth moment of 2e6 deviates against 0, 1
!!   and 3, within 5 standard errors of the estimators (sqrt(1/n), sqrt(2/n),
!!   sqrt(96/n)), and the fraction beyond 1.96 against 0.05 within 5 binomial standard
!!   errors; pairs of different streams, keys and indices uncorrelated (|r| < 5/sqrt(n)).
program test_random
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_random, only: philox4x32, gaussian_pair, portable_log, portable_exp, portable_sin_pi, random_key
   use vibrobeam_test_support, only: test_counter, same_bits
   implicit none
   type(test_counter) :: t
   integer(int64) :: words(4)
   integer, parameter :: n = 1000000
   real(dp) :: x, z(2), sums(4), beyond, cross(3)
   real(dp), allocatable :: a(:), b(:), c(:), d(:)
   integer :: i

   ! known answers (counter; key; output)
   words = philox4x32([0_int64, 0_int64, 0_int64, 0_int64], [0_int64, 0_int64])
   call t%check_true('philox4x32-10 of zeros', all(words == [int(z'6627e8d5', int64), int(z'e169c58d', int64), &
                                                             int(z'bc57ac4c', int64), int(z'9b00dbd8', int64)]))
   words = philox4x32([int(z'ffffffff', int64), int(z'ffffffff', int64), int(z'ffffffff', int64), &
                       int(z'ffffffff', int64)], [int(z'ffffffff', int64), int(z'ffffffff', int64)])
   call t%check_true('philox4x32-10 of ones', all(words == [int(z'408f276d', int64), int(z'41c83b0e', int64), &
                                                            int(z'a20bc7c6', int64), int(z'6d5451fd', int64)]))
   words = philox4x32([int(z'243f6a88', int64), int(z'85a308d3', int64), int(z'13198a2e', int64), &
                       int(z'03707344', int64)], [int(z'a4093822', int64), int(z'299f31d0', int64)])
   call t%check_true('philox4x32-10 of pi', all(words == [int(z'd16cfe09', int64), int(z'94fdcceb', int64), &
                                                          int(z'5001e420', int64), int(z'24126ea1', int64)]))

   ! the logarithm over (0, 1] and beyond, at numbers of every exponent
   do i = 0, 4000
      x = 1.0001_dp**(i*13)*1e-300_dp**(real(4000 - i, dp)/4000)
      call t%check_close('portable_log', portable_log(x), log(x), 16*epsilon(1.0_dp), scale=1.0_dp)
   end do
   call t%check_close('portable_log(1)', portable_log(1.0_dp), 0.0_dp, 0.0_dp, scale=1.0_dp)
   call t%check_close('portable_log(0.5)', portable_log(0.5_dp), log(0.5_dp), 4*epsilon(1.0_dp))

   ! the exponential and the sine
   do i = 0, 4000
      x = -700 + 1400*real(i, dp)/4000
      call t%check_close('portable_exp', portable_exp(x), exp(x), 16*epsilon(1.0_dp))
      x = real(i, dp)/4000
      call t%check_close('portable_sin_pi', portable_sin_pi(x), sin(acos(-1.0_dp)*min(x, 1 - x)), &
                         16*epsilon(1.0_dp), scale=tiny(1.0_dp))
   end do
   call t%check_close('portable_exp(0)', portable_exp(0.0_dp), 1.0_dp, 0.0_dp)
   call t%check_close('portable_sin_pi(1/2)', portable_sin_pi(0.5_dp), 1.0_dp, epsilon(1.0_dp))

   ! moments of the deviates of one stream
   allocate (a(n), b(n), c(n), d(n))
   do i = 1, n/2
      z = gaussian_pair(random_key(7, 0_int64), 0_int64, int(i - 1, int64))
      a(2*i - 1:2*i) = z
      b(2*i - 1:2*i) = gaussian_pair(random_key(7, 0_int64), 1_int64, int(i - 1, int64))   ! another stream
      c(2*i - 1:2*i) = gaussian_pair(random_key(8, 0_int64), 0_int64, int(i - 1, int64))   ! another seed
      d(2*i - 1:2*i) = gaussian_pair(random_key(7, 1_int64), 0_int64, int(i - 1, int64))   ! another realisation
   end do
   sums = [sum(a), sum(a**2), sum(a**4), 0.0_dp]/n
   call t%check_close('mean of the deviates', sums(1), 0.0_dp, 5*sqrt(1.0_dp/n), scale=1.0_dp)
   call t%check_close('variance of the deviates', sums(2), 1.0_dp, 5*sqrt(2.0_dp/n))
   call t%check_close('fourth moment of the deviates', sums(3), 3.0_dp, 5*sqrt(96.0_dp/n)/3)
   beyond = count(abs(a) > 1.959963984540054_dp)/real(n, dp)
   call t%check_close('fraction beyond 1.96', beyond, 0.05_dp, 5*sqrt(0.05_dp*0.95_dp/n)/0.05_dp)
   cross = [sum(a*b), sum(a*c), sum(a*d)]/n
   call t%check_close('correlation of two streams', cross(1), 0.0_dp, 5/sqrt(real(n, dp)), scale=1.0_dp)
   call t%check_close('correlation of two seeds', cross(2), 0.0_dp, 5/sqrt(real(n, dp)), scale=1.0_dp)
   call t%check_close('correlation of two realisations', cross(3), 0.0_dp, 5/sqrt(real(n, dp)), scale=1.0_dp)
   call t%check_close('lag-1 correlation', sum(a(2:)*a(:n - 1))/n, 0.0_dp, 5/sqrt(real(n, dp)), scale=1.0_dp)
   ! a pair is a function of its index alone: computed again out of order, the same bits
   z = gaussian_pair(random_key(7, 0_int64), 0_int64, int(n/4, int64))
   call t%check_true('a pair recomputed alone', all(same_bits(z, a(n/2 + 1:n/2 + 2))))
   call t%finish('test_random')
end program test_random
