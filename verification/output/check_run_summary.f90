!> The line a dynamics run with compliant stops only prints (docs/output.md, "What a run
!! prints") against its own histories: it names the peak contact force and the time in
!! contact, recomputed here from /contact/force (written at every step, `every` = 1), and
!! neither impacts nor penetration, which only rigid stops have.
!!    usage: check_run_summary SCREEN.txt RESULT.h5
!!
!! Recomputed: the peak force, max |force| over the contact points and the steps; the time
!! in contact, the largest over the contact points of dt times the number of steps after
!! which the force there is nonzero (a compliant point is in contact while its springs
!! push, docs/output.md). Both are printed with 4 significant digits (es10.3): they agree
!! to half a unit of the fourth digit, 5e-4 relative; the share of the run to 0.005 %.
program check_run_summary
   use vibrobeam_kinds, only: dp
   use vibrobeam_hdf5_file_reads, only: read_real_2d, read_attr_real
   use vibrobeam_test_support, only: test_counter
   implicit none
   type(test_counter) :: t
   character(len=4096) :: screen, file
   character(len=1024) :: line
   character(len=512) :: errmsg
   real(dp), allocatable :: force(:, :)
   real(dp) :: dt, t_end, peak, contact_time, printed_peak, printed_time, printed_share
   integer :: unit, stat, c, at
   call get_command_argument(1, screen)
   call get_command_argument(2, file)
   open (newunit=unit, file=trim(screen), status='old', action='read', iostat=stat)
   line = ''
   if (stat == 0) read (unit, '(a)', iostat=stat) line
   call t%check_true('the run printed a line', stat == 0 .and. index(line, 'vibrobeam: ') == 1, trim(line))
   write (*, '(a)') trim(line)
   call read_real_2d(trim(file), '/contact/force', force, stat, errmsg)
   call t%check_true('read /contact/force', stat == 0, errmsg)
   call read_attr_real(trim(file), '/', 'time.dt', dt, stat, errmsg)
   call read_attr_real(trim(file), '/', 'time.t_end', t_end, stat, errmsg)
   if (.not. allocated(force)) call t%finish('check_run_summary')
   peak = maxval(abs(force))
   contact_time = 0
   do c = 1, size(force, 1)
      contact_time = max(contact_time, dt*count(abs(force(c, 2:)) > 0))   ! column n + 1: after step n
   end do
   call t%check_true('compliant stops in contact', contact_time > 0)
   call t%check_true('no impacts nor penetration printed', index(line, 'impacts') == 0 .and. &
                     index(line, 'penetration') == 0, trim(line))
   printed_peak = number_after('peak contact force ')
   printed_time = number_after('in contact ')
   printed_share = number_after(' s (')
   call t%check_close('printed peak contact force (N)', printed_peak, peak, 5e-4_dp)
   call t%check_close('printed time in contact (s)', printed_time, contact_time, 5e-4_dp)
   call t%check_close('printed share of the run in contact (%)', printed_share, 100*contact_time/t_end, 5e-3_dp, 1.0_dp)
   call t%finish('check_run_summary')

contains

   !> The number that follows `label` on the line (-1 when the label is missing).
   real(dp) function number_after(label)
      character(len=*), intent(in) :: label
      integer :: ios
      number_after = -1
      at = index(line, label)
      call t%check_true('printed: '''//label//'''', at > 0, trim(line))
      if (at == 0) return
      read (line(at + len(label):), *, iostat=ios) number_after   ! the first word after it
      call t%check_true('a number after '''//label//'''', ios == 0, trim(line(at:)))
   end function number_after
end program check_run_summary
