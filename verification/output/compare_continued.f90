!> Restart check: a run continued from a checkpoint (&initial from_file) must go on
!! exactly as the run that was never stopped. Compares, bit for bit,
!! - every history of CONTINUED.h5 (one row per output time, field snapshot, impact,
!!   episode) with the last rows of the same history in FULL.h5 (the continued run writes
!!   only what follows its checkpoint);
!! - the tip spectrum and the contact fractions, which cover the whole run in both, and
!!   every statistic of /statistics (the window starts before the checkpoint) with its
!!   standard error;
!! - the final states (every item of the final checkpoint) and the step counts.
!! A beam of two planes with obstacles (issue 21): its histories of both planes, the
!! friction's energy, and the wear (/wear and /statistics/wear) too. The statistics'
!! layout is read from FULL.h5 (its points, contact points, obstacles and wear points).
!! The reference is the uninterrupted run itself: no tolerance, equality of bit patterns.
!! usage: compare_continued FULL.h5 CONTINUED.h5
program compare_continued
   use vibrobeam_kinds, only: dp, int64, output_unit
   use vibrobeam_text, only: integer_text
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_state_record, only: state_record
   use vibrobeam_checkpoint, only: read_checkpoint
   use vibrobeam_test_support, only: test_counter
   use vibrobeam_statistics_layout, only: statistics_layout
   implicit none
   character(len=*), parameter :: histories(*) = [character(len=40) :: '/time', '/tip/displacement', &
      '/tip/velocity', '/tip/reaction', '/tip/impulse', '/energy/kinetic', '/energy/elastic', '/energy/total', &
      '/energy/work', '/energy/dissipated', '/energy/dissipated_impacts', '/energy/dissipated_damping', &
      '/energy/dissipated_numerical', '/energy/balance', '/energy/dissipated_friction', &
      '/energy/dissipated_contact_damping', '/energy/contact_potential', '/contact/penetration', '/points/displacement', &
      '/points/velocity', '/field/time', '/field/displacement', '/impacts/time', '/impacts/x', &
      '/impacts/impulse', '/impacts/velocity_before', '/impacts/velocity_after', '/episodes/x', &
      '/episodes/start', '/episodes/end', '/episodes/impulse', '/episodes/approach_speed', '/episodes/impacts', &
      '/episodes/open_at_end', '/statistics/poincare/time', '/statistics/poincare/displacement', &
      '/statistics/poincare/velocity']
   character(len=*), parameter :: wholes(*) = [character(len=40) :: '/spectrum/frequency', &
      '/spectrum/tip_amplitude', '/contact/fraction']
   !> /wear/NAME and NAME_error (a beam of two planes with obstacles)
   character(len=*), parameter :: wear(*) = [character(len=24) :: 'work_rate', 'mean_force', 'rms_force', &
      'contact_fraction', 'sliding_fraction', 'impact_rate', 'wear_volume_rate']
   type(test_counter) :: t
   type(h5_reader) :: full, continued
   type(state_record) :: full_state, continued_state
   character(len=512) :: full_name, continued_name, errmsg
   real(dp), allocatable :: a(:), b(:)
   real(dp) :: time
   integer(int64) :: full_steps, continued_steps, rows_compared
   integer :: k, stat
   type(statistics_layout) :: layout
   integer(int64) :: obstacles

   call get_command_argument(1, full_name)
   call get_command_argument(2, continued_name)
   call full%open(trim(full_name), stat, errmsg)
   if (stat == 0) call continued%open(trim(continued_name), stat, errmsg)
   call t%check_true('open both files', stat == 0, errmsg)
   if (stat /= 0) call t%finish('compare_continued')

   rows_compared = 0
   do k = 1, size(histories)
      call compare_tail(trim(histories(k)))
   end do
   do k = 1, size(wholes)
      call compare_whole(trim(wholes(k)))
   end do
   do k = 1, size(wear)
      if (.not. full%exists('/wear/'//trim(wear(k)))) cycle
      call compare_whole('/wear/'//trim(wear(k)))
      call compare_whole('/wear/'//trim(wear(k))//'_error')
   end do
   ! the statistics' layout of the full run
   call full%attr_int64('/', 'obstacles.count', obstacles, stat, errmsg)
   call t%check_true('read the obstacles'' count', stat == 0, errmsg)
   call layout%init(entries('/statistics/points/x'), entries('/statistics/contacts/x'), int(obstacles), &
                    entries('/statistics/wear/x'), full%exists('/statistics/wear/wear_volume_rate'), &
                    full%exists('/statistics/energy/power_friction'))
   do k = 1, size(layout%entries)
      call compare_whole('/statistics/'//layout%path(k, .false.))
      if (layout%entries(k)%has_error) call compare_whole('/statistics/'//layout%path(k, .true.))
   end do
   call full%attr_int64('/run', 'steps', full_steps, stat, errmsg)
   if (stat == 0) call continued%attr_int64('/run', 'steps', continued_steps, stat, errmsg)
   call t%check_true('read /run steps', stat == 0, errmsg)
   call t%check_true('both runs end at the same step', full_steps == continued_steps, &
                     integer_text(int(full_steps))//' and '//integer_text(int(continued_steps)))
   call full%close()
   call continued%close()

   ! the final state: every item of the final checkpoint
   call read_checkpoint(trim(full_name), full_state, time, stat, errmsg)
   if (stat == 0) call read_checkpoint(trim(continued_name), continued_state, time, stat, errmsg)
   call t%check_true('read both final checkpoints', stat == 0, errmsg)
   if (stat == 0) then
      call t%check_true('the final checkpoints hold the same items', full_state%count == continued_state%count)
      do k = 1, min(full_state%count, continued_state%count)
         associate (x => full_state%items(k), y => continued_state%items(k))
            if (x%integers) then
               call t%check_true('final state '//trim(x%name), y%integers .and. size(x%int64s) == size(y%int64s))
               if (y%integers .and. size(x%int64s) == size(y%int64s)) &
                  call t%check_true('final state '//trim(x%name)//' equal', all(x%int64s == y%int64s))
            else
               call t%check_true('final state '//trim(x%name)//' equal', &
                                 .not. y%integers .and. same_bits(x%reals, y%reals))
            end if
         end associate
      end do
   end if
   write (output_unit, '(a,i0,a,i0,a)') 'compared ', rows_compared, ' rows of ', size(histories), &
      ' histories and the final state bit for bit'
   call t%finish('compare_continued')

contains

   !> Number of values of the dataset `path` of the full run (0 when it has none).
   integer function entries(path)
      character(len=*), intent(in) :: path
      entries = 0
      if (.not. full%exists(path)) return
      call full%read_reals(path, a, stat, errmsg)
      call t%check_true('read '//path, stat == 0, errmsg)
      if (stat == 0) entries = size(a)
   end function entries

   !> Dataset `path` is the same in both files.
   subroutine compare_whole(path)
      character(len=*), intent(in) :: path
      call full%read_reals(path, a, stat, errmsg)
      if (stat == 0) call continued%read_reals(path, b, stat, errmsg)
      call t%check_true('read '//path, stat == 0, errmsg)
      if (stat == 0) call t%check_true(path//' equals that of the uninterrupted run', same_bits(a, b), 'differs')
   end subroutine compare_whole

   !> The rows of `path` in the continued run equal the last rows of the full run.
   subroutine compare_tail(path)
      character(len=*), intent(in) :: path
      integer(int64), allocatable :: full_dims(:), continued_dims(:)
      real(dp), allocatable :: x(:, :), y(:, :)
      integer(int64) :: rows, first
      integer :: columns
      if (.not. continued%exists(path)) then
         call t%check_true(path//' in both files', .not. full%exists(path), 'only in '//trim(full_name))
         return
      end if
      call full%shape(path, full_dims, stat, errmsg)
      if (stat == 0) call continued%shape(path, continued_dims, stat, errmsg)
      call t%check_true('shape of '//path, stat == 0, errmsg)
      if (stat /= 0) return
      rows = continued_dims(size(continued_dims))
      ! a row of a 2-d or 3-d history: every value of its inner dimensions
      columns = int(product(continued_dims(1:size(continued_dims) - 1)))
      call t%check_true(path//': the continued run has no more rows than the full run', &
                        rows <= full_dims(size(full_dims)))
      if (rows == 0 .or. rows > full_dims(size(full_dims))) return
      first = full_dims(size(full_dims)) - rows + 1
      allocate (x(columns, rows), y(columns, rows))
      call full%read_rows(path, first, x, stat, errmsg)
      if (stat == 0) call continued%read_rows(path, 1_int64, y, stat, errmsg)
      call t%check_true('read '//path, stat == 0, errmsg)
      if (stat /= 0) return
      call t%check_true(path//' ('//integer_text(int(rows))//' rows) equals the end of the uninterrupted run', &
                        same_bits(reshape(x, [size(x)]), reshape(y, [size(y)])), 'differs')
      rows_compared = rows_compared + rows
   end subroutine compare_tail

   !> Equal bit patterns (NaNs and signed zeros included).
   pure logical function same_bits(x, y)
      real(dp), intent(in) :: x(:), y(:)
      same_bits = size(x) == size(y)
      if (same_bits) same_bits = all(transfer(x, 1_int64, size(x)) == transfer(y, 1_int64, size(y)))
   end function same_bits
end program compare_continued
