!> The scene: every input value of a run, resolved (defaults filled in) and validated
!! (INTERFACE.md, "Input"). Reading the namelist file is `vibrobeam_input`'s job; this
!! module knows what values are allowed and how to list them with their units.
module vibrobeam_scene
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   implicit none
   private
   public :: scene_type, obstacle_type, scene_entry, max_obstacles, max_points, unset
   public :: validate_scene, scene_entries, format_scene, rho_s_of, ei_of, is_unset

   integer, parameter :: max_obstacles = 32       !! most obstacles a scene may hold
   integer, parameter :: max_points = 64          !! most observation points (&output points)
   real(dp), parameter :: unset = -huge(1.0_dp)   !! marks a real the user did not give
   integer, parameter :: name_length = 64, text_length = 256

   !> One obstacle of `&obstacles` (INTERFACE.md).
   type :: obstacle_type
      character(len=16) :: side = 'below'   !! 'below' (bounds u from below) | 'above'
      real(dp) :: x_from = 0, x_to = 0      !! extent along the beam (m)
      real(dp) :: level_from = 0, level_to = 0   !! surface height at x_from, x_to (m)
   end type obstacle_type

   !> Every input value of a run, after defaults.
   type :: scene_type
      ! &beam
      real(dp) :: length = 1                  !! L (m)
      real(dp) :: k2 = 1                      !! EI/(rho S) (m^4/s^2)
      real(dp) :: youngs_modulus = unset      !! E (Pa)
      real(dp) :: density = unset             !! rho (kg/m^3)
      real(dp) :: area = unset                !! S (m^2)
      real(dp) :: inertia = unset             !! I (m^4)
      real(dp) :: rayleigh_mass = 0           !! a in C = a M + b K (1/s)
      real(dp) :: rayleigh_stiffness = 0      !! b in C = a M + b K (s)
      ! &mesh
      integer :: elements = 32
      character(len=16) :: basis = 'hermite'
      ! &analysis
      character(len=16) :: kind = 'dynamics'
      integer :: modes = 6
      ! &obstacles
      type(obstacle_type), allocatable :: obstacles(:)
      ! &impact
      real(dp) :: restitution = 1
      character(len=16) :: separating_points = 'elastic'   !! restitution of active points moving away
      ! &time
      real(dp) :: t_end = 1, dt = 1e-4_dp
      character(len=16) :: scheme = 'velocity'
      real(dp) :: theta = 0.5_dp, gamma = 0.5_dp
      ! &initial
      character(len=16) :: displacement = 'zero'
      integer :: displacement_mode = 1
      real(dp) :: displacement_amplitude = 0
      character(len=16) :: velocity = 'zero'
      integer :: velocity_mode = 1
      real(dp) :: velocity_amplitude = 0
      character(len=text_length) :: from_file = ''   !! continue from this results file ('' = no)
      ! &load
      real(dp) :: distributed = 0, distributed_frequency = 0, distributed_phase = 0
      real(dp) :: point_force = 0, point_position = unset, point_frequency = 0
      real(dp) :: base_amplitude = 0, base_frequency = 0
      ! &solver (vibrobeam extension)
      character(len=16) :: contact_solver = 'auto'
      character(len=16) :: contact_method = 'newton'   !! 'newton' | 'pivoting'
      integer :: contact_max_iterations = 0
      ! &output
      character(len=text_length) :: file = 'results/vibrobeam.h5'
      integer :: every = 10                   !! histories every `every` steps
      integer :: field_every = 0              !! field snapshots every `field_every` steps (0: = every)
      logical :: text = .true.
      logical :: progress = .false.
      real(dp), allocatable :: points(:)      !! observation points x (m), beside the tip
      real(dp) :: measure_from = 0            !! start of the statistics window (s)
      real(dp) :: checkpoint_seconds = 0      !! > 0: restartable checkpoint this often (wall s)
      real(dp) :: episode_gap = unset         !! impacts closer than this form one episode (s); unset: default
   end type scene_type

   !> One resolved input value with its unit, for printing and for HDF5 attributes.
   !! Exactly one of the value components is meaningful, as `kind` says.
   type :: scene_entry
      character(len=name_length) :: name = ''     !! 'group.variable', e.g. 'beam.length'
      character(len=8) :: kind = 'real'           !! 'real' | 'integer' | 'string' | 'logical'
      real(dp) :: real_value = 0
      integer :: integer_value = 0
      character(len=text_length) :: string_value = ''
      logical :: logical_value = .false.
      character(len=16) :: unit = ''              !! SI unit, '' when dimensionless
   end type scene_entry

contains

   !> True when `value` is the `unset` marker (a NaN is a given value, not unset). Uses no
   !! ordered comparison on a NaN, which traps under -ffpe-trap=invalid.
   elemental logical function is_unset(value)
      real(dp), intent(in) :: value
      if (ieee_is_nan(value)) then
         is_unset = .false.
      else
         is_unset = value <= unset
      end if
   end function is_unset

   !> True when the beam is given by E, rho, S, I (then k2 = EI/(rho S)).
   pure logical function physical(scene)
      type(scene_type), intent(in) :: scene
      physical = .not. all(is_unset([scene%youngs_modulus, scene%density, scene%area, scene%inertia]))
   end function physical

   !> Mass per unit length rho S (kg/m); 1 when the beam is given by k2.
   pure real(dp) function rho_s_of(scene)
      type(scene_type), intent(in) :: scene
      rho_s_of = 1
      if (physical(scene)) rho_s_of = scene%density*scene%area
   end function rho_s_of

   !> Bending stiffness E I (N m^2); k2 when the beam is given by k2.
   pure real(dp) function ei_of(scene)
      type(scene_type), intent(in) :: scene
      ei_of = scene%k2
      if (physical(scene)) ei_of = scene%youngs_modulus*scene%inertia
   end function ei_of

   !> Check every value against what is allowed. On the first violation stat = 1 and
   !! errmsg reads like '&impact restitution = 1.5 is outside [0, 1]'.
   subroutine validate_scene(scene, stat, errmsg)
      type(scene_type), intent(in) :: scene
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i
      character(len=8) :: index
      stat = 0
      errmsg = ''
      ! &beam
      call positive('beam', 'length', scene%length)
      call positive('beam', 'k2', scene%k2)
      if (physical(scene)) then
         call given_positive('youngs_modulus', scene%youngs_modulus)
         call given_positive('density', scene%density)
         call given_positive('area', scene%area)
         call given_positive('inertia', scene%inertia)
      end if
      call in_range('beam', 'rayleigh_mass', scene%rayleigh_mass, 0.0_dp, huge(1.0_dp))
      call in_range('beam', 'rayleigh_stiffness', scene%rayleigh_stiffness, 0.0_dp, huge(1.0_dp))
      ! &mesh
      call integer_in_range('mesh', 'elements', scene%elements, 1, 1000000)
      call one_of('mesh', 'basis', scene%basis, [character(len=16) :: 'hermite', 'bspline'])
      ! &analysis
      call one_of('analysis', 'kind', scene%kind, [character(len=16) :: 'modes', 'static', 'dynamics'])
      if (stat /= 0) return
      call integer_in_range('analysis', 'modes', scene%modes, 1, &
                            merge(2*scene%elements, scene%elements + 1, scene%basis == 'hermite'))
      ! &obstacles
      do i = 1, size(scene%obstacles)
         write (index, '(i0)') i
         associate (o => scene%obstacles(i))
            call one_of('obstacles', 'side('//trim(index)//')', o%side, [character(len=16) :: 'below', 'above'])
            call in_range('obstacles', 'x_from('//trim(index)//')', o%x_from, 0.0_dp, scene%length)
            if (stat /= 0) return
            call in_range('obstacles', 'x_to('//trim(index)//')', o%x_to, o%x_from, scene%length)
            call finite('obstacles', 'level_from('//trim(index)//')', o%level_from)
            call finite('obstacles', 'level_to('//trim(index)//')', o%level_to)
         end associate
      end do
      ! &impact
      call in_range('impact', 'restitution', scene%restitution, 0.0_dp, 1.0_dp)
      call one_of('impact', 'separating_points', scene%separating_points, [character(len=16) :: 'elastic', 'restitution'])
      ! &time
      call positive('time', 't_end', scene%t_end)
      call positive('time', 'dt', scene%dt)
      if (stat /= 0) return
      call in_range('time', 'dt', scene%dt, tiny(1.0_dp), scene%t_end)
      call one_of('time', 'scheme', scene%scheme, [character(len=16) :: 'velocity', 'position'])
      call in_range('time', 'theta', scene%theta, 0.5_dp, 1.0_dp)
      call in_range('time', 'gamma', scene%gamma, 0.0_dp, 1.0_dp)
      ! &initial
      call one_of('initial', 'displacement', scene%displacement, [character(len=16) :: 'zero', 'mode', 'static'])
      call integer_in_range('initial', 'displacement_mode', scene%displacement_mode, 1, 100)
      call finite('initial', 'displacement_amplitude', scene%displacement_amplitude)
      call one_of('initial', 'velocity', scene%velocity, [character(len=16) :: 'zero', 'mode', 'uniform'])
      call integer_in_range('initial', 'velocity_mode', scene%velocity_mode, 1, 100)
      call finite('initial', 'velocity_amplitude', scene%velocity_amplitude)
      ! &load
      call finite('load', 'distributed', scene%distributed)
      call in_range('load', 'distributed_frequency', scene%distributed_frequency, 0.0_dp, huge(1.0_dp))
      call finite('load', 'distributed_phase', scene%distributed_phase)
      call finite('load', 'point_force', scene%point_force)
      call in_range('load', 'point_position', scene%point_position, 0.0_dp, scene%length)
      call in_range('load', 'point_frequency', scene%point_frequency, 0.0_dp, huge(1.0_dp))
      call finite('load', 'base_amplitude', scene%base_amplitude)
      call in_range('load', 'base_frequency', scene%base_frequency, 0.0_dp, huge(1.0_dp))
      ! &solver
      call one_of('solver', 'contact_solver', scene%contact_solver, [character(len=16) :: 'auto', 'delassus', 'band'])
      call one_of('solver', 'contact_method', scene%contact_method, [character(len=16) :: 'newton', 'pivoting'])
      call integer_in_range('solver', 'contact_max_iterations', scene%contact_max_iterations, 0, huge(1))
      ! &output
      if (len_trim(scene%file) == 0) call fail('&output file is empty; give a file name such as ''results/run.h5''')
      call integer_in_range('output', 'every', scene%every, 1, huge(1))
      call integer_in_range('output', 'field_every', scene%field_every, 0, huge(1))
      if (allocated(scene%points)) then
         do i = 1, size(scene%points)
            write (index, '(i0)') i
            call in_range('output', 'points('//trim(index)//')', scene%points(i), 0.0_dp, scene%length)
         end do
      end if
      call in_range('output', 'measure_from', scene%measure_from, 0.0_dp, huge(1.0_dp))
      call in_range('output', 'checkpoint_seconds', scene%checkpoint_seconds, 0.0_dp, huge(1.0_dp))
      if (.not. is_unset(scene%episode_gap)) &
         call in_range('output', 'episode_gap', scene%episode_gap, 0.0_dp, huge(1.0_dp))

   contains

      subroutine fail(message)
         character(len=*), intent(in) :: message
         if (stat /= 0) return   ! keep the first violation
         stat = 1
         errmsg = message
      end subroutine fail

      subroutine finite(group, name, value)
         character(len=*), intent(in) :: group, name
         real(dp), intent(in) :: value
         if (.not. ieee_is_finite(value)) &
            call fail('&'//group//' '//name//' = '//real_text(value)//' is not a finite number')
      end subroutine finite

      subroutine in_range(group, name, value, low, high)
         character(len=*), intent(in) :: group, name
         real(dp), intent(in) :: value, low, high
         call finite(group, name, value)
         if (stat /= 0) return
         if (value < low .or. value > high) call fail('&'//group//' '//name//' = '//real_text(value)// &
                                                      ' is outside ['//real_text(low)//', '//real_text(high)//']')
      end subroutine in_range

      subroutine positive(group, name, value)
         character(len=*), intent(in) :: group, name
         real(dp), intent(in) :: value
         call finite(group, name, value)
         if (stat /= 0) return
         if (value <= 0) call fail('&'//group//' '//name//' = '//real_text(value)//' must be > 0')
      end subroutine positive

      subroutine given_positive(name, value)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: value
         if (is_unset(value)) then
            call fail('&beam '//name//' is missing: youngs_modulus, density, area and inertia '// &
                      'go together (or give k2 alone)')
         else
            call positive('beam', name, value)
         end if
      end subroutine given_positive

      subroutine integer_in_range(group, name, value, low, high)
         character(len=*), intent(in) :: group, name
         integer, intent(in) :: value, low, high
         character(len=24) :: text(3)
         if (value < low .or. value > high) then
            write (text(1), '(i0)') value
            write (text(2), '(i0)') low
            write (text(3), '(i0)') high
            call fail('&'//group//' '//name//' = '//trim(text(1))//' is outside ['//trim(text(2))// &
                      ', '//trim(text(3))//']')
         end if
      end subroutine integer_in_range

      subroutine one_of(group, name, value, allowed)
         character(len=*), intent(in) :: group, name, value
         character(len=*), intent(in) :: allowed(:)
         character(len=:), allocatable :: list
         integer :: k
         if (any(allowed == value)) return
         list = ''
         do k = 1, size(allowed)
            list = list//''''//trim(allowed(k))//''''
            if (k < size(allowed)) list = list//' | '
         end do
         call fail('&'//group//' '//name//' = '''//trim(value)//''' is not one of '//list)
      end subroutine one_of
   end subroutine validate_scene


   !> Every resolved input value as a list of entries (name 'group.variable', value, unit).
   pure function scene_entries(scene) result(list)
      type(scene_type), intent(in) :: scene
      type(scene_entry), allocatable :: list(:)
      integer :: i
      character(len=8) :: index
      allocate (list(0))
      call add_real('beam.length', scene%length, 'm')
      call add_real('beam.k2', ei_of(scene)/rho_s_of(scene), 'm^4/s^2')
      if (physical(scene)) then
         call add_real('beam.youngs_modulus', scene%youngs_modulus, 'Pa')
         call add_real('beam.density', scene%density, 'kg/m^3')
         call add_real('beam.area', scene%area, 'm^2')
         call add_real('beam.inertia', scene%inertia, 'm^4')
      end if
      call add_real('beam.mass_per_length', rho_s_of(scene), 'kg/m')
      call add_real('beam.bending_stiffness', ei_of(scene), 'N m^2')
      call add_real('beam.rayleigh_mass', scene%rayleigh_mass, '1/s')
      call add_real('beam.rayleigh_stiffness', scene%rayleigh_stiffness, 's')
      call add_integer('mesh.elements', scene%elements)
      call add_string('mesh.basis', scene%basis)
      call add_string('analysis.kind', scene%kind)
      call add_integer('analysis.modes', scene%modes)
      call add_integer('obstacles.count', size(scene%obstacles))
      do i = 1, size(scene%obstacles)
         write (index, '(a,i0,a)') '(', i, ')'
         call add_string('obstacles.side'//trim(index), scene%obstacles(i)%side)
         call add_real('obstacles.x_from'//trim(index), scene%obstacles(i)%x_from, 'm')
         call add_real('obstacles.x_to'//trim(index), scene%obstacles(i)%x_to, 'm')
         call add_real('obstacles.level_from'//trim(index), scene%obstacles(i)%level_from, 'm')
         call add_real('obstacles.level_to'//trim(index), scene%obstacles(i)%level_to, 'm')
      end do
      call add_real('impact.restitution', scene%restitution, '')
      call add_string('impact.separating_points', scene%separating_points)
      call add_real('time.t_end', scene%t_end, 's')
      call add_real('time.dt', scene%dt, 's')
      call add_string('time.scheme', scene%scheme)
      call add_real('time.theta', scene%theta, '')
      call add_real('time.gamma', scene%gamma, '')
      call add_string('initial.displacement', scene%displacement)
      call add_integer('initial.displacement_mode', scene%displacement_mode)
      call add_real('initial.displacement_amplitude', scene%displacement_amplitude, 'm')
      call add_string('initial.velocity', scene%velocity)
      call add_integer('initial.velocity_mode', scene%velocity_mode)
      call add_real('initial.velocity_amplitude', scene%velocity_amplitude, 'm/s')
      call add_string('initial.from_file', scene%from_file)
      call add_real('load.distributed', scene%distributed, 'N/m')
      call add_real('load.distributed_frequency', scene%distributed_frequency, 'rad/s')
      call add_real('load.distributed_phase', scene%distributed_phase, 'rad')
      call add_real('load.point_force', scene%point_force, 'N')
      call add_real('load.point_position', scene%point_position, 'm')
      call add_real('load.point_frequency', scene%point_frequency, 'rad/s')
      call add_real('load.base_amplitude', scene%base_amplitude, 'm')
      call add_real('load.base_frequency', scene%base_frequency, 'rad/s')
      call add_string('solver.contact_solver', scene%contact_solver)
      call add_string('solver.contact_method', scene%contact_method)
      call add_integer('solver.contact_max_iterations', scene%contact_max_iterations)
      call add_string('output.file', scene%file)
      call add_integer('output.every', scene%every)
      call add_logical('output.text', scene%text)
      call add_logical('output.progress', scene%progress)
      call add_integer('output.field_every', scene%field_every)
      if (allocated(scene%points)) then
         do i = 1, size(scene%points)
            write (index, '(a,i0,a)') '(', i, ')'
            call add_real('output.points'//trim(index), scene%points(i), 'm')
         end do
      end if
      call add_real('output.measure_from', scene%measure_from, 's')
      call add_real('output.checkpoint_seconds', scene%checkpoint_seconds, 's')
      if (.not. is_unset(scene%episode_gap)) call add_real('output.episode_gap', scene%episode_gap, 's')
   contains
      pure subroutine add_real(name, value, unit)
         character(len=*), intent(in) :: name, unit
         real(dp), intent(in) :: value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'real'
         item%real_value = value
         item%unit = unit
         list = [list, item]
      end subroutine add_real
      pure subroutine add_integer(name, value)
         character(len=*), intent(in) :: name
         integer, intent(in) :: value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'integer'
         item%integer_value = value
         list = [list, item]
      end subroutine add_integer
      pure subroutine add_string(name, value)
         character(len=*), intent(in) :: name, value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'string'
         item%string_value = value
         list = [list, item]
      end subroutine add_string
      pure subroutine add_logical(name, value)
         character(len=*), intent(in) :: name
         logical, intent(in) :: value
         type(scene_entry) :: item
         item%name = name
         item%kind = 'logical'
         item%logical_value = value
         list = [list, item]
      end subroutine add_logical
   end function scene_entries

   !> The resolved scene as text, one 'group.variable = value  ! unit' line per entry.
   function format_scene(scene) result(text)
      type(scene_type), intent(in) :: scene
      character(len=:), allocatable :: text
      type(scene_entry), allocatable :: list(:)
      character(len=:), allocatable :: value
      integer :: i
      allocate (list, source=scene_entries(scene))
      text = ''
      do i = 1, size(list)
         select case (list(i)%kind)
         case ('real')
            value = real_text(list(i)%real_value)
         case ('integer')
            value = integer_text(list(i)%integer_value)
         case ('logical')
            value = merge('.true. ', '.false.', list(i)%logical_value)
         case default
            value = ''''//trim(list(i)%string_value)//''''
         end select
         text = text//'  '//list(i)%name(1:max(32, len_trim(list(i)%name)))//' = '//trim(value)
         if (len_trim(list(i)%unit) > 0) text = text//'   ! '//trim(list(i)%unit)
         text = text//new_line('a')
      end do
   end function format_scene
end module vibrobeam_scene
