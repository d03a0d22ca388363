!> What is done with every input variable, each a visitor of the settings types'
!! declarations (`vibrobeam_schema_visitor`):
!!
!! - `schema_table`: collects the rows, the table the file scanner checks a file against;
!! - `schema_reader`: sets each variable the scanned file gives (`vibrobeam_namelist_scan`),
!!   converting the values the scanner accepted;
!! - `schema_checker`: checks each value against its hard range or choices (the first
!!   violation, in the words of the scanner's messages);
!! - `schema_lister`: the resolved values with their units, for `--check` and the HDF5
!!   attributes;
!! - `schema_accessor`: gets or sets one real by 'group.name' and element (sweeps).
!!
!! None knows a variable by name: adding a variable to a settings type's `visit` is all it
!! takes for every one of them to handle it.
module vibrobeam_schema_operations
   use vibrobeam_status, only: stat_failure
   use vibrobeam_kinds, only: dp
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_namelist_tokens, only: lowercase
   use vibrobeam_namelist_schema, only: namelist_variable, kind_real, kind_integer, kind_logical, kind_string, &
      choices_text, form_null, variable_index, real_range_problem, integer_range_problem
   use vibrobeam_namelist_scanned, only: scanned_file
   use vibrobeam_schema_visitor, only: schema_visitor, is_unset, unset_integer
   implicit none
   private
   public :: schema_table, schema_reader, schema_checker, schema_lister, schema_accessor, schema_entry
   public :: entry_length

   integer, parameter :: entry_length = 4096   !! longest string value an entry holds (a file name)

   !> Collects the rows of every variable visited, once each, in the order of the visits.
   !! `mismatch` names the first declaration whose row and variable differ in kind or
   !! rank (a real row with an integer variable, an array row with a scalar): a
   !! programming error the unit test of the table reports.
   type, extends(schema_visitor) :: schema_table
      type(namelist_variable), allocatable :: rows(:)
      character(len=:), allocatable :: mismatch
   contains
      procedure :: visit => add_row
   end type schema_table

   !> Sets each variable that `scanned` gives. stat = stat_failure and errmsg naming the assignment
   !! when the run-time library cannot convert a value the scanner accepted (a
   !! disagreement reported rather than trusted); the first failure stays.
   type, extends(schema_visitor) :: schema_reader
      type(scanned_file) :: scanned
      integer :: stat = 0
      character(len=512) :: errmsg = ''
   contains
      procedure :: visit => read_variable
   end type schema_reader

   !> Checks every value against its row (range, choices): stat = stat_failure and errmsg such as
   !! '&impact restitution = 1.5 is outside [0, 1]' at the first violation.
   type, extends(schema_visitor) :: schema_checker
      integer :: stat = 0
      character(len=512) :: errmsg = ''
   contains
      procedure :: visit => check_variable
   end type schema_checker

   !> One resolved input value with its unit, for printing and for HDF5 attributes.
   !! Exactly one of the value components is meaningful, as `kind` says.
   type :: schema_entry
      character(len=64) :: name = ''              !! 'group.variable' or 'group.variable(i)'
      character(len=8) :: kind = 'real'           !! 'real' | 'integer' | 'string' | 'logical'
      real(dp) :: real_value = 0
      integer :: integer_value = 0
      character(len=entry_length) :: string_value = ''
      logical :: logical_value = .false.
      character(len=16) :: unit = ''              !! SI unit, '' when dimensionless
   end type schema_entry

   !> Lists every value visited (an optional variable left unset is not listed).
   type, extends(schema_visitor) :: schema_lister
      type(schema_entry), allocatable :: entries(:)
   contains
      procedure :: visit => list_variable
      procedure :: add_real, add_integer, add_string, add_logical
   end type schema_lister

   !> Gets (set = .false.) or sets one real, 'group.name' element `index` (1 for a scalar):
   !! `found` tells whether the settings visited hold it; `not_real` that they hold a
   !! variable of that name of another kind.
   type, extends(schema_visitor) :: schema_accessor
      character(len=16) :: group = ''
      character(len=32) :: name = ''
      integer :: index = 1
      logical :: set = .false.
      real(dp) :: value = 0
      logical :: found = .false.
      logical :: not_real = .false.
   contains
      procedure :: visit => access_variable
   end type schema_accessor

contains

   subroutine add_row(self, row, real_value, real_values, integer_value, text_value, text_values, logical_value)
      class(schema_table), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout), optional :: real_value, real_values(:)
      integer, intent(inout), optional :: integer_value
      character(len=*), intent(inout), optional :: text_value, text_values(:)
      logical, intent(inout), optional :: logical_value
      type(namelist_variable) :: described
      logical :: agree
      if (.not. allocated(self%rows)) allocate (self%rows(0))
      if (.not. allocated(self%mismatch)) self%mismatch = ''
      ! the row must describe the variable handed over: its kind, and an array (extent > 0)
      ! either handed over whole or one element at a time
      select case (row%kind)
      case (kind_real)
         agree = present(real_value) .or. present(real_values)
      case (kind_integer)
         agree = present(integer_value)
      case (kind_logical)
         agree = present(logical_value)
      case default
         agree = present(text_value) .or. present(text_values)
      end select
      if (present(real_values) .or. present(text_values)) agree = agree .and. row%extent > 0
      if (row%element > 0) agree = agree .and. row%extent > 0
      if (.not. agree .and. len(self%mismatch) == 0) &
         self%mismatch = trim(row%group)//'.'//trim(row%name)//': its row and its variable differ in kind or rank'
      if (variable_index(self%rows, row%group, row%name) > 0) return   ! an element of one already listed
      described = row
      described%element = 0
      self%rows = [self%rows, described]
   end subroutine add_row

   subroutine read_variable(self, row, real_value, real_values, integer_value, text_value, text_values, logical_value)
      class(schema_reader), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout), optional :: real_value, real_values(:)
      integer, intent(inout), optional :: integer_value
      character(len=*), intent(inout), optional :: text_value, text_values(:)
      logical, intent(inout), optional :: logical_value
      integer :: v, k, j, r, element, ios
      character(len=256) :: iomsg
      if (self%stat /= 0 .or. .not. allocated(self%scanned%items)) return
      v = variable_index(self%scanned%schema, row%group, row%name)
      if (v == 0) return
      do k = 1, size(self%scanned%items)
         if (self%scanned%items(k)%variable /= v) cycle
         element = self%scanned%items(k)%first
         do j = 1, size(self%scanned%items(k)%values)
            associate (value => self%scanned%items(k)%values(j))
               do r = 1, value%repeat
                  if (value%form /= form_null) call take(value%text, element)
                  if (self%stat /= 0) return
                  element = element + 1
               end do
            end associate
         end do
      end do
   contains
      !> Element `element` of the variable (as the file numbers it) is `text`.
      subroutine take(text, element)
         character(len=*), intent(in) :: text
         integer, intent(in) :: element
         ios = 0
         iomsg = ''
         if (present(real_values)) then
            if (element <= size(real_values)) read (text, *, iostat=ios, iomsg=iomsg) real_values(element)
         else if (present(text_values)) then
            if (element <= size(text_values)) text_values(element) = keyword_case(text)
         else if (row%element > 0 .and. element /= row%element) then
            return   ! a scalar handed over for one element of an array of settings
         else if (present(real_value)) then
            read (text, *, iostat=ios, iomsg=iomsg) real_value
         else if (present(integer_value)) then
            read (text, *, iostat=ios, iomsg=iomsg) integer_value
         else if (present(logical_value)) then
            read (text, *, iostat=ios, iomsg=iomsg) logical_value
         else if (present(text_value)) then
            text_value = keyword_case(text)
         end if
         if (ios /= 0) then
            self%stat = stat_failure
            self%errmsg = self%scanned%label(k)//': the Fortran run-time library cannot read this value ('// &
                          trim(iomsg)//'); write it as a plain number, quoted string or .true./.false.'
         end if
      end subroutine take

      !> Keywords are read in lower case; free text as written.
      function keyword_case(text) result(out)
         character(len=*), intent(in) :: text
         character(len=:), allocatable :: out
         if (len_trim(row%choices) > 0) then
            out = lowercase(text)
         else
            out = text
         end if
      end function keyword_case
   end subroutine read_variable

   subroutine check_variable(self, row, real_value, real_values, integer_value, text_value, text_values, &
                             logical_value)
      class(schema_checker), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout), optional :: real_value, real_values(:)
      integer, intent(inout), optional :: integer_value
      character(len=*), intent(inout), optional :: text_value, text_values(:)
      logical, intent(inout), optional :: logical_value
      integer :: i
      character(len=:), allocatable :: problem
      if (self%stat /= 0 .or. row%element < 0) return
      if (row%element == 0 .and. row%extent > 0 .and. .not. (present(real_values) .or. present(text_values))) &
         return   ! only the description of an array of settings with no element
      if (present(real_value)) then
         if (.not. (row%optional .and. is_unset(real_value))) call check_real(label(), real_value)
      else if (present(real_values)) then
         do i = 1, size(real_values)
            call check_real(label(i), real_values(i))
         end do
      else if (present(integer_value)) then
         if (row%optional .and. integer_value == unset_integer) return
         problem = integer_range_problem(row, integer_value)
         if (len(problem) > 0) call fail(label()//' = '//integer_text(integer_value)//' '//problem)
      else if (present(text_value)) then
         call check_keyword(label(), text_value)
      else if (present(text_values)) then
         do i = 1, size(text_values)
            call check_keyword(label(i), text_values(i))
         end do
      else if (present(logical_value)) then
         return   ! either value is allowed
      end if
   contains
      !> '&group name', '&group name(i)' for an element.
      function label(i) result(text)
         integer, intent(in), optional :: i
         character(len=:), allocatable :: text
         text = '&'//trim(row%group)//' '//trim(row%name)
         if (present(i)) then
            text = text//'('//integer_text(i)//')'
         else if (row%element > 0) then
            text = text//'('//integer_text(row%element)//')'
         end if
      end function label

      subroutine fail(message)
         character(len=*), intent(in) :: message
         if (self%stat /= 0) return
         self%stat = stat_failure
         self%errmsg = message
      end subroutine fail

      !> Finite, inside [lowest, highest], and 0 or at least `smallest_nonzero` in magnitude.
      subroutine check_real(name, value)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: value
         problem = real_range_problem(row, value)
         if (len(problem) > 0) call fail(name//' = '//real_text(value)//' '//problem)
      end subroutine check_real

      !> One of the row's choices (free text is not checked here).
      subroutine check_keyword(name, value)
         character(len=*), intent(in) :: name, value
         if (len_trim(row%choices) == 0) return
         if (index('|'//trim(row%choices)//'|', '|'//trim(value)//'|') > 0 .and. len_trim(value) > 0) return
         call fail(name//' = '''//trim(value)//''' is not one of '//choices_text(row))
      end subroutine check_keyword
   end subroutine check_variable

   subroutine list_variable(self, row, real_value, real_values, integer_value, text_value, text_values, logical_value)
      class(schema_lister), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout), optional :: real_value, real_values(:)
      integer, intent(inout), optional :: integer_value
      character(len=*), intent(inout), optional :: text_value, text_values(:)
      logical, intent(inout), optional :: logical_value
      integer :: i
      character(len=:), allocatable :: name
      if (row%element == 0 .and. row%extent > 0 .and. .not. (present(real_values) .or. present(text_values))) &
         return   ! only the description of an array of settings with no element
      name = trim(row%group)//'.'//trim(row%name)
      if (row%element > 0) name = name//'('//integer_text(row%element)//')'
      if (present(real_value)) then
         if (.not. (row%optional .and. is_unset(real_value))) call self%add_real(name, real_value, row%unit)
      else if (present(real_values)) then
         do i = 1, size(real_values)
            call self%add_real(name//'('//integer_text(i)//')', real_values(i), row%unit)
         end do
      else if (present(integer_value)) then
         if (.not. (row%optional .and. integer_value == unset_integer)) call self%add_integer(name, integer_value)
      else if (present(text_value)) then
         call self%add_string(name, text_value)
      else if (present(text_values)) then
         do i = 1, size(text_values)
            call self%add_string(name//'('//integer_text(i)//')', text_values(i))
         end do
      else if (present(logical_value)) then
         call self%add_logical(name, logical_value)
      end if
   end subroutine list_variable

   subroutine add_real(self, name, value, unit)
      class(schema_lister), intent(inout) :: self
      character(len=*), intent(in) :: name, unit
      real(dp), intent(in) :: value
      type(schema_entry) :: item
      item%name = name
      item%kind = 'real'
      item%real_value = value
      item%unit = unit
      call append(self, item)
   end subroutine add_real

   subroutine add_integer(self, name, value)
      class(schema_lister), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer, intent(in) :: value
      type(schema_entry) :: item
      item%name = name
      item%kind = 'integer'
      item%integer_value = value
      call append(self, item)
   end subroutine add_integer

   subroutine add_string(self, name, value)
      class(schema_lister), intent(inout) :: self
      character(len=*), intent(in) :: name, value
      type(schema_entry) :: item
      item%name = name
      item%kind = 'string'
      item%string_value = value
      call append(self, item)
   end subroutine add_string

   subroutine add_logical(self, name, value)
      class(schema_lister), intent(inout) :: self
      character(len=*), intent(in) :: name
      logical, intent(in) :: value
      type(schema_entry) :: item
      item%name = name
      item%kind = 'logical'
      item%logical_value = value
      call append(self, item)
   end subroutine add_logical

   subroutine append(self, item)
      class(schema_lister), intent(inout) :: self
      type(schema_entry), intent(in) :: item
      if (.not. allocated(self%entries)) allocate (self%entries(0))
      self%entries = [self%entries, item]
   end subroutine append

   subroutine access_variable(self, row, real_value, real_values, integer_value, text_value, text_values, &
                              logical_value)
      class(schema_accessor), intent(inout) :: self
      type(namelist_variable), intent(in) :: row
      real(dp), intent(inout), optional :: real_value, real_values(:)
      integer, intent(inout), optional :: integer_value
      character(len=*), intent(inout), optional :: text_value, text_values(:)
      logical, intent(inout), optional :: logical_value
      if (self%found .or. row%group /= self%group .or. row%name /= self%name) return
      if (present(real_value)) then
         if (row%element /= merge(self%index, 0, row%extent > 0)) return
         call take(real_value)
      else if (present(real_values)) then
         if (self%index < 1 .or. self%index > size(real_values)) return
         call take(real_values(self%index))
      else
         self%not_real = present(integer_value) .or. present(text_value) .or. present(text_values) .or. &
                         present(logical_value)
      end if
   contains
      subroutine take(field)
         real(dp), intent(inout) :: field
         self%found = .true.
         if (self%set) then
            field = self%value
         else
            self%value = field
         end if
      end subroutine take
   end subroutine access_variable
end module vibrobeam_schema_operations
