!> Interruption by SIGINT, SIGTERM or SIGUSR1 (docs/output.md, "Interruption"): the C handlers of
!! src/os/vibrobeam_posix_signals.c only record the signal; the run loop asks `interrupt_requested`
!! after each step, finishes it, publishes a complete result marked 'interrupted' and the
!! program exits with status 4. A second signal ends the process at once (the first one
!! gives both signals back their default action). SIGXFSZ is ignored, so a write beyond
!! `ulimit -f` fails with EFBIG and is reported like any other I/O error.
module vibrobeam_signals
   use, intrinsic :: iso_c_binding, only: c_int
   use vibrobeam_status, only: stat_failure
   use vibrobeam_filesystem, only: error_text
   implicit none
   private
   public :: watch_signals, interrupt_requested, interrupt_name

   !> Linux signal numbers (signal(7), x86 and ARM).
   integer(c_int), parameter :: sigint = 2, sigusr1 = 10, sigterm = 15

   interface
      function c_install_interrupt_handlers() result(error) bind(C, name='vb_install_interrupt_handlers')
         import :: c_int
         integer(c_int) :: error
      end function c_install_interrupt_handlers
      function c_interrupt_signal() result(signal_number) bind(C, name='vb_interrupt_signal')
         import :: c_int
         integer(c_int) :: signal_number
      end function c_interrupt_signal
      function c_ignore_file_size_signal() result(error) bind(C, name='vb_ignore_file_size_signal')
         import :: c_int
         integer(c_int) :: error
      end function c_ignore_file_size_signal
   end interface

contains

   !> Install the SIGINT/SIGTERM/SIGUSR1 handlers and ignore SIGXFSZ. Called by the program
   !! before it creates any file.
   subroutine watch_signals(stat, errmsg)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(c_int) :: error_number
      stat = 0
      errmsg = ''
      error_number = c_ignore_file_size_signal()
      if (error_number == 0) error_number = c_install_interrupt_handlers()
      if (error_number /= 0) then
         stat = stat_failure
         errmsg = 'cannot install the signal handlers: ' // error_text(error_number)
      end if
   end subroutine watch_signals

   !> True once SIGINT, SIGTERM or SIGUSR1 has arrived.
   logical function interrupt_requested()
      interrupt_requested = c_interrupt_signal() /= 0
   end function interrupt_requested

   !> 'SIGINT', 'SIGTERM', 'SIGUSR1' or '' (none yet).
   function interrupt_name() result(name)
      character(len=:), allocatable :: name
      select case (c_interrupt_signal())
      case (sigint)
         name = 'SIGINT'
      case (sigterm)
         name = 'SIGTERM'
      case (sigusr1)
         name = 'SIGUSR1'
      case (0)
         name = ''
      case default
         name = 'a signal'
      end select
   end function interrupt_name
end module vibrobeam_signals
