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

   !> The tokens found so far, and the line the tokenizer is on.
   type :: token_list
      type(token), allocatable :: list(:)
      integer :: count = 0
      integer :: line = 1
   contains
      procedure :: add => list_add
      procedure :: add_bad => list_add_bad
   end type token_list

contains

   !> Split the text into tokens; bytes that are not allowed become t_bad tokens, so the
   !! parser reports them with the group they stand in.
   subroutine tokenize(source, list)
      character(len=*), intent(in) :: source
      type(token), allocatable, intent(out) :: list(:)
      type(token_list) :: found
      integer :: i, n, code, finish, bad
      character(len=:), allocatable :: problem
      n = len(source)
      allocate (found%list(64))
      i = 1
      do while (i <= n)
         code = iachar(source(i:i))
         select case (code)
         case (10)
            found%line = found%line + 1
            i = i + 1
         case (13)
            if (i < n) then
               if (source(i + 1:i + 1) == achar(10)) then
                  i = i + 1
                  cycle
               end if
            end if
            call found%add_bad(i, i, 'a carriage return (byte 0x0D) not followed by a line feed: '// &
                               'lines end with LF or CR LF')
            exit
         case (9, 32)
            i = i + 1
         case (33)   ! '!': a comment to the end of the line
            finish = line_end(source, i)
            call text_bytes_problem(source, i + 1, finish, 'in a comment', bad, problem)
            if (bad > 0) then
               call found%add_bad(bad, bad, problem)
               exit
            end if
            i = finish + 1
         case (34, 39)   ! a quoted string; a doubled quote stands for one
            call string_token(source, i, found, finish)
            if (finish == 0) exit
            i = finish + 1
         case (38, 36)   ! '&name' or '$name'
            call name_token(source, i, found, finish)
            if (finish == 0) exit
            i = finish + 1
         case (47)
            call found%add(t_slash, i, i)
            i = i + 1
         case (61)
            call found%add(t_equals, i, i)
            i = i + 1
         case (40)
            call found%add(t_open, i, i)
            i = i + 1
         case (41)
            call found%add(t_close, i, i)
            i = i + 1
         case (44)
            call found%add(t_comma, i, i)
            i = i + 1
         case (0:8, 11, 12, 14:31, 127)
            call found%add_bad(i, i, 'byte '//hex_byte(code)//' (a control character) is not allowed: '// &
                               'an input file is text')
            exit
         case (128:)
            call found%add_bad(i, i, 'byte '//hex_byte(code)//' (not ASCII) is not allowed outside a comment '// &
                               'or a quoted string: an input file is namelist text')
            exit
         case default   ! a word: a name, a number, a logical, a repeat count
            finish = word_end(source, i)
            call found%add(t_word, i, finish)
            i = finish + 1
         end select
      end do
      call found%add(t_end, n + 1, n)
      call found%add(t_end, n + 1, n)   ! two: the parser looks up to two tokens ahead
      call found%add(t_end, n + 1, n)
      list = found%list(1:found%count)
   end subroutine tokenize

   !> The quoted string starting at byte i (its quote): a t_string token, `finish` its
   !! closing quote; or, when it is not closed on its line or holds a byte that is not
   !! allowed, a t_bad token and finish = 0.
   subroutine string_token(source, i, found, finish)
      character(len=*), intent(in) :: source
      integer, intent(in) :: i
      type(token_list), intent(inout) :: found
      integer, intent(out) :: finish
      character(len=1) :: c
      character(len=:), allocatable :: problem
      integer :: n, bad
      n = len(source)
      c = source(i:i)
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
         call found%add_bad(i, n, 'the string starting '//abbreviated(source(i:n), 24)//' has no closing '//c// &
                            ': close it on the same line')
         finish = 0
         return
      else if (source(finish:finish) /= c) then
         call found%add_bad(i, finish, 'the string starting '//abbreviated(source(i:finish - 1), 24)// &
                            ' has no closing '//c//': close it on the same line')
         finish = 0
         return
      end if
      call text_bytes_problem(source, i + 1, finish - 1, 'in a string', bad, problem)
      if (bad > 0) then
         call found%add_bad(bad, bad, problem)
         finish = 0
         return
      end if
      call found%add(t_string, i, finish)
   end subroutine string_token

   !> '&name' (t_group, followed by a blank, '/', '!' or a line end) or '$name' (t_dollar)
   !! starting at byte i: `finish` its last byte; finish = 0 after a t_bad token.
   subroutine name_token(source, i, found, finish)
      character(len=*), intent(in) :: source
      integer, intent(in) :: i
      type(token_list), intent(inout) :: found
      integer, intent(out) :: finish
      integer :: n
      n = len(source)
      finish = i
      do while (finish < n)
         if (scan(source(finish + 1:finish + 1), &
                  'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_') == 0) exit
         finish = finish + 1
      end do
      if (source(i:i) == '$') then
         call found%add(t_dollar, i, finish)
      else if (finish == i) then
         call found%add_bad(i, i, '''&'' without a group name: a group starts with &name')
         finish = 0
      else
         call found%add(t_group, i, finish)
         if (finish < n) then
            if (scan(source(finish + 1:finish + 1), ' /!'//achar(9)//achar(10)//achar(13)) == 0) then
               call found%add_bad(finish + 1, finish + 1, 'the group name '//source(i:finish)// &
                                  ' must be followed by a blank or the end of the line, not '''// &
                                  shown_byte(source(finish + 1:finish + 1))//'''')
               finish = 0
            end if
         end if
      end if
   end subroutine name_token

   !> The last byte before the line feed that ends the line of byte i (or the end of the text).
   pure integer function line_end(source, i) result(finish)
      character(len=*), intent(in) :: source
      integer, intent(in) :: i
      finish = i
      do while (finish < len(source))
         if (source(finish + 1:finish + 1) == achar(10)) exit
         finish = finish + 1
      end do
   end function line_end

   !> The last byte of the word starting at byte i: printable ASCII up to a delimiter.
   pure integer function word_end(source, i) result(finish)
      character(len=*), intent(in) :: source
      integer, intent(in) :: i
      character(len=*), parameter :: delimiters = ' ,/!''"=()&$'//achar(9)//achar(10)//achar(13)
      integer :: code
      finish = i
      do while (finish < len(source))
         code = iachar(source(finish + 1:finish + 1))
         if (code < 33 .or. code > 126) exit
         if (index(delimiters, source(finish + 1:finish + 1)) > 0) exit
         finish = finish + 1
      end do
   end function word_end

   !> Bytes first..last of a comment or a string: no control characters, and UTF-8
   !! sequences only where they are well formed. `bad`: the first byte that is not
   !! allowed (0: none) and `problem` what is wrong with it.
   subroutine text_bytes_problem(source, first, last, where, bad, problem)
      character(len=*), intent(in) :: source
      integer, intent(in) :: first, last
      character(len=*), intent(in) :: where
      integer, intent(out) :: bad
      character(len=:), allocatable, intent(out) :: problem
      integer :: j, b, following, k
      logical :: ok
      bad = 0
      problem = ''
      j = first
      do while (j <= last)
         b = iachar(source(j:j))
         following = 0
         select case (b)
         case (0:8, 10:31, 127)
            if (b == 13 .and. j == last) exit   ! CR of a CR LF line end
            bad = j
            problem = 'byte '//hex_byte(b)//' (a control character) '//where//' is not allowed'
            return
         case (194:223)
            following = 1
         case (224:239)
            following = 2
         case (240:244)
            following = 3
         case (128:193, 245:255)
            bad = j
            problem = 'byte '//hex_byte(b)//' '//where//' is not part of a UTF-8 character'
            return
         end select
         do k = 1, following
            if (j + k > last) then
               ok = .false.
            else
               ok = iachar(source(j + k:j + k)) >= 128 .and. iachar(source(j + k:j + k)) <= 191
            end if
            if (.not. ok) then
               bad = j
               problem = 'byte '//hex_byte(b)//' '//where//' starts a malformed UTF-8 character'
               return
            end if
         end do
         j = j + 1 + following
      end do
   end subroutine text_bytes_problem

   !> Append a token of `type` (bytes first..last, on the current line).
   subroutine list_add(self, type, first, last)
      class(token_list), intent(inout) :: self
      integer, intent(in) :: type, first, last
      type(token), allocatable :: bigger(:)
      if (self%count == size(self%list)) then
         allocate (bigger(2*self%count))
         bigger(1:self%count) = self%list
         call move_alloc(bigger, self%list)
      end if
      self%count = self%count + 1
      self%list(self%count)%type = type
      self%list(self%count)%first = first
      self%list(self%count)%last = last
      self%list(self%count)%line = self%line
   end subroutine list_add

   !> Append a t_bad token saying what is wrong.
   subroutine list_add_bad(self, first, last, problem)
      class(token_list), intent(inout) :: self
      integer, intent(in) :: first, last
      character(len=*), intent(in) :: problem
      call self%add(t_bad, first, last)
      self%list(self%count)%problem = problem
   end subroutine list_add_bad

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
