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
   use vibrobeam_kinds, only: dp, int64
   use vibrobeam_text, only: real_text, integer_text
   use vibrobeam_namelist_tokens, only: token, tokenize, abbreviated, lowercase, t_end, t_word, t_string, &
      t_group, t_dollar, t_slash, t_equals, t_open, t_close, t_comma, t_bad
   implicit none
   private
   public :: namelist_variable, scanned_file, scanned_item, scanned_value
   public :: scan_namelist_file, scan_namelist_text, abbreviated, lowercase, real_exponent
   public :: range_text, choices_text, variable_index
   public :: kind_real, kind_integer, kind_logical, kind_string
   public :: form_word, form_string, form_null
   public :: max_input_bytes

   integer, parameter :: kind_real = 1, kind_integer = 2, kind_logical = 3, kind_string = 4
   integer, parameter :: form_word = 1, form_string = 2, form_null = 3

   !> Largest input file read (bytes): a scene takes a few hundred bytes; a file this large
   !! is not a scene.
   integer, parameter :: max_input_bytes = 1048576

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
end module vibrobeam_namelist_scan
