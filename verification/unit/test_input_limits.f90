!> The hard limits of the input (docs/input.md, "Hard limits") keep every quantity the
!! model derives from the inputs finite and normal. At every corner of the box of hard
!! limits (L, N, E, rho, S, I or k2, dt, theta), for both bases, this test evaluates what
!! the code itself evaluates - the assembled mass and stiffness matrices (with h = L/N,
!! built as three elements of that size), the iteration matrix W = M + theta^2 dt^2 K +
!! theta dt (a M + b K), omega_max of the discrete model, omega_1 and steps per period,
!! the base-excitation load rho S A Omega^2, static deflections, energy scales, the
!! penetration scale - and requires each non-zero value to lie in [tiny, huge]. In a Debug
!! build (-ffpe-trap=overflow) an overflowing expression would stop the test itself.
!! It prints the largest and smallest magnitude met, quoted in docs/input.md.
program test_input_limits
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_scene, only: scene_variables
   use vibrobeam_namelist_schema, only: namelist_variable, variable_index
   use vibrobeam_model, only: beam_model, build_model
   use vibrobeam_band, only: symmetric_band, band_combination
   use vibrobeam_highest_frequency, only: highest_frequency
   use vibrobeam_cantilever_exact, only: cantilever_frequency
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   type(namelist_variable), allocatable :: table(:)
   real(dp) :: length(2), elements(2), youngs(2), density(2), area(2), inertia(2), k2(2), dt(2), theta(2)
   real(dp) :: largest, smallest
   character(len=7), parameter :: bases(2) = ['hermite', 'bspline']
   integer :: a, b, c, d, e, f, g, r, basis, route
   integer :: bad
   allocate (table, source=scene_variables())
   length = limits('beam', 'length')
   elements = [1.0_dp, 1e6_dp]
   youngs = limits('beam', 'youngs_modulus')
   density = limits('beam', 'density')
   area = limits('beam', 'area')
   inertia = limits('beam', 'inertia')
   k2 = limits('beam', 'k2')
   dt = limits('time', 'dt')
   theta = limits('time', 'theta')
   largest = 0
   smallest = huge(1.0_dp)
   bad = 0
   do route = 1, 2   ! 1: E, rho, S, I; 2: k2 (rho S = 1)
      do a = 1, 2; do b = 1, 2; do c = 1, 2; do d = 1, 2; do e = 1, 2; do f = 1, 2; do g = 1, 2; do r = 1, 2
         if (route == 2 .and. (c == 2 .or. d == 2 .or. e == 2)) cycle   ! E, rho, S not used
         do basis = 1, 2
            if (route == 1) then
               call corner(length(a), elements(b), youngs(c)*inertia(f), density(d)*area(e), dt(g), theta(r), &
                           bases(basis))
            else
               call corner(length(a), elements(b), k2(f), 1.0_dp, dt(g), theta(r), bases(basis))
            end if
         end do
      end do; end do; end do; end do; end do; end do; end do; end do
   end do
   call t%check_true('every derived quantity finite and normal at every corner', bad == 0)
   write (*, '(a,es10.3,a,es10.3)') 'largest magnitude ', largest, ', smallest non-zero magnitude ', smallest
   call t%finish('test_input_limits')

contains

   !> [lowest, highest] of group.name in the input table.
   function limits(group, name) result(range)
      character(len=*), intent(in) :: group, name
      real(dp) :: range(2)
      range = [table(variable_index(table, group, name))%lowest, table(variable_index(table, group, name))%highest]
   end function limits

   subroutine corner(beam_length, element_count, ei, rho_s, step, theta_value, basis_name)
      real(dp), intent(in) :: beam_length, element_count, ei, rho_s, step, theta_value
      character(len=*), intent(in) :: basis_name
      type(beam_model) :: model
      type(symmetric_band) :: iteration_matrix
      real(dp) :: h, omega_max, omega_1, value, amplitude, frequency, load
      real(dp), parameter :: rayleigh_mass(2) = [1e-30_dp, 1e12_dp], rayleigh_stiffness(2) = [1e-30_dp, 1e3_dp]
      real(dp), parameter :: small = 1e-30_dp   ! the least non-zero magnitude of every other input
      integer :: stat, i, j
      character(len=128) :: errmsg
      h = beam_length/element_count
      ! three elements of size h: the element matrices of the full mesh, at low cost
      call build_model(basis_name, 3, 3*h, rho_s, ei, model, stat, errmsg)
      call record('mass matrix', model%mass%lower)
      call record('stiffness matrix', model%stiffness%lower)
      do i = 1, 2
         do j = 1, 2
            iteration_matrix = band_combination(1.0_dp, model%mass, theta_value**2*step**2, model%stiffness)
            iteration_matrix = band_combination(1.0_dp, iteration_matrix, theta_value*step*rayleigh_mass(i), &
                                                model%mass)
            iteration_matrix = band_combination(1.0_dp, iteration_matrix, theta_value*step*rayleigh_stiffness(j), &
                                                model%stiffness)
            call record('W = M + theta^2 dt^2 K + theta dt C', iteration_matrix%lower)
         end do
      end do
      call highest_frequency(model, omega_max, stat, errmsg)
      call record_value('omega_max', omega_max)
      call record_value('omega_max^2', omega_max**2)
      call record_value('omega_max dt', omega_max*step)
      omega_1 = cantilever_frequency(1, beam_length, ei/rho_s)
      call record_value('k2', ei/rho_s)
      call record_value('omega_1', omega_1)
      call record_value('steps per period of mode 1', 2*pi/(omega_1*step))
      do i = 1, 2
         amplitude = merge(small, 1e6_dp, i == 1)      ! base_amplitude, displacement_amplitude
         frequency = merge(small, 1e15_dp, i == 1)     ! base_frequency
         load = merge(small, 1e15_dp, i == 1)          ! distributed, point_force
         call record_value('rho S A Omega^2', rho_s*amplitude*frequency**2)
         call record_value('uniform load deflection q L^4/(8 EI)', load*beam_length**4/(8*ei))
         call record_value('point load deflection F L^3/(3 EI)', load*beam_length**3/(3*ei))
         value = merge(small, 1e8_dp, i == 1)          ! velocity_amplitude
         call record_value('kinetic energy 1/2 rho S L v^2', 0.5_dp*rho_s*beam_length*value**2)
         call record_value('penetration scale dt v', step*value)
         call record_value('elastic energy EI (A beta^2)^2 L', ei*(amplitude*(1.875_dp/beam_length)**2)**2*beam_length)
         call record_value('elastic energy of the load deflection', ei*(load*beam_length**2/ei)**2*beam_length)
      end do
   end subroutine corner

   subroutine record(name, values)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: values(:,:)
      integer :: i, j
      do j = 1, size(values, 2)
         do i = 1, size(values, 1)
            call record_value(name, values(i, j))
         end do
      end do
   end subroutine record

   subroutine record_value(name, value)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value
      if (.not. ieee_is_finite(value)) then
         bad = bad + 1
         write (*, '(a)') 'FAIL '//name//' is not finite'
         return
      end if
      if (abs(value) <= 0) return
      if (abs(value) < tiny(value)) then
         bad = bad + 1
         write (*, '(a,es10.3)') 'FAIL '//name//' is subnormal: ', value
      end if
      largest = max(largest, abs(value))
      smallest = min(smallest, abs(value))
   end subroutine record_value
end program test_input_limits
