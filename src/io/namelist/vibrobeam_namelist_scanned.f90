!> What the namelist scanner (`vibrobeam_namelist_scan`) found in a file: every
!! assignment with its values as written, which elements were given, which groups are
!! present, and the views the input module needs of them (the canonical namelist record
!! of an assignment for internal-file namelist input, the assignment as written for
!! messages).
module vibrobeam_namelist_scanned
   use vibrobeam_text, only: integer_text
   use vibrobeam_namelist_tokens, only: abbreviated
   use vibrobeam_namelist_schema, only: namelist_variable, scanned_value, form_word, form_string, form_null, &
      shown_value, variable_index
   implicit none
   private
   public :: scanned_file, scanned_item

   !> One assignment `name(first) = values` of the file.
   type :: scanned_item
      integer :: variable = 0                    !! index in the schema
      integer :: first = 1                       !! first array element assigned (1 for scalars)
      integer :: count = 0                       !! values with repeats expanded (nulls included)
      integer :: line = 0                        !! line of the name
      type(scanned_value), allocatable :: values(:)
   end type scanned_item

   !> What `scan_namelist_text` found: the schema, every assignment, which elements were given.
   type :: scanned_file
      type(namelist_variable), allocatable :: schema(:)
      type(scanned_item), allocatable :: items(:)
      logical, allocatable :: given(:,:)         !! (element, variable): assigned a non-null value
      logical, allocatable :: group_present(:)   !! (variable): its group is in the file
   contains
      procedure :: is_given                      !! was group.name(index) given?
      procedure :: group_given                   !! does the file hold &group?
      procedure :: in_group                      !! does assignment k belong to &group?
      procedure :: record                        !! canonical namelist record of assignment k
      procedure :: label                         !! assignment k as written, for messages
      procedure :: value_text                    !! the values of group.name as written
   end type scanned_file

contains

   !> Was element `index` (1 for scalars) of group.name given a value?
   pure logical function is_given(self, group, name, index)
      class(scanned_file), intent(in) :: self
      character(len=*), intent(in) :: group, name
      integer, intent(in), optional :: index
      integer :: v, element
      is_given = .false.
      if (.not. allocated(self%schema)) return
      v = variable_index(self%schema, group, name)
      if (v == 0) return
      element = 1
      if (present(index)) element = index
      if (element < 1 .or. element > size(self%given, 1)) return
      is_given = self%given(element, v)
   end function is_given

   !> Does the file hold &group?
   pure logical function group_given(self, group)
      class(scanned_file), intent(in) :: self
      character(len=*), intent(in) :: group
      group_given = .false.
      if (.not. allocated(self%schema)) return
      group_given = any(self%group_present .and. self%schema%group == group)
   end function group_given

   !> Does assignment k belong to &group?
   pure logical function in_group(self, k, group)
      class(scanned_file), intent(in) :: self
      integer, intent(in) :: k
      character(len=*), intent(in) :: group
      in_group = self%schema(self%items(k)%variable)%group == group
   end function in_group

   !> Assignment k as one namelist record '&group name(i)=v1,v2 /' for internal-file
   !! namelist input: the values as the scanner read them, strings re-quoted.
   pure function record(self, k) result(text)
      class(scanned_file), intent(in) :: self
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      integer :: j
      associate (item => self%items(k), variable => self%schema(self%items(k)%variable))
         text = '&'//trim(variable%group)//' '//assigned_name(self, k)//'='
         do j = 1, size(item%values)
            if (j > 1) text = text//','
            if (item%values(j)%repeat > 1 .or. item%values(j)%form == form_null) &
               text = text//integer_text(item%values(j)%repeat)//'*'
            select case (item%values(j)%form)
            case (form_string)
               text = text//''''//doubled_quotes(item%values(j)%text)//''''
            case (form_word)
               text = text//item%values(j)%text
            end select
         end do
         text = text//' /'
      end associate
   contains
      pure function doubled_quotes(content) result(out)
         character(len=*), intent(in) :: content
         character(len=:), allocatable :: out
         integer :: i
         out = ''
         do i = 1, len(content)
            out = out//content(i:i)
            if (content(i:i) == '''') out = out//''''
         end do
      end function doubled_quotes
   end function record

   !> Assignment k as written, '&group name(i) = v1, v2' (shortened), for messages.
   function label(self, k) result(text)
      class(scanned_file), intent(in) :: self
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      text = '&'//trim(self%schema(self%items(k)%variable)%group)//' '//assigned_name(self, k)//' = '// &
             self%value_text(k)
   end function label

   !> 'name' or 'name(i)' of assignment k.
   pure function assigned_name(self, k) result(name)
      class(scanned_file), intent(in) :: self
      integer, intent(in) :: k
      character(len=:), allocatable :: name
      name = trim(self%schema(self%items(k)%variable)%name)
      if (self%schema(self%items(k)%variable)%extent > 0) name = name//'('//integer_text(self%items(k)%first)//')'
   end function assigned_name

   !> The values of assignment k as written (shortened), for messages.
   function value_text(self, k) result(text)
      class(scanned_file), intent(in) :: self
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      integer :: j
      text = ''
      do j = 1, size(self%items(k)%values)
         if (j > 1) text = text//', '
         if (self%items(k)%values(j)%repeat > 1 .or. self%items(k)%values(j)%form == form_null) &
            text = text//integer_text(self%items(k)%values(j)%repeat)//'*'
         if (self%items(k)%values(j)%form /= form_null) text = text//shown_value(self%items(k)%values(j))
      end do
      text = abbreviated(text, 80)
   end function value_text
end module vibrobeam_namelist_scanned
