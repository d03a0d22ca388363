!> Checkpoints in the result file and restart from them (docs/output.md, "Checkpoint and
!! restart").
!!
!! Layout: /checkpoint/state_1/<item> and, when checkpoints are also written during the
!! run (&output checkpoint_seconds > 0), /checkpoint/state_2/<item>: one 1-d dataset per
!! item of a `state_record` (reals as doubles, integers as 64-bit integers). Each slot
!! group carries the attribute `checksum`, the CRC-64 of its state (`record_checksum`).
!! The attributes of /checkpoint say which slot holds the latest complete state: `current`
!! (0: none yet, 1 or 2), its `step` and `time` (s), and `items` (the item names, each
!! followed by ':r' or ':i', separated by blanks). A new checkpoint goes into the slot
!! that is not current, with its checksum; only after its data are flushed does `current`
!! change (and is flushed), so a run killed at any moment leaves `current` pointing at a
!! complete state. The datasets are created once, before the file enters SWMR mode, and
!! rewritten in place.
!!
!! Restart (`read_checkpoint`): `&initial from_file` names a result file (published, or
!! the temporary file of a killed run); its checkpoint is read only when its checksum
!! matches the state (one without a checksum, written by vibrobeam 0.2.0, is read and
!! reported as not verified). Whether a scene may continue it is
!! `vibrobeam_restart_check`'s question.
module vibrobeam_checkpoint
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text, real_text
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_hdf5_series, only: h5_array
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_state_record, only: state_record, state_item
   use vibrobeam_checksum, only: crc64_start, crc64_words, crc64_text, crc64_finish
   implicit none
   private
   public :: checkpoint_slots, read_checkpoint, record_checksum, no_checkpoint, same_bits

   !> The checkpoint datasets of an open result file.
   type :: checkpoint_slots
      integer :: slots = 0                           !! 1 or 2
      integer :: current = 0                         !! slot of the latest complete state
      type(h5_array), allocatable :: arrays(:, :)    !! (items, slots)
   contains
      procedure :: create => slots_create
      procedure :: write => slots_write
      procedure :: close => slots_close
   end type checkpoint_slots

contains

   !> Create `slots` slots (1 or 2) for records shaped like `record`.
   subroutine slots_create(self, writer, record, slots, stat, errmsg)
      class(checkpoint_slots), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      type(state_record), intent(in) :: record
      integer, intent(in) :: slots
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: items
      integer :: k, s
      self%slots = slots
      self%current = 0
      allocate (self%arrays(record%count, slots))
      items = ''
      stat = 0
      do k = 1, record%count
         associate (item => record%items(k))
            items = items//trim(item%name)//merge(':i', ':r', item%integers)//' '
            do s = 1, slots
               call self%arrays(k, s)%create(writer, slot_path(s)//'/'//trim(item%name), item_size(item), &
                                             item%integers, stat, errmsg)
               if (stat /= 0) return
            end do
         end associate
      end do
      do s = 1, slots
         call writer%attr_int64(slot_path(s), 'checksum', 0_int64, stat, errmsg)
         if (stat /= 0) return
      end do
      call writer%attr_string('/checkpoint', 'items', trim(items), stat, errmsg)
      if (stat == 0) call writer%attr_int64('/checkpoint', 'current', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_int64('/checkpoint', 'step', 0_int64, stat, errmsg)
      if (stat == 0) call writer%attr_real('/checkpoint', 'time', 0.0_dp, stat, errmsg)
   end subroutine slots_create

   !> Write `record` (shaped as at `create`) of step `step`, time `time` and its checksum
   !! into the slot that is not current, flush, then make it current and flush again.
   subroutine slots_write(self, writer, record, step, time, stat, errmsg)
      class(checkpoint_slots), intent(inout) :: self
      type(h5_writer), intent(inout) :: writer
      type(state_record), intent(in) :: record
      integer(int64), intent(in) :: step
      real(dp), intent(in) :: time
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: k, slot
      slot = 1
      if (self%slots == 2 .and. self%current == 1) slot = 2
      do k = 1, record%count
         associate (item => record%items(k))
            if (item%integers) then
               call self%arrays(k, slot)%write_int64s(item%int64s, stat, errmsg)
            else
               call self%arrays(k, slot)%write_reals(item%reals, stat, errmsg)
            end if
         end associate
         if (stat /= 0) return
      end do
      call writer%rewrite_attr(slot_path(slot), 'checksum', record_checksum(record), stat, errmsg)
      if (stat == 0) call writer%flush(stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/checkpoint', 'current', int(slot, int64), stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/checkpoint', 'step', step, stat, errmsg)
      if (stat == 0) call writer%rewrite_attr('/checkpoint', 'time', time, stat, errmsg)
      if (stat == 0) call writer%flush(stat, errmsg)
      if (stat == 0) self%current = slot
   end subroutine slots_write

   !> Close the datasets.
   subroutine slots_close(self)
      class(checkpoint_slots), intent(inout) :: self
      integer :: k, s
      if (.not. allocated(self%arrays)) return
      do s = 1, size(self%arrays, 2)
         do k = 1, size(self%arrays, 1)
            call self%arrays(k, s)%close()
         end do
      end do
   end subroutine slots_close

   !> The CRC-64 (`vibrobeam_checksum`) of a state: for each item in order, its name's
   !! length and characters, its type (0 reals, 1 integers), its size and its values (a
   !! real's bit pattern), so that a changed bit, name, type or size changes it.
   pure integer(int64) function record_checksum(record)
      type(state_record), intent(in) :: record
      integer(int64) :: crc
      integer :: k
      crc = crc64_start()
      do k = 1, record%count
         associate (item => record%items(k))
            call crc64_words(crc, [int(len_trim(item%name), int64)])
            call crc64_text(crc, trim(item%name))
            if (item%integers) then
               call crc64_words(crc, [1_int64, int(size(item%int64s), int64)])
               call crc64_words(crc, item%int64s)
            else
               call crc64_words(crc, [0_int64, int(size(item%reals), int64)])
               call crc64_words(crc, transfer(item%reals, 0_int64, size(item%reals)))
            end if
         end associate
      end do
      record_checksum = crc64_finish(crc)
   end function record_checksum

   !> True when a and b have the same bits (the file stores every value exactly).
   elemental logical function same_bits(a, b)
      real(dp), intent(in) :: a, b
      same_bits = transfer(a, 1_int64) == transfer(b, 1_int64)
   end function same_bits

   pure function slot_path(slot) result(path)
      integer, intent(in) :: slot
      character(len=:), allocatable :: path
      path = '/checkpoint/state_'//integer_text(slot)
   end function slot_path

   pure integer function item_size(item)
      type(state_item), intent(in) :: item
      if (item%integers) then
         item_size = size(item%int64s)
      else
         item_size = size(item%reals)
      end if
   end function item_size

   !> Read the latest complete checkpoint of `filename` into `record`; `time` is its time.
   !! The state must match the checksum of its slot (stat = stat_failure otherwise: the file is
   !! damaged); `verified` (optional) is false when the slot carries no checksum (a file of
   !! vibrobeam 0.2.0), which is read unverified.
   subroutine read_checkpoint(filename, record, time, stat, errmsg, verified)
      character(len=*), intent(in) :: filename
      type(state_record), intent(out) :: record
      real(dp), intent(out) :: time
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(out), optional :: verified
      type(h5_reader) :: file
      character(len=:), allocatable :: items, name
      integer(int64) :: current, checksum
      integer :: start, finish
      time = 0
      if (present(verified)) verified = .false.
      call file%open(filename, stat, errmsg)
      if (stat /= 0) return
      read_items: block
         if (.not. file%exists('/checkpoint')) then
            call no_checkpoint(filename, stat, errmsg)
            exit read_items
         end if
         call file%attr_int64('/checkpoint', 'current', current, stat, errmsg)
         if (stat == 0) call file%attr_string('/checkpoint', 'items', items, stat, errmsg)
         if (stat == 0) call file%attr_real('/checkpoint', 'time', time, stat, errmsg)
         if (stat /= 0) exit read_items
         if (current < 1 .or. current > 2) then
            stat = stat_failure
            errmsg = '''' // trim(filename) // ''' holds no complete checkpoint yet'
            exit read_items
         end if
         start = 1
         do while (start <= len(items))
            finish = index(items(start:), ' ')
            if (finish == 0) finish = len(items) - start + 2
            name = items(start:start + finish - 2)
            start = start + finish
            if (len(name) < 3) cycle
            call read_item(name(1:len(name) - 2), name(len(name):len(name)) == 'i')
            if (stat /= 0) exit read_items
         end do
         if (.not. file%has_attr(slot_path(int(current)), 'checksum')) exit read_items
         call file%attr_int64(slot_path(int(current)), 'checksum', checksum, stat, errmsg)
         if (stat /= 0) exit read_items
         if (checksum /= record_checksum(record)) then
            stat = stat_failure
            errmsg = 'its latest checkpoint (/checkpoint/state_'//integer_text(int(current))//', t = '// &
                     real_text(time)//' s) fails its checksum: the file is damaged and cannot be continued '// &
                     '(continue an undamaged copy, or run again)'
            exit read_items
         end if
         if (present(verified)) verified = .true.
      end block read_items
      call file%close()
   contains
      subroutine read_item(item_name, integers)
         character(len=*), intent(in) :: item_name
         logical, intent(in) :: integers
         real(dp), allocatable :: reals(:)
         integer(int64), allocatable :: int64s(:)
         character(len=:), allocatable :: path
         path = slot_path(int(current))//'/'//item_name
         if (integers) then
            call file%read_int64s(path, int64s, stat, errmsg)
            if (stat == 0) call record%put_int64s(item_name, int64s)
         else
            call file%read_reals(path, reals, stat, errmsg)
            if (stat == 0) call record%put_reals(item_name, reals)
         end if
      end subroutine read_item
   end subroutine read_checkpoint

   !> stat = stat_failure: `filename` is no result of a dynamics run.
   subroutine no_checkpoint(filename, stat, errmsg)
      character(len=*), intent(in) :: filename
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = stat_failure
      errmsg = '''' // trim(filename) // ''' holds no checkpoint (not a dynamics result of vibrobeam 0.2 or later)'
   end subroutine no_checkpoint

end module vibrobeam_checkpoint
