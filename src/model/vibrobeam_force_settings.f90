!> The loads of &forces as the input gives them (docs/input.md, "&forces"): each variable
!! declared once in `visit_forces`, the rules between them (`check_forces`) and the
!! values a scene gives but its analysis ignores (`ignored_forces`). What the loads are on
!! the mesh and in time is `vibrobeam_forces`'.
module vibrobeam_force_settings
   use vibrobeam_kinds, only: dp
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, unset, &
      is_unset, unset_integer, keyword_length, path_length
   use vibrobeam_namelist_scanned, only: scanned_file
   use vibrobeam_namelist_schema, only: namelist_variable
   use vibrobeam_frequency_twins, only: hertz_twin
   implicit none
   private
   public :: max_forces, force_settings, forces_settings, visit_forces, check_forces, ignored_forces

   integer, parameter :: max_forces = 64          !! most loads of &forces

   !> One load of &forces (docs/input.md, "&forces").
   type :: force_settings
      character(len=keyword_length) :: kind = 'point'        !! 'point' | 'distributed' | 'base'
      real(dp) :: position = unset                           !! point force: where (m); default the tip
      real(dp) :: x_from = 0                                 !! distributed: start of the segment (m)
      real(dp) :: x_to = unset                               !! distributed: end of the segment (m); default L
      character(len=keyword_length) :: signal = 'harmonic'   !! 'harmonic' | 'table' | 'random'
      !> harmonic: amplitude (N, N/m or m/s^2); table: factor of its values (default 1)
      real(dp) :: amplitude = unset
      real(dp) :: frequency = 0                              !! harmonic: Omega (rad/s)
      real(dp) :: frequency_hz = 0                           !! the same in Hz (`vibrobeam_frequency_twins`)
      real(dp) :: phase = 0                                  !! harmonic: phi (rad)
      character(len=path_length) :: table = ''               !! table: file of (t, value) pairs
      character(len=keyword_length) :: table_end = 'zero'    !! outside the table's times: 'zero' | 'hold'
      real(dp) :: psd_level = 0                              !! random: one-sided density over the band (unit^2/Hz)
      real(dp) :: band_from = 0, band_to = 0                 !! random: the band (Hz)
      character(len=path_length) :: psd_table = ''           !! random: file of (f, S) pairs instead
      integer :: seed = unset_integer                        !! random: seed (default the load's number)
      real(dp) :: correlation_length = 0                     !! random distributed: l of exp(-|dx|/l) (m); 0: fully correlated
      !> with &beam planes = 2: the load's direction, degrees from y towards z (unset: 0,
      !! along y; listed only when given)
      real(dp) :: direction = unset
   end type force_settings

   !> &forces: the loads and the realisation of their random signals.
   type :: forces_settings
      !> realisation of the random signals (a whole number >= 1): another realisation gives
      !! independent signals with the same seeds (docs/statistics.md, "Ensembles"); a real,
      !! so that a sweep can vary it
      real(dp) :: realisation = 1
      type(force_settings), allocatable :: load(:)
   end type forces_settings

contains

   !> Every variable of &forces, once: `count`, `realisation`, then each load's variables
   !! (element i of each array variable is load i). The defaults that follow other inputs
   !! (position and x_to: the beam's length; amplitude 1 for a table; seed: the load's
   !! number) are taken where the loads are built (`build_forces`), so that a sweep of
   !! &beam length moves them.
   subroutine visit_forces(forces, count, visitor)
      type(forces_settings), intent(inout) :: forces
      integer, intent(inout) :: count            !! the loads given (size(forces%load) once read)
      class(schema_visitor), intent(inout) :: visitor
      type(force_settings) :: description
      integer :: i
      if (.not. allocated(forces%load)) allocate (forces%load(0))
      call visitor%variable(integer_row('forces', 'count', 0, max_forces, 'number of loads'), count)
      call visitor%variable(real_row('forces', 'realisation', '', 1.0_dp, 1e9_dp, &
                                     'realisation of the random signals (a whole number)'), forces%realisation)
      do i = 1, size(forces%load)
         call visit_one(forces%load(i), i)
      end do
      if (size(forces%load) == 0) call visit_one(description, 0)
   contains
      subroutine visit_one(f, i)
         type(force_settings), intent(inout) :: f
         integer, intent(in) :: i                  !! the load (0: a description only)
         integer, parameter :: n = max_forces
         character(len=*), parameter :: load_unit = 'N|N/m|m/s^2'
         type(namelist_variable) :: row
         call visitor%variable(keyword_row('forces', 'kind', 'point|distributed|base', keyword_length, &
                                           'a point force, a load over a segment, or the support''s acceleration', &
                                           n, i), f%kind)
         call visitor%variable(real_row('forces', 'position', 'm', 0.0_dp, 1e6_dp, &
                                        'where a point force acts (default: the tip)', n, i, optional=.true.), f%position)
         call visitor%variable(real_row('forces', 'x_from', 'm', 0.0_dp, 1e6_dp, &
                                        'start of a distributed load''s segment', n, i), f%x_from)
         call visitor%variable(real_row('forces', 'x_to', 'm', 0.0_dp, 1e6_dp, &
                                        'end of a distributed load''s segment (default: the tip)', n, i, optional=.true.), &
                               f%x_to)
         call visitor%variable(keyword_row('forces', 'signal', 'harmonic|table|random', keyword_length, &
                                           'the time signal: harmonic, a table of (t, value), or random', n, i), f%signal)
         call visitor%variable(real_row('forces', 'amplitude', load_unit, -1e15_dp, 1e15_dp, &
                                        'harmonic: amplitude; table: factor of its values (default 1)', n, i, &
                                        optional=.true.), f%amplitude)
         row = real_row('forces', 'frequency', 'rad/s', 0.0_dp, 1e15_dp, &
                        'harmonic: Omega of amplitude cos(Omega t + phase) (0: constant)', n, i)
         call visitor%variable(row, f%frequency)
         call visitor%variable(hertz_twin(row), f%frequency_hz)
         call visitor%variable(real_row('forces', 'phase', 'rad', -1e6_dp, 1e6_dp, 'harmonic: phase', n, i), f%phase)
         call visitor%variable(text_row('forces', 'table', path_length, 'table: file of (t, value) pairs, '// &
                                        'linear in between', n, i), f%table)
         call visitor%variable(keyword_row('forces', 'table_end', 'zero|hold', keyword_length, &
                                           'table: the signal outside the table''s times: 0, or its end values', &
                                           n, i), f%table_end)
         call visitor%variable(real_row('forces', 'psd_level', 'unit^2/Hz', 0.0_dp, 1e30_dp, &
                                        'random: one-sided power spectral density over the band', n, i), f%psd_level)
         call visitor%variable(real_row('forces', 'band_from', 'Hz', 0.0_dp, 1e15_dp, &
                                        'random: lowest frequency of the band', n, i), f%band_from)
         call visitor%variable(real_row('forces', 'band_to', 'Hz', 0.0_dp, 1e15_dp, &
                                        'random: highest frequency of the band', n, i), f%band_to)
         call visitor%variable(text_row('forces', 'psd_table', path_length, 'random: file of (f, S) pairs '// &
                                        '(Hz, unit^2/Hz), linear in between, instead of the band', n, i), f%psd_table)
         call visitor%variable(integer_row('forces', 'seed', 0, huge(1), 'random: seed of the signal '// &
                                           '(default: the load''s number)', optional=.true., extent=n, element=i), &
                               f%seed)
         call visitor%variable(real_row('forces', 'correlation_length', 'm', 0.0_dp, 1e6_dp, &
                                        'random distributed: length l of the coherence exp(-|x - y|/l) (0: fully '// &
                                        'correlated)', n, i), f%correlation_length)
         call visitor%variable(real_row('forces', 'direction', 'deg', -360.0_dp, 360.0_dp, &
                                        'with &beam planes = 2: direction of the load, from y towards z (default 0)', &
                                        n, i, optional=.true.), f%direction)
      end subroutine visit_one
   end subroutine visit_forces

   !> The rules between the variables of &forces (docs/input.md, "&forces") for a beam of
   !! `length` (m) stepped with `dt` (s) when `dynamics`. stat = stat_failure and a message
   !! naming the variable, its value and what is allowed at the first violation.
   subroutine check_forces(forces, length, dt, dynamics, stat, errmsg)
      type(forces_settings), intent(in) :: forces
      real(dp), intent(in) :: length, dt
      logical, intent(in) :: dynamics
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i
      character(len=:), allocatable :: item
      real(dp) :: x_to, nyquist
      stat = 0
      errmsg = ''
      if (.not. allocated(forces%load)) return
      if (size(forces%load) > max_forces) &
         call fail('&forces count = '//integer_text(size(forces%load))//' is outside [0, '//integer_text(max_forces)//']')
      if (abs(forces%realisation - aint(forces%realisation)) > 0) &
         call fail('&forces realisation = '//real_text(forces%realisation)//' is not a whole number: give 1, 2, 3, ...')
      nyquist = 1/(2*dt)
      do i = 1, size(forces%load)
         item = '('//integer_text(i)//')'
         associate (f => forces%load(i))
            select case (f%kind)
            case ('point')
               if (.not. is_unset(f%position) .and. f%position > length) &
                  call fail('&forces position'//item//' = '//real_text(f%position)//' is outside [0, '// &
                            real_text(length)//'] m, [0, length]')
            case ('distributed')
               x_to = length
               if (.not. is_unset(f%x_to)) x_to = f%x_to
               if (x_to > length) call fail('&forces x_to'//item//' = '//real_text(x_to)//' is outside [x_from'// &
                                            item//', length] = ['//real_text(f%x_from)//', '//real_text(length)//'] m')
               if (x_to <= f%x_from) call fail('&forces x_from'//item//' = '//real_text(f%x_from)//' is not below x_to'// &
                                               item//' = '//real_text(x_to)//' m: a distributed load needs a segment '// &
                                               'of positive length')
            end select
            select case (f%signal)
            case ('harmonic')
               if (is_unset(f%amplitude)) call fail('&forces amplitude'//item//' is missing: a harmonic signal '// &
                                                    'amplitude cos(frequency t + phase) needs its amplitude')
            case ('table')
               if (len_trim(f%table) == 0) call fail('&forces table'//item//' is missing: give the file of '// &
                                                     '(t, value) pairs of the table signal')
            case ('random')
               if (len_trim(f%psd_table) > 0) then
                  if (f%psd_level > 0) call fail('&forces psd_level'//item//' = '//real_text(f%psd_level)// &
                                                 ' unit^2/Hz and psd_table'//item//' are both given: give one of them')
               else
                  if (f%psd_level <= 0) call fail('&forces psd_level'//item//' is missing: a random signal needs '// &
                                                  'psd_level > 0 over band_from .. band_to, or psd_table')
                  if (f%band_to <= f%band_from) call fail('&forces band_to'//item//' = '//real_text(f%band_to)// &
                                                          ' Hz is not above band_from'//item//' = '// &
                                                          real_text(f%band_from)//' Hz: the band needs a width')
                  if (dynamics .and. f%band_to > nyquist) &
                     call fail('&forces band_to'//item//' = '//real_text(f%band_to)//' Hz is above the Nyquist '// &
                               'frequency 1/(2 dt) = '//real_text(nyquist)//' Hz of &time dt: lower it or dt')
               end if
            end select
         end associate
      end do
   contains
      subroutine fail(message)
         character(len=*), intent(in) :: message
         if (stat /= 0) return
         stat = stat_failure
         errmsg = message
      end subroutine fail
   end subroutine check_forces

   !> One warning line in `warnings` for each variable of a load that the file gives and
   !! its kind or signal does not use (docs/input.md, "Warnings"): a position beside a
   !! load that is not a point force, a segment beside one that is not distributed, a
   !! harmonic's frequency or phase beside a table, a table beside a harmonic; and, for
   !! kind = 'static' (`static`), the frequencies (the loads at t = 0 are taken).
   subroutine ignored_forces(scanned, forces, static, warnings)
      type(scanned_file), intent(in) :: scanned
      type(forces_settings), intent(in) :: forces
      logical, intent(in) :: static
      character(len=:), allocatable, intent(inout) :: warnings
      integer :: i
      if (.not. allocated(forces%load)) return
      if (scanned%is_given('forces', 'realisation') .and. .not. any(forces%load%signal == 'random')) &
         warnings = warnings//'&forces realisation = '//real_text(forces%realisation)//' is ignored: no load has '// &
                    'signal = ''random'''//new_line('a')
      do i = 1, size(forces%load)
         associate (f => forces%load(i))
            if (f%kind /= 'point') call given('position', real_text(f%position)//' m', 'kind', f%kind)
            if (f%kind /= 'distributed') then
               call given('x_from', real_text(f%x_from)//' m', 'kind', f%kind)
               call given('x_to', real_text(f%x_to)//' m', 'kind', f%kind)
            end if
            if (f%signal /= 'harmonic') then
               call given('frequency', real_text(f%frequency)//' rad/s', 'signal', f%signal)
               call given('phase', real_text(f%phase)//' rad', 'signal', f%signal)
            end if
            if (f%signal /= 'table') then
               call given('table', ''''//trim(f%table)//'''', 'signal', f%signal)
               call given('table_end', ''''//trim(f%table_end)//'''', 'signal', f%signal)
            end if
            if (f%signal /= 'random') then
               call given('psd_level', real_text(f%psd_level)//' unit^2/Hz', 'signal', f%signal)
               call given('band_from', real_text(f%band_from)//' Hz', 'signal', f%signal)
               call given('band_to', real_text(f%band_to)//' Hz', 'signal', f%signal)
               call given('psd_table', ''''//trim(f%psd_table)//'''', 'signal', f%signal)
               call given('seed', integer_text(f%seed), 'signal', f%signal)
            end if
            if (f%signal /= 'random' .or. f%kind /= 'distributed') &
               call given('correlation_length', real_text(f%correlation_length)//' m', &
                          trim(merge('signal', 'kind  ', f%signal /= 'random')), &
                          merge(f%signal, f%kind, f%signal /= 'random'))
            if (f%signal == 'random' .and. len_trim(f%psd_table) > 0) then
               call given('band_from', real_text(f%band_from)//' Hz', 'psd_table', f%psd_table)
               call given('band_to', real_text(f%band_to)//' Hz', 'psd_table', f%psd_table)
            end if
            if (static .and. f%signal == 'harmonic' .and. scanned%is_given('forces', 'frequency', i)) &
               warnings = warnings//'&forces frequency('//integer_text(i)//') = '//real_text(f%frequency)// &
                          ' rad/s is ignored: kind = ''static'' takes the loads at t = 0 (amplitude cos(phase))'// &
                          new_line('a')
            if (static .and. f%signal == 'random') &
               warnings = warnings//'&forces signal('//integer_text(i)//') = ''random'': kind = ''static'' takes '// &
                          'the loads at t = 0, one sample of the random signal'//new_line('a')
         end associate
      end do
   contains
      !> '&forces name(i) = value is ignored: other(i) = 'keyword''.
      subroutine given(name, value, other, keyword)
         character(len=*), intent(in) :: name, value, other, keyword
         if (.not. scanned%is_given('forces', name, i)) return
         warnings = warnings//'&forces '//name//'('//integer_text(i)//') = '//value//' is ignored: '//other//'('// &
                    integer_text(i)//') = '''//trim(keyword)//''''//new_line('a')
      end subroutine given
   end subroutine ignored_forces

end module vibrobeam_force_settings
