!> A thin object layer over the HDF5 Fortran API: crash-safe, atomic writing of vibrobeam
!! result files (docs/output.md, "How a result is published"). Readers are in
!! `vibrobeam_hdf5_reader` and `vibrobeam_hdf5_file_reads`; extendible datasets that grow
!! during a run in `vibrobeam_hdf5_series`; the checks and steps of creating one object
!! in `vibrobeam_hdf5_objects`.
!!
!! `h5_writer` writes into a temporary file `<final>.<pid>-<token>.tmp` in the final
!! file's directory (`vibrobeam_filesystem: unique_temporary_name`); only `commit` (or a
!! caller that `finish`es the file and renames it itself, src/analysis/vibrobeam_result_files.f90)
!! publishes it under `<final>`, so a result file under its final name is always complete;
!! `discard` deletes the temporary file and leaves `<final>` untouched.
!!
!! Crash safety of the temporary file. The file is created in the HDF5 1.10 format
!! (libver bounds 'latest') with a metadata cache that never evicts (src/io/hdf5/vibrobeam_hdf5_swmr.c:
!! `vb_h5_disable_evictions`), so HDF5 writes metadata only when the file is flushed.
!! After every object is created, `start_swmr` puts the file in SWMR write mode, in which
!! HDF5 orders the metadata writes of a flush so that a reader always finds a consistent
!! file. A process killed at any moment thus leaves a temporary file that opens (as a SWMR
!! reader, or after `h5clear -s`) and holds every dataset as of a flush. In SWMR mode no
!! object or attribute can be created; existing attributes can be rewritten in place
!! (`rewrite_attr`).
!!
!! Conventions
!! - Paths are absolute HDF5 paths ('/modes/frequency'); a leading '/' may be omitted.
!!   Missing intermediate groups are created. Writing a dataset whose path already exists
!!   is an error; writing an attribute that already exists replaces it.
!! - Reals are stored as the native double type (IEEE binary64), integers as the native
!!   type of their Fortran kind; the round trip is bit-exact.
!! - Dimension order: HDF5's Fortran API reverses dimensions with respect to C, so a
!!   Fortran array `values(n1, n2)` is a dataset that h5py/h5dump/C see with shape
!!   `(n2, n1)`, and `values(i, j)` is `dataset[j-1, i-1]` in h5py. Storing one snapshot
!!   per column, `field(nodes, times)`, thus gives the (times x nodes) dataset of
!!   docs/output.md. `read_real_2d` applies the inverse map and returns `values(n1, n2)`.
!! - String attributes are scalar, fixed-length (length = len(value), at least 1),
!!   ASCII, NUL-padded (as h5py stores NumPy 'S' strings); h5py returns them as
!!   `bytes`. An empty string is stored as one NUL byte and reads back as ''. With a
!!   `capacity` they are NUL-terminated strings of that many bytes instead.
!! - Zero-size arrays give datasets with a zero dimension (nothing is written to them).
!!
!! Errors: every procedure returns `stat` (0 = success, 1 = failure) and an `errmsg` naming
!! the file, the HDF5 path, the operation that failed and the reason HDF5 gives (the errno
!! text for a failed write: 'No space left on device'); nothing stops or prints.
module vibrobeam_hdf5
   use, intrinsic :: iso_c_binding, only: c_int, c_int64_t
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_filesystem, only: make_parent_directories, rename_file, remove_file, &
      unique_temporary_name, sync_file, sync_directory_of
   use vibrobeam_hdf5_base, only: no_id, buffer_length, initialize_library, fail, attribute_outcome, &
      put_scalar_attribute, put_string_attribute, rewrite_attribute, close_property_list
   use vibrobeam_hdf5_objects, only: create_dataset, finish_dataset, open_or_create_object, open_existing_object
   use hdf5, only: hid_t, hsize_t, size_t, h5kind_to_type, H5_REAL_KIND, H5_INTEGER_KIND, h5fcreate_f, h5fclose_f, &
      h5fflush_f, H5F_ACC_TRUNC_F, H5F_SCOPE_GLOBAL_F, H5F_CLOSE_STRONG_F, H5F_LIBVER_LATEST_F, h5pcreate_f, &
      h5pset_fclose_degree_f, h5pset_create_inter_group_f, h5pset_libver_bounds_f, h5pset_cache_f, &
      h5pset_sieve_buf_size_f, H5P_FILE_ACCESS_F, H5P_LINK_CREATE_F, h5oclose_f, h5dwrite_f
   implicit none
   private
   public :: h5_writer

   interface
      !> int vb_h5_disable_evictions(hid_t fapl);  (src/io/hdf5/vibrobeam_hdf5_swmr.c)
      function c_h5_disable_evictions(file_access_list) result(error) bind(C, name='vb_h5_disable_evictions')
         import :: c_int, c_int64_t
         integer(c_int64_t), value, intent(in) :: file_access_list
         integer(c_int) :: error
      end function c_h5_disable_evictions

      !> int vb_h5_start_swmr_write(hid_t file);
      function c_h5_start_swmr_write(file_id) result(error) bind(C, name='vb_h5_start_swmr_write')
         import :: c_int, c_int64_t
         integer(c_int64_t), value, intent(in) :: file_id
         integer(c_int) :: error
      end function c_h5_start_swmr_write
   end interface

   !> Writer of one HDF5 result file, written under a temporary name and published by
   !! `commit` (or by the caller after `finish`).
   !!
   !! Life cycle: `create` -> `write_*` / `attr_*` (any number) -> [`start_swmr` -> `flush`
   !! (any number)] -> `commit`, or `finish` and a rename by the caller, or `discard`.
   !! A writer that is neither committed nor discarded leaves its temporary file behind.
   !! After `commit` or `discard` the same object may `create` another file.
   type :: h5_writer
      private
      integer(hid_t) :: file_id = no_id              !! open temporary file
      integer(hid_t) :: link_creation_list = no_id   !! creates missing intermediate groups
      character(len=:), allocatable :: final_name    !! name after commit
      character(len=:), allocatable :: temporary_name  !! name while writing
      logical :: is_open = .false.                   !! between create and finish/discard
      logical :: swmr = .false.                      !! in SWMR write mode
   contains
      procedure :: create => writer_create
      procedure :: start_swmr => writer_start_swmr
      procedure :: flush => writer_flush
      procedure :: finish => writer_finish
      procedure :: commit => writer_commit
      procedure :: discard => writer_discard
      procedure :: id => writer_id
      procedure :: link_properties => writer_link_properties
      procedure :: temporary_file => writer_temporary_file
      procedure :: final_file => writer_final_file
      procedure :: write_real_1d => writer_write_real_1d
      procedure :: write_real_2d => writer_write_real_2d
      procedure :: write_int_1d => writer_write_int_1d
      procedure :: write_real_scalar => writer_write_real_scalar
      procedure :: attr_real => writer_attr_real
      procedure :: attr_int => writer_attr_int
      procedure :: attr_int64 => writer_attr_int64
      procedure :: attr_string => writer_attr_string
      procedure :: rewrite_attr => writer_rewrite_attr
   end type h5_writer

contains

   ! =================================================================================
   ! h5_writer

   !> Start a new result file: initialise HDF5 (once), create the parent directories of
   !! `final_name` and create a fresh temporary file beside it (module documentation).
   !! `final_name` itself is not touched until `commit`. With `unbuffered`, HDF5 keeps no
   !! sieve buffer: a write of raw data into a contiguous dataset reaches the file (the
   !! operating system) when the call returns, in the order of the calls (a sweep's
   !! journal marks a point done only after its data, `vibrobeam_sweep_journal`).
   subroutine writer_create(self, final_name, stat, errmsg, unbuffered)
      class(h5_writer), intent(inout) :: self      !! writer, not currently open
      character(len=*), intent(in) :: final_name   !! name of the complete file
      integer, intent(out) :: stat                 !! 0 on success
      character(len=*), intent(out) :: errmsg      !! reason of the failure, blank on success
      logical, intent(in), optional :: unbuffered  !! no sieve buffer (default: HDF5's 64 KiB)
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
         stat = stat_failure
         errmsg = 'cannot create HDF5 file ''' // trim(final_name) // ''': ' // trim(fs_message)
         return
      end if
      self%final_name = trim(final_name)
      self%temporary_name = unique_temporary_name(final_name)
      self%swmr = .false.

      ! Strong close degree: h5fclose_f closes every object still open in the file, so the
      ! file is complete on disk before it is published, even after an error path. The
      ! 1.10 format (SWMR) and a metadata cache without evictions: module documentation.
      call h5pcreate_f(H5P_FILE_ACCESS_F, file_access_list, hdferr)
      if (hdferr >= 0) call h5pset_fclose_degree_f(file_access_list, H5F_CLOSE_STRONG_F, hdferr)
      if (hdferr >= 0) call h5pset_libver_bounds_f(file_access_list, H5F_LIBVER_LATEST_F, &
                                                   H5F_LIBVER_LATEST_F, hdferr)
      if (hdferr >= 0) then
         if (c_h5_disable_evictions(int(file_access_list, c_int64_t)) /= 0) hdferr = -1
      end if
      ! No raw-data chunk cache: series write whole chunks from their own buffers, memory
      ! must not grow with the datasets' cached chunks (1 MiB each by default), and a
      ! failed write (full disk) must fail the call that makes it. (In SWMR mode HDF5
      ! 1.10 takes the file's setting, not a dataset access list's.)
      if (hdferr >= 0) call h5pset_cache_f(file_access_list, 0, 0_size_t, 0_size_t, 1.0, hdferr)
      if (hdferr >= 0 .and. present(unbuffered)) then
         if (unbuffered) call h5pset_sieve_buf_size_f(file_access_list, 0_size_t, hdferr)
      end if
      if (hdferr >= 0) then
         call h5fcreate_f(self%temporary_name, H5F_ACC_TRUNC_F, self%file_id, hdferr, &
            access_prp=file_access_list)
      end if
      if (hdferr < 0) then
         self%file_id = no_id
         call fail(stat, errmsg, 'cannot create HDF5 file ''' // self%temporary_name // '''')
         call close_property_list(file_access_list)
         call remove_file(self%temporary_name, hdferr, fs_message)
         return
      end if
      call close_property_list(file_access_list)

      call h5pcreate_f(H5P_LINK_CREATE_F, self%link_creation_list, hdferr)
      if (hdferr >= 0) call h5pset_create_inter_group_f(self%link_creation_list, 1, hdferr)
      if (hdferr < 0) then
         call fail(stat, errmsg, 'cannot set up link creation properties for ''' // &
            self%temporary_name // '''')
         call close_property_list(self%link_creation_list)
         call remove_file(self%temporary_name, hdferr, fs_message)
         call h5fclose_f(self%file_id, hdferr)
         self%file_id = no_id
         return
      end if
      self%is_open = .true.
   end subroutine writer_create

   !> Switch the file to SWMR write mode (module documentation): from now on no object
   !! or attribute can be created, and every flush leaves a consistent file on disk.
   subroutine writer_start_swmr(self, stat, errmsg)
      class(h5_writer), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (.not. self%is_open) then
         call fail(stat, errmsg, 'cannot start SWMR mode: HDF5 writer has no open file')
         return
      end if
      if (c_h5_start_swmr_write(int(self%file_id, c_int64_t)) /= 0) then
         call fail(stat, errmsg, 'cannot switch HDF5 file ''' // self%temporary_file() // &
            ''' to SWMR write mode')
         return
      end if
      self%swmr = .true.
   end subroutine writer_start_swmr

   !> Write every buffered change to the temporary file (H5Fflush).
   subroutine writer_flush(self, stat, errmsg)
      class(h5_writer), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: hdferr
      stat = 0
      errmsg = ''
      if (.not. self%is_open) then
         call fail(stat, errmsg, 'cannot flush: HDF5 writer has no open file')
         return
      end if
      call h5fflush_f(self%file_id, H5F_SCOPE_GLOBAL_F, hdferr)
      if (hdferr < 0) call fail(stat, errmsg, 'cannot write HDF5 file ''' // self%temporary_file() // '''')
   end subroutine writer_flush

   !> Identifier of the open file (for `vibrobeam_hdf5_series`).
   pure function writer_id(self) result(file_id)
      class(h5_writer), intent(in) :: self
      integer(hid_t) :: file_id
      file_id = self%file_id
   end function writer_id

   !> Link creation properties that create missing intermediate groups.
   pure function writer_link_properties(self) result(list_id)
      class(h5_writer), intent(in) :: self
      integer(hid_t) :: list_id
      list_id = self%link_creation_list
   end function writer_link_properties

   !> Name of the temporary file ('' when none).
   pure function writer_temporary_file(self) result(name)
      class(h5_writer), intent(in) :: self
      character(len=:), allocatable :: name
      name = ''
      if (allocated(self%temporary_name)) name = self%temporary_name
   end function writer_temporary_file

   !> Name the file gets when published ('' when none).
   pure function writer_final_file(self) result(name)
      class(h5_writer), intent(in) :: self
      character(len=:), allocatable :: name
      name = ''
      if (allocated(self%final_name)) name = self%final_name
   end function writer_final_file

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
      call create_dataset(self%is_open, self%file_id, self%link_creation_list, self%temporary_file(), path, &
         h5kind_to_type(dp, H5_REAL_KIND), 1, dims, dataset_id, stat, errmsg)
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
      call finish_dataset(self%temporary_file(), path, dataset_id, hdferr, unit, stat, errmsg)
   end subroutine writer_write_real_1d

   !> Write the 2-d real dataset `path`. The Fortran array `values(n1, n2)` becomes a
   !! dataset of shape `(n2, n1)` as seen by h5py, h5dump and C (HDF5's Fortran API
   !! reverses the dimensions; memory order is unchanged). Optional string attribute
   !! 'unit'. Pass `stat`/`errmsg` by keyword when `unit` is omitted. With `layers` > 1 the
   !! dataset is 3-d, (n2, n1/layers, layers) as h5py sees it (a beam of two planes' y, z).
   subroutine writer_write_real_2d(self, path, values, unit, stat, errmsg, layers)
      class(h5_writer), intent(inout) :: self         !! open writer
      character(len=*), intent(in) :: path            !! dataset path, e.g. '/modes/shape'
      real(dp), intent(in) :: values(:, :)            !! data (n1, n2), may be empty
      character(len=*), intent(in), optional :: unit  !! physical unit, e.g. 'm'
      integer, intent(out) :: stat                    !! 0 on success
      character(len=*), intent(out) :: errmsg         !! reason of the failure, blank on success
      integer, intent(in), optional :: layers         !! > 1: a 3-d dataset (see above)
      integer(hid_t) :: dataset_id
      integer(hsize_t) :: dims(2), file_dims(3)
      integer :: hdferr, rank
      real(dp), allocatable :: contiguous_values(:, :)

      dims = int(shape(values), hsize_t)
      rank = 2
      file_dims(1:2) = dims
      if (present(layers)) then
         if (layers > 1) rank = 3
         if (layers > 1) file_dims = [int(layers, hsize_t), dims(1)/layers, dims(2)]
      end if
      call create_dataset(self%is_open, self%file_id, self%link_creation_list, self%temporary_file(), path, &
         h5kind_to_type(dp, H5_REAL_KIND), rank, file_dims(1:rank), dataset_id, stat, errmsg)
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
      call finish_dataset(self%temporary_file(), path, dataset_id, hdferr, unit, stat, errmsg)
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
      call create_dataset(self%is_open, self%file_id, self%link_creation_list, self%temporary_file(), path, &
         h5kind_to_type(kind(values), H5_INTEGER_KIND), 1, dims, dataset_id, stat, errmsg)
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
      call finish_dataset(self%temporary_file(), path, dataset_id, hdferr, stat=stat, errmsg=errmsg)
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

      call create_dataset(self%is_open, self%file_id, self%link_creation_list, self%temporary_file(), path, &
         h5kind_to_type(dp, H5_REAL_KIND), 0, dims, dataset_id, stat, errmsg)
      if (stat /= 0) return
      call h5dwrite_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), value, [1_hsize_t], hdferr)
      call finish_dataset(self%temporary_file(), path, dataset_id, hdferr, unit, stat, errmsg)
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
      call put_attribute(self, object_path, name, value, stat, errmsg)
   end subroutine writer_attr_real

   !> Set the integer attribute `name` of the object `object_path` (see `attr_real`).
   subroutine writer_attr_int(self, object_path, name, value, stat, errmsg)
      class(h5_writer), intent(inout) :: self       !! open writer
      character(len=*), intent(in) :: object_path   !! '/', a group or a dataset
      character(len=*), intent(in) :: name          !! attribute name
      integer, intent(in) :: value                  !! attribute value
      integer, intent(out) :: stat                  !! 0 on success
      character(len=*), intent(out) :: errmsg       !! reason of the failure, blank on success
      call put_attribute(self, object_path, name, value, stat, errmsg)
   end subroutine writer_attr_int

   !> Set the 64-bit integer attribute `name` of the object `object_path` (see `attr_real`).
   subroutine writer_attr_int64(self, object_path, name, value, stat, errmsg)
      class(h5_writer), intent(inout) :: self       !! open writer
      character(len=*), intent(in) :: object_path   !! '/', a group or a dataset
      character(len=*), intent(in) :: name          !! attribute name
      integer(int64), intent(in) :: value           !! attribute value
      integer, intent(out) :: stat                  !! 0 on success
      character(len=*), intent(out) :: errmsg       !! reason of the failure, blank on success
      call put_attribute(self, object_path, name, value, stat, errmsg)
   end subroutine writer_attr_int64

   !> The scalar attribute of `attr_real`, `attr_int`, `attr_int64`.
   subroutine put_attribute(self, object_path, name, value, stat, errmsg)
      class(h5_writer), intent(inout) :: self
      character(len=*), intent(in) :: object_path, name
      class(*), intent(in) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: object_id
      character(len=:), allocatable :: failed_step
      integer :: close_error

      call open_or_create_object(self%is_open, self%file_id, self%link_creation_list, self%temporary_file(), &
         object_path, object_id, stat, errmsg)
      if (stat /= 0) return
      call put_scalar_attribute(object_id, name, value, failed_step)
      call h5oclose_f(object_id, close_error)
      call attribute_outcome(self%temporary_file(), object_path, name, failed_step, stat, errmsg)
   end subroutine put_attribute

   !> Set the fixed-length string attribute `name` of the object `object_path` (see
   !! `attr_real`). The stored length is `len(value)` (trailing blanks are kept; pass
   !! `trim(value)` to drop them); with `capacity`, a NUL-terminated string of `capacity`
   !! bytes that `rewrite_attr` can change later.
   subroutine writer_attr_string(self, object_path, name, value, stat, errmsg, capacity)
      class(h5_writer), intent(inout) :: self       !! open writer
      character(len=*), intent(in) :: object_path   !! '/', a group or a dataset
      character(len=*), intent(in) :: name          !! attribute name
      character(len=*), intent(in) :: value         !! attribute value, may be ''
      integer, intent(out) :: stat                  !! 0 on success
      character(len=*), intent(out) :: errmsg       !! reason of the failure, blank on success
      integer, intent(in), optional :: capacity     !! bytes reserved for later values
      integer(hid_t) :: object_id
      character(len=:), allocatable :: failed_step
      integer :: close_error

      call open_or_create_object(self%is_open, self%file_id, self%link_creation_list, self%temporary_file(), &
         object_path, object_id, stat, errmsg)
      if (stat /= 0) return
      call put_string_attribute(object_id, name, value, failed_step, capacity)
      call h5oclose_f(object_id, close_error)
      call attribute_outcome(self%temporary_file(), object_path, name, failed_step, stat, errmsg)
   end subroutine writer_attr_string


   !> Change the attribute `name` of `object_path` in place (allowed in SWMR mode): a
   !! real(dp) or integer(int64) made by `attr_real`/`attr_int64`, or a string made by
   !! `attr_string` with this `capacity`.
   subroutine writer_rewrite_attr(self, object_path, name, value, stat, errmsg, capacity)
      class(h5_writer), intent(inout) :: self
      character(len=*), intent(in) :: object_path, name
      class(*), intent(in) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: capacity
      integer(hid_t) :: object_id
      character(len=:), allocatable :: failed_step
      integer :: close_error
      call open_existing_object(self%is_open, self%file_id, self%temporary_file(), object_path, object_id, stat, errmsg)
      if (stat /= 0) return
      call rewrite_attribute(object_id, name, value, failed_step, capacity)
      call h5oclose_f(object_id, close_error)
      call attribute_outcome(self%temporary_file(), object_path, name, failed_step, stat, errmsg)
   end subroutine writer_rewrite_attr

   !> Flush and close the temporary file and sync it to disk (fsync). The file keeps its
   !! temporary name (`temporary_file`); the caller publishes it by a rename, or discards
   !! it with `discard`. A failure of any of these steps is reported with its reason.
   subroutine writer_finish(self, stat, errmsg)
      class(h5_writer), intent(inout) :: self  !! open writer; closed on return
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      integer :: flush_error, close_error

      stat = 0
      errmsg = ''
      if (.not. self%is_open) then
         call fail(stat, errmsg, 'cannot finish: HDF5 writer has no open file')
         return
      end if
      call h5fflush_f(self%file_id, H5F_SCOPE_GLOBAL_F, flush_error)
      if (flush_error < 0) then
         call fail(stat, errmsg, 'cannot write HDF5 file ''' // self%temporary_file() // '''')
         return   ! still open: `discard` closes it
      end if
      call close_property_list(self%link_creation_list)
      call h5fclose_f(self%file_id, close_error)
      self%file_id = no_id
      self%is_open = .false.
      self%swmr = .false.
      if (close_error < 0) then
         call fail(stat, errmsg, 'cannot close HDF5 file ''' // self%temporary_file() // '''')
         return
      end if
      call sync_file(self%temporary_name, stat, errmsg)
   end subroutine writer_finish

   !> `finish`, rename the temporary file onto the final name and sync the directory. On
   !! failure the temporary file may remain: call `discard` to delete it.
   subroutine writer_commit(self, stat, errmsg)
      class(h5_writer), intent(inout) :: self  !! open writer; closed on return
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      character(len=buffer_length) :: fs_message

      call self%finish(stat, errmsg)
      if (stat /= 0) return
      call rename_file(self%temporary_name, self%final_name, stat, fs_message)
      if (stat == 0) call sync_directory_of(self%final_name, stat, fs_message)
      if (stat /= 0) then
         errmsg = 'cannot publish HDF5 file ''' // self%final_name // ''': ' // trim(fs_message)
         return
      end if
      ! Nothing is left to discard: forget the names.
      deallocate (self%final_name, self%temporary_name)
   end subroutine writer_commit

   !> Delete the temporary file, then close it (if open): whatever HDF5 still writes while
   !! closing goes to a file that no longer has a name. The final name is never touched.
   !! Never fails loudly: errors are ignored; a no-op on a writer with nothing to discard.
   subroutine writer_discard(self)
      class(h5_writer), intent(inout) :: self  !! writer; closed on return
      integer :: hdferr
      character(len=buffer_length) :: fs_message

      if (allocated(self%temporary_name)) then
         call remove_file(self%temporary_name, hdferr, fs_message)
      end if
      if (self%is_open) then
         call close_property_list(self%link_creation_list)
         call h5fclose_f(self%file_id, hdferr)
      end if
      self%file_id = no_id
      self%is_open = .false.
      self%swmr = .false.
      if (allocated(self%final_name)) deallocate (self%final_name)
      if (allocated(self%temporary_name)) deallocate (self%temporary_name)
   end subroutine writer_discard
end module vibrobeam_hdf5
