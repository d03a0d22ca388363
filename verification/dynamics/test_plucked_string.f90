!> A plucked string (issue 18, item 5): a tensioned beam of negligible EI between pinned
!! ends, released at rest from a triangle, stepped by the velocity scheme and compared with
!! d'Alembert's exact solution (docs/theory.md §7, "Sections and axial force").
!!
!! L = 1 m, rho S = 1 (given by k2), T = 1 (c = sqrt(T/rho S) = 1 m/s: the period of the
!! fundamental is 2L/c = 2 s), EI = k2 = 1e-10 T L^2 (its dispersion, (n pi/L)^2 EI/(2T)
!! relative on mode n, shifts the phase of the modes the mesh resolves by less than 1e-6
!! over the window: far below the errors measured); the triangle of height d = 0.01 m at
!! x = a = 0.25 m (a node of every mesh here). d'Alembert: u(x, t) = (U(x - ct) +
!! U(x + ct))/2 with U the odd 2L-periodic extension of the triangle. The initial
!! displacement on the mesh is the triangle's L2 projection (M U_0 = int u_0 phi, exact:
!! the triangle is linear on each element); the initial velocity is 0.
!!
!! Refinement: N = 16, 32, 64, 128 with dt = h/(2c) (Courant number 1/2), both bases;
!! compared at t = 0.375, 0.625 and 1.125 s (the kinks have travelled, reflected at the
!! ends and crossed; they lie on nodes of every mesh then, so that the largest nodal error
!! is not modulated by where a kink falls between nodes), by the RMS of the nodal error (a
!! discrete L2 norm) and its maximum, relative to d. What to expect (derived, not fitted):
!! the triangle's sine coefficients fall like a_n ~ n^-2; the theta = 1/2 rule advances
!! mode n by 2 atan(omega_n dt/2) per step instead of omega_n dt, a phase error
!! omega_n t (omega_n dt)^2/12 ~ n^3 h^2 at fixed t and Courant number, so the modes below
!! n* = h^(-2/3) err by a_n n^3 h^2 and the others by O(a_n): the L2 error is
!! (h^4 sum_{n<n*} n^2 + sum_{n>n*} n^-4)^(1/2) ~ h and the maximum h^2 sum_{n<n*} n +
!! sum_{n>n*} n^-2 ~ h^(2/3). (The space error of cubic elements on the string is h^6 per
!! mode, and the modes beyond the mesh, n > N, add h^(3/2) in L2 and h at most: both
!! smaller.) Checked: both errors fall at every refinement, and the observed orders from
!! N = 32 to 128 are at least 0.8 (L2; asymptotically 1) and 0.5 (maximum; 2/3), margins
!! of 0.2 for the approach to the asymptote; the measured orders are printed (1.02 to
!! 1.14 and 0.66 to 0.82); and dt alone (N = 128, dt = h/(2c), h/(4c), h/(8c)) lowers the
!! L2 error at each halving (printed; the time error dominates).
!! Energy: the theta = 1/2 scheme conserves 1/2 V^T M V + 1/2 U^T K U exactly without
!! contact (each mode is rotated, theory §3), tension's part included: checked to
!! 8 n eps cond(W) after the n steps of the finest run (cond(W) <= 1 + (dt omega_max/2)^2).
program test_plucked_string
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_model, only: nodal_displacement, load_vector, energy_integrals
   use vibrobeam_band, only: band_cholesky, band_factor, band_solve, band_matvec
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_test_support, only: test_counter, prepare_test_scene
   implicit none
   type(test_counter) :: t
   real(dp), parameter :: length = 1, c = 1, height = 0.01_dp, peak = 0.25_dp
   real(dp), parameter :: times(3) = [0.375_dp, 0.625_dp, 1.125_dp]
   character(len=8), parameter :: bases(2) = [character(len=8) :: 'hermite', 'bspline']
   integer :: b
   do b = 1, 2
      call refine(trim(bases(b)))
   end do
   call t%finish('test_plucked_string')

contains

   !> The triangle: height d at a, 0 at the ends.
   pure function triangle(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      if (x <= peak) then
         value = height*x/peak
      else
         value = height*(length - x)/(length - peak)
      end if
   end function triangle

   !> d'Alembert's solution at x, t.
   pure real(dp) function exact(x, time)
      real(dp), intent(in) :: x, time
      exact = 0.5_dp*(extended(x - c*time) + extended(x + c*time))
   end function exact

   !> The odd 2L-periodic extension of the triangle.
   pure real(dp) function extended(x)
      real(dp), intent(in) :: x
      real(dp) :: y
      y = modulo(x, 2*length)
      if (y <= length) then
         extended = triangle(y)
      else
         extended = -triangle(2*length - y)
      end if
   end function extended

   !> Run N elements with dt = h/(courant c) to each of `times`: the RMS and the largest
   !! nodal error at each; with `energy_drift`, |E(end)/E(0) - 1| and its bound.
   subroutine run(basis, elements, courant, rms, largest, energy_drift, energy_bound)
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), intent(in) :: courant
      real(dp), intent(out) :: rms(size(times)), largest(size(times))
      real(dp), intent(out), optional :: energy_drift, energy_bound
      type(scene_type) :: scene
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      type(band_cholesky) :: factor
      real(dp), allocatable :: w(:), reference(:), mv(:)
      real(dp) :: bending, inertia, energy_0, energy_n, omega_max
      integer :: stat, k, i, steps, done
      character(len=512) :: errmsg
      scene%beam%length = length
      scene%beam%k2 = 1e-10_dp*c**2*length**2
      scene%beam%axial_force = c**2
      scene%beam%left_end = 'pinned'
      scene%beam%right_end = 'pinned'
      scene%mesh%basis = basis
      scene%mesh%elements = elements
      scene%time%scheme = 'velocity'
      scene%time%dt = length/elements/(courant*c)
      scene%time%t_end = times(size(times))
      allocate (scene%obstacles(0))
      call prepare_test_scene(scene, prepared)
      ! U_0: the L2 projection of the triangle
      prepared%start%u = load_vector(prepared%model, triangle)
      call band_factor(prepared%model%mass, factor, stat, errmsg)
      call band_solve(factor, prepared%start%u)
      prepared%start%v = 0
      call energy_integrals(prepared%model, prepared%start%u, bending, inertia)
      energy_0 = bending
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      call t%check_true(basis//' N = '//integer_text(elements)//': stepper', stat == 0, trim(errmsg))
      if (stat /= 0) return
      done = 0
      do k = 1, size(times)
         steps = nint(times(k)/scene%time%dt)
         do while (done < steps)
            call stepper%step(stat, errmsg)
            if (stat /= 0) exit
            done = done + 1
         end do
         call t%check_true(basis//' N = '//integer_text(elements)//': steps', stat == 0, trim(errmsg))
         w = nodal_displacement(prepared%model, stepper%u)
         reference = [(exact(length*i/elements, done*scene%time%dt), i=0, elements)]
         rms(k) = sqrt(sum((w - reference)**2)/size(w))/height
         largest(k) = maxval(abs(w - reference))/height
      end do
      if (present(energy_drift)) then
         call energy_integrals(prepared%model, stepper%u, bending, inertia)
         allocate (mv(size(stepper%v)))
         call band_matvec(prepared%model%mass, stepper%v, mv)
         energy_n = bending + 0.5_dp*dot_product(stepper%v, mv)
         energy_drift = abs(energy_n/energy_0 - 1)
         call highest_frequency(prepared%model, omega_max, stat, errmsg)
         energy_bound = 8*done*epsilon(1.0_dp)*(1 + (0.5_dp*scene%time%dt*omega_max)**2)
      end if
   end subroutine run

   !> The refinement path, the orders, dt alone and the energy (module documentation).
   subroutine refine(basis)
      character(len=*), intent(in) :: basis
      integer, parameter :: levels = 4
      real(dp) :: rms(size(times), levels), largest(size(times), levels), dt_rms(size(times), 3), &
                  dt_largest(size(times), 3), drift, bound, order_rms, order_largest
      integer :: level, k
      do level = 1, levels
         if (level < levels) then
            call run(basis, 16*2**(level - 1), 2.0_dp, rms(:, level), largest(:, level))
         else
            call run(basis, 16*2**(level - 1), 2.0_dp, rms(:, level), largest(:, level), drift, bound)
         end if
      end do
      do k = 1, size(times)
         order_rms = log(rms(k, 2)/rms(k, levels))/log(4.0_dp)
         order_largest = log(largest(k, 2)/largest(k, levels))/log(4.0_dp)
         write (*, '(a,f6.3,a,4es10.2,a,f5.2,a,4es10.2,a,f5.2)') basis//' t = ', times(k), &
            ' s: RMS error/d at N = 16..128', rms(k, :), ', order', order_rms, '; largest', largest(k, :), &
            ', order', order_largest
         call t%check_true(basis//' t = '//integer_text(nint(1000*times(k)))//' ms: the errors fall at each refinement', &
                           all(rms(k, 2:) < rms(k, :levels - 1)) .and. all(largest(k, 2:) < largest(k, :levels - 1)))
         call t%check_true(basis//' t = '//integer_text(nint(1000*times(k)))//' ms: L2 order (N = 32 to 128) >= 0.8', &
                           order_rms >= 0.8_dp)
         call t%check_true(basis//' t = '//integer_text(nint(1000*times(k)))//' ms: max order (N = 32 to 128) >= 0.5', &
                           order_largest >= 0.5_dp)
      end do
      ! dt alone at N = 128
      dt_rms(:, 1) = rms(:, levels)
      dt_largest(:, 1) = largest(:, levels)
      call run(basis, 128, 4.0_dp, dt_rms(:, 2), dt_largest(:, 2))
      call run(basis, 128, 8.0_dp, dt_rms(:, 3), dt_largest(:, 3))
      write (*, '(a,3es10.2,a,3es10.2)') basis//' N = 128, dt = h/2c, h/4c, h/8c: RMS error/d at t = 1.125 s', &
         dt_rms(size(times), :), '; largest', dt_largest(size(times), :)
      call t%check_true(basis//' N = 128: the L2 error falls as dt alone is refined', &
                        all(dt_rms(:, 2) < dt_rms(:, 1)) .and. all(dt_rms(:, 3) < dt_rms(:, 2)))
      write (*, '(a,es10.2,a,es10.2)') basis//' energy drift after the finest run', drift, ', bound', bound
      call t%check_close(basis//' N = 128: energy (tension included) conserved', drift, 0.0_dp, 1.0_dp, bound)
   end subroutine refine
end program test_plucked_string
