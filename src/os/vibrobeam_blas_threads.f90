!> How many threads the BLAS/LAPACK library may use (docs/method.md, "BLAS threads").
!!
!! vibrobeam's band operations have 3 sub-diagonals: a product or a solve is a few hundred
!! to a few thousand flops, far below what a threaded BLAS can share out among threads
!! (measured with OpenBLAS on 2 cores: 140-160 % CPU for no gain), and parameter sweeps
!! parallelise better over whole runs. So the program asks its BLAS for one thread,
!! unless the environment variable VIBROBEAM_BLAS_THREADS says otherwise:
!!   unset        one thread;
!!   n >= 1       n threads;
!!   0            leave the library's own setting (e.g. OPENBLAS_NUM_THREADS).
!! The binary links the generic libblas.so.3, so which library runs is only known at run
!! time: the known thread controls (FlexiBLAS, OpenBLAS, Intel MKL, BLIS) are looked up
!! with dlsym among the libraries already loaded; a BLAS without one (the reference BLAS)
!! is single-threaded anyway. Nothing is linked against a particular vendor.
module vibrobeam_blas_threads
   use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_char, c_int, c_int64_t, c_null_char, &
                                          c_null_ptr, c_associated, c_f_procpointer, c_f_pointer
   implicit none
   private
   public :: limit_blas_threads, blas_threads, blas_library_description, blas_thread_variable

   character(len=*), parameter :: blas_thread_variable = 'VIBROBEAM_BLAS_THREADS'

   interface
      !> POSIX dlsym; the handle RTLD_DEFAULT (a null pointer with glibc) searches every
      !! library loaded with the program.
      function dlsym(handle, symbol) bind(c, name='dlsym') result(address)
         import :: c_ptr, c_funptr, c_char
         type(c_ptr), value :: handle
         character(kind=c_char), intent(in) :: symbol(*)
         type(c_funptr) :: address
      end function dlsym
      function strlen(string) bind(c, name='strlen') result(length)
         import :: c_ptr, c_int64_t
         type(c_ptr), value :: string
         integer(c_int64_t) :: length
      end function strlen
   end interface

   abstract interface
      subroutine set_int_threads(n) bind(c)
         import :: c_int
         integer(c_int), value :: n
      end subroutine set_int_threads
      function get_int_threads() bind(c) result(n)
         import :: c_int
         integer(c_int) :: n
      end function get_int_threads
      subroutine set_long_threads(n) bind(c)   ! BLIS: dim_t, a 64-bit integer
         import :: c_int64_t
         integer(c_int64_t), value :: n
      end subroutine set_long_threads
      function get_long_threads() bind(c) result(n)
         import :: c_int64_t
         integer(c_int64_t) :: n
      end function get_long_threads
      function get_text() bind(c) result(text)
         import :: c_ptr
         type(c_ptr) :: text
      end function get_text
   end interface

   !> A library's thread control: the names of its set and get functions, and whether they
   !! take a 64-bit integer.
   type :: thread_control
      character(len=32) :: library, set_name, get_name
      logical :: long_integer
   end type thread_control

   ! FlexiBLAS first: it forwards to the library it wraps
   type(thread_control), parameter :: controls(4) = [ &
      thread_control('FlexiBLAS', 'flexiblas_set_num_threads', 'flexiblas_get_num_threads', .false.), &
      thread_control('OpenBLAS', 'openblas_set_num_threads', 'openblas_get_num_threads', .false.), &
      thread_control('Intel MKL', 'MKL_Set_Num_Threads', 'MKL_Get_Max_Threads', .false.), &
      thread_control('BLIS', 'bli_thread_set_num_threads', 'bli_thread_get_num_threads', .true.)]

contains

   !> Apply the policy above. `warning` is '' or one line (for the caller to print) when
   !! VIBROBEAM_BLAS_THREADS is not a whole number >= 0; one thread is then used.
   subroutine limit_blas_threads(warning)
      character(len=:), allocatable, intent(out) :: warning
      character(len=64) :: value
      integer :: length, status, wanted, k, io
      procedure(set_int_threads), pointer :: set_int
      procedure(set_long_threads), pointer :: set_long
      type(c_funptr) :: address
      warning = ''
      wanted = 1
      call get_environment_variable(blas_thread_variable, value, length, status)
      if (status == -1) then
         warning = blas_thread_variable//' is too long to be a number; using 1 BLAS thread'
      else if (status == 0 .and. length > 0) then
         io = 1
         if (verify(trim(value), ' 0123456789') == 0) read (value, *, iostat=io) wanted
         if (io /= 0) then
            warning = blas_thread_variable//' = '''//trim(value)//''' is not a whole number >= 0 (0: the '// &
                      'library''s own setting); using 1 BLAS thread'
            wanted = 1
         end if
      end if
      if (wanted == 0) return
      do k = 1, size(controls)
         address = lookup(controls(k)%set_name)
         if (.not. c_associated(address)) cycle
         if (controls(k)%long_integer) then
            call c_f_procpointer(address, set_long)
            call set_long(int(wanted, c_int64_t))
         else
            call c_f_procpointer(address, set_int)
            call set_int(int(wanted, c_int))
         end if
         return
      end do
   end subroutine limit_blas_threads

   !> The number of threads the BLAS reports, or 0 when it has no known thread control.
   integer function blas_threads()
      integer :: k
      type(c_funptr) :: address
      procedure(get_int_threads), pointer :: get_int
      procedure(get_long_threads), pointer :: get_long
      blas_threads = 0
      do k = 1, size(controls)
         address = lookup(controls(k)%get_name)
         if (.not. c_associated(address)) cycle
         if (controls(k)%long_integer) then
            call c_f_procpointer(address, get_long)
            blas_threads = int(get_long())
         else
            call c_f_procpointer(address, get_int)
            blas_threads = int(get_int())
         end if
         return
      end do
   end function blas_threads

   !> One line saying which BLAS runs: the library with a known thread control (OpenBLAS
   !! adds its configuration and the kernel it chose for this processor) and its threads.
   function blas_library_description() result(text)
      character(len=:), allocatable :: text
      integer :: k
      character(len=16) :: threads
      text = 'a BLAS without a known thread control (e.g. the reference BLAS), single-threaded'
      do k = 1, size(controls)
         if (.not. c_associated(lookup(controls(k)%set_name))) cycle
         write (threads, '(i0)') blas_threads()
         text = trim(controls(k)%library)
         if (controls(k)%library == 'OpenBLAS') text = c_text('openblas_get_config')//', kernel '// &
                                                       c_text('openblas_get_corename')
         text = text//', '//trim(threads)//' thread(s)'
         return
      end do
   end function blas_library_description

   function lookup(name) result(address)
      character(len=*), intent(in) :: name
      type(c_funptr) :: address
      address = dlsym(c_null_ptr, trim(name)//c_null_char)
   end function lookup

   !> The string returned by a C function `char *name(void)` of the BLAS ('' if absent).
   function c_text(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      type(c_funptr) :: address
      procedure(get_text), pointer :: get
      type(c_ptr) :: pointer
      character(kind=c_char), pointer :: characters(:)
      integer :: i, n
      address = lookup(name)
      if (.not. c_associated(address)) then
         text = ''
         return
      end if
      call c_f_procpointer(address, get)
      pointer = get()
      if (.not. c_associated(pointer)) then
         text = ''
         return
      end if
      n = int(strlen(pointer))
      call c_f_pointer(pointer, characters, [n])
      allocate (character(len=n) :: text)
      do i = 1, n
         text(i:i) = characters(i)
      end do
   end function c_text
end module vibrobeam_blas_threads
