!> What the derivers of a result's .dat files share (docs/output.md, "Text files";
!! `vibrobeam_text_output`, `vibrobeam_sweep_text`): the open HDF5 file and the name its
!! text files follow (`derivation`), and one .dat file being written (`text_sink`): its
!! header, its lines and rows, every write checked, and rows streamed from datasets a
!! block at a time, so that a long run's text files need no more memory than a short
!! run's.
!!
!! Names follow the HDF5 file: results/run.h5 gives results/run_tip.dat, ...
!! (`text_file_name`). Each file is written under its own temporary name
!! (`vibrobeam_text_file`), closed and synced; the caller renames the set
!! (`vibrobeam_result_files: publish_files`). Line 1 of each file names the run
!! ('# vibrobeam run <run_id> (<file>.h5)', the /run run_id attribute), line 2 its
!! columns and units.
module vibrobeam_text_derivation
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: integer_text
   use vibrobeam_hdf5_reader, only: h5_reader
   use vibrobeam_text_file, only: text_file, open_text_for_atomic_write, write_text_line, write_text_row, &
      finish_text_file, discard_text_file
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   implicit none
   private
   public :: derivation, text_sink, derived_file, text_file_name, discard_derived, path_length, block_values

   integer, parameter :: path_length = 1024

   !> Most values read from the HDF5 file at once (8 MiB).
   integer, parameter :: block_values = 2**20

   !> A derived file, complete under its temporary name.
   type :: derived_file
      character(len=path_length) :: temporary = ''
      character(len=path_length) :: final = ''
   end type derived_file

   !> The derivation of one result's text files.
   type :: derivation
      type(h5_reader) :: file                        !! the result, open
      character(len=:), allocatable :: final_h5      !! the name the text files follow
      character(len=:), allocatable :: header        !! line 1 of every file
      type(progress_meter) :: meter
      !> SIGINT/SIGTERM stops the derivation (`interrupted`)
      logical :: stop_on_signal = .false.
      logical :: interrupted = .false.
      type(derived_file), allocatable :: files(:)    !! the files complete so far
   contains
      procedure :: open_sink
      procedure :: close_sink
      procedure :: stream_rows
      procedure :: rows_of
      procedure :: check_signal
   end type derivation

   !> One .dat file being written.
   type :: text_sink
      type(text_file) :: file
      character(len=:), allocatable :: temporary, final
   contains
      procedure :: put_line
      procedure :: put_row
   end type text_sink

contains

   !> '<stem>_<suffix>.dat' for a result file 'stem.h5'.
   pure function text_file_name(h5_name, suffix) result(name)
      character(len=*), intent(in) :: h5_name, suffix
      character(len=:), allocatable :: name
      integer :: n
      n = len_trim(h5_name)
      if (n > 3) then
         if (h5_name(n - 2:n) == '.h5') n = n - 3
      end if
      name = h5_name(1:n)//'_'//suffix//'.dat'
   end function text_file_name

   !> Delete the temporary files of `files`.
   subroutine discard_derived(files)
      type(derived_file), intent(in) :: files(:)
      integer :: k
      type(text_file) :: closed
      do k = 1, size(files)
         call discard_text_file(closed, trim(files(k)%temporary))
      end do
   end subroutine discard_derived

   !> Open '<stem>_<suffix>.dat' with its two header lines.
   subroutine open_sink(self, sink, suffix, columns, stat, errmsg)
      class(derivation), intent(inout) :: self
      type(text_sink), intent(out) :: sink
      character(len=*), intent(in) :: suffix, columns
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      sink%final = text_file_name(self%final_h5, suffix)
      call open_text_for_atomic_write(sink%final, sink%file, sink%temporary, stat, errmsg)
      if (stat /= 0) return
      call sink%put_line(self%header, stat, errmsg)
      if (stat == 0) call sink%put_line('# '//columns, stat, errmsg)
      if (self%meter%due()) call self%meter%report('deriving '//sink%final)
   end subroutine open_sink

   !> Close and sync `sink` and add it to the files done. stat: in, the outcome of its
   !! writes; when it is not 0, or closing fails, the file is deleted instead.
   subroutine close_sink(self, sink, stat, errmsg)
      class(derivation), intent(inout) :: self
      type(text_sink), intent(inout) :: sink
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      type(derived_file) :: done
      if (stat == 0) call finish_text_file(sink%file, sink%temporary, stat, errmsg)
      if (stat /= 0) then
         call discard_text_file(sink%file, sink%temporary)
         return
      end if
      done%temporary = sink%temporary
      done%final = sink%final
      self%files = [self%files, done]
   end subroutine close_sink

   !> Write one line, checked.
   subroutine put_line(self, line, stat, errmsg)
      class(text_sink), intent(inout) :: self
      character(len=*), intent(in) :: line
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call write_text_line(self%file, line, self%temporary, stat, errmsg)
   end subroutine put_line

   !> Write one row of numbers (`layout`: 'wide' es24.15-like, 'narrow' es16.7-like;
   !! the last `integers` values as integers), checked.
   subroutine put_row(self, layout, values, stat, errmsg, integers)
      class(text_sink), intent(inout) :: self
      character(len=*), intent(in) :: layout
      real(dp), intent(in) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: integers
      integer :: tail
      tail = 0
      if (present(integers)) tail = integers
      if (layout == 'narrow') then
         call write_text_row(self%file, values, 16, 7, tail, self%temporary, stat, errmsg)
      else
         call write_text_row(self%file, values, 24, 15, tail, self%temporary, stat, errmsg)
      end if
   end subroutine put_row

   !> Rows of the datasets `paths` (each 1-d of `rows` values, or 2-d of
   !! widths(k) columns) side by side, `form` per row (`put_row`), a block of rows at a
   !! time; stops early when interrupted (`check_signal`).
   subroutine stream_rows(self, sink, paths, widths, rows, form, stat, errmsg, integers, order)
      class(derivation), intent(inout) :: self
      type(text_sink), intent(inout) :: sink
      character(len=*), intent(in) :: paths(:)
      integer, intent(in) :: widths(:)
      integer(int64), intent(in) :: rows
      character(len=*), intent(in) :: form
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer, intent(in), optional :: integers
      !> the columns of a row in the order written (a permutation of 1..sum(widths));
      !! absent: as read
      integer, intent(in), optional :: order(:)
      real(dp), allocatable :: block(:, :), part(:, :)
      integer(int64) :: first
      integer :: count, k, column, i
      stat = 0
      errmsg = ''
      count = int(max(1_int64, min(rows, int(block_values/max(1, sum(widths)), int64))))
      allocate (block(sum(widths), count))
      first = 1
      do while (first <= rows .and. stat == 0)
         count = int(min(int(size(block, 2), int64), rows - first + 1))
         column = 1
         do k = 1, size(paths)
            allocate (part(widths(k), count))
            call self%file%read_rows(trim(paths(k)), first, part, stat, errmsg)
            if (stat /= 0) return
            block(column:column + widths(k) - 1, 1:count) = part
            column = column + widths(k)
            deallocate (part)
         end do
         do i = 1, count
            if (present(order)) then
               call sink%put_row(form, block(order, i), stat, errmsg, integers)
            else
               call sink%put_row(form, block(:, i), stat, errmsg, integers)
            end if
            if (stat /= 0) return
         end do
         first = first + count
         if (self%check_signal()) return
         if (self%meter%due()) call self%meter%report('deriving '//sink%final//': '// &
                                                      integer_text(int(100*(first - 1)/max(rows, 1_int64)))//' %')
      end do
   end subroutine stream_rows

   !> Rows of the dataset `path` (its last dimension; 0 when it is missing).
   subroutine rows_of(self, path, rows, stat, errmsg)
      class(derivation), intent(in) :: self
      character(len=*), intent(in) :: path
      integer(int64), intent(out) :: rows
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64), allocatable :: dims(:)
      rows = 0
      stat = 0
      errmsg = ''
      if (.not. self%file%exists(path)) return
      call self%file%shape(path, dims, stat, errmsg)
      if (stat == 0 .and. size(dims) > 0) rows = dims(size(dims))
   end subroutine rows_of

   !> With stop_on_signal, whether SIGINT/SIGTERM arrived (then `interrupted` is set).
   logical function check_signal(self)
      class(derivation), intent(inout) :: self
      if (self%stop_on_signal .and. interrupt_requested()) self%interrupted = .true.
      check_signal = self%interrupted
   end function check_signal
end module vibrobeam_text_derivation
