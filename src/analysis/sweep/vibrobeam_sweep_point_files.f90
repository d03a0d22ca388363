!> The point files of a sweep's set (docs/sweeps.md, "The sweep file"; `&sweep keep_runs`),
!! published with the sweep file as one step of its publication (`publish_step` of
!! `vibrobeam_result_files`): under the directory lock, each point's result goes from the
!! partial directory onto its name beside the sweep file ('<stem>_pointNNNN.h5',
!! `point_file_name`), and the point files of an earlier sweep of the same name that the
!! new set does not have are removed.
module vibrobeam_sweep_point_files
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: integer_text
   use vibrobeam_result_files, only: publish_step
   use vibrobeam_filesystem, only: directory_of, rename_file, remove_file, file_exists, process_id, temporary_suffix
   use vibrobeam_directory_entries, only: directory_listing, link_file
   use vibrobeam_sweep_runner, only: point_file_name, kept_point_file, point_digits
   implicit none
   private
   public :: point_files

   !> The point files of a sweep's set: from the partial directory onto their names
   !! beside the sweep file, and the point files of an earlier set removed.
   type, extends(publish_step) :: point_files
      character(len=:), allocatable :: file, directory
      logical, allocatable :: has_file(:)   !! (points) the point's file is in the set
      logical :: keep = .false.             !! the partial directory stays: link, do not move
      integer :: missing = 0                !! a point of the set whose file is not there (`prepare`)
   contains
      procedure :: prepare => point_files_prepare
      procedure :: commit => point_files_commit
   end type point_files

contains

   !> Under the directory lock, before the sweep file is renamed: every point file must be
   !! in the partial directory and its name free for a file (not a directory), and when the
   !! partial directory stays its point files get a second name beside their final one
   !! (renamed onto it in `commit`).
   subroutine point_files_prepare(self, stat, errmsg)
      class(point_files), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=256) :: message
      integer :: k, j, ignored
      stat = 0
      errmsg = ''
      do k = 1, size(self%has_file)
         if (.not. self%has_file(k)) cycle
         if (file_exists(point_file_name(self%file, k)//'/')) then
            stat = stat_failure
            errmsg = 'cannot publish '''//point_file_name(self%file, k)//''': it is a directory'
         else if (.not. file_exists(kept_point_file(self%directory, k))) then
            stat = stat_failure
            self%missing = k
            errmsg = 'cannot publish the result of point '//integer_text(k)//': '''// &
                     kept_point_file(self%directory, k)//''' is missing ('//partial_contents(self, k)//')'
         else if (self%keep) then
            call remove_file(linked_name(self%file, k), ignored, message)
            call link_file(kept_point_file(self%directory, k), linked_name(self%file, k), stat, errmsg)
         end if
         if (stat /= 0) then
            ! take back the names given so far: nothing is published
            do j = 1, k - 1
               if (self%has_file(j)) call remove_file(linked_name(self%file, j), ignored, message)
            end do
            return
         end if
      end do
   end subroutine point_files_prepare

   !> What the partial directory holds of the set when the file of point k is missing, for
   !! the message: 'the directory holds 4 of the 5 point files of the set (missing: 5), no
   !! temporary file of point 5' (or the temporary files of point k there: never renamed).
   function partial_contents(self, k) result(text)
      class(point_files), intent(in) :: self
      integer, intent(in) :: k
      character(len=:), allocatable :: text, name, base, temporaries, absent
      type(directory_listing) :: listing
      logical, allocatable :: found(:)
      character(len=256) :: message
      integer :: j, stat, shown
      allocate (found(size(self%has_file)), source=.false.)
      base = kept_point_file(self%directory, k)
      base = base(len(self%directory) + 2:)   ! 'point0005.h5'
      temporaries = ''
      call listing%open(self%directory, stat, message)
      if (stat /= 0) then
         text = trim(message)
         return
      end if
      do while (listing%next(name))
         j = point_index(name, 'point')
         if (j >= 1 .and. j <= size(found)) then
            found(j) = .true.
         else if (index(name, base//'.') == 1 .and. index(name, temporary_suffix, back=.true.) == &
                  len(name) - len(temporary_suffix) + 1) then
            temporaries = temporaries//merge(', ', '  ', len(temporaries) > 0)//''''//name//''''
         end if
      end do
      call listing%close()
      absent = ''
      shown = 0
      do j = 1, size(found)
         if (.not. self%has_file(j) .or. found(j)) cycle
         shown = shown + 1
         if (shown <= 8) absent = absent//merge(', ', '  ', shown > 1)//integer_text(j)
      end do
      if (shown > 8) absent = absent//', ...'
      text = 'the directory holds '//integer_text(count(found .and. self%has_file))//' of the '// &
             integer_text(count(self%has_file))//' point files of the set (missing: '//absent(3:)//'), '
      if (len(temporaries) == 0) then
         text = text//'no temporary file of point '//integer_text(k)
      else
         text = text//'temporary files of point '//integer_text(k)//': '//temporaries(3:)
      end if
   end function partial_contents

   !> The second name point k's file gets beside its final one when the partial directory
   !! stays ('<point file>.<pid>-set.tmp').
   function linked_name(file, k) result(name)
      character(len=*), intent(in) :: file
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      name = point_file_name(file, k)//'.'//integer_text(process_id())//'-set'//temporary_suffix
   end function linked_name

   !> Under the directory lock, after the sweep file was renamed: every point file onto its
   !! name, then the point files of an earlier set that this one does not have removed
   !! ('<stem>_point<k>.h5' for a k without a file here).
   subroutine point_files_commit(self, stat, errmsg)
      class(point_files), intent(inout) :: self
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(directory_listing) :: listing
      character(len=:), allocatable :: name, directory, prefix, stem
      character(len=256) :: message
      integer :: k, ignored, slash
      stat = 0
      errmsg = ''
      do k = 1, size(self%has_file)
         if (.not. self%has_file(k)) cycle
         if (self%keep) then
            call rename_file(linked_name(self%file, k), point_file_name(self%file, k), stat, errmsg)
         else
            call rename_file(kept_point_file(self%directory, k), point_file_name(self%file, k), stat, errmsg)
         end if
         if (stat /= 0) then
            errmsg = 'the sweep file is published but not all its point files: '//trim(errmsg)
            return
         end if
      end do
      ! stale members of an earlier set
      directory = directory_of(self%file)
      stem = point_file_name(self%file, 1)
      slash = index(stem, '/', back=.true.)
      prefix = stem(slash + 1:index(stem, '_point', back=.true.) + 5)
      call listing%open(directory, stat, errmsg)
      if (stat /= 0) return
      do while (listing%next(name))
         k = point_index(name, prefix)
         if (k == 0) cycle
         if (k <= size(self%has_file)) then
            if (self%has_file(k)) cycle
         end if
         call remove_file(directory//'/'//name, ignored, message)
      end do
      call listing%close()
   end subroutine point_files_commit

   !> k when `name` is the name of point k's file, `prefix` followed by k's digits as
   !! `point_digits` writes them and '.h5' ('s_point0012.h5' with the prefix 's_point' of
   !! `point_file_name`, 'point0012.h5' with the prefix 'point' of `kept_point_file`), else 0.
   function point_index(name, prefix) result(k)
      character(len=*), intent(in) :: name, prefix
      integer :: k, digits, ios
      k = 0
      digits = len(name) - len(prefix) - 3
      if (digits < 4 .or. digits > 9) return
      if (name(1:len(prefix)) /= prefix .or. name(len(name) - 2:) /= '.h5') return
      if (verify(name(len(prefix) + 1:len(name) - 3), '0123456789') /= 0) return
      read (name(len(prefix) + 1:len(name) - 3), *, iostat=ios) k
      if (ios /= 0 .or. k < 1) then
         k = 0
         return
      end if
      if (name /= prefix//point_digits(k)//'.h5') k = 0
   end function point_index
end module vibrobeam_sweep_point_files
