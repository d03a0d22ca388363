!> Verification (acceptance test "FFT test: peaks within one frequency bin of omega_1..3"):
!! free vibration of a cantilever with no obstacle, theta = 1/2, released from rest in a
!! combination of modes 1, 2 and 3 (tip values `tip_amplitudes`; the namelist's &initial
!! holds one mode only, so the initial displacement is set here with mode_field). The tip
!! displacement, recorded at every step, goes through amplitude_spectrum (Hann window); the
!! three largest spectral peaks must sit within one bin width 1/(n dt) of the natural
!! frequencies omega_k/(2 pi) of the same discrete model (compute_modes).
!!
!! Also checked: each peak amplitude lies within the Hann scalloping loss of the tip
!! amplitude of its mode, [8/(3 pi), 1] a_k (theta = 1/2 conserves the amplitude of each
!! mode; the continuum mode shapes of mode_field differ from the discrete modes by the
!! spatial error, and the other components leak a little: 2% allowed), and the
!! preconditions the bin criterion relies on: no contact point, theta = 1/2, omega_3 dt <= 0.1
!! and a bin width below a tenth of the closest frequency spacing.
!!
!! usage: test_free_vibration_spectrum verification/dynamics/free_vibration_spectrum.nml
program test_free_vibration_spectrum
   use vibrobeam_kinds, only: dp, pi, output_unit, error_unit
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_model, only: nodal_displacement
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_modes, only: compute_modes
   use vibrobeam_initial_state, only: mode_field
   use vibrobeam_spectrum, only: amplitude_spectrum, spectral_peaks, bin_width
   use vibrobeam_roundoff_bounds, only: gamma_n
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene
   implicit none
   integer, parameter :: modes = 3
   real(dp), parameter :: tip_amplitudes(modes) = [0.01_dp, 0.004_dp, 0.002_dp]   ! m
   real(dp), parameter :: hann_worst_scalloping = 8/(3*pi)   ! sinc(1/2)/(1 - 1/4)
   real(dp), parameter :: amplitude_tolerance = 2e-2_dp
   type(test_counter) :: t
   type(scene_type) :: scene
   type(run_problem) :: prepared
   class(time_stepper), allocatable :: stepper
   character(len=512) :: path, errmsg
   real(dp), allocatable :: omega(:), shapes(:,:), vectors(:,:), tip(:), frequency(:), amplitude(:)
   integer, allocatable :: peaks(:)
   real(dp) :: natural(modes), width, found_frequency(modes), found_amplitude(modes)
   integer :: k, n, steps, stat, order(modes)

   call get_command_argument(1, path)
   if (len_trim(path) == 0) then
      write (error_unit, '(a)') 'usage: test_free_vibration_spectrum SCENE.nml'
      error stop 1
   end if
   scene = read_test_scene(trim(path))
   call prepare_test_scene(scene, prepared)
   call t%check_true('no contact point (free vibration)', prepared%contacts%count == 0, &
                     'the scene has contact points')
   call t%check_close('theta (energy-conserving scheme)', scene%time%theta, 0.5_dp, 0.0_dp)

   call compute_modes(prepared%model, modes, omega, shapes, vectors, stat, errmsg)
   if (stat /= 0) then
      write (error_unit, '(a)') 'FAIL compute_modes: '//trim(errmsg)
      error stop 1
   end if
   natural = omega/(2*pi)

   steps = nint(scene%time%t_end/scene%time%dt)
   width = bin_width(steps + 1, scene%time%dt)
   call t%check_true('omega_3 dt <= 0.1 (mode 3 resolved in time)', omega(modes)*scene%time%dt <= 0.1_dp, &
                     'omega_3 dt = '//real_text(omega(modes)*scene%time%dt)//', tolerance 0.1')
   call t%check_true('bin width <= (closest frequency spacing)/10', width <= minval(natural(2:) - natural(:modes - 1))/10, &
                     'bin width '//real_text(width)//' Hz, spacing '//real_text(minval(natural(2:) - natural(:modes - 1)))// &
                     ' Hz')

   ! released from rest in modes 1..3 (continuum shapes interpolated, tip value a_k): the
   ! state the stepper starts from
   prepared%start%u = 0
   do k = 1, modes
      prepared%start%u = prepared%start%u + mode_field(prepared%model, k, tip_amplitudes(k))
   end do
   prepared%start%v = 0

   call new_stepper(scene, prepared, stepper, stat, errmsg)
   if (stat /= 0) then
      write (error_unit, '(a)') 'FAIL start_stepper: '//trim(errmsg)
      error stop 1
   end if
   allocate (tip(0:steps))
   ! tip displacement through nodal_displacement: w_N = u(J-1) for Hermite elements, a
   ! combination of the last coefficients for B-splines
   tip(0) = tip_displacement(stepper%u)
   do n = 1, steps
      call stepper%step(stat, errmsg)
      if (stat /= 0) then
         write (error_unit, '(a,i0,a)') 'FAIL step ', n, ': '//trim(errmsg)
         error stop 1
      end if
      tip(n) = tip_displacement(stepper%u)
   end do

   call amplitude_spectrum(tip, scene%time%dt, frequency, amplitude, stat, errmsg, window='hann')
   call t%check_true('amplitude_spectrum succeeds', stat == 0, trim(errmsg))
   if (stat /= 0) call t%finish('test_free_vibration_spectrum')
   ! frequency(2) = 1/(n dt) and frequency(1) = 0 exactly; both sides round twice (gamma_4)
   call t%check_close('bin width = frequency(2) - frequency(1)', frequency(2) - frequency(1), width, gamma_n(4))
   allocate (peaks(0))   ! gfortran 12 -fcheck=bounds: else a false -Wmaybe-uninitialized on peaks = ...
   peaks = spectral_peaks(frequency, amplitude, modes, 1e-3_dp)
   call t%check_true('three spectral peaks', size(peaks) == modes, 'found '//integer_text(size(peaks)))
   if (size(peaks) /= modes) call t%finish('test_free_vibration_spectrum')
   ! match by frequency: the k-th lowest peak against omega_k
   order = sorted(frequency(peaks))
   found_frequency = frequency(peaks(order))
   found_amplitude = amplitude(peaks(order))

   write (output_unit, '(a,i0,a,es10.3,a,es10.3,a,f8.5,a)') 'record: ', steps + 1, ' samples, dt = ', scene%time%dt, &
      ' s, bin width ', width, ' Hz, omega_3 dt = ', omega(modes)*scene%time%dt
   write (output_unit, '(a)') 'mode  omega_k/2pi (Hz)   peak (Hz)        difference (bins)  ' // &
      'peak amplitude (m)  tip amplitude a_k (m)'
   do k = 1, modes
      write (output_unit, '(i4, 2f18.10, f14.4, 2es20.6)') k, natural(k), found_frequency(k), &
         (found_frequency(k) - natural(k))/width, found_amplitude(k), tip_amplitudes(k)
   end do
   do k = 1, modes
      call t%check_close('peak '//integer_text(k)//' frequency within one bin of omega_'//integer_text(k)//'/(2 pi)', &
                         abs(found_frequency(k) - natural(k)), 0.0_dp, 1.0_dp, width)
      call t%check_true('peak '//integer_text(k)//' amplitude within the Hann scalloping loss of a_'//integer_text(k), &
                        found_amplitude(k) >= (1 - amplitude_tolerance)*hann_worst_scalloping*tip_amplitudes(k) .and. &
                        found_amplitude(k) <= (1 + amplitude_tolerance)*tip_amplitudes(k), &
                        'value '//real_text(found_amplitude(k))//', reference interval ['// &
                        real_text(hann_worst_scalloping*tip_amplitudes(k))//', '//real_text(tip_amplitudes(k))// &
                        '], tolerance '//real_text(amplitude_tolerance))
   end do
   call t%finish('test_free_vibration_spectrum')

contains

   !> Displacement at x = L (m) of the unknowns `u` of the scene's model.
   function tip_displacement(u) result(tip)
      real(dp), intent(in) :: u(:)
      real(dp) :: tip
      real(dp) :: nodes(prepared%model%elements + 1)
      nodes = nodal_displacement(prepared%model, u)
      tip = nodes(size(nodes))
   end function tip_displacement

   !> Permutation that sorts `values` ascending (insertion sort, a few entries).
   pure function sorted(values) result(permutation)
      real(dp), intent(in) :: values(:)
      integer :: permutation(size(values))
      integer :: i, j, moving
      permutation = [(i, i = 1, size(values))]
      do i = 2, size(values)
         moving = permutation(i)
         j = i - 1
         do while (j >= 1)
            if (values(permutation(j)) <= values(moving)) exit
            permutation(j + 1) = permutation(j)
            j = j - 1
         end do
         permutation(j + 1) = moving
      end do
   end function sorted


end program test_free_vibration_spectrum
