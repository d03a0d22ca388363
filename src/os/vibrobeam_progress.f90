!> Progress reports on stderr (docs/output.md, "Progress"): at most one per
!! `report_interval` seconds of wall time, only when stderr is a terminal or the scene
!! asks for them (&output progress = .true.). On a terminal each report overwrites the
!! previous one ('\r'); into a file each is a whole line ending in a newline, so a log
!! reads line by line. Used by the time loop, the publication and the text derivation.
module vibrobeam_progress
   use, intrinsic :: iso_c_binding, only: c_int
   use vibrobeam_kinds, only: dp, int64, error_unit
   implicit none
   private
   public :: progress_meter, report_interval

   !> Shortest wall time between two reports (s).
   real(dp), parameter :: report_interval = 1

   type :: progress_meter
      logical :: enabled = .false.
      logical :: terminal = .false.
      logical :: open_line = .false.        !! a '\r' report is on screen
      integer(int64) :: rate = 1, start = 0, last = 0
   contains
      procedure :: init => meter_init
      procedure :: due => meter_due
      procedure :: report => meter_report
      procedure :: elapsed => meter_elapsed
      procedure :: end_line => meter_end_line
   end type progress_meter

   interface
      function c_isatty(fd) result(flag) bind(C, name='isatty')
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: flag
      end function c_isatty
   end interface

contains

   !> Start the clock; report when stderr is a terminal or `requested`.
   subroutine meter_init(self, requested)
      class(progress_meter), intent(inout) :: self
      logical, intent(in) :: requested
      self%terminal = c_isatty(2_c_int) == 1
      self%enabled = requested .or. self%terminal
      self%open_line = .false.
      call system_clock(self%start, self%rate)
      self%last = self%start
   end subroutine meter_init

   !> True when a report is wanted now (enabled, and `report_interval` since the last).
   logical function meter_due(self)
      class(progress_meter), intent(in) :: self
      integer(int64) :: now
      meter_due = .false.
      if (.not. self%enabled) return
      call system_clock(now)
      meter_due = real(now - self%last, dp) >= report_interval*self%rate
   end function meter_due

   !> Print 'vibrobeam: text' (a '\r' line on a terminal, a whole line otherwise).
   subroutine meter_report(self, text)
      class(progress_meter), intent(inout) :: self
      character(len=*), intent(in) :: text
      if (.not. self%enabled) return
      call system_clock(self%last)
      if (self%terminal) then
         write (error_unit, '(a)', advance='no') achar(13) // 'vibrobeam: ' // text // achar(27) // '[K'
         self%open_line = .true.
      else
         write (error_unit, '(a)') 'vibrobeam: ' // text
      end if
      flush (error_unit)
   end subroutine meter_report

   !> Wall time since `init` (s).
   function meter_elapsed(self) result(seconds)
      class(progress_meter), intent(in) :: self
      real(dp) :: seconds
      integer(int64) :: now
      call system_clock(now)
      seconds = real(now - self%start, dp)/self%rate
   end function meter_elapsed

   !> End the '\r' line on a terminal before other messages are printed.
   subroutine meter_end_line(self)
      class(progress_meter), intent(inout) :: self
      if (self%open_line) write (error_unit, '(a)') ''
      self%open_line = .false.
      flush (error_unit)
   end subroutine meter_end_line
end module vibrobeam_progress
