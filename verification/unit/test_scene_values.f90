!> Every real input can be set by its name (what a sweep does, docs/sweeps.md "The
!! parameter"), and every declaration is consistent.
!!
!! 1. The table of every variable is built from the settings' declarations; each row and
!!    the variable handed over with it agree in kind and rank (`schema_table%mismatch`).
!! 2. For every real variable of the table outside &sweep, and for elements 1 and 2 of an
!!    array (a scene with two obstacles, two loads of &forces and two observation points),
!!    `set_real_input` sets a value no variable holds (two supports and two masses too),
!!    `real_input` reads it back, and the listing of the
!!    resolved scene (`scene_entries`, a different walk of the declarations than the
!!    accessor's) shows it under that variable's name and nowhere else: every other entry
!!    is unchanged, but for the beam's derived k2, mass per length and bending stiffness,
!!    and the twin of a frequency (docs/input.md, "Frequencies in Hz": setting a frequency
!!    in rad/s sets its twin in Hz to it over 2 pi, setting the twin sets the frequency to 2
!!    pi times it; compared to 4 eps, one rounding of the product and one of pi).
!!    E, rho, S and I are set on a beam given by them, the variables of &sections on a
!!    beam of two sections, the others on a beam given by k2 (its k2 is listed, not
!!    derived).
!! 3. A name that is not a real input, and an element beyond the scene's, are not found.
!! The scenes are of kind 'periodic', whose visit includes every group.
!! The values are compared exactly: they are copied, never computed (but for the twins).
program test_scene_values
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   use vibrobeam_scene, only: scene_type, scene_entry, scene_entries, visit_scene, obstacle_type, support_settings, &
      mass_settings, section_settings
   use vibrobeam_scene_values, only: real_input, set_real_input
   use vibrobeam_schema_operations, only: schema_table
   use vibrobeam_sweep_input, only: sweep_input, visit_sweep
   use vibrobeam_namelist_schema, only: kind_real
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   type(schema_table) :: table
   type(scene_type) :: scene, defaults, physical_scene, sectioned_scene
   type(sweep_input) :: sweep
   type(scene_entry), allocatable :: before(:), after(:)
   real(dp) :: value, marker
   logical :: found
   integer :: k, element, elements, covered
   character(len=:), allocatable :: name

   ! scenes of kind 'periodic': their visit holds every group (&periodic only in that kind)
   defaults%analysis%kind = 'periodic'
   call visit_scene(defaults, table)
   call visit_sweep(sweep, table)
   call t%check_true('every declaration''s row agrees with its variable', len(table%mismatch) == 0, table%mismatch)

   ! a scene with two compliant obstacles and two observation points
   scene%obstacles = [obstacle_type(side='below', x_from=0.5_dp, x_to=0.5_dp, level_from=-0.01_dp, &
                                    level_to=-0.01_dp, stiffness=1e5_dp), &
                      obstacle_type(side='above', x_from=1.0_dp, x_to=1.0_dp, level_from=0.01_dp, &
                                    level_to=0.01_dp, stiffness=1e5_dp, damping=0.1_dp)]
   scene%output%points = [0.25_dp, 0.75_dp]
   ! two intermediate supports and two point masses
   scene%supports = [support_settings(x=0.3_dp), support_settings(x=0.6_dp, kind='spring', stiffness=1e3_dp)]
   scene%masses = [mass_settings(x=1.0_dp, mass=0.2_dp), mass_settings(x=0.5_dp, mass=0.1_dp, rotary_inertia=1e-4_dp)]
   allocate (scene%forces%load(2))   ! two loads of &forces (their defaults)
   scene%analysis%kind = 'periodic'
   physical_scene = scene
   physical_scene%beam%youngs_modulus = 2.1e11_dp
   physical_scene%beam%density = 7850
   physical_scene%beam%area = 2e-4_dp
   physical_scene%beam%inertia = 1.6e-9_dp
   sectioned_scene = scene
   sectioned_scene%beam%sections = [section_settings(x_to=0.4_dp, youngs_modulus=2.1e11_dp, density=7850, area=2e-4_dp, &
                                                     inertia=1.6e-9_dp), &
                                    section_settings(x_to=1.0_dp, youngs_modulus=7e10_dp, density=2700, area=1e-4_dp, &
                                                     inertia=1e-9_dp)]
   covered = 0
   marker = 0.123456789_dp
   do k = 1, size(table%rows)
      if (table%rows(k)%kind /= kind_real .or. table%rows(k)%group == 'sweep') cycle
      elements = merge(2, 1, table%rows(k)%extent > 0)
      do element = 1, elements
         name = trim(table%rows(k)%group)//'.'//trim(table%rows(k)%name)
         if (table%rows(k)%extent > 0) name = name//'('//integer_text(element)//')'
         marker = marker + 1
         call check_one(trim(table%rows(k)%group), trim(table%rows(k)%name), element, name, marker)
         covered = covered + 1
      end do
   end do
   call t%check_true('real variables (and elements) covered: '//integer_text(covered), covered >= 40, &
                     'fewer real inputs than the scene declares')

   call real_input(scene, 'mesh', 'elements', 1, value, found)
   call t%check_true('an integer input is not a real input', .not. found)
   call real_input(scene, 'obstacles', 'stiffness', 3, value, found)
   call t%check_true('obstacle 3 of a scene with 2 is not found', .not. found)
   call real_input(scene, 'forces', 'amplitude', 3, value, found)
   call t%check_true('load 3 of a scene with 2 is not found', .not. found)
   call real_input(scene, 'output', 'points', 3, value, found)
   call t%check_true('point 3 of a scene with 2 is not found', .not. found)
   call real_input(scene, 'beam', 'no_such_variable', 1, value, found)
   call t%check_true('an unknown name is not found', .not. found)
   call t%finish('test_scene_values')

contains

   subroutine check_one(group, variable, element, name, marker)
      character(len=*), intent(in) :: group, variable, name
      integer, intent(in) :: element
      real(dp), intent(in) :: marker
      type(scene_type) :: changed
      integer :: j, shown, twin_shown
      logical :: others_same
      character(len=:), allocatable :: twin
      real(dp) :: twin_value
      ! the twin of a frequency (rad/s) or the frequency of a twin (Hz), and its value
      if (len(variable) > 3 .and. index(variable, '_hz', back=.true.) == len(variable) - 2) then
         twin = group//'.'//variable(1:len(variable) - 3)
         twin_value = 8*atan(1.0_dp)*marker
      else
         twin = group//'.'//variable//'_hz'
         twin_value = marker/(8*atan(1.0_dp))
      end if
      ! an element of an array of settings is listed as 'group.name(i)', its twin too
      if (name(len(name):) == ')') twin = twin//name(index(name, '(', back=.true.):)
      twin_shown = 0
      changed = scene
      if (group == 'beam' .and. any(variable == [character(len=14) :: 'youngs_modulus', 'density', 'area', &
                                                  'inertia'])) changed = physical_scene
      if (group == 'sections') changed = sectioned_scene
      before = scene_entries(changed)
      call set_real_input(changed, group, variable, element, marker, found)
      call t%check_true(name//' can be set', found)
      if (.not. found) return
      call real_input(changed, group, variable, element, value, found)
      call t%check_true(name//' reads back what was set', found .and. same_bits(value, marker))
      after = scene_entries(changed)
      shown = 0
      others_same = .true.
      do j = 1, size(after)
         if (after(j)%name == name) then
            if (after(j)%kind == 'real' .and. same_bits(after(j)%real_value, marker)) shown = shown + 1
         else if (any(after(j)%name == [character(len=24) :: 'beam.k2', 'beam.mass_per_length', &
                                         'beam.bending_stiffness'])) then
            cycle   ! derived from the beam's data
         else if (after(j)%name == twin) then
            if (abs(after(j)%real_value - twin_value) <= 4*epsilon(1.0_dp)*abs(twin_value)) twin_shown = twin_shown + 1
         else if (.not. same_as_before(after(j))) then
            others_same = .false.
         end if
      end do
      call t%check_true(name//' is listed with the value set', shown == 1)
      if (any(after%name == twin)) call t%check_true(twin//', the twin of '//name//', is listed with it converted', &
                                                     twin_shown == 1)
      call t%check_true(name//' changes no other input', others_same)
   end subroutine check_one

   !> The entry of the same name in `before` holds the same value (an entry that was not
   !! listed before, an optional input now given, is only allowed for the one set).
   logical function same_as_before(item)
      type(scene_entry), intent(in) :: item
      integer :: j
      same_as_before = .false.
      do j = 1, size(before)
         if (before(j)%name /= item%name) cycle
         same_as_before = before(j)%kind == item%kind .and. same_bits(before(j)%real_value, item%real_value) .and. &
                          before(j)%integer_value == item%integer_value .and. &
                          before(j)%string_value == item%string_value .and. &
                          (before(j)%logical_value .eqv. item%logical_value)
         return
      end do
   end function same_as_before

   !> a and b are the same double, bit for bit (values are copied, never computed).
   elemental logical function same_bits(a, b)
      real(dp), intent(in) :: a, b
      same_bits = transfer(a, 0_int64) == transfer(b, 0_int64)
   end function same_bits
end program test_scene_values
