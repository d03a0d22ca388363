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
   use vibrobeam_text, only: real_text
   use vibrobeam_scene, only: scene_type, step_count
   use vibrobeam_setup, only: prepared_scene, start_time_stepper, release_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   use vibrobeam_result_files, only: result_files, run_summary, run_outcome
   use vibrobeam_checkpoint, only: checkpoint_slots
   use vibrobeam_state_record, only: state_record
   use vibrobeam_progress, only: progress_meter
   use vibrobeam_signals, only: interrupt_requested
   use vibrobeam_statistics, only: statistics_result
   implicit none
   private
   public :: run_dynamics, flush_seconds

   !> Wall time between two flushes of the temporary file (s).
   real(dp), parameter :: flush_seconds = 2


contains

   !> Run the scene and publish its result. stat /= 0 (with errmsg) for failures that
   !! prevented a result (I/O: nothing is published, earlier results are untouched); a
   !! numerical failure or an interruption is reported in `outcome`.
   !!
   !! A sweep runs its points' result files through here (&sweep keep_runs, possibly from
   !! several threads): `quiet` turns the progress reports off, `statistics` and
   !! `final_state` hand back the window's statistics and the last state (a checkpoint
   !! record), and every call that may touch HDF5 (not thread-safe) is in the critical
   !! section `vibrobeam_hdf5`.
   subroutine run_dynamics(scene, prepared, outcome, stat, errmsg, quiet, statistics, final_state)
      type(scene_type), intent(in) :: scene
      type(prepared_scene), intent(in) :: prepared
      type(run_outcome), intent(out) :: outcome
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      logical, intent(in), optional :: quiet
      type(statistics_result), intent(out), optional :: statistics
      type(state_record), intent(out), optional :: final_state
      class(time_stepper), allocatable :: stepper
      type(dynamics_recorder) :: recorder
      type(result_files) :: files
      type(checkpoint_slots) :: slots
      type(state_record) :: record
      type(progress_meter) :: meter
      type(run_summary) :: summary
      integer(int64) :: last, n, start, now, rate, last_flush, last_checkpoint
      real(dp) :: flush_interval
      integer :: step_stat
      character(len=512) :: step_message
      character(len=:), allocatable :: warning

      call meter%init(scene%output%progress)
      if (present(quiet)) then
         if (quiet) meter%enabled = .false.
      end if
      call system_clock(start, rate)
      last = step_count(scene)
      ! (n dt rounds to the nearest double of t_end: allow a few of its ulps)
      if (.not. prepared%resuming .and. abs(last*scene%time%dt - scene%time%t_end) > &
          max(1e-9_dp*scene%time%dt, 4*epsilon(1.0_dp)*scene%time%t_end)) &
         write (error_unit, '(a)') 'vibrobeam: warning: t_end is not a whole number of steps; the run ends at '// &
         real_text(last*scene%time%dt)//' s'
      call start_time_stepper(scene, prepared, stepper, stat, errmsg)
      if (stat /= 0) return
      summary%start_step = stepper%steps
      if (prepared%reduced) then
         call recorder%init(scene, stepper, prepared%model, stepper%v, last, reduction=prepared%reduction)
      else
         call recorder%init(scene, stepper, prepared%model, prepared%v0, last)
      end if
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
      call open_result()
      if (stat /= 0) return
      run: block
         call system_clock(last_flush)
         last_checkpoint = last_flush
         flush_interval = flush_seconds
         if (scene%output%checkpoint_seconds > 0) flush_interval = min(flush_seconds, scene%output%checkpoint_seconds)

         do n = stepper%steps + 1, last
            call stepper%step(step_stat, step_message)
            if (step_stat /= 0) then
               outcome%status = 'failed'
               write (outcome%failure, '(a,i0,a,es14.7,a)') 'step ', n, ' (t = ', n*scene%time%dt, ' s): '//trim(step_message)
               exit
            end if
            call record_step(n)
            if (stat /= 0) exit run
            if (interrupt_requested()) then
               outcome%status = 'interrupted'
               exit
            end if
            call system_clock(now)
            if (now - last_flush >= flush_interval*rate) then
               call flush_and_checkpoint(now)
               if (stat /= 0) exit run
               last_flush = now
            end if
            if (meter%due()) call meter%report(progress_text(n))
         end do

         call finish_result()
         if (stat /= 0) exit run
         outcome%wall_seconds = meter%elapsed()
         call meter%end_line()
         if (present(statistics)) statistics = recorder%window_statistics(stepper)
         if (present(final_state)) final_state = record
         call release_stepper(stepper)   ! (a sweep's keep_runs runs this once per point)
         return
      end block run
      ! an I/O failure: nothing is published
      call meter%end_line()
      !$omp critical (vibrobeam_hdf5)
      call files%discard()
      !$omp end critical (vibrobeam_hdf5)
      call release_stepper(stepper)
      if (stat == 0) stat = 1

   contains

      !> Create the result file, every dataset, the checkpoint slots, enter SWMR mode, take
      !! the first sample and flush; on failure nothing is left (stat /= 0).
      subroutine open_result()
         !$omp critical (vibrobeam_hdf5)
         call files%open(scene, prepared%model, stat, errmsg)
         outcome%run_id = files%run_id
         if (stat == 0) call recorder%create_datasets(files%h5, stepper, prepared%model, stat, errmsg)
         if (stat == 0) then
            call save_state()
            call slots%create(files%h5, record, merge(2, 1, scene%output%checkpoint_seconds > 0), stat, errmsg)
         end if
         if (stat == 0 .and. len_trim(scene%initial%from_file) > 0) &
            call files%h5%attr_string('/run', 'continued_from', trim(scene%initial%from_file), stat, errmsg)
         if (stat == 0) call files%h5%start_swmr(stat, errmsg)
         if (stat == 0 .and. .not. prepared%resuming) then
            call recorder%sample(stepper, stat, errmsg)
            if (stat == 0) call recorder%sample_field(stepper, prepared%model, stat, errmsg)
         end if
         if (stat == 0) call flush_all()
         if (stat /= 0) call files%discard()
         !$omp end critical (vibrobeam_hdf5)
         if (stat /= 0) call meter%end_line()
      end subroutine open_result

      !> The recorder's work after step n (impacts, episodes, statistics, the samples due).
      subroutine record_step(step)
         integer(int64), intent(in) :: step
         !$omp critical (vibrobeam_hdf5)
         call recorder%after_step(stepper, stat, errmsg)
         if (stat == 0 .and. recorder%output_due(step)) call recorder%sample(stepper, stat, errmsg)
         if (stat == 0 .and. recorder%field_due(step)) call recorder%sample_field(stepper, prepared%model, stat, errmsg)
         !$omp end critical (vibrobeam_hdf5)
      end subroutine record_step

      !> A flush, and a checkpoint when `checkpoint_seconds` have passed since the last.
      subroutine flush_and_checkpoint(now)
         integer(int64), intent(in) :: now
         !$omp critical (vibrobeam_hdf5)
         call flush_all()
         if (stat == 0 .and. scene%output%checkpoint_seconds > 0 .and. &
             now - last_checkpoint >= scene%output%checkpoint_seconds*rate) then
            call save_state()
            call slots%write(files%h5, record, stepper%steps, stepper%t, stat, errmsg)
            if (stat == 0) last_checkpoint = now
         end if
         !$omp end critical (vibrobeam_hdf5)
      end subroutine flush_and_checkpoint

      !> The last sample, the final statistics and checkpoint, /run, and publication.
      subroutine finish_result()
         !$omp critical (vibrobeam_hdf5)
         ! the result ends with a sample of the last (good) state
         call recorder%sample(stepper, stat, errmsg)
         if (stat == 0) call recorder%sample_field(stepper, prepared%model, stat, errmsg)
         if (stat == 0) then
            call save_state()
            call recorder%finish(files%h5, stepper, stat, errmsg)
         end if
         if (stat == 0) call slots%write(files%h5, record, stepper%steps, stepper%t, stat, errmsg)
         if (stat == 0) then
            call slots%close()
            outcome%steps = stepper%steps
            outcome%impacts = recorder%impacts
            outcome%max_penetration = recorder%max_penetration
            outcome%compliant = recorder%compliant
            if (outcome%compliant) outcome%peak_force = maxval(recorder%peak_force)
            outcome%contact_time = maxval([0.0_dp, recorder%contact_time])
            summary%status = outcome%status
            summary%steps = stepper%steps
            summary%wall_seconds = meter%elapsed()
            summary%iterations_total = recorder%iterations_total
            summary%iterations_max = recorder%iterations_max
            summary%linear_solves_total = recorder%linear_solves_total
            summary%linear_solves_max = recorder%linear_solves_max
            summary%fallback_steps = recorder%fallback_steps
            call files%set_flushed(stepper%steps, recorder%rows(), stat, errmsg)
         end if
         if (stat == 0) call files%set_run(summary, stat, errmsg)
         if (stat == 0) call files%publish(meter, outcome%status /= 'interrupted', outcome%text_skipped, stat, errmsg)
         !$omp end critical (vibrobeam_hdf5)
      end subroutine finish_result

      !> The state of stepper and recorder, as a checkpoint holds it.
      subroutine save_state()
         call record%clear()
         call stepper%save_state(record)
         call recorder%save_state(record)
      end subroutine save_state

      !> Buffered rows to the file, what it holds into /run, then H5Fflush.
      subroutine flush_all()
         call recorder%write_buffers(stat, errmsg)
         if (stat == 0) call files%h5%flush(stat, errmsg)
         if (stat == 0) call files%set_flushed(stepper%steps, recorder%rows(), stat, errmsg)
         if (stat == 0) call files%h5%flush(stat, errmsg)
      end subroutine flush_all

      function progress_text(step) result(text)
         integer(int64), intent(in) :: step
         character(len=:), allocatable :: text
         character(len=160) :: buffer
         real(dp) :: elapsed, fraction
         elapsed = meter%elapsed()
         fraction = real(step - summary%start_step, dp)/max(1_int64, last - summary%start_step)
         write (buffer, '(f6.2,a,es11.4,a,f9.1,a,f9.1,a)') 100.0_dp*step/last, ' %  t = ', step*scene%time%dt, &
            ' s  wall ', elapsed, ' s  left ~', elapsed*(1 - fraction)/max(fraction, 1e-12_dp), ' s'
         text = trim(buffer)
      end function progress_text
   end subroutine run_dynamics
end module vibrobeam_dynamics
