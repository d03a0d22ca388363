!> A dynamics run from start to published result (&analysis kind = 'dynamics'): the time
!! loop around the scheme's stepper, streaming output, flushes and checkpoints, progress
!! reports, interruption and failure handling (docs/output.md).
!!
!! The run ends at step nint(t_end/dt) (t_end is rounded to a whole number of steps; a
!! warning says so when that changes it by more than 1e-9 dt); step numbers are global
!! 64-bit counts and t = n dt. It starts at step 0, or at the checkpoint of &initial
!! from_file. Every `flush_seconds` of wall time the buffered rows go to the temporary
!! file and it is flushed (a run killed then leaves a consistent file up to that flush);
!! with &output checkpoint_seconds > 0 a checkpoint is also written at the first flush
!! after each such interval. On a numerical failure (contact solver without convergence,
!! non-finite state) the histories up to the last good step are published, complete,
!! with /run status = 'failed'; on SIGINT/SIGTERM the current step is finished and the
!! result is published with /run status = 'interrupted'.
module vibrobeam_dynamics
   use vibrobeam_kinds, only: dp, int64, error_unit
   use vibrobeam_status, only: outcome_interrupted
   use vibrobeam_text, only: real_text
   use vibrobeam_scene, only: scene_type, step_count
   use vibrobeam_problem, only: run_problem, new_stepper
   use vibrobeam_stepper_factory, only: release_stepper
   use vibrobeam_time_stepper, only: time_stepper, dynamic_state
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_result_files, only: result_files, run_summary, run_outcome
   use vibrobeam_checkpoint, only: checkpoint_slots
   use vibrobeam_state_record, only: state_record
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_statistics, only: statistics_result, first_value
   use vibrobeam_statistics_layout, only: group_poincare
   use vibrobeam_run_loop, only: advance, run_hooks
   implicit none
   private
   public :: run_dynamics, flush_seconds

   !> Wall time between two flushes of the temporary file (s).
   real(dp), parameter :: flush_seconds = 2

   !> The result file of a run while it goes on: created with every dataset before the
   !! steps, flushed every `flush_interval` of wall time (with a checkpoint every
   !! `checkpoint_seconds`, when asked), progress reported; finished and published at the
   !! end. Every HDF5 call is in the critical section `vibrobeam_hdf5` (a sweep's keep_runs
   !! points run this from several threads).
   type, extends(run_hooks) :: result_stream
      type(result_files) :: files
      type(checkpoint_slots) :: slots
      type(state_record) :: record             !! the last checkpoint's state
      type(progress_meter) :: meter
      type(run_summary) :: summary
      integer(int64) :: rate = 1               !! clock ticks per second
      integer(int64) :: last_flush = 0, last_checkpoint = 0   !! clock ticks
      real(dp) :: flush_interval = flush_seconds   !! wall s between flushes
      real(dp) :: checkpoint_seconds = 0       !! &output checkpoint_seconds
      integer(int64) :: last_step = 0          !! the run's last step
      real(dp) :: dt = 0
   contains
      procedure :: after_step => stream_after_step
      procedure :: open => open_stream
      procedure :: finish => finish_stream
      procedure :: save_state => stream_save_state
      procedure :: flush_all
      procedure :: progress_text
   end type result_stream

contains

   !> Run the scene and publish its result. stat /= 0 (with errmsg) for failures that
   !! prevented a result (I/O: nothing is published, earlier results are untouched); a
   !! numerical failure or an interruption is reported in `outcome`.
   !!
   !! A sweep runs its points' result files through here (&sweep keep_runs, possibly from
   !! several threads): `quiet` turns the progress reports off, `statistics` and
   !! `final_state` hand back the window's statistics and the last state, and every call
   !! that may touch HDF5 (not thread-safe) is in the critical section `vibrobeam_hdf5`.
   subroutine run_dynamics(scene, prepared, outcome, stat, errmsg, quiet, statistics, final_state)
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: quiet
      type(statistics_result), intent(out), optional :: statistics
      type(dynamic_state), intent(out), optional :: final_state
      class(time_stepper), allocatable :: stepper
      type(dynamics_recorder) :: recorder
      type(result_stream) :: stream
      integer(int64) :: last
      character(len=:), allocatable :: warning

      call stream%meter%init(scene%output%progress)
      if (present(quiet)) then
         if (quiet) stream%meter%enabled = .false.
      end if
      last = step_count(scene)
      ! (n dt rounds to the nearest double of t_end: allow a few of its ulps)
      if (.not. prepared%resuming .and. abs(last*scene%time%dt - scene%time%t_end) > &
          max(1e-9_dp*scene%time%dt, 4*epsilon(1.0_dp)*scene%time%t_end)) &
         write (error_unit, '(a)') 'vibrobeam: warning: t_end is not a whole number of steps; the run ends at '// &
         real_text(last*scene%time%dt)//' s'
      call new_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) return
      call recorder%init(scene, stepper, prepared, last)
      if (prepared%resuming) then
         call recorder%restore_state(prepared%resume, stat, errmsg)
         if (stat /= 0) then
            errmsg = '&initial from_file = '''//trim(scene%initial%from_file)//''': '//trim(errmsg)
            return
         end if
      end if
      call recorder%start_statistics(stepper, warning)
      if (len(warning) > 0) write (error_unit, '(a)') 'vibrobeam: warning: '//warning

      ! every dataset exists before the file enters SWMR mode
      call stream%open(scene, prepared, stepper, recorder, last, stat, errmsg)
      outcome%run_id = stream%files%run_id
      if (stat == 0) call advance(stepper, recorder, prepared%model, last, outcome%status, outcome%failure, stat, &
                                  errmsg, stream)
      if (stat == 0) call stream%finish(prepared, stepper, recorder, outcome, stat, errmsg)
      call stream%meter%end_line()
      if (stat /= 0) then
         ! an I/O failure: nothing is published
         !$omp critical (vibrobeam_hdf5)
         call stream%files%discard()
         !$omp end critical (vibrobeam_hdf5)
         call release_stepper(stepper)
         return
      end if
      outcome%wall_seconds = stream%meter%elapsed()
      if (present(statistics)) statistics = recorder%window_statistics(stepper)
      if (present(final_state)) final_state = stepper%state()
      call release_stepper(stepper)   ! (a sweep's keep_runs runs this once per point)
   end subroutine run_dynamics

   !> Create the result file, every dataset, the checkpoint slots, enter SWMR mode, take
   !! the first sample and flush; on failure nothing is left (stat /= 0).
   subroutine open_stream(self, scene, prepared, stepper, recorder, last, stat, errmsg)
      class(result_stream), intent(inout) :: self
      type(scene_type), intent(in) :: scene
      type(run_problem), intent(in) :: prepared
      class(time_stepper), intent(in) :: stepper
      type(dynamics_recorder), intent(inout) :: recorder
      integer(int64), intent(in) :: last
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: start
      call system_clock(start, self%rate)
      self%last_step = last
      self%dt = scene%time%dt
      self%summary%start_step = stepper%steps
      self%checkpoint_seconds = scene%output%checkpoint_seconds
      !$omp critical (vibrobeam_hdf5)
      call self%files%open(scene, prepared%model, stat, errmsg)
      if (stat == 0) call recorder%create_datasets(self%files%h5, stepper, prepared%model, stat, errmsg)
      if (stat == 0) then
         call self%save_state(stepper, recorder)
         call self%slots%create(self%files%h5, self%record, merge(2, 1, self%checkpoint_seconds > 0), stat, errmsg)
      end if
      if (stat == 0 .and. len_trim(scene%initial%from_file) > 0) &
         call self%files%h5%attr_string('/run', 'continued_from', trim(scene%initial%from_file), stat, errmsg)
      if (stat == 0) call self%files%h5%start_swmr(stat, errmsg)
      if (stat == 0 .and. .not. prepared%resuming) then
         call recorder%sample(stepper, stat, errmsg)
         if (stat == 0) call recorder%sample_field(stepper, prepared%model, stat, errmsg)
      end if
      if (stat == 0) call self%flush_all(stepper, recorder, stat, errmsg)
      if (stat /= 0) call self%files%discard()
      !$omp end critical (vibrobeam_hdf5)
      call system_clock(self%last_flush)
      self%last_checkpoint = self%last_flush
      if (self%checkpoint_seconds > 0) self%flush_interval = min(flush_seconds, self%checkpoint_seconds)
   end subroutine open_stream

   !> After each step: a flush when `flush_interval` has passed (and a checkpoint when
   !! `checkpoint_seconds` have passed since the last), a progress report when due.
   subroutine stream_after_step(self, stepper, recorder, step, stat, errmsg)
      class(result_stream), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(dynamics_recorder), intent(inout) :: recorder
      integer(int64), intent(in) :: step
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer(int64) :: now
      stat = 0
      errmsg = ''
      call system_clock(now)
      if (now - self%last_flush >= self%flush_interval*self%rate) then
         !$omp critical (vibrobeam_hdf5)
         call self%flush_all(stepper, recorder, stat, errmsg)
         if (stat == 0 .and. self%checkpoint_seconds > 0 .and. &
             now - self%last_checkpoint >= self%checkpoint_seconds*self%rate) then
            call self%save_state(stepper, recorder)
            call self%slots%write(self%files%h5, self%record, stepper%steps, stepper%t, stat, errmsg)
            if (stat == 0) self%last_checkpoint = now
         end if
         !$omp end critical (vibrobeam_hdf5)
         if (stat /= 0) return
         self%last_flush = now
      end if
      if (self%meter%due()) call self%meter%report(self%progress_text(step))
   end subroutine stream_after_step

   !> The last sample, the final statistics and checkpoint, /run, and publication.
   subroutine finish_stream(self, prepared, stepper, recorder, outcome, stat, errmsg)
      class(result_stream), intent(inout) :: self
      type(run_problem), intent(in) :: prepared
      class(time_stepper), intent(in) :: stepper
      type(dynamics_recorder), intent(inout) :: recorder
      type(run_outcome), intent(inout) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      !$omp critical (vibrobeam_hdf5)
      ! the result ends with a sample of the last (good) state
      call recorder%sample(stepper, stat, errmsg)
      if (stat == 0) call recorder%sample_field(stepper, prepared%model, stat, errmsg)
      if (stat == 0) then
         call self%save_state(stepper, recorder)
         call recorder%finish(self%files%h5, stepper, stat, errmsg)
      end if
      if (stat == 0) call self%slots%write(self%files%h5, self%record, stepper%steps, stepper%t, stat, errmsg)
      if (stat == 0) then
         call self%slots%close()
         outcome%steps = stepper%steps
         outcome%impacts = recorder%impacts
         outcome%max_penetration = recorder%max_penetration
         outcome%compliant = recorder%compliant
         if (outcome%compliant) outcome%peak_force = maxval(recorder%peak_force)
         outcome%contact_time = maxval([0.0_dp, recorder%contact_time])
         call take_diagnostics(recorder%window_statistics(stepper), outcome)
         self%summary%status = outcome%status
         self%summary%steps = stepper%steps
         self%summary%wall_seconds = self%meter%elapsed()
         self%summary%iterations_total = recorder%iterations_total
         self%summary%iterations_max = recorder%iterations_max
         self%summary%linear_solves_total = recorder%linear_solves_total
         self%summary%linear_solves_max = recorder%linear_solves_max
         self%summary%fallback_steps = recorder%fallback_steps
         call self%files%set_flushed(stepper%steps, recorder%rows(), stat, errmsg)
      end if
      if (stat == 0) call self%files%set_run(self%summary, stat, errmsg)
      if (stat == 0) call self%files%publish(self%meter, outcome%status /= outcome_interrupted, outcome%text_skipped, stat, &
                                             errmsg)
      !$omp end critical (vibrobeam_hdf5)
   end subroutine finish_stream

   !> What the statistics window's Poincare samples say, for the run's summary.
   subroutine take_diagnostics(window, outcome)
      type(statistics_result), intent(in) :: window
      type(run_outcome), intent(inout) :: outcome
      if (.not. window%present) return
      outcome%poincare_samples = window%poincare_total
      outcome%poincare_period = nint(first_value(window, group_poincare, 'period'))
      outcome%zero_one_k = first_value(window, group_poincare, 'zero_one_k')
      outcome%zero_one_lags = nint(first_value(window, group_poincare, 'zero_one_lags'))
      outcome%lyapunov = first_value(window, group_poincare, 'lyapunov_exponent')
      outcome%lyapunov_error = window%errors(window%layout%entries(window%layout%find(group_poincare, &
                                                                                       'lyapunov_exponent'))%offset + 1)
      outcome%lyapunov_per_period = first_value(window, group_poincare, 'lyapunov_exponent_per_period')
      outcome%lyapunov_periods = nint(first_value(window, group_poincare, 'lyapunov_periods'), int64)
   end subroutine take_diagnostics

   !> The state of stepper and recorder, as a checkpoint holds it.
   subroutine stream_save_state(self, stepper, recorder)
      class(result_stream), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(dynamics_recorder), intent(in) :: recorder
      call self%record%clear()
      call stepper%save_state(self%record)
      call recorder%save_state(self%record)
   end subroutine stream_save_state

   !> Buffered rows to the file, what it holds into /run, then H5Fflush.
   subroutine flush_all(self, stepper, recorder, stat, errmsg)
      class(result_stream), intent(inout) :: self
      class(time_stepper), intent(in) :: stepper
      type(dynamics_recorder), intent(inout) :: recorder
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call recorder%write_buffers(stat, errmsg)
      if (stat == 0) call self%files%h5%flush(stat, errmsg)
      if (stat == 0) call self%files%set_flushed(stepper%steps, recorder%rows(), stat, errmsg)
      if (stat == 0) call self%files%h5%flush(stat, errmsg)
   end subroutine flush_all

   !> 'p %  t = ...  wall ... s  left ~... s' after step `step`.
   function progress_text(self, step) result(text)
      class(result_stream), intent(in) :: self
      integer(int64), intent(in) :: step
      character(len=:), allocatable :: text
      character(len=160) :: buffer
      real(dp) :: elapsed, fraction
      elapsed = self%meter%elapsed()
      fraction = real(step - self%summary%start_step, dp)/max(1_int64, self%last_step - self%summary%start_step)
      write (buffer, '(f6.2,a,es11.4,a,f9.1,a,f9.1,a)') 100.0_dp*step/self%last_step, ' %  t = ', step*self%dt, &
         ' s  wall ', elapsed, ' s  left ~', elapsed*(1 - fraction)/max(fraction, 1e-12_dp), ' s'
      text = trim(buffer)
   end function progress_text
end module vibrobeam_dynamics
