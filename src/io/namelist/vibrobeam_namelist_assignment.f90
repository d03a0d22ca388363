!> One assignment of a namelist group, `name = values` or `name(i) = values`, parsed from
!! the tokens (`token_cursor`) and checked against the schema: the variable exists in its
!! group, the subscript is a whole number inside the array, the values are of the
!! variable's kind and inside its hard range, repeats `r*value` fit, no element is given
!! twice (module documentation of `vibrobeam_namelist_scan` for the syntax). What it
!! accepts is kept in the `scanned_file`.
module vibrobeam_namelist_assignment
   use vibrobeam_text, only: integer_text
   use vibrobeam_namelist_tokens, only: abbreviated, lowercase, t_word, t_string, t_equals, t_open, t_close, &
      t_comma, t_bad
   use vibrobeam_namelist_schema, only: namelist_variable, scanned_value, form_word, form_string, form_null, &
      value_problem, allowed_text, element_label, shown_value, integer_value, is_name, variable_index
   use vibrobeam_namelist_scanned, only: scanned_file, scanned_item
   use vibrobeam_namelist_cursor, only: token_cursor, fail_at, fail_variable
   implicit none
   private
   public :: parse_assignment

contains

   !> name [(i)] = values, starting at the cursor's token (the name) in &group; leaves
   !! the cursor after the values and appends the assignment to scanned%items(1:count).
   !! stat = stat_failure with the message on the first problem.
   subroutine parse_assignment(cursor, group, scanned, count, stat, errmsg)
      type(token_cursor), intent(inout) :: cursor
      character(len=*), intent(in) :: group
      type(scanned_file), intent(inout) :: scanned
      integer, intent(inout) :: count                !! assignments kept in scanned%items
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: name, label
      type(scanned_item) :: item
      integer :: v, line, index_value
      logical :: ok
      stat = 0
      errmsg = ''
      line = cursor%line_at(0)
      name = lowercase(cursor%word_at(0))
      v = 0
      if (is_name(name)) v = variable_index(scanned%schema, group, name)
      if (v == 0) then
         if (is_name(name) .and. (cursor%type_at(1) == t_equals .or. cursor%type_at(1) == t_open)) then
            call fail_at(line, '&'//group//': unknown variable '''//abbreviated(name, 40)//''' (the variables of &'// &
                         group//' are: '//variables_text(scanned%schema, group)//')', stat, errmsg)
         else
            call fail_at(line, '&'//group//': '''//abbreviated(cursor%rest_of_line(0), 40)// &
                         ''' where a variable name is expected (name = value)', stat, errmsg)
         end if
         return
      end if
      item%variable = v
      item%line = line
      item%first = 1
      label = trim(name)
      cursor%p = cursor%p + 1
      if (cursor%type_at(0) == t_open) then
         if (cursor%type_at(1) /= t_word .or. cursor%type_at(2) /= t_close) then
            call fail_variable(line, '&'//group//' '//label//': malformed subscript '''// &
                               abbreviated(cursor%rest_of_line(0), 40)//'''; write '//label//'(i) = value', stat, errmsg)
            return
         end if
         if (scanned%schema(v)%extent == 0) then
            call fail_variable(line, '&'//group//' '//label//' is not an array: write '//label//' = value', stat, errmsg)
            return
         end if
         label = label//'('//cursor%word_at(1)//')'
         call integer_value(cursor%word_at(1), index_value, ok)
         if (index(cursor%word_at(1), ':') > 0) then
            call fail_variable(line, '&'//group//' '//abbreviated(label, 60)//': array sections are not accepted; '// &
                               'write '//trim(name)//'(i) = value, value, ... to set elements i, i+1, ...', stat, errmsg)
            return
         end if
         if (.not. ok .or. index_value < 1 .or. index_value > scanned%schema(v)%extent) then
            call fail_variable(line, '&'//group//' '//abbreviated(label, 60)//': index '// &
                               abbreviated(cursor%word_at(1), 24)//' is outside [1, '// &
                               integer_text(scanned%schema(v)%extent)//']', stat, errmsg)
            return
         end if
         item%first = index_value
         cursor%p = cursor%p + 3
      end if
      if (cursor%type_at(0) /= t_equals) then
         call fail_variable(line, '&'//group//' '//abbreviated(label, 60)//': ''='' expected after the name '// &
                            '(name = value)', stat, errmsg)
         return
      end if
      cursor%p = cursor%p + 1
      call parse_values(cursor, group, label, scanned%schema(v), item, stat, errmsg)
      if (stat /= 0) return
      call record_assignment(scanned, count, group, label, item, stat, errmsg)
   end subroutine parse_assignment

   !> The values after '=' up to the next name, '/' or the end of the group, into
   !! item%values and item%count.
   subroutine parse_values(cursor, group, label, variable, item, stat, errmsg)
      type(token_cursor), intent(inout) :: cursor
      character(len=*), intent(in) :: group, label
      type(namelist_variable), intent(in) :: variable
      type(scanned_item), intent(inout) :: item
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(scanned_value), allocatable :: values(:)
      type(scanned_value) :: value
      logical :: after_value
      stat = 0
      errmsg = ''
      allocate (values(0))
      after_value = .false.
      do
         select case (cursor%type_at(0))
         case (t_comma)
            if (.not. after_value) then
               value%form = form_null
               value%text = ''
               value%repeat = 1
               call append_value(values, value)
            end if
            after_value = .false.
            cursor%p = cursor%p + 1
         case (t_word)
            ! a word followed by '=' or '(' is the next variable's name
            if (cursor%type_at(1) == t_equals .or. cursor%type_at(1) == t_open) exit
            call word_value(cursor, group, label, variable, value, stat, errmsg)
            if (stat /= 0) return
            call append_value(values, value)
            after_value = .true.
            cursor%p = cursor%p + 1
         case (t_string)
            value%form = form_string
            value%text = cursor%string_at(0)
            value%repeat = 1
            call append_value(values, value)
            after_value = .true.
            cursor%p = cursor%p + 1
         case (t_bad)
            call fail_at(cursor%line_at(0), '&'//group//' '//abbreviated(label, 60)//': '// &
                         cursor%tokens(cursor%p)%problem, stat, errmsg)
            return
         case (t_equals, t_open, t_close)
            call fail_variable(cursor%line_at(0), '&'//group//' '//abbreviated(label, 60)//': unexpected '''// &
                               cursor%word_at(0)//''' among the values', stat, errmsg)
            return
         case default   ! '/', end of file, next group, bad token: the caller reports them
            exit
         end select
      end do
      item%values = values
      item%count = sum(values%repeat)
   end subroutine parse_values

   !> The value of the word token at the cursor: a value, or `r*value` (r copies) and
   !! `r*` (r nulls), where 'r*' glued to a string token is r copies of the string (the
   !! cursor then stands on the string).
   subroutine word_value(cursor, group, label, variable, value, stat, errmsg)
      type(token_cursor), intent(inout) :: cursor
      character(len=*), intent(in) :: group, label
      type(namelist_variable), intent(in) :: variable
      type(scanned_value), intent(out) :: value
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: star, repeat
      logical :: ok
      stat = 0
      errmsg = ''
      value%form = form_word
      value%text = cursor%word_at(0)
      value%repeat = 1
      star = index(value%text, '*')
      if (star == 0) return
      call integer_value(value%text(1:star - 1), repeat, ok)
      if (.not. ok .or. verify(value%text(1:star - 1), '0123456789') /= 0 .or. repeat < 1) then
         call fail_variable(cursor%line_at(0), '&'//group//' '//abbreviated(label, 60)//' = '// &
                            abbreviated(value%text, 40)//': bad repeat count '''// &
                            abbreviated(value%text(1:star - 1), 24)//''' (r*value needs a whole number r >= 1)', &
                            stat, errmsg)
         return
      end if
      if (repeat > max(1, variable%extent)) then
         call fail_variable(cursor%line_at(0), '&'//group//' '//abbreviated(label, 60)//' = '// &
                            abbreviated(cursor%word_at(0), 40)//': repeat count '//integer_text(repeat)// &
                            ' is more than the '//integer_text(max(1, variable%extent))// &
                            ' element(s) of '//trim(variable%name), stat, errmsg)
         return
      end if
      value%repeat = repeat
      value%text = value%text(star + 1:)
      if (len(value%text) == 0) then
         value%form = form_null
         ! 'r*' glued to a string: r copies of the string
         if (cursor%type_at(1) == t_string .and. cursor%tokens(cursor%p + 1)%first == cursor%tokens(cursor%p)%last + 1) then
            cursor%p = cursor%p + 1
            value%form = form_string
            value%text = cursor%string_at(0)
         end if
      else if (index(value%text, '*') > 0) then
         call fail_variable(cursor%line_at(0), '&'//group//' '//abbreviated(label, 60)//' = '// &
                            abbreviated(cursor%word_at(0), 40)//': malformed repeat (r*value)', stat, errmsg)
      end if
   end subroutine word_value

   !> Check the values of an assignment against the schema and keep it (as
   !! scanned%items(count + 1), the array growing by doubling).
   subroutine record_assignment(scanned, count, group, label, item, stat, errmsg)
      type(scanned_file), intent(inout) :: scanned
      integer, intent(inout) :: count
      character(len=*), intent(in) :: group, label
      type(scanned_item), intent(in) :: item
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(scanned_item), allocatable :: bigger(:)
      integer :: k, element, r, v, last
      character(len=:), allocatable :: problem
      stat = 0
      errmsg = ''
      v = item%variable
      associate (variable => scanned%schema(v))
         if (item%count == 0 .or. all(item%values%form == form_null)) then
            call fail_variable(item%line, '&'//group//' '//abbreviated(label, 60)//' has no value: '// &
                               allowed_text(variable), stat, errmsg)
            return
         end if
         if (variable%extent == 0 .and. item%count > 1) then
            call fail_variable(item%line, '&'//group//' '//abbreviated(label, 60)//' takes one value; '// &
                               integer_text(item%count)//' are given', stat, errmsg)
            return
         end if
         last = item%first + item%count - 1
         if (variable%extent > 0 .and. (item%count > variable%extent .or. last > variable%extent)) then
            call fail_variable(item%line, '&'//group//' '//abbreviated(label, 60)//': '//integer_text(item%count)// &
                               ' values from element '//integer_text(item%first)//' go beyond element '// &
                               integer_text(variable%extent)//', the last of '//trim(variable%name), stat, errmsg)
            return
         end if
         element = item%first
         do k = 1, size(item%values)
            if (item%values(k)%form /= form_null) then
               problem = value_problem(variable, item%values(k))
               if (len(problem) > 0) then
                  call fail_variable(item%line, '&'//group//' '//element_label(variable, element, label)//' = '// &
                                     shown_value(item%values(k))//' '//problem, stat, errmsg)
                  return
               end if
            end if
            do r = 1, item%values(k)%repeat
               if (item%values(k)%form /= form_null) then
                  if (scanned%given(element, v)) then
                     call fail_variable(item%line, '&'//group//' '//element_label(variable, element, label)// &
                                        ' is given twice: give each variable once', stat, errmsg)
                     return
                  end if
                  scanned%given(element, v) = .true.
               end if
               element = element + 1
            end do
         end do
      end associate
      count = count + 1
      if (count > size(scanned%items)) then
         allocate (bigger(2*size(scanned%items)))
         bigger(1:count - 1) = scanned%items(1:count - 1)
         call move_alloc(bigger, scanned%items)
      end if
      scanned%items(count) = item
   end subroutine record_assignment

   !> 'a, b, c': the variables of &group, for messages.
   function variables_text(schema, group) result(list)
      type(namelist_variable), intent(in) :: schema(:)
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: list
      integer :: k
      list = ''
      do k = 1, size(schema)
         if (schema(k)%group /= group) cycle
         if (len(list) > 0) list = list//', '
         list = list//trim(schema(k)%name)
      end do
   end function variables_text

   subroutine append_value(values, value)
      type(scanned_value), allocatable, intent(inout) :: values(:)
      type(scanned_value), intent(in) :: value
      type(scanned_value), allocatable :: longer(:)
      allocate (longer(size(values) + 1))
      longer(1:size(values)) = values
      longer(size(values) + 1) = value
      call move_alloc(longer, values)
   end subroutine append_value
end module vibrobeam_namelist_assignment
