!> The partial directory of a sweep (docs/sweeps.md, "Resuming a sweep"): `FILE.partial`
!! beside the sweep file `FILE` holds, while the sweep runs and after it was killed or
!! interrupted, the journals of the points done (`vibrobeam_sweep_journal`, one per
!! process and run), the keep_runs point files of those points (`pointNNNN.h5`) and the
!! file `lock`, which the running sweep holds (flock) from start to publication, so that
!! two sweeps never write one sweep file at once.
!!
!! A rerun of the same input (the same `fingerprint`) finds the journals and runs only the
!! points they do not hold as done; a partial directory of another input is refused, and
!! the directory is removed once its sweep is published complete.
!!
!! The fingerprint is a 64-bit hash (two FNV-1a 32-bit hashes, 16 hexadecimal digits) of
!! what decides the points' results: the program version, every resolved input value but
!! those that do not change a point (output.file, output.text, output.progress, time.t_end,
!! output.measure_from; initial.from_file is replaced by the start state read from it),
!! the sweep's settings with the bit patterns of its values, and the bits of that start
!! state.
module vibrobeam_sweep_partial
   use vibrobeam_status, only: stat_failure, stat_invalid_input
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   use vibrobeam_version, only: version_string
   use vibrobeam_scene, only: scene_type, scene_entry, scene_entries
   use vibrobeam_filesystem, only: make_parent_directories, directory_lock, remove_file, file_exists, &
      temporary_suffix
   use vibrobeam_directory_entries, only: directory_listing, touch_file, remove_directory
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_sweep_settings, only: sweep_settings
   use vibrobeam_sweep_runner, only: 
   use vibrobeam_time_stepper, only: dynamic_state
   use vibrobeam_sweep_journal, only: done_none, done_ok, done_failed, message_words
   implicit none
   private
   public :: sweep_partial, partial_directory, sweep_fingerprint, partial_point_file

   !> Points read at a time when the done flags are indexed.
   integer, parameter :: index_block = 4096

   !> One journal found in the partial directory.
   type :: journal_found
      character(len=:), allocatable :: name
      integer :: generation = 0
      type(h5_reader) :: reader
   end type journal_found

   !> A sweep's partial directory, open.
   type :: sweep_partial
      character(len=:), allocatable :: directory
      type(directory_lock) :: lock
      logical :: existed = .false.          !! it was there before this run
      logical :: busy = .false.             !! another process holds its lock (`inspect`)
      type(journal_found), allocatable :: journals(:)
      integer :: generation = 0             !! the highest generation of its journals
      character(len=:), allocatable :: notes   !! journals removed as unreadable, one line each
   contains
      procedure :: open => partial_open
      procedure :: inspect => partial_inspect
      procedure :: index => partial_index
      procedure :: read_records => partial_read_records
      procedure :: read_message => partial_read_message
      procedure :: read_poincare => partial_read_poincare
      procedure :: read_chunks => partial_read_chunks
      procedure :: read_state => partial_read_state
      procedure :: journal_label => partial_journal_label
      procedure :: reload => partial_reload
      procedure :: close => partial_close
      procedure :: remove => partial_remove
   end type sweep_partial

contains

   !> 'results/run.h5.partial' for the sweep file 'results/run.h5'.
   pure function partial_directory(file) result(directory)
      character(len=*), intent(in) :: file
      character(len=:), allocatable :: directory
      directory = trim(file)//'.partial'
   end function partial_directory

   !> The keep_runs file of point k in the partial directory: 'pointNNNN.h5' (at least 4 digits).
   pure function partial_point_file(directory, k) result(name)
      character(len=*), intent(in) :: directory
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      character(len=16) :: digits
      write (digits, '(i4.4)') k
      name = directory//'/point'//trim(digits)//'.h5'
   end function partial_point_file

   !> Create (when missing), lock and read the partial directory of the sweep file `file`
   !! for a run: stat = stat_failure when another process holds it (a sweep running into `file`) or
   !! it cannot be made, stat = stat_invalid_input when it holds a journal of another input (not
   !! `fingerprint`). Temporary files of point files in progress are removed, and so are
   !! journals that cannot be read (a run killed while creating it: no point in them).
   subroutine partial_open(self, file, fingerprint, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      character(len=*), intent(in) :: file, fingerprint
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical :: busy
      self%directory = partial_directory(file)
      self%existed = file_exists(self%directory)
      call make_parent_directories(self%directory//'/lock', stat, errmsg)
      if (stat == 0) call touch_file(self%directory//'/lock', stat, errmsg)
      if (stat == 0) call self%lock%try_acquire(self%directory//'/lock', busy, stat, errmsg)
      if (stat /= 0) return
      if (busy) then
         stat = stat_failure
         errmsg = 'another vibrobeam process is running a sweep into '''//trim(file)//''' (it holds '''// &
                  self%directory//'/lock''): wait for it to end, or give &output file another name'
         return
      end if
      call read_journals(self, fingerprint, .true., stat, errmsg)
   end subroutine partial_open

   !> Read the partial directory of `file` without changing anything (`vibrobeam --check`):
   !! `existed` false when there is none; `busy` when a running sweep holds it: its
   !! journals are then read as they are now, as a SWMR reader that takes no lock (the
   !! points they hold as done are those the sweep has committed so far; a journal it is
   !! still creating, or one of another input, is left out), and stat /= 0 only when the
   !! directory cannot be listed; otherwise stat = stat_invalid_input when it holds a journal of another
   !! input. With `locked_here` the lock is held by this sweep (rank 0 of an MPI run): the
   !! journals are read without looking at it.
   subroutine partial_inspect(self, file, fingerprint, stat, errmsg, locked_here)
      class(sweep_partial), intent(inout) :: self
      character(len=*), intent(in) :: file, fingerprint
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: locked_here
      type(directory_lock) :: probe
      self%directory = partial_directory(file)
      self%existed = file_exists(self%directory)
      stat = 0
      errmsg = ''
      self%notes = ''
      if (.not. self%existed) then
         allocate (self%journals(0))
         return
      end if
      self%busy = .false.
      if (present(locked_here)) then
         if (locked_here) then
            call read_journals(self, fingerprint, .false., stat, errmsg)
            return
         end if
      end if
      if (file_exists(self%directory//'/lock')) then
         call probe%try_acquire(self%directory//'/lock', self%busy, stat, errmsg)
         call probe%release()
         if (stat /= 0) return
      end if
      call read_journals(self, fingerprint, .false., stat, errmsg, live=self%busy)
   end subroutine partial_inspect

   !> The journals of the directory (see `partial_open`; with `tidy` false nothing is
   !! removed; with `live` those of a running sweep, see `partial_inspect`).
   subroutine read_journals(self, fingerprint, tidy, stat, errmsg, live)
      class(sweep_partial), intent(inout) :: self
      character(len=*), intent(in) :: fingerprint
      logical, intent(in) :: tidy
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: live
      type(directory_listing) :: listing
      logical :: running
      character(len=:), allocatable :: name, their
      character(len=512) :: message
      integer(int64) :: generation
      integer :: ignored
      stat = 0
      errmsg = ''
      running = .false.
      if (present(live)) running = live
      self%notes = ''
      self%generation = 0
      if (allocated(self%journals)) deallocate (self%journals)
      allocate (self%journals(0))
      call listing%open(self%directory, stat, errmsg)
      if (stat /= 0) return
      do while (listing%next(name))
         if (.not. ends_with(name, temporary_suffix)) cycle
         if (.not. starts_with(name, 'journal.h5.')) then
            ! a point file or journal of a process killed while writing it
            if (tidy) call remove_file(self%directory//'/'//name, ignored, message)
            cycle
         end if
         found_one: block
            type(journal_found) :: found   ! a new one each time: the array keeps the open readers
            found%name = self%directory//'/'//name
            call found%reader%open(found%name, stat, message, running)
            if (stat == 0) call found%reader%attr_string('/journal', 'fingerprint', their, stat, message)
            if (stat == 0) call found%reader%attr_int64('/journal', 'generation', generation, stat, message)
            if (running) then
               if (stat == 0) then
                  if (their /= fingerprint) stat = stat_invalid_input
               end if
               if (stat /= 0) then
                  ! a journal the running sweep is still creating, or one of another input
                  call found%reader%close()
                  stat = 0
                  exit found_one
               end if
            end if
            if (stat /= 0) then
               call found%reader%close()
               self%notes = self%notes//'the journal '''//found%name//''' cannot be read ('//trim(message)//')'
               if (tidy) then
                  call remove_file(found%name, ignored, message)
                  self%notes = self%notes//'; it was removed (a run killed as it created it: it holds no point)'
               end if
               self%notes = self%notes//new_line('a')
               stat = 0
               exit found_one
            end if
            if (their /= fingerprint) then
               call found%reader%close()
               stat = stat_invalid_input
               errmsg = '&output file: '''//self%directory//''' holds a partial sweep of another input (a '// &
                        'journal of fingerprint '//their//', this input''s is '//fingerprint//'): rerun that '// &
                        'input to finish it, or remove the directory to start this sweep'
               exit found_one
            end if
            found%generation = int(generation)
            self%generation = max(self%generation, found%generation)
            self%journals = [self%journals, found]
         end block found_one
         if (stat /= 0) exit
      end do
      call listing%close()
   end subroutine read_journals

   !> For every point, the journal that holds it (0: none) and its done flag there: a
   !! point done (ok or failed) in any journal is taken from the newest such journal,
   !! otherwise an interrupted one from the newest journal that holds it.
   subroutine partial_index(self, points, owner, flag, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      integer, intent(in) :: points
      integer, allocatable, intent(out) :: owner(:), flag(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp), allocatable :: block(:, :)
      integer :: j, first, count, k, f
      logical :: better
      allocate (owner(points), flag(points), source=0)
      stat = 0
      errmsg = ''
      do j = 1, size(self%journals)
         do first = 1, points, index_block
            count = min(index_block, points - first + 1)
            if (allocated(block)) deallocate (block)
            allocate (block(1, count))
            call self%journals(j)%reader%read_rows('/journal/done', int(first, int64), block, stat, errmsg)
            if (stat /= 0) return
            do k = first, first + count - 1
               f = nint(block(1, k - first + 1))
               if (f == done_none) cycle
               if (owner(k) == 0) then
                  better = .true.
               else if (done_class(f) /= done_class(flag(k))) then
                  better = done_class(f) > done_class(flag(k))
               else
                  better = self%journals(j)%generation > self%journals(owner(k))%generation
               end if
               if (better) then
                  owner(k) = j
                  flag(k) = f
               end if
            end do
         end do
      end do
   contains
      !> 2 for a point done, 1 for one interrupted.
      pure integer function done_class(f)
         integer, intent(in) :: f
         done_class = merge(2, 1, f == done_ok .or. f == done_failed)
      end function done_class
   end subroutine partial_index

   !> The records of points first .. first + size(records, 2) - 1 from journal j.
   subroutine partial_read_records(self, j, first, records, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      integer, intent(in) :: j, first
      real(dp), intent(out), contiguous :: records(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%journals(j)%reader%read_rows('/journal/record', int(first, int64), records, stat, errmsg)
   end subroutine partial_read_records

   !> The message of point k from journal j.
   subroutine partial_read_message(self, j, k, message, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      integer, intent(in) :: j, k
      character(len=*), intent(out) :: message
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: words(message_words, 1)
      character(len=4*message_words) :: text
      integer :: w
      message = ''
      call self%journals(j)%reader%read_rows('/journal/message', int(k, int64), words, stat, errmsg)
      if (stat /= 0) return
      do w = 1, message_words
         text(4*w - 3:4*w) = transfer(nint(words(w, 1)), 'abcd')
      end do
      message = text
   end subroutine partial_read_message

   !> Rows first_row .. of the Poincare samples of journal j (first_row from 0, as in a record).
   subroutine partial_read_poincare(self, j, first_row, rows, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      integer, intent(in) :: j
      integer(int64), intent(in) :: first_row
      real(dp), intent(out), contiguous :: rows(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%journals(j)%reader%read_rows('/journal/poincare', first_row + 1, rows, stat, errmsg)
   end subroutine partial_read_poincare

   !> The Poincare chunks of journal j (`vibrobeam_sweep_journal`): chunks(:, c) = its
   !! point, first row (from 0) and rows; none when it wrote no samples.
   subroutine partial_read_chunks(self, j, chunks, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      integer, intent(in) :: j
      real(dp), allocatable, intent(out) :: chunks(:, :)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64), allocatable :: dims(:)
      stat = 0
      errmsg = ''
      allocate (chunks(3, 0))
      if (.not. self%journals(j)%reader%exists('/journal/poincare_chunks')) return
      call self%journals(j)%reader%shape('/journal/poincare_chunks', dims, stat, errmsg)
      if (stat /= 0 .or. size(dims) < 2) return
      deallocate (chunks)
      allocate (chunks(3, dims(size(dims))))
      if (size(chunks, 2) > 0) call self%journals(j)%reader%read_rows('/journal/poincare_chunks', 1_int64, chunks, &
                                                                       stat, errmsg)
   end subroutine partial_read_chunks

   !> The state of point k of task `task` from journal j; state%u not allocated when neither
   !! slot of the task holds it there.
   subroutine partial_read_state(self, j, task, k, unknowns, state, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      integer, intent(in) :: j, task, k, unknowns
      type(dynamic_state), intent(out) :: state
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      real(dp) :: slot(2 + 3*unknowns, 1)
      integer :: s
      stat = 0
      errmsg = ''
      if (.not. self%journals(j)%reader%exists('/journal/state')) return
      do s = 1, 2
         call self%journals(j)%reader%read_rows('/journal/state', 2*int(task - 1, int64) + s, slot, stat, errmsg)
         if (stat /= 0) return
         if (nint(slot(1, 1)) /= k) cycle
         state%u = slot(3:2 + unknowns, 1)
         state%v = slot(3 + unknowns:2 + 2*unknowns, 1)
         if (nint(slot(2, 1)) == 1) state%extra = slot(3 + 2*unknowns:, 1)
         return
      end do
   end subroutine partial_read_state

   !> Journal j for messages: its name in the directory and its generation
   !! ('journal.h5.1234-0a1b2c3d.tmp' (generation 2)).
   function partial_journal_label(self, j) result(label)
      class(sweep_partial), intent(in) :: self
      integer, intent(in) :: j
      character(len=:), allocatable :: label
      label = ''''//self%journals(j)%name(len(self%directory) + 2:)//''' (generation '// &
              integer_text(self%journals(j)%generation)//')'
   end function partial_journal_label

   !> Read the journals again (those written since `open` included), keeping the lock.
   subroutine partial_reload(self, fingerprint, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      character(len=*), intent(in) :: fingerprint
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call close_journals(self)
      call read_journals(self, fingerprint, .false., stat, errmsg)
   end subroutine partial_reload

   !> Close the journals and release the lock.
   subroutine partial_close(self)
      class(sweep_partial), intent(inout) :: self
      call close_journals(self)
      call self%lock%release()
   end subroutine partial_close

   subroutine close_journals(self)
      class(sweep_partial), intent(inout) :: self
      integer :: j
      if (allocated(self%journals)) then
         do j = 1, size(self%journals)
            call self%journals(j)%reader%close()
         end do
      end if
   end subroutine close_journals

   !> Remove the directory and everything in it (after its sweep was published complete);
   !! the lock is released last.
   subroutine partial_remove(self, stat, errmsg)
      class(sweep_partial), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(directory_listing) :: listing
      character(len=:), allocatable :: name
      call close_journals(self)
      call listing%open(self%directory, stat, errmsg)
      do while (stat == 0 .and. listing%next(name))
         if (name /= 'lock') call remove_file(self%directory//'/'//name, stat, errmsg)
      end do
      call listing%close()
      if (stat == 0) call remove_file(self%directory//'/lock', stat, errmsg)
      if (stat == 0) call remove_directory(self%directory, stat, errmsg)
      call self%lock%release()
   end subroutine partial_remove

   !> The fingerprint of a sweep (module documentation).
   function sweep_fingerprint(scene, settings, base) result(text)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(dynamic_state), intent(in) :: base
      character(len=16) :: text
      character(len=*), parameter :: ignored(6) = [character(len=24) :: 'output.file', 'output.text', &
         'output.progress', 'time.t_end', 'output.measure_from', 'initial.from_file']
      type(scene_entry), allocatable :: list(:)
      integer(int64) :: first, second
      integer :: k, a
      first = 2166136261_int64    ! FNV-1a 32-bit offset basis
      second = 3735928559_int64   ! another basis for the second half
      call add(version_string)
      allocate (list, source=scene_entries(scene))
      do k = 1, size(list)
         if (any(list(k)%name == ignored)) cycle
         call add(trim(list(k)%name)//'=')
         select case (list(k)%kind)
         case ('real')
            call add_reals([list(k)%real_value])
         case ('integer')
            call add(integer_text(list(k)%integer_value))
         case ('logical')
            call add(merge('T', 'F', list(k)%logical_value))
         case default
            call add(trim(list(k)%string_value))
         end select
      end do
      call add('sweep mode='//trim(settings%mode)//' keep_runs='//merge('T', 'F', settings%keep_runs)// &
               ' poincare_samples='//trim(settings%poincare_samples))
      call add_reals([settings%settle, settings%measure, settings%settle_periods, settings%measure_periods, &
                      settings%steady_tolerance])
      do a = 1, 2
         call add(' parameter='//trim(settings%axis(a)%parameter))
         if (allocated(settings%axis(a)%values)) call add_reals(settings%axis(a)%values)
      end do
      if (allocated(base%u)) then
         call add(' start')
         call add_reals(base%u)
         call add_reals(base%v)
         if (allocated(base%extra)) call add_reals(base%extra)
      end if
      write (text, '(z8.8,z8.8)') first, second
   contains
      !> FNV-1a over the bytes of `bytes` into both hashes (32-bit products fit in 64 bits).
      subroutine add(bytes)
         character(len=*), intent(in) :: bytes
         integer(int64), parameter :: prime = 16777619_int64, mask = 4294967295_int64
         integer :: i
         do i = 1, len(bytes)
            first = iand(ieor(first, int(ichar(bytes(i:i)), int64))*prime, mask)
            second = iand(ieor(second, int(ichar(bytes(i:i)), int64))*prime, mask)
         end do
         ! the two differ in their basis; mix the position into the second
         second = iand(ieor(second, int(len(bytes), int64))*prime, mask)
      end subroutine add

      !> The bit patterns of reals, as hexadecimal text.
      subroutine add_reals(values)
         real(dp), intent(in) :: values(:)
         character(len=16) :: hex
         integer :: i
         do i = 1, size(values)
            write (hex, '(z16.16)') transfer(values(i), 1_int64)
            call add(hex)
         end do
      end subroutine add_reals
   end function sweep_fingerprint

   pure logical function starts_with(text, prefix)
      character(len=*), intent(in) :: text, prefix
      starts_with = .false.
      if (len(text) >= len(prefix)) starts_with = text(1:len(prefix)) == prefix
   end function starts_with

   pure logical function ends_with(text, suffix)
      character(len=*), intent(in) :: text, suffix
      ends_with = .false.
      if (len(text) >= len(suffix)) ends_with = text(len(text) - len(suffix) + 1:) == suffix
   end function ends_with
end module vibrobeam_sweep_partial
