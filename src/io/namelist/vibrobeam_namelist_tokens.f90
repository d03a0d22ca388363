!> The tokens of a namelist file: names and numbers (words), quoted strings, '&group',
!! '$...', '/', '=', '(', ')', ','; blanks, line ends and comments after '!' separate them.
!!
!! Every byte is looked at: control characters anywhere, and non-ASCII bytes outside
!! comments and strings (or malformed UTF-8 inside them), end the token list with a
!! t_bad token that says what is wrong, so that the parser reports it with the group it
!! stands in (`vibrobeam_namelist_scan`).
module vibrobeam_namelist_tokens
   use vibrobeam_text, only: integer_text
   implicit none
   private
   public :: token, tokenize, abbreviated, lowercase
   public :: t_end, t_word, t_string, t_group, t_dollar, t_slash, t_equals, t_open, t_close, t_comma, t_bad

   ! token types
   integer, parameter :: t_end = 0, t_word = 1, t_string = 2, t_group = 3, t_dollar = 4, t_slash = 5, &
                         t_equals = 6, t_open = 7, t_close = 8, t_comma = 9, t_bad = 10

   type :: token
      integer :: type = t_end
      integer :: first = 0, last = -1            !! bytes of the token in the file text
      integer :: line = 0
      character(len=:), allocatable :: problem   !! t_bad: what is wrong
   end type token

contains

   !> Split the text into tokens; bytes that are not allowed become t_bad tokens, so the
   !! parser reports them with the group they stand in.
   subroutine tokenize(source, list)
      character(len=*), intent(in) :: source
      type(token), allocatable, intent(out) :: list(:)
      integer :: i, n, line, count, code, finish
      character(len=1) :: c
      character(len=*), parameter :: delimiters = ' ,/!''"=()&$'//achar(9)//achar(10)//achar(13)
      n = len(source)
      allocate (list(64))
      count = 0
      line = 1
      i = 1
      do while (i <= n)
         c = source(i:i)
         code = iachar(c)
         select case (code)
         case (10)
            line = line + 1
            i = i + 1
         case (13)
            if (i < n) then
               if (source(i + 1:i + 1) == achar(10)) then
                  i = i + 1
                  cycle
               end if
            end if
            call add_bad(i, i, 'a carriage return (byte 0x0D) not followed by a line feed: '// &
                         'lines end with LF or CR LF')
            exit
         case (9, 32)
            i = i + 1
         case (33)   ! '!': a comment to the end of the line
            finish = i
            do while (finish < n)
               if (source(finish + 1:finish + 1) == achar(10)) exit
               finish = finish + 1
            end do
            if (.not. text_bytes_ok(i + 1, finish, 'in a comment')) exit
            i = finish + 1
         case (34, 39)   ! a quoted string; a doubled quote stands for one
            finish = i + 1
            do
               if (finish > n) exit
               if (source(finish:finish) == achar(10)) exit
               if (source(finish:finish) == c) then
                  if (finish < n) then
                     if (source(finish + 1:finish + 1) == c) then
                        finish = finish + 2
                        cycle
                     end if
                  end if
                  exit
               end if
               finish = finish + 1
            end do
            if (finish > n) then
               call add_bad(i, n, 'the string starting '//abbreviated(source(i:n), 24)//' has no closing '//c// &
                            ': close it on the same line')
               exit
            else if (source(finish:finish) /= c) then
               call add_bad(i, finish, 'the string starting '//abbreviated(source(i:finish - 1), 24)// &
                            ' has no closing '//c//': close it on the same line')
               exit
            end if
            if (.not. text_bytes_ok(i + 1, finish - 1, 'in a string')) exit
            call add(t_string, i, finish)
            i = finish + 1
         case (38, 36)   ! '&name' or '$name'
            finish = i
            do while (finish < n)
               if (scan(source(finish + 1:finish + 1), &
                        'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_') == 0) exit
               finish = finish + 1
            end do
            if (code == 36) then
               call add(t_dollar, i, finish)
            else if (finish == i) then
               call add_bad(i, i, '''&'' without a group name: a group starts with &name')
               exit
            else
               call add(t_group, i, finish)
               if (finish < n) then
                  if (scan(source(finish + 1:finish + 1), ' /!'//achar(9)//achar(10)//achar(13)) == 0) then
                     call add_bad(finish + 1, finish + 1, 'the group name '//source(i:finish)// &
                                  ' must be followed by a blank or the end of the line, not '''// &
                                  shown_byte(source(finish + 1:finish + 1))//'''')
                     exit
                  end if
               end if
            end if
            i = finish + 1
         case (47)
            call add(t_slash, i, i)
            i = i + 1
         case (61)
            call add(t_equals, i, i)
            i = i + 1
         case (40)
            call add(t_open, i, i)
            i = i + 1
         case (41)
            call add(t_close, i, i)
            i = i + 1
         case (44)
            call add(t_comma, i, i)
            i = i + 1
         case (0:8, 11, 12, 14:31, 127)
            call add_bad(i, i, 'byte '//hex_byte(code)//' (a control character) is not allowed: '// &
                         'an input file is text')
            exit
         case (128:)
            call add_bad(i, i, 'byte '//hex_byte(code)//' (not ASCII) is not allowed outside a comment '// &
                         'or a quoted string: an input file is namelist text')
            exit
         case default   ! a word: a name, a number, a logical, a repeat count
            finish = i
            do while (finish < n)
               code = iachar(source(finish + 1:finish + 1))
               if (code < 33 .or. code > 126) exit
               if (index(delimiters, source(finish + 1:finish + 1)) > 0) exit
               finish = finish + 1
            end do
            call add(t_word, i, finish)
            i = finish + 1
         end select
      end do
      call add(t_end, n + 1, n)
      call add(t_end, n + 1, n)   ! two: the parser looks up to two tokens ahead
      call add(t_end, n + 1, n)
      list = list(1:count)
   contains
      subroutine add(type, first, last)
         integer, intent(in) :: type, first, last
         type(token), allocatable :: bigger(:)
         if (count == size(list)) then
            allocate (bigger(2*count))
            bigger(1:count) = list
            call move_alloc(bigger, list)
         end if
         count = count + 1
         list(count)%type = type
         list(count)%first = first
         list(count)%last = last
         list(count)%line = line
      end subroutine add

      subroutine add_bad(first, last, problem)
         integer, intent(in) :: first, last
         character(len=*), intent(in) :: problem
         call add(t_bad, first, last)
         list(count)%problem = problem
      end subroutine add_bad

      !> Bytes first..last of a comment or a string: no control characters, and UTF-8
      !! sequences only where they are well formed.
      logical function text_bytes_ok(first, last, where) result(ok)
         integer, intent(in) :: first, last
         character(len=*), intent(in) :: where
         integer :: j, b, following, k
         ok = .true.
         j = first
         do while (j <= last)
            b = iachar(source(j:j))
            following = 0
            select case (b)
            case (0:8, 10:31, 127)
               if (b == 13 .and. j == last) exit   ! CR of a CR LF line end
               call add_bad(j, j, 'byte '//hex_byte(b)//' (a control character) '//where//' is not allowed')
               ok = .false.
               return
            case (194:223)
               following = 1
            case (224:239)
               following = 2
            case (240:244)
               following = 3
            case (128:193, 245:255)
               call add_bad(j, j, 'byte '//hex_byte(b)//' '//where//' is not part of a UTF-8 character')
               ok = .false.
               return
            end select
            do k = 1, following
               if (j + k > last) then
                  ok = .false.
               else
                  ok = iachar(source(j + k:j + k)) >= 128 .and. iachar(source(j + k:j + k)) <= 191
               end if
               if (.not. ok) then
                  call add_bad(j, j, 'byte '//hex_byte(b)//' '//where//' starts a malformed UTF-8 character')
                  return
               end if
            end do
            j = j + 1 + following
         end do
      end function text_bytes_ok
   end subroutine tokenize

   function hex_byte(code) result(text)
      integer, intent(in) :: code
      character(len=4) :: text
      write (text, '(a,z2.2)') '0x', code
   end function hex_byte


   function shown_byte(c) result(text)
      character(len=1), intent(in) :: c
      character(len=:), allocatable :: text
      if (iachar(c) < 32 .or. iachar(c) > 126) then
         text = 'byte '//hex_byte(iachar(c))
      else
         text = c
      end if
   end function shown_byte


   !> `text` with bytes outside printable ASCII shown as '?', cut to `width` characters
   !! with '...' and the full length when longer.
   function abbreviated(text, width) result(short)
      character(len=*), intent(in) :: text
      integer, intent(in) :: width
      character(len=:), allocatable :: short
      integer :: i, code
      short = text(1:min(len(text), width))
      do i = 1, len(short)
         code = iachar(short(i:i))
         if (code < 32 .or. code > 126) short(i:i) = '?'
      end do
      if (len(text) > width) short = short//'... ('//integer_text(len(text))//' characters)'
   end function abbreviated


   !> ASCII lower case.
   pure function lowercase(text) result(lower)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: lower
      integer :: i, code
      lower = text
      do i = 1, len(text)
         code = iachar(text(i:i))
         if (code >= iachar('A') .and. code <= iachar('Z')) lower(i:i) = achar(code + 32)
      end do
   end function lowercase
end module vibrobeam_namelist_tokens
