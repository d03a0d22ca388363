!> What a value of a namelist variable may be: the schema entry of a variable (kind,
!! extent, longest string, hard range, keywords, unit), the checks of a value as written
!! before any conversion (`value_problem`), the checks of a converted number against the
!! hard range (`real_range_problem`, `integer_range_problem`), and the texts of what is
!! allowed that every message about a variable ends with.
!!
!! Reals are checked on their text: the decimal exponent is computed from the digits
!! (`real_exponent`), so that 1e400 or 1e-400 is refused without being converted (the
!! conversion of 1e400 traps under -ffpe-trap=overflow inside the run-time library).
module vibrobeam_namelist_values
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_namelist_tokens, only: abbreviated, lowercase
   implicit none
   private
   public :: namelist_variable, scanned_value
   public :: kind_real, kind_integer, kind_logical, kind_string
   public :: form_word, form_string, form_null
   public :: value_problem, real_range_problem, integer_range_problem
   public :: allowed_text, range_text, choices_text, element_label, shown_value
   public :: real_exponent, integer_value, is_name, first_match, variable_index, group_names

   integer, parameter :: kind_real = 1, kind_integer = 2, kind_logical = 3, kind_string = 4
   integer, parameter :: form_word = 1, form_string = 2, form_null = 3

   !> Reals whose decimal exponent lies outside [-exponent_limit, exponent_limit] are
   !! refused before conversion: 1e400 overflows inside the run-time library's conversion
   !! (a trap under -ffpe-trap=overflow), 1e-320 is subnormal. No variable's range comes
   !! near either.
   integer, parameter :: exponent_limit = 300

   !> One variable of the schema: what `scan_namelist_text` accepts for it.
   type :: namelist_variable
      character(len=16) :: group = ''            !! group name, lower case, without '&'
      character(len=32) :: name = ''             !! variable name, lower case
      integer :: kind = kind_real                !! kind_real | kind_integer | kind_logical | kind_string
      integer :: extent = 0                      !! 0: scalar; n > 0: array with elements 1..n
      integer :: max_length = 0                  !! strings: most characters
      real(dp) :: lowest = 0, highest = 0        !! reals: hard range
      real(dp) :: smallest_nonzero = 1e-30_dp    !! reals whose range holds 0: least non-zero magnitude
      integer :: lowest_integer = 0, highest_integer = 0   !! integers: hard range
      character(len=64) :: choices = ''          !! strings: allowed values 'a|b|c'; '' for free text
      character(len=16) :: unit = ''             !! SI unit ('' dimensionless), for messages and docs
   end type namelist_variable

   !> One value of an assignment, as written.
   type :: scanned_value
      integer :: form = form_null                !! form_word (number, logical) | form_string | form_null
      character(len=:), allocatable :: text      !! word as written; string content (quotes undoubled)
      integer :: repeat = 1                      !! r of 'r*value'
   end type scanned_value

contains

   !> '' when `value` is acceptable for `variable` (before conversion), otherwise the reason
   !! and what is allowed, to follow 'group name = value'.
   function value_problem(variable, value) result(problem)
      type(namelist_variable), intent(in) :: variable
      type(scanned_value), intent(in) :: value
      character(len=:), allocatable :: problem
      character(len=:), allocatable :: word
      integer :: exponent, integer_result
      logical :: ok, zero
      problem = ''
      word = lowercase(value%text)
      select case (variable%kind)
      case (kind_string)
         if (value%form /= form_string) then
            problem = 'is not a quoted string: write '//trim(variable%name)//' = '''//abbreviated(value%text, 40)//''''
         else if (len(value%text) > variable%max_length) then
            problem = 'is longer than '//integer_text(variable%max_length)//' characters, the most '// &
                      trim(variable%name)//' holds (nothing is cut: shorten it)'
         end if
      case (kind_logical)
         if (value%form /= form_word .or. .not. any(word == [character(len=7) :: '.true.', '.false.', '.t.', &
                                                            '.f.', 't', 'f'])) &
            problem = 'is not a logical: write .true. or .false.'
      case (kind_integer)
         if (value%form /= form_word) then
            problem = 'is not a whole number: '//allowed_text(variable)
            return
         end if
         call integer_value(word, integer_result, ok)
         if (.not. ok) then
            if (verify(word, '+-0123456789') == 0 .and. scan(word, '0123456789') > 0) then
               problem = 'is outside '//range_text(variable)   ! beyond the integer range
            else
               problem = 'is not a whole number: '//allowed_text(variable)
            end if
         end if
      case default
         if (value%form /= form_word) then
            problem = 'is not a number: '//allowed_text(variable)
            return
         end if
         if (is_non_finite_word(word)) then
            problem = 'is not a finite number: '//allowed_text(variable)
            return
         end if
         call real_exponent(word, exponent, zero, ok)
         if (.not. ok) then
            problem = 'is not a number (write e.g. 0.5, 2e-3, -1.5e+11): '//allowed_text(variable)
         else if (.not. zero .and. exponent > exponent_limit) then
            problem = 'is outside '//range_text(variable)
         else if (.not. zero .and. exponent < -exponent_limit) then
            if (variable%lowest <= 0 .and. variable%highest >= 0) then
               problem = 'is too small in magnitude: write 0 or a magnitude of at least '// &
                         real_text(variable%smallest_nonzero)//'; '//allowed_text(variable)
            else
               problem = 'is outside '//range_text(variable)
            end if
         end if
      end select
   end function value_problem

   !> '' when the converted real `value` lies in the hard range of `variable` (finite,
   !! inside [lowest, highest], and 0 or at least `smallest_nonzero` in magnitude),
   !! otherwise the reason and what is allowed, to follow 'group name = value'.
   function real_range_problem(variable, value) result(problem)
      type(namelist_variable), intent(in) :: variable
      real(dp), intent(in) :: value
      character(len=:), allocatable :: problem
      problem = ''
      if (.not. ieee_is_finite(value)) then
         problem = 'is not a finite number: '//allowed_text(variable)
      else if (value < variable%lowest .or. value > variable%highest) then
         problem = 'is outside '//range_text(variable)
      else if (abs(value) > 0 .and. abs(value) < variable%smallest_nonzero) then
         problem = 'is too small in magnitude: write 0 or a magnitude of at least '// &
                   real_text(variable%smallest_nonzero)//'; '//allowed_text(variable)
      end if
   end function real_range_problem

   !> '' when the integer `value` lies in the hard range of `variable`, otherwise
   !! 'is outside [lowest, highest]'.
   function integer_range_problem(variable, value) result(problem)
      type(namelist_variable), intent(in) :: variable
      integer, intent(in) :: value
      character(len=:), allocatable :: problem
      problem = ''
      if (value < variable%lowest_integer .or. value > variable%highest_integer) &
         problem = 'is outside '//range_text(variable)
   end function integer_range_problem

   !> 'allowed ...' for a variable: its range, its choices or its form.
   function allowed_text(variable) result(text)
      type(namelist_variable), intent(in) :: variable
      character(len=:), allocatable :: text
      select case (variable%kind)
      case (kind_real, kind_integer)
         text = 'allowed '//range_text(variable)
      case (kind_logical)
         text = 'allowed .true. or .false.'
      case default
         if (len_trim(variable%choices) > 0) then
            text = 'allowed '//choices_text(variable)
         else
            text = 'a quoted string of at most '//integer_text(variable%max_length)//' characters'
         end if
      end select
   end function allowed_text

   !> The hard range of a number variable as '[lowest, highest] unit'.
   function range_text(variable) result(text)
      type(namelist_variable), intent(in) :: variable
      character(len=:), allocatable :: text
      if (variable%kind == kind_integer) then
         text = '['//integer_text(variable%lowest_integer)//', '//integer_text(variable%highest_integer)//']'
      else
         text = '['//real_text(variable%lowest)//', '//real_text(variable%highest)//']'
         if (len_trim(variable%unit) > 0) text = text//' '//trim(variable%unit)
      end if
   end function range_text

   !> The allowed values of a keyword variable as 'a' | 'b'.
   function choices_text(variable) result(list)
      type(namelist_variable), intent(in) :: variable
      character(len=:), allocatable :: list
      integer :: i
      list = ''''
      do i = 1, len_trim(variable%choices)
         if (variable%choices(i:i) == '|') then
            list = list//''' | '''
         else
            list = list//variable%choices(i:i)
         end if
      end do
      list = list//''''
   end function choices_text

   !> 'name(i)' of an array element, or the label as written for scalars.
   function element_label(variable, element, label) result(text)
      type(namelist_variable), intent(in) :: variable
      integer, intent(in) :: element
      character(len=*), intent(in) :: label
      character(len=:), allocatable :: text
      if (variable%extent > 0) then
         text = trim(variable%name)//'('//integer_text(element)//')'
      else
         text = abbreviated(label, 60)
      end if
   end function element_label

   !> A value as it would be written in the file (strings quoted), shortened for messages.
   function shown_value(value) result(text)
      type(scanned_value), intent(in) :: value
      character(len=:), allocatable :: text
      if (value%form == form_string) then
         text = ''''//abbreviated(value%text, 40)//''''
      else
         text = abbreviated(value%text, 40)
      end if
   end function shown_value

   !> True for the words the run-time library reads as NaN or an infinity.
   pure logical function is_non_finite_word(word)
      character(len=*), intent(in) :: word   !! lower case
      character(len=:), allocatable :: body
      body = word
      if (len(body) > 0) then
         if (body(1:1) == '+' .or. body(1:1) == '-') body = body(2:)
      end if
      is_non_finite_word = body == 'inf' .or. body == 'infinity' .or. body(1:min(3, len(body))) == 'nan'
   end function is_non_finite_word

   !> Decimal exponent of a real written as [sign] digits [. digits] [e|d [sign] digits]:
   !! the value lies in [10^exponent, 10^(exponent+1)). ok = .false. when `word` is not of
   !! that form; zero = .true. when every digit is 0. Computed on the text, without
   !! converting: the conversion of an out-of-range value is what must be avoided.
   pure subroutine real_exponent(word, exponent, zero, ok)
      character(len=*), intent(in) :: word
      integer, intent(out) :: exponent
      logical, intent(out) :: zero, ok
      integer :: i, n, point, first_nonzero, digits_before, exponent_start, written
      logical :: negative_exponent
      n = len(word)
      exponent = 0
      zero = .true.
      ok = .false.
      i = 1
      if (n == 0) return
      if (word(1:1) == '+' .or. word(1:1) == '-') i = 2
      point = 0
      first_nonzero = 0
      digits_before = 0
      written = 0
      ! mantissa: digits with at most one point, at least one digit
      do while (i <= n)
         if (word(i:i) == '.') then
            if (point /= 0) return
            point = i
         else if (index('0123456789', word(i:i)) > 0) then
            written = written + 1
            if (point == 0) digits_before = digits_before + 1
            if (word(i:i) /= '0' .and. first_nonzero == 0) first_nonzero = i
         else
            exit
         end if
         i = i + 1
      end do
      if (written == 0) return
      exponent_start = i
      if (i <= n) then
         if (index('eEdD', word(i:i)) == 0) return
         i = i + 1
         negative_exponent = .false.
         if (i <= n) then
            if (word(i:i) == '+' .or. word(i:i) == '-') then
               negative_exponent = word(i:i) == '-'
               i = i + 1
            end if
         end if
         if (i > n) return
         if (verify(word(i:n), '0123456789') /= 0) return
         ! more than 6 digits: far beyond any limit (leading zeros aside)
         written = verify(word(i:n), '0')
         if (written == 0) then
            exponent = 0
         else if (n - (i + written - 1) + 1 > 6) then
            exponent = 10**7
         else
            read (word(i + written - 1:n), *) exponent
         end if
         if (negative_exponent) exponent = -exponent
      end if
      ok = .true.
      if (first_nonzero == 0) then
         exponent = 0
         return
      end if
      zero = .false.
      ! position of the first non-zero digit relative to the point
      if (point == 0) point = exponent_start
      if (first_nonzero < point) then
         exponent = exponent + (point - first_nonzero - 1)
      else
         exponent = exponent - (first_nonzero - point)
      end if
   end subroutine real_exponent

   !> A whole number [sign] digits as a default integer; ok = .false. when `word` is not
   !! of that form or beyond the default integer range.
   pure subroutine integer_value(word, value, ok)
      character(len=*), intent(in) :: word
      integer, intent(out) :: value
      logical, intent(out) :: ok
      integer :: start, first
      integer(int64) :: wide
      value = 0
      ok = .false.
      start = 1
      if (len(word) == 0) return
      if (word(1:1) == '+' .or. word(1:1) == '-') start = 2
      if (start > len(word)) return
      if (verify(word(start:), '0123456789') /= 0) return
      first = verify(word(start:), '0')
      if (first == 0) then
         ok = .true.
         return
      end if
      first = start + first - 1
      if (len(word) - first + 1 > 10) return
      read (word(first:), *) wide
      if (word(1:1) == '-') wide = -wide
      if (wide > huge(value) .or. wide < -huge(value) - 1_int64) return
      value = int(wide)
      ok = .true.
   end subroutine integer_value

   !> True for a Fortran name: a letter followed by letters, digits and underscores.
   pure logical function is_name(word)
      character(len=*), intent(in) :: word
      is_name = .false.
      if (len(word) == 0) return
      if (scan(word(1:1), 'abcdefghijklmnopqrstuvwxyz') == 0) return
      is_name = verify(word, 'abcdefghijklmnopqrstuvwxyz0123456789_') == 0
   end function is_name

   !> Index of the first element of `list` equal to `word` (blank-padded comparison), 0 if none.
   pure integer function first_match(list, word)
      character(len=*), intent(in) :: list(:), word
      integer :: k
      first_match = 0
      do k = 1, size(list)
         if (list(k) == word) then
            first_match = k
            return
         end if
      end do
   end function first_match

   !> Index of group.name in the schema, 0 if absent.
   pure integer function variable_index(schema, group, name)
      type(namelist_variable), intent(in) :: schema(:)
      character(len=*), intent(in) :: group, name
      integer :: k
      variable_index = 0
      do k = 1, size(schema)
         if (schema(k)%group == group .and. schema(k)%name == name) then
            variable_index = k
            return
         end if
      end do
   end function variable_index

   !> The group names of a schema, in order of first appearance.
   pure function group_names(schema) result(groups)
      type(namelist_variable), intent(in) :: schema(:)
      character(len=16), allocatable :: groups(:)
      character(len=16) :: found(size(schema))
      integer :: k, count
      count = 0
      do k = 1, size(schema)
         if (any(found(1:count) == schema(k)%group)) cycle
         count = count + 1
         found(count) = schema(k)%group
      end do
      allocate (groups(count))
      groups = found(1:count)
   end function group_names
end module vibrobeam_namelist_values
