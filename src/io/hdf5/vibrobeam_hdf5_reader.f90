!> `h5_reader`, a reader of HDF5 files that keeps one file open and reads large datasets
!! a block of rows at a time (the text derivation, `vibrobeam --text`, and the checkpoint
!! of a restart), so memory does not grow with the length of a run. Whole datasets and
!! attributes read by file name are in `vibrobeam_hdf5_file_reads`.
!!
!! Conventions (as `vibrobeam_hdf5`): a dataset that h5py sees with shape (rows, columns)
!! is a Fortran array values(columns, rows); a 1-d dataset of `rows` values is read as
!! values(1, rows) by the block readers. A file whose writer was killed opens as well
!! (`open_file_for_reading`, SWMR reader).
module vibrobeam_hdf5_reader
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   use vibrobeam_hdf5_base, only: no_id, fail, describe, link_exists, open_file_for_reading, close_dataspace
   use hdf5, only: hid_t, hsize_t, h5kind_to_type, H5_REAL_KIND, H5_INTEGER_KIND, h5fclose_f, h5oopen_f, &
      h5oclose_f, h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, h5screate_simple_f, &
      h5sselect_hyperslab_f, H5S_SELECT_SET_F, h5dopen_f, h5dclose_f, h5dread_f, h5dget_space_f, h5aexists_f
   use vibrobeam_hdf5_file_reads, only: read_attr_real, read_attr_string, read_attr_int64
   implicit none
   private
   public :: h5_reader

   !> One HDF5 file open for reading.
   type :: h5_reader
      private
      integer(hid_t) :: file_id = no_id
      character(len=:), allocatable :: name
   contains
      procedure :: open => reader_open
      procedure :: close => reader_close
      procedure :: exists => reader_exists
      procedure :: has_attr => reader_has_attr
      procedure :: shape => reader_shape
      procedure :: read_rows => reader_read_rows
      procedure :: read_reals => reader_read_reals
      procedure :: read_int64s => reader_read_int64s
      procedure :: attr_string => reader_attr_string
      procedure :: attr_real => reader_attr_real
      procedure :: attr_int64 => reader_attr_int64
   end type h5_reader

contains

   ! =================================================================================
   ! h5_reader

   !> Open `filename` for reading; with `live`, a file whose writer may be running
   !! (`open_file_for_reading`).
   subroutine reader_open(self, filename, stat, errmsg, live)
      class(h5_reader), intent(inout) :: self
      character(len=*), intent(in) :: filename
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: live
      call self%close()
      call open_file_for_reading(filename, self%file_id, stat, errmsg, live)
      self%name = trim(filename)
   end subroutine reader_open

   !> Close the file (a no-op when none is open).
   subroutine reader_close(self)
      class(h5_reader), intent(inout) :: self
      integer :: hdferr
      if (self%file_id /= no_id) call h5fclose_f(self%file_id, hdferr)
      self%file_id = no_id
   end subroutine reader_close

   !> True when the object `path` exists in the open file.
   function reader_exists(self, path) result(exists)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      logical :: exists
      exists = .false.
      if (self%file_id /= no_id) exists = link_exists(self%file_id, path)
   end function reader_exists

   !> True when the object `object_path` of the open file exists and has the attribute
   !! `name`.
   function reader_has_attr(self, object_path, name) result(exists)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: object_path, name
      logical :: exists
      integer(hid_t) :: object_id
      integer :: hdferr, close_error
      exists = .false.
      if (.not. self%exists(object_path)) return
      call h5oopen_f(self%file_id, trim(object_path), object_id, hdferr)
      if (hdferr < 0) return
      call h5aexists_f(object_id, trim(name), exists, hdferr)
      if (hdferr < 0) exists = .false.
      call h5oclose_f(object_id, close_error)
   end function reader_has_attr

   !> The dimensions of dataset `path` in Fortran order (columns first, rows last; a 1-d
   !! dataset of n values gives [n]).
   subroutine reader_shape(self, path, dims, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(int64), allocatable, intent(out) :: dims(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: dataset_id, space_id
      integer(hsize_t) :: extent(7), max_extent(7)
      integer :: hdferr, rank, close_error
      allocate (dims(0))
      call open_dataset(self, path, dataset_id, stat, errmsg)
      if (stat /= 0) return
      call h5dget_space_f(dataset_id, space_id, hdferr)
      rank = -1
      if (hdferr >= 0) call h5sget_simple_extent_ndims_f(space_id, rank, hdferr)
      if (hdferr >= 0 .and. rank > 0 .and. rank <= 7) &
         call h5sget_simple_extent_dims_f(space_id, extent(1:rank), max_extent(1:rank), hdferr)
      call close_dataspace(space_id)
      call h5dclose_f(dataset_id, close_error)
      if (hdferr < 0 .or. rank < 0 .or. rank > 7) then
         call fail(stat, errmsg, 'cannot read the dataspace of dataset ' // describe(path, self%name))
         return
      end if
      dims = int(extent(1:rank), int64)
   end subroutine reader_shape

   !> Rows first_row .. first_row + size(values, 2) - 1 (1-based) of the real dataset
   !! `path` of size(values, 1) columns (1 for a 1-d dataset), into values(columns, rows).
   subroutine reader_read_rows(self, path, first_row, values, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(int64), intent(in) :: first_row
      real(dp), intent(out), contiguous :: values(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: dataset_id, file_space, memory_space
      integer(hsize_t) :: offset(3), count(3), memory_dims(2), file_dims(3), file_max(3)
      integer :: hdferr, rank, close_error
      values = 0
      if (size(values) == 0) then
         stat = 0
         errmsg = ''
         return
      end if
      call open_dataset(self, path, dataset_id, stat, errmsg)
      if (stat /= 0) return
      memory_space = no_id
      call h5dget_space_f(dataset_id, file_space, hdferr)
      if (hdferr >= 0) call h5sget_simple_extent_ndims_f(file_space, rank, hdferr)
      if (hdferr >= 0) then
         memory_dims = int([size(values, 1), size(values, 2)], hsize_t)
         if (rank == 1) then
            offset(1) = int(first_row - 1, hsize_t)
            count(1) = memory_dims(2)
            call h5sselect_hyperslab_f(file_space, H5S_SELECT_SET_F, offset(1:1), count(1:1), hdferr)
         else if (rank == 2) then
            offset(1:2) = [0_hsize_t, int(first_row - 1, hsize_t)]
            count(1:2) = memory_dims
            call h5sselect_hyperslab_f(file_space, H5S_SELECT_SET_F, offset(1:2), count(1:2), hdferr)
         else   ! 3-d (rows, columns, layers): a row is every value of its two inner dimensions
            call h5sget_simple_extent_dims_f(file_space, file_dims, file_max, hdferr)
            offset = [0_hsize_t, 0_hsize_t, int(first_row - 1, hsize_t)]
            count = [file_dims(1), file_dims(2), memory_dims(2)]
            if (hdferr >= 0) call h5sselect_hyperslab_f(file_space, H5S_SELECT_SET_F, offset, count, hdferr)
         end if
      end if
      if (hdferr >= 0) call h5screate_simple_f(2, memory_dims, memory_space, hdferr)
      if (hdferr >= 0) call h5dread_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, memory_dims, &
                                      hdferr, mem_space_id=memory_space, file_space_id=file_space)
      call close_dataspace(memory_space)
      call close_dataspace(file_space)
      call h5dclose_f(dataset_id, close_error)
      if (hdferr < 0) call fail(stat, errmsg, 'cannot read rows ' // integer_text(int(first_row)) // &
                                ' and following of dataset ' // describe(path, self%name))
   end subroutine reader_read_rows

   !> The whole real dataset `path` as a 1-d array (any rank, in storage order).
   subroutine reader_read_reals(self, path, values, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      real(dp), allocatable, intent(out) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call read_whole(self, path, stat, errmsg, reals=values)
   end subroutine reader_read_reals

   !> The whole integer dataset `path` as 64-bit integers (any rank, in storage order).
   subroutine reader_read_int64s(self, path, values, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(int64), allocatable, intent(out) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call read_whole(self, path, stat, errmsg, int64s=values)
   end subroutine reader_read_int64s

   !> The whole dataset `path` into `reals` or `int64s` (the one present), converted by
   !! HDF5; empty on failure.
   subroutine read_whole(self, path, stat, errmsg, reals, int64s)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable, intent(out), optional :: reals(:)
      integer(int64), allocatable, intent(out), optional :: int64s(:)
      integer(hid_t) :: dataset_id
      integer :: count, hdferr, close_error
      call whole_dataset_size(self, path, dataset_id, count, stat, errmsg)
      if (stat /= 0) count = 0
      if (present(reals)) allocate (reals(count))
      if (present(int64s)) allocate (int64s(count))
      if (stat /= 0) return
      hdferr = 0
      if (count > 0) then
         if (present(reals)) call h5dread_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), reals, &
                                            [int(count, hsize_t)], hdferr)
         if (present(int64s)) call h5dread_f(dataset_id, h5kind_to_type(int64, H5_INTEGER_KIND), int64s, &
                                             [int(count, hsize_t)], hdferr)
      end if
      call h5dclose_f(dataset_id, close_error)
      if (hdferr < 0) call fail(stat, errmsg, 'cannot read dataset ' // describe(path, self%name))
   end subroutine read_whole

   !> The string attribute `name` of `object_path` (trailing NULs removed).
   subroutine reader_attr_string(self, object_path, name, value, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: object_path, name
      character(len=:), allocatable, intent(out) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call read_attr_string(self%name, object_path, name, value, stat, errmsg, self%file_id)
   end subroutine reader_attr_string

   !> The real attribute `name` of `object_path`.
   subroutine reader_attr_real(self, object_path, name, value, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: object_path, name
      real(dp), intent(out) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call read_attr_real(self%name, object_path, name, value, stat, errmsg, self%file_id)
   end subroutine reader_attr_real

   !> The integer attribute `name` of `object_path`, as a 64-bit integer.
   subroutine reader_attr_int64(self, object_path, name, value, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: object_path, name
      integer(int64), intent(out) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call read_attr_int64(self%name, object_path, name, value, stat, errmsg, self%file_id)
   end subroutine reader_attr_int64

   !> Open dataset `path` of the reader's file.
   subroutine open_dataset(self, path, dataset_id, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(hid_t), intent(out) :: dataset_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: hdferr
      stat = 0
      errmsg = ''
      dataset_id = no_id
      if (self%file_id == no_id) then
         call fail(stat, errmsg, 'cannot read ''' // trim(path) // ''': no HDF5 file is open')
         return
      end if
      if (.not. link_exists(self%file_id, path)) then
         call fail(stat, errmsg, 'no dataset ' // describe(path, self%name))
         return
      end if
      call h5dopen_f(self%file_id, trim(path), dataset_id, hdferr)
      if (hdferr < 0) then
         dataset_id = no_id
         call fail(stat, errmsg, 'cannot open dataset ' // describe(path, self%name))
      end if
   end subroutine open_dataset

   !> Open dataset `path` and count its values (the product of its dimensions: the HDF5
   !! Fortran wrapper of H5Sget_simple_extent_npoints reports an empty dataset as an error).
   subroutine whole_dataset_size(self, path, dataset_id, values_count, stat, errmsg)
      class(h5_reader), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(hid_t), intent(out) :: dataset_id
      integer, intent(out) :: values_count
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64), allocatable :: dims(:)
      values_count = 0
      dataset_id = no_id
      call self%shape(path, dims, stat, errmsg)
      if (stat /= 0) return
      values_count = int(product(dims))
      call open_dataset(self, path, dataset_id, stat, errmsg)
   end subroutine whole_dataset_size

end module vibrobeam_hdf5_reader
