!> Every input frequency can be given in Hz (docs/input.md, "Frequencies in Hz").
!!
!! 1. Every real variable in rad/s has a twin '<name>_hz' in Hz in the same group, declared
!!    right after it, whose range is the frequency's over 2 pi; every variable named
!!    '<name>_hz' is such a twin. (A frequency added without its twin fails here.)
!! 2. For every twin, read from a file: the twin f alone gives the frequency 2 pi f and
!!    the listing of the resolved scene (--check, the HDF5 attributes) shows both; the
!!    frequency omega alone lists its twin omega/(2 pi); both together are refused with a
!!    message naming both.
!! 3. Setting a twin by its name (what a sweep over it does) sets its frequency, and
!!    setting a frequency sets its twin.
!! Reference: 2 pi f with pi = 4 atan(1) computed here; the code multiplies by its own 2 pi
!! (one rounding, and pi itself rounded: at most 2 eps relative apart), and divides
!! (the same). Tolerance 4 eps relative.
program test_frequency_twins
   use vibrobeam_kinds, only: dp
   use vibrobeam_scene, only: scene_type, scene_entry, scene_entries, scene_variables
   use vibrobeam_scene_read, only: read_scene
   use vibrobeam_scene_values, only: real_input, set_real_input
   use vibrobeam_namelist_schema, only: namelist_variable, kind_real, variable_index
   use vibrobeam_test_support, only: test_counter
   implicit none
   real(dp), parameter :: two_pi = 8*atan(1.0_dp), tolerance = 4*epsilon(1.0_dp)
   character(len=*), parameter :: file = 'test_frequency_twins.nml'
   type(test_counter) :: t
   type(namelist_variable), allocatable :: table(:)
   integer :: k, twin, frequencies
   character(len=:), allocatable :: group, name

   allocate (table, source=scene_variables())
   frequencies = 0
   do k = 1, size(table)
      group = trim(table(k)%group)
      name = trim(table(k)%name)
      if (table(k)%kind /= kind_real) cycle
      if (table(k)%unit == 'rad/s') then
         frequencies = frequencies + 1
         twin = variable_index(table, group, name//'_hz')
         call t%check_true('&'//group//' '//name//' (rad/s) has a twin '//name//'_hz', twin == k + 1)
         if (twin /= k + 1) cycle
         call t%check_true(name//'_hz in Hz', table(twin)%unit == 'Hz')
         call t%check_close(name//'_hz lowest', table(twin)%lowest, table(k)%lowest/two_pi, tolerance, tiny(1.0_dp))
         call t%check_close(name//'_hz highest', table(twin)%highest, table(k)%highest/two_pi, tolerance)
         call t%check_true(name//'_hz scalar like its frequency', table(twin)%extent == table(k)%extent .and. &
                           table(twin)%optional .eqv. table(k)%optional)
         call check_reading(group, name, table(k)%extent > 0)
         call check_setting(group, name, table(k)%extent > 0)
      else if (index(name, '_hz', back=.true.) == len(name) - 2 .and. len(name) > 3) then
         call t%check_true('&'//group//' '//name//' is the twin of a frequency in rad/s', &
                           table(k)%unit == 'Hz' .and. table(k - 1)%unit == 'rad/s' .and. &
                           trim(table(k - 1)%name)//'_hz' == name)
      end if
   end do
   call t%check_true('frequencies in rad/s found', frequencies >= 4)
   call t%finish('test_frequency_twins')

contains

   !> Item 2 for the frequency group.name; of element 1 of an array of settings (`array`:
   !! &forces frequency(1), the file then gives count = 1).
   subroutine check_reading(group, name, array)
      character(len=*), intent(in) :: group, name
      logical, intent(in) :: array
      type(scene_type) :: scene
      character(len=512) :: errmsg
      character(len=:), allocatable :: count, item
      integer :: stat
      real(dp), parameter :: hz = 12.5_dp, omega = 150.0_dp
      count = trim(merge('count = 1, ', '           ', array))//' '
      item = trim(merge('(1)', '   ', array))
      call write_file('&'//group//' '//count//name//'_hz'//item//' = 12.5 /')
      call read_scene(file, scene, stat, errmsg)
      call t%check_true(name//'_hz = 12.5 is read', stat == 0, errmsg)
      call t%check_close(name//' from '//name//'_hz = 12.5 (rad/s)', value_of(scene, group, name), two_pi*hz, tolerance)
      call t%check_close(name//' listed (rad/s)', listed(scene, group//'.'//name//item), two_pi*hz, tolerance)
      call t%check_close(name//'_hz listed as given (Hz)', listed(scene, group//'.'//name//'_hz'//item), hz, 0.0_dp)
      call write_file('&'//group//' '//count//name//item//' = 150 /')
      call read_scene(file, scene, stat, errmsg)
      call t%check_true(name//' = 150 is read', stat == 0, errmsg)
      call t%check_close(name//'_hz from '//name//' = 150 (Hz)', value_of(scene, group, name//'_hz'), omega/two_pi, &
                         tolerance)
      call t%check_close(name//'_hz listed (Hz)', listed(scene, group//'.'//name//'_hz'//item), omega/two_pi, tolerance)
      call write_file('&'//group//' '//count//name//item//' = 150, '//name//'_hz'//item//' = 12.5 /')
      call read_scene(file, scene, stat, errmsg)
      call t%check_true(name//' and '//name//'_hz both given: refused, naming both', stat /= 0 .and. &
                        index(errmsg, name//item//' = 150 rad/s and '//name//'_hz'//item//' = 12.5 Hz are both given') &
                        > 0, errmsg)
      call delete_file()
   end subroutine check_reading

   !> Item 3 for the frequency group.name (element 1 of an array of settings: `array`, on a
   !! scene read with count = 1).
   subroutine check_setting(group, name, array)
      character(len=*), intent(in) :: group, name
      logical, intent(in) :: array
      type(scene_type) :: scene
      character(len=512) :: errmsg
      integer :: stat
      logical :: found
      if (array) then
         call write_file('&'//group//' count = 1 /')
         call read_scene(file, scene, stat, errmsg)
         call t%check_true('&'//group//' count = 1 is read', stat == 0, errmsg)
         call delete_file()
      end if
      call set_real_input(scene, group, name//'_hz', 1, 40.0_dp, found)
      call t%check_true(name//'_hz can be set', found)
      call t%check_close(name//' set with '//name//'_hz = 40 (rad/s)', value_of(scene, group, name), two_pi*40, &
                         tolerance)
      call set_real_input(scene, group, name, 1, 300.0_dp, found)
      call t%check_close(name//'_hz set with '//name//' = 300 (Hz)', value_of(scene, group, name//'_hz'), &
                         300/two_pi, tolerance)
      call t%check_close(name//' = 300 as set', value_of(scene, group, name), 300.0_dp, 0.0_dp)
   end subroutine check_setting

   real(dp) function value_of(scene, group, name) result(value)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: group, name
      logical :: found
      call real_input(scene, group, name, 1, value, found)
      call t%check_true(group//'.'//name//' found', found)
   end function value_of

   !> The value the listing of the resolved scene shows for 'group.name' (-1: not listed).
   real(dp) function listed(scene, name)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: name
      type(scene_entry), allocatable :: entries(:)
      integer :: j
      listed = -1
      allocate (entries, source=scene_entries(scene))
      do j = 1, size(entries)
         if (entries(j)%name == name) listed = entries(j)%real_value
      end do
      call t%check_true(name//' listed', listed >= 0, 'not in the listing')
   end function listed

   subroutine write_file(line)
      character(len=*), intent(in) :: line
      integer :: unit
      open (newunit=unit, file=file, status='replace', action='write')
      write (unit, '(a)') line
      close (unit)
   end subroutine write_file

   subroutine delete_file()
      integer :: unit
      open (newunit=unit, file=file, status='old')
      close (unit, status='delete')
   end subroutine delete_file
end program test_frequency_twins
