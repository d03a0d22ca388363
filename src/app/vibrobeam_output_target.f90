!> Checks of where a run will write, made before anything is computed or written: the
!! result file must be a new or replaceable file (not an existing directory, not the input
!! file, not one of the text files derived from its name, on a path the system can
!! create, on a file system that stores files), `&initial from_file` must be a readable
!! file, and the results of a dynamics run must fit: their estimated size
!! (`estimate_result_size`) below a hard limit and below the free space of the target file
!! system. Failures are invalid input (the program exits 2 and writes nothing).
!!
!! The run's writer guards the same things at write time; these checks are the ones a
!! user meets first, before an afternoon of computing.
module vibrobeam_output_target
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_double, c_size_t, c_null_char
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_scene, only: scene_type, path_length, step_count
   use vibrobeam_namelist_tokens, only: abbreviated
   implicit none
   private
   public :: check_output_target, estimate_result_size, result_size, max_result_bytes
   ! for the checks of a sweep's files (vibrobeam_sweep_check)
   public :: real_path, resolve_directory, split_path, join, bytes_text, free_bytes

   !> Largest result set a run may write (bytes): 2^40, one tebibyte.
   real(dp), parameter :: max_result_bytes = 1099511627776.0_dp

   !> Room left in a path for what the writer appends to the result file's name
   !! ('_penetration.dat', a temporary suffix): the whole path may use path_length - 1 -
   !! path_margin bytes, its last name 255 - path_margin (NAME_MAX is 255 on Linux).
   integer, parameter :: path_margin = 64
   integer, parameter :: name_max = 255

   !> What a run will write, estimated from the scene (impacts, whose number is not known
   !! beforehand, are not counted).
   type :: result_size
      real(dp) :: steps = 0            !! time steps
      real(dp) :: outputs = 0          !! output times (rows of the histories)
      real(dp) :: snapshots = 0        !! displacement field snapshots
      real(dp) :: values_per_output = 0   !! numbers written per output time besides the field
      real(dp) :: hdf5_bytes = 0       !! the HDF5 file's data
      real(dp) :: text_bytes = 0       !! the .dat files (0 with text = .false.)
      real(dp) :: total_bytes = 0
   end type result_size

   interface
      function c_path_kind(path) result(kind) bind(C, name='vibrobeam_path_kind')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: kind
      end function c_path_kind
      function c_same_file(first, second) result(same) bind(C, name='vibrobeam_same_file')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: first(*), second(*)
         integer(c_int) :: same
      end function c_same_file
      function c_real_path(path, resolved, size) result(status) bind(C, name='vibrobeam_real_path')
         import :: c_char, c_int, c_size_t
         character(kind=c_char), intent(in) :: path(*)
         character(kind=c_char), intent(out) :: resolved(*)
         integer(c_size_t), value, intent(in) :: size
         integer(c_int) :: status
      end function c_real_path
      function c_free_bytes(path, bytes, size) result(status) bind(C, name='vibrobeam_free_bytes')
         import :: c_char, c_int, c_double
         character(kind=c_char), intent(in) :: path(*)
         real(c_double), intent(out) :: bytes, size
         integer(c_int) :: status
      end function c_free_bytes
   end interface

   integer, parameter :: kind_absent = 0, kind_file = 1, kind_directory = 2

contains

   !> Refuse a result path or a result size that cannot work (see the module comment).
   !! `input_file` is the namelist file as given on the command line. `check_size` false:
   !! the result size is checked elsewhere (a sweep's, `vibrobeam_sweep_check`, whose
   !! points set their own t_end).
   subroutine check_output_target(scene, input_file, stat, errmsg, check_size)
      type(scene_type), intent(in) :: scene
      character(len=*), intent(in) :: input_file
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: check_size
      character(len=:), allocatable :: file, directory, name, resolved, input_resolved, stem, shown
      character(len=:), allocatable :: existing
      type(result_size) :: estimate
      real(dp) :: free, capacity
      logical :: known_space
      stat = stat_failure
      file = trim(scene%output%file)
      if (len(file) == 0) then
         errmsg = '&output file = '''' is empty: give a file name such as ''results/run.h5'''
         return
      end if
      shown = '&output file = '''//abbreviated(file, 60)//''''
      if (path_kind(file) == kind_directory .or. file(len(file):) == '/') then
         errmsg = shown//' is a directory: give a file name such as '''// &
                  abbreviated(strip_slashes(file), 60)//'/run.h5'''
         return
      end if
      call split_path(file, directory, name)
      if (len(file) > path_length - 1 - path_margin) then
         errmsg = shown//' is too long for the files derived from it: at most '// &
                  integer_text(path_length - 1 - path_margin)//' characters'
         return
      end if
      if (len(name) > name_max - path_margin) then
         errmsg = shown//': its last name has '//integer_text(len(name))//' characters; at most '// &
                  integer_text(name_max - path_margin)//' (the file system allows '//integer_text(name_max)// &
                  ', and the run appends suffixes such as ''_penetration.dat'')'
         return
      end if
      if (any_name_too_long(directory)) then
         errmsg = shown//': a directory name in it is longer than '//integer_text(name_max)//' characters'
         return
      end if
      call resolve_directory(directory, resolved, existing, stat, errmsg)
      if (stat /= 0) then
         errmsg = shown//': '//trim(errmsg)
         return
      end if
      stat = stat_failure
      ! a file system that stores nothing (/proc, /sys): every run would fail to write
      known_space = c_free_bytes(c_string(existing), free, capacity) == 0
      if (known_space .and. capacity <= 0) then
         errmsg = shown//': '''//abbreviated(existing, 60)//''' is on a file system without storage (size 0, '// &
                  'such as /proc or /sys): give a path on a disk'
         return
      end if
      ! the input file: the same file under any name (links included), or the same path
      if (c_same_file(c_string(file), c_string(input_file)) == 1) then
         errmsg = shown//' is the input file: the results would replace it; give another name'
         return
      end if
      input_resolved = real_path(input_file)
      if (len(input_resolved) > 0) then
         if (join(resolved, name) == input_resolved) then
            errmsg = shown//' is the input file: the results would replace it; give another name'
            return
         end if
         ! the text files STEM_*.dat beside the HDF5 file
         stem = join(resolved, name)
         if (len(stem) > 3) then
            if (stem(len(stem) - 2:) == '.h5') stem = stem(1:len(stem) - 3)
         end if
         if (scene%output%text .and. len(input_resolved) > len(stem) + 5) then
            if (input_resolved(1:len(stem) + 1) == stem//'_' .and. input_resolved(len(input_resolved) - 3:) == '.dat' &
                .and. index(input_resolved(len(stem) + 2:), '/') == 0) then
               errmsg = shown//' would write text files named '''//abbreviated(base_name(stem), 60)// &
                        '_*.dat'', and the input file '''//abbreviated(base_name(input_resolved), 60)// &
                        ''' is one of those names: rename the input or the output'
               return
            end if
         end if
      end if
      if (len_trim(scene%initial%from_file) > 0) then
         if (path_kind(trim(scene%initial%from_file)) /= kind_file) then
            errmsg = '&initial from_file = '''//abbreviated(trim(scene%initial%from_file), 60)// &
                     ''' is not an existing file: give the results file of an earlier run'
            return
         end if
         ! the continued result holds only what follows the checkpoint: writing it over the
         ! file it continues would lose the earlier part
         if (c_same_file(c_string(file), c_string(trim(scene%initial%from_file))) == 1 .or. &
             join(resolved, name) == real_path(trim(scene%initial%from_file))) then
            errmsg = shown//' is the file that &initial from_file continues; the continued result holds '// &
                     'only what follows its checkpoint: give it another name'
            return
         end if
      end if
      if (present(check_size)) then
         if (.not. check_size) then
            stat = 0
            errmsg = ''
            return
         end if
      end if
      if (scene%analysis%kind == 'dynamics') then
         estimate = estimate_result_size(scene)
         if (estimate%total_bytes > max_result_bytes) then
            errmsg = size_message(estimate)//', more than the limit of '//bytes_text(max_result_bytes)//size_advice()
            return
         end if
         if (known_space) then
            if (estimate%total_bytes > free) then
               errmsg = size_message(estimate)//', more than the '//bytes_text(free)//' free on the file system of '''// &
                        abbreviated(existing, 60)//''''//size_advice()
               return
            end if
         end if
      end if
      stat = 0
      errmsg = ''
   contains
      function size_message(estimate) result(text)
         type(result_size), intent(in) :: estimate
         character(len=:), allocatable :: text
         text = '&output every = '//integer_text(scene%output%every)//', field_every = '//integer_text(scene%output%field_every)// &
                ' with '//real_text(estimate%steps)//' steps and '//integer_text(scene%mesh%elements + 1)// &
                ' nodes would write about '//bytes_text(estimate%total_bytes)//' of results'
      end function size_message
      function size_advice() result(text)
         character(len=:), allocatable :: text
         text = ': raise every or field_every, set text = .false., or shorten &time t_end'
      end function size_advice
   end subroutine check_output_target

   !> The size of the results of a dynamics run (kind = 'dynamics'): histories at
   !! floor(steps/every) + 2 output times (t = 0, every `every` steps, the last step) of
   !! 16 numbers plus 2 per observation point, and field snapshots of N + 1 values at
   !! floor(steps/field_every) + 2 times (field_every = 0: every). 8 bytes per number in
   !! HDF5; in the .dat files 25 characters per number and 49 per field value (x, t, u).
   !! Computed in reals: the step count may exceed any default integer.
   pure function estimate_result_size(scene) result(estimate)
      type(scene_type), intent(in) :: scene
      type(result_size) :: estimate
      integer, parameter :: history_columns = 16
      real(dp), parameter :: bytes_per_number = 8, text_per_number = 25, text_per_field_value = 49
      integer :: field_every, points
      real(dp) :: nodes
      points = 0
      if (allocated(scene%output%points)) points = size(scene%output%points)
      estimate%steps = real(step_count(scene), dp)
      field_every = scene%output%field_every
      if (field_every == 0) field_every = scene%output%every
      estimate%outputs = real(step_count(scene)/int(scene%output%every, int64), dp) + 2
      estimate%snapshots = real(step_count(scene)/int(field_every, int64), dp) + 2
      estimate%values_per_output = history_columns + 2*points
      nodes = scene%mesh%elements + 1
      estimate%hdf5_bytes = bytes_per_number*(estimate%outputs*estimate%values_per_output + estimate%snapshots*nodes)
      if (scene%output%text) estimate%text_bytes = text_per_number*estimate%outputs*estimate%values_per_output + &
                                        text_per_field_value*estimate%snapshots*nodes
      estimate%total_bytes = estimate%hdf5_bytes + estimate%text_bytes
   end function estimate_result_size

   !> '1.2e9 bytes (1.1 GiB)'.
   function bytes_text(bytes) result(text)
      real(dp), intent(in) :: bytes
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      character(len=3), parameter :: units(5) = ['KiB', 'MiB', 'GiB', 'TiB', 'PiB']
      integer :: k
      write (buffer, '(es9.2e2)') bytes
      text = trim(adjustl(buffer))
      text = text(1:index(text, 'E') - 1)//'e'//text(index(text, 'E') + 1:)//' bytes'
      k = 0
      do while (k < size(units))
         if (bytes < 1024.0_dp**(k + 1)) exit
         k = k + 1
      end do
      if (k > 0) then
         write (buffer, '(f0.1)') bytes/1024.0_dp**k
         text = text//' ('//trim(buffer)//' '//units(k)//')'
      end if
   end function bytes_text

   !> The canonical directory of `directory` once the run has created what is missing:
   !! realpath(3) of its longest existing prefix, with the missing names appended ('.'
   !! dropped, '..' removing the name before it: the directories the run creates are real
   !! directories, not links). `existing` is that existing prefix, for statvfs. Fails when
   !! a prefix exists but is not a directory.
   subroutine resolve_directory(directory, resolved, existing, stat, errmsg)
      character(len=*), intent(in) :: directory
      character(len=:), allocatable, intent(out) :: resolved, existing
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: missing, part, head
      integer :: slash
      stat = 0
      errmsg = ''
      existing = directory
      missing = ''
      do
         if (len(existing) == 0) existing = '.'
         select case (path_kind(existing))
         case (kind_directory)
            exit
         case (kind_absent)
            call split_path(existing, head, part)
            missing = part//'/'//missing
            existing = head
         case default
            stat = stat_failure
            errmsg = ''''//abbreviated(existing, 60)//''' exists and is not a directory'
            return
         end select
      end do
      resolved = real_path(existing)
      if (len(resolved) == 0) resolved = existing
      do while (len(missing) > 0)
         slash = index(missing, '/')
         part = missing(1:slash - 1)
         missing = missing(slash + 1:)
         if (part == '.' .or. len(part) == 0) cycle
         if (part == '..') then
            call split_path(resolved, head, part)
            resolved = head
            if (len(resolved) == 0) resolved = '/'
            cycle
         end if
         resolved = join(resolved, part)
      end do
   end subroutine resolve_directory

   !> Directory part (without the last '/', '' when there is none; '/' for the root) and
   !! last name of a path.
   pure subroutine split_path(path, directory, name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: directory, name
      integer :: slash
      slash = index(path, '/', back=.true.)
      name = path(slash + 1:)
      directory = path(1:max(slash - 1, 0))
      if (slash == 1) directory = '/'
   end subroutine split_path

   pure function join(directory, name) result(path)
      character(len=*), intent(in) :: directory, name
      character(len=:), allocatable :: path
      if (len(directory) == 0) then
         path = name
      else if (directory(len(directory):) == '/') then
         path = directory//name
      else
         path = directory//'/'//name
      end if
   end function join

   pure function base_name(path) result(name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: name
      name = path(index(path, '/', back=.true.) + 1:)
   end function base_name

   pure function strip_slashes(path) result(stripped)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: stripped
      stripped = path
      do while (len(stripped) > 1)
         if (stripped(len(stripped):) /= '/') exit
         stripped = stripped(1:len(stripped) - 1)
      end do
   end function strip_slashes

   pure logical function any_name_too_long(path)
      character(len=*), intent(in) :: path
      integer :: start, slash
      any_name_too_long = .false.
      start = 1
      do while (start <= len(path))
         slash = index(path(start:), '/')
         if (slash == 0) slash = len(path) - start + 2
         if (slash - 1 > name_max) any_name_too_long = .true.
         start = start + slash
      end do
   end function any_name_too_long

   integer function path_kind(path)
      character(len=*), intent(in) :: path
      path_kind = c_path_kind(c_string(path))
   end function path_kind

   !> The bytes free for an unprivileged user on the file system of the existing `path`;
   !! .false. when it cannot be told.
   logical function free_bytes(path, bytes)
      character(len=*), intent(in) :: path
      real(dp), intent(out) :: bytes
      real(dp) :: capacity
      free_bytes = c_free_bytes(c_string(path), bytes, capacity) == 0
   end function free_bytes

   !> realpath(3) of an existing path; '' when it cannot be resolved.
   function real_path(path) result(resolved)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: resolved
      character(kind=c_char, len=path_length + 1) :: buffer
      integer :: finish
      resolved = ''
      if (c_real_path(c_string(path), buffer, int(len(buffer), c_size_t)) /= 0) return
      finish = index(buffer, c_null_char)
      if (finish > 1) resolved = buffer(1:finish - 1)
   end function real_path

   pure function c_string(path) result(string)
      character(len=*), intent(in) :: path
      character(kind=c_char, len=:), allocatable :: string
      string = path//c_null_char
   end function c_string
end module vibrobeam_output_target
