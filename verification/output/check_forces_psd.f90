!> The outputs of a run's random load (/forces/load_1, docs/output.md; forces_psd.nml: a
!! band-limited white point force S = level on [f_a, f_b], 2^16 steps) against what they
!! claim, computed here independently:
!! - the bins inside the band, 8 filter bins 1/(L dt) and 8 Welch bins from its edges (the
!!   filter's Hann-windowed taps and the Welch segments' Hann window each smooth an edge;
!!   beyond 8 bins both leave less than 1e-4 of the level, unit.test_random_signal): the
!!   target S lies outside the measured density's 95 % band in a fraction q of the M bins,
!!   which must be 5 % within 4 binomial standard errors sqrt(0.05 0.95 2/M) (neighbouring
!!   bins of a Hann window are correlated: M/2 independent ones); the mean of P/S within 5
!!   standard errors sqrt(2 (2/nu)/M) of 1 (each bin's variance 2/nu, the factor 2 again);
!! - bins above f_b + the same margin, up to 2 f_b or the Nyquist frequency: measured density below 1e-3 of the
!!   level (the edges' leakage is below 1e-4 of it and a bin exceeds twice its mean with a
!!   probability below 1e-6 at nu = 119);
!! - the degrees of freedom: segments = (N - n_s)/(n_s/2) + 1, nu = 2 K^2/(K + (K - 1)/18),
!!   and the chi-square quantiles of the band against tabulated values;
!! - the recipe: a signal designed here from the scene's density, dt, seed and realisation
!!   (docs/output.md, "Regenerating a random load") gives the stored taps and samples bit
!!   for bit; and the direct convolution y_n = sum_k h_k xi_{n-k} of the stored taps with
!!   the Philox deviates xi_m (pair (m + 2^21)/2 of stream 0, key (seed, realisation - 1))
!!   equals the stored samples to the FFT's rounding, bounded by 3 (log2(2L) + 1) 4 u
!!   ||h||_1 max|xi| (three transforms of 2L points, Higham, "Accuracy and Stability of
!!   Numerical Algorithms", Thm 24.2, with ||y||_inf <= ||h||_1 max|xi|).
!!
!! usage: check_forces_psd SCENE.nml RESULT.h5
program check_forces_psd
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_scene, only: scene_type
   use vibrobeam_random, only: random_key, gaussian_pair
   use vibrobeam_random_signal, only: spectrum_shape, random_signal
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_quantiles, only: chi_square_quantile
   use vibrobeam_test_support, only: test_counter, read_test_scene, same_bits
   implicit none
   integer(int64), parameter :: noise_origin = 2_int64**21
   type(test_counter) :: t
   type(scene_type) :: scene
   type(h5_reader) :: file
   type(spectrum_shape) :: shape
   type(random_signal) :: signal
   character(len=4096) :: scene_path, result_path
   character(len=512) :: errmsg
   character(len=*), parameter :: g = '/forces/load_1'
   real(dp), allocatable :: frequency(:), target(:), measured(:), lower(:), upper(:), taps(:), samples(:), xi(:)
   logical, allocatable :: inside(:), above(:)
   real(dp) :: level, f_a, f_b, dt, width, nu, margin, q, mean_ratio, error, worst, bound, v(1), pair(2), u
   integer(int64) :: seed, realisation, segments, n_s, l, n, k, m, d
   integer :: stat, bins
   logical :: same

   call get_command_argument(1, scene_path)
   call get_command_argument(2, result_path)
   scene = read_test_scene(trim(scene_path))
   level = scene%forces%load(1)%psd_level
   f_a = scene%forces%load(1)%band_from
   f_b = scene%forces%load(1)%band_to
   dt = scene%time%dt
   call file%open(trim(result_path), stat, errmsg)
   call t%check_true('open the result', stat == 0, errmsg)
   if (stat /= 0) call t%finish('check_forces_psd')
   call file%read_reals(g//'/frequency', frequency, stat, errmsg)
   if (stat == 0) call file%read_reals(g//'/psd_target', target, stat, errmsg)
   if (stat == 0) call file%read_reals(g//'/psd_measured', measured, stat, errmsg)
   if (stat == 0) call file%read_reals(g//'/psd_lower', lower, stat, errmsg)
   if (stat == 0) call file%read_reals(g//'/psd_upper', upper, stat, errmsg)
   if (stat == 0) call file%read_reals(g//'/filter_taps', taps, stat, errmsg)
   if (stat == 0) call file%read_reals(g//'/signal', samples, stat, errmsg)
   if (stat == 0) call file%attr_real(g, 'bin_width', width, stat, errmsg)
   if (stat == 0) call file%attr_real(g, 'degrees_of_freedom', nu, stat, errmsg)
   if (stat == 0) call file%attr_int64(g, 'segments', segments, stat, errmsg)
   if (stat == 0) call file%attr_int64(g, 'segment_samples', n_s, stat, errmsg)
   if (stat == 0) call file%attr_int64(g, 'taps', l, stat, errmsg)
   if (stat == 0) call file%attr_int64(g, 'seed', seed, stat, errmsg)
   if (stat == 0) call file%attr_int64(g, 'realisation', realisation, stat, errmsg)
   call t%check_true('read /forces/load_1', stat == 0, errmsg)
   if (stat /= 0) call t%finish('check_forces_psd')
   call file%close()
   n = size(samples, kind=int64)
   bins = size(frequency)

   ! degrees of freedom and the band's quantiles
   call t%check_true('segments = (N - n_s)/(n_s/2) + 1', segments == (n - n_s)/(n_s/2) + 1)
   call t%check_close('degrees of freedom 2 K^2/(K + (K - 1)/18)', nu, &
                      2*real(segments, dp)**2/(segments + (segments - 1)/18.0_dp), 1e-14_dp)
   call t%check_close('bin width 1/(n_s dt)', width, 1/(n_s*dt), 1e-14_dp)
   ! chi-square quantiles: nu = 2 in closed form -2 ln(1 - p); nu = 10 from tables (6 digits)
   call t%check_close('chi2_2(0.025)', chi_square_quantile(2.0_dp, 0.025_dp), -2*log(0.975_dp), 1e-12_dp)
   call t%check_close('chi2_2(0.975)', chi_square_quantile(2.0_dp, 0.975_dp), -2*log(0.025_dp), 1e-12_dp)
   call t%check_close('chi2_10(0.025)', chi_square_quantile(10.0_dp, 0.025_dp), 3.24697_dp, 2e-6_dp)
   call t%check_close('chi2_10(0.975)', chi_square_quantile(10.0_dp, 0.975_dp), 20.4832_dp, 2e-6_dp)
   call t%check_close('the band of one bin', lower(bins/4), &
                      nu*measured(bins/4)/chi_square_quantile(nu, 0.975_dp), 1e-12_dp)

   ! the measured density against the target
   margin = 8/(l*dt) + 8*width
   allocate (inside(bins), above(bins))
   inside = frequency > f_a + margin .and. frequency < f_b - margin
   above = frequency > f_b + margin
   call t%check_true('the bins reach twice the band''s top or the Nyquist frequency', &
                     frequency(bins) <= min(2*f_b, 1/(2*dt)) .and. frequency(bins) > min(2*f_b, 1/(2*dt)) - width)
   call t%check_true('the target is the level inside the band', all(same_bits(target, merge(level, 0.0_dp, &
                     frequency >= f_a .and. frequency <= f_b))))
   m = count(inside)
   q = count(inside .and. (target < lower .or. target > upper))/real(m, dp)
   mean_ratio = sum(measured/level, mask=inside)/m
   write (*, '(a,i0,a,f7.4,a,f7.4,a,f7.4)') 'bins inside: ', m, ', target outside the 95 % band: ', q, &
      ' (accepted within ', 4*sqrt(0.05_dp*0.95_dp*2/m), ' of 0.05), mean P/S ', mean_ratio
   call t%check_close('fraction of the bins whose band misses the target', q, 0.05_dp, &
                      4*sqrt(0.05_dp*0.95_dp*2/m), scale=1.0_dp)
   call t%check_close('mean measured/target inside the band', mean_ratio, 1.0_dp, 5*sqrt(2*(2/nu)/m))
   write (*, '(a,es10.3,a)') 'largest measured density above the band: ', maxval(measured, mask=above)/level, &
      ' of the level'
   call t%check_true('measured density above the band below 1e-3 of the level', &
                     all(measured <= 1e-3_dp*level .or. .not. above))

   ! the recipe: the library, designed anew, gives the same bits
   shape%level = level
   shape%band_from = f_a
   shape%band_to = f_b
   call signal%design(shape, dt, random_key(int(seed), realisation - 1), stat, errmsg)
   call t%check_true('design the signal from the recipe', stat == 0 .and. signal%taps == l, errmsg)
   call t%check_true('the same taps, bit for bit', all(same_bits(signal%taps_values, taps)))
   same = .true.
   do k = 1, n
      call signal%sample(k, v)
      same = same .and. same_bits(v(1), samples(k))
   end do
   call t%check_true('the same samples y_1 .. y_N, bit for bit', same)

   ! the recipe by hand: the direct convolution with the Philox deviates
   allocate (xi(1 - l:n))
   do k = 1 - l, n
      d = k + noise_origin
      pair = gaussian_pair(random_key(int(seed), realisation - 1), 0_int64, d/2)
      xi(k) = pair(mod(d, 2_int64) + 1)
   end do
   u = epsilon(1.0_dp)/2
   bound = 3*(log(2.0_dp*l)/log(2.0_dp) + 1)*4*u*sum(abs(taps))*maxval(abs(xi))
   worst = 0
   do k = 1, n
      error = abs(samples(k) - dot_product(taps, xi(k:k - l + 1:-1)))
      worst = max(worst, error)
   end do
   write (*, '(a,es10.3,a,es10.3)') 'direct convolution against the stored samples: largest difference ', worst, &
      ', bound ', bound
   call t%check_true('the direct convolution of the recipe', worst <= bound)
   call t%finish('check_forces_psd')
end program check_forces_psd
