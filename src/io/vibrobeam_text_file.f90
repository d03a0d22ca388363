!> Text files written atomically (docs/output.md, "How a result is published"): a text
!! file is written under a fresh temporary name beside its final one
!! (`vibrobeam_filesystem: unique_temporary_name`), every write checked, then synced and
!! closed; the caller renames it onto its final name, or discards it. The writes go
!! through src/os/vibrobeam_posix_files.c: libgfortran does not report a failed write of
!! its buffer to a formatted WRITE with iostat, and a full disk must fail the write.
!!
!! Every procedure returns `stat` (0 = success) and `errmsg` (blank on success, otherwise a
!! message naming the file and the C library's reason) and never stops.
module vibrobeam_text_file
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_null_ptr, c_size_t, c_double, c_associated
   use vibrobeam_status, only: stat_failure
   use vibrobeam_filesystem, only: make_parent_directories, remove_file, unique_temporary_name, c_string, &
      error_text
   implicit none
   private
   public :: text_file, open_text_for_atomic_write, write_text_line, write_text_row, finish_text_file, &
      discard_text_file

   !> A text file open for writing (the handle of src/os/vibrobeam_posix_files.c).
   type :: text_file
      type(c_ptr) :: handle = c_null_ptr
   end type text_file

   interface
      !> void *vb_text_open(const char *path, int *error);
      function c_text_open(path, error) result(handle) bind(C, name='vb_text_open')
         import :: c_char, c_int, c_ptr
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), intent(out) :: error
         type(c_ptr) :: handle
      end function c_text_open

      !> int vb_text_write(void *handle, const char *data, size_t length);
      function c_text_write(handle, data, length) result(error) bind(C, name='vb_text_write')
         import :: c_char, c_int, c_ptr, c_size_t
         type(c_ptr), value, intent(in) :: handle
         character(kind=c_char), intent(in) :: data(*)
         integer(c_size_t), value, intent(in) :: length
         integer(c_int) :: error
      end function c_text_write

      !> int vb_text_write_row(void *handle, const double *values, int count, int width, int digits,
      !!                       int integers);
      function c_text_write_row(handle, values, count, width, digits, integers) result(error) &
         bind(C, name='vb_text_write_row')
         import :: c_int, c_ptr, c_double
         type(c_ptr), value, intent(in) :: handle
         real(c_double), intent(in) :: values(*)
         integer(c_int), value, intent(in) :: count, width, digits, integers
         integer(c_int) :: error
      end function c_text_write_row

      !> int vb_text_close(void *handle);
      function c_text_close(handle) result(error) bind(C, name='vb_text_close')
         import :: c_int, c_ptr
         type(c_ptr), value, intent(in) :: handle
         integer(c_int) :: error
      end function c_text_close

      !> void vb_text_abandon(void *handle);
      subroutine c_text_abandon(handle) bind(C, name='vb_text_abandon')
         import :: c_ptr
         type(c_ptr), value, intent(in) :: handle
      end subroutine c_text_abandon
   end interface

contains

   !> Create a fresh temporary file for `final_name` (`unique_temporary_name`), after
   !! creating the parent directories of `final_name`. Write lines with `write_text_line`;
   !! finish with `finish_text_file` (then rename `temporary` onto `final_name`) or
   !! `discard_text_file`.
   subroutine open_text_for_atomic_write(final_name, file, temporary, stat, errmsg)
      character(len=*), intent(in) :: final_name  !! name of the complete text file
      type(text_file), intent(out) :: file        !! the open temporary file
      character(len=:), allocatable, intent(out) :: temporary   !! its name
      integer, intent(out) :: stat                !! 0 on success
      character(len=*), intent(out) :: errmsg     !! reason of the failure, blank on success
      integer(c_int) :: error_number

      temporary = unique_temporary_name(final_name)
      call make_parent_directories(final_name, stat, errmsg)
      if (stat /= 0) return
      file%handle = c_text_open(c_string(temporary), error_number)
      if (.not. c_associated(file%handle)) then
         stat = stat_failure
         errmsg = 'cannot create ''' // temporary // ''': ' // error_text(error_number)
      end if
   end subroutine open_text_for_atomic_write

   !> Append `line` and a newline to `file` (named `temporary` in messages).
   subroutine write_text_line(file, line, temporary, stat, errmsg)
      type(text_file), intent(inout) :: file
      character(len=*), intent(in) :: line, temporary
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(c_int) :: error_number
      stat = 0
      errmsg = ''
      error_number = c_text_write(file%handle, line // new_line('a'), int(len(line) + 1, c_size_t))
      if (error_number /= 0) then
         stat = stat_failure
         errmsg = 'cannot write ''' // trim(temporary) // ''': ' // error_text(error_number)
      end if
   end subroutine write_text_line

   !> Append one line of numbers to `file`: each right-aligned in `width` characters, in
   !! scientific notation with `digits` digits after the point (C's %E), the last
   !! `integers` of them as integers.
   subroutine write_text_row(file, values, width, digits, integers, temporary, stat, errmsg)
      type(text_file), intent(inout) :: file
      real(c_double), intent(in) :: values(:)
      integer, intent(in) :: width, digits, integers
      character(len=*), intent(in) :: temporary
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(c_int) :: error_number
      stat = 0
      errmsg = ''
      error_number = c_text_write_row(file%handle, values, int(size(values), c_int), int(width, c_int), &
                                      int(digits, c_int), int(integers, c_int))
      if (error_number /= 0) then
         stat = stat_failure
         errmsg = 'cannot write ''' // trim(temporary) // ''': ' // error_text(error_number)
      end if
   end subroutine write_text_row

   !> Write out what is buffered, sync the file `temporary` to disk and close it.
   subroutine finish_text_file(file, temporary, stat, errmsg)
      type(text_file), intent(inout) :: file      !! the temporary file
      character(len=*), intent(in) :: temporary   !! its name
      integer, intent(out) :: stat                !! 0 on success
      character(len=*), intent(out) :: errmsg     !! reason of the failure, blank on success
      integer(c_int) :: error_number

      stat = 0
      errmsg = ''
      error_number = c_text_close(file%handle)
      file%handle = c_null_ptr
      if (error_number /= 0) then
         stat = stat_failure
         errmsg = 'cannot write ''' // trim(temporary) // ''': ' // error_text(error_number)
      end if
   end subroutine finish_text_file

   !> Close `file` (if open) and delete the temporary file `temporary`. Never fails:
   !! errors are ignored (there is nothing left to do about them).
   subroutine discard_text_file(file, temporary)
      type(text_file), intent(inout) :: file      !! the temporary file (may be closed)
      character(len=*), intent(in) :: temporary  !! its name
      integer :: remove_status
      character(len=256) :: remove_message

      if (c_associated(file%handle)) call c_text_abandon(file%handle)
      file%handle = c_null_ptr
      call remove_file(temporary, remove_status, remove_message)
   end subroutine discard_text_file
end module vibrobeam_text_file
