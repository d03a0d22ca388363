!> What a run or a sweep will cost, estimated before it runs (`vibrobeam --check`, the
!! size checks of `vibrobeam_output_target` and `vibrobeam_sweep_check`; docs/input.md,
!! "What --check prints", and docs/sweeps.md, "Checking a sweep").
!!
!! Size. A run's HDF5 file holds its histories as chunked datasets that grow by whole
!! chunks (`series_buffer_rows` rows: 4096 rows of a 1-d history, 32 KiB, at least one
!! chunk for a dataset with a row), the field, the spectra (one bin per frequency of the
!! record: min(samples, 2^16)/2 + 1), the Poincare samples, the checkpoint (the state and
!! the spectra's buffers), and about `metadata_bytes` of attributes and object headers;
!! impacts and episodes, whose number is not known beforehand, are counted as one chunk
!! each (up to 4096 rows) when the scene has obstacles. The .dat files take 24 characters
!! a number (16 in the field) and a newline a row. A sweep writes its file (a row of every
!! statistic and its error per point, the kept Poincare samples), its text files and, with
!! keep_runs, every point's result file; its journals exist beside them until it ends.
!! The estimates were measured against the files the bundled inputs write (docs/input.md,
!! "What --check prints": within 10 % for every one of them; verification/input/
!! check_estimates.sh).
!!
!! Time. The steps a run or a sweep makes are known exactly (a sweep with steady_tolerance:
!! between its first comparison and max_settle_windows windows); the cost of a step is
!! timed on the CPU clock (`cpu_time`, not the wall clock, which other jobs on the machine
!! stretch) over steps of the stepper and the recorder that a sweep's point runs (statistics
!! included, nothing written), after a warm-up, as the median of a few blocks. The
!! estimate is in CPU seconds of one core; a sweep's tasks share the workers.
module vibrobeam_result_estimate
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_sorting, only: median
   use vibrobeam_scene, only: scene_type, step_count, forcing_of, forcing_period_steps
   use vibrobeam_continuation_axis, only: branch_points
   use vibrobeam_hdf5_series, only: series_buffer_rows
   use vibrobeam_welch, only: welch_segment
   use vibrobeam_recorder, only: history_paths
   use vibrobeam_statistics, only: window_first_step
   use vibrobeam_statistics_layout, only: statistics_layout, periodic_names
   use vibrobeam_poincare, only: kept_samples
   use vibrobeam_sweep_journal, only: record_length, message_words
   use vibrobeam_sweep_runner, only: chunk_rows
   use vibrobeam_zero_one, only: frequencies, max_lag
   use vibrobeam_poincare_period, only: max_period
   use vibrobeam_sweep_settings, only: sweep_settings, sweep_point, point_scene, point_windows, max_settle_windows
   use vibrobeam_problem, only: run_problem, build_problem, new_stepper
   use vibrobeam_stepper_factory, only: release_stepper
   use vibrobeam_time_stepper, only: time_stepper
   use vibrobeam_recorder, only: dynamics_recorder
   implicit none
   private
   public :: result_size, estimate_result_size, sweep_size, estimate_sweep_size, step_cost

   !> Attributes (the resolved input, each with its unit), groups and object headers of a
   !! dynamics result file and of a modes or static one (measured on the bundled scenes: 98
   !! kB, about 20 kB).
   real(dp), parameter :: metadata_bytes = 100000, small_metadata_bytes = 20000
   !> The header of one more small dataset (its object header, unit attribute and link):
   !! measured on a continuation's /periodic/branch, 12 datasets in 10.3 kB beyond the rest.
   real(dp), parameter :: dataset_header_bytes = 900
   !> The same for a sweep file (measured: 66 kB), and the header lines of a .dat file (a
   !! line naming the run, one with the columns' names and units, and in a sweep's files a
   !! line per column: 2.2 kB for STEM_sweep.dat, 0.4 kB for STEM_poincare.dat).
   real(dp), parameter :: sweep_metadata_bytes = 66000, text_header_bytes = 2000
   !> Columns of /impacts and /episodes (one chunk each is counted when there are obstacles).
   integer, parameter :: impact_columns = 5, episode_columns = 7
   !> Characters of a number in the .dat files: 'wide' rows (%24.15E) and the field's (%16.7E).
   real(dp), parameter :: wide = 24, narrow = 16
   !> Columns of STEM_sweep.dat and of a sweep's STEM_poincare.dat.
   integer, parameter :: sweep_columns = 54, sweep_poincare_columns = 7
   !> Columns of STEM_sweep.dat of a sweep of periodic analyses (point, line, direction, the
   !! two parameters, status, the 'periodic' statistics, wall time).
   integer, parameter :: orbit_sweep_columns = 7 + size(periodic_names)

   !> What a run will write (docs/output.md).
   type :: result_size
      real(dp) :: steps = 0            !! time steps
      real(dp) :: outputs = 0          !! output times (rows of the histories)
      real(dp) :: snapshots = 0        !! displacement field snapshots
      real(dp) :: values_per_output = 0   !! numbers written per output time besides the field
      real(dp) :: hdf5_bytes = 0       !! the HDF5 file
      real(dp) :: text_bytes = 0       !! the .dat files (0 with text = .false.)
      real(dp) :: total_bytes = 0
   end type result_size

   !> What a sweep will write (docs/sweeps.md, "The sweep file").
   type :: sweep_size
      real(dp) :: sweep_bytes = 0      !! the sweep file
      real(dp) :: text_bytes = 0       !! STEM_sweep.dat and STEM_poincare.dat
      real(dp) :: point_bytes = 0      !! the points' result files (keep_runs)
      real(dp) :: journal_bytes = 0    !! its journals, removed when it ends
      real(dp) :: total_bytes = 0      !! what it leaves: sweep file, text and point files
      real(dp) :: peak_bytes = 0       !! while it publishes: the total and the journals
   end type sweep_size

contains

   !> Bytes of a chunked dataset of `rows` rows of `columns` values: whole chunks of
   !! `series_buffer_rows(columns)` rows (none for no row).
   pure real(dp) function chunked(rows, columns)
      real(dp), intent(in) :: rows
      integer, intent(in) :: columns
      real(dp) :: chunk_rows
      chunk_rows = series_buffer_rows(columns)
      chunked = 8*columns*chunk_rows*ceiling(max(rows, 0.0_dp)/chunk_rows)
   end function chunked

   !> Bins of a spectrum of `samples` samples (one record, or Welch's segments beyond 2^16).
   pure real(dp) function bins_of(samples)
      real(dp), intent(in) :: samples
      bins_of = 0
      if (samples >= 2) bins_of = aint(min(samples, real(welch_segment, dp))/2) + 1
   end function bins_of

   !> The size of the results of a run (module documentation; a modes or static run writes
   !! its modes or its equilibrium).
   !! `contact_points`: those of the scene when known (the compliant stops' force has a
   !! column each); the number of obstacles otherwise. Computed in reals: the step count
   !! may exceed any default integer.
   function estimate_result_size(scene, contact_points) result(estimate)
      type(scene_type), intent(in) :: scene
      integer, intent(in), optional :: contact_points
      type(result_size) :: estimate
      integer :: field_every, points, contacts, nodes, unknowns, histories, planes
      real(dp) :: samples, bins, window, periods, omega, buffer, power
      logical :: compliant, obstacles
      planes = scene%beam%plane_count()   ! a beam of two planes: the tip and points in z too
      points = 0
      if (allocated(scene%output%points)) points = size(scene%output%points)
      obstacles = .false.
      compliant = .false.
      contacts = 0
      if (allocated(scene%obstacles)) then
         obstacles = size(scene%obstacles) > 0
         compliant = any(scene%obstacles%stiffness > 0)
         contacts = size(scene%obstacles)
      end if
      if (present(contact_points)) contacts = contact_points
      nodes = scene%mesh%elements + 1
      unknowns = scene%mesh%unknowns()
      select case (scene%analysis%kind)
      case ('modes')
         ! /mesh/x, /modes/frequency and frequency_hz, /modes/shape; STEM_modes.dat (mode,
         ! omega, f) and STEM_shapes.dat (x, then each shape); with contact_modes the same
         ! again under /contact_modes and in STEM_contact_modes.dat, STEM_contact_shapes.dat
         ! (with their group's object headers, about a third of the small metadata)
         associate (modes => real(scene%analysis%modes, dp), sets => merge(2, 1, scene%analysis%contact_modes))
            estimate%hdf5_bytes = small_metadata_bytes + 8*nodes + sets*8*(2*modes + modes*nodes) + &
                                  (sets - 1)*small_metadata_bytes/3
            if (scene%output%text) estimate%text_bytes = sets*(modes*(6 + 2*wide + 1) + nodes*((1 + modes)*wide + 1))
         end associate
         estimate%total_bytes = estimate%hdf5_bytes + estimate%text_bytes
         return
      case ('periodic')
         if (len_trim(scene%periodic%parameter) > 0) then
            ! a continuation, at most max_points points (a bounded backbone: `branch_points`): /mesh/x; /periodic/branch, 6 values
            ! and the 2J Floquet multipliers (real, imaginary) a point, and a few bifurcations
            ! (5 values each), 13 datasets' headers beside the small metadata;
            ! STEM_branch.dat (6 columns a point), STEM_bifurcations.dat and
            ! STEM_branch_multipliers.dat (5 columns a multiplier, a blank line a point), with
            ! their column lines. With switch_branch the switched branch's points come on top
            ! (not known before the run: it ends at its branch points), not counted.
            associate (points => real(branch_points(scene), dp), multipliers => 2*real(unknowns, dp))
               estimate%hdf5_bytes = small_metadata_bytes + 13*dataset_header_bytes + &
                                     8*(nodes + points*(6 + 2*multipliers) + 5*4)
               if (scene%output%text) estimate%text_bytes = points*(6*wide + 1) + 4*(5*wide + 1) + &
                                                            points*(multipliers*(5*wide + 1) + 1) + 2*text_header_bytes
            end associate
            estimate%total_bytes = estimate%hdf5_bytes + estimate%text_bytes
            return
         end if
         ! /mesh/x; /periodic: the orbit (time, tip displacement and velocity at P = k n + 1
         ! times, n the steps of a forcing period, k period_multiple), the 2J Floquet
         ! multipliers (real, imaginary), the start (2J), Newton's residuals (at most
         ! max_iterations); STEM_orbit.dat (t, u, v) and STEM_multipliers.dat (real,
         ! imaginary, modulus). J of the full model: a reduced one writes fewer multipliers.
         associate (orbit => real(forcing_period_steps(scene), dp)*scene%periodic%period_multiple + 1, &
                    multipliers => 2*real(unknowns, dp))
            estimate%hdf5_bytes = small_metadata_bytes + 8*(nodes + 3*orbit + 3*multipliers + &
                                                            scene%periodic%max_iterations)
            if (scene%output%text) estimate%text_bytes = (orbit + multipliers)*(3*wide + 1)
         end associate
         estimate%total_bytes = estimate%hdf5_bytes + estimate%text_bytes
         return
      case ('static')
         ! /mesh/x, /static/displacement, contact_x and reaction; STEM_static.dat (x, u) and
         ! STEM_reactions.dat (x, reaction)
         estimate%hdf5_bytes = small_metadata_bytes + 8*(2*nodes + 2*contacts)
         if (scene%output%text) estimate%text_bytes = (nodes + contacts)*(2*wide + 1)
         estimate%total_bytes = estimate%hdf5_bytes + estimate%text_bytes
         return
      end select
      estimate%steps = real(step_count(scene), dp)
      field_every = scene%output%field_every
      if (field_every == 0) field_every = scene%output%every
      estimate%outputs = real(step_count(scene)/int(scene%output%every, int64), dp) + 2
      estimate%snapshots = real(step_count(scene)/int(field_every, int64), dp) + 2
      ! the spectra: the output rows on the grid of `every` (t = 0 included)
      samples = real(step_count(scene)/int(scene%output%every, int64), dp) + 1
      bins = bins_of(samples)
      ! the Poincare samples: one per forcing period of the statistics window
      window = max(0.0_dp, estimate%steps - window_first_step(scene%output%measure_from, scene%time%dt))
      periods = 0
      if (forcing_of(scene, omega) /= 'none') periods = aint(window*scene%time%dt*omega/(2*pi))
      histories = size(history_paths) + merge(2, 0, compliant)   ! (+ the springs' potential and damping)
      estimate%values_per_output = histories + 2*(planes - 1) + 2*planes*points + merge(contacts, 0, compliant)
      associate (h => estimate%hdf5_bytes)
         h = metadata_bytes + histories*chunked(estimate%outputs, 1) + 2*(planes - 1)*chunked(estimate%outputs, 1)
         if (compliant) h = h + chunked(estimate%outputs, contacts)
         if (points > 0) h = h + 2*chunked(estimate%outputs, planes*points)
         h = h + chunked(estimate%snapshots, 1) + chunked(estimate%snapshots, planes*nodes)
         if (obstacles) h = h + (impact_columns + episode_columns)*chunked(1.0_dp, 1)
         h = h + 3*chunked(bins, 1)
         if (points > 0) h = h + chunked(bins, points)
         if (periods > 0) h = h + chunked(periods, 1) + 2*chunked(periods, 1 + points)
         ! the checkpoint: U, V (and U^{n-1}), the spectra's buffers and power sums (the
         ! tip's and the points' over the run, the statistics' over the window)
         buffer = min(samples, real(welch_segment, dp))
         power = merge(welch_segment/2 + 1, 0, samples > welch_segment)
         h = h + 8*(merge(3, 2, scene%time%scheme == 'position')*unknowns + (1 + points)*(buffer + power) + &
                    min(window, real(welch_segment, dp)) + merge(welch_segment/2 + 1, 0, window > welch_segment))
         ! with a Poincare section, the diagnostics' accumulators (the 0-1 test's sums, the
         ! period's ring and differences; the Lyapunov exponent's perturbation)
         if (forcing_of(scene) /= 'none') h = h + 8*(frequencies*max_lag + max_lag + 4*(1 + points)*max_period + &
                                                     merge(2*unknowns, 0, scene%output%lyapunov))
      end associate
      if (scene%output%text) then
         associate (t => estimate%text_bytes)
            ! tip (5 numbers) and energy (11) rows, points (1 + 2 P), the springs' force
            t = estimate%outputs*((5 + 2*(planes - 1) + 11)*wide + 2)
            if (points > 0) t = t + estimate%outputs*((1 + 2*planes*points)*wide + 1)
            if (compliant) t = t + estimate%outputs*((1 + contacts)*wide + 1)
            t = t + estimate%snapshots*(nodes*((2 + planes)*narrow + 1) + 1) + bins*((3 + points)*wide + 1)
            if (periods > 0) t = t + periods*((1 + 2*(1 + points))*wide + 1)
         end associate
      end if
      estimate%total_bytes = estimate%hdf5_bytes + estimate%text_bytes
   end function estimate_result_size

   !> What the sweep of `points` will write (module documentation): `contact_points` and
   !! `obstacles` those of its first point, `observations` 1 + &output points.
   function estimate_sweep_size(scene, settings, points, contact_points) result(estimate)
      type(scene_type), intent(in) :: scene
      type(sweep_settings), intent(in) :: settings
      type(sweep_point), intent(in) :: points(:)
      integer, intent(in) :: contact_points
      type(sweep_size) :: estimate
      type(statistics_layout) :: layout
      type(scene_type) :: local
      type(result_size) :: run
      integer(int64) :: settle_steps, measure_steps
      real(dp) :: omega, kept, written
      integer :: k, observations, stat
      character(len=256) :: errmsg
      observations = 1
      if (allocated(scene%output%points)) observations = 1 + size(scene%output%points)
      if (scene%analysis%kind == 'periodic') then
         call layout%init_periodic()
      else
         call layout%init(observations, contact_points, size(scene%obstacles), planes=scene%beam%plane_count())
      end if
      do k = 1, size(points)
         local = point_scene(scene, settings, points(k))
         if (local%analysis%kind == 'periodic') then
            ! its numbers in the sweep file, its record in the journal, its row, its file
            estimate%sweep_bytes = estimate%sweep_bytes + 8*(8 + layout%size)
            estimate%journal_bytes = estimate%journal_bytes + 8*record_length(layout%size) + 4*(message_words + 1)
            if (scene%output%text) estimate%text_bytes = estimate%text_bytes + orbit_sweep_columns*wide + 1
            local%output%text = .false.
            run = estimate_result_size(local, contact_points)
            estimate%point_bytes = estimate%point_bytes + run%hdf5_bytes
            cycle
         end if
         call point_windows(settings, local, settle_steps, measure_steps, stat, errmsg)
         if (stat /= 0) cycle
         kept = 0
         if (forcing_of(local, omega) /= 'none') kept = aint(measure_steps*local%time%dt*omega/(2*pi)) + 1
         ! poincare_samples = 'all' keeps every sample of the window, and its journal those
         ! of every window steady_tolerance measures too (at most max_settle_windows)
         written = kept
         if (settings%poincare_samples == 'all') then
            if (settings%steady_tolerance > 0) written = max_settle_windows*kept
         else
            kept = min(real(kept_samples, dp), kept)
            written = kept
         end if
         ! the sweep file: 16 numbers of the point and every statistic with its error; the
         ! kept Poincare samples (point, branch, parameters, time, u and v)
         estimate%sweep_bytes = estimate%sweep_bytes + 8*(16 + 2*layout%size) + kept*8*(5 + 2*observations)
         ! the journal: its record and message, the samples again (and their chunks' rows)
         estimate%journal_bytes = estimate%journal_bytes + 8*record_length(layout%size) + 4*(message_words + 1) + &
                                  written*8*(1 + 2*observations) + 24*(aint(written/chunk_rows) + 1)
         if (scene%output%text) estimate%text_bytes = estimate%text_bytes + sweep_columns*wide + 1 + &
                                                      kept*(sweep_poincare_columns*wide + 1)
         if (settings%keep_runs) then
            local%output%text = .false.
            if (settings%steady_tolerance > 0) &
               local%time%t_end = (settle_steps + max_settle_windows*measure_steps)*local%time%dt
            run = estimate_result_size(local, contact_points)
            estimate%point_bytes = estimate%point_bytes + run%hdf5_bytes
         end if
      end do
      estimate%sweep_bytes = estimate%sweep_bytes + sweep_metadata_bytes
      if (scene%output%text) estimate%text_bytes = estimate%text_bytes + 2*text_header_bytes
      estimate%total_bytes = estimate%sweep_bytes + estimate%text_bytes + estimate%point_bytes
      estimate%peak_bytes = estimate%total_bytes + estimate%journal_bytes
   end function estimate_sweep_size

   !> CPU seconds of one step of `scene` as a sweep's point runs it: the stepper and the
   !! recorder with its statistics window open, nothing written (module documentation);
   !! 0 when the scene cannot be prepared. `warm_up` steps first, which also size the
   !! blocks (at least `block_seconds` of CPU each, the clock read once a block: reading it
   !! costs as much as a step of a small model), then `blocks` blocks; the median block's
   !! cost per step.
   function step_cost(scene) result(seconds)
      type(scene_type), intent(in) :: scene
      real(dp) :: seconds
      integer, parameter :: warm_up = 1000, blocks = 5, most_block_steps = 1000000
      real(dp), parameter :: block_seconds = 0.02_dp
      type(scene_type) :: local
      type(run_problem) :: prepared
      class(time_stepper), allocatable :: stepper
      type(dynamics_recorder) :: recorder
      character(len=:), allocatable :: warnings, ignored
      character(len=256) :: errmsg
      real(dp) :: costs(blocks), start, finish
      integer :: stat, n, b, block_steps
      integer(int64) :: last
      seconds = 0
      local = scene
      local%output%measure_from = 0
      warnings = ''
      call build_problem(local, prepared, warnings, stat, errmsg)
      if (stat == 0) call new_stepper(local, prepared, stepper, stat, errmsg)
      if (stat /= 0) return
      last = warm_up + int(blocks, int64)*most_block_steps
      local%time%t_end = last*local%time%dt
      call recorder%init(local, stepper, prepared, last, write_rows=.false.)
      call recorder%start_statistics(stepper, ignored)
      call cpu_time(start)
      do n = 1, warm_up
         call advance()
         if (stat /= 0) exit
      end do
      call cpu_time(finish)
      block_steps = int(min(real(most_block_steps, dp), max(1000.0_dp, block_seconds*warm_up/max(finish - start, 1e-6_dp))))
      do b = 1, blocks
         if (stat /= 0) exit
         call cpu_time(start)
         do n = 1, block_steps
            call advance()
            if (stat /= 0) exit
         end do
         call cpu_time(finish)
         costs(b) = (finish - start)/block_steps
      end do
      call release_stepper(stepper)
      if (stat /= 0) return
      ! the median block: a block the process lost to paging or a cache storm does not count
      seconds = median(costs)
   contains
      subroutine advance()
         call stepper%step(stat, errmsg)
         if (stat == 0) call recorder%after_step(stepper, stat, errmsg)
      end subroutine advance
   end function step_cost

end module vibrobeam_result_estimate
