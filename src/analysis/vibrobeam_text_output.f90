!> The gnuplot-ready .dat files of a result, derived from its HDF5 file (docs/output.md,
!! "Text files"): after a run with `&output text = .true.`, and by `vibrobeam --text
!! FILE.h5` at any time later. The HDF5 file is read a block of rows at a time, so a
!! long run's text files need no more memory than a short run's.
!!
!! One deriver per kind of result: the modes (`modes_files`), the static equilibrium
!! (`static_files`), a periodic orbit (`periodic_files`), the histories of a dynamics run
!! (`dynamics_files`), a continued branch (`vibrobeam_branch_text`) and a sweep
!! (`vibrobeam_sweep_text`); what they share, the open file, the names and the checked
!! writes, is `vibrobeam_text_derivation`'s.
module vibrobeam_text_output
   use vibrobeam_kinds, only: dp, int64, pi
   use vibrobeam_text_derivation, only: derivation, text_sink, derived_file, discard_derived, text_file_name, &
      path_length, block_values
   use vibrobeam_sweep_text, only: sweep_files
   use vibrobeam_sweep_wear_text, only: sweep_wear_file
   use vibrobeam_branch_text, only: branch_files
   use vibrobeam_text, only: integer_text
   use vibrobeam_force_settings, only: max_forces
   use vibrobeam_progress, only: progress_meter
   implicit none
   private
   public :: derived_file, derive_text_files, discard_derived, text_file_name, text_suffixes, path_length

   !> Every suffix a result's .dat files can have.
   character(len=*), parameter :: text_suffixes(24) = [character(len=16) :: 'modes', 'shapes', 'static', &
      'reactions', 'tip', 'energy', 'impacts', 'episodes', 'points', 'field', 'spectrum', 'obstacles', 'contact', &
      'force', 'sweep', 'poincare', 'contact_modes', 'contact_shapes', 'orbit', 'multipliers', 'forces_psd', 'ensemble', &
      'branch', 'bifurcations']

contains

   !> Derive every .dat file of the HDF5 file `source` (the temporary file of a run, or a
   !! published file), named after `final_h5`. On return `files` lists them, complete and
   !! synced under temporary names. With `stop_on_signal`, SIGINT/SIGTERM stops the
   !! derivation (a run already stopped by a signal passes .false.: its result gets its
   !! text files, and a second signal ends the process): `interrupted` is set, nothing is
   !! left and `files` is empty. On failure nothing is left either.
   subroutine derive_text_files(source, final_h5, meter, stop_on_signal, files, interrupted, stat, errmsg)
      character(len=*), intent(in) :: source, final_h5
      type(progress_meter), intent(inout) :: meter
      logical, intent(in) :: stop_on_signal
      type(derived_file), allocatable, intent(out) :: files(:)
      logical, intent(out) :: interrupted
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(derivation) :: run
      character(len=:), allocatable :: run_id
      integer :: slash

      allocate (files(0))
      interrupted = .false.
      call run%file%open(source, stat, errmsg)
      if (stat /= 0) return
      call run%file%attr_string('/run', 'run_id', run_id, stat, errmsg)
      if (stat /= 0) then
         call run%file%close()
         return
      end if
      slash = index(final_h5, '/', back=.true.)
      run%header = '# vibrobeam run '//run_id//' ('//final_h5(slash + 1:)//')'
      run%final_h5 = final_h5
      run%meter = meter
      run%stop_on_signal = stop_on_signal
      allocate (run%files(0))
      derive: block
         if (run%file%exists('/modes/frequency')) then
            call modes_files(run, '/modes', 'modes', 'shapes', stat, errmsg)
            if (stat /= 0 .or. run%interrupted) exit derive
         end if
         if (run%file%exists('/contact_modes/frequency')) then
            call modes_files(run, '/contact_modes', 'contact_modes', 'contact_shapes', stat, errmsg)
            if (stat /= 0 .or. run%interrupted) exit derive
         end if
         if (run%file%exists('/static/displacement')) then
            call static_files(run, stat, errmsg)
            if (stat /= 0 .or. run%interrupted) exit derive
         end if
         if (run%file%exists('/periodic/orbit/time')) then
            call periodic_files(run, stat, errmsg)
            if (stat /= 0 .or. run%interrupted) exit derive
         end if
         if (run%file%exists('/periodic/branch/parameter')) then
            call branch_files(run, stat, errmsg)
            if (stat /= 0 .or. run%interrupted) exit derive
         end if
         if (run%file%exists('/time')) call dynamics_files(run, stat, errmsg)
         if (stat /= 0 .or. run%interrupted) exit derive
         if (run%file%exists('/sweep/parameter')) call sweep_files(run, stat, errmsg)
         if (stat /= 0 .or. run%interrupted) exit derive
         if (run%file%exists('/sweep/parameter')) call sweep_wear_file(run, stat, errmsg)
      end block derive
      call run%file%close()
      meter = run%meter
      interrupted = run%interrupted
      if (stat /= 0 .or. interrupted) then
         call discard_derived(run%files)
      else
         call move_alloc(run%files, files)
      end if
   end subroutine derive_text_files

   !> STEM_modes.dat (each mode's frequency) and STEM_shapes.dat (the mode shapes) of the
   !! modes in `group` (/modes; /contact_modes with the suffixes contact_modes,
   !! contact_shapes).
   subroutine modes_files(run, group, modes_suffix, shapes_suffix, stat, errmsg)
      type(derivation), intent(inout) :: run
      character(len=*), intent(in) :: group, modes_suffix, shapes_suffix
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: omega(:), x(:), shapes(:)
      character(len=64) :: line
      integer :: k, i, nodes
      call run%file%read_reals(group//'/frequency', omega, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/mesh/x', x, stat, errmsg)
      if (stat == 0) call run%file%read_reals(group//'/shape', shapes, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, modes_suffix, 'mode  omega (rad/s)  frequency (Hz)', stat, errmsg)
      if (stat /= 0) return
      do k = 1, size(omega)
         write (line, '(i6, 2es24.15)') k, omega(k), omega(k)/(2*pi)
         call sink%put_line(trim(line), stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, shapes_suffix, 'x (m)  then the shape of mode 1, 2, ... (tip value 1)', stat, errmsg)
      if (stat /= 0) return
      nodes = size(x)
      do i = 1, nodes
         call sink%put_row('wide', [x(i), (shapes(i + (k - 1)*nodes), k=1, size(omega))], stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
   end subroutine modes_files

   !> STEM_orbit.dat (the tip over one period of a periodic orbit) and
   !! STEM_multipliers.dat (its Floquet multipliers, when they were written).
   subroutine periodic_files(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: time(:), u(:), v(:), multipliers(:)
      integer :: i
      call run%file%read_reals('/periodic/orbit/time', time, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/periodic/orbit/tip_displacement', u, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/periodic/orbit/tip_velocity', v, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'orbit', 't (s)  tip u (m)  tip v (m/s): one period of the orbit', stat, errmsg)
      if (stat /= 0) return
      do i = 1, size(time)
         call sink%put_row('wide', [time(i), u(i), v(i)], stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0 .or. .not. run%file%exists('/periodic/floquet_multipliers')) return
      call run%file%read_reals('/periodic/floquet_multipliers', multipliers, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'multipliers', 'real  imaginary  modulus: the Floquet multipliers, largest modulus '// &
                         'first', stat, errmsg)
      if (stat /= 0) return
      do i = 1, size(multipliers)/2
         call sink%put_row('wide', [multipliers(2*i - 1), multipliers(2*i), &
                                    hypot(multipliers(2*i - 1), multipliers(2*i))], stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
   end subroutine periodic_files

   !> STEM_static.dat (the deflection) and STEM_reactions.dat (the reactions).
   subroutine static_files(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: x(:), u(:), contact_x(:), reaction(:)
      integer :: i
      call run%file%read_reals('/mesh/x', x, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/static/displacement', u, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/static/contact_x', contact_x, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/static/reaction', reaction, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'static', 'x (m)  u (m)', stat, errmsg)
      if (stat /= 0) return
      do i = 1, size(x)
         call sink%put_row('wide', [x(i), u(i)], stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'reactions', 'x (m)  reaction (N, positive upwards)', stat, errmsg)
      if (stat /= 0) return
      do i = 1, size(contact_x)
         call sink%put_row('wide', [contact_x(i), reaction(i)], stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
   end subroutine static_files

   !> The files of a dynamics run: the histories (tip, energy, impacts, episodes,
   !! observation points, compliant stops' forces), the field, the spectra, the Poincare
   !! samples and the contact points (obstacles, contact fraction).
   subroutine dynamics_files(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      call history_files(run, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      call field_file(run, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      call spectrum_file(run, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      if (run%file%exists('/forces')) call forces_psd_file(run, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      call poincare_file(run, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      call contact_point_files(run, stat, errmsg)
   end subroutine dynamics_files

   !> The series of a dynamics run, one row per output time (tip, energy, observation
   !! points, force), per impact and per contact episode.
   subroutine history_files(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      integer(int64) :: outputs, impacts, episodes
      real(dp), allocatable :: x(:)
      integer(int64), allocatable :: dims(:)
      integer :: points, k, planes
      call run%rows_of('/time', outputs, stat, errmsg)
      if (stat == 0) call run%rows_of('/impacts/time', impacts, stat, errmsg)
      if (stat == 0) call run%rows_of('/episodes/x', episodes, stat, errmsg)
      if (stat /= 0) return
      ! a beam of two planes has two columns (y, z) in /tip/displacement and /tip/velocity
      planes = 1
      if (run%file%exists('/tip/displacement')) then
         call run%file%shape('/tip/displacement', dims, stat, errmsg)
         if (stat /= 0) return
         if (size(dims) == 2) planes = int(dims(1))
      end if
      if (planes == 1) then
         call run%open_sink(sink, 'tip', 't (s)  u_tip (m)  v_tip (m/s)  mean tip contact force over the output '// &
                            'interval = tip impulse/interval (N)  tip impulse over the interval (N s)', stat, errmsg)
         if (stat /= 0) return
         call run%stream_rows(sink, [character(len=40) :: '/time', '/tip/displacement', '/tip/velocity', &
                                     '/tip/reaction', '/tip/impulse'], [1, 1, 1, 1, 1], outputs, 'wide', stat, errmsg)
      else   ! the planar columns in their places, then the z plane's (read: t, u_y, u_z, v_y, v_z, ...)
         call run%open_sink(sink, 'tip', 't (s)  u_tip (m)  v_tip (m/s)  mean tip contact force over the output '// &
                            'interval = tip impulse/interval (N)  tip impulse over the interval (N s), all in y; '// &
                            'then u_tip in z (m)  v_tip in z (m/s)', stat, errmsg)
         if (stat /= 0) return
         call run%stream_rows(sink, [character(len=40) :: '/time', '/tip/displacement', '/tip/velocity', &
                                     '/tip/reaction', '/tip/impulse'], [1, 2, 2, 1, 1], outputs, 'wide', stat, errmsg, &
                              order=[1, 2, 4, 6, 7, 3, 5])
      end if
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      call run%open_sink(sink, 'energy', 't (s)  kinetic  elastic  work of loads  dissipated (impacts + damping + '// &
                         'numerical)  dissipated by impacts  by damping  total = kinetic + elastic  balance = total - '// &
                         'work + dissipated (J)  penetration (m)  dissipated by the theta-method (J)', stat, errmsg)
      if (stat /= 0) return
      call run%stream_rows(sink, [character(len=40) :: '/time', '/energy/kinetic', '/energy/elastic', '/energy/work', &
                                  '/energy/dissipated', '/energy/dissipated_impacts', '/energy/dissipated_damping', &
                                  '/energy/total', '/energy/balance', '/contact/penetration', &
                                  '/energy/dissipated_numerical'], [(1, k=1, 11)], outputs, 'wide', stat, errmsg)
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      call run%open_sink(sink, 'impacts', 't (s)  x (m)  impulse (N s)  velocity before (m/s)  velocity after (m/s)', &
                         stat, errmsg)
      if (stat /= 0) return
      call run%stream_rows(sink, [character(len=40) :: '/impacts/time', '/impacts/x', '/impacts/impulse', &
                                  '/impacts/velocity_before', '/impacts/velocity_after'], [1, 1, 1, 1, 1], impacts, &
                           'wide', stat, errmsg)
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      call run%open_sink(sink, 'episodes', 'x (m)  start (s)  end (s)  total impulse (N s)  largest approach '// &
                         'speed (m/s)  impacts  open at the end of the run (1)', stat, errmsg)
      if (stat /= 0) return
      call run%stream_rows(sink, [character(len=40) :: '/episodes/x', '/episodes/start', '/episodes/end', &
                                  '/episodes/impulse', '/episodes/approach_speed', '/episodes/impacts', &
                                  '/episodes/open_at_end'], [(1, k=1, 7)], episodes, 'wide', stat, errmsg, integers=2)
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0 .or. run%interrupted) return
      if (run%file%exists('/points/x')) then
         call run%file%read_reals('/points/x', x, stat, errmsg)
         if (stat /= 0) return
         points = size(x)
         if (planes == 1) then
            call run%open_sink(sink, 'points', 't (s)  then u (m) at each observation point x = '// &
                               points_text(x)//' m, then v (m/s) at each', stat, errmsg)
            if (stat /= 0) return
            call run%stream_rows(sink, [character(len=40) :: '/time', '/points/displacement', '/points/velocity'], &
                                 [1, points, points], outputs, 'wide', stat, errmsg)
         else   ! the planar columns in their places, then the z plane's (read: t, (u_y, u_z) at each point, ...)
            call run%open_sink(sink, 'points', 't (s)  then u (m) at each observation point x = '// &
                               points_text(x)//' m, then v (m/s) at each, all in y; then u in z (m) at each, then '// &
                               'v in z (m/s) at each', stat, errmsg)
            if (stat /= 0) return
            call run%stream_rows(sink, [character(len=40) :: '/time', '/points/displacement', '/points/velocity'], &
                                 [1, 2*points, 2*points], outputs, 'wide', stat, errmsg, &
                                 order=[1, [(2*k, k = 1, points)], [(2*points + 2*k, k = 1, points)], &
                                        [(2*k + 1, k = 1, points)], [(2*points + 2*k + 1, k = 1, points)]])
         end if
         call run%close_sink(sink, stat, errmsg)
         if (stat /= 0 .or. run%interrupted) return
      end if
      if (run%file%exists('/contact/force')) then
         ! compliant stops: the force at each contact point (docs/output.md)
         call run%file%read_reals('/contact/x', x, stat, errmsg)
         if (stat /= 0) return
         points = size(x)
         call run%open_sink(sink, 'force', 't (s)  then the compliant stops'' force (N) at each contact point x = '// &
                            points_text(x)//' m', stat, errmsg)
         if (stat /= 0) return
         call run%stream_rows(sink, [character(len=40) :: '/time', '/contact/force'], [1, points], outputs, 'wide', &
                              stat, errmsg)
         call run%close_sink(sink, stat, errmsg)
      end if
   end subroutine history_files

   !> STEM_field.dat: one gnuplot block per snapshot, x t u (a beam of two planes: x t u_y u_z).
   subroutine field_file(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: x(:), times(:, :), field(:, :)
      integer(int64), allocatable :: dims(:)
      integer(int64) :: snapshots, first, count
      integer :: nodes, i, k, planes
      character(len=:), allocatable :: columns
      call run%rows_of('/field/time', snapshots, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/mesh/x', x, stat, errmsg)
      if (stat == 0) call run%file%shape('/field/displacement', dims, stat, errmsg)
      if (stat /= 0) return
      nodes = size(x)
      planes = merge(2, 1, size(dims) == 3)   ! (snapshots, nodes, 2): y, z at each node
      columns = 'x (m)  t (s)  u (m)'
      if (planes == 2) columns = 'x (m)  t (s)  u in y (m)  u in z (m)'
      call run%open_sink(sink, 'field', columns//'; one block per snapshot (gnuplot splot/pm3d)', stat, errmsg)
      if (stat /= 0) return
      count = max(1_int64, int(block_values/nodes, int64))
      first = 1
      blocks: do while (first <= snapshots)
         count = min(count, snapshots - first + 1)
         allocate (times(1, count), field(planes*nodes, count))
         call run%file%read_rows('/field/time', first, times, stat, errmsg)
         if (stat == 0) call run%file%read_rows('/field/displacement', first, field, stat, errmsg)
         if (stat /= 0) exit blocks
         do k = 1, int(count)
            do i = 1, nodes
               call sink%put_row('narrow', [x(i), times(1, k), field(planes*(i - 1) + 1:planes*i, k)], stat, errmsg)
               if (stat /= 0) exit blocks
            end do
            call sink%put_line('', stat, errmsg)
            if (stat /= 0) exit blocks
         end do
         deallocate (times, field)
         first = first + count
         if (run%check_signal()) exit blocks
      end do blocks
      call run%close_sink(sink, stat, errmsg)
   end subroutine field_file

   !> STEM_spectrum.dat: frequency (Hz), the tip's amplitude, frequency (rad/s), and the
   !! amplitude at each observation point (those a file of an earlier version lacks are
   !! left out); a beam of two planes: these in y, then the tip's and the points' in z.
   subroutine spectrum_file(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      integer(int64) :: bins, point_bins
      character(len=40), allocatable :: paths(:)
      integer, allocatable :: widths(:), order(:)
      integer(int64), allocatable :: dims(:)
      real(dp), allocatable :: x(:)
      character(len=:), allocatable :: columns
      integer :: planes, p, k
      call run%rows_of('/spectrum/frequency', bins, stat, errmsg)
      if (stat == 0) call run%rows_of('/spectrum/point_amplitude', point_bins, stat, errmsg)
      if (stat == 0) call run%file%shape('/spectrum/tip_amplitude', dims, stat, errmsg)
      if (stat /= 0) return
      planes = merge(2, 1, size(dims) == 2)   ! (bins, 2): y, z
      allocate (paths, source=[character(len=40) :: '/spectrum/frequency', '/spectrum/tip_amplitude'])
      allocate (widths, source=[1, planes])
      columns = 'frequency (Hz)  amplitude of the tip displacement (m)'
      if (run%file%exists('/spectrum/frequency_rad_s')) then
         paths = [character(len=40) :: paths, '/spectrum/frequency_rad_s']
         widths = [widths, 1]
         columns = columns//'  frequency (rad/s)'
      end if
      if (point_bins == bins .and. bins > 0) then
         call run%file%read_reals('/points/x', x, stat, errmsg)
         if (stat /= 0) return
         paths = [character(len=40) :: paths, '/spectrum/point_amplitude']
         widths = [widths, planes*size(x)]
         columns = columns//'  then the amplitude (m) at each observation point x = '//points_text(x)//' m'
      end if
      if (planes == 2) then   ! read: f, tip y, z, f (rad/s), y and z of each point; the z columns last
         p = (sum(widths) - 4)/2
         order = [1, 2, 4, (4 + 2*k - 1, k = 1, p), 3, (4 + 2*k, k = 1, p)]
         columns = columns//'; these in y, then the amplitudes in z (m) at the tip and at each observation point'
      end if
      call run%open_sink(sink, 'spectrum', columns//': single-sided, mean removed, Hann window, Welch average '// &
                         'over segments of 2^16 samples when longer', stat, errmsg)
      if (stat /= 0) return
      if (planes == 2) then
         call run%stream_rows(sink, paths, widths, bins, 'wide', stat, errmsg, order=order)
      else
         call run%stream_rows(sink, paths, widths, bins, 'wide', stat, errmsg)
      end if
      call run%close_sink(sink, stat, errmsg)
   end subroutine spectrum_file

   !> STEM_forces_psd.dat: for each random load (/forces/load_<i>, in the order of
   !! &forces), one gnuplot block (blocks separated by two blank lines, a comment naming the
   !! load first): frequency (Hz), target density, measured density and its 95 % band.
   subroutine forces_psd_file(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      character(len=:), allocatable :: group, unit
      character(len=40) :: paths(5)
      integer(int64) :: bins
      integer :: i, blocks
      call run%open_sink(sink, 'forces_psd', 'frequency (Hz)  target one-sided density S (unit^2/Hz)  measured '// &
                         'density (Welch, Hann segments overlapping by half)  lower and upper end of its 95 % '// &
                         'confidence band (chi-square): one block per random load (gnuplot index 0, 1, ...)', &
                         stat, errmsg)
      if (stat /= 0) return
      blocks = 0
      do i = 1, max_forces
         group = '/forces/load_'//integer_text(i)
         if (.not. run%file%exists(group//'/frequency')) cycle
         call run%file%attr_string(group, 'unit', unit, stat, errmsg)
         if (stat == 0) call run%rows_of(group//'/frequency', bins, stat, errmsg)
         if (stat == 0 .and. blocks > 0) call sink%put_line('', stat, errmsg)
         if (stat == 0 .and. blocks > 0) call sink%put_line('', stat, errmsg)
         if (stat == 0) call sink%put_line('# load '//integer_text(i)//' (unit '//unit//')', stat, errmsg)
         if (stat /= 0) exit
         paths = [character(len=40) :: group//'/frequency', group//'/psd_target', group//'/psd_measured', &
                  group//'/psd_lower', group//'/psd_upper']
         call run%stream_rows(sink, paths, [1, 1, 1, 1, 1], bins, 'wide', stat, errmsg)
         if (stat /= 0 .or. run%interrupted) exit
         blocks = blocks + 1
      end do
      call run%close_sink(sink, stat, errmsg)
   end subroutine forces_psd_file

   !> STEM_poincare.dat of a run with Poincare samples (docs/statistics.md): time, then u
   !! at the tip and at each observation point, then v at each.
   subroutine poincare_file(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: x(:)
      integer(int64) :: samples
      call run%rows_of('/statistics/poincare/time', samples, stat, errmsg)
      if (samples == 0 .or. stat /= 0) return
      call run%file%read_reals('/statistics/points/x', x, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'poincare', 't (s)  then u (m) at each observation point x = '//points_text(x)// &
                         ' m (the tip first), then v (m/s) at each: the state at phase 0 of the forcing, once per '// &
                         'period of the statistics window', stat, errmsg)
      if (stat /= 0) return
      call run%stream_rows(sink, [character(len=40) :: '/statistics/poincare/time', &
                                  '/statistics/poincare/displacement', '/statistics/poincare/velocity'], &
                           [1, size(x), size(x)], samples, 'wide', stat, errmsg)
      call run%close_sink(sink, stat, errmsg)
   end subroutine poincare_file

   !> STEM_obstacles.dat (the bounds at each contact point) and STEM_contact.dat (the
   !! fraction of the run each spent in contact).
   subroutine contact_point_files(run, stat, errmsg)
      type(derivation), intent(inout) :: run
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(text_sink) :: sink
      real(dp), allocatable :: x(:), lower(:), upper(:), fraction(:)
      integer :: k
      call run%file%read_reals('/contact/x', x, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/contact/lower', lower, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/contact/upper', upper, stat, errmsg)
      if (stat == 0) call run%file%read_reals('/contact/fraction', fraction, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'obstacles', 'x (m)  lower bound g1 (m)  upper bound g2 (m) at each contact point '// &
                         '(+-1e30: no obstacle on that side)', stat, errmsg)
      if (stat /= 0) return
      do k = 1, size(x)
         call sink%put_row('wide', [x(k), max(-1e30_dp, lower(k)), min(1e30_dp, upper(k))], stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
      if (stat /= 0) return
      call run%open_sink(sink, 'contact', 'x (m)  fraction of the run in contact (1)', stat, errmsg)
      if (stat /= 0) return
      do k = 1, size(x)
         call sink%put_row('wide', [x(k), fraction(k)], stat, errmsg)
         if (stat /= 0) exit
      end do
      call run%close_sink(sink, stat, errmsg)
   end subroutine contact_point_files

   !> '0.1, 0.25' for the observation points' x.
   function points_text(x) result(text)
      real(dp), intent(in) :: x(:)
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      integer :: k
      text = ''
      do k = 1, size(x)
         write (buffer, '(g0.6)') x(k)
         text = text//trim(adjustl(buffer))
         if (k < size(x)) text = text//', '
      end do
   end function points_text
end module vibrobeam_text_output
