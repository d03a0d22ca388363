!> Any number of loads (&forces, docs/input.md; docs/theory.md section 9): each a point
!! force, a load distributed over a segment, or the acceleration of the support (base
!! excitation), times a time signal that is harmonic, a table (a measured record) or
!! random (a stationary Gaussian signal of a given spectral density,
!! `vibrobeam_random_signal`).
!!
!! On the mesh a load is one or more channels, each a load vector (the consistent one of a
!! unit point force, of a unit load over the segment, or of a hat function of the field
!! of a spatially coherent random load) kept as the slice of unknowns where it is not zero,
!! times the channel's signal value: F(t) = sum_loads sum_channels s_c(t) F_c. A step
!! costs what the loads touch (4 unknowns for a point force), not the mesh size per load.
module vibrobeam_forces
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_force_settings, only: force_settings, forces_settings
   use vibrobeam_status, only: stat_failure, stat_invalid_input
   use vibrobeam_text, only: real_text, integer_text, short_text
   use vibrobeam_schema_visitor, only: is_unset, unset_integer
   use vibrobeam_model, only: beam_model, point_load_vector, load_vector, unit_profile, add_inertial_excess
   use vibrobeam_table_file, only: linear_table, read_table
   use vibrobeam_random, only: random_key
   use vibrobeam_planes, only: direction_shares
   use vibrobeam_random_signal, only: spectrum_shape, random_signal
   implicit none
   private
   public :: force_set, build_forces

   integer, parameter :: signal_harmonic = 1, signal_table = 2, signal_random = 3
   !> most samples a random load keeps per kind (its block and its noise, L values each per
   !! channel: 1 GiB in all)
   integer(int64), parameter :: max_block_samples = 2_int64**26


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
      type(random_signal) :: random               !! random: the signal of each channel
      type(load_slice), allocatable :: channel(:)
      real(dp), allocatable :: values(:)          !! (channels) work space: signal values at t
      !> (cos, sin) of its direction (&forces direction): a beam of two planes takes the
      !! load in y times the first and in z times the second (`add_to_planes`)
      real(dp) :: shares(2) = [1.0_dp, 0.0_dp]
   end type force_term

   !> The loads of &forces on the mesh (or on the reduced coordinates, `project`).
   type :: force_set
      integer :: count = 0
      type(force_term), allocatable :: term(:)
   contains
      procedure :: add_to => forces_add_to
      procedure :: add_uncached => forces_add_uncached
      procedure :: add_to_planes => forces_add_to_planes
      procedure :: add_uncached_planes => forces_add_uncached_planes
      procedure :: project => forces_project
      procedure :: frequencies => forces_frequencies
      procedure :: signal_values => forces_signal_values
      procedure :: random_of => forces_random_of
      procedure :: report => forces_report
   end type force_set

contains

   !> The loads of `forces` on `model` (rho S in kg/m: base excitation loads the beam with
   !! -rho S times the support's acceleration), their random signals sampled every `dt`
   !! (s). Reads the tables. stat = stat_invalid_input with a message naming the variable
   !! and the file's line when a table cannot be read or does not fit (a spectrum above the
   !! Nyquist frequency, a negative density), stat_failure when FFTW cannot plan.
   subroutine build_forces(settings, model, rho_s, dt, forces, stat, errmsg)
      type(forces_settings), intent(in) :: settings
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: rho_s, dt
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
         if (.not. is_unset(settings%load(i)%direction)) forces%term(i)%shares = direction_shares(settings%load(i)%direction)
         if (stat /= 0) return
      end do
   contains
      subroutine build_term(f, i, term)
         type(force_settings), intent(in) :: f
         integer, intent(in) :: i
         type(force_term), intent(out) :: term
         type(spectrum_shape) :: shape
         real(dp), allocatable :: field(:), base(:)
         real(dp) :: x_to
         integer :: k, seed
         character(len=:), allocatable :: item
         item = '('//integer_text(i)//')'
         x_to = model%length
         if (.not. is_unset(f%x_to)) x_to = f%x_to
         ! where the load acts: the load vector of a unit point force or unit load, or the
         ! hat functions of the points of a spatially coherent random field
         if (f%kind == 'distributed' .and. f%signal == 'random' .and. f%correlation_length > 0) then
            field = field_points(model, f%x_from, x_to)
            allocate (term%channel(size(field)))
            do k = 1, size(field)
               call set_slice(term%channel(k), hat_vector(model, field, k))
            end do
         else
            allocate (term%channel(1))
            select case (f%kind)
            case ('point')
               call set_slice(term%channel(1), point_load_vector(model, merge(model%length, f%position, &
                                                                               is_unset(f%position))))
            case ('base')
               ! the support's acceleration loads rho S (each section's) and each point mass
               ! m_k (&masses)
               base = load_vector(model, unit_profile)
               call add_inertial_excess(model, rho_s, base)
               call set_slice(term%channel(1), base)
               term%load_factor = -rho_s
            case default   ! distributed
               call set_slice(term%channel(1), load_vector(model, unit_profile, f%x_from, x_to))
            end select
         end if
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
            if (stat /= 0) then
               stat = stat_invalid_input
               errmsg = '&forces table'//item//' = '''//trim(f%table)//''': '//trim(errmsg)
            end if
            term%table%hold_ends = f%table_end == 'hold'
         case ('random')
            term%signal = signal_random
            if (len_trim(f%psd_table) > 0) then
               shape%tabulated = .true.
               call read_table(trim(f%psd_table), shape%table, stat, errmsg)
               if (stat /= 0) then
                  stat = stat_invalid_input
                  errmsg = '&forces psd_table'//item//' = '''//trim(f%psd_table)//''': '//trim(errmsg)
               else if (shape%table%x(1) < 0 .or. any(shape%table%y < 0)) then
                  stat = stat_invalid_input
                  errmsg = '&forces psd_table'//item//' = '''//trim(f%psd_table)//''' holds a negative frequency '// &
                           'or density: f >= 0 Hz and S >= 0 are allowed'
               else if (shape%variance() <= 0) then
                  stat = stat_invalid_input
                  errmsg = '&forces psd_table'//item//' = '''//trim(f%psd_table)//''' has a zero density everywhere'
               else if (shape%highest() > 1/(2*dt)) then
                  stat = stat_invalid_input
                  errmsg = '&forces psd_table'//item//' = '''//trim(f%psd_table)//''' reaches '// &
                           real_text(shape%highest())//' Hz, above the Nyquist frequency 1/(2 dt) = '// &
                           real_text(1/(2*dt))//' Hz of &time dt: cut the table or lower dt'
               end if
               if (stat /= 0) return
            else
               shape%level = f%psd_level
               shape%band_from = f%band_from
               shape%band_to = f%band_to
            end if
            seed = i
            if (f%seed /= unset_integer) seed = f%seed
            if (size(term%channel) > 1) then
               call term%random%design(shape, dt, random_key(seed, int(settings%realisation, int64) - 1), stat, &
                                       errmsg, field, f%correlation_length)
            else
               call term%random%design(shape, dt, random_key(seed, int(settings%realisation, int64) - 1), stat, errmsg)
            end if
            if (stat == 0 .and. int(term%random%taps, int64)*size(term%channel) > max_block_samples) then
               stat = stat_invalid_input
               errmsg = '&forces load'//item//': its random signal keeps 2 x '// &
                        integer_text(term%random%taps)//' samples for each of its '//integer_text(size(term%channel))// &
                        ' points, more than 1 GiB: give correlation_length = 0 or fewer elements, or a band further '// &
                        'from 0 Hz and wider (the filter resolves its narrowest feature)'
            end if
         end select
      end subroutine build_term
   end subroutine build_forces

   !> The points of a coherent random field over [a, b] (m): a, the nodes strictly inside,
   !! b (docs/theory.md section 9: the load is linear between them).
   function field_points(model, a, b) result(points)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: a, b
      real(dp), allocatable :: points(:)
      integer :: node
      points = [a]
      do node = 2, model%elements
         if (model%x(node) > a + 1e-9_dp*model%h .and. model%x(node) < b - 1e-9_dp*model%h) &
            points = [points, model%x(node)]
      end do
      points = [points, b]
   end function field_points

   !> The load vector of the hat function of field point k: 1 there, linear to 0 at its
   !! neighbours (`field_points`). On [a, b] the hat is (x - a)/(b - a) or (b - x)/(b - a):
   !! combinations of the load vectors of the profiles 1 and x over [a, b] (module
   !! procedures: an internal one passed as a profile would need an executable stack).
   function hat_vector(model, points, k) result(f)
      type(beam_model), intent(in) :: model
      real(dp), intent(in) :: points(:)
      integer, intent(in) :: k
      real(dp) :: f(model%unknowns)
      real(dp) :: a, b
      f = 0
      if (k > 1) then
         a = points(k - 1)
         b = points(k)
         f = f + (load_vector(model, position_profile, a, b) - a*load_vector(model, unit_profile, a, b))/(b - a)
      end if
      if (k < size(points)) then
         a = points(k)
         b = points(k + 1)
         f = f + (b*load_vector(model, unit_profile, a, b) - load_vector(model, position_profile, a, b))/(b - a)
      end if
   end function hat_vector

   !> The profile x (m): with `unit_profile`, every linear profile.
   pure function position_profile(x) result(value)
      real(dp), intent(in) :: x
      real(dp) :: value
      value = x
   end function position_profile

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

   !> `add_to` for a caller that keeps no state: the same values (a copy of each load
   !! evaluates them: a table's hint only speeds up its search, a random signal computes
   !! the block of t).
   !> `add_to` for a beam of two planes: each load into y and z (f of 2J values, stacked)
   !! times the shares of its direction.
   subroutine forces_add_to_planes(self, t, f)
      class(force_set), intent(inout) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(inout) :: f(:)
      integer :: i
      do i = 1, self%count
         call term_values(self%term(i), t)
         call add_turned(self%term(i), f)
      end do
   end subroutine forces_add_to_planes

   !> `add_uncached` for a beam of two planes (`add_to_planes`).
   subroutine forces_add_uncached_planes(self, t, f)
      class(force_set), intent(in) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(inout) :: f(:)
      type(force_term) :: term
      integer :: i
      do i = 1, self%count
         term = self%term(i)
         call term_values(term, t)
         call add_turned(term, f)
      end do
   end subroutine forces_add_uncached_planes

   !> One load's channels into the y plane (f(1:J)) and, when its direction has a share in
   !! z, into the z plane (f(J+1:2J)), each times its share (a load along y: the planar
   !! sum unchanged, nothing in z).
   pure subroutine add_turned(term, f)
      type(force_term), intent(in) :: term
      real(dp), intent(inout) :: f(:)
      integer :: j
      j = size(f)/2
      if (abs(term%shares(1) - 1) <= 0) then
         call add_channels(term, f(1:j))
      else if (abs(term%shares(1)) > 0) then
         call add_channels(term, f(1:j), term%shares(1))
      end if
      if (abs(term%shares(2)) > 0) call add_channels(term, f(j + 1:), term%shares(2))
   end subroutine add_turned

   subroutine forces_add_uncached(self, t, f)
      class(force_set), intent(in) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(inout) :: f(:)
      type(force_term) :: term
      integer :: i
      do i = 1, self%count
         term = self%term(i)
         call term_values(term, t)
         call add_channels(term, f)
      end do
   end subroutine forces_add_uncached

   !> f += load_factor s_c F_c over the channels of a term (its values at t).
   pure subroutine add_channels(term, f, share)
      type(force_term), intent(in) :: term
      real(dp), intent(inout) :: f(:)
      real(dp), intent(in), optional :: share   !! a factor on every value (a direction's share)
      integer :: c, last
      do c = 1, size(term%channel)
         associate (slice => term%channel(c))
            last = slice%first + size(slice%values) - 1
            if (present(share)) then
               f(slice%first:last) = f(slice%first:last) + term%load_factor*(share*term%values(c))*slice%values
            else
               f(slice%first:last) = f(slice%first:last) + term%load_factor*term%values(c)*slice%values
            end if
         end associate
      end do
   end subroutine add_channels

   !> The highest frequencies (rad/s) the loads put into the beam: each harmonic signal's,
   !! and 2 pi times the highest frequency of each random signal's density (a reduced
   !! model keeps the modes up to them, `vibrobeam_problem`).
   pure function forces_frequencies(self) result(omega)
      class(force_set), intent(in) :: self
      real(dp), allocatable :: omega(:)
      real(dp), parameter :: two_pi = 2*acos(-1.0_dp)
      integer :: i
      allocate (omega(0))
      do i = 1, self%count
         associate (term => self%term(i))
            if (term%signal == signal_harmonic .and. term%frequency > 0) omega = [omega, term%frequency]
            if (term%signal == signal_random) omega = [omega, two_pi*term%random%highest]
         end associate
      end do
   end function forces_frequencies

   !> The signal of each load at t (channel 1 of a coherent field), in its unit (N, N/m,
   !! or m/s^2 for the support's acceleration): what the loads' outputs record.
   subroutine forces_signal_values(self, t, values)
      class(force_set), intent(inout) :: self
      real(dp), intent(in) :: t   !! time (s)
      real(dp), intent(out) :: values(:)   !! (count)
      integer :: i
      do i = 1, self%count
         call term_values(self%term(i), t)
         values(i) = self%term(i)%values(1)
      end do
   end subroutine forces_signal_values

   !> What `vibrobeam --check` says of the random loads (docs/method.md, "Random
   !! signals"), one line each: the filter's taps and resolution, the RMS of the signal
   !! made against the RMS its density asks for (they differ by the smoothing of the
   !! density's sharp edges), and the points of a coherent field. '' without random loads.
   function forces_report(self) result(text)
      class(force_set), intent(in) :: self
      character(len=:), allocatable :: text
      integer :: i
      text = ''
      do i = 1, self%count
         associate (term => self%term(i), signal => self%term(i)%random)
            if (term%signal /= signal_random) cycle
            text = text//'random load '//integer_text(i)//': filter of '//integer_text(signal%taps)// &
                   ' taps (resolution 1/(L dt) = '//short_text(1/(signal%taps*signal%step))//' Hz), signal RMS '// &
                   short_text(signal%rms)//', the density''s sqrt(integral of S) '//short_text(signal%target_rms)
            if (signal%channels > 1) text = text//', '//integer_text(signal%channels)//' coherent points'
            text = text//new_line('a')
         end associate
      end do
   end function forces_report

   !> The random signal of load i (a copy; none designed when load i is not random):
   !! its taps, density and block length, for reports and tests.
   function forces_random_of(self, i) result(signal)
      class(force_set), intent(in) :: self
      integer, intent(in) :: i
      type(random_signal) :: signal
      signal = self%term(i)%random
   end function forces_random_of

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
   !! interval of the last call (`linear_table%lookup`), a random signal keeps the block
   !! of samples t is in (`random_signal%values`).
   subroutine term_values(term, t)
      type(force_term), intent(inout) :: term
      real(dp), intent(in) :: t
      real(dp) :: value
      select case (term%signal)
      case (signal_harmonic)
         term%values = term%scale*cos(term%frequency*t + term%phase)
      case (signal_table)
         call term%table%lookup(t, value, term%hint)
         term%values = term%scale*value
      case (signal_random)
         call term%random%values(t, term%values)
      end select
   end subroutine term_values
end module vibrobeam_forces
