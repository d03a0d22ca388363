!> Unit test of `vibrobeam_hdf5` (and the file-system helpers it relies on).
!!
!! Writes a result file through `h5_writer` (1-d, non-square 2-d, integer, scalar and
!! empty datasets, nested group paths, attributes of every kind on '/', on a dataset and
!! on a group created on the fly), checks the atomic-write protocol (only the temporary
!! file `<final>.<pid>-<token>.tmp` exists before `commit`, only `<final>` after; `discard`
!! leaves nothing and never touches an existing `<final>`), reads everything back with the module's readers and
!! compares bit for bit (the reference is the written data itself: HDF5 must store the
!! native double/integer types without conversion). When `h5dump` is on the PATH, it is
!! used as an independent reader to check the dimension order: a Fortran (n1, n2) array
!! must appear as an HDF5 dataset of dims (n2, n1).
!!
!! Files go to `$TMPDIR` (default /tmp) in a fresh directory that is removed at the end.
!! Prints one line per failed check and a summary; `error stop 1` on any failure.
program test_hdf5_roundtrip
   use vibrobeam_kinds, only: dp, int64, error_unit
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_filesystem, only: file_exists, remove_file, rename_file
   use vibrobeam_text_file, only: text_file_handle => text_file, open_text_for_atomic_write, write_text_line, &
      finish_text_file, discard_text_file
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_file_reads, only: read_real_1d, read_real_2d, read_int_1d, read_real_scalar, read_attr_real, &
      read_attr_int, read_attr_string, h5_path_exists
   implicit none

   integer, parameter :: message_length = 512
   integer :: passed = 0
   integer :: failed = 0

   character(len=:), allocatable :: base_dir, nested_dir, deeper_dir, result_file
   character(len=:), allocatable :: discarded_file, text_file, discarded_text_file, temporary
   type(h5_writer) :: writer
   integer :: stat, i, j
   character(len=message_length) :: errmsg

   ! Written data (the references).
   real(dp), allocatable :: mesh_x(:), mode_shape(:, :), empty_times(:), empty_field(:, :)
   real(dp), allocatable :: nested_values(:)
   integer, allocatable :: step_counts(:)
   real(dp) :: static_energy
   real(dp), parameter :: beam_length = 0.7_dp
   real(dp), parameter :: x_scale = 1.0_dp / 3.0_dp
   real(dp), parameter :: wall_seconds = 12.345678901234567_dp
   integer, parameter :: element_count = 32
   integer, parameter :: mode_count = -7
   integer, parameter :: step_total = 123456789

   ! Read-back data.
   real(dp), allocatable :: real_1d(:), real_2d(:, :)
   integer, allocatable :: int_1d(:)
   real(dp) :: real_value
   integer :: int_value
   character(len=:), allocatable :: string_value

   call set_up_paths()

   ! ------------------------------------------------------------------------------
   ! reference data
   mesh_x = [0.0_dp, -0.0_dp, 1.0_dp / 3.0_dp, 4.0_dp * atan(1.0_dp), huge(1.0_dp), &
      tiny(1.0_dp), -1.0e-300_dp, 0.1_dp]
   allocate (mode_shape(3, 5))   ! non-square: n1 = 3 (nodes), n2 = 5 (modes)
   do j = 1, size(mode_shape, 2)
      do i = 1, size(mode_shape, 1)
         mode_shape(i, j) = real(i, dp) + 10.0_dp * real(j, dp) + 1.0_dp / 7.0_dp
      end do
   end do
   allocate (empty_times(0), empty_field(0, 4))
   nested_values = [1.5_dp, -2.25_dp]
   step_counts = [0, 1, -2, huge(0), -huge(0) - 1]
   static_energy = -2.0_dp / 3.0_dp

   ! ------------------------------------------------------------------------------
   ! write, checking the atomic protocol
   call writer%write_real_1d('/mesh/x', mesh_x, 'm', stat, errmsg)
   call check_fails('write_real_1d before create', stat, errmsg)
   call writer%commit(stat, errmsg)
   call check_fails('commit before create', stat, errmsg)

   call writer%create(result_file, stat, errmsg)
   call check_ok('create ' // result_file, stat, errmsg)
   temporary = writer%temporary_file()
   call check_true('temporary name is <final>.<pid>-<token>.tmp', index(temporary, result_file // '.') == 1 &
      .and. index(temporary, '.tmp', back=.true.) == len(temporary) - 3)
   call check_true('temporary file exists before commit', file_exists(temporary))
   call check_true('final file absent before commit', .not. file_exists(result_file))

   call writer%create(result_file, stat, errmsg)
   call check_fails('create on an open writer', stat, errmsg)

   call writer%write_real_1d('/mesh/x', mesh_x, 'm', stat, errmsg)
   call check_ok('write /mesh/x', stat, errmsg)
   call writer%write_real_2d('/modes/shape', mode_shape, stat=stat, errmsg=errmsg)
   call check_ok('write /modes/shape', stat, errmsg)
   call writer%write_int_1d('/run/step_counts', step_counts, stat, errmsg)
   call check_ok('write /run/step_counts', stat, errmsg)
   call writer%write_real_scalar('/static/energy', static_energy, 'J', stat, errmsg)
   call check_ok('write /static/energy', stat, errmsg)
   call writer%write_real_1d('/impacts/time', empty_times, 's', stat, errmsg)
   call check_ok('write empty /impacts/time', stat, errmsg)
   call writer%write_real_2d('/field/empty', empty_field, 'm', stat, errmsg)
   call check_ok('write empty 2-d /field/empty', stat, errmsg)
   call writer%write_real_1d('level1/level2/level3/values', nested_values, stat=stat, &
      errmsg=errmsg)
   call check_ok('write level1/level2/level3/values (relative, nested)', stat, errmsg)

   call writer%attr_string('/', 'version', 'vibrobeam 0.1.0', stat, errmsg)
   call check_ok('attr_string / version', stat, errmsg)
   call writer%attr_string('/', 'empty_string', '', stat, errmsg)
   call check_ok('attr_string / empty_string', stat, errmsg)
   call writer%attr_real('/', 'beam_length', beam_length, stat, errmsg)
   call check_ok('attr_real / beam_length', stat, errmsg)
   call writer%attr_int('/', 'mesh_elements', element_count, stat, errmsg)
   call check_ok('attr_int / mesh_elements', stat, errmsg)
   call writer%attr_string('/mesh/x', 'description', 'node positions', stat, errmsg)
   call check_ok('attr_string /mesh/x description', stat, errmsg)
   call writer%attr_real('/mesh/x', 'scale', x_scale, stat, errmsg)
   call check_ok('attr_real /mesh/x scale', stat, errmsg)
   call writer%attr_int('/mesh/x', 'modes', mode_count, stat, errmsg)
   call check_ok('attr_int /mesh/x modes', stat, errmsg)
   ! '/run' exists (parent of /run/step_counts); '/solver/lcp' does not: created as groups.
   call writer%attr_string('/run', 'status', 'running', stat, errmsg)
   call check_ok('attr_string /run status (first value)', stat, errmsg)
   call writer%attr_string('/run', 'status', 'ok', stat, errmsg)
   call check_ok('attr_string /run status (replaced)', stat, errmsg)
   call writer%attr_int('/run', 'steps', step_total, stat, errmsg)
   call check_ok('attr_int /run steps', stat, errmsg)
   call writer%attr_real('/solver/lcp', 'wall_seconds', wall_seconds, stat, errmsg)
   call check_ok('attr_real /solver/lcp wall_seconds (new group)', stat, errmsg)

   ! Errors are reported, not fatal, and the file stays usable.
   call writer%write_real_1d('/mesh/x', mesh_x, 'm', stat, errmsg)
   call check_fails('write an existing dataset /mesh/x', stat, errmsg, '/mesh/x')
   call writer%write_real_1d('/mesh/x/child', mesh_x, stat=stat, errmsg=errmsg)
   call check_fails('write below a dataset /mesh/x/child', stat, errmsg, '/mesh/x/child')
   call writer%write_real_1d('/bad//path', mesh_x, stat=stat, errmsg=errmsg)
   call check_fails('write to an invalid path /bad//path', stat, errmsg, '/bad//path')
   call writer%attr_real('/mesh/x', '', 1.0_dp, stat, errmsg)
   call check_fails('attr_real with an empty name', stat, errmsg, '/mesh/x')

   call check_true('temporary file exists before commit (after writes)', &
      file_exists(temporary))
   call check_true('final file absent before commit (after writes)', .not. file_exists(result_file))
   call writer%commit(stat, errmsg)
   call check_ok('commit', stat, errmsg)
   call check_true('final file exists after commit', file_exists(result_file))
   call check_true('temporary file gone after commit', .not. file_exists(temporary))
   call writer%commit(stat, errmsg)
   call check_fails('second commit', stat, errmsg)

   ! ------------------------------------------------------------------------------
   ! read back
   call read_real_1d(result_file, '/mesh/x', real_1d, stat, errmsg)
   call check_ok('read /mesh/x', stat, errmsg)
   if (stat == 0) call check_real_1d('/mesh/x', real_1d, mesh_x)

   call read_real_2d(result_file, '/modes/shape', real_2d, stat, errmsg)
   call check_ok('read /modes/shape', stat, errmsg)
   if (stat == 0) call check_real_2d('/modes/shape', real_2d, mode_shape)

   call read_int_1d(result_file, '/run/step_counts', int_1d, stat, errmsg)
   call check_ok('read /run/step_counts', stat, errmsg)
   if (stat == 0) call check_int_1d('/run/step_counts', int_1d, step_counts)

   call read_real_scalar(result_file, '/static/energy', real_value, stat, errmsg)
   call check_ok('read /static/energy', stat, errmsg)
   if (stat == 0) call check_real('/static/energy', real_value, static_energy)

   call read_real_1d(result_file, '/impacts/time', real_1d, stat, errmsg)
   call check_ok('read empty /impacts/time', stat, errmsg)
   if (stat == 0) call check_real_1d('/impacts/time', real_1d, empty_times)

   call read_real_2d(result_file, '/field/empty', real_2d, stat, errmsg)
   call check_ok('read empty /field/empty', stat, errmsg)
   if (stat == 0) call check_real_2d('/field/empty', real_2d, empty_field)

   call read_real_1d(result_file, '/level1/level2/level3/values', real_1d, stat, errmsg)
   call check_ok('read /level1/level2/level3/values', stat, errmsg)
   if (stat == 0) call check_real_1d('/level1/level2/level3/values', real_1d, nested_values)

   call read_attr_string(result_file, '/', 'version', string_value, stat, errmsg)
   call check_ok('read attribute / version', stat, errmsg)
   call check_string('attribute / version', string_value, 'vibrobeam 0.1.0')
   call read_attr_string(result_file, '/', 'empty_string', string_value, stat, errmsg)
   call check_ok('read attribute / empty_string', stat, errmsg)
   call check_string('attribute / empty_string', string_value, '')
   call read_attr_real(result_file, '/', 'beam_length', real_value, stat, errmsg)
   call check_ok('read attribute / beam_length', stat, errmsg)
   call check_real('attribute / beam_length', real_value, beam_length)
   call read_attr_int(result_file, '/', 'mesh_elements', int_value, stat, errmsg)
   call check_ok('read attribute / mesh_elements', stat, errmsg)
   call check_int('attribute / mesh_elements', int_value, element_count)

   call read_attr_string(result_file, '/mesh/x', 'unit', string_value, stat, errmsg)
   call check_ok('read attribute /mesh/x unit', stat, errmsg)
   call check_string('attribute /mesh/x unit', string_value, 'm')
   call read_attr_string(result_file, '/static/energy', 'unit', string_value, stat, errmsg)
   call check_ok('read attribute /static/energy unit', stat, errmsg)
   call check_string('attribute /static/energy unit', string_value, 'J')
   call read_attr_string(result_file, '/impacts/time', 'unit', string_value, stat, errmsg)
   call check_ok('read attribute /impacts/time unit', stat, errmsg)
   call check_string('attribute /impacts/time unit', string_value, 's')
   call read_attr_string(result_file, '/mesh/x', 'description', string_value, stat, errmsg)
   call check_ok('read attribute /mesh/x description', stat, errmsg)
   call check_string('attribute /mesh/x description', string_value, 'node positions')
   call read_attr_real(result_file, '/mesh/x', 'scale', real_value, stat, errmsg)
   call check_ok('read attribute /mesh/x scale', stat, errmsg)
   call check_real('attribute /mesh/x scale', real_value, x_scale)
   call read_attr_int(result_file, '/mesh/x', 'modes', int_value, stat, errmsg)
   call check_ok('read attribute /mesh/x modes', stat, errmsg)
   call check_int('attribute /mesh/x modes', int_value, mode_count)
   call read_attr_string(result_file, '/run', 'status', string_value, stat, errmsg)
   call check_ok('read attribute /run status', stat, errmsg)
   call check_string('attribute /run status (replaced value)', string_value, 'ok')
   call read_attr_int(result_file, '/run', 'steps', int_value, stat, errmsg)
   call check_ok('read attribute /run steps', stat, errmsg)
   call check_int('attribute /run steps', int_value, step_total)
   call read_attr_real(result_file, '/solver/lcp', 'wall_seconds', real_value, stat, errmsg)
   call check_ok('read attribute /solver/lcp wall_seconds', stat, errmsg)
   call check_real('attribute /solver/lcp wall_seconds', real_value, wall_seconds)

   ! Reader errors: reported with the file and the path.
   call read_real_1d(result_file, '/no/such/dataset', real_1d, stat, errmsg)
   call check_fails('read a missing dataset', stat, errmsg, '/no/such/dataset')
   call read_real_1d(result_file, '/modes/shape', real_1d, stat, errmsg)
   call check_fails('read a 2-d dataset as 1-d', stat, errmsg, '/modes/shape')
   call read_real_2d(result_file, '/mesh', real_2d, stat, errmsg)
   call check_fails('read a group as a dataset', stat, errmsg, '/mesh')
   call read_attr_real(result_file, '/mesh/x', 'no_such_attribute', real_value, stat, errmsg)
   call check_fails('read a missing attribute', stat, errmsg, 'no_such_attribute')
   call read_attr_string(result_file, '/mesh/x', 'scale', string_value, stat, errmsg)
   call check_fails('read a real attribute as a string', stat, errmsg, 'scale')
   call read_real_1d(base_dir // '/missing.h5', '/mesh/x', real_1d, stat, errmsg)
   call check_fails('read from a missing file', stat, errmsg, 'missing.h5')

   call check_true('h5_path_exists /', h5_path_exists(result_file, '/'))
   call check_true('h5_path_exists /mesh/x', h5_path_exists(result_file, '/mesh/x'))
   call check_true('h5_path_exists /level1/level2', h5_path_exists(result_file, '/level1/level2'))
   call check_true('h5_path_exists /solver/lcp', h5_path_exists(result_file, '/solver/lcp'))
   call check_true('not h5_path_exists /nope', .not. h5_path_exists(result_file, '/nope'))
   call check_true('not h5_path_exists /nope/deeper', &
      .not. h5_path_exists(result_file, '/nope/deeper'))
   call check_true('not h5_path_exists /mesh/x/below', &
      .not. h5_path_exists(result_file, '/mesh/x/below'))
   call check_true('not h5_path_exists in a missing file', &
      .not. h5_path_exists(base_dir // '/missing.h5', '/'))

   ! ------------------------------------------------------------------------------
   ! independent check of the dimension order with h5dump
   call check_with_h5dump()

   ! ------------------------------------------------------------------------------
   ! discard: nothing is left, and an existing final file is untouched
   call writer%create(discarded_file, stat, errmsg)
   call check_ok('create ' // discarded_file, stat, errmsg)
   temporary = writer%temporary_file()
   call writer%write_real_1d('/mesh/x', mesh_x, 'm', stat, errmsg)
   call check_ok('write /mesh/x before discard', stat, errmsg)
   call writer%discard()
   call check_true('no temporary file after discard', .not. file_exists(temporary))
   call check_true('no final file after discard', .not. file_exists(discarded_file))
   call writer%discard()   ! a second discard is a no-op

   call writer%create(result_file, stat, errmsg)
   call check_ok('create over an existing final file', stat, errmsg)
   temporary = writer%temporary_file()
   call writer%write_real_1d('/other', nested_values, stat=stat, errmsg=errmsg)
   call check_ok('write /other before discard', stat, errmsg)
   call writer%discard()
   call check_true('discard keeps the existing final file', file_exists(result_file))
   call check_true('discard removes the temporary file', .not. file_exists(temporary))
   call check_true('discarded content not in the final file', &
      .not. h5_path_exists(result_file, '/other'))
   call read_real_2d(result_file, '/modes/shape', real_2d, stat, errmsg)
   call check_ok('read /modes/shape after discard', stat, errmsg)
   if (stat == 0) call check_real_2d('/modes/shape after discard', real_2d, mode_shape)

   ! ------------------------------------------------------------------------------
   ! atomic text files
   call check_text_files()

   call clean_up()

   write (*, '(a,i0,a,i0,a)') 'test_hdf5_roundtrip: ', passed, ' passed, ', failed, ' failed'
   if (failed > 0) error stop 1

contains

   !> A fresh directory below $TMPDIR (default /tmp), and the file names used in it.
   subroutine set_up_paths()
      character(len=4096) :: tmpdir
      integer :: length, env_status
      integer(int64) :: clock

      call get_environment_variable('TMPDIR', tmpdir, length, env_status)
      if (env_status /= 0 .or. length == 0) tmpdir = '/tmp'
      call system_clock(clock)
      base_dir = trim(tmpdir) // '/vibrobeam_test_hdf5_' // &
         integer_text(int(modulo(clock, 1000000000_int64)))
      nested_dir = base_dir // '/nested'
      deeper_dir = nested_dir // '/deeper'
      result_file = deeper_dir // '/results.h5'
      discarded_file = base_dir // '/discarded.h5'
      text_file = base_dir // '/text/series.dat'
      discarded_text_file = base_dir // '/text/discarded.dat'
   end subroutine set_up_paths

   !> h5dump (independent reader) must show /modes/shape, written from a Fortran (3, 5)
   !! array, with dims ( 5, 3 ), and the 'unit' attribute of /mesh/x as the string "m".
   subroutine check_with_h5dump()
      integer :: exit_status, command_status

      exit_status = 0
      command_status = 0
      call execute_command_line('command -v h5dump > /dev/null 2>&1', wait=.true., &
         exitstat=exit_status, cmdstat=command_status)
      if (command_status /= 0 .or. exit_status /= 0) then
         write (*, '(a)') 'test_hdf5_roundtrip: h5dump not on PATH, dimension-order check skipped'
         return
      end if
      call execute_command_line('h5dump -H -d /modes/shape ''' // result_file // &
         ''' | grep -F -q ''SIMPLE { ( 5, 3 ) / ( 5, 3 ) }''', wait=.true., &
         exitstat=exit_status, cmdstat=command_status)
      call check_true('h5dump shows /modes/shape (Fortran 3 x 5) with dims ( 5, 3 )', &
         command_status == 0 .and. exit_status == 0)
      call execute_command_line('h5dump -H -d /impacts/time ''' // result_file // &
         ''' | grep -F -q ''SIMPLE { ( 0 ) / ( 0 ) }''', wait=.true., &
         exitstat=exit_status, cmdstat=command_status)
      call check_true('h5dump shows /impacts/time with dims ( 0 )', &
         command_status == 0 .and. exit_status == 0)
      call execute_command_line('h5dump -a /mesh/x/unit ''' // result_file // &
         ''' | grep -F -q ''"m"''', wait=.true., exitstat=exit_status, cmdstat=command_status)
      call check_true('h5dump shows attribute /mesh/x unit = "m"', &
         command_status == 0 .and. exit_status == 0)
   end subroutine check_with_h5dump

   !> open_text_for_atomic_write / finish_text_file (+ rename) / discard_text_file.
   subroutine check_text_files()
      integer :: unit, io_status
      character(len=64) :: line
      character(len=:), allocatable :: text_temporary
      type(text_file_handle) :: file

      call open_text_for_atomic_write(text_file, file, text_temporary, stat, errmsg)
      call check_ok('open_text_for_atomic_write ' // text_file, stat, errmsg)
      if (stat /= 0) return
      call write_text_line(file, '# t (s)  u (m)', text_temporary, stat, errmsg)
      call check_ok('write_text_line', stat, errmsg)
      call check_true('text: temporary file exists before commit', file_exists(text_temporary))
      call check_true('text: final file absent before commit', .not. file_exists(text_file))
      call finish_text_file(file, text_temporary, stat, errmsg)
      call check_ok('finish_text_file', stat, errmsg)
      call rename_file(text_temporary, text_file, stat, errmsg)
      call check_ok('rename the text file', stat, errmsg)
      call check_true('text: final file exists after commit', file_exists(text_file))
      call check_true('text: temporary file gone after commit', &
         .not. file_exists(text_temporary))
      open (newunit=unit, file=text_file, status='old', action='read', iostat=io_status)
      line = ''
      if (io_status == 0) then
         read (unit, '(a)', iostat=io_status) line
         close (unit)
      end if
      call check_string('text: committed header line', trim(line), '# t (s)  u (m)')

      call open_text_for_atomic_write(discarded_text_file, file, text_temporary, stat, errmsg)
      call check_ok('open_text_for_atomic_write ' // discarded_text_file, stat, errmsg)
      if (stat /= 0) return
      call write_text_line(file, 'partial', text_temporary, stat, errmsg)
      call discard_text_file(file, text_temporary)
      call check_true('text: no temporary file after discard', .not. file_exists(text_temporary))
      call check_true('text: no final file after discard', .not. file_exists(discarded_text_file))
   end subroutine check_text_files

   !> Remove the files and (empty) directories made by this test.
   subroutine clean_up()
      integer :: remove_status
      character(len=message_length) :: remove_message

      call remove_file(result_file, remove_status, remove_message)
      call remove_file(text_file, remove_status, remove_message)
      call remove_directory(deeper_dir)
      call remove_directory(nested_dir)
      call remove_directory(base_dir // '/text')
      call remove_directory(base_dir)
   end subroutine clean_up

   !> rmdir (only ever removes an empty directory).
   subroutine remove_directory(path)
      character(len=*), intent(in) :: path
      integer :: exit_status, command_status
      exit_status = 0
      command_status = 0
      call execute_command_line('rmdir ''' // path // ''' 2> /dev/null', wait=.true., &
         exitstat=exit_status, cmdstat=command_status)
   end subroutine remove_directory

   ! ---------------------------------------------------------------------------------
   ! checks

   subroutine record(ok, message)
      logical, intent(in) :: ok
      character(len=*), intent(in) :: message
      if (ok) then
         passed = passed + 1
      else
         failed = failed + 1
         write (error_unit, '(a)') 'FAILED: ' // message
      end if
   end subroutine record

   subroutine check_true(quantity, condition)
      character(len=*), intent(in) :: quantity
      logical, intent(in) :: condition
      call record(condition, quantity)
   end subroutine check_true

   subroutine check_ok(quantity, stat, errmsg)
      character(len=*), intent(in) :: quantity
      integer, intent(in) :: stat
      character(len=*), intent(in) :: errmsg
      call record(stat == 0, quantity // ': stat = ' // integer_text(stat) // ', expected 0: ' &
         // trim(errmsg))
   end subroutine check_ok

   !> The call must fail with a message (naming `expected_text` when given).
   subroutine check_fails(quantity, stat, errmsg, expected_text)
      character(len=*), intent(in) :: quantity
      integer, intent(in) :: stat
      character(len=*), intent(in) :: errmsg
      character(len=*), intent(in), optional :: expected_text
      call record(stat /= 0, quantity // ': stat = 0, expected a failure')
      call record(len_trim(errmsg) > 0, quantity // ': empty errmsg')
      if (present(expected_text)) then
         call record(index(errmsg, expected_text) > 0, quantity // ': errmsg "' // &
            trim(errmsg) // '" does not name ' // expected_text)
      end if
   end subroutine check_fails

   !> Exact comparison of reals: identical bit patterns (tolerance 0; also tells -0 from +0).
   elemental function same_bits(a, b) result(same)
      real(dp), intent(in) :: a, b
      logical :: same
      same = transfer(a, 0_int64) == transfer(b, 0_int64)
   end function same_bits

   subroutine check_real(quantity, value, reference)
      character(len=*), intent(in) :: quantity
      real(dp), intent(in) :: value, reference
      call record(same_bits(value, reference), quantity // ' = ' // real_text(value) // &
         ', reference ' // real_text(reference) // ', tolerance 0 (bit-exact)')
   end subroutine check_real

   subroutine check_int(quantity, value, reference)
      character(len=*), intent(in) :: quantity
      integer, intent(in) :: value, reference
      call record(value == reference, quantity // ' = ' // integer_text(value) // &
         ', reference ' // integer_text(reference))
   end subroutine check_int

   subroutine check_string(quantity, value, reference)
      character(len=*), intent(in) :: quantity, value, reference
      ! len() as well: trailing blanks or padding must not appear.
      call record(len(value) == len(reference) .and. value == reference, quantity // &
         ' = "' // value // '" (length ' // integer_text(len(value)) // '), reference "' // &
         reference // '" (length ' // integer_text(len(reference)) // ')')
   end subroutine check_string

   subroutine check_real_1d(quantity, values, reference)
      character(len=*), intent(in) :: quantity
      real(dp), intent(in) :: values(:), reference(:)
      integer :: k
      if (size(values) /= size(reference)) then
         call record(.false., quantity // ': size ' // integer_text(size(values)) // &
            ', reference ' // integer_text(size(reference)))
         return
      end if
      do k = 1, size(values)
         if (.not. same_bits(values(k), reference(k))) then
            call record(.false., quantity // '(' // integer_text(k) // ') = ' // &
               real_text(values(k)) // ', reference ' // real_text(reference(k)) // &
               ', tolerance 0 (bit-exact)')
            return
         end if
      end do
      call record(.true., quantity)
   end subroutine check_real_1d

   subroutine check_real_2d(quantity, values, reference)
      character(len=*), intent(in) :: quantity
      real(dp), intent(in) :: values(:, :), reference(:, :)
      integer :: k, l
      if (any(shape(values) /= shape(reference))) then
         call record(.false., quantity // ': shape (' // integer_text(size(values, 1)) // ', ' &
            // integer_text(size(values, 2)) // '), reference (' // &
            integer_text(size(reference, 1)) // ', ' // integer_text(size(reference, 2)) // ')')
         return
      end if
      do l = 1, size(values, 2)
         do k = 1, size(values, 1)
            if (.not. same_bits(values(k, l), reference(k, l))) then
               call record(.false., quantity // '(' // integer_text(k) // ', ' // &
                  integer_text(l) // ') = ' // real_text(values(k, l)) // ', reference ' // &
                  real_text(reference(k, l)) // ', tolerance 0 (bit-exact)')
               return
            end if
         end do
      end do
      call record(.true., quantity)
   end subroutine check_real_2d

   subroutine check_int_1d(quantity, values, reference)
      character(len=*), intent(in) :: quantity
      integer, intent(in) :: values(:), reference(:)
      integer :: k
      if (size(values) /= size(reference)) then
         call record(.false., quantity // ': size ' // integer_text(size(values)) // &
            ', reference ' // integer_text(size(reference)))
         return
      end if
      do k = 1, size(values)
         if (values(k) /= reference(k)) then
            call record(.false., quantity // '(' // integer_text(k) // ') = ' // &
               integer_text(values(k)) // ', reference ' // integer_text(reference(k)))
            return
         end if
      end do
      call record(.true., quantity)
   end subroutine check_int_1d



end program test_hdf5_roundtrip
