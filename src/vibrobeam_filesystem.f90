!> Small POSIX file-system helpers (mkdir -p, rename, remove, existence) and atomic text
!! output, through `bind(C)` interfaces to the C library.
!!
!! Every procedure returns `stat` (0 = success) and `errmsg` (blank on success, otherwise a
!! message naming the path(s) and the C library's reason) and never stops. Trailing blanks
!! of path arguments are ignored, as in a Fortran `open(file=...)`.
!!
!! Atomic output (INTERFACE.md, "Output: ... written atomically"): a result is written to
!! `temporary_name(final_name)` and renamed onto `final_name` once complete. The temporary
!! file lives in the same directory as the final one, so both are on the same file system
!! and POSIX rename(2) replaces the final name atomically: a reader sees either the old
!! complete file or the new complete file, never a partial one.
!!
!! Portability: the C error number is read through glibc/musl's `__errno_location` (the
!! function behind the `errno` macro on Linux); `mode_t` is taken to be a C `int`-sized
!! unsigned integer, as on Linux.
module vibrobeam_filesystem
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char, c_ptr, c_size_t, &
      c_associated, c_f_pointer
   implicit none
   private
   public :: make_parent_directories, rename_file, remove_file, file_exists
   public :: temporary_name
   public :: open_text_for_atomic_write, commit_text_file, discard_text_file

   !> Suffix appended to a final file name to form its temporary name.
   character(len=*), parameter :: temporary_suffix = '.tmp'

   !> Permission bits for new directories (octal 0777, reduced by the process umask as
   !! `mkdir -p` does).
   integer(c_int), parameter :: directory_mode = int(o'777', c_int)

   !> `access` mode testing existence only (POSIX F_OK).
   integer(c_int), parameter :: f_ok = 0_c_int

   !> errno "No such file or directory" (2 on Linux, the BSDs and macOS).
   integer(c_int), parameter :: enoent = 2_c_int

   interface
      !> int mkdir(const char *path, mode_t mode);
      function c_mkdir(path, mode) result(status) bind(C, name='mkdir')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value, intent(in) :: mode
         integer(c_int) :: status
      end function c_mkdir

      !> int rename(const char *from, const char *to);
      function c_rename(from, to) result(status) bind(C, name='rename')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: from(*), to(*)
         integer(c_int) :: status
      end function c_rename

      !> int unlink(const char *path);
      function c_unlink(path) result(status) bind(C, name='unlink')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: status
      end function c_unlink

      !> int access(const char *path, int mode);
      function c_access(path, mode) result(status) bind(C, name='access')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value, intent(in) :: mode
         integer(c_int) :: status
      end function c_access

      !> int *__errno_location(void);  (what the errno macro expands to on Linux)
      function c_errno_location() result(location) bind(C, name='__errno_location')
         import :: c_ptr
         type(c_ptr) :: location
      end function c_errno_location

      !> char *strerror(int errnum);
      function c_strerror(errnum) result(message) bind(C, name='strerror')
         import :: c_int, c_ptr
         integer(c_int), value, intent(in) :: errnum
         type(c_ptr) :: message
      end function c_strerror

      !> size_t strlen(const char *s);
      function c_strlen(s) result(length) bind(C, name='strlen')
         import :: c_ptr, c_size_t
         type(c_ptr), value, intent(in) :: s
         integer(c_size_t) :: length
      end function c_strlen
   end interface

contains

   !> Create every missing directory of the directory part of `path`, like
   !! `mkdir -p "$(dirname path)"`. A path without a directory part ('out.h5') or whose
   !! directory is '/' needs nothing and succeeds. Fails (stat /= 0) when a component
   !! exists but is not a directory, or cannot be created.
   subroutine make_parent_directories(path, stat, errmsg)
      character(len=*), intent(in) :: path     !! file path whose parent directories are made
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      integer :: last, slash
      integer(c_int) :: mkdir_status, mkdir_errno

      stat = 0
      errmsg = ''
      last = len_trim(path)
      ! Each '/' after the first character ends one directory prefix; the last '/' ends
      ! the parent directory itself. Empty prefixes ('a//b') are skipped.
      do slash = 2, last
         if (path(slash:slash) /= '/') cycle
         if (path(slash - 1:slash - 1) == '/') cycle
         mkdir_status = c_mkdir(c_string(path(1:slash - 1)), directory_mode)
         if (mkdir_status == 0) cycle
         mkdir_errno = c_errno()
         ! Already there (or made concurrently): fine if it is a directory. Appending '/'
         ! makes access() fail with ENOTDIR when the prefix is a regular file.
         if (c_access(c_string(path(1:slash)), f_ok) == 0) cycle
         stat = 1
         if (c_access(c_string(path(1:slash - 1)), f_ok) == 0) then
            errmsg = 'cannot create directory ''' // path(1:slash - 1) // ''' for ''' // &
               path(1:last) // ''': it exists and is not a directory'
         else
            errmsg = 'cannot create directory ''' // path(1:slash - 1) // ''' for ''' // &
               path(1:last) // ''': ' // c_error_message(mkdir_errno)
         end if
         return
      end do
   end subroutine make_parent_directories

   !> Rename `from` to `to`, replacing `to` if it exists. Atomic when both names are on the
   !! same file system (POSIX rename(2)).
   subroutine rename_file(from, to, stat, errmsg)
      character(len=*), intent(in) :: from     !! existing file
      character(len=*), intent(in) :: to       !! new name (replaced if present)
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      integer(c_int) :: error_number

      stat = 0
      errmsg = ''
      if (c_rename(c_string(from), c_string(to)) /= 0) then
         error_number = c_errno()
         stat = 1
         errmsg = 'cannot rename ''' // trim(from) // ''' to ''' // trim(to) // ''': ' // &
            c_error_message(error_number)
      end if
   end subroutine rename_file

   !> Delete the file `path`. A missing file is not an error (stat = 0).
   subroutine remove_file(path, stat, errmsg)
      character(len=*), intent(in) :: path     !! file to delete
      integer, intent(out) :: stat             !! 0 on success or if the file did not exist
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      integer(c_int) :: error_number

      stat = 0
      errmsg = ''
      if (c_unlink(c_string(path)) /= 0) then
         error_number = c_errno()
         if (error_number == enoent) return
         stat = 1
         errmsg = 'cannot remove ''' // trim(path) // ''': ' // c_error_message(error_number)
      end if
   end subroutine remove_file

   !> True when `path` names an existing file system entry (file, directory, ...).
   function file_exists(path) result(exists)
      character(len=*), intent(in) :: path  !! path to test
      logical :: exists                     !! .true. if access(path, F_OK) succeeds
      exists = c_access(c_string(path), f_ok) == 0
   end function file_exists

   !> Name of the temporary file used while writing `final_name`: `final_name // '.tmp'`.
   !! It is in the same directory as `final_name`, so renaming it onto `final_name` stays
   !! on one file system and is atomic.
   pure function temporary_name(final_name) result(name)
      character(len=*), intent(in) :: final_name  !! name the file will have when complete
      character(len=:), allocatable :: name       !! trim(final_name) // '.tmp'
      name = trim(final_name) // temporary_suffix
   end function temporary_name

   !> Open `temporary_name(final_name)` for formatted sequential writing (replacing any
   !! previous temporary file), after creating the parent directories of `final_name`.
   !! Finish with `commit_text_file` (or `discard_text_file` on error).
   subroutine open_text_for_atomic_write(final_name, unit, stat, errmsg)
      character(len=*), intent(in) :: final_name  !! name of the complete text file
      integer, intent(out) :: unit                !! unit opened on the temporary file (newunit)
      integer, intent(out) :: stat                !! 0 on success
      character(len=*), intent(out) :: errmsg     !! reason of the failure, blank on success
      character(len=512) :: io_message

      unit = -1
      call make_parent_directories(final_name, stat, errmsg)
      if (stat /= 0) return
      io_message = ''
      open (newunit=unit, file=temporary_name(final_name), status='replace', &
         action='write', form='formatted', access='sequential', iostat=stat, &
         iomsg=io_message)
      if (stat /= 0) then
         unit = -1
         errmsg = 'cannot open ''' // temporary_name(final_name) // ''' for writing: ' // &
            trim(io_message)
      end if
   end subroutine open_text_for_atomic_write

   !> Close `unit` (opened by `open_text_for_atomic_write(final_name, ...)`) and rename
   !! its temporary file onto `final_name`. On failure the temporary file is left in place.
   subroutine commit_text_file(unit, final_name, stat, errmsg)
      integer, intent(in) :: unit                 !! unit of the temporary file
      character(len=*), intent(in) :: final_name  !! name of the complete text file
      integer, intent(out) :: stat                !! 0 on success
      character(len=*), intent(out) :: errmsg     !! reason of the failure, blank on success
      character(len=512) :: io_message

      errmsg = ''
      io_message = ''
      close (unit, status='keep', iostat=stat, iomsg=io_message)
      if (stat /= 0) then
         errmsg = 'cannot close ''' // temporary_name(final_name) // ''': ' // trim(io_message)
         return
      end if
      call rename_file(temporary_name(final_name), final_name, stat, errmsg)
   end subroutine commit_text_file

   !> Close `unit` and delete the temporary file of `final_name`; `final_name` itself is
   !! untouched. Never fails: errors are ignored (there is nothing left to do about them).
   subroutine discard_text_file(unit, final_name)
      integer, intent(in) :: unit                 !! unit of the temporary file
      character(len=*), intent(in) :: final_name  !! name the text file would have had
      integer :: close_status, remove_status
      character(len=256) :: remove_message

      close (unit, status='delete', iostat=close_status)
      ! Deleting on close can fail silently (e.g. unit already closed): make sure.
      call remove_file(temporary_name(final_name), remove_status, remove_message)
   end subroutine discard_text_file

   ! ---------------------------------------------------------------------------------
   ! private helpers

   !> `path` without trailing blanks, as a NUL-terminated C string.
   pure function c_string(path) result(string)
      character(len=*), intent(in) :: path
      character(kind=c_char, len=:), allocatable :: string
      string = trim(path) // c_null_char
   end function c_string

   !> Current value of the C `errno`.
   function c_errno() result(error_number)
      integer(c_int) :: error_number
      integer(c_int), pointer :: errno_pointer
      call c_f_pointer(c_errno_location(), errno_pointer)
      error_number = errno_pointer
   end function c_errno

   !> strerror(error_number) as a Fortran string.
   function c_error_message(error_number) result(message)
      integer(c_int), intent(in) :: error_number
      character(len=:), allocatable :: message
      type(c_ptr) :: c_message
      character(kind=c_char), pointer :: characters(:)
      integer :: length, i

      c_message = c_strerror(error_number)
      if (.not. c_associated(c_message)) then
         message = 'error number'
         return
      end if
      length = int(c_strlen(c_message))
      call c_f_pointer(c_message, characters, [length])
      allocate (character(len=length) :: message)
      do i = 1, length
         message(i:i) = characters(i)
      end do
   end function c_error_message

end module vibrobeam_filesystem
