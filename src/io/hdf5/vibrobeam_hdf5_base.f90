!> What every part of vibrobeam's HDF5 layer shares: the library's one-time
!! initialisation, the reason of the last HDF5 failure as text, path checks, attribute
!! writers and the closing of identifiers. Used by `vibrobeam_hdf5` (the result writer),
!! `vibrobeam_hdf5_series` (extendible datasets) and `vibrobeam_hdf5_reader`.
!!
!! Errors: every procedure returns `stat` (0 = success, 1 = failure) and an `errmsg` naming
!! the file, the HDF5 path and the operation that failed, with the reason HDF5 recorded
!! (`h5_reason`: the C library's errno text when there is one, e.g. 'No space left on
!! device'); nothing stops or prints. HDF5's automatic error-stack printing is switched off
!! by `initialize_library`, which every file opening or creation calls: the switch belongs
!! to the calling thread in a thread-safe HDF5 (each thread has its own error stack, born
!! with printing on), and a sweep's OpenMP threads write their points' files themselves.
!! This module owns the library's initialisation (`h5open_f`); `close_library` is called
!! once, by the program, before it exits.
module vibrobeam_hdf5_base
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_int64_t, c_null_char
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_filesystem, only: file_exists
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5close_f, h5eset_auto_f, h5kind_to_type, &
      H5_REAL_KIND, H5_INTEGER_KIND, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F, &
      h5pclose_f, h5lexists_f, h5dclose_f, h5screate_f, h5sclose_f, H5S_SCALAR_F, &
      h5acreate_f, h5aclose_f, h5awrite_f, h5aexists_f, h5adelete_f, h5aopen_f, &
      h5tcopy_f, h5tclose_f, h5tset_size_f, h5tset_strpad_f, H5T_FORTRAN_S1, &
      H5T_STR_NULLPAD_F, H5T_STR_NULLTERM_F
   implicit none
   private
   public :: no_id, buffer_length, initialize_library, close_library, h5_reason
   public :: fail, describe, valid_path, link_exists
   public :: attribute_outcome, put_scalar_attribute, &
      put_string_attribute, rewrite_attribute
   public :: open_file_for_reading
   public :: close_dataspace, close_datatype, close_property_list, close_dataset

   !> Marks an HDF5 identifier that is not open.
   integer(hid_t), parameter :: no_id = -1

   !> Length of the internal message buffers.
   integer, parameter :: buffer_length = 512

   !> HDF5 is a process-wide library: `h5open_f` (which also sets up the Fortran
   !! predefined type identifiers, leaking a few of them on each call) is called once per
   !! process. This flag mirrors the library's own global state; it is the only module
   !! variable that is not a constant.
   logical, save :: library_initialized = .false.

   interface
      !> int vb_h5_error_text(char *buffer, int length);  (src/io/hdf5/vibrobeam_hdf5_swmr.c)
      function c_h5_error_text(buffer, length) result(error) bind(C, name='vb_h5_error_text')
         import :: c_char, c_int
         character(kind=c_char), intent(out) :: buffer(*)
         integer(c_int), value, intent(in) :: length
         integer(c_int) :: error
      end function c_h5_error_text

      !> hid_t vb_h5_open_read(const char *name, int swmr, int locking);
      function c_h5_open_read(name, swmr, locking) result(file_id) bind(C, name='vb_h5_open_read')
         import :: c_char, c_int, c_int64_t
         character(kind=c_char), intent(in) :: name(*)
         integer(c_int), value, intent(in) :: swmr, locking
         integer(c_int64_t) :: file_id   ! hid_t of HDF5 1.10
      end function c_h5_open_read
   end interface

contains

   !> Close the HDF5 library (every identifier still open is closed with it). Called by
   !! the program before it exits, so that HDF5's own exit handler finds nothing to do.
   subroutine close_library()
      integer :: hdferr
      if (.not. library_initialized) return
      call h5close_f(hdferr)
      library_initialized = .false.
   end subroutine close_library

   !> The reason of the last HDF5 failure as text ('' when HDF5 recorded none): the C
   !! library's errno text when the error stack holds one ('No space left on device',
   !! 'File too large'), else the innermost description. Clears the error stack.
   function h5_reason() result(reason)
      character(len=:), allocatable :: reason
      character(kind=c_char) :: buffer(buffer_length)
      integer :: i, error
      error = c_h5_error_text(buffer, int(buffer_length, c_int))
      reason = ''
      do i = 1, buffer_length
         if (buffer(i) == c_null_char) exit
         reason = reason // buffer(i)
      end do
   end function h5_reason

   !> Initialise the HDF5 library once per process, and switch off its automatic
   !! error-stack printing for the calling thread (failures are reported through
   !! stat/errmsg instead). Called before every file is opened or created, so that each
   !! thread that uses HDF5 has switched the printing off before its first HDF5 call on a
   !! file; the switch costs a few instructions.
   subroutine initialize_library(stat, errmsg)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: hdferr

      stat = 0
      errmsg = ''
      if (.not. library_initialized) then
         call h5open_f(hdferr)
         if (hdferr < 0) then
            call fail(stat, errmsg, 'cannot initialise the HDF5 library (h5open_f)')
            return
         end if
         library_initialized = .true.
      end if
      call h5eset_auto_f(0, hdferr)
      if (hdferr < 0) call fail(stat, errmsg, 'cannot switch off HDF5 automatic error printing')
   end subroutine initialize_library

   !> Set stat = stat_failure and errmsg = message, followed by the reason HDF5 recorded for its last
   !! failure (`h5_reason`), or by `reason` when given: every HDF5 call clears the error
   !! stack, so a caller that closes identifiers after a failed call takes the reason
   !! (`h5_reason()`) right after that call.
   subroutine fail(stat, errmsg, message, reason)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: reason
      character(len=:), allocatable :: why
      stat = stat_failure
      if (present(reason)) then
         why = reason
      else
         why = h5_reason()
      end if
      if (len(why) > 0) then
         errmsg = message // ': ' // why
      else
         errmsg = message
      end if
   end subroutine fail

   !> 'path' in 'file', for messages.
   pure function describe(path, filename) result(text)
      character(len=*), intent(in) :: path, filename
      character(len=:), allocatable :: text
      text = '''' // trim(path) // ''' in HDF5 file ''' // trim(filename) // ''''
   end function describe

   !> Whether `path` is a well-formed object path: non-empty, no empty component, and no
   !! trailing '/' unless it is the root '/' (allowed only when `root_allowed`).
   pure function valid_path(path, root_allowed) result(valid)
      character(len=*), intent(in) :: path
      logical, intent(in) :: root_allowed
      logical :: valid
      integer :: last

      last = len_trim(path)
      if (last == 0) then
         valid = .false.
      else if (path(1:last) == '/') then
         valid = root_allowed
      else
         valid = path(last:last) /= '/' .and. index(path(1:last), '//') == 0
      end if
   end function valid_path

   !> Whether the object `path` exists below `location_id`, tested one component at a
   !! time (h5lexists_f fails, rather than returning false, when an intermediate
   !! component is missing).
   function link_exists(location_id, path) result(exists)
      integer(hid_t), intent(in) :: location_id
      character(len=*), intent(in) :: path
      logical :: exists
      integer :: last, position, hdferr

      last = len_trim(path)
      exists = .false.
      if (.not. valid_path(path, root_allowed=.true.)) return
      if (path(1:last) == '/') then
         exists = .true.
         return
      end if
      do position = 2, last + 1
         if (position <= last) then
            if (path(position:position) /= '/') cycle
         end if
         call h5lexists_f(location_id, path(1:position - 1), exists, hdferr)
         if (hdferr < 0) exists = .false.
         if (.not. exists) return
      end do
   end function link_exists

   !> Turn the outcome of a put_*_attribute (`failed_step` empty on success) into
   !! stat/errmsg.
   subroutine attribute_outcome(filename, object_path, name, failed_step, stat, errmsg)
      character(len=*), intent(in) :: filename, object_path, name, failed_step
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg

      stat = 0
      errmsg = ''
      if (len(failed_step) > 0) then
         call fail(stat, errmsg, 'cannot write attribute ''' // trim(name) // ''' of ' // &
            describe(object_path, filename) // ' (' // failed_step // ')')
      end if
   end subroutine attribute_outcome

   !> Create (replacing an existing one) the scalar attribute `name` of type `type_id` on
   !! the open object `object_id`. `failed_step` is empty on success.
   subroutine new_scalar_attribute(object_id, name, type_id, attribute_id, failed_step)
      integer(hid_t), intent(in) :: object_id, type_id
      character(len=*), intent(in) :: name
      integer(hid_t), intent(out) :: attribute_id
      character(len=:), allocatable, intent(out) :: failed_step
      integer(hid_t) :: space_id
      logical :: exists
      integer :: hdferr

      attribute_id = no_id
      failed_step = ''
      if (len_trim(name) == 0) then
         failed_step = 'empty attribute name'
         return
      end if
      call h5aexists_f(object_id, trim(name), exists, hdferr)
      if (hdferr < 0) then
         failed_step = 'H5Aexists'
         return
      end if
      if (exists) then
         call h5adelete_f(object_id, trim(name), hdferr)
         if (hdferr < 0) then
            failed_step = 'H5Adelete of the previous value'
            return
         end if
      end if
      call h5screate_f(H5S_SCALAR_F, space_id, hdferr)
      if (hdferr < 0) then
         failed_step = 'H5Screate'
         return
      end if
      call h5acreate_f(object_id, trim(name), type_id, space_id, attribute_id, hdferr)
      call close_dataspace(space_id)
      if (hdferr < 0) then
         attribute_id = no_id
         failed_step = 'H5Acreate'
      end if
   end subroutine new_scalar_attribute

   !> Write the scalar attribute `name` = `value` (a real(dp), a default integer or an
   !! integer(int64), stored in its native type) on the open object `object_id`.
   subroutine put_scalar_attribute(object_id, name, value, failed_step)
      integer(hid_t), intent(in) :: object_id
      character(len=*), intent(in) :: name
      class(*), intent(in) :: value
      character(len=:), allocatable, intent(out) :: failed_step
      integer(hid_t) :: attribute_id, type_id
      integer :: hdferr

      select type (value)
      type is (real(dp))
         type_id = h5kind_to_type(dp, H5_REAL_KIND)
      type is (integer)
         type_id = h5kind_to_type(kind(value), H5_INTEGER_KIND)
      type is (integer(int64))
         type_id = h5kind_to_type(int64, H5_INTEGER_KIND)
      class default
         failed_step = 'unsupported attribute type'
         return
      end select
      call new_scalar_attribute(object_id, name, type_id, attribute_id, failed_step)
      if (len(failed_step) > 0) return
      select type (value)
      type is (real(dp))
         call h5awrite_f(attribute_id, type_id, value, [1_hsize_t], hdferr)
      type is (integer)
         call h5awrite_f(attribute_id, type_id, value, [1_hsize_t], hdferr)
      type is (integer(int64))
         call h5awrite_f(attribute_id, type_id, value, [1_hsize_t], hdferr)
      end select
      if (hdferr < 0) failed_step = 'H5Awrite'
      call h5aclose_f(attribute_id, hdferr)
   end subroutine put_scalar_attribute

   !> Write the fixed-length string attribute `name` = `value` on the open object
   !! `object_id`: NUL-padded and of length len(value) by default; with `capacity`, a
   !! NUL-terminated string of `capacity` bytes, which `rewrite_attribute` can later
   !! change in place (while the file is in SWMR mode, where attributes cannot be created).
   !! HDF5 string types need a size of at least 1, so '' is stored as one NUL byte (read
   !! back as '').
   subroutine put_string_attribute(object_id, name, value, failed_step, capacity)
      integer(hid_t), intent(in) :: object_id
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: value
      character(len=:), allocatable, intent(out) :: failed_step
      integer, intent(in), optional :: capacity
      integer(hid_t) :: attribute_id, string_type
      integer :: hdferr

      call string_type_for(value, capacity, string_type, failed_step)
      if (len(failed_step) > 0) return
      call new_scalar_attribute(object_id, name, string_type, attribute_id, failed_step)
      if (len(failed_step) == 0) then
         call h5awrite_f(attribute_id, string_type, padded(value, capacity), [1_hsize_t], hdferr)
         if (hdferr < 0) failed_step = 'H5Awrite'
         call h5aclose_f(attribute_id, hdferr)
      end if
      call close_datatype(string_type)
   end subroutine put_string_attribute

   !> Change the value of the existing scalar attribute `name` of `object_id` in place
   !! (allowed in SWMR mode): a real(dp), an integer(int64), or a string attribute made by
   !! `put_string_attribute` with this `capacity` (len(value) <= capacity - 1).
   subroutine rewrite_attribute(object_id, name, value, failed_step, capacity)
      integer(hid_t), intent(in) :: object_id
      character(len=*), intent(in) :: name
      class(*), intent(in) :: value
      character(len=:), allocatable, intent(out) :: failed_step
      integer, intent(in), optional :: capacity
      integer(hid_t) :: attribute_id, string_type
      integer :: hdferr

      failed_step = ''
      call h5aopen_f(object_id, trim(name), attribute_id, hdferr)
      if (hdferr < 0) then
         failed_step = 'H5Aopen'
         return
      end if
      select type (value)
      type is (real(dp))
         call h5awrite_f(attribute_id, h5kind_to_type(dp, H5_REAL_KIND), value, [1_hsize_t], hdferr)
      type is (integer(int64))
         call h5awrite_f(attribute_id, h5kind_to_type(int64, H5_INTEGER_KIND), value, [1_hsize_t], hdferr)
      type is (character(len=*))
         call string_type_for(value, capacity, string_type, failed_step)
         if (len(failed_step) == 0) then
            call h5awrite_f(attribute_id, string_type, padded(value, capacity), [1_hsize_t], hdferr)
            call close_datatype(string_type)
         end if
      class default
         failed_step = 'unsupported attribute type'
      end select
      if (hdferr < 0) failed_step = 'H5Awrite'
      call h5aclose_f(attribute_id, hdferr)
   end subroutine rewrite_attribute

   !> The string type of a `put_string_attribute` (see there).
   subroutine string_type_for(value, capacity, string_type, failed_step)
      character(len=*), intent(in) :: value
      integer, intent(in), optional :: capacity
      integer(hid_t), intent(out) :: string_type
      character(len=:), allocatable, intent(out) :: failed_step
      integer :: hdferr

      failed_step = ''
      call h5tcopy_f(H5T_FORTRAN_S1, string_type, hdferr)
      if (hdferr < 0) then
         failed_step = 'H5Tcopy'
         return
      end if
      call h5tset_size_f(string_type, int(len(padded(value, capacity)), size_t), hdferr)
      if (hdferr >= 0) then
         if (present(capacity)) then
            call h5tset_strpad_f(string_type, H5T_STR_NULLTERM_F, hdferr)
         else
            call h5tset_strpad_f(string_type, H5T_STR_NULLPAD_F, hdferr)
         end if
      end if
      if (hdferr < 0) then
         call close_datatype(string_type)
         failed_step = 'H5Tset_size/H5Tset_strpad'
      end if
   end subroutine string_type_for

   !> `value` as stored: NUL-padded to `capacity` bytes, or as it is (one NUL if empty).
   pure function padded(value, capacity) result(buffer)
      character(len=*), intent(in) :: value
      integer, intent(in), optional :: capacity
      character(len=:), allocatable :: buffer
      if (present(capacity)) then
         buffer = value(1:min(len(value), capacity - 1)) // repeat(achar(0), capacity - min(len(value), capacity - 1))
      else if (len(value) > 0) then
         buffer = value
      else
         buffer = achar(0)
      end if
   end function padded

   !> Open `filename` read-only (initialising HDF5 if needed). A file whose writer was
   !! killed still says "open for SWMR write" in its superblock; it is then opened as a
   !! SWMR reader, which HDF5 allows (docs/output.md, "After a kill"). With `live`, the
   !! file's writer may be running (the journal of a running sweep, read by `--check`):
   !! it is opened as a SWMR reader at once and without HDF5's file lock, so that the
   !! reader never stands in the writer's way.
   subroutine open_file_for_reading(filename, file_id, stat, errmsg, live)
      character(len=*), intent(in) :: filename
      integer(hid_t), intent(out) :: file_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: live
      integer :: hdferr
      logical :: running

      file_id = no_id
      call initialize_library(stat, errmsg)
      if (stat /= 0) return
      if (.not. file_exists(filename)) then
         call fail(stat, errmsg, 'HDF5 file ''' // trim(filename) // ''' does not exist')
         return
      end if
      running = .false.
      if (present(live)) running = live
      if (running) then
         file_id = int(c_h5_open_read(trim(filename) // c_null_char, 1_c_int, 0_c_int), hid_t)
      else
         call h5fopen_f(trim(filename), H5F_ACC_RDONLY_F, file_id, hdferr)
         if (hdferr < 0) file_id = int(c_h5_open_read(trim(filename) // c_null_char, 1_c_int, 1_c_int), hid_t)
      end if
      if (file_id < 0) then
         file_id = no_id
         call fail(stat, errmsg, 'cannot open ''' // trim(filename) // ''' as an HDF5 file')
      end if
   end subroutine open_file_for_reading

   !> Close a dataspace identifier if it is open.
   subroutine close_dataspace(space_id)
      integer(hid_t), intent(inout) :: space_id
      integer :: hdferr
      if (space_id /= no_id) call h5sclose_f(space_id, hdferr)
      space_id = no_id
   end subroutine close_dataspace

   !> Close a dataset identifier if it is open.
   subroutine close_dataset(dataset)
      integer(hid_t), intent(inout) :: dataset
      integer :: hdferr
      if (dataset /= no_id) call h5dclose_f(dataset, hdferr)
      dataset = no_id
   end subroutine close_dataset

   !> Close a datatype identifier if it is open.
   subroutine close_datatype(type_id)
      integer(hid_t), intent(inout) :: type_id
      integer :: hdferr
      if (type_id /= no_id) call h5tclose_f(type_id, hdferr)
      type_id = no_id
   end subroutine close_datatype

   !> Close a property list identifier if it is open.
   subroutine close_property_list(list_id)
      integer(hid_t), intent(inout) :: list_id
      integer :: hdferr
      if (list_id /= no_id) call h5pclose_f(list_id, hdferr)
      list_id = no_id
   end subroutine close_property_list
end module vibrobeam_hdf5_base
