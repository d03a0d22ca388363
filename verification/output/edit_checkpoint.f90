!> Damages the checkpoint of a result file on purpose, in place, for the checksum cases of
!! run_restart_test.sh (docs/output.md, "Checkpoint and restart"):
!! - `edit_checkpoint FILE flip ITEM INDEX BIT` flips bit BIT (0: the least significant;
!!   a real's bit pattern, an integer's two's complement) of value INDEX of the item ITEM
!!   ('stepper.u', 'stepper.steps', ...) of the current checkpoint slot: one flipped bit,
!!   the smallest damage a disk or a copy can do;
!! - `edit_checkpoint FILE drop-checksum` deletes the attribute `checksum` of the current
!!   slot, which makes the checkpoint look like one of vibrobeam 0.2.0 (written before
!!   checkpoints carried a checksum).
!! Uses the HDF5 library directly, not vibrobeam's writer: the test damages the file the way
!! an outside cause would. Exit status 0 when the edit was made, 1 otherwise.
program edit_checkpoint
   use hdf5
   use vibrobeam_kinds, only: dp, int64, error_unit
   implicit none
   character(len=4096) :: file, action, item, argument
   integer(hid_t) :: file_id, group_id, dataset_id, attribute_id, type_id
   integer(hsize_t) :: dims(1), max_dims(1)
   integer(hid_t) :: space_id
   integer(int64) :: current
   integer(int64), allocatable :: words(:)
   real(dp), allocatable :: values(:)
   integer :: hdferr, index, bit, class, rank
   character(len=:), allocatable :: slot

   call get_command_argument(1, file)
   call get_command_argument(2, action)
   call h5open_f(hdferr)
   call h5eset_auto_f(0, hdferr)   ! this program's own messages say what failed
   call h5fopen_f(trim(file), H5F_ACC_RDWR_F, file_id, hdferr)
   call check('open '//trim(file)//' for writing')
   call h5gopen_f(file_id, '/checkpoint', group_id, hdferr)
   call check('open /checkpoint')
   call h5aopen_f(group_id, 'current', attribute_id, hdferr)
   call check('open /checkpoint current')
   call h5aread_f(attribute_id, h5kind_to_type(int64, H5_INTEGER_KIND), current, [1_hsize_t], hdferr)
   call check('read /checkpoint current')
   call h5aclose_f(attribute_id, hdferr)
   call h5gclose_f(group_id, hdferr)
   if (current < 1 .or. current > 2) call stop_with('no complete checkpoint in '//trim(file))
   slot = '/checkpoint/state_'//achar(iachar('0') + int(current))

   select case (trim(action))
   case ('drop-checksum')
      call h5gopen_f(file_id, slot, group_id, hdferr)
      call check('open '//slot)
      call h5adelete_f(group_id, 'checksum', hdferr)
      call check('delete '//slot//' checksum')
      call h5gclose_f(group_id, hdferr)
   case ('flip')
      call get_command_argument(3, item)
      call get_command_argument(4, argument)
      read (argument, *) index
      call get_command_argument(5, argument)
      read (argument, *) bit
      call h5dopen_f(file_id, slot//'/'//trim(item), dataset_id, hdferr)
      call check('open '//slot//'/'//trim(item))
      call h5dget_space_f(dataset_id, space_id, hdferr)
      call h5sget_simple_extent_ndims_f(space_id, rank, hdferr)
      call h5sget_simple_extent_dims_f(space_id, dims, max_dims, hdferr)
      call h5sclose_f(space_id, hdferr)
      if (rank /= 1 .or. index < 1 .or. index > dims(1)) call stop_with('no value of that index in '//trim(item))
      call h5dget_type_f(dataset_id, type_id, hdferr)
      call h5tget_class_f(type_id, class, hdferr)
      call h5tclose_f(type_id, hdferr)
      if (class == H5T_INTEGER_F) then
         allocate (words(dims(1)))
         call h5dread_f(dataset_id, h5kind_to_type(int64, H5_INTEGER_KIND), words, dims, hdferr)
         call check('read '//trim(item))
         words(index) = ieor(words(index), shiftl(1_int64, bit))
         call h5dwrite_f(dataset_id, h5kind_to_type(int64, H5_INTEGER_KIND), words, dims, hdferr)
      else
         allocate (values(dims(1)))
         call h5dread_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, dims, hdferr)
         call check('read '//trim(item))
         values(index) = transfer(ieor(transfer(values(index), 1_int64), shiftl(1_int64, bit)), 1.0_dp)
         call h5dwrite_f(dataset_id, h5kind_to_type(dp, H5_REAL_KIND), values, dims, hdferr)
      end if
      call check('write '//trim(item))
      call h5dclose_f(dataset_id, hdferr)
   case default
      call stop_with('usage: edit_checkpoint FILE flip ITEM INDEX BIT | edit_checkpoint FILE drop-checksum')
   end select
   call h5fclose_f(file_id, hdferr)
   call check('close '//trim(file))
   call h5close_f(hdferr)

contains

   subroutine check(what)
      character(len=*), intent(in) :: what
      if (hdferr < 0) call stop_with('cannot '//what)
   end subroutine check

   subroutine stop_with(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'edit_checkpoint: '//message
      error stop 1
   end subroutine stop_with
end program edit_checkpoint
