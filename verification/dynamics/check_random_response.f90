!> The stationary response of a beam without contact to a random load (docs/theory.md
!! section 9), against the integral of |H|^2 S computed here, and the honesty of the
!! run's confidence intervals (their coverage over an ensemble of realisations).
!!
!! usage: check_random_response SCENE.nml SWEEP.h5 [REPLICATES]
!! SCENE.nml is a sweep over `forces.realisation` of a scene with one random load of
!! &forces (a point force or the support's acceleration) and no obstacle; SWEEP.h5 its
!! sweep file (one point per realisation, each with its RMS tip displacement and velocity
!! and their standard errors, docs/statistics.md).
!!
!! Reference. The velocity scheme maps a sampled load F_n to U_n = H(s) F_n with its
!! discrete s(omega) = (z - 1)/(dt (theta z + 1 - theta)), z = exp(i omega dt) (theory §9),
!! and V_n = s U_n. The load's samples are a stationary sequence of one-sided density
!! S_y(f) = 2 dt |G(f)|^2 on [0, 1/(2 dt)] (G the transform of its filter's taps, evaluated
!! here by a zero-padded FFT of 2^17 points with FFTW). So, exactly,
!!     sigma_u^2 = integral_0^{1/(2 dt)} |e_tip^T H(s) F|^2 S_y(f) df,   sigma_v^2: |s|^2 inside,
!! with H(s) = (s^2 M + s C + K)^-1 by dense complex LU (`vibrobeam_linear_response`),
!! F the load vector (a point force: phi_j(x); the support's acceleration: -rho S times the
!! uniform load vector by Simpson's rule), by the trapezoidal rule on that grid
!! (df = 0.0381 Hz for dt = 2e-4 s, 150 points per half-power band of the scene's
!! resonances: the rule's error is below 1e-4 of the integral). The semi-discrete system
!! under the target density S (s = i omega) is printed beside it (the scheme's frequency
!! error and the filter's smoothing of the band's edges).
!!
!! Checks, with R realisations (R points of the sweep):
!! - the ensemble: the mean of the R RMS values against sigma within 4 of its standard
!!   errors (their standard deviation / sqrt(R)), plus the bias of the RMS as the root of a
!!   mean square (below 1e-3 here);
!! - each run's interval: rms_k +- t(0.975, c - 1) error_k (c the batches of point k,
!!   t Student's quantile: the error has c - 1 degrees of freedom) covers sigma in at least
!!   95 % - 3 binomial standard errors of the R points;
!! - the spread of z_k = (rms_k - sigma)/error_k: its variance within [0.5, 2.5] (an honest
!!   error gives about (c - 1)/(c - 3) = 1.2; a third too small or too large an error
!!   would move it out by a factor 1.8);
!! - the sweep file's own ensemble statistics (/sweep/ensemble, R = 40): its mean equals
!!   the mean of the R rows to 1e-13 (two sums of 40 terms: 2 R u = 9e-15), its half-width
!!   equals t_{0.975,39} s/sqrt(R) with t_{0.975,39} = 2.02269 from tables (1e-5, the
!!   table's digits), and its interval mean +- half-width covers sigma (widened by the RMS
!!   bias, below 1e-3 sigma).
program check_random_response
   use, intrinsic :: iso_c_binding
   use vibrobeam_kinds, only: dp, output_unit, error_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_scene_rules, only: validate_scene
   use vibrobeam_scene_read, only: read_scene
   use vibrobeam_sweep_settings, only: sweep_settings
   use vibrobeam_problem, only: run_problem
   use vibrobeam_model, only: node_row, point_load_vector
   use vibrobeam_random_signal, only: random_signal
   use vibrobeam_hdf5_file_reads, only: read_real_2d, read_int_1d
   use vibrobeam_linear_response, only: dense_transfer, theta_frequency, simpson_load_vector
   use vibrobeam_test_support, only: test_counter, prepare_test_scene
   use vibrobeam_test_fftw
   implicit none
   integer, parameter :: grid = 2**17
   real(dp), parameter :: two_pi = 2*acos(-1.0_dp)
   type(test_counter) :: t
   type(scene_type) :: scene
   type(sweep_settings) :: sweep
   type(run_problem) :: prepared
   type(random_signal) :: signal
   character(len=4096) :: scene_path, sweep_path, argument
   character(len=512) :: errmsg
   real(dp), allocatable :: load(:), rms(:, :), errors(:, :), density(:)
   integer, allocatable :: batches(:)
   real(dp) :: sigma(2), semi_discrete(2), mean, spread, coverage_needed
   integer :: stat, tip_dofs(4), replicates, quantity, covered, k
   real(dp) :: tip_weights(4)
   character(len=*), parameter :: names(2) = [character(len=12) :: 'displacement', 'velocity']

   call get_command_argument(1, scene_path)
   call get_command_argument(2, sweep_path)
   call read_scene(trim(scene_path), scene, stat, errmsg, sweep=sweep)
   if (stat == 0) call validate_scene(scene, stat, errmsg)
   if (stat /= 0) then
      write (error_unit, '(a)') 'FAIL reading '//trim(scene_path)//': '//trim(errmsg)
      error stop 1
   end if
   call prepare_test_scene(scene, prepared)
   signal = prepared%loads%forces%random_of(1)
   call node_row(prepared%model, prepared%model%elements, tip_dofs, tip_weights)
   associate (f => scene%forces%load(1), model => prepared%model)
      select case (f%kind)
      case ('point')
         load = point_load_vector(model, scene%beam%length)
      case ('base')
         load = -scene%beam%rho_s()*simpson_load_vector(model, 0.0_dp, scene%beam%length)
      case default
         error stop 'check_random_response: a point force or a base acceleration'
      end select
      density = padded_density(signal)
      call variances(density, f%psd_level, f%band_from, f%band_to, sigma, semi_discrete)
   end associate
   write (output_unit, '(a,i0,a,es12.5,a,es12.5,a)') 'filter: ', signal%taps, ' taps; signal RMS ', signal%rms, &
      ' (target ', sqrt(scene%forces%load(1)%psd_level*(scene%forces%load(1)%band_to - scene%forces%load(1)%band_from)), &
      ')'

   call read_real_2d(trim(sweep_path), '/sweep/statistics/points/displacement_rms', rms, stat, errmsg)
   if (stat == 0) call read_real_2d(trim(sweep_path), '/sweep/statistics/points/displacement_rms_error', errors, stat, &
                                    errmsg)
   if (stat == 0) call read_int_1d(trim(sweep_path), '/sweep/batches', batches, stat, errmsg)
   if (stat /= 0) then
      write (error_unit, '(a)') 'FAIL reading '//trim(sweep_path)//': '//trim(errmsg)
      error stop 1
   end if
   replicates = size(batches)
   if (command_argument_count() >= 3) then
      call get_command_argument(3, argument)
      read (argument, *) replicates
   end if
   do quantity = 1, 2
      if (quantity == 2) then
         call read_real_2d(trim(sweep_path), '/sweep/statistics/points/velocity_rms', rms, stat, errmsg)
         if (stat == 0) call read_real_2d(trim(sweep_path), '/sweep/statistics/points/velocity_rms_error', errors, &
                                          stat, errmsg)
         if (stat /= 0) error stop 'check_random_response: cannot read the velocity statistics'
      end if
      call check_ensemble(trim(names(quantity)), rms(1, 1:replicates), errors(1, 1:replicates), batches(1:replicates), &
                          sigma(quantity), semi_discrete(quantity))
      if (replicates == 40 .and. size(batches) == 40) call check_sweep_ensemble(trim(names(quantity)), sigma(quantity))
   end do
   call t%finish('check_random_response')

contains

   !> S_y(f_j) = 2 dt |G(f_j)|^2 at f_j = j/(grid dt), j = 0 .. grid/2: the taps padded
   !! with zeros to `grid` points, one FFTW transform.
   function padded_density(signal) result(values)
      type(random_signal), intent(in) :: signal
      real(dp), allocatable :: values(:)
      real(c_double), pointer :: padded(:)
      complex(c_double_complex), pointer :: transform(:)
      type(c_ptr) :: memory_in, memory_out, plan
      memory_in = fftw_alloc_real(int(grid, c_size_t))
      memory_out = fftw_alloc_complex(int(grid/2 + 1, c_size_t))
      call c_f_pointer(memory_in, padded, [grid])
      call c_f_pointer(memory_out, transform, [grid/2 + 1])
      plan = fftw_plan_dft_r2c_1d(int(grid, c_int), padded, transform, FFTW_ESTIMATE)
      padded = 0
      padded(1:signal%taps) = signal%taps_values
      call fftw_execute_dft_r2c(plan, padded, transform)
      values = 2*signal%step*abs(transform)**2
      call fftw_destroy_plan(plan)
      call fftw_free(memory_in)
      call fftw_free(memory_out)
   end function padded_density

   !> sigma_u, sigma_v of the scheme under the applied density (module documentation), and
   !! of the semi-discrete system under the target band-limited white density.
   subroutine variances(density, level, band_from, band_to, sigma, semi_discrete)
      real(dp), intent(in) :: density(0:), level, band_from, band_to
      real(dp), intent(out) :: sigma(2), semi_discrete(2)
      real(dp) :: df, f, weight, target
      complex(dp) :: s, response
      integer :: j
      df = 1/(grid*scene%time%dt)
      sigma = 0
      semi_discrete = 0
      do j = 0, grid/2
         f = j*df
         weight = df
         if (j == 0 .or. j == grid/2) weight = df/2
         s = theta_frequency(two_pi*f, scene%time%dt, scene%time%theta)
         response = tip_response(s)
         sigma = sigma + weight*density(j)*[abs(response)**2, abs(s*response)**2]
         target = 0
         if (f >= band_from .and. f <= band_to) target = level
         if (target > 0) then
            s = cmplx(0.0_dp, two_pi*f, dp)
            response = tip_response(s)
            semi_discrete = semi_discrete + weight*target*[abs(response)**2, abs(s*response)**2]
         end if
      end do
      sigma = sqrt(sigma)
      semi_discrete = sqrt(semi_discrete)
   end subroutine variances

   !> e_tip^T H(s) F.
   complex(dp) function tip_response(s)
      complex(dp), intent(in) :: s
      complex(dp) :: x(size(load))
      integer :: a
      associate (model => prepared%model)
         x = dense_transfer(model%mass, model%stiffness, scene%beam%rayleigh_mass, scene%beam%rayleigh_stiffness, s, &
                            cmplx(load, 0.0_dp, dp))
      end associate
      tip_response = 0
      do a = 1, 4
         if (tip_dofs(a) /= 0) tip_response = tip_response + tip_weights(a)*x(tip_dofs(a))
      end do
   end function tip_response

   !> The checks of the module documentation for one quantity.
   subroutine check_ensemble(name, rms, errors, batches, sigma, semi_discrete)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: rms(:), errors(:), sigma, semi_discrete
      integer, intent(in) :: batches(:)
      real(dp) :: z(size(rms)), z_variance, bias
      integer :: r
      r = size(rms)
      mean = sum(rms)/r
      spread = sqrt(sum((rms - mean)**2)/(r - 1))
      covered = 0
      do k = 1, r
         z(k) = (rms(k) - sigma)/errors(k)
         if (abs(z(k)) <= student_975(batches(k) - 1)) covered = covered + 1
      end do
      z_variance = sum((z - sum(z)/r)**2)/(r - 1)
      ! the RMS is the root of a mean square: low by about var(ms)/(8 sigma^3) = (spread/sigma)^2 sigma/2
      bias = 0.5_dp*spread**2/sigma
      write (output_unit, '(a,es12.5,a,es12.5,a,es12.5,a,f7.4,a)') 'tip '//name//' RMS: exact (scheme) ', sigma, &
         ', semi-discrete under the target density ', semi_discrete, '; ensemble mean ', mean, ' (', &
         (mean - sigma)/(spread/sqrt(real(r, dp))), ' standard errors)'
      write (output_unit, '(a,i0,a,i0,a,f6.3,a,es10.3)') '   intervals covering it: ', covered, ' of ', r, &
         '; variance of (rms - exact)/error ', z_variance, '; mean error / spread ', sum(errors)/r/spread
      call t%check_close('tip '//name//' RMS: ensemble mean against the exact', mean, sigma, &
                         (4*spread/sqrt(real(r, dp)) + bias)/sigma)
      coverage_needed = r*0.95_dp - 3*sqrt(r*0.95_dp*0.05_dp)
      call t%check_true('tip '//name//' RMS: 95 % intervals cover the exact in enough runs', covered >= coverage_needed)
      call t%check_true('tip '//name//' RMS: the errors are honest (variance of z in [0.5, 2.5])', &
                        z_variance >= 0.5_dp .and. z_variance <= 2.5_dp)
   end subroutine check_ensemble

   !> The sweep file's ensemble mean and interval of the tip's `name` RMS (module
   !! documentation), against `mean` and `spread` of `check_ensemble` and the exact sigma.
   subroutine check_sweep_ensemble(name, sigma)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: sigma
      real(dp), allocatable :: ensemble_mean(:, :), half_width(:, :)
      real(dp), parameter :: t_39 = 2.02269_dp   ! Student's t_{0.975, 39} (tables)
      call read_real_2d(trim(sweep_path), '/sweep/ensemble/points/'//name//'_rms', ensemble_mean, stat, errmsg)
      if (stat == 0) call read_real_2d(trim(sweep_path), '/sweep/ensemble/points/'//name//'_rms_half_width', &
                                       half_width, stat, errmsg)
      call t%check_true('the sweep file has /sweep/ensemble (tip '//name//' RMS)', stat == 0, errmsg)
      if (stat /= 0) return
      write (output_unit, '(a,es12.5,a,es10.3,a,f6.2,a)') '   sweep file ensemble: ', ensemble_mean(1, 1), ' +- ', &
         half_width(1, 1), ' (', (ensemble_mean(1, 1) - sigma)/half_width(1, 1), ' half-widths from the exact)'
      call t%check_close('tip '//name//' RMS: /sweep/ensemble mean', ensemble_mean(1, 1), mean, 1e-13_dp)
      call t%check_close('tip '//name//' RMS: /sweep/ensemble half-width', half_width(1, 1), &
                         t_39*spread/sqrt(40.0_dp), 1e-5_dp)
      call t%check_true('tip '//name//' RMS: the ensemble''s 95 % interval covers the exact', &
                        abs(ensemble_mean(1, 1) - sigma) <= half_width(1, 1) + 1e-3_dp*sigma)
   end subroutine check_sweep_ensemble

   !> Student's t quantile 0.975 for nu degrees of freedom (tables; nu >= 30: 2.042 to 1.96).
   pure real(dp) function student_975(nu)
      integer, intent(in) :: nu
      real(dp), parameter :: table(30) = [12.706_dp, 4.303_dp, 3.182_dp, 2.776_dp, 2.571_dp, 2.447_dp, 2.365_dp, &
                                          2.306_dp, 2.262_dp, 2.228_dp, 2.201_dp, 2.179_dp, 2.160_dp, 2.145_dp, &
                                          2.131_dp, 2.120_dp, 2.110_dp, 2.101_dp, 2.093_dp, 2.086_dp, 2.080_dp, &
                                          2.074_dp, 2.069_dp, 2.064_dp, 2.060_dp, 2.056_dp, 2.052_dp, 2.048_dp, &
                                          2.045_dp, 2.042_dp]
      if (nu < 1) then
         student_975 = huge(1.0_dp)
      else if (nu <= 30) then
         student_975 = table(nu)
      else
         student_975 = 1.96_dp
      end if
   end function student_975
end program check_random_response
