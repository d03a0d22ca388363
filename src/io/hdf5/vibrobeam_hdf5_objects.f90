!> Objects of an HDF5 file being written (`vibrobeam_hdf5`): a new dataset created with
!! its checks (the file open, the path valid and free), finished with its 'unit'
!! attribute and closed, and an object opened for its attributes (created as a group
!! when missing). Every procedure returns `stat` (0 = success, 1 = failure) and an
!! `errmsg` naming the file, the path and what failed.
module vibrobeam_hdf5_objects
   use vibrobeam_hdf5_base, only: no_id, fail, describe, valid_path, link_exists, h5_reason, put_string_attribute, &
      close_dataspace
   use hdf5, only: hid_t, hsize_t, h5gcreate_f, h5gclose_f, h5oopen_f, h5screate_f, h5screate_simple_f, &
      H5S_SCALAR_F, h5dcreate_f, h5dclose_f
   implicit none
   private
   public :: create_dataset, finish_dataset, open_or_create_object, open_existing_object

contains

   !> Check that the file is open (`is_open`) and `path` is a new dataset path, then create
   !! the dataset (rank 0: scalar) of type `type_id` in the file `file_id` (named
   !! `file_name` in messages), its missing groups with `link_list`. On success
   !! `dataset_id` is open.
   subroutine create_dataset(is_open, file_id, link_list, file_name, path, type_id, rank, dims, dataset_id, stat, errmsg)
      logical, intent(in) :: is_open
      integer(hid_t), intent(in) :: file_id, link_list
      character(len=*), intent(in) :: file_name
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
      if (.not. is_open) then
         call fail(stat, errmsg, 'cannot write dataset ''' // trim(path) // &
            ''': HDF5 writer has no open file')
         return
      end if
      if (.not. valid_path(path, root_allowed=.false.)) then
         call fail(stat, errmsg, 'invalid dataset path ''' // trim(path) // ''' for HDF5 file ''' &
            // file_name // '''')
         return
      end if
      if (link_exists(file_id, path)) then
         call fail(stat, errmsg, 'cannot write dataset ' // describe(path, file_name) &
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
            describe(path, file_name))
         return
      end if
      call h5dcreate_f(file_id, trim(path), type_id, space_id, dataset_id, hdferr, &
         lcpl_id=link_list)
      if (hdferr < 0) then
         dataset_id = no_id
         call fail(stat, errmsg, 'cannot create dataset ' // describe(path, file_name))
      end if
      call close_dataspace(space_id)
   end subroutine create_dataset

   !> After the h5dwrite_f of a new dataset (its error code `write_error`): add the
   !! optional 'unit' attribute, close the dataset and set stat/errmsg.
   subroutine finish_dataset(file_name, path, dataset_id, write_error, unit, stat, errmsg)
      character(len=*), intent(in) :: file_name
      character(len=*), intent(in) :: path
      integer(hid_t), intent(in) :: dataset_id
      integer, intent(in) :: write_error
      character(len=*), intent(in), optional :: unit
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: failed_step, reason
      integer :: close_error

      stat = 0
      errmsg = ''
      failed_step = ''
      reason = ''
      if (write_error < 0) reason = h5_reason()
      if (present(unit) .and. write_error >= 0) then
         call put_string_attribute(dataset_id, 'unit', unit, failed_step)
      end if
      call h5dclose_f(dataset_id, close_error)
      if (write_error < 0) then
         call fail(stat, errmsg, 'cannot write the values of dataset ' // &
            describe(path, file_name), reason)
      else if (len(failed_step) > 0) then
         call fail(stat, errmsg, 'cannot write attribute ''unit'' of dataset ' // &
            describe(path, file_name) // ' (' // failed_step // ')')
      else if (close_error < 0) then
         call fail(stat, errmsg, 'cannot close dataset ' // describe(path, file_name))
      end if
   end subroutine finish_dataset

   !> Open the object `object_path` of the file `file_id` (open: `is_open`; named
   !! `file_name` in messages), creating it (and its parents, with `link_list`) as a group
   !! when missing.
   subroutine open_or_create_object(is_open, file_id, link_list, file_name, object_path, object_id, stat, errmsg)
      logical, intent(in) :: is_open
      integer(hid_t), intent(in) :: file_id, link_list
      character(len=*), intent(in) :: file_name
      character(len=*), intent(in) :: object_path
      integer(hid_t), intent(out) :: object_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(hid_t) :: group_id
      integer :: hdferr

      stat = 0
      errmsg = ''
      object_id = no_id
      if (.not. is_open) then
         call fail(stat, errmsg, 'cannot write an attribute of ''' // trim(object_path) // &
            ''': HDF5 writer has no open file')
         return
      end if
      if (.not. valid_path(object_path, root_allowed=.true.)) then
         call fail(stat, errmsg, 'invalid object path ''' // trim(object_path) // &
            ''' for HDF5 file ''' // file_name // '''')
         return
      end if
      if (.not. link_exists(file_id, object_path)) then
         call h5gcreate_f(file_id, trim(object_path), group_id, hdferr, &
            lcpl_id=link_list)
         if (hdferr < 0) then
            call fail(stat, errmsg, 'cannot create group ' // &
               describe(object_path, file_name) // ' (is a parent a dataset?)')
            return
         end if
         call h5gclose_f(group_id, hdferr)
      end if
      call h5oopen_f(file_id, trim(object_path), object_id, hdferr)
      if (hdferr < 0) then
         object_id = no_id
         call fail(stat, errmsg, 'cannot open object ' // describe(object_path, file_name))
      end if
   end subroutine open_or_create_object


   !> Open the existing object `object_path` of the file `file_id` (open: `is_open`;
   !! named `file_name` in messages).
   subroutine open_existing_object(is_open, file_id, file_name, object_path, object_id, stat, errmsg)
      logical, intent(in) :: is_open
      integer(hid_t), intent(in) :: file_id
      character(len=*), intent(in) :: file_name
      character(len=*), intent(in) :: object_path
      integer(hid_t), intent(out) :: object_id
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: hdferr
      stat = 0
      errmsg = ''
      object_id = no_id
      if (.not. is_open) then
         call fail(stat, errmsg, 'cannot change an attribute of ''' // trim(object_path) // &
            ''': HDF5 writer has no open file')
         return
      end if
      call h5oopen_f(file_id, trim(object_path), object_id, hdferr)
      if (hdferr < 0) then
         object_id = no_id
         call fail(stat, errmsg, 'cannot open object ' // describe(object_path, file_name))
      end if
   end subroutine open_existing_object
end module vibrobeam_hdf5_objects
