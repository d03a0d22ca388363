!> Datasets written while a run goes on (docs/output.md, "Streaming"):
!! - `h5_series`: an extendible, chunked dataset that grows by rows (one row per output
!!   time, per impact, per episode, ...). Rows are collected in a bounded buffer and
!!   written as one hyperslab (H5Dset_extent + a selection) when the buffer is full or
!!   when the caller flushes, so memory does not grow with the number of rows.
!! - `h5_array`: a fixed-size 1-d dataset created once and rewritten in place (the
!!   checkpoint slots), which SWMR mode allows; with `layers` > 1 a 2-d dataset that h5py
!!   sees as (length/layers, layers), the layer fastest (a beam of two planes' y, z).
!!
!! A series of one column is a 1-d dataset (rows); of c columns, a 2-d dataset that h5py
!! sees as (rows, c) (the Fortran array (c, rows), `vibrobeam_hdf5` conventions); a series or
!! a table of `layers` > 1 is 3-d, (rows, c/layers, layers), the layer fastest. Values
!! are stored as native doubles, or as 64-bit integers for `integers = .true.` (counts).
!! Every dataset gets its string attribute 'unit'. Create every dataset before the file
!! enters SWMR mode (`h5_writer%start_swmr`).
module vibrobeam_hdf5_series
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_base, only: no_id, fail, describe, link_exists, put_string_attribute, &
      close_dataspace, close_property_list, close_dataset, h5_reason
   use hdf5, only: hid_t, hsize_t, size_t, h5kind_to_type, H5_REAL_KIND, H5_INTEGER_KIND, &
      h5pcreate_f, h5pset_chunk_f, h5pset_alloc_time_f, h5pset_chunk_cache_f, H5P_DATASET_CREATE_F, &
      H5P_DATASET_ACCESS_F, H5D_ALLOC_TIME_EARLY_F, &
      H5S_UNLIMITED_F, &
      h5screate_simple_f, h5sselect_hyperslab_f, H5S_SELECT_SET_F, &
      h5dcreate_f, h5dwrite_f, h5dget_space_f, h5dset_extent_f
   implicit none
   private
   public :: h5_series, h5_array, h5_table, series_buffer_rows

   !> Largest buffer (and chunk) of a series in bytes: 1 MiB, HDF5's default chunk cache.
   integer, parameter :: buffer_bytes = 2**20
   !> Most rows buffered by a series (a chunk of a 1-d series is then 32 KiB).
   integer, parameter :: most_buffer_rows = 4096

   !> An extendible dataset of rows.
   type :: h5_series
      private
      integer(hid_t) :: dataset = no_id
      integer :: columns = 1
      logical :: matrix = .false.            !! 2-d dataset (also for one column)
      integer :: layers = 1                  !! > 1: a 3-d dataset (rows, columns/layers, layers)
      logical :: integers = .false.          !! stored as 64-bit integers
      integer(int64) :: written = 0          !! rows in the file
      integer :: buffered = 0                !! rows waiting in the buffer
      real(dp), allocatable :: buffer(:, :)  !! (columns, capacity)
      character(len=:), allocatable :: path, file
   contains
      procedure :: create => series_create
      procedure :: append => series_append
      procedure :: write => series_write
      procedure :: rows => series_rows
      procedure :: close => series_close
   end type h5_series

   !> A fixed-size 1-d dataset rewritten in place.
   type :: h5_array
      private
      integer(hid_t) :: dataset = no_id
      integer :: length = 0
      logical :: integers = .false.
      character(len=:), allocatable :: path, file
   contains
      procedure :: create => array_create
      procedure :: write_reals => array_write_reals
      procedure :: write_int64s => array_write_int64s
      procedure :: close => array_close
   end type h5_array

   !> A fixed-size dataset of rows written in blocks (module documentation).
   type :: h5_table
      private
      integer(hid_t) :: dataset = no_id
      integer :: columns = 1
      integer(int64) :: rows = 0
      integer :: layers = 1                  !! > 1: a 3-d dataset (rows, columns/layers, layers)
      logical :: integers = .false.
      logical :: vector = .false.
      character(len=:), allocatable :: path, file
   contains
      procedure :: create => table_create
      procedure :: write_rows => table_write_rows
      procedure :: close => table_close
   end type h5_table

contains

   !> Rows a series of `columns` columns buffers: at most `most_buffer_rows`, at most
   !! `buffer_bytes` of values, at least 1.
   pure integer function series_buffer_rows(columns)
      integer, intent(in) :: columns
      series_buffer_rows = max(1, min(most_buffer_rows, buffer_bytes/(8*max(columns, 1))))
   end function series_buffer_rows

   !> Create the empty extendible dataset `path` with `columns` values per row, chunks of
   !! `series_buffer_rows(columns)` rows, and its 'unit' attribute. With `layers` > 1 a row
   !! is columns/layers values of each of `layers` layers, the layer fastest, and the
   !! dataset is 3-d: (rows, columns/layers, layers) in HDF5's order (a beam of two planes'
   !! histories of a deflection at several points: their last dimension y, z).
   subroutine series_create(self, writer, path, columns, unit, stat, errmsg, integers, matrix, layers)
      class(h5_series), intent(inout) :: self
      type(h5_writer), intent(in) :: writer
      character(len=*), intent(in) :: path, unit
      integer, intent(in) :: columns
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: integers   !! store 64-bit integers (default: reals)
      logical, intent(in), optional :: matrix     !! 2-d even with one column (default: columns > 1)
      integer, intent(in), optional :: layers     !! a 3-d dataset of `layers` layers (columns a multiple)
      integer(hid_t) :: space_id, properties, access
      integer(hsize_t) :: dims(3), max_dims(3), chunk(3)
      character(len=:), allocatable :: failed_step, reason
      integer :: hdferr, rank, capacity, allocation_stat
      stat = 0
      errmsg = ''
      self%columns = columns
      self%integers = .false.
      if (present(integers)) self%integers = integers
      self%matrix = columns > 1
      if (present(matrix)) self%matrix = matrix .or. columns > 1
      self%layers = 1
      if (present(layers)) self%layers = max(1, layers)
      self%path = trim(path)
      self%file = writer%temporary_file()
      self%written = 0
      self%buffered = 0
      capacity = series_buffer_rows(columns)
      allocate (self%buffer(columns, capacity), stat=allocation_stat)
      if (allocation_stat /= 0) then
         stat = stat_failure
         errmsg = 'cannot allocate the output buffer of ' // describe(path, self%file)
         return
      end if
      if (link_exists(writer%id(), path)) then
         call fail(stat, errmsg, 'cannot create dataset ' // describe(path, self%file) // &
            ': the path already exists')
         return
      end if
      if (self%layers > 1) then
         rank = 3
         dims = [int(self%layers, hsize_t), int(columns/self%layers, hsize_t), 0_hsize_t]
         max_dims = [int(self%layers, hsize_t), int(columns/self%layers, hsize_t), H5S_UNLIMITED_F]
         chunk = [int(self%layers, hsize_t), int(columns/self%layers, hsize_t), int(capacity, hsize_t)]
      else if (self%matrix) then
         rank = 2
         dims(1:2) = [int(columns, hsize_t), 0_hsize_t]
         max_dims(1:2) = [int(columns, hsize_t), H5S_UNLIMITED_F]
         chunk(1:2) = [int(columns, hsize_t), int(capacity, hsize_t)]
      else
         rank = 1
         dims(1) = 0
         max_dims(1) = H5S_UNLIMITED_F
         chunk(1) = int(capacity, hsize_t)
      end if
      properties = no_id
      access = no_id
      space_id = no_id
      ! no chunk cache (also set for the whole file, `vibrobeam_hdf5`): rows are written a
      ! whole chunk (the buffer) at a time
      call h5screate_simple_f(rank, dims(1:rank), space_id, hdferr, max_dims(1:rank))
      if (hdferr >= 0) call h5pcreate_f(H5P_DATASET_CREATE_F, properties, hdferr)
      if (hdferr >= 0) call h5pset_chunk_f(properties, rank, chunk(1:rank), hdferr)
      if (hdferr >= 0) call h5pcreate_f(H5P_DATASET_ACCESS_F, access, hdferr)
      if (hdferr >= 0) call h5pset_chunk_cache_f(access, 0_size_t, 0_size_t, 1.0, hdferr)
      if (hdferr >= 0) call h5dcreate_f(writer%id(), trim(path), value_type(self%integers), space_id, &
                                        self%dataset, hdferr, properties, writer%link_properties(), access)
      reason = ''
      if (hdferr < 0) reason = h5_reason()
      call close_dataspace(space_id)
      call close_property_list(properties)
      call close_property_list(access)
      if (hdferr < 0) then
         self%dataset = no_id
         call fail(stat, errmsg, 'cannot create dataset ' // describe(path, self%file), reason)
         return
      end if
      call put_string_attribute(self%dataset, 'unit', unit, failed_step)
      if (len(failed_step) > 0) call fail(stat, errmsg, 'cannot write attribute ''unit'' of ' // &
                                          describe(path, self%file) // ' (' // failed_step // ')')
   end subroutine series_create

   !> Add one row (size(row) = columns); writes the buffer when it is full.
   subroutine series_append(self, row, stat, errmsg)
      class(h5_series), intent(inout) :: self
      real(dp), intent(in) :: row(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (self%buffered == size(self%buffer, 2)) then
         call self%write(stat, errmsg)
         if (stat /= 0) return
      end if
      self%buffered = self%buffered + 1
      self%buffer(:, self%buffered) = row
   end subroutine series_append

   !> Write the buffered rows to the file (extend the dataset, write one hyperslab).
   subroutine series_write(self, stat, errmsg)
      class(h5_series), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: file_space, memory_space
      integer(hsize_t) :: offset(3), count(3), extent(3)
      integer(int64), allocatable :: counts(:, :)
      character(len=:), allocatable :: reason
      integer :: hdferr, rank
      stat = 0
      errmsg = ''
      if (self%buffered == 0) return
      if (self%dataset == no_id) then
         call fail(stat, errmsg, 'cannot write ' // describe(self%path, self%file) // ': the dataset is not open')
         return
      end if
      if (self%layers > 1) then
         rank = 3
         extent = [int(self%layers, hsize_t), int(self%columns/self%layers, hsize_t), &
                   int(self%written + self%buffered, hsize_t)]
         offset = [0_hsize_t, 0_hsize_t, int(self%written, hsize_t)]
         count = [int(self%layers, hsize_t), int(self%columns/self%layers, hsize_t), int(self%buffered, hsize_t)]
      else if (self%matrix) then
         rank = 2
         extent(1:2) = [int(self%columns, hsize_t), int(self%written + self%buffered, hsize_t)]
         offset(1:2) = [0_hsize_t, int(self%written, hsize_t)]
         count(1:2) = [int(self%columns, hsize_t), int(self%buffered, hsize_t)]
      else
         rank = 1
         extent(1) = int(self%written + self%buffered, hsize_t)
         offset(1) = int(self%written, hsize_t)
         count(1) = int(self%buffered, hsize_t)
      end if
      file_space = no_id
      memory_space = no_id
      call h5dset_extent_f(self%dataset, extent(1:rank), hdferr)
      if (hdferr >= 0) call h5dget_space_f(self%dataset, file_space, hdferr)
      if (hdferr >= 0) call h5sselect_hyperslab_f(file_space, H5S_SELECT_SET_F, offset(1:rank), count(1:rank), hdferr)
      if (hdferr >= 0) call h5screate_simple_f(rank, count(1:rank), memory_space, hdferr)
      if (hdferr >= 0) then
         if (self%integers) then
            allocate (counts, source=nint(self%buffer(:, 1:self%buffered), int64))
            call h5dwrite_f(self%dataset, value_type(.true.), counts, count(1:rank), hdferr, &
                            mem_space_id=memory_space, file_space_id=file_space)
         else if (self%buffered == size(self%buffer, 2)) then
            call h5dwrite_f(self%dataset, value_type(.false.), self%buffer, count(1:rank), hdferr, &
                            mem_space_id=memory_space, file_space_id=file_space)
         else
            call write_section(self%buffer(:, 1:self%buffered))
         end if
      end if
      reason = ''
      if (hdferr < 0) reason = h5_reason()
      call close_dataspace(memory_space)
      call close_dataspace(file_space)
      if (hdferr < 0) then
         call fail(stat, errmsg, 'cannot write ' // describe(self%path, self%file), reason)
         return
      end if
      self%written = self%written + self%buffered
      self%buffered = 0
   contains
      !> h5dwrite_f of a contiguous copy of the filled part of the buffer.
      subroutine write_section(values)
         real(dp), intent(in) :: values(:, :)
         real(dp), allocatable :: contiguous_values(:, :)
         allocate (contiguous_values, source=values)
         call h5dwrite_f(self%dataset, value_type(.false.), contiguous_values, count(1:rank), hdferr, &
                         mem_space_id=memory_space, file_space_id=file_space)
      end subroutine write_section
   end subroutine series_write

   !> Rows appended so far (written or buffered).
   pure function series_rows(self) result(rows)
      class(h5_series), intent(in) :: self
      integer(int64) :: rows
      rows = self%written + self%buffered
   end function series_rows

   !> Close the dataset (buffered rows not written are lost: `write` first).
   subroutine series_close(self)
      class(h5_series), intent(inout) :: self
      call close_dataset(self%dataset)
   end subroutine series_close

   !> Create the 1-d dataset `path` of `length` values (reals, or 64-bit integers).
   subroutine array_create(self, writer, path, length, integers, stat, errmsg, layers)
      class(h5_array), intent(inout) :: self
      type(h5_writer), intent(in) :: writer
      character(len=*), intent(in) :: path
      integer, intent(in) :: length
      logical, intent(in) :: integers
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: layers     !! > 1: (length/layers, layers) (module documentation)
      self%length = length
      self%integers = integers
      self%path = trim(path)
      self%file = writer%temporary_file()
      ! storage allocated now: writing it later (in SWMR mode) changes no metadata
      if (present(layers)) then
         if (layers > 1) then
            call create_fixed(writer, self%path, int([layers, length/layers], hsize_t), value_type(integers), .true., &
                              self%dataset, stat, errmsg)
            return
         end if
      end if
      call create_fixed(writer, self%path, [int(length, hsize_t)], value_type(integers), .true., self%dataset, &
                        stat, errmsg)
   end subroutine array_create

   !> Write all values of a real array dataset.
   subroutine array_write_reals(self, values, stat, errmsg)
      class(h5_array), intent(inout) :: self
      real(dp), intent(in) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: contiguous_values(:)
      integer :: hdferr
      stat = 0
      errmsg = ''
      if (size(values) /= self%length .or. self%integers) then
         call fail(stat, errmsg, 'cannot write ' // describe(self%path, self%file) // ': wrong size or type')
         return
      end if
      if (self%length == 0) return
      allocate (contiguous_values, source=values)
      call h5dwrite_f(self%dataset, value_type(.false.), contiguous_values, [int(self%length, hsize_t)], hdferr)
      if (hdferr < 0) call fail(stat, errmsg, 'cannot write ' // describe(self%path, self%file))
   end subroutine array_write_reals

   !> Write all values of an integer array dataset.
   subroutine array_write_int64s(self, values, stat, errmsg)
      class(h5_array), intent(inout) :: self
      integer(int64), intent(in) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64), allocatable :: contiguous_values(:)
      integer :: hdferr
      stat = 0
      errmsg = ''
      if (size(values) /= self%length .or. .not. self%integers) then
         call fail(stat, errmsg, 'cannot write ' // describe(self%path, self%file) // ': wrong size or type')
         return
      end if
      if (self%length == 0) return
      allocate (contiguous_values, source=values)
      call h5dwrite_f(self%dataset, value_type(.true.), contiguous_values, [int(self%length, hsize_t)], hdferr)
      if (hdferr < 0) call fail(stat, errmsg, 'cannot write ' // describe(self%path, self%file))
   end subroutine array_write_int64s

   !> Close the dataset.
   subroutine array_close(self)
      class(h5_array), intent(inout) :: self
      call close_dataset(self%dataset)
   end subroutine array_close

   !> Create the dataset `path` of `rows` rows of `columns` values (module documentation),
   !! with the string attribute 'unit' when `unit` is given.
   subroutine table_create(self, writer, path, columns, rows, stat, errmsg, unit, integers, vector, early, layers)
      class(h5_table), intent(inout) :: self
      type(h5_writer), intent(in) :: writer
      character(len=*), intent(in) :: path
      integer, intent(in) :: columns
      integer(int64), intent(in) :: rows
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), intent(in), optional :: unit
      logical, intent(in), optional :: integers   !! default integers (default: doubles)
      logical, intent(in), optional :: vector     !! a 1-d dataset (one column; default: 2-d)
      logical, intent(in), optional :: early      !! storage allocated now (default: at the first write)
      integer, intent(in), optional :: layers     !! > 1: 3-d, (rows, columns/layers, layers) (module documentation)
      integer(hsize_t) :: dims(3)
      character(len=:), allocatable :: failed_step
      integer :: rank
      logical :: early_storage
      stat = 0
      errmsg = ''
      self%columns = columns
      self%rows = rows
      self%integers = .false.
      if (present(integers)) self%integers = integers
      self%vector = .false.
      if (present(vector)) self%vector = vector .and. columns == 1
      self%path = trim(path)
      self%file = writer%temporary_file()
      if (link_exists(writer%id(), path)) then
         call fail(stat, errmsg, 'cannot create dataset '//describe(path, self%file)//': the path already exists')
         return
      end if
      self%layers = 1
      if (present(layers) .and. .not. self%vector) self%layers = max(1, layers)
      rank = merge(1, merge(3, 2, self%layers > 1), self%vector)
      dims(1:2) = [int(columns, hsize_t), int(rows, hsize_t)]
      if (self%vector) dims(1) = int(rows, hsize_t)
      if (rank == 3) dims = [int(self%layers, hsize_t), int(columns/self%layers, hsize_t), int(rows, hsize_t)]
      early_storage = .false.
      if (present(early)) early_storage = early
      call create_fixed(writer, self%path, dims(1:rank), value_type(self%integers, whole=.true.), early_storage, &
                        self%dataset, stat, errmsg)
      if (stat /= 0) return
      if (present(unit)) then
         call put_string_attribute(self%dataset, 'unit', unit, failed_step)
         if (len(failed_step) > 0) call fail(stat, errmsg, 'cannot write attribute ''unit'' of '// &
                                             describe(path, self%file)//' ('//failed_step//')')
      end if
   end subroutine table_create

   !> Write rows first_row .. first_row + size(values, 2) - 1 (1-based) from
   !! values(columns, rows); an integer table stores nint(values).
   subroutine table_write_rows(self, first_row, values, stat, errmsg)
      class(h5_table), intent(inout) :: self
      integer(int64), intent(in) :: first_row
      real(dp), intent(in) :: values(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: file_space, memory_space
      integer(hsize_t) :: offset(3), count(3)
      real(dp), allocatable :: reals(:, :)
      integer, allocatable :: whole(:, :)
      character(len=:), allocatable :: reason
      integer :: hdferr, rank
      stat = 0
      errmsg = ''
      if (size(values, 2) == 0) return
      if (self%dataset == no_id .or. size(values, 1) /= self%columns .or. first_row < 1 .or. &
          first_row - 1 + size(values, 2) > self%rows) then
         call fail(stat, errmsg, 'cannot write rows '//integer_text(int(first_row))//' and following of '// &
                   describe(self%path, self%file)//': not open, or outside its '//integer_text(int(self%rows))// &
                   ' rows of '//integer_text(self%columns)//' values')
         return
      end if
      if (self%vector) then
         rank = 1
         offset(1) = int(first_row - 1, hsize_t)
         count(1) = int(size(values, 2), hsize_t)
      else if (self%layers > 1) then
         rank = 3
         offset = [0_hsize_t, 0_hsize_t, int(first_row - 1, hsize_t)]
         count = int([self%layers, size(values, 1)/self%layers, size(values, 2)], hsize_t)
      else
         rank = 2
         offset(1:2) = [0_hsize_t, int(first_row - 1, hsize_t)]
         count(1:2) = int([size(values, 1), size(values, 2)], hsize_t)
      end if
      file_space = no_id
      memory_space = no_id
      call h5dget_space_f(self%dataset, file_space, hdferr)
      if (hdferr >= 0) call h5sselect_hyperslab_f(file_space, H5S_SELECT_SET_F, offset(1:rank), count(1:rank), hdferr)
      if (hdferr >= 0) call h5screate_simple_f(rank, count(1:rank), memory_space, hdferr)
      if (hdferr >= 0) then
         ! contiguous copies: h5dwrite_f takes an explicit-shape buffer
         if (self%integers) then
            allocate (whole, source=nint(values))
            call h5dwrite_f(self%dataset, value_type(.true., whole=.true.), whole, count(1:rank), hdferr, &
                            mem_space_id=memory_space, file_space_id=file_space)
         else
            allocate (reals, source=values)
            call h5dwrite_f(self%dataset, value_type(.false.), reals, count(1:rank), hdferr, &
                            mem_space_id=memory_space, file_space_id=file_space)
         end if
      end if
      reason = ''
      if (hdferr < 0) reason = h5_reason()
      call close_dataspace(memory_space)
      call close_dataspace(file_space)
      if (hdferr < 0) call fail(stat, errmsg, 'cannot write '//describe(self%path, self%file), reason)
   end subroutine table_write_rows

   !> Close the dataset.
   subroutine table_close(self)
      class(h5_table), intent(inout) :: self
      call close_dataset(self%dataset)
   end subroutine table_close

   !> Create the dataset `path` of the writer's file with dimensions `dims` (Fortran order)
   !! and type `type_id`, its storage allocated now with `early`; `dataset` is open after.
   subroutine create_fixed(writer, path, dims, type_id, early, dataset, stat, errmsg)
      type(h5_writer), intent(in) :: writer
      character(len=*), intent(in) :: path
      integer(hsize_t), intent(in) :: dims(:)
      integer(hid_t), intent(in) :: type_id
      logical, intent(in) :: early
      integer(hid_t), intent(out) :: dataset
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: space_id, properties
      character(len=:), allocatable :: reason
      integer :: hdferr
      stat = 0
      errmsg = ''
      space_id = no_id
      properties = no_id
      call h5screate_simple_f(size(dims), dims, space_id, hdferr)
      if (hdferr >= 0) call h5pcreate_f(H5P_DATASET_CREATE_F, properties, hdferr)
      if (hdferr >= 0 .and. early) call h5pset_alloc_time_f(properties, H5D_ALLOC_TIME_EARLY_F, hdferr)
      if (hdferr >= 0) call h5dcreate_f(writer%id(), trim(path), type_id, space_id, dataset, hdferr, properties, &
                                        writer%link_properties())
      reason = ''
      if (hdferr < 0) reason = h5_reason()
      call close_dataspace(space_id)
      call close_property_list(properties)
      if (hdferr < 0) then
         dataset = no_id
         call fail(stat, errmsg, 'cannot create dataset '//describe(path, writer%temporary_file()), reason)
      end if
   end subroutine create_fixed

   !> HDF5 type of the stored values: doubles, or integers (64-bit; of the default kind
   !! with `whole`, a table's).
   function value_type(integers, whole) result(type_id)
      logical, intent(in) :: integers
      logical, intent(in), optional :: whole
      integer(hid_t) :: type_id
      integer :: default_integer
      if (integers .and. present(whole)) then
         type_id = h5kind_to_type(kind(default_integer), H5_INTEGER_KIND)
      else if (integers) then
         type_id = h5kind_to_type(int64, H5_INTEGER_KIND)
      else
         type_id = h5kind_to_type(dp, H5_REAL_KIND)
      end if
   end function value_type
end module vibrobeam_hdf5_series
