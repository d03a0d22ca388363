!> Any number of loads (&forces, docs/input.md; docs/theory.md section 9): each a point
!! force, a load distributed over a segment, or the acceleration of the support (base
!! excitation), times a time signal that is harmonic or a table (a measured record).
!!
!! On the mesh a load is one or more channels, each a load vector (the consistent one of a
!! unit point force or of a unit load over the segment) kept as the slice of unknowns
!! where it is not zero, times the channel's signal value: F(t) = sum_loads sum_channels
!! s_c(t) F_c. A step costs what the loads touch (4 unknowns for a point force), not the
!! mesh size per load.
module vibrobeam_forces
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_schema_visitor, only: schema_visitor, real_row, integer_row, keyword_row, text_row, unset, &
      is_unset, keyword_length, path_length
   use vibrobeam_model, only: beam_model, point_load_vector, load_vector, unit_profile
   use vibrobeam_table_file, only: linear_table, read_table
   use vibrobeam_namelist_scanned, only: scanned_file
   implicit none
   private
   public :: max_forces, force_settings, forces_settings, visit_forces, check_forces, force_set, build_forces
   public :: forces_frequencies, ignored_forces

   integer, parameter :: max_forces = 64          !! most loads of &forces
   integer, parameter :: signal_harmonic = 1, signal_table = 2

   !> One load of &forces (docs/input.md, "&forces").
   type :: force_settings
      character(len=keyword_length) :: kind = 'point'        !! 'point' | 'distributed' | 'base'
      real(dp) :: position = unset                           !! point force: where (m); default the tip
      real(dp) :: x_from = 0                                 !! distributed: start of the segment (m)
      real(dp) :: x_to = unset                               !! distributed: end of the segment (m); default L
      character(len=keyword_length) :: signal = 'harmonic'   !! 'harmonic' | 'table'
      !> harmonic: amplitude (N, N/m or m/s^2); table: factor of its values (default 1)
      real(dp) :: amplitude = unset
      real(dp) :: frequency = 0                              !! harmonic: Omega (rad/s)
      real(dp) :: phase = 0                                  !! harmonic: phi (rad)
      character(len=path_length) :: table = ''               !! table: file of (t, value) pairs
      character(len=keyword_length) :: table_end = 'zero'    !! outside the table's times: 'zero' | 'hold'
   end type force_settings

   !> &forces: the loads.
   type :: forces_settings
      type(force_settings), allocatable :: load(:)
   end type forces_settings

   !> One channel of a load on the mesh: F_c on unknowns first .. first + size(values) - 1.
   type :: load_slice
      integer :: first = 1
      real(dp), allocatable :: values(:)
   end type load_slice

   !> One load on the mesh, ready to evaluate.
   type :: force_term
      integer :: signal = signal_harmonic
      real(dp) :: scale = 1                       !! harmonic amplitude, table factor
      real(dp) :: load_factor = 1                 !! load per unit signal: -rho S for base, else 1
      real(dp) :: frequency = 0, phase = 0        !! harmonic (rad/s, rad)
      type(linear_table) :: table                 !! table: (t, value)
      integer :: hint = 0                         !! table: the interval of the last time asked
      type(load_slice), allocatable :: channel(:)
      real(dp), allocatable :: values(:)          !! (channels) work space: signal values at t
   end type force_term

   !> The loads of &forces on the mesh (or on the reduced coordinates, `project`).
   type :: force_set
      integer :: count = 0
      type(force_term), allocatable :: term(:)
   contains
      procedure :: add_to => forces_add_to
      procedure :: add_uncached => forces_add_uncached
      procedure :: project => forces_project
   end type force_set

contains

   !> Every variable of &forces, once: `count`, then each load's variables (element i of
   !! each array variable is load i). The defaults that follow other inputs (position and
   !! x_to: the beam's length; amplitude 1 for a table) are taken where the loads are
   !! built (`build_forces`), so that a sweep of &beam length moves them.
   subroutine visit_forces(forces, count, visitor)
      type(forces_settings), intent(inout) :: forces
      integer, intent(inout) :: count            !! the loads given (size(forces%load) once read)
      class(schema_visitor), intent(inout) :: visitor
      type(force_settings) :: description
      integer :: i
      if (.not. allocated(forces%load)) allocate (forces%load(0))
      call visitor%variable(integer_row('forces', 'count', 0, max_forces, 'number of loads'), count)
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
         call visitor%variable(keyword_row('forces', 'signal', 'harmonic|table', keyword_length, &
                                           'the time signal: harmonic, or a table of (t, value)', n, i), f%signal)
         call visitor%variable(real_row('forces', 'amplitude', load_unit, -1e15_dp, 1e15_dp, &
                                        'harmonic: amplitude; table: factor of its values (default 1)', n, i, &
                                        optional=.true.), f%amplitude)
         call visitor%variable(real_row('forces', 'frequency', 'rad/s', 0.0_dp, 1e15_dp, &
                                        'harmonic: Omega of amplitude cos(Omega t + phase) (0: constant)', n, i), &
                               f%frequency)
         call visitor%variable(real_row('forces', 'phase', 'rad', -1e6_dp, 1e6_dp, 'harmonic: phase', n, i), f%phase)
         call visitor%variable(text_row('forces', 'table', path_length, 'table: file of (t, value) pairs, '// &
                                        'linear in between', n, i), f%table)
         call visitor%variable(keyword_row('forces', 'table_end', 'zero|hold', keyword_length, &
                                           'table: the signal outside the table''s times: 0, or its end values', &
                                           n, i), f%table_end)
      end subroutine visit_one
   end subroutine visit_forces

   !> The rules between the variables of &forces (docs/input.md, "&forces") for a beam of
   !! `length` (m). stat = 1 and a message naming the variable, its value and what is
   !! allowed at the first violation.
   subroutine check_forces(forces, length, stat, errmsg)
      type(forces_settings), intent(in) :: forces
      real(dp), intent(in) :: length
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i
      character(len=:), allocatable :: item
      real(dp) :: x_to
      stat = 0
      errmsg = ''
      if (.not. allocated(forces%load)) return
      if (size(forces%load) > max_forces) &
         call fail('&forces count = '//integer_text(size(forces%load))//' is outside [0, '//integer_text(max_forces)//']')
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
            end select
         end associate
      end do
   contains
      subroutine fail(message)
         character(len=*), intent(in) :: message
         if (stat /= 0) return
         stat = 1
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
            if (static .and. f%signal == 'harmonic' .and. scanned%is_given('forces', 'frequency', i)) &
               warnings = warnings//'&forces frequency('//integer_text(i)//') = '//real_text(f%frequency)// &
                          ' rad/s is ignored: kind = ''static'' takes the loads at t = 0 (amplitude cos(phase))'// &
                          new_line('a')
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

   !> The frequencies (rad/s) the loads of &forces put into the beam: each harmonic
   !! signal's (a reduced model keeps the modes up to them, `vibrobeam_problem`).
   pure function forces_frequencies(forces) result(omega)
      type(forces_settings), intent(in) :: forces
      real(dp), allocatable :: omega(:)
      integer :: i
      allocate (omega(0))
      if (.not. allocated(forces%load)) return
      do i = 1, size(forces%load)
         associate (f => forces%load(i))
            if (f%signal == 'harmonic' .and. f%frequency > 0) omega = [omega, f%frequency]
         end associate
      end do
   end function forces_frequencies

   !> The loads of `forces` on `model` (rho S in kg/m: base excitation loads the beam with
   !! -rho S times the support's acceleration). Reads the tables. stat = 1 with a message
   !! naming the variable and the file's line when a table cannot be read.
   subroutine build_forces(settings, model, rho_s, forces, stat, errmsg)
      type(forces_settings), intent(in) :: settings
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rho_s
      type(force_set), intent(out) :: forces
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: i
      stat = 0
      errmsg = ''
      forces%count = 0
      if (allocated(settings%load)) forces%count = size(settings%load)
      allocate (forces%term(forces%count))
      do i = 1, forces%count
         call build_term(settings%load(i), i, forces%term(i))
         if (stat /= 0) return
      end do
   contains
      subroutine build_term(f, i, term)
         type(force_settings), intent(in) :: f
         integer, intent(in) :: i
         type(force_term), intent(out) :: term
         real(dp) :: x_to
         x_to = model%length
         if (.not. is_unset(f%x_to)) x_to = f%x_to
         ! where the load acts: the load vector of a unit point force or unit load
         allocate (term%channel(1))
         select case (f%kind)
         case ('point')
            call set_slice(term%channel(1), point_load_vector(model, merge(model%length, f%position, is_unset(f%position))))
         case ('base')
            call set_slice(term%channel(1), load_vector(model, unit_profile))
            term%load_factor = -rho_s
         case default   ! distributed
            call set_slice(term%channel(1), load_vector(model, unit_profile, f%x_from, x_to))
         end select
         allocate (term%values(size(term%channel)), source=0.0_dp)
         ! the signal
         select case (f%signal)
         case ('harmonic')
            term%signal = signal_harmonic
            term%scale = f%amplitude
            term%frequency = f%frequency
            term%phase = f%phase
         case ('table')
            term%signal = signal_table
            term%scale = 1
            if (.not. is_unset(f%amplitude)) term%scale = f%amplitude
            call read_table(trim(f%table), term%table, stat, errmsg)
            if (stat /= 0) errmsg = '&forces table('//integer_text(i)//') = '''//trim(f%table)//''': '//trim(errmsg)
            term%table%hold_ends = f%table_end == 'hold'
         end select
      end subroutine build_term
   end subroutine build_forces

   !> The slice of `full` between its first and last non-zero entries.
   subroutine set_slice(slice, full)
      type(load_slice), intent(out) :: slice
      real(dp), intent(in) :: full(:)
      integer :: first, last
      first = findloc(abs(full) > 0, .true., dim=1)
      last = findloc(abs(full) > 0, .true., dim=1, back=.true.)
      if (first == 0) then
         slice%first = 1
         allocate (slice%values(0))
      else
         slice%first = first
         slice%values = full(first:last)
      end if
   end subroutine set_slice

   !> F(t) of the loads added to f (the steppers: the tables' positions are kept between
   !! calls, so increasing times cost O(1) per table).
   subroutine forces_add_to(self, t, f)
      class(force_set), intent(inout) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(inout) :: f(:)
      integer :: i
      do i = 1, self%count
         call term_values(self%term(i), t)
         call add_channels(self%term(i), f)
      end do
   end subroutine forces_add_to

   !> `add_to` for a caller that keeps no state: the same values.
   subroutine forces_add_uncached(self, t, f)
      class(force_set), intent(in) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(inout) :: f(:)
      type(force_term) :: term
      integer :: i
      do i = 1, self%count
         term = self%term(i)   ! (a table's hint only speeds up the search)
         call term_values(term, t)
         call add_channels(term, f)
      end do
   end subroutine forces_add_uncached

   !> f += load_factor s_c F_c over the channels of a term (its values at t).
   pure subroutine add_channels(term, f)
      type(force_term), intent(in) :: term
      real(dp), intent(inout) :: f(:)
      integer :: c, last
      do c = 1, size(term%channel)
         associate (slice => term%channel(c))
            last = slice%first + size(slice%values) - 1
            f(slice%first:last) = f(slice%first:last) + term%load_factor*term%values(c)*slice%values
         end associate
      end do
   end subroutine add_channels

   !> The loads on other coordinates q, U = T q: each channel's vector becomes T^T F_c
   !! (`vibrobeam_reduction`'s reduce_loads).
   subroutine forces_project(self, transform)
      class(force_set), intent(inout) :: self
      real(dp), intent(in) :: transform(:, :)   !! T (J, r)
      integer :: i, c
      real(dp), allocatable :: reduced(:)
      do i = 1, self%count
         do c = 1, size(self%term(i)%channel)
            associate (slice => self%term(i)%channel(c))
               if (size(slice%values) > 0) then
                  reduced = matmul(slice%values, transform(slice%first:slice%first + size(slice%values) - 1, :))
               else
                  allocate (reduced(size(transform, 2)), source=0.0_dp)
               end if
               slice%first = 1
               call move_alloc(reduced, slice%values)
            end associate
         end do
      end do
   end subroutine forces_project

   !> The signal of each of a load's channels at t into term%values (N, N/m, or the
   !! support's acceleration in m/s^2 for base); a table starts its search at the
   !! interval of the last call (`linear_table%lookup`).
   pure subroutine term_values(term, t)
      type(force_term), intent(inout) :: term
      real(dp), intent(in) :: t
      real(dp) :: value
      select case (term%signal)
      case (signal_harmonic)
         term%values = term%scale*cos(term%frequency*t + term%phase)
      case (signal_table)
         call term%table%lookup(t, value, term%hint)
         term%values = term%scale*value
      end select
   end subroutine term_values
end module vibrobeam_forces
