!> The entries of directories (POSIX, through src/os/vibrobeam_posix_files.c): listing a
!! directory's names, a second name for a file (link), an empty file made when missing, an
!! empty directory removed. A sweep's partial directory is managed with them
!! (docs/sweeps.md, "Resuming a sweep"). Every procedure returns `stat` (0 = success) and
!! `errmsg` (the path and the C library's reason), as `vibrobeam_filesystem` does.
module vibrobeam_directory_entries
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_null_ptr, c_associated
   use vibrobeam_status, only: stat_failure
   use vibrobeam_filesystem, only: c_string, error_text
   implicit none
   private
   public :: directory_listing, link_file, remove_directory, touch_file

   !> The names in a directory, one at a time (`open`, `next` until it returns .false.,
   !! `close`), in the order the file system gives them.
   type :: directory_listing
      type(c_ptr) :: handle = c_null_ptr
   contains
      procedure :: open => listing_open
      procedure :: next => listing_next
      procedure :: close => listing_close
   end type directory_listing

   interface
      !> int vb_touch(const char *path);  int vb_link(const char *from, const char *to);
      !! int vb_remove_directory(const char *path);  (0 or errno)
      function c_touch(path) result(error) bind(C, name='vb_touch')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: error
      end function c_touch
      function c_link(from, to) result(error) bind(C, name='vb_link')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: from(*), to(*)
         integer(c_int) :: error
      end function c_link
      function c_remove_directory(path) result(error) bind(C, name='vb_remove_directory')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: error
      end function c_remove_directory

      !> void *vb_directory_open(const char *path, int *error);
      !! int vb_directory_next(void *handle, char *buffer, int length);
      !! void vb_directory_close(void *handle);
      function c_directory_open(path, error) result(handle) bind(C, name='vb_directory_open')
         import :: c_char, c_int, c_ptr
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), intent(out) :: error
         type(c_ptr) :: handle
      end function c_directory_open
      function c_directory_next(handle, buffer, length) result(size) bind(C, name='vb_directory_next')
         import :: c_char, c_int, c_ptr
         type(c_ptr), value, intent(in) :: handle
         character(kind=c_char), intent(out) :: buffer(*)
         integer(c_int), value, intent(in) :: length
         integer(c_int) :: size
      end function c_directory_next
      subroutine c_directory_close(handle) bind(C, name='vb_directory_close')
         import :: c_ptr
         type(c_ptr), value, intent(in) :: handle
      end subroutine c_directory_close
   end interface

contains

   !> Create the empty file `path` when it does not exist (an existing one is kept as it is).
   subroutine touch_file(path, stat, errmsg)
      character(len=*), intent(in) :: path
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call outcome(c_touch(c_string(path)), 'cannot create ''' // trim(path) // '''', stat, errmsg)
   end subroutine touch_file

   !> Give the file `from` the second name `to` (a hard link; `to` must not exist): both
   !! names then show the same file, and renaming another file onto one of them leaves the
   !! other as it was.
   subroutine link_file(from, to, stat, errmsg)
      character(len=*), intent(in) :: from, to
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call outcome(c_link(c_string(from), c_string(to)), 'cannot link ''' // trim(from) // ''' to ''' // &
                   trim(to) // '''', stat, errmsg)
   end subroutine link_file

   !> Remove the empty directory `path`.
   subroutine remove_directory(path, stat, errmsg)
      character(len=*), intent(in) :: path
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call outcome(c_remove_directory(c_string(path)), 'cannot remove directory ''' // trim(path) // '''', &
                   stat, errmsg)
   end subroutine remove_directory

   !> stat and errmsg of a C call that returned `error_number` (0 or errno).
   subroutine outcome(error_number, what, stat, errmsg)
      integer(c_int), intent(in) :: error_number
      character(len=*), intent(in) :: what
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      if (error_number /= 0) then
         stat = stat_failure
         errmsg = what // ': ' // error_text(error_number)
      end if
   end subroutine outcome

   !> Start listing the directory `path`.
   subroutine listing_open(self, path, stat, errmsg)
      class(directory_listing), intent(inout) :: self
      character(len=*), intent(in) :: path
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(c_int) :: error_number
      call self%close()
      self%handle = c_directory_open(c_string(path), error_number)
      call outcome(error_number, 'cannot list directory ''' // trim(path) // '''', stat, errmsg)
   end subroutine listing_open

   !> The next name of the directory ('.' and '..' left out); .false. at the end (names
   !! longer than 4096 bytes are skipped).
   function listing_next(self, name) result(found)
      class(directory_listing), intent(inout) :: self
      character(len=:), allocatable, intent(out) :: name
      logical :: found
      character(kind=c_char) :: buffer(4096)
      integer :: length, i
      found = .false.
      name = ''
      if (.not. c_associated(self%handle)) return
      do
         length = int(c_directory_next(self%handle, buffer, int(size(buffer), c_int)))
         if (length >= 0) exit
      end do
      if (length == 0) return
      name = repeat(' ', length)
      do i = 1, length
         name(i:i) = buffer(i)
      end do
      found = .true.
   end function listing_next

   subroutine listing_close(self)
      class(directory_listing), intent(inout) :: self
      if (c_associated(self%handle)) call c_directory_close(self%handle)
      self%handle = c_null_ptr
   end subroutine listing_close
end module vibrobeam_directory_entries
