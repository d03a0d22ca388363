!> Verification of the free flight of two bending planes (issue 21; docs/method.md, "Two
!! bending planes and tube-support contact"), on verification/dynamics/two_planes.nml:
!! (1) planar reduction: planes = 2 with loads and initial data in y equals planes = 1
!!     bit for bit in y at every step, z exactly 0; turned by 90 degrees, z equals the
!!     planar y bit for bit and y is exactly 0 (the stacked layout does the same operations
!!     in the same order on each plane, and direction_shares is exact at 90 degrees);
!! (2) rotation invariance (I_z = I): turned by 30 degrees, y = cos 30 u and z = sin 30 u
!!     of the planar u to round-off, at every step; likewise for the loads of &forces (a
!!     random distributed load and a harmonic point force), each turned by its direction,
!!     and bit for bit along z;
!! (3) a section whose inertias differ (I_z = 2.5 I), no damping, no load, mode-1 initial
!!     displacement at 45 degrees: the tip moves in y and z at the closed-form cantilever
!!     frequencies (beta_1 L)^2 sqrt(E I/(rho S L^4)) and the same with I_z, within the
!!     theta-method's phase error; its energy is conserved to round-off (theta = 1/2);
!! (4) the energy ledger of two planes with damping, a load at 60 degrees, I_z /= I and
!!     theta = 0.6: E - W + D stays E_0 to round-off;
!! (5) a whirl (I_z = I, theta = 1/2): the discrete angular momentum about the beam's axis
!!     is conserved to round-off over 1e5 steps.
program test_two_planes
   use vibrobeam_kinds, only: dp, output_unit
   use vibrobeam_scene, only: scene_type
   use vibrobeam_force_settings, only: force_settings
   use vibrobeam_problem, only: run_problem
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_cantilever_exact, only: cantilever_frequency
   use vibrobeam_test_support, only: test_counter, read_test_scene, prepare_test_scene, same_bits, &
      start_test_stepper, advance_test_stepper, angular_momentum
   implicit none
   type(test_counter) :: t
   type(scene_type) :: scene, planar, turned
   type(run_problem) :: prepared_planar, prepared
   class(time_stepper), allocatable :: reference, stepper
   character(len=512) :: path
   real(dp), parameter :: eps = epsilon(1.0_dp)
   real(dp) :: shares(2), deviation, scale, tolerance, omega_y, omega_z, amplitude, energy0, worst, tip(2)
   real(dp) :: ledger
   integer :: n, steps, j
   logical :: same
   call get_command_argument(1, path)
   scene = read_test_scene(trim(path))
   steps = nint(scene%time%t_end/scene%time%dt)

   ! (1) planar reduction, y and z
   planar = scene
   planar%beam%planes = 1
   call prepare_test_scene(planar, prepared_planar)
   call prepare_test_scene(scene, prepared)
   call start_test_stepper(planar, prepared_planar, reference)
   call start_test_stepper(scene, prepared, stepper)
   j = prepared%model%unknowns
   call t%check_true('two planes hold 2J unknowns', size(stepper%u) == 2*j .and. size(reference%u) == j)
   same = .true.
   do n = 1, steps
      call advance_test_stepper(reference)
      call advance_test_stepper(stepper)
      same = same .and. all(same_bits(stepper%u(1:j), reference%u)) .and. all(same_bits(stepper%v(1:j), reference%v)) &
             .and. all(abs(stepper%u(j + 1:)) <= 0) .and. all(abs(stepper%v(j + 1:)) <= 0) .and. &
             same_bits(stepper%kinetic_energy(), reference%kinetic_energy()) .and. &
             same_bits(stepper%elastic_energy(), reference%elastic_energy()) .and. &
             same_bits(stepper%energy%work, reference%energy%work) .and. &
             same_bits(stepper%energy%dissipated_damping, reference%energy%dissipated_damping)
   end do
   call t%check_true('direction 0: y equals the planar run bit for bit at every step, z exactly 0', same)
   turned = scene
   turned%load%direction = 90
   turned%initial%direction = 90
   turned%initial%displacement_direction = 90
   call prepare_test_scene(turned, prepared)
   call start_test_stepper(planar, prepared_planar, reference)
   call start_test_stepper(turned, prepared, stepper)
   same = .true.
   do n = 1, steps
      call advance_test_stepper(reference)
      call advance_test_stepper(stepper)
      same = same .and. all(same_bits(stepper%u(j + 1:), reference%u)) .and. &
             all(same_bits(stepper%v(j + 1:), reference%v)) .and. all(abs(stepper%u(1:j)) <= 0) .and. &
             all(abs(stepper%v(1:j)) <= 0)
   end do
   call t%check_true('direction 90: z equals the planar y bit for bit at every step, y exactly 0', same)

   ! (2) turned by 30 degrees: each plane the planar run times its share
   turned%load%direction = 30
   turned%initial%direction = 30
   shares = [cos(30*acos(-1.0_dp)/180), sin(30*acos(-1.0_dp)/180)]
   call prepare_test_scene(turned, prepared)
   deviation = turned_deviation()
   ! the two runs apply the same linear step to data that differ by one rounding; each
   ! step rounds each unknown in a few operations (the fused residual solve, the update),
   ! and the step's map is not expanding (theta = 1/2 with damping), so the difference
   ! grows at most by a few eps of the largest value per step: 8 n eps
   tolerance = 8*steps*eps
   write (output_unit, '(a,es10.3,a,es10.3)') 'direction 30: largest deviation / largest |u| ', deviation, &
      ', tolerance ', tolerance
   call t%check_close('direction 30: y = cos 30 u, z = sin 30 u of the planar run', deviation, 0.0_dp, &
                      tolerance, 1.0_dp)

   ! (2b) the loads of &forces, each turned by its own direction: a random distributed load
   ! and a harmonic point force, both along z (90 degrees), equal the planar run bit for
   ! bit in z (y exactly 0); both at 30 degrees, the planar run times the shares
   planar = scene
   planar%beam%planes = 1
   planar%load%point_force = 0
   planar%forces%load = [force_settings(kind='distributed', signal='random', psd_level=0.5_dp, band_from=20.0_dp, &
                                        band_to=2000.0_dp, correlation_length=0.1_dp), &
                         force_settings(kind='point', position=0.5_dp, signal='harmonic', amplitude=2.0_dp, &
                                        frequency=250.0_dp)]
   call prepare_test_scene(planar, prepared_planar)
   turned = planar
   turned%beam%planes = 2
   turned%initial%direction = 90
   turned%forces%load(:)%direction = 90
   call prepare_test_scene(turned, prepared)
   call start_test_stepper(planar, prepared_planar, reference)
   call start_test_stepper(turned, prepared, stepper)
   same = .true.
   do n = 1, steps
      call advance_test_stepper(reference)
      call advance_test_stepper(stepper)
      same = same .and. all(same_bits(stepper%u(j + 1:), reference%u)) .and. &
             all(same_bits(stepper%v(j + 1:), reference%v)) .and. all(abs(stepper%u(1:j)) <= 0)
   end do
   call t%check_true('&forces along z: z equals the planar run bit for bit at every step, y exactly 0', same)
   turned%initial%direction = 30
   turned%forces%load(:)%direction = 30
   call prepare_test_scene(turned, prepared)
   deviation = turned_deviation()
   write (output_unit, '(a,es10.3)') '&forces at 30 degrees: largest deviation / largest |u| ', deviation
   ! as (2): 8 n eps
   call t%check_close('&forces at 30 degrees: y = cos 30 u, z = sin 30 u of the planar run', deviation, 0.0_dp, &
                      tolerance, 1.0_dp)

   ! (3) I_z = 2.5 I: two frequencies, against the closed form; energy conserved
   turned = scene
   turned%forces = scene%forces
   turned%beam%inertia_z = 2.5_dp*scene%beam%inertia
   turned%beam%rayleigh_mass = 0
   turned%load%point_force = 0
   turned%initial%velocity = 'zero'
   turned%initial%displacement = 'mode'
   turned%initial%displacement_mode = 1
   amplitude = 1e-3_dp
   turned%initial%displacement_amplitude = amplitude
   turned%initial%displacement_direction = 45
   call prepare_test_scene(turned, prepared)
   call start_test_stepper(turned, prepared, stepper)
   energy0 = stepper%kinetic_energy() + stepper%elastic_energy()
   worst = 0
   do n = 1, steps
      call advance_test_stepper(stepper)
      worst = max(worst, abs(stepper%kinetic_energy() + stepper%elastic_energy() - energy0))
   end do
   omega_y = cantilever_frequency(1, scene%beam%length, scene%beam%ei()/scene%beam%rho_s())
   omega_z = cantilever_frequency(1, scene%beam%length, turned%beam%ei_z()/scene%beam%rho_s())
   tip = [stepper%u(j - 1), stepper%u(2*j - 1)]
   write (output_unit, '(a,2es22.14)') 'tip (y, z) at t_end: vibrobeam ', tip
   write (output_unit, '(a,2es22.14)') '                     closed form ', &
      amplitude*sqrt(0.5_dp)*[cos(omega_y*scene%time%t_end), cos(omega_z*scene%time%t_end)]
   ! tolerance: the theta-method's phase error (omega dt)^2/12 omega t (1.5e-5 of the
   ! amplitude for z at t_end) plus the mesh's: omega_1 at N = 16 is 1e-7 relative and the
   ! interpolated closed-form mode holds higher modes at about 1e-6: 3e-5 of the amplitude
   tolerance = 3e-5_dp
   call t%check_close('tip in y at the closed-form frequency of I', tip(1), &
                      amplitude*sqrt(0.5_dp)*cos(omega_y*scene%time%t_end), tolerance, amplitude)
   call t%check_close('tip in z at the closed-form frequency of I_z = 2.5 I', tip(2), &
                      amplitude*sqrt(0.5_dp)*cos(omega_z*scene%time%t_end), tolerance, amplitude)
   ! the frequencies differ enough that a z plane stepped with K (not K_z) fails this
   call t%check_true('the planes'' frequencies are told apart', &
                     abs(cos(omega_y*scene%time%t_end) - cos(omega_z*scene%time%t_end)) > 100*tolerance)
   ! theta = 1/2 conserves E exactly; each step rounds E by a few eps: 8 n eps E_0
   write (output_unit, '(a,es10.3,a,es10.3)') 'largest |E - E_0|/E_0 ', worst/energy0, ', tolerance ', 8*steps*eps
   call t%check_close('energy of both planes conserved (theta = 1/2)', worst/energy0, 0.0_dp, 8*steps*eps, 1.0_dp)

   ! (4) the ledger: damping, a load at 60 degrees, I_z /= I, theta = 0.6
   turned = scene
   turned%beam%inertia_z = 0.4_dp*scene%beam%inertia
   turned%load%direction = 60
   turned%initial%direction = -20
   turned%time%theta = 0.6_dp
   call prepare_test_scene(turned, prepared)
   call start_test_stepper(turned, prepared, stepper)
   energy0 = stepper%kinetic_energy() + stepper%elastic_energy()
   worst = 0
   scale = energy0
   do n = 1, steps
      call advance_test_stepper(stepper)
      associate (e => stepper%energy)
         ledger = stepper%kinetic_energy() + stepper%elastic_energy() - e%work + e%dissipated_damping + &
                  e%dissipated_numerical - energy0
         scale = max(scale, abs(e%work), e%dissipated_damping + e%dissipated_numerical)
      end associate
      worst = max(worst, abs(ledger))
   end do
   write (output_unit, '(a,es10.3,a,es10.3)') 'largest |E - W + D - E_0| / energy scale ', worst/scale, &
      ', tolerance ', 8*steps*eps
   call t%check_close('energy ledger of two planes (damping, load at 60 degrees, theta = 0.6)', worst/scale, 0.0_dp, &
                      8*steps*eps, 1.0_dp)
   call t%check_true('the ledger''s terms are not trivial', stepper%energy%dissipated_damping > 0 .and. &
                     stepper%energy%dissipated_numerical > 0 .and. abs(stepper%energy%work) > 0)

   ! (5) a whirl (I_z = I, no damping, no load, theta = 1/2): mode-1 displacement in y,
   ! mode-1 velocity omega_1 times its amplitude in z; the angular momentum about the axis
   ! U_y^T M V_z - U_z^T M V_y is conserved to round-off over 1e5 steps (docs/theory.md,
   ! "Two bending planes": the step is the implicit midpoint rule)
   turned = scene
   turned%beam%rayleigh_mass = 0
   turned%load%point_force = 0
   turned%initial%displacement = 'mode'
   turned%initial%displacement_amplitude = amplitude
   turned%initial%velocity_amplitude = omega_y*amplitude
   turned%initial%direction = 90
   turned%time%t_end = 1e5_dp*scene%time%dt
   call prepare_test_scene(turned, prepared)
   call start_test_stepper(turned, prepared, stepper)
   energy0 = angular_momentum(stepper)
   worst = 0
   do n = 1, 100000
      call advance_test_stepper(stepper)
      worst = max(worst, abs(angular_momentum(stepper) - energy0))
   end do
   write (output_unit, '(a,es22.14,a,es10.3,a,es10.3)') 'angular momentum ', energy0, ', largest change relative ', &
      worst/abs(energy0), ', tolerance ', 8*1e5_dp*eps
   call t%check_close('angular momentum of a whirl conserved over 1e5 steps (theta = 1/2)', worst/abs(energy0), 0.0_dp, &
                      8*1e5_dp*eps, 1.0_dp)
   call t%check_true('the whirl moves both planes', maxval(abs(stepper%u(1:j))) > 0.5_dp*amplitude .and. &
                     maxval(abs(stepper%u(j + 1:))) > 0.5_dp*amplitude)
   call t%finish('test_two_planes')

contains

   !> The largest |y - cos a u| and |z - sin a u| over the steps of `turned` (prepared) against
   !! the planar run `planar` (prepared_planar), (cos a, sin a) = `shares`, relative to the
   !! largest |u| of the planar run.
   real(dp) function turned_deviation() result(relative)
      real(dp) :: largest, largest_u
      call start_test_stepper(planar, prepared_planar, reference)
      call start_test_stepper(turned, prepared, stepper)
      largest = 0
      largest_u = 0
      do n = 1, steps
         call advance_test_stepper(reference)
         call advance_test_stepper(stepper)
         largest = max(largest, maxval(abs(stepper%u(1:j) - shares(1)*reference%u)), &
                       maxval(abs(stepper%u(j + 1:) - shares(2)*reference%u)))
         largest_u = max(largest_u, maxval(abs(reference%u)))
      end do
      relative = largest/largest_u
   end function turned_deviation
end program test_two_planes
