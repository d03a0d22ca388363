!> vibrobeam's velocity scheme on a string against a point obstacle, measured against the
!! exact solution (vibrobeam_string_obstacle_reference; docs/theory.md §7, "A string
!! against a point obstacle"): the runs of verification/dynamics/test_string_obstacle.f90
!! and of studies/string_obstacle.
!!
!! The string is a tensioned beam of negligible bending stiffness between pinned ends:
!! rho S = 1 (the beam is given by k2), T = c^2, EI = k2 = 1e-10 T L^2. Its bending shifts
!! mode n's frequency by (n pi/L)^2 EI/(2T) relative (5e-5 for n = 320) and smooths the
!! kink at the obstacle over sqrt(EI/T) = 1e-5 L, a hundredth of the finest element used:
!! both below the errors measured. The obstacle is rigid, punctual, at a node, with e = 1.
module vibrobeam_string_obstacle_runs
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type, obstacle_type
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_model, only: nodal_displacement, load_vector, energy_integrals
   use vibrobeam_band, only: band_cholesky, band_factor, band_solve, band_matvec
   use vibrobeam_test_support, only: prepare_test_scene
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_string_obstacle_reference, only: string_reference
   implicit none
   private

   !> What a run measured, every error relative to the scale given to the run (the
   !! amplitude of the initial data).
   type, public :: string_run_errors
      real(dp) :: rms = 0            !! largest RMS nodal error over the sample times
      real(dp) :: largest = 0        !! largest nodal error over the sample times
      real(dp) :: point = 0          !! largest error of the obstacle node over every step
      real(dp) :: away = 0           !! largest error at x = x_away over every step
      real(dp) :: impulse = 0        !! largest error of the cumulative contact impulse over every step,
                                     !! relative to the exact impulse at the end (0 without contact)
      real(dp) :: energy_drift = 0   !! largest |E(t_n)/E(0) - 1| over every step
      real(dp) :: energy_bound = 0   !! round-off bound of energy_drift: 8 n eps cond(W), n steps,
                                     !! cond(W) <= 1 + (dt omega_max/2)^2 (as verification.plucked_string)
      real(dp) :: impulse_end = 0    !! the run's cumulative impulse at the end / the exact one
      real(dp) :: contact_times = 0  !! largest error of the start or end of a contact force (s): for each
                                     !! exact interval of R > 0, the first and last step with an impulse
                                     !! between the midpoints to its neighbours; an interval without one
                                     !! counts its whole length
      integer :: steps = 0
      integer :: impulse_steps = 0   !! steps whose impulse at the obstacle is not zero
   end type string_run_errors

   public :: run_string_obstacle

   !> The reference whose initial data the projection reads (load_vector takes a pure
   !! function of x only).
   type(string_reference) :: projected

contains

   !> u0 of the reference at x.
   pure real(dp) function initial_displacement(x)
      real(dp), intent(in) :: x
      initial_displacement = projected%displacement(x, 0.0_dp)
   end function initial_displacement

   !> v0 of the reference at x (c (g' - f') of the piecewise-linear initial waves).
   pure real(dp) function initial_velocity(x)
      real(dp), intent(in) :: x
      integer :: k
      k = max(1, min(size(projected%knots) - 1, count(projected%knots <= x)))
      initial_velocity = projected%c*((projected%g0(k + 1) - projected%g0(k)) - (projected%f0(k + 1) - projected%f0(k))) &
                         /(projected%knots(k + 1) - projected%knots(k))
   end function initial_velocity

   !> Step N elements of `basis` with dt = h/(courant c) to t_end from the L2 projections of
   !! the reference's initial data (exact: they are linear on each element when the knots
   !! are nodes), and measure against the reference (built to t_end): the nodal errors every
   !! `sample_every` seconds, the obstacle node, the node at x_away and the cumulative
   !! impulse at every step (the exact one is 2 c (w - a - b), per unit rho S: docs/theory.md
   !! §7), the energy at every step. `restitution` other than 1 is for the study's comparison.
   subroutine run_string_obstacle(ref, basis, elements, courant, t_end, sample_every, x_away, scale, errors, &
                                  stat, errmsg, restitution)
      type(string_reference), intent(in) :: ref
      character(len=*), intent(in) :: basis
      integer, intent(in) :: elements
      real(dp), intent(in) :: courant, t_end, sample_every, x_away, scale
      type(string_run_errors), intent(out) :: errors
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), intent(in), optional :: restitution   !! e of the obstacle (default 1)
      type(scene_type) :: scene
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      type(band_cholesky) :: factor
      real(dp), allocatable :: w(:), exact(:), mv(:), starts(:), ends(:), borders(:), first(:), last(:)
      real(dp) :: bending, inertia, energy_0, omega_max, time, impulse, a, b, exact_impulse, impulse_total
      integer :: i, n, steps, node, node_away, every, interval
      scene%beam%length = ref%length
      scene%beam%k2 = 1e-10_dp*ref%c**2*ref%length**2
      scene%beam%axial_force = ref%c**2
      scene%beam%left_end = 'pinned'
      scene%beam%right_end = 'pinned'
      scene%mesh%basis = basis
      scene%mesh%elements = elements
      scene%time%scheme = 'velocity'
      scene%time%dt = ref%length/elements/(courant*ref%c)
      scene%time%t_end = t_end
      scene%impact%restitution = 1
      if (present(restitution)) scene%impact%restitution = restitution
      allocate (scene%obstacles(1))
      scene%obstacles(1) = obstacle_type(side='below', x_from=ref%x0, x_to=ref%x0, level_from=ref%level, &
                                         level_to=ref%level)
      call prepare_test_scene(scene, prepared)
      projected = ref
      call band_factor(prepared%model%mass, factor, stat, errmsg)
      if (stat /= 0) return
      prepared%start%u = load_vector(prepared%model, initial_displacement)
      call band_solve(factor, prepared%start%u)
      prepared%start%v = load_vector(prepared%model, initial_velocity)
      call band_solve(factor, prepared%start%v)
      allocate (mv(size(prepared%start%v)))
      energy_0 = total_energy(prepared%start%u, prepared%start%v)
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) return
      node = nint(ref%x0/ref%length*elements)
      node_away = nint(x_away/ref%length*elements)
      every = max(1, nint(sample_every/scene%time%dt))
      steps = nint(t_end/scene%time%dt)
      call exact_impulse_at(t_end, impulse_total)
      impulse = 0
      call ref%contact_intervals(starts, ends, pressed=.true.)
      ! interval k owns the steps between borders(k) and borders(k + 1)
      allocate (borders(size(starts) + 1))
      borders(1) = -huge(1.0_dp)
      borders(2:size(starts)) = 0.5_dp*(ends(:size(ends) - 1) + starts(2:))
      borders(size(borders)) = huge(1.0_dp)
      allocate (first(size(starts)), source=huge(1.0_dp))
      allocate (last(size(starts)), source=-huge(1.0_dp))
      do n = 1, steps
         call stepper%step(stat, errmsg)
         if (stat /= 0) return
         time = n*scene%time%dt
         if (stepper%report%active_count > 0) then
            if (maxval(abs(stepper%report%impulse(:stepper%report%active_count))) > 0) then
               errors%impulse_steps = errors%impulse_steps + 1
               impulse = impulse + sum(stepper%report%impulse(:stepper%report%active_count))
               interval = count(borders(2:size(borders) - 1) < time) + 1
               if (interval <= size(starts)) then
                  first(interval) = min(first(interval), time)
                  last(interval) = max(last(interval), time)
               end if
            end if
         end if
         w = nodal_displacement(prepared%model, stepper%u)
         errors%point = max(errors%point, abs(w(node + 1) - ref%displacement(ref%x0, time))/scale)
         errors%away = max(errors%away, abs(w(node_away + 1) - ref%displacement(x_away, time))/scale)
         call exact_impulse_at(time, exact_impulse)
         if (impulse_total > 0) errors%impulse = max(errors%impulse, abs(impulse - exact_impulse)/impulse_total)
         errors%energy_drift = max(errors%energy_drift, abs(total_energy(stepper%u, stepper%v)/energy_0 - 1))
         if (mod(n, every) == 0) then
            exact = [(ref%displacement(ref%length*i/elements, time), i=0, elements)]
            errors%rms = max(errors%rms, sqrt(sum((w - exact)**2)/size(w))/scale)
            errors%largest = max(errors%largest, maxval(abs(w - exact))/scale)
         end if
      end do
      errors%steps = steps
      do i = 1, size(starts)
         if (first(i) <= last(i)) then
            errors%contact_times = max(errors%contact_times, abs(first(i) - starts(i)), abs(last(i) - ends(i)))
         else
            errors%contact_times = max(errors%contact_times, ends(i) - starts(i))
         end if
      end do
      call highest_frequency(prepared%model, omega_max, stat, errmsg)
      if (stat /= 0) return
      errors%energy_bound = 8*steps*epsilon(1.0_dp)*(1 + (0.5_dp*scene%time%dt*omega_max)**2)
      if (impulse_total > 0) errors%impulse_end = impulse/impulse_total
   contains
      !> 1/2 V^T M V + 1/2 U^T K U (tension's part included).
      real(dp) function total_energy(u, v)
         real(dp), intent(in) :: u(:), v(:)
         call energy_integrals(prepared%model, u, bending, inertia)
         call band_matvec(prepared%model%mass, v, mv)
         total_energy = bending + 0.5_dp*dot_product(v, mv)
      end function total_energy

      !> The exact cumulative impulse per unit rho S up to `at`, 2 c (w - a - b).
      subroutine exact_impulse_at(at, value)
         real(dp), intent(in) :: at
         real(dp), intent(out) :: value
         call ref%incoming_at(at, a, b)
         value = 2*ref%c*(ref%point_displacement(at) - a - b)
      end subroutine exact_impulse_at
   end subroutine run_string_obstacle
end module vibrobeam_string_obstacle_runs
