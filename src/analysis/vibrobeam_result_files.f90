!> The result of a run (docs/output.md): one HDF5 file, THE result, written under a
!! temporary name and published atomically, and the gnuplot-ready .dat files derived from
!! it (`vibrobeam_text_output`).
!!
!! Publication (`publish`), after the HDF5 file is complete:
!!  1. the file is flushed, closed and synced to disk (fsync) under its temporary name;
!!  2. with `&output text = .true.`, every .dat file is derived from it, each under its
!!     own temporary name, and synced;
!!  3. under an exclusive lock on the target directory (flock), the HDF5 file and then
!!     every .dat file are renamed onto their final names, the .dat files of the same
!!     stem that this result does not produce (left by an earlier run) are removed, and
!!     the directory is synced. A result with more files than these (a sweep's point
!!     files) passes a `publish_step`, whose `prepare` runs under the lock before the
!!     first rename and `commit` after the last. Concurrent runs with one output path thus publish one
!!     after the other, and the last publisher's set is what remains.
!! Any failure before the renames deletes every temporary file and leaves what was at the
!! target untouched. Each .dat file's first line names the run id that /run holds, so a
!! reader can tell a .dat file of another run.
module vibrobeam_result_files
   use, intrinsic :: iso_c_binding, only: c_long
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_status, only: outcome_ok, outcome_interrupted, outcome_name
   use vibrobeam_version, only: version_string
   use vibrobeam_scene, only: scene_type, scene_entry, scene_entries, format_scene
   use vibrobeam_model, only: beam_model
   use vibrobeam_hdf5, only: h5_writer
   use vibrobeam_filesystem, only: rename_file, remove_file, file_exists, sync_directory_of, &
      directory_of, directory_lock, utc_stamp, process_id, random_hex
   use vibrobeam_text, only: integer_text
   use vibrobeam_text_output, only: derived_file, derive_text_files, discard_derived, text_file_name, &
      text_suffixes
   use vibrobeam_progress, only: progress_meter
   implicit none
   private
   public :: result_files, run_summary, run_outcome, new_run_id, publish_files, publish_step

   !> Bytes reserved for the /run status attribute ('running', 'ok', 'failed', 'interrupted').
   integer, parameter :: status_capacity = 16

   !> What /run records about a run (docs/output.md).
   type :: run_summary
      integer :: status = outcome_ok                 !! outcome_ok | outcome_failed | outcome_interrupted
      integer(int64) :: steps = 0                    !! global step number at the end
      integer(int64) :: start_step = 0               !! global step number at the start
      real(dp) :: wall_seconds = 0
      integer(int64) :: iterations_total = 0, iterations_max = 0
      integer(int64) :: linear_solves_total = 0, linear_solves_max = 0
      integer(int64) :: fallback_steps = 0
   end type run_summary

   !> An open result.
   type :: result_files
      type(h5_writer) :: h5
      logical :: text = .true.                  !! also derive .dat files
      character(len=:), allocatable :: run_id
   contains
      procedure :: open => open_results
      procedure :: set_run
      procedure :: set_flushed
      procedure :: publish
      procedure :: finish
      procedure :: discard => discard_results
      procedure :: write_modes
      procedure :: write_static
      procedure :: write_static_accuracy
   end type result_files

   !> More files published with a result, under the same directory lock (module
   !! documentation): `prepare` before the result's first rename (a failure there leaves
   !! every file as it was), `commit` after its last.
   type, abstract :: publish_step
   contains
      procedure(publish_step_action), deferred :: prepare
      procedure(publish_step_action), deferred :: commit
   end type publish_step

   abstract interface
      subroutine publish_step_action(self, stat, errmsg)
         import :: publish_step
         class(publish_step), intent(inout) :: self
         integer, intent(out) :: stat
         character(len=*), intent(out) :: errmsg
      end subroutine publish_step_action
   end interface

   interface
      !> long vb_peak_rss_kb(void);  (src/os/vibrobeam_posix_files.c)
      function c_peak_rss_kb() result(kb) bind(C, name='vb_peak_rss_kb')
         import :: c_long
         integer(c_long) :: kb
      end function c_peak_rss_kb
   end interface

   !> What a run (modes, static, dynamics or periodic) reports back to the program.
   type :: run_outcome
      integer :: status = outcome_ok           !! outcome_ok | outcome_failed | outcome_interrupted (/run status)
      logical :: text_skipped = .false.        !! a signal stopped the text derivation
      integer(int64) :: steps = 0              !! global step number at the end
      integer(int64) :: impacts = 0
      real(dp) :: wall_seconds = 0
      real(dp) :: max_penetration = 0
      logical :: compliant = .false.           !! the scene has compliant stops
      real(dp) :: peak_force = 0               !! their largest |force| over every step (N)
      real(dp) :: contact_time = 0             !! longest time a contact point spent in contact (s, /contact/fraction)
      character(len=512) :: failure = ''
      character(len=64) :: run_id = ''         !! /run run_id of the published result
      real(dp), allocatable :: omega(:)        !! kind = 'modes': the natural frequencies written (rad/s)
      integer :: in_contact = 0                !! kind = 'static': contact points in contact
      real(dp) :: position_bound = 0           !! kind = 'static': bound of the displacements' round-off (m)
      ! kind = 'periodic': of the orbit (of a continuation: of its branch's first orbit, no residual)
      integer :: newton_iterations = 0         !! kind = 'periodic': Newton iterations taken
      real(dp) :: residual = 0                 !! kind = 'periodic': relative residual of the last iterate
      real(dp) :: period = 0                   !! kind = 'periodic': the orbit's period (s)
      real(dp) :: largest_multiplier = 0       !! kind = 'periodic': largest modulus of its Floquet multipliers
      integer :: branch_points = 0             !! a continuation: points of the branch
      integer :: bifurcations = 0              !! a continuation: bifurcations located on it
      ! kind = 'dynamics' with a harmonic load: what its Poincare samples say (/statistics/poincare)
      integer(int64) :: poincare_samples = 0   !! samples in the statistics window (0: no section)
      integer :: poincare_period = -1          !! of the sequence; 0 none, -1 not determined
      real(dp) :: zero_one_k = 0               !! the 0-1 test's K
      integer :: zero_one_lags = 0             !! its lags (0: not determined)
      real(dp) :: lyapunov = 0, lyapunov_error = 0   !! the largest Lyapunov exponent (1/s) and its standard error
      real(dp) :: lyapunov_per_period = 0      !! times the forcing period
      integer(int64) :: lyapunov_periods = 0   !! the periods it covers (0: not asked)
   end type run_outcome

contains

   !> Peak resident set size of the process so far (kB; getrusage).
   function peak_memory_kb() result(kb)
      integer(int64) :: kb
      kb = int(c_peak_rss_kb(), int64)
   end function peak_memory_kb

   !> A run id: the UTC time, the process id and 32 random bits ('20240101T120000Z-1234-89abcdef').
   function new_run_id() result(id)
      character(len=:), allocatable :: id
      id = utc_stamp() // '-' // integer_text(process_id()) // '-' // random_hex(8)
   end function new_run_id

   !> Create the HDF5 file (temporary name) with the root attributes (version, every
   !! resolved input value with its unit, the resolved scene as text), /mesh/x and the
   !! /run attributes (status 'running', run_id; the others 0 until `set_run`). With
   !! `unbuffered`, HDF5 keeps no sieve buffer (a sweep file writes ~100 datasets a block
   !! of points at a time: one buffer of up to 64 KiB each otherwise).
   subroutine open_results(self, scene, model, stat, errmsg, unbuffered)
      class(result_files), intent(inout) :: self
      type(scene_type), intent(in) :: scene
      type(beam_model), intent(in) :: model
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: unbuffered
      type(scene_entry), allocatable :: list(:)
      integer :: i
      self%text = scene%output%text
      self%run_id = new_run_id()
      call self%h5%create(trim(scene%output%file), stat, errmsg, unbuffered)
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
      if (stat == 0) call self%h5%attr_string('/run', 'run_id', self%run_id, stat, errmsg)
      if (stat == 0) call self%h5%attr_string('/run', 'status', 'running', stat, errmsg, capacity=status_capacity)
      call zero('steps')
      call zero('start_step')
      if (stat == 0) call self%h5%attr_real('/run', 'wall_seconds', 0.0_dp, stat, errmsg)
      call zero('contact_solver_iterations')
      call zero('contact_solver_iterations_max_per_step')
      call zero('contact_linear_solves')
      call zero('contact_linear_solves_max_per_step')
      call zero('contact_fallback_steps')
      call zero('peak_memory_kb')
      call zero('flushed_step')
      call zero('flushed_outputs')
      call zero('flushed_field_outputs')
      call zero('flushed_impacts')
      call zero('flushed_episodes')
   contains
      subroutine zero(name)
         character(len=*), intent(in) :: name
         if (stat == 0) call self%h5%attr_int64('/run', name, 0_int64, stat, errmsg)
      end subroutine zero
   end subroutine open_results

   !> Write the /run attributes of `summary` (in place: allowed in SWMR mode).
   subroutine set_run(self, summary, stat, errmsg)
      class(result_files), intent(inout) :: self
      type(run_summary), intent(in) :: summary
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%h5%rewrite_attr('/run', 'status', outcome_name(summary%status), stat, errmsg, capacity=status_capacity)
      call put('steps', summary%steps)
      call put('start_step', summary%start_step)
      if (stat == 0) call self%h5%rewrite_attr('/run', 'wall_seconds', summary%wall_seconds, stat, errmsg)
      call put('contact_solver_iterations', summary%iterations_total)
      call put('contact_solver_iterations_max_per_step', summary%iterations_max)
      call put('contact_linear_solves', summary%linear_solves_total)
      call put('contact_linear_solves_max_per_step', summary%linear_solves_max)
      call put('contact_fallback_steps', summary%fallback_steps)
      call put('peak_memory_kb', peak_memory_kb())
   contains
      subroutine put(name, value)
         character(len=*), intent(in) :: name
         integer(int64), intent(in) :: value
         if (stat == 0) call self%h5%rewrite_attr('/run', name, value, stat, errmsg)
      end subroutine put
   end subroutine set_run

   !> Record what the file holds at a flush: the step and the rows of each kind
   !! [outputs, field snapshots, impacts, closed episodes] (docs/output.md, "After a kill").
   subroutine set_flushed(self, step, rows, stat, errmsg)
      class(result_files), intent(inout) :: self
      integer(int64), intent(in) :: step, rows(4)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%h5%rewrite_attr('/run', 'flushed_step', step, stat, errmsg)
      if (stat == 0) call self%h5%rewrite_attr('/run', 'flushed_outputs', rows(1), stat, errmsg)
      if (stat == 0) call self%h5%rewrite_attr('/run', 'flushed_field_outputs', rows(2), stat, errmsg)
      if (stat == 0) call self%h5%rewrite_attr('/run', 'flushed_impacts', rows(3), stat, errmsg)
      if (stat == 0) call self%h5%rewrite_attr('/run', 'flushed_episodes', rows(4), stat, errmsg)
   end subroutine set_flushed

   !> Publish the result (module documentation). With `stop_on_signal`, a signal that
   !! arrives while the .dat files are derived stops that (`text_skipped`): the HDF5 file
   !! is then published alone (its stale .dat files removed) and `vibrobeam --text`
   !! derives them later. `also`: more files to publish with it (`publish_step`).
   subroutine publish(self, meter, stop_on_signal, text_skipped, stat, errmsg, also)
      class(result_files), intent(inout) :: self
      type(progress_meter), intent(inout) :: meter
      logical, intent(in) :: stop_on_signal
      logical, intent(out) :: text_skipped
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      class(publish_step), intent(inout), optional :: also
      type(derived_file), allocatable :: files(:)
      character(len=:), allocatable :: final_name, temporary
      text_skipped = .false.
      final_name = self%h5%final_file()
      temporary = self%h5%temporary_file()
      call meter%report('publishing '//final_name)
      call self%h5%finish(stat, errmsg)
      if (stat /= 0) return
      allocate (files(0))
      if (self%text) then
         call derive_text_files(temporary, final_name, meter, stop_on_signal, files, text_skipped, stat, errmsg)
         if (stat /= 0) return
      end if
      call publish_files(temporary, final_name, files, stat, errmsg, also)
      if (stat /= 0) call discard_derived(files)
   end subroutine publish

   !> Rename `temporary` (if not '') onto `final_name` and each derived file onto its final
   !! name, remove the stem's .dat files not among them, sync the directory; all under an
   !! exclusive lock on the directory, with the `prepare` and `commit` of `also`.
   subroutine publish_files(temporary, final_name, files, stat, errmsg, also)
      character(len=*), intent(in) :: temporary, final_name
      type(derived_file), intent(in) :: files(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      class(publish_step), intent(inout), optional :: also
      type(directory_lock) :: lock
      character(len=512) :: message
      integer :: k, ignored
      call lock%acquire(directory_of(final_name), stat, errmsg)
      if (stat /= 0) return
      if (present(also)) then
         call also%prepare(stat, errmsg)
         if (stat /= 0) then
            call lock%release()
            return
         end if
      end if
      if (len(temporary) > 0) call rename_file(temporary, final_name, stat, errmsg)
      do k = 1, size(files)
         if (stat /= 0) exit
         call rename_file(files(k)%temporary, files(k)%final, stat, errmsg)
      end do
      if (stat == 0) then
         do k = 1, size(text_suffixes)
            if (any(files%final == text_file_name(final_name, trim(text_suffixes(k))))) cycle
            if (file_exists(text_file_name(final_name, trim(text_suffixes(k))))) &
               call remove_file(text_file_name(final_name, trim(text_suffixes(k))), ignored, message)
         end do
         if (present(also)) call also%commit(stat, errmsg)
         if (stat == 0) call sync_directory_of(final_name, stat, errmsg)
      end if
      call lock%release()
   end subroutine publish_files

   !> The end of a modes or static result: /run from `summary`, then publication (a signal
   !! during the text derivation stops it unless the run was already interrupted). With
   !! stat /= 0 on entry (an earlier write failed), or when either step fails, the
   !! temporary file is discarded instead: nothing is published, earlier results stay.
   subroutine finish(self, summary, meter, text_skipped, stat, errmsg)
      class(result_files), intent(inout) :: self
      type(run_summary), intent(in) :: summary
      type(progress_meter), intent(inout) :: meter
      logical, intent(out) :: text_skipped
      integer, intent(inout) :: stat
      character(len=*), intent(inout) :: errmsg
      text_skipped = .false.
      if (stat == 0) call self%set_run(summary, stat, errmsg)
      if (stat == 0) call self%publish(meter, summary%status /= outcome_interrupted, text_skipped, stat, errmsg)
      if (stat /= 0) call self%discard()
   end subroutine finish

   !> Remove the temporary file; `final_name` is untouched.
   subroutine discard_results(self)
      class(result_files), intent(inout) :: self
      call self%h5%discard()
   end subroutine discard_results

   !> /modes/frequency (rad/s) and /modes/frequency_hz (Hz), /modes/shape (or the same
   !! under `group`).
   subroutine write_modes(self, omega, shapes, stat, errmsg, group)
      class(result_files), intent(inout) :: self
      real(dp), intent(in) :: omega(:)       !! angular frequencies (rad/s)
      real(dp), intent(in) :: shapes(:,:)    !! (N+1, modes), tip value 1
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=*), intent(in), optional :: group   !! '/modes' (default) or '/contact_modes'
      character(len=:), allocatable :: name
      name = '/modes'
      if (present(group)) name = group
      call self%h5%write_real_1d(name//'/frequency', omega, 'rad/s', stat, errmsg)
      if (stat == 0) call self%h5%write_real_1d(name//'/frequency_hz', omega/(2*pi), 'Hz', stat, errmsg)
      if (stat == 0) call self%h5%write_real_2d(name//'/shape', shapes, '1 (tip value 1)', stat, errmsg)
   end subroutine write_modes

   !> /static/displacement, /static/reaction and /static/contact_x.
   subroutine write_static(self, displacement, contact_x, reaction, stat, errmsg)
      class(result_files), intent(inout) :: self
      real(dp), intent(in) :: displacement(:)   !! at the N+1 nodes (m)
      real(dp), intent(in) :: contact_x(:)      !! contact point positions (m)
      real(dp), intent(in) :: reaction(:)       !! reaction at each contact point (N)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%h5%write_real_1d('/static/displacement', displacement, 'm', stat, errmsg)
      if (stat == 0) call self%h5%write_real_1d('/static/reaction', reaction, 'N', stat, errmsg)
      if (stat == 0) call self%h5%write_real_1d('/static/contact_x', contact_x, 'm', stat, errmsg)
   end subroutine write_static

   !> The /static attributes of a static solve's accuracy (docs/output.md): the a-posteriori
   !! error estimate and its bound (m), the bound of the contact points' positions (m), the
   !! active-set iterations, and `failure` (the reason) when the solve failed.
   subroutine write_static_accuracy(self, error_estimate, error_bound, position_bound, iterations, failure, stat, errmsg)
      class(result_files), intent(inout) :: self
      real(dp), intent(in) :: error_estimate, error_bound, position_bound
      integer, intent(in) :: iterations
      character(len=*), intent(in) :: failure   !! '' when the solve succeeded
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call self%h5%attr_real('/static', 'error_estimate', error_estimate, stat, errmsg)
      if (stat == 0) call self%h5%attr_real('/static', 'error_bound', error_bound, stat, errmsg)
      if (stat == 0) call self%h5%attr_real('/static', 'position_bound', position_bound, stat, errmsg)
      if (stat == 0) call self%h5%attr_int('/static', 'iterations', iterations, stat, errmsg)
      if (stat == 0 .and. len(failure) > 0) call self%h5%attr_string('/static', 'failure', failure, stat, errmsg)
   end subroutine write_static_accuracy
end module vibrobeam_result_files
