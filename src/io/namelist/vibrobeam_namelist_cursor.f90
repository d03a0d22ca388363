!> The parser's position in the tokens of a namelist file (`vibrobeam_namelist_scan`,
!! `vibrobeam_namelist_assignment`): the file's text, its tokens (`tokenize`), the
!! current token, and what the tokens around it say; and the two forms of a message
!! about the file ('line L: ...' for its structure, '... (line L)' for one variable).
module vibrobeam_namelist_cursor
   use vibrobeam_status, only: stat_failure
   use vibrobeam_text, only: integer_text
   use vibrobeam_namelist_tokens, only: token, tokenize
   implicit none
   private
   public :: token_cursor, fail_at, fail_variable

   !> The tokens of a file and the position `p` of the parser.
   type :: token_cursor
      character(len=:), allocatable :: text   !! the whole file
      type(token), allocatable :: tokens(:)   !! ending with three t_end tokens
      integer :: p = 1                        !! the current token
   contains
      procedure :: start
      procedure :: type_at
      procedure :: line_at
      procedure :: word_at
      procedure :: rest_of_line
      procedure :: string_at
   end type token_cursor

contains

   !> Tokenize `text` and stand at its first token.
   subroutine start(self, text)
      class(token_cursor), intent(out) :: self
      character(len=*), intent(in) :: text
      self%text = text
      call tokenize(text, self%tokens)
      self%p = 1
   end subroutine start

   !> The type of token p + offset.
   pure integer function type_at(self, offset)
      class(token_cursor), intent(in) :: self
      integer, intent(in) :: offset
      type_at = self%tokens(self%p + offset)%type
   end function type_at

   !> The line of token p + offset.
   pure integer function line_at(self, offset)
      class(token_cursor), intent(in) :: self
      integer, intent(in) :: offset
      line_at = self%tokens(self%p + offset)%line
   end function line_at

   !> The text of token p + offset, as written.
   function word_at(self, offset) result(word)
      class(token_cursor), intent(in) :: self
      integer, intent(in) :: offset
      character(len=:), allocatable :: word
      word = self%text(self%tokens(self%p + offset)%first:self%tokens(self%p + offset)%last)
   end function word_at

   !> The rest of the line from token p + offset (for messages).
   function rest_of_line(self, offset) result(line)
      class(token_cursor), intent(in) :: self
      integer, intent(in) :: offset
      character(len=:), allocatable :: line
      integer :: first, finish
      first = self%tokens(self%p + offset)%first
      finish = index(self%text(first:), achar(10))
      if (finish == 0) then
         finish = len(self%text)
      else
         finish = first + finish - 2
      end if
      line = self%text(first:finish)
      if (len(line) > 0) then
         if (line(len(line):) == achar(13)) line = line(1:len(line) - 1)
      end if
   end function rest_of_line

   !> The content of the string token p + offset, quotes removed and doubled quotes
   !! undoubled.
   function string_at(self, offset) result(content)
      class(token_cursor), intent(in) :: self
      integer, intent(in) :: offset
      character(len=:), allocatable :: content
      character(len=1) :: quote
      integer :: i
      associate (t => self%tokens(self%p + offset))
         quote = self%text(t%first:t%first)
         content = ''
         i = t%first + 1
         do while (i < t%last)
            content = content//self%text(i:i)
            if (self%text(i:i) == quote) i = i + 1
            i = i + 1
         end do
      end associate
   end function string_at

   !> A problem of the file's structure: stat = stat_failure, 'line L: message'.
   subroutine fail_at(line, message, stat, errmsg)
      integer, intent(in) :: line
      character(len=*), intent(in) :: message
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = stat_failure
      errmsg = 'line '//integer_text(line)//': '//message
   end subroutine fail_at

   !> A problem of one variable: stat = stat_failure, '&group name = value ...: allowed ... (line L)'.
   subroutine fail_variable(line, message, stat, errmsg)
      integer, intent(in) :: line
      character(len=*), intent(in) :: message
      integer, intent(out) :: stat
      character(len=*), intent(out) :: errmsg
      stat = stat_failure
      errmsg = message//' (line '//integer_text(line)//')'
   end subroutine fail_variable
end module vibrobeam_namelist_cursor
