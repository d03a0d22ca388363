!> A namelist file read as a whole before Fortran namelist input sees any of it.
!!
!! Fortran namelist input skips whatever lies outside the group it looks for, cuts strings
!! to the length of their variable, reads a last group without its '/', and traps (Debug)
!! or stops on values it cannot convert. This module tokenizes the whole file first -
!! comments after '!', strings in ' or " with doubled quotes, '&group ... /' blocks - and
!! checks it against a schema (the groups, their variables, their kinds, array extents,
!! longest strings, hard ranges). Anything it does not accept is refused with a message
!! naming the line, the group, the variable and what is allowed. What it accepts it hands
!! on as one canonical record per assignment ('&group name(i)=v1,v2 /'), which namelist
!! input then reads from an internal file: the run-time library sees exactly what was
!! checked, and a failure of that read names the assignment it came from.
!!
!! Accepted syntax (a subset of Fortran namelist input): `&group` at the start of a group,
!! followed by a blank, '/', '!' or the end of the line; assignments `name = values` or
!! `name(i) = values` (array elements i, i+1, ...), separated by commas or blanks; values
!! separated by commas or blanks, `r*value` repeats, `r*` and empty values between commas
!! are null (leave the element as it was); one '/' ends the group, and nothing but a
!! comment may follow it on its line. Comments and quoted strings may hold UTF-8 text;
!! everything else is printable ASCII, blanks, tabs and line ends (LF or CR LF).
module vibrobeam_namelist_scan
   use vibrobeam_text, only: integer_text
   use vibrobeam_namelist_tokens, only: token, tokenize, abbreviated, lowercase, t_end, t_word, t_string, &
      t_group, t_dollar, t_slash, t_equals, t_open, t_close, t_comma, t_bad
   use vibrobeam_namelist_schema, only: namelist_variable, scanned_value, form_word, form_string, form_null, &
      value_problem, allowed_text, element_label, shown_value, integer_value, is_name, first_match, &
      variable_index, group_names
   use vibrobeam_namelist_scanned, only: scanned_file, scanned_item
   implicit none
   private
   public :: scanned_file, scanned_item, scan_namelist_file, scan_namelist_text
   public :: max_input_bytes

   !> Largest input file read (bytes): a scene takes a few hundred bytes; a file this large
   !! is not a scene.
   integer, parameter :: max_input_bytes = 1048576

contains

   !> Read `filename` whole and scan it (see `scan_namelist_text`). stat = 1 with a message
   !! when the file cannot be read, is empty of groups or is not accepted.
   subroutine scan_namelist_file(filename, schema, scanned, stat, errmsg)
      character(len=*), intent(in) :: filename
      type(namelist_variable), intent(in) :: schema(:)
      type(scanned_file), intent(out) :: scanned
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: text
      character(len=256) :: iomsg
      integer :: unit, bytes
      logical :: exists, is_directory
      stat = 1
      inquire (file=filename, exist=exists, size=bytes)
      if (.not. exists) then
         errmsg = 'input file '''//abbreviated(filename, 200)//''' does not exist'
         return
      end if
      ! a directory "exists" and opens on some systems; its size is unreliable
      is_directory = .false.
      inquire (file=trim(filename)//'/.', exist=is_directory)
      if (is_directory) then
         errmsg = 'input file '''//abbreviated(filename, 200)//''' is a directory; give a namelist file'
         return
      end if
      if (bytes > max_input_bytes) then
         write (errmsg, '(a,i0,a,i0,a)') 'input file '''//abbreviated(filename, 200)//''' has ', bytes, &
            ' bytes; an input file holds at most ', max_input_bytes, ' bytes (a scene takes a few hundred)'
         return
      end if
      open (newunit=unit, file=filename, access='stream', form='unformatted', status='old', action='read', &
            iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         stat = 1
         errmsg = 'cannot open input file '''//abbreviated(filename, 200)//''': '//trim(iomsg)
         return
      end if
      allocate (character(len=max(bytes, 0)) :: text)
      if (bytes > 0) read (unit, iostat=stat, iomsg=iomsg) text
      close (unit)
      if (stat /= 0) then
         stat = 1
         errmsg = 'cannot read input file '''//abbreviated(filename, 200)//''': '//trim(iomsg)
         return
      end if
      call scan_namelist_text(text, schema, scanned, stat, errmsg)
   end subroutine scan_namelist_file

   !> Tokenize `text` (a whole namelist file) and check it against `schema`. stat = 0 and
   !! `scanned` filled on success; stat = 1 and a message naming the line, the group, the
   !! variable, the value and what is allowed on the first problem in file order.
   subroutine scan_namelist_text(text, schema, scanned, stat, errmsg)
      character(len=*), intent(in) :: text
      type(namelist_variable), intent(in) :: schema(:)
      type(scanned_file), intent(out) :: scanned
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(token), allocatable :: tokens(:)
      character(len=16), allocatable :: groups(:)
      integer, allocatable :: group_line(:)
      integer :: p, g, previous_end_line, item_count
      stat = 0
      errmsg = ''
      scanned%schema = schema
      allocate (scanned%items(16))
      item_count = 0
      allocate (scanned%given(max(1, maxval([1, schema%extent])), size(schema)), source=.false.)
      allocate (scanned%group_present(size(schema)), source=.false.)
      groups = group_names(schema)
      allocate (group_line(size(groups)), source=0)
      call tokenize(text, tokens)
      previous_end_line = 0
      p = 1
      do
         associate (t => tokens(p))
            select case (t%type)
            case (t_end)
               exit
            case (t_group)
               call parse_group()
               if (stat /= 0) return
            case (t_dollar)
               call fail_at(t%line, old_style_message(word_of(t)))
               return
            case (t_bad)
               call fail_at(t%line, t%problem//' (outside any namelist group)')
               return
            case default
               call outside_group(t)
               return
            end select
         end associate
      end do
      scanned%items = scanned%items(1:item_count)

   contains

      !> The text of a token, as written.
      function word_of(t) result(word)
         type(token), intent(in) :: t
         character(len=:), allocatable :: word
         word = text(t%first:t%last)
      end function word_of

      !> A problem of the file's structure: 'line L: ...'.
      subroutine fail_at(line, message)
         integer, intent(in) :: line
         character(len=*), intent(in) :: message
         stat = 1
         errmsg = 'line '//integer_text(line)//': '//message
      end subroutine fail_at

      !> A problem of one variable: '&group name = value ...: allowed ... (line L)'.
      subroutine fail_variable(line, message)
         integer, intent(in) :: line
         character(len=*), intent(in) :: message
         stat = 1
         errmsg = message//' (line '//integer_text(line)//')'
      end subroutine fail_variable

      !> Text outside any group: a misplaced assignment or anything else.
      subroutine outside_group(t)
         type(token), intent(in) :: t
         integer :: v, q
         ! a byte that is not allowed on the same line says more than the text around it
         do q = p, size(tokens)
            if (tokens(q)%line /= t%line .or. tokens(q)%type == t_end) exit
            if (tokens(q)%type == t_bad) then
               call fail_at(t%line, tokens(q)%problem)
               return
            end if
         end do
         if (t%type == t_word .and. tokens(p + 1)%type == t_equals .or. &
             t%type == t_word .and. tokens(p + 1)%type == t_open) then
            v = first_match(schema%name, lowercase(word_of(t)))
            if (v > 0) then
               call fail_at(t%line, 'variable '''//abbreviated(word_of(t), 40)//''' is outside any namelist group: '// &
                            'write it inside &'//trim(schema(v)%group)//' ... /')
               return
            end if
         end if
         if (t%type == t_slash) then
            call fail_at(t%line, '''/'' outside any namelist group: a group starts with &name and ends with one ''/''')
            return
         end if
         call fail_at(t%line, '''' // abbreviated(line_text(t), 40) // ''' is outside any namelist group: '// &
                      'a file holds only groups (&name ... /), blank lines and comments after ''!''')
      end subroutine outside_group

      !> The rest of the line from token t (for messages).
      function line_text(t) result(line)
         type(token), intent(in) :: t
         character(len=:), allocatable :: line
         integer :: finish
         finish = index(text(t%first:), achar(10))
         if (finish == 0) then
            finish = len(text)
         else
            finish = t%first + finish - 2
         end if
         line = text(t%first:finish)
         if (len(line) > 0) then
            if (line(len(line):) == achar(13)) line = line(1:len(line) - 1)
         end if
      end function line_text

      !> &group ... / starting at token p; leaves p after the '/'.
      subroutine parse_group()
         character(len=:), allocatable :: name
         name = lowercase(text(tokens(p)%first + 1:tokens(p)%last))
         if (name == 'end') then
            call fail_at(tokens(p)%line, '''&end'' closes a group in an old style that is not accepted: '// &
                         'end each group with ''/'', as in &mesh elements = 32 /')
            return
         end if
         g = first_match(groups, name)
         if (g == 0) then
            call fail_at(tokens(p)%line, 'unknown namelist group &'//abbreviated(name, 40)//' (known: '// &
                         known_groups_text()//')')
            return
         end if
         if (group_line(g) /= 0) then
            call fail_at(tokens(p)%line, '&'//name//' appears a second time (first at line '// &
                         integer_text(group_line(g))//'): give each group once')
            return
         end if
         if (tokens(p)%line == previous_end_line) then
            call fail_at(tokens(p)%line, '&'//name//' starts on the line where the previous group ends: '// &
                         'start each group on a line of its own')
            return
         end if
         group_line(g) = tokens(p)%line
         where (schema%group == name) scanned%group_present = .true.
         p = p + 1
         do
            select case (tokens(p)%type)
            case (t_slash)
               previous_end_line = tokens(p)%line
               p = p + 1
               if (tokens(p)%type /= t_end .and. tokens(p)%line == previous_end_line) then
                  if (tokens(p)%type == t_bad) then
                     call fail_at(tokens(p)%line, tokens(p)%problem)
                  else if (tokens(p)%type == t_group) then
                     call fail_at(tokens(p)%line, abbreviated(word_of(tokens(p)), 40)//' starts on the line '// &
                                  'where &'//name//' ends: start each group on a line of its own')
                  else
                     call fail_at(tokens(p)%line, ''''//abbreviated(line_text(tokens(p)), 40)//''' follows the ''/'' '// &
                                  'that ends &'//name//': only a comment may follow it on its line')
                  end if
               end if
               return
            case (t_end)
               call fail_at(group_line(g), '&'//name//' is not terminated: end the group with ''/''')
               return
            case (t_group)
               if (lowercase(word_of(tokens(p))) == '&end') then
                  call fail_at(tokens(p)%line, '&'//name//' ends with ''&end'', an old style that is not accepted: '// &
                               'end the group with ''/''')
               else
                  call fail_at(group_line(g), '&'//name//' is not terminated: end the group with ''/'' before '// &
                               abbreviated(word_of(tokens(p)), 40)//' (line '//integer_text(tokens(p)%line)//')')
               end if
               return
            case (t_dollar)
               call fail_at(tokens(p)%line, old_style_message(word_of(tokens(p))))
               return
            case (t_bad)
               call fail_at(tokens(p)%line, '&'//name//': '//tokens(p)%problem)
               return
            case (t_comma)
               p = p + 1
            case (t_word)
               call parse_item(name)
               if (stat /= 0) return
            case default
               call fail_at(tokens(p)%line, '&'//name//': '''//abbreviated(line_text(tokens(p)), 40)// &
                            ''' where a variable name is expected (name = value)')
               return
            end select
         end do
      end subroutine parse_group

      !> name [(i)] = values, starting at token p (the name) in &group.
      subroutine parse_item(group)
         character(len=*), intent(in) :: group
         character(len=:), allocatable :: name, label
         type(scanned_item) :: item
         integer :: v, line, index_value
         logical :: ok
         line = tokens(p)%line
         name = lowercase(word_of(tokens(p)))
         v = 0
         if (is_name(name)) v = variable_index(schema, group, name)
         if (v == 0) then
            if (is_name(name) .and. (tokens(p + 1)%type == t_equals .or. tokens(p + 1)%type == t_open)) then
               call fail_at(line, '&'//group//': unknown variable '''//abbreviated(name, 40)//''' (the variables of &'// &
                            group//' are: '//variables_text(group)//')')
            else
               call fail_at(line, '&'//group//': '''//abbreviated(line_text(tokens(p)), 40)// &
                            ''' where a variable name is expected (name = value)')
            end if
            return
         end if
         item%variable = v
         item%line = line
         item%first = 1
         label = trim(name)
         p = p + 1
         if (tokens(p)%type == t_open) then
            if (tokens(p + 1)%type /= t_word .or. tokens(p + 2)%type /= t_close) then
               call fail_variable(line, '&'//group//' '//label//': malformed subscript '''// &
                            abbreviated(line_text(tokens(p)), 40)//'''; write '//label//'(i) = value')
               return
            end if
            if (schema(v)%extent == 0) then
               call fail_variable(line, '&'//group//' '//label//' is not an array: write '//label//' = value')
               return
            end if
            label = label//'('//word_of(tokens(p + 1))//')'
            call integer_value(word_of(tokens(p + 1)), index_value, ok)
            if (index(word_of(tokens(p + 1)), ':') > 0) then
               call fail_variable(line, '&'//group//' '//abbreviated(label, 60)//': array sections are not accepted; '// &
                            'write '//trim(name)//'(i) = value, value, ... to set elements i, i+1, ...')
               return
            end if
            if (.not. ok .or. index_value < 1 .or. index_value > schema(v)%extent) then
               call fail_variable(line, '&'//group//' '//abbreviated(label, 60)//': index '// &
                            abbreviated(word_of(tokens(p + 1)), 24)//' is outside [1, '// &
                            integer_text(schema(v)%extent)//']')
               return
            end if
            item%first = index_value
            p = p + 3
         end if
         if (tokens(p)%type /= t_equals) then
            call fail_variable(line, '&'//group//' '//abbreviated(label, 60)//': ''='' expected after the name '// &
                         '(name = value)')
            return
         end if
         p = p + 1
         call parse_values(group, label, item)
         if (stat /= 0) return
         call record_item(group, label, item)
      end subroutine parse_item

      !> The values after '=' up to the next name, '/' or the end of the group.
      subroutine parse_values(group, label, item)
         character(len=*), intent(in) :: group, label
         type(scanned_item), intent(inout) :: item
         type(scanned_value), allocatable :: values(:)
         type(scanned_value) :: value
         logical :: after_value
         integer :: star, repeat
         logical :: ok
         allocate (values(0))
         after_value = .false.
         do
            select case (tokens(p)%type)
            case (t_comma)
               if (.not. after_value) then
                  value%form = form_null
                  value%text = ''
                  value%repeat = 1
                  call append_value(values, value)
               end if
               after_value = .false.
               p = p + 1
            case (t_word)
               ! a word followed by '=' or '(' is the next variable's name
               if (tokens(p + 1)%type == t_equals .or. tokens(p + 1)%type == t_open) exit
               value%form = form_word
               value%text = word_of(tokens(p))
               value%repeat = 1
               star = index(value%text, '*')
               if (star > 0) then
                  call integer_value(value%text(1:star - 1), repeat, ok)
                  if (.not. ok .or. verify(value%text(1:star - 1), '0123456789') /= 0 .or. repeat < 1) then
                     call fail_variable(tokens(p)%line, '&'//group//' '//abbreviated(label, 60)//' = '// &
                                  abbreviated(value%text, 40)//': bad repeat count '''// &
                                  abbreviated(value%text(1:star - 1), 24)//''' (r*value needs a whole number r >= 1)')
                     return
                  end if
                  if (repeat > max(1, schema(item%variable)%extent)) then
                     call fail_variable(tokens(p)%line, '&'//group//' '//abbreviated(label, 60)//' = '// &
                                  abbreviated(word_of(tokens(p)), 40)//': repeat count '//integer_text(repeat)// &
                                  ' is more than the '//integer_text(max(1, schema(item%variable)%extent))// &
                                  ' element(s) of '//trim(schema(item%variable)%name))
                     return
                  end if
                  value%repeat = repeat
                  value%text = value%text(star + 1:)
                  if (len(value%text) == 0) then
                     value%form = form_null
                     ! 'r*' glued to a string: r copies of the string
                     if (tokens(p + 1)%type == t_string .and. tokens(p + 1)%first == tokens(p)%last + 1) then
                        p = p + 1
                        value%form = form_string
                        value%text = string_content(tokens(p))
                     end if
                  else if (index(value%text, '*') > 0) then
                     call fail_variable(tokens(p)%line, '&'//group//' '//abbreviated(label, 60)//' = '// &
                                  abbreviated(word_of(tokens(p)), 40)//': malformed repeat (r*value)')
                     return
                  end if
               end if
               call append_value(values, value)
               after_value = .true.
               p = p + 1
            case (t_string)
               value%form = form_string
               value%text = string_content(tokens(p))
               value%repeat = 1
               call append_value(values, value)
               after_value = .true.
               p = p + 1
            case (t_bad)
               call fail_at(tokens(p)%line, '&'//group//' '//abbreviated(label, 60)//': '//tokens(p)%problem)
               return
            case (t_equals, t_open, t_close)
               call fail_variable(tokens(p)%line, '&'//group//' '//abbreviated(label, 60)//': unexpected '''// &
                            word_of(tokens(p))//''' among the values')
               return
            case default   ! '/', end of file, next group, bad token: the caller reports them
               exit
            end select
         end do
         item%values = values
         item%count = sum(values%repeat)
      end subroutine parse_values

      !> Check the values of an assignment against the schema and keep it.
      subroutine record_item(group, label, item)
         character(len=*), intent(in) :: group, label
         type(scanned_item), intent(inout) :: item
         type(scanned_item), allocatable :: bigger(:)
         integer :: k, element, r, v, last
         character(len=:), allocatable :: problem
         v = item%variable
         associate (variable => schema(v))
            if (item%count == 0 .or. all(item%values%form == form_null)) then
               call fail_variable(item%line, '&'//group//' '//abbreviated(label, 60)//' has no value: '// &
                            allowed_text(variable))
               return
            end if
            if (variable%extent == 0 .and. item%count > 1) then
               call fail_variable(item%line, '&'//group//' '//abbreviated(label, 60)//' takes one value; '// &
                            integer_text(item%count)//' are given')
               return
            end if
            last = item%first + item%count - 1
            if (variable%extent > 0 .and. (item%count > variable%extent .or. last > variable%extent)) then
               call fail_variable(item%line, '&'//group//' '//abbreviated(label, 60)//': '//integer_text(item%count)// &
                            ' values from element '//integer_text(item%first)//' go beyond element '// &
                            integer_text(variable%extent)//', the last of '//trim(variable%name))
               return
            end if
            element = item%first
            do k = 1, size(item%values)
               if (item%values(k)%form /= form_null) then
                  problem = value_problem(variable, item%values(k))
                  if (len(problem) > 0) then
                     call fail_variable(item%line, '&'//group//' '//element_label(variable, element, label)//' = '// &
                                  shown_value(item%values(k))//' '//problem)
                     return
                  end if
               end if
               do r = 1, item%values(k)%repeat
                  if (item%values(k)%form /= form_null) then
                     if (scanned%given(element, v)) then
                        call fail_variable(item%line, '&'//group//' '//element_label(variable, element, label)// &
                                     ' is given twice: give each variable once')
                        return
                     end if
                     scanned%given(element, v) = .true.
                  end if
                  element = element + 1
               end do
            end do
         end associate
         item_count = item_count + 1
         if (item_count > size(scanned%items)) then
            allocate (bigger(2*size(scanned%items)))
            bigger(1:item_count - 1) = scanned%items(1:item_count - 1)
            call move_alloc(bigger, scanned%items)
         end if
         scanned%items(item_count) = item
      end subroutine record_item

      !> The content of a string token, quotes removed and doubled quotes undoubled.
      function string_content(t) result(content)
         type(token), intent(in) :: t
         character(len=:), allocatable :: content
         character(len=1) :: quote
         integer :: i
         quote = text(t%first:t%first)
         content = ''
         i = t%first + 1
         do while (i < t%last)
            content = content//text(i:i)
            if (text(i:i) == quote) i = i + 1
            i = i + 1
         end do
      end function string_content

      function known_groups_text() result(list)
         character(len=:), allocatable :: list
         integer :: k
         list = ''
         do k = 1, size(groups)
            list = list//'&'//trim(groups(k))
            if (k < size(groups)) list = list//' '
         end do
      end function known_groups_text

      function variables_text(group) result(list)
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

   end subroutine scan_namelist_text

   subroutine append_value(values, value)
      type(scanned_value), allocatable, intent(inout) :: values(:)
      type(scanned_value), intent(in) :: value
      type(scanned_value), allocatable :: longer(:)
      allocate (longer(size(values) + 1))
      longer(1:size(values)) = values
      longer(size(values) + 1) = value
      call move_alloc(longer, values)
   end subroutine append_value

   !> The message for '$group ... $end' (an old, non-standard form).
   function old_style_message(word) result(message)
      character(len=*), intent(in) :: word
      character(len=:), allocatable :: message
      character(len=:), allocatable :: name
      name = lowercase(word(2:))
      if (name == 'end' .or. len(name) == 0) name = 'group'
      message = '''' // abbreviated(word, 40) // ''' is the old $group ... $end style, which is not accepted: '// &
                'write &'//name//' name = value, ... / (an ampersand before the name, one ''/'' at the end)'
   end function old_style_message

end module vibrobeam_namelist_scan
