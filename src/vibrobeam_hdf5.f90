!> A thin object layer over the HDF5 Fortran API: atomic writing of vibrobeam result files
!! (INTERFACE.md, "Output") and small readers for tests and post-processing.
!!
!! `h5_writer` writes into `<final>.tmp` (see `vibrobeam_filesystem: temporary_name`) and
!! only `commit` renames it onto `<final>`, so a result file under its final name is always
!! complete; `discard` deletes the temporary file and leaves `<final>` untouched.
!!
!! Conventions
!! - Paths are absolute HDF5 paths ('/modes/frequency'); a leading '/' may be omitted.
!!   Missing intermediate groups are created. Writing a dataset whose path already exists
!!   is an error; writing an attribute that already exists replaces it.
!! - Reals are stored as the native double type (IEEE binary64), integers as the native
!!   type of the default Fortran integer; the round trip is bit-exact.
!! - Dimension order: HDF5's Fortran API reverses dimensions with respect to C, so a
!!   Fortran array `values(n1, n2)` is a dataset that h5py/h5dump/C see with shape
!!   `(n2, n1)`, and `values(i, j)` is `dataset[j-1, i-1]` in h5py. Storing one snapshot
!!   per column, `field(nodes, times)`, thus gives the (times x nodes) dataset of
!!   INTERFACE.md. `read_real_2d` applies the inverse map and returns `values(n1, n2)`.
!! - String attributes are scalar, fixed-length (length = len(value), at least 1),
!!   ASCII, NUL-padded (as h5py stores NumPy 'S' strings); h5py returns them as
!!   `bytes`. An empty string is stored as one NUL byte and reads back as ''.
!! - Zero-size arrays give datasets with a zero dimension (nothing is written to them).
!!
!! Errors: every procedure returns `stat` (0 = success, 1 = failure) and an `errmsg` naming
!! the file, the HDF5 path and the operation that failed; nothing stops or prints. HDF5's
!! automatic error-stack printing is switched off when this module initialises the library.
!! This module owns the library's initialisation (`h5open_f`); nothing else in the program
!! may call `h5close_f`.
module vibrobeam_hdf5
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: integer_text
   use vibrobeam_filesystem, only: make_parent_directories, rename_file, remove_file, &
      file_exists, temporary_name
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5eset_auto_f, h5kind_to_type, &
      H5_REAL_KIND, H5_INTEGER_KIND, &
      h5fcreate_f, h5fopen_f, h5fclose_f, h5fflush_f, H5F_ACC_TRUNC_F, H5F_ACC_RDONLY_F, &
      H5F_SCOPE_GLOBAL_F, H5F_CLOSE_STRONG_F, &
      h5pcreate_f, h5pclose_f, h5pset_fclose_degree_f, h5pset_create_inter_group_f, &
      H5P_FILE_ACCESS_F, H5P_LINK_CREATE_F, &
      h5gcreate_f, h5gclose_f, h5lexists_f, h5oopen_f, h5oclose_f, &
      h5screate_f, h5screate_simple_f, h5sclose_f, h5sget_simple_extent_ndims_f, &
      h5sget_simple_extent_dims_f, h5sget_simple_extent_npoints_f, H5S_SCALAR_F, &
      h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dread_f, h5dget_space_f, &
      h5acreate_f, h5aopen_f, h5aclose_f, h5awrite_f, h5aread_f, h5aexists_f, &
      h5adelete_f, h5aget_space_f, h5aget_type_f, &
      h5tcopy_f, h5tclose_f, h5tset_size_f, h5tget_size_f, h5tset_strpad_f, &
      h5tget_class_f, h5tis_variable_str_f, H5T_FORTRAN_S1, H5T_STR_NULLPAD_F, &
      H5T_STRING_F
   implicit none
   private
   public :: h5_writer
   public :: read_real_1d, read_real_2d, read_int_1d, read_real_scalar
   public :: read_attr_real, read_attr_int, read_attr_string
   public :: h5_path_exists

   !> Marks an HDF5 identifier that is not open.
   integer(hid_t), parameter :: no_id = -1

   !> Length of the internal message buffers (file-system messages).
   integer, parameter :: buffer_length = 512

   !> HDF5 is a process-wide library: `h5open_f` (which also sets up the Fortran
   !! predefined type identifiers, leaking a few of them on each call) is called once per
   !! process. This flag mirrors the library's own global state; it is the only module
   !! variable that is not a constant.
   logical, save :: library_initialized = .false.

   !> Writer of one HDF5 result file, written as `<final>.tmp` and renamed on `commit`.
   !!
   !! Life cycle: `create` -> `write_*` / `attr_*` (any number) -> `commit` or `discard`.
   !! A writer that is neither committed nor discarded leaves its `.tmp` file behind.
   !! After `commit` or `discard` the same object may `create` another file.
   type :: h5_writer
      private
      integer(hid_t) :: file_id = no_id              !! open temporary file
      integer(hid_t) :: link_creation_list = no_id   !! creates missing intermediate groups
      character(len=:), allocatable :: final_name    !! name after commit
      character(len=:), allocatable :: temporary_name  !! name while writing
      logical :: is_open = .false.                   !! between create and commit/discard
   contains
      procedure :: create => writer_create
      procedure :: write_real_1d => writer_write_real_1d
      procedure :: write_real_2d => writer_write_real_2d
      procedure :: write_int_1d => writer_write_int_1d
      procedure :: write_real_scalar => writer_write_real_scalar
      procedure :: attr_real => writer_attr_real
      procedure :: attr_int => writer_attr_int
      procedure :: attr_string => writer_attr_string
      procedure :: commit => writer_commit
      procedure :: discard => writer_discard
   end type h5_writer

contains

   ! =================================================================================
   ! h5_writer

   !> Start a new result file: initialise HDF5 (once), create the parent directories of
   !! `final_name` and create (truncating) `final_name // '.tmp'`. `final_name` itself is
   !! not touched until `commit`.
   subroutine writer_create(self, final_name, stat, errmsg)
      class(h5_writer), intent(inout) :: self      !! writer, not currently open
      character(len=*), intent(in) :: final_name   !! name of the complete file
      integer, intent(out) :: stat                 !! 0 on success
      character(len=*), intent(out) :: errmsg      !! reason of the failure, blank on success
      integer(hid_t) :: file_access_list
      integer :: hdferr
      character(len=buffer_length) :: fs_message

      stat = 0
      errmsg = ''
      if (self%is_open) then
         call fail(stat, errmsg, 'HDF5 writer is already writing ''' // self%temporary_name &
            // '''; commit or discard it before creating ''' // trim(final_name) // '''')
         return
      end if
      call initialize_library(stat, errmsg)
      if (stat /= 0) return
      call make_parent_directories(final_name, stat, fs_message)
      if (stat /= 0) then
         call fail(stat, errmsg, 'cannot create HDF5 file ''' // trim(final_name) // ''': ' &
            // trim(fs_message))
         return
      end if
      self%final_name = trim(final_name)
      self%temporary_name = temporary_name(final_name)

      ! Strong close degree: h5fclose_f closes every object still open in the file, so the
      ! file is complete on disk before the rename in `commit`, even after an error path.
      call h5pcreate_f(H5P_FILE_ACCESS_F, file_access_list, hdferr)
      if (hdferr >= 0) call h5pset_fclose_degree_f(file_access_list, H5F_CLOSE_STRONG_F, hdferr)
      if (hdferr >= 0) then
         call h5fcreate_f(self%temporary_name, H5F_ACC_TRUNC_F, self%file_id, hdferr, &
            access_prp=file_access_list)
         call close_property_list(file_access_list)
      end if
      if (hdferr < 0) then
         self%file_id = no_id
         call fail(stat, errmsg, 'cannot create HDF5 file ''' // self%temporary_name // '''')
         return
      end if

      call h5pcreate_f(H5P_LINK_CREATE_F, self%link_creation_list, hdferr)
      if (hdferr >= 0) call h5pset_create_inter_group_f(self%link_creation_list, 1, hdferr)
      if (hdferr < 0) then
         call close_property_list(self%link_creation_list)
         call h5fclose_f(self%file_id, hdferr)
         self%file_id = no_id
         call remove_file(self%temporary_name, hdferr, fs_message)
         call fail(stat, errmsg, 'cannot set up link creation properties for ''' // &
            self%temporary_name // '''')
         return
      end if
      self%is_open = .true.
   end subroutine writer_create

   !> Write the 1-d real dataset `path` (shape `(size(values))`), with an optional
   !! string attribute 'unit'. Pass `stat`/`errmsg` by keyword when `unit` is omitted.
   subroutine writer_write_real_1d(self, path, values, unit, stat, errmsg)
      class(h5_writer), intent(inout) :: self         !! open writer
      character(len=*), intent(in) :: path            !! dataset path, e.g. '/modes/frequency'
      real(dp), intent(in) :: values(:)               !! data, may be empty
      character(len=*), intent(in), optional :: unit  !! physical unit, e.g. 'rad/s'
      integer, intent(out) :: stat                    !! 0 on success
      character(len=*), intent(out) :: errmsg         !! reason of the failure, blank on success
      integer(hid_t) :: dataset_id
      integer(hsize_t) :: dims(1)
      integer :: hdferr
      real(dp), allocatable :: contiguous_values(:)

      dims = int(shape(values), hsize_t)
      call create_dataset(self, path, h5kind_to_type(dp, H5_REAL_KIND), 1, dims, &
         dataset_id, stat, errmsg)
      if (stat /= 0) return
      hdferr = 0
      if (size(values) > 0) then
         ! h5dwrite_f takes an explicit-shape buffer: copy an array section ourselves rather
         ! than leave it to a compiler temporary (reported at run time by -fcheck=array-temps).
         if (is_contiguous(values)) then
            call h5dwrite_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, dims, hdferr)
         else
            allocate (contiguous_values(size(values)))
            contiguous_values(:) = values
            call h5dwrite_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), contiguous_values, &
               dims, hdferr)
         end if
      end if
      call finish_dataset(self, path, dataset_id, hdferr, unit, stat, errmsg)
   end subroutine writer_write_real_1d

   !> Write the 2-d real dataset `path`. The Fortran array `values(n1, n2)` becomes a
   !! dataset of shape `(n2, n1)` as seen by h5py, h5dump and C (HDF5's Fortran API
   !! reverses the dimensions; memory order is unchanged). Optional string attribute
   !! 'unit'. Pass `stat`/`errmsg` by keyword when `unit` is omitted.
   subroutine writer_write_real_2d(self, path, values, unit, stat, errmsg)
      class(h5_writer), intent(inout) :: self         !! open writer
      character(len=*), intent(in) :: path            !! dataset path, e.g. '/modes/shape'
      real(dp), intent(in) :: values(:, :)            !! data (n1, n2), may be empty
      character(len=*), intent(in), optional :: unit  !! physical unit, e.g. 'm'
      integer, intent(out) :: stat                    !! 0 on success
      character(len=*), intent(out) :: errmsg         !! reason of the failure, blank on success
      integer(hid_t) :: dataset_id
      integer(hsize_t) :: dims(2)
      integer :: hdferr
      real(dp), allocatable :: contiguous_values(:, :)

      dims = int(shape(values), hsize_t)
      call create_dataset(self, path, h5kind_to_type(dp, H5_REAL_KIND), 2, dims, &
         dataset_id, stat, errmsg)
      if (stat /= 0) return
      hdferr = 0
      if (size(values) > 0) then
         ! h5dwrite_f takes an explicit-shape buffer: copy an array section ourselves rather
         ! than leave it to a compiler temporary (reported at run time by -fcheck=array-temps).
         if (is_contiguous(values)) then
            call h5dwrite_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, dims, hdferr)
         else
            allocate (contiguous_values(size(values, 1), size(values, 2)))
            contiguous_values(:, :) = values
            call h5dwrite_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), contiguous_values, &
               dims, hdferr)
         end if
      end if
      call finish_dataset(self, path, dataset_id, hdferr, unit, stat, errmsg)
   end subroutine writer_write_real_2d

   !> Write the 1-d integer dataset `path` (default integer kind).
   subroutine writer_write_int_1d(self, path, values, stat, errmsg)
      class(h5_writer), intent(inout) :: self  !! open writer
      character(len=*), intent(in) :: path     !! dataset path
      integer, intent(in) :: values(:)         !! data, may be empty
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      integer(hid_t) :: dataset_id
      integer(hsize_t) :: dims(1)
      integer :: hdferr
      integer, allocatable :: contiguous_values(:)

      dims = int(shape(values), hsize_t)
      call create_dataset(self, path, h5kind_to_type(kind(values), H5_INTEGER_KIND), 1, &
         dims, dataset_id, stat, errmsg)
      if (stat /= 0) return
      hdferr = 0
      if (size(values) > 0) then
         if (is_contiguous(values)) then
            call h5dwrite_f(dataset_id, h5kind_to_type(kind(values), H5_INTEGER_KIND), values, &
               dims, hdferr)
         else
            allocate (contiguous_values(size(values)))
            contiguous_values(:) = values
            call h5dwrite_f(dataset_id, h5kind_to_type(kind(values), H5_INTEGER_KIND), &
               contiguous_values, dims, hdferr)
         end if
      end if
      call finish_dataset(self, path, dataset_id, hdferr, stat=stat, errmsg=errmsg)
   end subroutine writer_write_int_1d

   !> Write the scalar (rank-0) real dataset `path`, with an optional string attribute
   !! 'unit'. Pass `stat`/`errmsg` by keyword when `unit` is omitted.
   subroutine writer_write_real_scalar(self, path, value, unit, stat, errmsg)
      class(h5_writer), intent(inout) :: self         !! open writer
      character(len=*), intent(in) :: path            !! dataset path
      real(dp), intent(in) :: value                   !! the value
      character(len=*), intent(in), optional :: unit  !! physical unit
      integer, intent(out) :: stat                    !! 0 on success
      character(len=*), intent(out) :: errmsg         !! reason of the failure, blank on success
      integer(hid_t) :: dataset_id
      integer(hsize_t) :: dims(0)
      integer :: hdferr

      call create_dataset(self, path, h5kind_to_type(dp, H5_REAL_KIND), 0, dims, &
         dataset_id, stat, errmsg)
      if (stat /= 0) return
      call h5dwrite_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), value, [1_hsize_t], hdferr)
      call finish_dataset(self, path, dataset_id, hdferr, unit, stat, errmsg)
   end subroutine writer_write_real_scalar

   !> Set the real attribute `name` of the object `object_path` ('/' for the file's root
   !! group, or a group or dataset path). A missing object is created as a group; an
   !! existing attribute of that name is replaced.
   subroutine writer_attr_real(self, object_path, name, value, stat, errmsg)
      class(h5_writer), intent(inout) :: self       !! open writer
      character(len=*), intent(in) :: object_path   !! '/', a group or a dataset
      character(len=*), intent(in) :: name          !! attribute name
      real(dp), intent(in) :: value                 !! attribute value
      integer, intent(out) :: stat                  !! 0 on success
      character(len=*), intent(out) :: errmsg       !! reason of the failure, blank on success
      integer(hid_t) :: object_id
      character(len=:), allocatable :: failed_step
      integer :: close_error

      call open_or_create_object(self, object_path, object_id, stat, errmsg)
      if (stat /= 0) return
      call put_real_attribute(object_id, name, value, failed_step)
      call h5oclose_f(object_id, close_error)
      call attribute_outcome(self%temporary_name, object_path, name, failed_step, stat, errmsg)
   end subroutine writer_attr_real

   !> Set the integer attribute `name` of the object `object_path` (see `attr_real`).
   subroutine writer_attr_int(self, object_path, name, value, stat, errmsg)
      class(h5_writer), intent(inout) :: self       !! open writer
      character(len=*), intent(in) :: object_path   !! '/', a group or a dataset
      character(len=*), intent(in) :: name          !! attribute name
      integer, intent(in) :: value                  !! attribute value
      integer, intent(out) :: stat                  !! 0 on success
      character(len=*), intent(out) :: errmsg       !! reason of the failure, blank on success
      integer(hid_t) :: object_id
      character(len=:), allocatable :: failed_step
      integer :: close_error

      call open_or_create_object(self, object_path, object_id, stat, errmsg)
      if (stat /= 0) return
      call put_int_attribute(object_id, name, value, failed_step)
      call h5oclose_f(object_id, close_error)
      call attribute_outcome(self%temporary_name, object_path, name, failed_step, stat, errmsg)
   end subroutine writer_attr_int

   !> Set the fixed-length string attribute `name` of the object `object_path` (see
   !! `attr_real`). The stored length is `len(value)` (trailing blanks are kept; pass
   !! `trim(value)` to drop them).
   subroutine writer_attr_string(self, object_path, name, value, stat, errmsg)
      class(h5_writer), intent(inout) :: self       !! open writer
      character(len=*), intent(in) :: object_path   !! '/', a group or a dataset
      character(len=*), intent(in) :: name          !! attribute name
      character(len=*), intent(in) :: value         !! attribute value, may be ''
      integer, intent(out) :: stat                  !! 0 on success
      character(len=*), intent(out) :: errmsg       !! reason of the failure, blank on success
      integer(hid_t) :: object_id
      character(len=:), allocatable :: failed_step
      integer :: close_error

      call open_or_create_object(self, object_path, object_id, stat, errmsg)
      if (stat /= 0) return
      call put_string_attribute(object_id, name, value, failed_step)
      call h5oclose_f(object_id, close_error)
      call attribute_outcome(self%temporary_name, object_path, name, failed_step, stat, errmsg)
   end subroutine writer_attr_string

   !> Flush and close the temporary file, then rename it onto the final name. On failure
   !! the temporary file may remain: call `discard` to delete it.
   subroutine writer_commit(self, stat, errmsg)
      class(h5_writer), intent(inout) :: self  !! open writer; closed on return
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      integer :: flush_error, close_error
      character(len=buffer_length) :: fs_message

      stat = 0
      errmsg = ''
      if (.not. self%is_open) then
         call fail(stat, errmsg, 'cannot commit: HDF5 writer has no open file')
         return
      end if
      call h5fflush_f(self%file_id, H5F_SCOPE_GLOBAL_F, flush_error)
      call close_property_list(self%link_creation_list)
      call h5fclose_f(self%file_id, close_error)
      self%file_id = no_id
      self%is_open = .false.
      if (flush_error < 0 .or. close_error < 0) then
         call fail(stat, errmsg, 'cannot flush and close HDF5 file ''' // &
            self%temporary_name // '''; ''' // self%final_name // ''' was not written')
         return
      end if
      call rename_file(self%temporary_name, self%final_name, stat, fs_message)
      if (stat /= 0) then
         call fail(stat, errmsg, 'cannot commit HDF5 file ''' // self%final_name // ''': ' // &
            trim(fs_message))
         return
      end if
      ! Nothing is left to discard: forget the names.
      deallocate (self%final_name, self%temporary_name)
   end subroutine writer_commit

   !> Close the temporary file (if open) and delete it. The final name is never touched.
   !! Never fails loudly: errors are ignored; a no-op on a writer with nothing to discard.
   subroutine writer_discard(self)
      class(h5_writer), intent(inout) :: self  !! writer; closed on return
      integer :: hdferr
      character(len=buffer_length) :: fs_message

      if (self%is_open) then
         call close_property_list(self%link_creation_list)
         call h5fclose_f(self%file_id, hdferr)
      end if
      self%file_id = no_id
      self%is_open = .false.
      if (allocated(self%temporary_name)) then
         call remove_file(self%temporary_name, hdferr, fs_message)
      end if
      if (allocated(self%final_name)) deallocate (self%final_name)
      if (allocated(self%temporary_name)) deallocate (self%temporary_name)
   end subroutine writer_discard

   ! =================================================================================
   ! readers

   !> Read the 1-d numeric dataset `path` of `filename` into `values` (converted to real).
   subroutine read_real_1d(filename, path, values, stat, errmsg)
      character(len=*), intent(in) :: filename          !! HDF5 file
      character(len=*), intent(in) :: path              !! dataset path
      real(dp), allocatable, intent(out) :: values(:)   !! the data
      integer, intent(out) :: stat                      !! 0 on success
      character(len=*), intent(out) :: errmsg           !! reason of the failure, blank on success
      integer(hid_t) :: file_id, dataset_id
      integer(hsize_t) :: dims(1)
      integer :: hdferr

      call open_dataset_for_reading(filename, path, 1, file_id, dataset_id, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (values(dims(1)))
      hdferr = 0
      if (size(values) > 0) then
         call h5dread_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, dims, hdferr)
      end if
      call close_after_reading(filename, path, file_id, dataset_id, hdferr, stat, errmsg)
   end subroutine read_real_1d

   !> Read the 2-d numeric dataset `path` of `filename`: a dataset of shape (n2, n1) as
   !! h5py sees it is returned as `values(n1, n2)`, the inverse of `write_real_2d`.
   subroutine read_real_2d(filename, path, values, stat, errmsg)
      character(len=*), intent(in) :: filename             !! HDF5 file
      character(len=*), intent(in) :: path                 !! dataset path
      real(dp), allocatable, intent(out) :: values(:, :)   !! the data (n1, n2)
      integer, intent(out) :: stat                         !! 0 on success
      character(len=*), intent(out) :: errmsg              !! reason of the failure, blank on success
      integer(hid_t) :: file_id, dataset_id
      integer(hsize_t) :: dims(2)
      integer :: hdferr

      call open_dataset_for_reading(filename, path, 2, file_id, dataset_id, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (values(dims(1), dims(2)))
      hdferr = 0
      if (size(values) > 0) then
         call h5dread_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, dims, hdferr)
      end if
      call close_after_reading(filename, path, file_id, dataset_id, hdferr, stat, errmsg)
   end subroutine read_real_2d

   !> Read the 1-d integer dataset `path` of `filename` (default integer kind).
   subroutine read_int_1d(filename, path, values, stat, errmsg)
      character(len=*), intent(in) :: filename         !! HDF5 file
      character(len=*), intent(in) :: path             !! dataset path
      integer, allocatable, intent(out) :: values(:)   !! the data
      integer, intent(out) :: stat                     !! 0 on success
      character(len=*), intent(out) :: errmsg          !! reason of the failure, blank on success
      integer(hid_t) :: file_id, dataset_id
      integer(hsize_t) :: dims(1)
      integer :: hdferr

      call open_dataset_for_reading(filename, path, 1, file_id, dataset_id, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (values(dims(1)))
      hdferr = 0
      if (size(values) > 0) then
         call h5dread_f(dataset_id, h5kind_to_type(kind(values), H5_INTEGER_KIND), values, &
            dims, hdferr)
      end if
      call close_after_reading(filename, path, file_id, dataset_id, hdferr, stat, errmsg)
   end subroutine read_int_1d

   !> Read the scalar (rank-0) numeric dataset `path` of `filename`.
   subroutine read_real_scalar(filename, path, value, stat, errmsg)
      character(len=*), intent(in) :: filename  !! HDF5 file
      character(len=*), intent(in) :: path      !! dataset path
      real(dp), intent(out) :: value            !! the value (0 on failure)
      integer, intent(out) :: stat              !! 0 on success
      character(len=*), intent(out) :: errmsg   !! reason of the failure, blank on success
      integer(hid_t) :: file_id, dataset_id
      integer(hsize_t) :: dims(0)
      integer :: hdferr

      value = 0.0_dp
      call open_dataset_for_reading(filename, path, 0, file_id, dataset_id, dims, stat, errmsg)
      if (stat /= 0) return
      call h5dread_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), value, [1_hsize_t], hdferr)
      call close_after_reading(filename, path, file_id, dataset_id, hdferr, stat, errmsg)
   end subroutine read_real_scalar

   !> Read the single-valued numeric attribute `name` of `object_path` ('/', a group or a
   !! dataset) in `filename`.
   subroutine read_attr_real(filename, object_path, name, value, stat, errmsg)
      character(len=*), intent(in) :: filename     !! HDF5 file
      character(len=*), intent(in) :: object_path  !! '/', a group or a dataset
      character(len=*), intent(in) :: name         !! attribute name
      real(dp), intent(out) :: value               !! the value (0 on failure)
      integer, intent(out) :: stat                 !! 0 on success
      character(len=*), intent(out) :: errmsg      !! reason of the failure, blank on success
      integer(hid_t) :: file_id, object_id, attribute_id
      integer :: hdferr

      value = 0.0_dp
      call open_attribute_for_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, stat, errmsg)
      if (stat /= 0) return
      call h5aread_f(attribute_id, h5kind_to_type(dp, H5_REAL_KIND), value, [1_hsize_t], hdferr)
      call close_attribute_after_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, hdferr, stat, errmsg)
   end subroutine read_attr_real

   !> Read the single-valued integer attribute `name` of `object_path` in `filename`.
   subroutine read_attr_int(filename, object_path, name, value, stat, errmsg)
      character(len=*), intent(in) :: filename     !! HDF5 file
      character(len=*), intent(in) :: object_path  !! '/', a group or a dataset
      character(len=*), intent(in) :: name         !! attribute name
      integer, intent(out) :: value                !! the value (0 on failure)
      integer, intent(out) :: stat                 !! 0 on success
      character(len=*), intent(out) :: errmsg      !! reason of the failure, blank on success
      integer(hid_t) :: file_id, object_id, attribute_id
      integer :: hdferr

      value = 0
      call open_attribute_for_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, stat, errmsg)
      if (stat /= 0) return
      call h5aread_f(attribute_id, h5kind_to_type(kind(value), H5_INTEGER_KIND), value, &
         [1_hsize_t], hdferr)
      call close_attribute_after_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, hdferr, stat, errmsg)
   end subroutine read_attr_int

   !> Read the scalar fixed-length string attribute `name` of `object_path` in `filename`.
   !! Trailing NUL padding is removed. Variable-length strings are not supported.
   subroutine read_attr_string(filename, object_path, name, value, stat, errmsg)
      character(len=*), intent(in) :: filename               !! HDF5 file
      character(len=*), intent(in) :: object_path            !! '/', a group or a dataset
      character(len=*), intent(in) :: name                   !! attribute name
      character(len=:), allocatable, intent(out) :: value    !! the string ('' on failure)
      integer, intent(out) :: stat                           !! 0 on success
      character(len=*), intent(out) :: errmsg                !! reason of the failure, blank on success
      integer(hid_t) :: file_id, object_id, attribute_id, file_type, memory_type
      integer(size_t) :: string_length
      integer :: hdferr, type_class, last
      logical :: is_variable
      character(len=:), allocatable :: buffer, problem

      value = ''
      call open_attribute_for_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, stat, errmsg)
      if (stat /= 0) return
      file_type = no_id
      memory_type = no_id
      problem = ''
      read_string: block
         call h5aget_type_f(attribute_id, file_type, hdferr)
         if (hdferr >= 0) call h5tget_class_f(file_type, type_class, hdferr)
         if (hdferr < 0) then
            problem = 'cannot get its datatype'
            exit read_string
         end if
         if (type_class /= H5T_STRING_F) then
            problem = 'it is not a string'
            exit read_string
         end if
         call h5tis_variable_str_f(file_type, is_variable, hdferr)
         if (hdferr >= 0) call h5tget_size_f(file_type, string_length, hdferr)
         if (hdferr < 0) then
            problem = 'cannot get its string length'
            exit read_string
         end if
         if (is_variable) then
            problem = 'it is a variable-length string, which is not supported'
            exit read_string
         end if
         ! Memory type of the same length, NUL-padded: padding arrives as NULs, stripped below.
         call h5tcopy_f(H5T_FORTRAN_S1, memory_type, hdferr)
         if (hdferr >= 0) call h5tset_size_f(memory_type, string_length, hdferr)
         if (hdferr >= 0) call h5tset_strpad_f(memory_type, H5T_STR_NULLPAD_F, hdferr)
         if (hdferr < 0) then
            problem = 'cannot set up the memory string type'
            exit read_string
         end if
         allocate (character(len=string_length) :: buffer)
         call h5aread_f(attribute_id, memory_type, buffer, [1_hsize_t], hdferr)
         if (hdferr < 0) problem = 'H5Aread failed'
      end block read_string
      call close_datatype(memory_type)
      call close_datatype(file_type)
      call close_attribute_after_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, 0, stat, errmsg)
      if (len(problem) > 0) then
         call fail(stat, errmsg, 'cannot read string attribute ''' // trim(name) // ''' of ' &
            // describe(object_path, filename) // ': ' // problem)
         return
      end if
      last = len(buffer)
      do while (last > 0)
         if (buffer(last:last) /= achar(0)) exit
         last = last - 1
      end do
      value = buffer(1:last)
   end subroutine read_attr_string

   !> True when `filename` is an HDF5 file that contains the object `path` ('/' is the
   !! root group). False when the file is missing or unreadable.
   function h5_path_exists(filename, path) result(exists)
      character(len=*), intent(in) :: filename  !! HDF5 file
      character(len=*), intent(in) :: path      !! object path
      logical :: exists                         !! whether the object exists
      integer(hid_t) :: file_id
      integer :: stat
      character(len=buffer_length) :: errmsg

      exists = .false.
      call open_file_for_reading(filename, file_id, stat, errmsg)
      if (stat /= 0) return
      exists = link_exists(file_id, path)
      call h5fclose_f(file_id, stat)
   end function h5_path_exists

   ! =================================================================================
   ! private helpers

   !> Initialise the HDF5 library once per process and switch off its automatic
   !! error-stack printing (failures are reported through stat/errmsg instead).
   subroutine initialize_library(stat, errmsg)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: hdferr

      stat = 0
      errmsg = ''
      if (library_initialized) return
      call h5open_f(hdferr)
      if (hdferr < 0) then
         call fail(stat, errmsg, 'cannot initialise the HDF5 library (h5open_f)')
         return
      end if
      call h5eset_auto_f(0, hdferr)
      if (hdferr < 0) then
         call fail(stat, errmsg, 'cannot switch off HDF5 automatic error printing')
         return
      end if
      library_initialized = .true.
   end subroutine initialize_library

   !> Set stat = 1 and errmsg = message.
   pure subroutine fail(stat, errmsg, message)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), intent(in) :: message
      stat = 1
      errmsg = message
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

   !> Check that the writer is open and `path` is a new dataset path, then create the
   !! dataset (rank 0: scalar) of type `type_id`. On success `dataset_id` is open.
   subroutine create_dataset(self, path, type_id, rank, dims, dataset_id, stat, errmsg)
      class(h5_writer), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(hid_t), intent(in) :: type_id
      integer, intent(in) :: rank
      integer(hsize_t), intent(in) :: dims(:)
      integer(hid_t), intent(out) :: dataset_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: space_id
      integer :: hdferr

      stat = 0
      errmsg = ''
      dataset_id = no_id
      if (.not. self%is_open) then
         call fail(stat, errmsg, 'cannot write dataset ''' // trim(path) // &
            ''': HDF5 writer has no open file')
         return
      end if
      if (.not. valid_path(path, root_allowed=.false.)) then
         call fail(stat, errmsg, 'invalid dataset path ''' // trim(path) // ''' for HDF5 file ''' &
            // self%temporary_name // '''')
         return
      end if
      if (link_exists(self%file_id, path)) then
         call fail(stat, errmsg, 'cannot write dataset ' // describe(path, self%temporary_name) &
            // ': the path already exists')
         return
      end if
      if (rank == 0) then
         call h5screate_f(H5S_SCALAR_F, space_id, hdferr)
      else
         call h5screate_simple_f(rank, dims, space_id, hdferr)
      end if
      if (hdferr < 0) then
         call fail(stat, errmsg, 'cannot create the dataspace of dataset ' // &
            describe(path, self%temporary_name))
         return
      end if
      call h5dcreate_f(self%file_id, trim(path), type_id, space_id, dataset_id, hdferr, &
         lcpl_id=self%link_creation_list)
      call close_dataspace(space_id)
      if (hdferr < 0) then
         dataset_id = no_id
         call fail(stat, errmsg, 'cannot create dataset ' // describe(path, self%temporary_name) &
            // ' (is a parent a dataset?)')
      end if
   end subroutine create_dataset

   !> After the h5dwrite_f of a new dataset (its error code `write_error`): add the
   !! optional 'unit' attribute, close the dataset and set stat/errmsg.
   subroutine finish_dataset(self, path, dataset_id, write_error, unit, stat, errmsg)
      class(h5_writer), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(hid_t), intent(in) :: dataset_id
      integer, intent(in) :: write_error
      character(len=*), intent(in), optional :: unit
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: failed_step
      integer :: close_error

      stat = 0
      errmsg = ''
      failed_step = ''
      if (present(unit) .and. write_error >= 0) then
         call put_string_attribute(dataset_id, 'unit', unit, failed_step)
      end if
      call h5dclose_f(dataset_id, close_error)
      if (write_error < 0) then
         call fail(stat, errmsg, 'cannot write the values of dataset ' // &
            describe(path, self%temporary_name))
      else if (len(failed_step) > 0) then
         call fail(stat, errmsg, 'cannot write attribute ''unit'' of dataset ' // &
            describe(path, self%temporary_name) // ' (' // failed_step // ')')
      else if (close_error < 0) then
         call fail(stat, errmsg, 'cannot close dataset ' // describe(path, self%temporary_name))
      end if
   end subroutine finish_dataset

   !> Open the object `object_path` of the writer's file, creating it (and its parents)
   !! as a group when missing.
   subroutine open_or_create_object(self, object_path, object_id, stat, errmsg)
      class(h5_writer), intent(in) :: self
      character(len=*), intent(in) :: object_path
      integer(hid_t), intent(out) :: object_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: group_id
      integer :: hdferr

      stat = 0
      errmsg = ''
      object_id = no_id
      if (.not. self%is_open) then
         call fail(stat, errmsg, 'cannot write an attribute of ''' // trim(object_path) // &
            ''': HDF5 writer has no open file')
         return
      end if
      if (.not. valid_path(object_path, root_allowed=.true.)) then
         call fail(stat, errmsg, 'invalid object path ''' // trim(object_path) // &
            ''' for HDF5 file ''' // self%temporary_name // '''')
         return
      end if
      if (.not. link_exists(self%file_id, object_path)) then
         call h5gcreate_f(self%file_id, trim(object_path), group_id, hdferr, &
            lcpl_id=self%link_creation_list)
         if (hdferr < 0) then
            call fail(stat, errmsg, 'cannot create group ' // &
               describe(object_path, self%temporary_name) // ' (is a parent a dataset?)')
            return
         end if
         call h5gclose_f(group_id, hdferr)
      end if
      call h5oopen_f(self%file_id, trim(object_path), object_id, hdferr)
      if (hdferr < 0) then
         object_id = no_id
         call fail(stat, errmsg, 'cannot open object ' // describe(object_path, self%temporary_name))
      end if
   end subroutine open_or_create_object

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

   !> Write the real attribute `name` = `value` on the open object `object_id`.
   subroutine put_real_attribute(object_id, name, value, failed_step)
      integer(hid_t), intent(in) :: object_id
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: value
      character(len=:), allocatable, intent(out) :: failed_step
      integer(hid_t) :: attribute_id
      integer :: hdferr

      call new_scalar_attribute(object_id, name, h5kind_to_type(dp, H5_REAL_KIND), &
         attribute_id, failed_step)
      if (len(failed_step) > 0) return
      call h5awrite_f(attribute_id, h5kind_to_type(dp, H5_REAL_KIND), value, [1_hsize_t], hdferr)
      if (hdferr < 0) failed_step = 'H5Awrite'
      call h5aclose_f(attribute_id, hdferr)
   end subroutine put_real_attribute

   !> Write the integer attribute `name` = `value` on the open object `object_id`.
   subroutine put_int_attribute(object_id, name, value, failed_step)
      integer(hid_t), intent(in) :: object_id
      character(len=*), intent(in) :: name
      integer, intent(in) :: value
      character(len=:), allocatable, intent(out) :: failed_step
      integer(hid_t) :: attribute_id
      integer :: hdferr

      call new_scalar_attribute(object_id, name, h5kind_to_type(kind(value), H5_INTEGER_KIND), &
         attribute_id, failed_step)
      if (len(failed_step) > 0) return
      call h5awrite_f(attribute_id, h5kind_to_type(kind(value), H5_INTEGER_KIND), value, &
         [1_hsize_t], hdferr)
      if (hdferr < 0) failed_step = 'H5Awrite'
      call h5aclose_f(attribute_id, hdferr)
   end subroutine put_int_attribute

   !> Write the fixed-length, NUL-padded string attribute `name` = `value` on the open
   !! object `object_id`. HDF5 string types need a size of at least 1, so '' is stored as
   !! one NUL byte (read back as '').
   subroutine put_string_attribute(object_id, name, value, failed_step)
      integer(hid_t), intent(in) :: object_id
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: value
      character(len=:), allocatable, intent(out) :: failed_step
      integer(hid_t) :: attribute_id, string_type
      character(len=:), allocatable :: buffer
      integer :: hdferr

      if (len(value) > 0) then
         buffer = value
      else
         buffer = achar(0)
      end if
      call h5tcopy_f(H5T_FORTRAN_S1, string_type, hdferr)
      if (hdferr < 0) then
         failed_step = 'H5Tcopy'
         return
      end if
      call h5tset_size_f(string_type, int(len(buffer), size_t), hdferr)
      if (hdferr >= 0) call h5tset_strpad_f(string_type, H5T_STR_NULLPAD_F, hdferr)
      if (hdferr < 0) then
         call close_datatype(string_type)
         failed_step = 'H5Tset_size/H5Tset_strpad'
         return
      end if
      call new_scalar_attribute(object_id, name, string_type, attribute_id, failed_step)
      if (len(failed_step) == 0) then
         call h5awrite_f(attribute_id, string_type, buffer, [1_hsize_t], hdferr)
         if (hdferr < 0) failed_step = 'H5Awrite'
         call h5aclose_f(attribute_id, hdferr)
      end if
      call close_datatype(string_type)
   end subroutine put_string_attribute

   !> Open `filename` read-only (initialising HDF5 if needed).
   subroutine open_file_for_reading(filename, file_id, stat, errmsg)
      character(len=*), intent(in) :: filename
      integer(hid_t), intent(out) :: file_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: hdferr

      file_id = no_id
      call initialize_library(stat, errmsg)
      if (stat /= 0) return
      if (.not. file_exists(filename)) then
         call fail(stat, errmsg, 'HDF5 file ''' // trim(filename) // ''' does not exist')
         return
      end if
      call h5fopen_f(trim(filename), H5F_ACC_RDONLY_F, file_id, hdferr)
      if (hdferr < 0) then
         file_id = no_id
         call fail(stat, errmsg, 'cannot open ''' // trim(filename) // ''' as an HDF5 file')
      end if
   end subroutine open_file_for_reading

   !> Open `filename` read-only and its dataset `path`, check that the dataset has rank
   !! `rank` and return its (Fortran-order) dimensions. On failure nothing is left open.
   subroutine open_dataset_for_reading(filename, path, rank, file_id, dataset_id, dims, &
         stat, errmsg)
      character(len=*), intent(in) :: filename, path
      integer, intent(in) :: rank
      integer(hid_t), intent(out) :: file_id, dataset_id
      integer(hsize_t), intent(out) :: dims(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: space_id
      integer(hsize_t) :: max_dims(max(rank, 1))
      integer :: hdferr, file_rank, close_error

      dataset_id = no_id
      dims = 0
      call open_file_for_reading(filename, file_id, stat, errmsg)
      if (stat /= 0) return
      if (.not. link_exists(file_id, path)) then
         call h5fclose_f(file_id, close_error)
         call fail(stat, errmsg, 'no dataset ' // describe(path, filename))
         return
      end if
      call h5dopen_f(file_id, trim(path), dataset_id, hdferr)
      if (hdferr < 0) then
         call h5fclose_f(file_id, close_error)
         call fail(stat, errmsg, 'cannot open dataset ' // describe(path, filename) // &
            ' (not a dataset?)')
         return
      end if
      space_id = no_id
      file_rank = -1
      call h5dget_space_f(dataset_id, space_id, hdferr)
      if (hdferr >= 0) call h5sget_simple_extent_ndims_f(space_id, file_rank, hdferr)
      if (hdferr >= 0 .and. file_rank == rank .and. rank > 0) then
         ! Returns the rank on success, -1 on failure.
         call h5sget_simple_extent_dims_f(space_id, dims, max_dims, hdferr)
      end if
      call close_dataspace(space_id)
      if (hdferr < 0 .or. file_rank /= rank) then
         call h5dclose_f(dataset_id, close_error)
         call h5fclose_f(file_id, close_error)
         dataset_id = no_id
         file_id = no_id
         if (hdferr < 0) then
            call fail(stat, errmsg, 'cannot read the dataspace of dataset ' // &
               describe(path, filename))
         else
            call fail(stat, errmsg, 'dataset ' // describe(path, filename) // ' has rank ' // &
               integer_text(file_rank) // ', expected ' // integer_text(rank))
         end if
      end if
   end subroutine open_dataset_for_reading

   !> Close what open_dataset_for_reading opened and report a read error (`read_error`,
   !! the h5dread_f error code) through stat/errmsg.
   subroutine close_after_reading(filename, path, file_id, dataset_id, read_error, stat, errmsg)
      character(len=*), intent(in) :: filename, path
      integer(hid_t), intent(in) :: file_id, dataset_id
      integer, intent(in) :: read_error
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: close_error

      stat = 0
      errmsg = ''
      call h5dclose_f(dataset_id, close_error)
      call h5fclose_f(file_id, close_error)
      if (read_error < 0) then
         call fail(stat, errmsg, 'cannot read dataset ' // describe(path, filename) // &
            ' (type not convertible?)')
      end if
   end subroutine close_after_reading

   !> Open `filename` read-only, its object `object_path` and the attribute `name` of
   !! it, which must hold a single value. On failure nothing is left open.
   subroutine open_attribute_for_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, stat, errmsg)
      character(len=*), intent(in) :: filename, object_path, name
      integer(hid_t), intent(out) :: file_id, object_id, attribute_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: space_id
      integer(hsize_t) :: value_count
      logical :: exists
      integer :: hdferr, close_error

      object_id = no_id
      attribute_id = no_id
      call open_file_for_reading(filename, file_id, stat, errmsg)
      if (stat /= 0) return
      if (.not. link_exists(file_id, object_path)) then
         call h5fclose_f(file_id, close_error)
         call fail(stat, errmsg, 'no object ' // describe(object_path, filename))
         return
      end if
      call h5oopen_f(file_id, trim(object_path), object_id, hdferr)
      if (hdferr < 0) then
         call h5fclose_f(file_id, close_error)
         call fail(stat, errmsg, 'cannot open object ' // describe(object_path, filename))
         return
      end if
      exists = .false.
      if (len_trim(name) > 0) call h5aexists_f(object_id, trim(name), exists, hdferr)
      if (.not. exists .or. hdferr < 0) then
         call h5oclose_f(object_id, close_error)
         call h5fclose_f(file_id, close_error)
         call fail(stat, errmsg, 'no attribute ''' // trim(name) // ''' on ' // &
            describe(object_path, filename))
         return
      end if
      call h5aopen_f(object_id, trim(name), attribute_id, hdferr)
      value_count = 0
      space_id = no_id
      if (hdferr >= 0) call h5aget_space_f(attribute_id, space_id, hdferr)
      if (hdferr >= 0) call h5sget_simple_extent_npoints_f(space_id, value_count, hdferr)
      call close_dataspace(space_id)
      if (hdferr < 0 .or. value_count /= 1) then
         if (attribute_id /= no_id) call h5aclose_f(attribute_id, close_error)
         call h5oclose_f(object_id, close_error)
         call h5fclose_f(file_id, close_error)
         if (hdferr < 0) then
            call fail(stat, errmsg, 'cannot open attribute ''' // trim(name) // ''' of ' // &
               describe(object_path, filename))
         else
            call fail(stat, errmsg, 'attribute ''' // trim(name) // ''' of ' // &
               describe(object_path, filename) // ' holds ' // &
               integer_text(int(value_count)) // ' values, expected 1')
         end if
         attribute_id = no_id
         object_id = no_id
         file_id = no_id
      end if
   end subroutine open_attribute_for_reading

   !> Close what open_attribute_for_reading opened and report a read error (`read_error`,
   !! the h5aread_f error code) through stat/errmsg.
   subroutine close_attribute_after_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, read_error, stat, errmsg)
      character(len=*), intent(in) :: filename, object_path, name
      integer(hid_t), intent(in) :: file_id, object_id, attribute_id
      integer, intent(in) :: read_error
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: close_error

      stat = 0
      errmsg = ''
      call h5aclose_f(attribute_id, close_error)
      call h5oclose_f(object_id, close_error)
      call h5fclose_f(file_id, close_error)
      if (read_error < 0) then
         call fail(stat, errmsg, 'cannot read attribute ''' // trim(name) // ''' of ' // &
            describe(object_path, filename) // ' (type not convertible?)')
      end if
   end subroutine close_attribute_after_reading

   !> Close a dataspace identifier if it is open.
   subroutine close_dataspace(space_id)
      integer(hid_t), intent(inout) :: space_id
      integer :: hdferr
      if (space_id /= no_id) call h5sclose_f(space_id, hdferr)
      space_id = no_id
   end subroutine close_dataspace

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


end module vibrobeam_hdf5
