!> Readers of HDF5 files by file name: whole datasets (tests, small files) and
!! single-valued attributes (also from a file already open: `h5_reader`). Each call opens
!! the file, reads and closes it, and reports any failure through stat and errmsg (a
!! message naming the file, the path and the reason). A file whose writer was killed
!! opens as well (`open_file_for_reading`, SWMR reader).
!!
!! Conventions (as `vibrobeam_hdf5`): a dataset that h5py sees with shape (rows, columns)
!! is a Fortran array values(columns, rows).
module vibrobeam_hdf5_file_reads
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   use vibrobeam_hdf5_base, only: no_id, buffer_length, fail, describe, link_exists, &
      open_file_for_reading, close_dataspace, close_datatype
   use hdf5, only: hid_t, hsize_t, size_t, h5kind_to_type, H5_REAL_KIND, H5_INTEGER_KIND, h5fclose_f, &
      h5oopen_f, h5oclose_f, h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
      h5sget_simple_extent_npoints_f, h5dopen_f, h5dclose_f, h5dread_f, h5dget_space_f, h5aopen_f, h5aclose_f, &
      h5aread_f, h5aexists_f, h5aget_space_f, h5aget_type_f, h5tcopy_f, h5tset_size_f, h5tget_size_f, &
      h5tset_strpad_f, h5tget_class_f, h5tis_variable_str_f, H5T_FORTRAN_S1, H5T_STR_NULLPAD_F, H5T_STRING_F
   implicit none
   private
   public :: read_real_1d, read_real_2d, read_real_3d, read_int_1d, read_real_scalar
   public :: read_attr_real, read_attr_int, read_attr_int64, read_attr_string
   public :: h5_path_exists

contains

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

   !> Read the 3-d numeric dataset `path` of `filename`: a dataset of shape (n3, n2, n1) as
   !! h5py sees it is returned as `values(n1, n2, n3)` (a beam of two planes' y, z: n1 = 2).
   subroutine read_real_3d(filename, path, values, stat, errmsg)
      character(len=*), intent(in) :: filename                !! HDF5 file
      character(len=*), intent(in) :: path                    !! dataset path
      real(dp), allocatable, intent(out) :: values(:, :, :)   !! the data (n1, n2, n3)
      integer, intent(out) :: stat                            !! 0 on success
      character(len=*), intent(out) :: errmsg                 !! reason of the failure, blank on success
      integer(hid_t) :: file_id, dataset_id
      integer(hsize_t) :: dims(3)
      integer :: hdferr

      call open_dataset_for_reading(filename, path, 3, file_id, dataset_id, dims, stat, errmsg)
      if (stat /= 0) return
      allocate (values(dims(1), dims(2), dims(3)))
      hdferr = 0
      if (size(values) > 0) call h5dread_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, dims, hdferr)
      call close_after_reading(filename, path, file_id, dataset_id, hdferr, stat, errmsg)
   end subroutine read_real_3d

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
   subroutine read_attr_real(filename, object_path, name, value, stat, errmsg, open_file)
      character(len=*), intent(in) :: filename     !! HDF5 file
      character(len=*), intent(in) :: object_path  !! '/', a group or a dataset
      character(len=*), intent(in) :: name         !! attribute name
      real(dp), intent(out) :: value               !! the value (0 on failure)
      integer, intent(out) :: stat                 !! 0 on success
      character(len=*), intent(out) :: errmsg      !! reason of the failure, blank on success
      integer(hid_t), intent(in), optional :: open_file   !! read from this open file instead
      integer(hid_t) :: file_id, object_id, attribute_id
      integer :: hdferr

      value = 0.0_dp
      call open_attribute_for_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, stat, errmsg, open_file)
      if (stat /= 0) return
      call h5aread_f(attribute_id, h5kind_to_type(dp, H5_REAL_KIND), value, [1_hsize_t], hdferr)
      call close_attribute_after_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, hdferr, stat, errmsg, keep_file=present(open_file))
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

   !> Read the single-valued integer attribute `name` of `object_path` in `filename`, as
   !! a 64-bit integer.
   subroutine read_attr_int64(filename, object_path, name, value, stat, errmsg, open_file)
      character(len=*), intent(in) :: filename     !! HDF5 file
      character(len=*), intent(in) :: object_path  !! '/', a group or a dataset
      character(len=*), intent(in) :: name         !! attribute name
      integer(int64), intent(out) :: value         !! the value (0 on failure)
      integer, intent(out) :: stat                 !! 0 on success
      character(len=*), intent(out) :: errmsg      !! reason of the failure, blank on success
      integer(hid_t), intent(in), optional :: open_file   !! read from this open file instead
      integer(hid_t) :: file_id, object_id, attribute_id
      integer :: hdferr
      value = 0
      call open_attribute_for_reading(filename, object_path, name, file_id, object_id, &
                                      attribute_id, stat, errmsg, open_file)
      if (stat /= 0) return
      call h5aread_f(attribute_id, h5kind_to_type(int64, H5_INTEGER_KIND), value, [1_hsize_t], hdferr)
      call close_attribute_after_reading(filename, object_path, name, file_id, object_id, &
                                         attribute_id, hdferr, stat, errmsg, keep_file=present(open_file))
   end subroutine read_attr_int64

   !> Read the scalar fixed-length string attribute `name` of `object_path` in `filename`.
   !! Trailing NUL padding is removed. Variable-length strings are not supported.
   subroutine read_attr_string(filename, object_path, name, value, stat, errmsg, open_file)
      character(len=*), intent(in) :: filename               !! HDF5 file
      character(len=*), intent(in) :: object_path            !! '/', a group or a dataset
      character(len=*), intent(in) :: name                   !! attribute name
      character(len=:), allocatable, intent(out) :: value    !! the string ('' on failure)
      integer, intent(out) :: stat                           !! 0 on success
      character(len=*), intent(out) :: errmsg                !! reason of the failure, blank on success
      integer(hid_t), intent(in), optional :: open_file      !! read from this open file instead
      integer(hid_t) :: file_id, object_id, attribute_id, file_type, memory_type
      integer(size_t) :: string_length
      integer :: hdferr, type_class, last
      logical :: is_variable
      character(len=:), allocatable :: buffer, problem

      value = ''
      call open_attribute_for_reading(filename, object_path, name, file_id, object_id, &
         attribute_id, stat, errmsg, open_file)
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
         attribute_id, 0, stat, errmsg, keep_file=present(open_file))
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
         attribute_id, stat, errmsg, open_file)
      character(len=*), intent(in) :: filename, object_path, name
      integer(hid_t), intent(out) :: file_id, object_id, attribute_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t), intent(in), optional :: open_file   !! use this open file (not closed here)
      integer(hid_t) :: space_id
      integer(hsize_t) :: value_count
      logical :: exists, borrowed
      integer :: hdferr, close_error

      object_id = no_id
      attribute_id = no_id
      borrowed = .false.
      if (present(open_file)) borrowed = open_file /= no_id
      if (borrowed) then
         file_id = open_file
         stat = 0
         errmsg = ''
      else
         call open_file_for_reading(filename, file_id, stat, errmsg)
         if (stat /= 0) return
      end if
      if (.not. link_exists(file_id, object_path)) then
         if (.not. borrowed) call h5fclose_f(file_id, close_error)
         call fail(stat, errmsg, 'no object ' // describe(object_path, filename))
         return
      end if
      call h5oopen_f(file_id, trim(object_path), object_id, hdferr)
      if (hdferr < 0) then
         if (.not. borrowed) call h5fclose_f(file_id, close_error)
         call fail(stat, errmsg, 'cannot open object ' // describe(object_path, filename))
         return
      end if
      exists = .false.
      if (len_trim(name) > 0) call h5aexists_f(object_id, trim(name), exists, hdferr)
      if (.not. exists .or. hdferr < 0) then
         call h5oclose_f(object_id, close_error)
         if (.not. borrowed) call h5fclose_f(file_id, close_error)
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
         if (.not. borrowed) call h5fclose_f(file_id, close_error)
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
         attribute_id, read_error, stat, errmsg, keep_file)
      character(len=*), intent(in) :: filename, object_path, name
      integer(hid_t), intent(in) :: file_id, object_id, attribute_id
      integer, intent(in) :: read_error
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: keep_file   !! the file was borrowed: leave it open
      integer :: close_error

      stat = 0
      errmsg = ''
      call h5aclose_f(attribute_id, close_error)
      call h5oclose_f(object_id, close_error)
      if (.not. present(keep_file)) then
         call h5fclose_f(file_id, close_error)
      else if (.not. keep_file) then
         call h5fclose_f(file_id, close_error)
      end if
      if (read_error < 0) then
         call fail(stat, errmsg, 'cannot read attribute ''' // trim(name) // ''' of ' // &
            describe(object_path, filename) // ' (type not convertible?)')
      end if
   end subroutine close_attribute_after_reading
end module vibrobeam_hdf5_file_reads
