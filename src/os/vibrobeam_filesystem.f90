!> Small POSIX file-system helpers (mkdir -p, rename, remove, existence, fsync, a lock on
!! a directory or file, unique temporary names), through `bind(C)` interfaces to the C
!! library and to src/os/vibrobeam_posix_files.c. Text files written atomically are
!! `vibrobeam_text_file`'s (src/io).
!!
!! Every procedure returns `stat` (0 = success) and `errmsg` (blank on success, otherwise a
!! message naming the path(s) and the C library's reason) and never stops. Trailing blanks
!! of path arguments are ignored, as in a Fortran `open(file=...)`.
!!
!! Atomic output (docs/output.md, "How a result is published"): a result is written to
!! `unique_temporary_name(final_name)` = `<final_name>.<pid>-<token>.tmp`, synced to disk
!! (`sync_file`) and renamed onto `final_name` once complete; the directory is then synced
!! too (`sync_directory_of`), so the rename itself survives a crash. The temporary file
!! lives in the same directory as the final one, so both are on the same file system and
!! POSIX rename(2) replaces the final name atomically: a reader sees either the old
!! complete file or the new complete file, never a partial one. The process id and a
!! random token make the name unique, so concurrent runs writing one result never share a
!! temporary file.
!!
!! Portability: the C error number is read through glibc/musl's `__errno_location` (the
!! function behind the `errno` macro on Linux); `mode_t` is taken to be a C `int`-sized
!! unsigned integer, as on Linux.
module vibrobeam_filesystem
   use vibrobeam_status, only: stat_failure
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_long, c_int64_t, c_null_char, c_ptr, &
      c_size_t, c_associated, c_f_pointer
   implicit none
   private
   public :: make_parent_directories, rename_file, remove_file, file_exists
   public :: unique_temporary_name, temporary_suffix, directory_of
   public :: sync_file, sync_directory_of, directory_lock, error_text, last_error_text
   public :: process_id, utc_stamp, random_hex
   public :: c_string

   !> Suffix of every temporary file name (`unique_temporary_name`).
   character(len=*), parameter :: temporary_suffix = '.tmp'

   !> An exclusive flock(2) on a directory, held from `acquire` to `release` (or until the
   !! process ends: the kernel releases it with the descriptor).
   type :: directory_lock
      integer(c_int) :: descriptor = -1
   contains
      procedure :: acquire => lock_acquire
      procedure :: try_acquire => lock_try_acquire
      procedure :: release => lock_release
   end type directory_lock


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

      !> int vb_fsync_path(const char *path);  (0 or errno)
      function c_fsync_path(path) result(error) bind(C, name='vb_fsync_path')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: error
      end function c_fsync_path

      !> int vb_lock(const char *path, int *fd);  (0 or errno)
      function c_lock(path, fd) result(error) bind(C, name='vb_lock')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), intent(out) :: fd
         integer(c_int) :: error
      end function c_lock

      !> int vb_try_lock(const char *path, int *fd);  (0, errno, or -1: held elsewhere)
      function c_try_lock(path, fd) result(error) bind(C, name='vb_try_lock')
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), intent(out) :: fd
         integer(c_int) :: error
      end function c_try_lock

      !> int vb_unlock(int fd);
      function c_unlock(fd) result(error) bind(C, name='vb_unlock')
         import :: c_int
         integer(c_int), value, intent(in) :: fd
         integer(c_int) :: error
      end function c_unlock

      !> long vb_process_id(void);
      function c_process_id() result(pid) bind(C, name='vb_process_id')
         import :: c_long
         integer(c_long) :: pid
      end function c_process_id

      !> uint64_t vb_random_token(void);
      function c_random_token() result(token) bind(C, name='vb_random_token')
         import :: c_int64_t
         integer(c_int64_t) :: token
      end function c_random_token

      !> int vb_utc_stamp(char *buffer, int length);
      function c_utc_stamp(buffer, length) result(error) bind(C, name='vb_utc_stamp')
         import :: c_char, c_int
         character(kind=c_char), intent(out) :: buffer(*)
         integer(c_int), value, intent(in) :: length
         integer(c_int) :: error
      end function c_utc_stamp

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
         stat = stat_failure
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
         stat = stat_failure
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
         stat = stat_failure
         errmsg = 'cannot remove ''' // trim(path) // ''': ' // c_error_message(error_number)
      end if
   end subroutine remove_file

   !> True when `path` names an existing file system entry (file, directory, ...).
   function file_exists(path) result(exists)
      character(len=*), intent(in) :: path  !! path to test
      logical :: exists                     !! .true. if access(path, F_OK) succeeds
      exists = c_access(c_string(path), f_ok) == 0
   end function file_exists

   !> A fresh temporary name for writing `final_name`: `<final_name>.<pid>-<token>.tmp`,
   !! the process id and 32 random bits in hexadecimal. It is in the same directory as
   !! `final_name`, so renaming it onto `final_name` stays on one file system and is atomic,
   !! and no other run (another process id) nor another file of this run (another token)
   !! uses it.
   function unique_temporary_name(final_name) result(name)
      character(len=*), intent(in) :: final_name  !! name the file will have when complete
      character(len=:), allocatable :: name
      character(len=32) :: pid
      write (pid, '(i0)') process_id()
      name = trim(final_name) // '.' // trim(pid) // '-' // random_hex(8) // temporary_suffix
   end function unique_temporary_name

   !> The process id.
   function process_id() result(pid)
      integer :: pid
      pid = int(c_process_id())
   end function process_id

   !> `digits` (1..16) random hexadecimal digits.
   function random_hex(digits) result(text)
      integer, intent(in) :: digits
      character(len=digits) :: text
      character(len=16), parameter :: hex = '0123456789abcdef'
      integer(c_int64_t) :: token
      integer :: i, nibble
      token = c_random_token()
      do i = 1, digits
         nibble = int(iand(token, 15_c_int64_t)) + 1
         text(i:i) = hex(nibble:nibble)
         token = shiftr(token, 4)
      end do
   end function random_hex

   !> The current UTC time as 'YYYYMMDDTHHMMSSZ'.
   function utc_stamp() result(stamp)
      character(len=16) :: stamp
      character(kind=c_char) :: buffer(17)
      integer :: i
      stamp = '00000000T000000Z'
      if (c_utc_stamp(buffer, 17_c_int) /= 0) return
      do i = 1, 16
         stamp(i:i) = buffer(i)
      end do
   end function utc_stamp

   !> The directory part of `path` ('.' when it has none, '/' for a file in the root).
   pure function directory_of(path) result(directory)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: directory
      integer :: slash
      slash = index(trim(path), '/', back=.true.)
      if (slash == 0) then
         directory = '.'
      else if (slash == 1) then
         directory = '/'
      else
         directory = path(1:slash - 1)
      end if
   end function directory_of

   !> Wait until the data of the file `path` are on disk (fsync(2)).
   subroutine sync_file(path, stat, errmsg)
      character(len=*), intent(in) :: path     !! existing file
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      integer(c_int) :: error_number
      stat = 0
      errmsg = ''
      error_number = c_fsync_path(c_string(path))
      if (error_number /= 0) then
         stat = stat_failure
         errmsg = 'cannot sync ''' // trim(path) // ''' to disk: ' // error_text(error_number)
      end if
   end subroutine sync_file

   !> Wait until the directory holding `path` is on disk (fsync(2) of the directory), so
   !! that a rename into it survives a crash.
   subroutine sync_directory_of(path, stat, errmsg)
      character(len=*), intent(in) :: path     !! a file in the directory
      integer, intent(out) :: stat             !! 0 on success
      character(len=*), intent(out) :: errmsg  !! reason of the failure, blank on success
      call sync_file(directory_of(path), stat, errmsg)
   end subroutine sync_directory_of

   !> Take an exclusive lock on the directory `directory`, waiting while another process
   !! holds it.
   subroutine lock_acquire(self, directory, stat, errmsg)
      class(directory_lock), intent(inout) :: self
      character(len=*), intent(in) :: directory
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(c_int) :: error_number
      stat = 0
      errmsg = ''
      error_number = c_lock(c_string(directory), self%descriptor)
      if (error_number /= 0) then
         stat = stat_failure
         errmsg = 'cannot lock directory ''' // trim(directory) // ''': ' // error_text(error_number)
      end if
   end subroutine lock_acquire

   !> Take an exclusive lock on the existing file or directory `path` without waiting:
   !! `busy` (and stat = 0) when another process holds it.
   subroutine lock_try_acquire(self, path, busy, stat, errmsg)
      class(directory_lock), intent(inout) :: self
      character(len=*), intent(in) :: path
      logical, intent(out) :: busy
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(c_int) :: error_number
      stat = 0
      errmsg = ''
      error_number = c_try_lock(c_string(path), self%descriptor)
      busy = error_number == -1
      if (error_number /= 0 .and. .not. busy) then
         stat = stat_failure
         errmsg = 'cannot lock ''' // trim(path) // ''': ' // error_text(error_number)
      end if
   end subroutine lock_try_acquire

   !> Release the lock (a no-op when none is held).
   subroutine lock_release(self)
      class(directory_lock), intent(inout) :: self
      integer(c_int) :: error_number
      error_number = c_unlock(self%descriptor)
      self%descriptor = -1
   end subroutine lock_release

   !> strerror(error_number) as a Fortran string.
   function error_text(error_number) result(message)
      integer(c_int), intent(in) :: error_number
      character(len=:), allocatable :: message
      message = c_error_message(error_number)
   end function error_text

   !> strerror(errno): the C library's reason of the last failed call.
   function last_error_text() result(message)
      character(len=:), allocatable :: message
      message = c_error_message(c_errno())
   end function last_error_text

   ! ---------------------------------------------------------------------------------
   ! private helpers

   !> `path` without trailing blanks, as a NUL-terminated C string (for the other modules
   !! of src/os that call the C library).
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
