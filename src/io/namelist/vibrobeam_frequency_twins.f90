!> Frequencies in Hz beside rad/s (docs/input.md, "Frequencies in Hz").
!!
!! Every input frequency is declared in rad/s (an angular frequency omega, unit 'rad/s')
!! and, on the next line of the same `visit` routine, its twin in Hz (f = omega/(2 pi)),
!! named with `twin_suffix`: `&load base_frequency` and `base_frequency_hz`. The twin's row
!! is made from the frequency's (`hertz_twin`), so its range, unit and meaning follow:
!!
!!     row = real_row('load', 'base_frequency', 'rad/s', 0.0_dp, 1e15_dp, 'Omega_b of ...')
!!     call visitor%variable(row, load%base_frequency)
!!     call visitor%variable(hertz_twin(row), load%base_frequency_hz)
!!
!! The rad/s variable is the one the code uses; the twin is a way to give it and a listing
!! of it. A file gives one of the two (both: invalid input), and the reader sets the other
!! (`vibrobeam_scene_read`); `pair_accessor` sets a variable and its twin together (what a
!! sweep over either does, `vibrobeam_scene_values`); `twin_sync` makes every twin agree
!! with its frequency (before a scene is checked or listed). Which rows are twins follows
!! from the declarations alone: a real row named '<name>_hz' in 'Hz' beside a row <name>
!! in 'rad/s' of the same group (verification/unit/test_frequency_twins.f90 checks that
!! every 'rad/s' variable has one).
module vibrobeam_frequency_twins
   use vibrobeam_kinds, only: dp, pi
   use vibrobeam_namelist_schema, only: namelist_variable, kind_real
   use vibrobeam_schema_visitor, only: schema_visitor, is_unset, unset
   use vibrobeam_schema_operations, only: schema_accessor
   implicit none
   private
   public :: twin_suffix, angular_unit, twin_unit, two_pi, hertz_twin, is_twin, frequency_name, twin_name
   public :: agrees, pair_accessor, pair_for, twin_sync

   character(len=*), parameter :: twin_suffix = '_hz'     !! name of the twin: the frequency's name and this
   character(len=*), parameter :: angular_unit = 'rad/s'  !! unit of a frequency that has a twin
   character(len=*), parameter :: twin_unit = 'Hz'        !! unit of the twin
   real(dp), parameter :: two_pi = 2*pi                   !! omega = two_pi f, f = omega/two_pi

   !> Sets (or gets) one real by name, like `schema_accessor`, and keeps its twin in step
   !! in the same walk: setting a frequency sets its twin to value/(2 pi), setting a twin
   !! sets its frequency to 2 pi value. A variable without a twin is set alone.
   type, extends(schema_visitor) :: pair_accessor
      type(schema_accessor) :: named                       !! the variable asked for
      type(schema_accessor) :: partner                     !! its twin or its frequency (set mode only)
   contains
      procedure :: visit => visit_pair
   end type pair_accessor

   !> Makes every twin agree with its frequency, in two walks of the same declarations:
   !! the first (`collecting`) notes each frequency (each element of an array's), the
   !! second sets each twin that does not agree with its frequency (`agrees`) to
   !! frequency/(2 pi), or unset with it.
   type, extends(schema_visitor) :: twin_sync
      logical :: collecting = .true.
      character(len=49), allocatable :: names(:)           !! 'group.name' or 'group.name(i)' of each frequency
      real(dp), allocatable :: values(:)                   !! its value (rad/s)
   contains
      procedure :: visit => visit_sync
   end type twin_sync

contains

   !> The row of the twin in Hz of the frequency described by `row` (rad/s): its name with
   !! `twin_suffix`, unit Hz, range and least magnitude divided by 2 pi.
   pure function hertz_twin(row) result(twin)
      type(namelist_variable), intent(in) :: row
      type(namelist_variable) :: twin
      twin = row
      twin%name = twin_name(row%name)
      twin%unit = twin_unit
      twin%lowest = row%lowest/two_pi
      twin%highest = row%highest/two_pi
      twin%smallest_nonzero = row%smallest_nonzero/two_pi
      twin%meaning = trim(row%name)//' in Hz, f = omega/(2 pi) (give one of the two)'
   end function hertz_twin

   !> `name` is the name of a twin (ends with `twin_suffix`).
   pure logical function is_twin(name)
      character(len=*), intent(in) :: name
      integer :: n
      n = len_trim(name)
      is_twin = n > len(twin_suffix)
      if (is_twin) is_twin = name(n - len(twin_suffix) + 1:n) == twin_suffix
   end function is_twin

   !> The name of the frequency a twin stands for ('base_frequency' for 'base_frequency_hz').
   pure function frequency_name(name) result(frequency)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: frequency
      frequency = name(1:len_trim(name) - len(twin_suffix))
   end function frequency_name

   !> The name of the twin of a frequency ('base_frequency_hz' for 'base_frequency').
   pure function twin_name(name) result(twin)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: twin
      twin = trim(name)//twin_suffix
   end function twin_name

   !> The twin (Hz) and the frequency (rad/s) agree: 2 pi twin equals the frequency to two
   !! roundings (one in each conversion), or both are unset.
   elemental logical function agrees(twin, frequency)
      real(dp), intent(in) :: twin, frequency
      if (is_unset(frequency) .or. is_unset(twin)) then
         agrees = is_unset(frequency) .and. is_unset(twin)
      else
         agrees = abs(two_pi*twin - frequency) <= 2*epsilon(1.0_dp)*abs(frequency)
      end if
   end function agrees

   !> A pair accessor for 'group.name' element `index`: `set` with `value`, or a get.
   function pair_for(group, name, index, set, value) result(accessor)
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: index
      logical, intent(in) :: set
      real(dp), intent(in) :: value
      type(pair_accessor) :: accessor
      accessor%named = schema_accessor(group=group, name=name, index=index, set=set, value=value)
      if (.not. set) return
      if (is_twin(name)) then
         accessor%partner = schema_accessor(group=group, name=frequency_name(name), index=index, set=.true., &
                                            value=converted(value, two_pi))
      else
         accessor%partner = schema_accessor(group=group, name=twin_name(name), index=index, set=.true., &
                                            value=converted(value, 1/two_pi))
      end if
   contains
      !> value times factor; unset stays unset.
      pure real(dp) function converted(value, factor)
         real(dp), intent(in) :: value, factor
         converted = unset
         if (.not. is_unset(value)) converted = value*factor
      end function converted
   end function pair_for

   subroutine visit_pair(self, row, real_value, real_values, integer_value, text_value, text_values, logical_value)
      class(pair_accessor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout), optional :: real_value, real_values(:)
      integer, intent(inout), optional :: integer_value
      character(len=*), intent(inout), optional :: text_value, text_values(:)
      logical, intent(inout), optional :: logical_value
      call self%named%visit(row, real_value, real_values, integer_value, text_value, text_values, logical_value)
      if (.not. self%named%set) return
      ! (a twin and its frequency are real scalars, or elements of an array of settings visited
      ! one by one: only such a row can be the partner)
      if (row%kind == kind_real .and. present(real_value) .and. &
          (row%unit == angular_unit .or. row%unit == twin_unit)) &
         call self%partner%visit(row, real_value=real_value)
   end subroutine visit_pair

   subroutine visit_sync(self, row, real_value, real_values, integer_value, text_value, text_values, logical_value)
      class(twin_sync), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout), optional :: real_value, real_values(:)
      integer, intent(inout), optional :: integer_value
      character(len=*), intent(inout), optional :: text_value, text_values(:)
      logical, intent(inout), optional :: logical_value
      integer :: k
      if (.not. allocated(self%names)) allocate (self%names(0), self%values(0))
      ! only real scalars have twins
      if (row%kind /= kind_real .or. .not. present(real_value) .or. present(real_values) .or. &
          present(integer_value) .or. present(text_value) .or. present(text_values) .or. present(logical_value)) return
      if (self%collecting) then
         if (row%unit /= angular_unit) return
         self%names = [character(len=49) :: self%names, key(row, trim(row%name))]
         self%values = [self%values, real_value]
      else if (row%unit == twin_unit .and. is_twin(row%name)) then
         do k = 1, size(self%names)
            if (self%names(k) /= key(row, frequency_name(row%name))) cycle
            if (.not. agrees(real_value, self%values(k))) then
               real_value = unset
               if (.not. is_unset(self%values(k))) real_value = self%values(k)/two_pi
            end if
         end do
      end if
   contains
      !> 'group.name', or 'group.name(i)' for element i of an array of settings (&forces).
      function key(row, name) result(text)
         type(namelist_variable), intent(in) :: row
         character(len=*), intent(in) :: name
         character(len=:), allocatable :: text
         character(len=12) :: number
         text = trim(row%group)//'.'//name
         if (row%element > 0) then
            write (number, '(i0)') row%element
            text = text//'('//trim(number)//')'
         end if
      end function key
   end subroutine visit_sync
end module vibrobeam_frequency_twins
