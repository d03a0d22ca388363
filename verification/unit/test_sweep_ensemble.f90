!> The ensemble statistics of a sweep over forces.realisation (src/analysis/sweep/
!! vibrobeam_sweep_ensemble.f90) against numbers computed by hand, and Student's and the
!! chi-square quantiles (src/analysis/statistics/vibrobeam_quantiles.f90) against tables.
!!
!! A 2-D sweep: axis 1 = forces.realisation (1, 2, 3), axis 2 = load.frequency (10, 20),
!! points in the order of the lines. Two statistics a point. Group 1 (frequency 10): the
!! values (1, 10), (2, 20), (4, 40): mean 7/3 (and 70/3), s^2 = ((4/3)^2 + (1/3)^2 +
!! (5/3)^2)/2 = 7/3, half-width t_{0.975,2} sqrt(7/3)/sqrt(3) = 4.302653 x 0.881917 =
!! 3.794583 (and 10 times that). Group 2 (frequency 20): one realisation finished (5, 6):
!! mean (5, 6), half-width 0 (no interval). Then the realisation on axis 2 of a sweep
!! whose axis 1 has two values: points grouped by the value of axis 1, not by line.
program test_sweep_ensemble
   use vibrobeam_kinds, only: dp
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point
   use vibrobeam_sweep_ensemble, only: sweep_ensemble
   use vibrobeam_quantiles, only: student_quantile, chi_square_quantile
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   type(sweep_settings) :: settings
   type(sweep_point) :: points(6)
   type(sweep_ensemble) :: ensemble
   real(dp) :: h(2)
   integer :: k

   ! quantiles: Student's t_{0.975, nu} (tables to 6 digits) and t_{0.5} = 0
   call t%check_close('t(0.975, 1)', student_quantile(1.0_dp, 0.975_dp), 12.7062_dp, 1e-5_dp)
   call t%check_close('t(0.975, 2)', student_quantile(2.0_dp, 0.975_dp), 4.30265_dp, 1e-5_dp)
   call t%check_close('t(0.975, 10)', student_quantile(10.0_dp, 0.975_dp), 2.22814_dp, 1e-5_dp)
   call t%check_close('t(0.975, 39)', student_quantile(39.0_dp, 0.975_dp), 2.02269_dp, 1e-5_dp)
   call t%check_close('t(0.975, 1000)', student_quantile(1000.0_dp, 0.975_dp), 1.96234_dp, 1e-5_dp)
   ! nu = 1 in closed form: tan(pi (p - 1/2))
   call t%check_close('t(0.9, 1) = tan(0.4 pi)', student_quantile(1.0_dp, 0.9_dp), tan(0.4_dp*acos(-1.0_dp)), 1e-12_dp)
   call t%check_close('chi2(0.5, 2) = 2 ln 2', chi_square_quantile(2.0_dp, 0.5_dp), 2*log(2.0_dp), 1e-12_dp)

   settings%axis(1)%parameter = 'forces.realisation'
   settings%axis(2)%parameter = 'load.frequency'
   do k = 1, 6
      points(k)%value = [real(mod(k - 1, 3) + 1, dp), merge(10.0_dp, 20.0_dp, k <= 3)]
      points(k)%line = merge(1, 2, k <= 3)
   end do
   call ensemble%init(settings, points, 2)
   call t%check_true('two groups, one per frequency', ensemble%axis == 1 .and. ensemble%groups == 2 .and. &
                     all(ensemble%group_of == [1, 1, 1, 2, 2, 2]))
   call ensemble%add(1, [1.0_dp, 10.0_dp])
   call ensemble%add(2, [2.0_dp, 20.0_dp])
   call ensemble%add(3, [4.0_dp, 40.0_dp])
   call ensemble%add(5, [5.0_dp, 6.0_dp])   ! points 4 and 6 failed: not added
   call t%check_true('realisations per group', all(ensemble%count == [3, 1]))
   call t%check_close('group 1: mean', ensemble%mean(1, 1), 7.0_dp/3, 1e-15_dp)
   call t%check_close('group 1: mean of the second statistic', ensemble%mean(2, 1), 70.0_dp/3, 1e-15_dp)
   h = ensemble%half_width(1)
   call t%check_close('group 1: half-width', h(1), 3.794583_dp, 1e-6_dp)
   call t%check_close('group 1: half-width of the second statistic', h(2), 37.94583_dp, 1e-6_dp)
   call t%check_close('group 1: the other axis', ensemble%other(1), 10.0_dp, 0.0_dp, scale=1.0_dp)
   call t%check_close('group 2: mean', ensemble%mean(2, 2), 6.0_dp, 0.0_dp, scale=1.0_dp)
   h = ensemble%half_width(2)
   call t%check_true('group 2: one realisation, no interval', maxval(abs(h)) <= 0)

   ! the realisation on axis 2: groups are the values of axis 1
   settings%axis(1)%parameter = 'load.frequency'
   settings%axis(2)%parameter = 'forces.realisation'
   do k = 1, 6
      points(k)%value = [merge(10.0_dp, 20.0_dp, mod(k, 2) == 1), real((k + 1)/2, dp)]
      points(k)%line = (k + 1)/2
   end do
   call ensemble%init(settings, points, 2)
   call t%check_true('realisation on axis 2: groups by the value of axis 1', ensemble%axis == 2 .and. &
                     ensemble%groups == 2 .and. all(ensemble%group_of == [1, 2, 1, 2, 1, 2]))
   ! not an ensemble
   settings%axis(2)%parameter = ''
   call ensemble%init(settings, points, 2)
   call t%check_true('no realisation axis: nothing', ensemble%axis == 0)
   call t%finish('test_sweep_ensemble')
end program test_sweep_ensemble
