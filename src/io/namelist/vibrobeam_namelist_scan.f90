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
!! This module parses the structure (groups and what lies between them); each assignment
!! is `vibrobeam_namelist_assignment`'s.
!!
!! Accepted syntax (a subset of Fortran namelist input): `&group` at the start of a group,
!! followed by a blank, '/', '!' or the end of the line; assignments `name = values` or
!! `name(i) = values` (array elements i, i+1, ...), separated by commas or blanks; values
!! separated by commas or blanks, `r*value` repeats, `r*` and empty values between commas
!! are null (leave the element as it was); one '/' ends the group, and nothing but a
!! comment may follow it on its line. Comments and quoted strings may hold UTF-8 text;
!! everything else is printable ASCII, blanks, tabs and line ends (LF or CR LF).
module vibrobeam_namelist_scan
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: integer_text
   use vibrobeam_namelist_tokens, only: abbreviated, lowercase, t_end, t_word, t_group, t_dollar, t_slash, &
      t_equals, t_open, t_comma, t_bad
   use vibrobeam_namelist_schema, only: namelist_variable, first_match, group_names
   use vibrobeam_namelist_scanned, only: scanned_file, scanned_item
   use vibrobeam_namelist_cursor, only: token_cursor, fail_at
   use vibrobeam_namelist_assignment, only: parse_assignment
   implicit none
   private
   public :: scanned_file, scanned_item, scan_namelist_file, scan_namelist_text
   public :: max_input_bytes

   !> Largest input file read (bytes): a scene takes a few hundred bytes; a file this large
   !! is not a scene.
   integer, parameter :: max_input_bytes = 1048576

   !> The groups of the schema and where the file has them.
   type :: group_record
      character(len=16), allocatable :: names(:)
      integer, allocatable :: line(:)          !! (group) the line of its '&name', 0 not seen
      integer :: previous_end_line = 0         !! the line of the last group's '/'
   end type group_record

contains

   !> Read `filename` whole and scan it (see `scan_namelist_text`). stat = stat_failure with a message
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
      stat = stat_failure
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
         stat = stat_failure
         errmsg = 'cannot open input file '''//abbreviated(filename, 200)//''': '//trim(iomsg)
         return
      end if
      allocate (character(len=max(bytes, 0)) :: text)
      if (bytes > 0) read (unit, iostat=stat, iomsg=iomsg) text
      close (unit)
      if (stat /= 0) then
         stat = stat_failure
         errmsg = 'cannot read input file '''//abbreviated(filename, 200)//''': '//trim(iomsg)
         return
      end if
      call scan_namelist_text(text, schema, scanned, stat, errmsg)
   end subroutine scan_namelist_file

   !> Tokenize `text` (a whole namelist file) and check it against `schema`. stat = 0 and
   !! `scanned` filled on success; stat = stat_failure and a message naming the line, the group, the
   !! variable, the value and what is allowed on the first problem in file order.
   subroutine scan_namelist_text(text, schema, scanned, stat, errmsg)
      character(len=*), intent(in) :: text
      type(namelist_variable), intent(in) :: schema(:)
      type(scanned_file), intent(out) :: scanned
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      type(token_cursor) :: cursor
      type(group_record) :: groups
      integer :: item_count
      stat = 0
      errmsg = ''
      scanned%schema = schema
      allocate (scanned%items(16))
      item_count = 0
      allocate (scanned%given(max(1, maxval([1, schema%extent])), size(schema)), source=.false.)
      allocate (scanned%group_present(size(schema)), source=.false.)
      groups%names = group_names(schema)
      allocate (groups%line(size(groups%names)), source=0)
      call cursor%start(text)
      do
         select case (cursor%type_at(0))
         case (t_end)
            exit
         case (t_group)
            call parse_group(cursor, groups, scanned, item_count, stat, errmsg)
            if (stat /= 0) return
         case (t_dollar)
            call fail_at(cursor%line_at(0), old_style_message(cursor%word_at(0)), stat, errmsg)
            return
         case (t_bad)
            call fail_at(cursor%line_at(0), cursor%tokens(cursor%p)%problem//' (outside any namelist group)', stat, &
                         errmsg)
            return
         case default
            call outside_group(cursor, schema, stat, errmsg)
            return
         end select
      end do
      scanned%items = scanned%items(1:item_count)
   end subroutine scan_namelist_text

   !> Text outside any group (at the cursor): a misplaced assignment or anything else.
   subroutine outside_group(cursor, schema, stat, errmsg)
      type(token_cursor), intent(in) :: cursor
      type(namelist_variable), intent(in) :: schema(:)
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      integer :: v, q, line
      line = cursor%line_at(0)
      ! a byte that is not allowed on the same line says more than the text around it
      do q = cursor%p, size(cursor%tokens)
         if (cursor%tokens(q)%line /= line .or. cursor%tokens(q)%type == t_end) exit
         if (cursor%tokens(q)%type == t_bad) then
            call fail_at(line, cursor%tokens(q)%problem, stat, errmsg)
            return
         end if
      end do
      if (cursor%type_at(0) == t_word .and. cursor%type_at(1) == t_equals .or. &
          cursor%type_at(0) == t_word .and. cursor%type_at(1) == t_open) then
         v = first_match(schema%name, lowercase(cursor%word_at(0)))
         if (v > 0) then
            call fail_at(line, 'variable '''//abbreviated(cursor%word_at(0), 40)//''' is outside any namelist '// &
                         'group: write it inside &'//trim(schema(v)%group)//' ... /', stat, errmsg)
            return
         end if
      end if
      if (cursor%type_at(0) == t_slash) then
         call fail_at(line, '''/'' outside any namelist group: a group starts with &name and ends with one ''/''', &
                      stat, errmsg)
         return
      end if
      call fail_at(line, '''' // abbreviated(cursor%rest_of_line(0), 40) // ''' is outside any namelist group: '// &
                   'a file holds only groups (&name ... /), blank lines and comments after ''!''', stat, errmsg)
   end subroutine outside_group

   !> &group ... / starting at the cursor; leaves the cursor after the '/'.
   subroutine parse_group(cursor, groups, scanned, item_count, stat, errmsg)
      type(token_cursor), intent(inout) :: cursor
      type(group_record), intent(inout) :: groups
      type(scanned_file), intent(inout) :: scanned
      integer, intent(inout) :: item_count
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      character(len=:), allocatable :: name
      integer :: g
      call open_group(cursor, groups, name, g, stat, errmsg)
      if (stat /= 0) return
      where (scanned%schema%group == name) scanned%group_present = .true.
      cursor%p = cursor%p + 1
      do
         select case (cursor%type_at(0))
         case (t_slash)
            groups%previous_end_line = cursor%line_at(0)
            cursor%p = cursor%p + 1
            if (cursor%type_at(0) /= t_end .and. cursor%line_at(0) == groups%previous_end_line) then
               if (cursor%type_at(0) == t_bad) then
                  call fail_at(cursor%line_at(0), cursor%tokens(cursor%p)%problem, stat, errmsg)
               else if (cursor%type_at(0) == t_group) then
                  call fail_at(cursor%line_at(0), abbreviated(cursor%word_at(0), 40)//' starts on the line '// &
                               'where &'//name//' ends: start each group on a line of its own', stat, errmsg)
               else
                  call fail_at(cursor%line_at(0), ''''//abbreviated(cursor%rest_of_line(0), 40)//''' follows the '// &
                               '''/'' that ends &'//name//': only a comment may follow it on its line', stat, errmsg)
               end if
            end if
            return
         case (t_end)
            call fail_at(groups%line(g), '&'//name//' is not terminated: end the group with ''/''', stat, errmsg)
            return
         case (t_group)
            if (lowercase(cursor%word_at(0)) == '&end') then
               call fail_at(cursor%line_at(0), '&'//name//' ends with ''&end'', an old style that is not accepted: '// &
                            'end the group with ''/''', stat, errmsg)
            else
               call fail_at(groups%line(g), '&'//name//' is not terminated: end the group with ''/'' before '// &
                            abbreviated(cursor%word_at(0), 40)//' (line '//integer_text(cursor%line_at(0))//')', &
                            stat, errmsg)
            end if
            return
         case (t_dollar)
            call fail_at(cursor%line_at(0), old_style_message(cursor%word_at(0)), stat, errmsg)
            return
         case (t_bad)
            call fail_at(cursor%line_at(0), '&'//name//': '//cursor%tokens(cursor%p)%problem, stat, errmsg)
            return
         case (t_comma)
            cursor%p = cursor%p + 1
         case (t_word)
            call parse_assignment(cursor, name, scanned, item_count, stat, errmsg)
            if (stat /= 0) return
         case default
            call fail_at(cursor%line_at(0), '&'//name//': '''//abbreviated(cursor%rest_of_line(0), 40)// &
                         ''' where a variable name is expected (name = value)', stat, errmsg)
            return
         end select
      end do
   end subroutine parse_group

   !> The '&name' at the cursor: a known group, given once, on a line of its own. `name`
   !! in lower case, `g` its index in groups%names; its line is recorded.
   subroutine open_group(cursor, groups, name, g, stat, errmsg)
      type(token_cursor), intent(in) :: cursor
      type(group_record), intent(inout) :: groups
      character(len=:), allocatable, intent(out) :: name
      integer, intent(out) :: g
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = 0
      errmsg = ''
      name = lowercase(cursor%word_at(0))
      name = name(2:)
      g = 0
      if (name == 'end') then
         call fail_at(cursor%line_at(0), '''&end'' closes a group in an old style that is not accepted: '// &
                      'end each group with ''/'', as in &mesh elements = 32 /', stat, errmsg)
         return
      end if
      g = first_match(groups%names, name)
      if (g == 0) then
         call fail_at(cursor%line_at(0), 'unknown namelist group &'//abbreviated(name, 40)//' (known: '// &
                      known_groups_text(groups%names)//')', stat, errmsg)
         return
      end if
      if (groups%line(g) /= 0) then
         call fail_at(cursor%line_at(0), '&'//name//' appears a second time (first at line '// &
                      integer_text(groups%line(g))//'): give each group once', stat, errmsg)
         return
      end if
      if (cursor%line_at(0) == groups%previous_end_line) then
         call fail_at(cursor%line_at(0), '&'//name//' starts on the line where the previous group ends: '// &
                      'start each group on a line of its own', stat, errmsg)
         return
      end if
      groups%line(g) = cursor%line_at(0)
   end subroutine open_group

   !> '&beam &mesh ...': the groups of the schema, for messages.
   function known_groups_text(groups) result(list)
      character(len=*), intent(in) :: groups(:)
      character(len=:), allocatable :: list
      integer :: k
      list = ''
      do k = 1, size(groups)
         list = list//'&'//trim(groups(k))
         if (k < size(groups)) list = list//' '
      end do
   end function known_groups_text

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
