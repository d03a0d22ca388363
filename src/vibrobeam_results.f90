!> The result file set of a run (INTERFACE.md, "Output"): one HDF5 file plus gnuplot-ready
!! .dat files beside it, all written under temporary names and renamed at the end, so a
!! reader never sees a half-written result.
!!
!! Text files are named after the HDF5 file: results/run.h5 gives results/run_modes.dat,
!! results/run_shapes.dat, ...; each starts with a '#' header naming columns and units.
module vibrobeam_results
   use vibrobeam_kinds, only: dp
   use vibrobeam_version, only: version_string
   use vibrobeam_scene, only: scene_type, scene_entry, scene_entries, format_scene
   use vibrobeam_model, only: beam_model
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_filesystem, only: open_text_for_atomic_write, commit_text_file, discard_text_file
   use vibrobeam_kinds, only: pi
   implicit none
   private
   public :: result_files, text_file_name

   integer, parameter :: max_text_files = 16

   !> An open set of result files.
   type :: result_files
      type(h5_writer) :: h5
      logical :: text = .true.                  !! also write .dat files
      character(len=:), allocatable :: stem     !! HDF5 file name without '.h5'
      integer :: text_count = 0
      integer :: text_units(max_text_files) = -1
      character(len=512) :: text_names(max_text_files) = ''
   contains
      procedure :: open => open_results
      procedure :: open_text => open_text_file
      procedure :: commit => commit_results
      procedure :: discard => discard_results
      procedure :: write_modes
      procedure :: write_static
   end type result_files

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

   !> Create the HDF5 file (temporary name) with the root attributes (version, every
   !! resolved input value with its unit, the resolved scene as text) and /mesh/x.
   subroutine open_results(self, scene, model, stat, errmsg)
      class(result_files), intent(inout) :: self
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(scene_entry), allocatable :: list(:)
      integer :: i
      self%text = scene%text
      self%stem = trim(scene%file)
      call self%h5%create(trim(scene%file), stat, errmsg)
      if (stat /= 0) return
      call self%h5%attr_string('/', 'program', 'vibrobeam', stat, errmsg)
      if (stat == 0) call self%h5%attr_string('/', 'version', version_string, stat, errmsg)
      if (stat == 0) call self%h5%attr_string('/', 'resolved_input', format_scene(scene), stat, errmsg)
      allocate (list, source=scene_entries(scene))
      do i = 1, size(list)
         if (stat /= 0) exit
         associate (item => list(i))
            select case (item%kind)
            case ('real')
               call self%h5%attr_real('/', trim(item%name), item%real_value, stat, errmsg)
            case ('integer')
               call self%h5%attr_int('/', trim(item%name), item%integer_value, stat, errmsg)
            case ('logical')
               call self%h5%attr_int('/', trim(item%name), merge(1, 0, item%logical_value), stat, errmsg)
            case default
               call self%h5%attr_string('/', trim(item%name), trim(item%string_value), stat, errmsg)
            end select
            if (stat == 0 .and. len_trim(item%unit) > 0) &
               call self%h5%attr_string('/', trim(item%name)//'.unit', trim(item%unit), stat, errmsg)
         end associate
      end do
      if (stat == 0) call self%h5%write_real_1d('/mesh/x', model%x, 'm', stat, errmsg)
   end subroutine open_results

   !> Open '<stem>_<suffix>.dat' under a temporary name, with `header` as its first line;
   !! returns the unit (or -1 when text output is off).
   subroutine open_text_file(self, suffix, header, unit, stat, errmsg)
      class(result_files), intent(inout) :: self
      character(len=*), intent(in) :: suffix, header
      integer, intent(out) :: unit, stat
      character(len=*), intent(out) :: errmsg
      unit = -1
      stat = 0
      errmsg = ''
      if (.not. self%text) return
      if (self%text_count == max_text_files) then
         stat = 1
         errmsg = 'too many text result files'
         return
      end if
      call open_text_for_atomic_write(text_file_name(self%stem, suffix), unit, stat, errmsg)
      if (stat /= 0) return
      self%text_count = self%text_count + 1
      self%text_units(self%text_count) = unit
      self%text_names(self%text_count) = text_file_name(self%stem, suffix)
      write (unit, '(a)') '# '//header
   end subroutine open_text_file

   !> Write the /run attributes, then rename every temporary file to its final name. On
   !! failure the caller discards the set (`discard`), as after any other failure.
   subroutine commit_results(self, status, steps, wall_seconds, iterations_total, iterations_max, stat, errmsg)
      class(result_files), intent(inout) :: self
      character(len=*), intent(in) :: status   !! 'ok' | 'failed'
      integer, intent(in) :: steps, iterations_total, iterations_max
      real(dp), intent(in) :: wall_seconds
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i
      call self%h5%attr_string('/run', 'status', status, stat, errmsg)
      if (stat == 0) call self%h5%attr_int('/run', 'steps', steps, stat, errmsg)
      if (stat == 0) call self%h5%attr_real('/run', 'wall_seconds', wall_seconds, stat, errmsg)
      if (stat == 0) call self%h5%attr_int('/run', 'contact_solver_iterations', iterations_total, stat, errmsg)
      if (stat == 0) call self%h5%attr_int('/run', 'contact_solver_iterations_max_per_step', iterations_max, stat, errmsg)
      do i = 1, self%text_count
         if (stat /= 0) exit
         call commit_text_file(self%text_units(i), trim(self%text_names(i)), stat, errmsg)
      end do
      if (stat == 0) call self%h5%commit(stat, errmsg)
      if (stat == 0) self%text_count = 0
   end subroutine commit_results

   !> Remove every temporary file of the set.
   subroutine discard_results(self)
      class(result_files), intent(inout) :: self
      integer :: i
      do i = 1, self%text_count
         call discard_text_file(self%text_units(i), trim(self%text_names(i)))
      end do
      self%text_count = 0
      call self%h5%discard()
   end subroutine discard_results

   !> /modes/frequency, /modes/shape and the files _modes.dat, _shapes.dat.
   subroutine write_modes(self, model, omega, shapes, stat, errmsg)
      class(result_files), intent(inout) :: self
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: omega(:)       !! angular frequencies (rad/s)
      real(dp), intent(in) :: shapes(:,:)    !! (N+1, modes), tip value 1
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: unit, k, i
      call self%h5%write_real_1d('/modes/frequency', omega, 'rad/s', stat, errmsg)
      if (stat == 0) call self%h5%write_real_2d('/modes/shape', shapes, '1 (tip value 1)', stat, errmsg)
      if (stat /= 0) return
      call self%open_text('modes', 'mode  omega (rad/s)  frequency (Hz)', unit, stat, errmsg)
      if (stat /= 0) return
      if (unit /= -1) then
         do k = 1, size(omega)
            write (unit, '(i6, 2es24.15)') k, omega(k), omega(k)/(2*pi)
         end do
      end if
      call self%open_text('shapes', 'x (m)  then the shape of mode 1, 2, ... (tip value 1)', unit, stat, errmsg)
      if (stat /= 0 .or. unit == -1) return
      do i = 1, size(model%x)
         write (unit, '(*(es24.15))') model%x(i), shapes(i, :)
      end do
   end subroutine write_modes

   !> /static/displacement, /static/reaction (+ /static/contact_x) and _static.dat,
   !! _reactions.dat.
   subroutine write_static(self, model, displacement, contact_x, reaction, stat, errmsg)
      class(result_files), intent(inout) :: self
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: displacement(:)   !! at the N+1 nodes (m)
      real(dp), intent(in) :: contact_x(:)      !! contact point positions (m)
      real(dp), intent(in) :: reaction(:)       !! reaction at each contact point (N)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: unit, i
      call self%h5%write_real_1d('/static/displacement', displacement, 'm', stat, errmsg)
      if (stat == 0) call self%h5%write_real_1d('/static/reaction', reaction, 'N', stat, errmsg)
      if (stat == 0) call self%h5%write_real_1d('/static/contact_x', contact_x, 'm', stat, errmsg)
      if (stat /= 0) return
      call self%open_text('static', 'x (m)  u (m)', unit, stat, errmsg)
      if (stat /= 0) return
      if (unit /= -1) then
         do i = 1, size(model%x)
            write (unit, '(*(es24.15))') model%x(i), displacement(i)
         end do
      end if
      call self%open_text('reactions', 'x (m)  reaction (N, positive upwards)', unit, stat, errmsg)
      if (stat /= 0 .or. unit == -1) return
      do i = 1, size(contact_x)
         write (unit, '(*(es24.15))') contact_x(i), reaction(i)
      end do
   end subroutine write_static
end module vibrobeam_results
